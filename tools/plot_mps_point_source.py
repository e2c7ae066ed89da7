#!/usr/bin/python3
"""Plots of an mps_point_source run (seed 000 section 5.1).

  /usr/bin/python3 tools/plot_mps_point_source.py out/mps_point_source

writes into the run folder:
  snapshots.png   |u|/u0 at the snapshot steps (like the paper's Fig. 4)
  probe_A.png     |u|/u0 at probe A over time (like Fig. 5)
  arrivals.png    divergence (P) and rotation (S) at the wave-speed probes, with measured arrivals
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, open_h5, pyplot, read_summary, run_folder, run_parser, snapshot_steps  # noqa: E402


def lattice_image(points, values):
    """Particles sit on a square lattice (index j * nx + i): reshape to an image."""
    x = points[:, 0]
    nx = int(np.sum(np.isclose(points[:, 1], points[0, 1])))
    ny = len(x) // nx
    return values.reshape(ny, nx), (x.min(), x.max(), points[:, 1].min(), points[:, 1].max())


def plot_snapshots(run, out):
    """True when it wrote `out` (a run without snapshots after step 0 has none to draw)."""
    h5 = os.path.join(run, "fields.h5")
    if not os.path.exists(h5):
        return False
    plt = pyplot()
    with open_h5(h5) as f:
        points = f["mesh/points"][:]
        steps = [s for s in snapshot_steps(f) if int(s[5:]) > 0][:4]
        if not steps:
            return False
        fig, axes = plt.subplots(1, len(steps), figsize=(3.2 * len(steps), 5.2), squeeze=False)
        for ax, s in zip(axes[0], steps):
            img, extent = lattice_image(points, f[s]["abs_u_over_u0"][:])
            im = ax.imshow(img, origin="lower", extent=[e * 1e3 for e in extent], cmap="jet", vmin=0,
                           vmax=max(np.percentile(img, 99.9), 1e-12))
            ax.set_title(f"n = {int(s[5:])}")
            ax.set_xlabel("x1 [mm]")
        axes[0][0].set_ylabel("x3 [mm]")
        fig.colorbar(im, ax=axes[0].tolist(), shrink=0.7, label="|u| / u0")
        fig.savefig(out, dpi=110)
        plt.close(fig)
    return True


def main():
    run = run_folder(run_parser(__doc__, "out/mps_point_source").parse_args().run)
    summary = read_summary(run, cases=("mps_point_source",))
    if summary.get("diverged"):  # its summary names the reason; no probes.csv, its last snapshot is the last good state
        drawn = plot_snapshots(run, os.path.join(run, "snapshots.png"))
        print(f"{run}: the run diverged at step {summary.get('diverged_step')} ({summary.get('diverged_reason')}): "
              + ("snapshots.png only" if drawn else "nothing to plot"))
        return 0
    probes = load_csv(os.path.join(run, "probes.csv"), required=("time",))
    t_us = probes["time"] * 1e6
    u0 = 10e-9
    plt = pyplot()
    written = []

    if plot_snapshots(run, os.path.join(run, "snapshots.png")):
        written.append("snapshots.png")

    if "A_u1" in probes:
        fig, ax = plt.subplots(figsize=(7, 3.5))
        ax.plot(t_us, np.hypot(probes["A_u1"], probes["A_u3"]) / u0, lw=1)
        ax.set_xlabel("time [us]")
        ax.set_ylabel("|u| / u0 at A")
        ax.set_title(f"probe A, {summary['accuracy']} accuracy ({summary['particles']} particles)")
        ax.grid(alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(run, "probe_A.png"), dpi=110)
        plt.close(fig)
        written.append("probe_A.png")

    arr = summary.get("arrivals", {})
    fig, axes = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    for ax, wave, field, names in ((axes[0], "P", "divergence", ("P_near", "P_far")),
                                   (axes[1], "S", "rotation", ("S_near", "S_far"))):
        for name, key in zip(names, ("t_near", "t_far")):
            col = f"{name}_{field}"
            if col not in probes:
                continue
            s = probes[col]
            peak = np.max(np.abs(s)) or 1.0
            (line,) = ax.plot(t_us, s / peak, lw=1, label=f"{name} ({field})")
            t = arr.get(wave, {}).get(key)
            if t is not None:
                ax.axvline(t * 1e6, color=line.get_color(), ls="--", lw=0.8)
        measured = summary.get("cp_measured" if wave == "P" else "cs_measured")
        analytic = summary["cp_analytic" if wave == "P" else "cs_analytic"]
        if measured:
            ax.set_title(f"{wave} wave: measured {measured:.0f} m/s, analytic {analytic:.0f} m/s "
                         f"({100 * (measured - analytic) / analytic:+.2f} %)")
        ax.set_ylabel("normalised")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    axes[1].set_xlabel("time [us]")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "arrivals.png"), dpi=110)
    plt.close(fig)
    written.append("arrivals.png")
    print(f"plots in {run}: {', '.join(written)}")


if __name__ == "__main__":
    guarded(main)
