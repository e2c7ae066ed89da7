#!/usr/bin/python3
"""Plots of one dem_pour run (seed 002 paper 2: gravel poured into a bin, a heap, the wheel on gravel).

  /usr/bin/python3 tools/plot_dem_pour.py out/dem_pour

writes into the run folder:
  pour.png           kinetic energy, mean and top particle height against time (energy.csv), with the
                     packing fraction of the bed
  particles.png      the spheres of the last snapshot (fields.h5) seen from the side (x, z), coloured by
                     speed
  heap.png           a heap (scenes/dem/gravel_heap.toml): the surface height across the heap
                     (heap_profile.csv) and the angle of repose
  wheel.png          the wheel (scenes/dem/wheel_gravel*.toml): vertical force, tractive force and rim
                     sinkage against time since it was set down (wheel.csv; Figs. 8-10), the steady stage
                     whose means summary.json gives shaded
  track_profile.png  the wheel: the bed's surface across the track (track_profile.csv; Fig. 7)
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, open_h5, pyplot, read_summary, run_folder, run_parser, snapshot_steps  # noqa: E402


def fmt(x, spec):
    return "-" if x is None else format(x, spec)


def plot_pour(run, s):
    plt = pyplot()
    e = load_csv(os.path.join(run, "energy.csv"), required=("time", "kinetic_energy", "mean_height", "top_height"))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5.4), sharex=True)
    top.plot(e["time"], e["kinetic_energy"])
    if np.any(e["kinetic_energy"] > 0):
        top.set_yscale("log")
    top.set_ylabel("kinetic energy [J]")
    bottom.plot(e["time"], e["mean_height"] * 1e3, label="mean particle height")
    bottom.plot(e["time"], e["top_height"] * 1e3, label="top of the highest particle")
    bottom.set_ylabel("height [mm]")
    bottom.set_xlabel("time [s]")
    bottom.legend(fontsize=8)
    for a in (top, bottom):
        a.grid(alpha=0.3)
    phi = s.get("packing_fraction")
    top.set_title(f"{s['title']}\n{s['spheres']} spheres ({s['clumps']} clumps), {s['steps']} steps; packing fraction "
                  f"{fmt(phi, '.4f')}, bed height {1e3 * s['bed_height']:.1f} mm" + (" (DIVERGED)" if s.get("diverged") else ""),
                  fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "pour.png"), dpi=110)
    plt.close(fig)


def plot_particles(run, s):
    path = os.path.join(run, "fields.h5")
    if not os.path.exists(path):
        return False
    plt = pyplot()
    with open_h5(path) as f:
        steps = snapshot_steps(f)
        if not steps:
            return False
        g = f[steps[-1]]
        x = f["mesh/points"][...] + g["displacement"][...]
        v = np.linalg.norm(g["velocity"][...], axis=1)
        r = g["radius"][...] if "radius" in g else np.full(len(x), 1e-3)
        t = g.attrs.get("time")
    order = np.argsort(x[:, 1])  # far side (large y) drawn first: draw in decreasing y
    order = order[::-1]
    fig, ax = plt.subplots(figsize=(8, 4))
    ax.set_aspect("equal")
    lo, hi = x[:, [0, 2]].min(axis=0) - r.max(), x[:, [0, 2]].max(axis=0) + r.max()
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(min(lo[1], 0.0), hi[1])
    fig.canvas.draw()
    # marker area in points^2 for a disc of radius r metres at this axis scale
    pts_per_m = ax.get_window_extent().width / (hi[0] - lo[0]) * 72.0 / fig.dpi
    sc = ax.scatter(x[order, 0], x[order, 2], s=(math.pi * (r[order] * pts_per_m) ** 2), c=v[order], cmap="viridis",
                    edgecolors="k", linewidths=0.1)
    fig.colorbar(sc, ax=ax, label="speed [m/s]", shrink=0.8)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("z [m]")
    ax.set_title(f"side view, last snapshot (step {int(steps[-1][5:])}" + (f", t = {float(t):.3g} s" if t is not None else "") + ")",
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "particles.png"), dpi=110)
    plt.close(fig)
    return True


def plot_heap(run, s):
    plt = pyplot()
    h = load_csv(os.path.join(run, "heap_profile.csv"), required=("x", "surface_height"))
    fig, ax = plt.subplots(figsize=(6.4, 4))
    ax.plot(h["x"] * 1e3, h["surface_height"] * 1e3, "o-", ms=3)
    ax.set_aspect("equal")
    ax.set_xlabel("x [mm] (from the wall that stayed)")
    ax.set_ylabel("surface height [mm]")
    ax.set_title(f"heap released at {s.get('release_at', float('nan')):.3g} s: angle of repose "
                 f"{fmt(s.get('repose_angle_deg'), '.1f')} deg", fontsize=9)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "heap.png"), dpi=110)
    plt.close(fig)


def plot_wheel(run, s):
    plt = pyplot()
    w = load_csv(os.path.join(run, "wheel.csv"), required=("time_from_start", "sinkage_mm", "vertical_force", "tractive_force"))
    t = w["time_from_start"]
    fig, ax = plt.subplots(3, 1, figsize=(7, 7.2), sharex=True)
    ax[0].plot(t, w["vertical_force"], lw=0.8, label="vertical force")
    if "load" in w:
        ax[0].plot(t, w["load"], "k--", lw=0.8, label="load applied")
    ax[0].set_ylabel("vertical force [N]")
    ax[1].plot(t, w["tractive_force"], lw=0.8)
    ax[1].set_ylabel("tractive force [N]")
    ax[2].plot(t, w["sinkage_mm"], lw=0.8)
    ax[2].set_ylabel("rim sinkage [mm]")
    ax[2].set_xlabel("time since the wheel was set down [s]")
    steady = s.get("steady_stage_from")
    for a, key in zip(ax, ("vertical_force", "tractive_force", "sinkage_mm")):
        a.grid(alpha=0.3)
        if steady is not None and len(t):
            a.axvspan(steady, t[-1], color="0.92", zorder=0)
            if s.get(key) is not None:
                a.axhline(s[key], color="C3", lw=0.8, ls=":", label=f"steady mean {s[key]:.4g}")
                a.legend(fontsize=7, loc="best")
    ax[0].set_title(f"{s['title']}\nsteady stage (shaded): sinkage {fmt(s.get('sinkage_mm'), '.2f')} mm (paper, deformable tyre: "
                    f"{s.get('paper_sinkage_mm', '-')}), vertical {fmt(s.get('vertical_force'), '.4g')} N, tractive "
                    f"{fmt(s.get('tractive_force'), '.4g')} N", fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "wheel.png"), dpi=110)
    plt.close(fig)
    p = load_csv(os.path.join(run, "track_profile.csv"), required=("y", "surface_height"))
    fig, ax = plt.subplots(figsize=(6.4, 3.6))
    ax.plot(p["y"] * 1e3, p["surface_height"] * 1e3, "o-", ms=3)
    wheel = s.get("wheel", {})
    if "bed_level" in wheel:
        ax.axhline(1e3 * wheel["bed_level"], color="k", ls="--", lw=0.8, label="bed level under the wheel at the start")
        ax.legend(fontsize=8)
    ax.set_xlabel("y across the track [mm]")
    ax.set_ylabel("surface height [mm]")
    ax.set_title("the bed's surface across the track, over the run of the wheel (Fig. 7)", fontsize=9)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "track_profile.png"), dpi=110)
    plt.close(fig)


def main():
    run = run_folder(run_parser(__doc__, "out/dem_pour").parse_args().run)
    s = read_summary(run, cases=("dem_pour",))
    plot_pour(run, s)
    written = ["pour.png"]
    if plot_particles(run, s):
        written.append("particles.png")
    if os.path.exists(os.path.join(run, "heap_profile.csv")):
        plot_heap(run, s)
        written.append("heap.png")
    if os.path.exists(os.path.join(run, "wheel.csv")):
        plot_wheel(run, s)
        written += ["wheel.png", "track_profile.png"]
    print(f"plots in {run}: {', '.join(written)}")


if __name__ == "__main__":
    guarded(main)
