#!/usr/bin/python3
"""Plot of one pd_tension run (seed 003 section 4(1): uniaxial tension of a bar, NOSB peridynamics).

  /usr/bin/python3 tools/plot_pd_tension.py out/pd_tension

Writes tension.png into the run folder, from the last snapshot (fields.h5) and summary.json:
  left   the axial displacement u_x of every particle against its position x along the bar, with the
         line of the measured gauge strain (the modulus run) over the gauge section, the middle third
  right  the particles seen from the side (x, y), displaced (magnified), coloured by u_x
The title gives Young's modulus against the reference (or, after --identify-omega-v, omega_v).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, open_h5, pyplot, read_summary, run_folder, run_parser, snapshot_steps  # noqa: E402


def main():
    run = run_folder(run_parser(__doc__, "out/pd_tension").parse_args().run)
    s = read_summary(run, cases=("pd_tension",))
    h5 = os.path.join(run, "fields.h5")
    with open_h5(h5) as f:
        steps = snapshot_steps(f)
        if not steps:
            raise InputError(f"{h5}: no snapshot")
        x = f["mesh/points"][...]
        u = f[steps[-1]]["displacement"][...]
        t_end = float(f[steps[-1]].attrs["time"]) if "time" in f[steps[-1]].attrs else None
    if x.ndim != 2 or x.shape != u.shape or x.shape[1] < 2:
        raise InputError(f"{h5}: mesh/points {x.shape} and displacement {u.shape} do not match")
    plt = pyplot()
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.3), gridspec_kw={"width_ratios": [1, 1.3]})
    xs, ux = x[:, 0] * 1e3, u[:, 0] * 1e6
    left.plot(xs, ux, ".", ms=3, label="particles")
    if "gauge_strain" in s:
        # the gauge section of the app's measure: x in [L/3, 2L/3] of a bar [0, L] (particles at its cell centres)
        length = xs.max() + xs.min()
        lo, hi = length / 3, 2 * length / 3
        mid = (xs >= lo) & (xs <= hi)
        if np.any(mid):
            x0, u0 = np.mean(xs[mid]), np.mean(ux[mid])
            line = np.array([xs.min(), xs.max()])
            left.plot(line, u0 + s["gauge_strain"] * (line - x0) * 1e3, "k--", lw=1,
                      label=f"gauge strain {s['gauge_strain']:.4g} (summary)")
            left.axvspan(lo, hi, color="0.92", zorder=0, label="gauge section (the middle third)")
    left.set_xlabel("x along the bar [mm]")
    left.set_ylabel("axial displacement u_x [um]")
    left.grid(alpha=0.3)
    left.legend(fontsize=8)

    span = float(np.ptp(x[:, 0])) or 1.0
    umax = float(np.max(np.abs(u))) or 1.0
    mag = 0.05 * span / umax  # the largest displacement drawn as 5 % of the bar's length
    y = x + mag * u
    order = np.argsort(x[:, 2]) if x.shape[1] == 3 else np.arange(len(x))  # 3D: the near side drawn last
    sc = right.scatter(y[order, 0] * 1e3, y[order, 1] * 1e3, c=u[order, 0] * 1e6, s=10, cmap="viridis")
    right.set_aspect("equal")
    right.set_xlabel("x [mm]")
    right.set_ylabel("y [mm]" + (" (side view)" if x.shape[1] == 3 else ""))
    right.set_title(f"displacement x {mag:.3g}", fontsize=9)
    fig.colorbar(sc, ax=right, label="u_x [um]", shrink=0.8)

    if "modulus" in s:
        what = (f"E = {s['modulus'] / 1e9:.2f} GPa (reference {s['reference'] / 1e9:.1f} GPa, "
                f"{100 * s['relative_error']:+.2f} %), {s['steps']} steps")
    elif "omega_v" in s:
        what = f"omega_v = {s['omega_v']:.4g} rad/s (omega_v h / c_p = {s['omega_v_times_spacing_over_cp']:.3f})"
    else:
        what = ""
    when = f", t = {t_end * 1e6:.1f} us" if t_end is not None else ""
    fig.suptitle(f"{s['title']}\n{what}; {s['particles']} particles, spacing {s['spacing'] * 1e3:.3g} mm, "
                 f"{s['accuracy']}{when}" + (" (DIVERGED)" if s.get("diverged") else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "tension.png"), dpi=110)
    plt.close(fig)
    print(f"plot: {os.path.join(run, 'tension.png')}")


if __name__ == "__main__":
    guarded(main)
