#!/usr/bin/python3
"""Plots of one pd_penetration run (seed 003 Figs. 4-5): projectile velocity and energies over time,
and the damage in a cut through the plate along the projectile's axis.

  /usr/bin/python3 tools/plot_pd_penetration.py out/pd_penetration

Writes projectile.png, energy.png and damage.png into the run folder.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, open_h5, pyplot, read_summary, run_folder, run_parser, snapshot_steps  # noqa: E402


def main():
    run = run_folder(run_parser(__doc__, "out/pd_penetration").parse_args().run)
    summary = read_summary(run, cases=("pd_penetration",))
    p = load_csv(os.path.join(run, "projectile.csv"), required=("time", "velocity", "nose_position"))
    e = load_csv(os.path.join(run, "energy.csv"), required=("time", "total"))
    plt = pyplot()
    t = p["time"] * 1e6

    fig, ax = plt.subplots(1, 2, figsize=(10, 3.8))
    ax[0].plot(t, -p["velocity"], label="NOSB-PD")
    if summary.get("experiment_residual_velocity"):
        ax[0].axhline(summary["experiment_residual_velocity"], color="k", ls="--", label="experiment (residual)")
    ax[0].set_xlabel("time [us]")
    ax[0].set_ylabel("projectile velocity [m/s]")
    ax[0].legend(fontsize=8)
    ax[0].grid(alpha=0.3)
    ax[1].plot(t, p["nose_position"] * 1e3)
    ax[1].axhline(-12.0, color="k", ls=":", label="plate bottom")
    ax[1].set_xlabel("time [us]")
    ax[1].set_ylabel("nose position [mm]")
    ax[1].legend(fontsize=8)
    ax[1].grid(alpha=0.3)
    vr = summary["residual_velocity"]  # null when the run diverged
    fig.suptitle(f"v0 = {summary['initial_velocity']} m/s -> {'-' if vr is None else f'{vr:.1f}'} m/s "
                 f"({summary['particles']} particles, c_v = {summary['c_v']})")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "projectile.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(6.5, 4))
    te = e["time"] * 1e6
    for key, label in (("projectile_kinetic", "projectile kinetic"), ("kinetic", "plate kinetic"), ("strain", "elastic"),
                       ("plastic", "plastic work"), ("viscous_dissipated", "velocity viscosity"),
                       ("hourglass_work", "hourglass work"), ("contact", "contact"), ("short_range", "short-range springs")):
        if key in e and np.any(e[key] != 0):
            ax.plot(te, e[key], label=label)
    ax.plot(te, e["total"], "k--", label="total")
    ax.set_xlabel("time [us]")
    ax.set_ylabel("energy [J]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "energy.png"), dpi=110)

    with open_h5(os.path.join(run, "fields.h5")) as h:
        x = h["mesh/points"][...]
        steps = snapshot_steps(h)
        if not steps:
            print(f"plots: {run}/projectile.png, energy.png (fields.h5 has no snapshot: no damage.png)")
            return
        last = h[steps[-1]]
        u = last["displacement"][...]
        d = last["damage"][...] if "damage" in last else np.zeros(len(x))
    y = x + u
    cut = np.abs(x[:, 1]) < 0.6 * summary["spacing"] + 1e-12  # a slab around the x-z plane through the axis
    fig, ax = plt.subplots(figsize=(8, 3.4))
    sc = ax.scatter(y[cut, 0] * 1e3, y[cut, 2] * 1e3, c=d[cut], s=4, cmap="inferno", vmin=0, vmax=1)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("z [mm]")
    fig.colorbar(sc, ax=ax, label="damage")
    ax.set_title(f"damage in the plane through the axis at t = {summary['simulated_time'] * 1e6:.0f} us (seed 003 Fig. 4)")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "damage.png"), dpi=110)
    print(f"plots: {run}/projectile.png, energy.png, damage.png")


if __name__ == "__main__":
    guarded(main)
