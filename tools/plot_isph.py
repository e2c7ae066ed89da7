#!/usr/bin/python3
"""Plots of one isph run (seed 002 paper 4): the hydrostatic tank, the dam break, and the tanks with a
rigid body (scenes/isph/).

  /usr/bin/python3 tools/plot_isph.py out/isph_hydrostatic

writes into the run folder:
  series.png             the sampled series (series.csv) against time: the case's measure (relative L2
                         error of the pressure against rho g (H - y), or the surge front Z = x / a), the
                         largest particle speed, the PPE iterations per step; with a body, its centre
                         height and the fluid's vertical force on it
  particles.png          the particles of the first, a middle and the last snapshot (fields.h5),
                         coloured by pressure, free-surface particles circled
  pressure_profile.png   hydrostatic tank: the pressure of every particle of the last snapshot against
                         its depth, with rho g (H - y) (rho, g, H from the run's scene file)
  front.png              dam break: the surge front against Martin & Moyce and Koshizuka & Oka (as
                         tools/isph_dam_break.py draws it; that tool also compares several runs)
Several runs with a body side by side: tools/plot_isph_body.py.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, open_h5, pyplot, read_summary, run_folder, run_parser, snapshot_steps  # noqa: E402


def scene_values(s):
    """{"rho", "g", "H", "W", "tank_height"} from the run's scene file (fluid.density, fluid.gravity,
    tank.water_height, tank.width, tank.height), or {} where it cannot be read (moved, or no tomllib)."""
    try:
        import tomllib  # Python >= 3.11 (Debian 12)

        with open(s["scene"], "rb") as f:
            t = tomllib.load(f)
        fluid, tank = t.get("fluid", {}), t.get("tank", {})
        return {"rho": float(fluid["density"]), "g": float(fluid.get("gravity", 9.8)), "H": float(tank["water_height"]),
                "W": float(tank["width"]), "tank_height": float(tank["height"])}
    except Exception:  # noqa: BLE001 - the analytic line and the tank outline are optional
        return {}


def plot_series(run, s, c):
    plt = pyplot()
    dam = "front_Z" in c
    body = "body_y" in c
    rows = 4 if body else 3
    fig, ax = plt.subplots(rows, 1, figsize=(7, 2.1 * rows + 0.6), sharex=True)
    t = c["time"]
    if dam:
        ax[0].plot(t, c["front_Z"])
        ax[0].set_ylabel("front Z = x / a")
    else:
        ax[0].plot(t, 100 * c["pressure_error"])
        ax[0].set_ylabel("pressure error [%]\n(relative L2)")
    ax[1].plot(t, c["max_speed"])
    ax[1].set_ylabel("max. speed [m/s]")
    if len(t) and np.min(c["max_speed"]) > 0 and np.max(c["max_speed"]) > 1e4 * np.min(c["max_speed"]):
        ax[1].set_yscale("log")  # a run that blew up
    ax[2].plot(t, c["ppe_iterations"], ".", ms=3)
    ax[2].set_ylabel("PPE iterations")
    if body:
        ax[3].plot(t, c["body_y"], label="centre height")
        ax[3].set_ylabel("body centre y [m]")
        f = ax[3].twinx()
        f.plot(t, c["body_force_y"], color="C1", lw=0.6)
        f.set_ylabel("fluid force y [N/m]", color="C1")
    ax[-1].set_xlabel("time [s]")
    for a in ax:
        a.grid(alpha=0.3)
    ax[0].set_title(f"{s['title']}\n{s['particles']} particles, {s['steps']} steps, {s['precision']}, "
                    f"{s['wall_seconds']:.1f} s" + (" (DIVERGED)" if s.get("diverged") else ""), fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "series.png"), dpi=110)
    plt.close(fig)


def plot_particles(run, s, tank):
    """particles.png from the snapshots; returns the last one drawn, or None when there is none. Snapshots
    whose positions are all zero (the isph app writes its step-0 snapshot before the particles are
    placed) are left out; particles outside the tank (a run that blew up) are counted, not drawn."""
    path = os.path.join(run, "fields.h5")
    if not os.path.exists(path):  # runs before the field files had one name
        path = os.path.join(run, "particles.h5")
    if not os.path.exists(path):
        return None
    plt = pyplot()
    with open_h5(path) as f:
        steps = [k for k in snapshot_steps(f) if "position" in f[k] and np.any(f[k]["position"][...] != 0)]
        if not steps:
            return None
        pick = sorted({steps[0], steps[len(steps) // 2], steps[-1]}, key=steps.index)
        snaps = []
        for k in pick:
            g = f[k]
            x = g["position"][...]
            p = g["pressure"][...] if "pressure" in g else np.zeros(len(x))
            fs = g["free_surface"][...] if "free_surface" in g else np.zeros(len(x))
            snaps.append((int(k.split("_")[1]), x, p, fs))
    dt = s.get("dt", 0.0)
    if tank:
        lo, hi = np.array([0.0, 0.0]), np.array([tank["W"], tank["tank_height"]])
    else:  # the extent of the first snapshot (the particles at rest), with room for a surge
        x0 = snaps[0][1][:, :2]
        lo, hi = np.min(x0, axis=0), np.max(x0, axis=0) + 0.5 * np.ptp(x0, axis=0)
    span = np.maximum(hi - lo, 1e-12)
    lo, hi = lo - 0.05 * span, hi + 0.05 * span
    inside = [np.all(np.isfinite(x[:, :2]), axis=1) & np.all((x[:, :2] >= lo) & (x[:, :2] <= hi), axis=1)
              for _, x, _, _ in snaps]
    ps = [p[m] for (_, _, p, _), m in zip(snaps, inside) if np.any(m)]
    plo = min((float(np.min(p)) for p in ps), default=0.0)
    phi = max((float(np.max(p)) for p in ps), default=1.0)
    if not (np.isfinite(plo) and np.isfinite(phi)) or phi <= plo:
        plo, phi = 0.0, max(phi, plo, 0.0) + 1.0
    w = min(4.5, max(2.0, 3.2 * span[0] / span[1]))
    fig, ax = plt.subplots(1, len(snaps), figsize=(w * len(snaps) + 1.4, 3.8), squeeze=False)
    size = max(1.0, 4000.0 / max(len(snaps[0][1]), 1))
    sc = None
    for a, (step, x, p, fs), m in zip(ax[0], snaps, inside):
        sc = a.scatter(x[m, 0], x[m, 1], c=p[m], s=size, cmap="viridis", vmin=plo, vmax=phi)
        surf = m & (fs > 0.5)
        a.scatter(x[surf, 0], x[surf, 1], s=size * 2.5, facecolors="none", edgecolors="r", linewidths=0.4)
        a.set_aspect("equal")
        a.set_xlim(lo[0], hi[0])
        a.set_ylim(lo[1], hi[1])
        out = int(np.count_nonzero(~m))
        a.set_title(f"step {step}, t = {step * dt:.3g} s" + (f"\n{out} particles outside the tank" if out else ""), fontsize=8)
        a.set_xlabel("x [m]")
    ax[0][0].set_ylabel("y [m]" + (" (3D: side view)" if s.get("dimension") == 3 else ""))
    fig.colorbar(sc, ax=ax[0].tolist(), label="pressure [Pa] (red rings: free surface)")
    fig.savefig(os.path.join(run, "particles.png"), dpi=110)
    plt.close(fig)
    return snaps[-1]


def plot_pressure_profile(run, s, last, tank):
    plt = pyplot()
    step, x, p, fs = last
    y = x[:, 1]
    ok = np.isfinite(y) & np.isfinite(p)
    if tank:
        ok &= (y >= -0.05 * tank["tank_height"]) & (y <= 1.05 * tank["tank_height"])
    fig, ax = plt.subplots(figsize=(5.5, 4.4))
    ax.plot(p[ok & (fs < 0.5)], y[ok & (fs < 0.5)], ".", ms=3, label="particles")
    ax.plot(p[ok & (fs > 0.5)], y[ok & (fs > 0.5)], "r.", ms=3, label="free-surface particles (p = 0)")
    if tank:
        rho, g, H = tank["rho"], tank["g"], tank["H"]
        yy = np.linspace(0.0, H, 50)
        ax.plot(rho * g * (H - yy), yy, "k--", lw=1, label=f"rho g (H - y), H = {H:g} m")
    ax.set_xlabel("pressure [Pa]")
    ax.set_ylabel("y [m]")
    err = s.get("hydrostatic_pressure_error")
    ax.set_title(f"last snapshot (step {step}); pressure error averaged over {s.get('pressure_averaged_over_seconds', 0):.3g} s: "
                 + (f"{100 * err:.2f} %" if err is not None else "-"), fontsize=8)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "pressure_profile.png"), dpi=110)
    plt.close(fig)


def main():
    run = run_folder(run_parser(__doc__).parse_args().run)
    s = read_summary(run, cases=("hydrostatic", "dam_break"))
    c = load_csv(os.path.join(run, "series.csv"), required=("time", "ppe_iterations", "max_speed"))
    tank = scene_values(s)
    written = []
    plot_series(run, s, c)
    written.append("series.png")
    last = plot_particles(run, s, tank)
    if last is not None:
        written.append("particles.png")
    if s["case"] == "hydrostatic" and last is not None:
        plot_pressure_profile(run, s, last, tank)
        written.append("pressure_profile.png")
    if s["case"] == "dam_break" and len(s.get("front_positions", [])) >= 2:
        import isph_dam_break as dam

        runs = [dam.front_of(os.path.join(run, "summary.json"))]
        plot_fronts_quiet(dam, runs, os.path.join(run, "front.png"))
        written.append("front.png")
    print(f"plots in {run}: {', '.join(written)}")


def plot_fronts_quiet(dam, runs, png):
    """front.png as isph_dam_break.py draws it (with the shift fitted to Martin & Moyce), without its table."""
    import contextlib
    import io

    with contextlib.redirect_stdout(io.StringIO()):
        fits = dam.fit_table(runs, 1.0)
    dam.plot_fronts(runs, fits, png)


if __name__ == "__main__":
    guarded(main)
