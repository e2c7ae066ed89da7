#!/usr/bin/python3
"""Accuracy against cost of the wheel on gravel (issue 13; promise 1): the rigid wheel's sinkage, vertical
and tractive force against the grain size (so the sphere count and the step) and the CPU time.

    /usr/bin/python3 bench/sweep_dem_wheel.py [--app build/ci/bin/dem_pour]
        [--scene scenes/dem/wheel_gravel_coarse.toml] [--scales 2 1.5] [--seeds 1]
        [--add-summary docs/figures/dem/wheel_coarse_summary.json:1] [--out out/sweep_dem_wheel] [--plot-only]

Each run is the scene with the grains' radii multiplied by SCALE and their count divided by SCALE^3 (the
same bed depth in the same bin; the time step follows the smallest grain), one thread, no snapshots.
SCALE = 1 is the scene (R 15-21 mm, 5 400 clumps, 55 min on one core); the paper's grains (R 5-7 mm) are
SCALE = 1/3, days on one core, so the sweep walks from the cheap coarse end toward the paper.
--add-summary FILE:SCALE adds a run made before (its wall time taken as its CPU time: a one-thread run).
Writes OUT/sweep.csv (scale, radii, clumps, spheres, dt, steps, sinkage, forces, torque, packing fraction,
bed height, CPU seconds) and OUT/accuracy_cost.png (sinkage and forces against CPU time and grain size,
with the paper's 53.6 mm). Optional, outside ctest.
"""
import argparse
import json
import os
import sys

from sweep_runner import read_rows, run_scene, scene_value, write_rows

PAPER_SINKAGE_MM = 53.6


def row_of(summary, scale, seed, radius_min, radius_max, cpu):
    return {"scale": scale, "seed": seed, "radius_min": radius_min, "radius_max": radius_max,
            "clumps": summary["clumps"], "spheres": summary["spheres"], "dt": summary["dt"],
            "steps": summary["steps"], "sinkage_mm": summary["sinkage_mm"],
            "tread_sinkage_mm": summary.get("tread_sinkage_mm", summary["sinkage_mm"]),
            "vertical_force": summary["vertical_force"], "tractive_force": summary["tractive_force"],
            "driving_torque": summary["driving_torque"], "packing_fraction": summary["packing_fraction"],
            "bed_height": summary["bed_height"], "cpu_seconds": cpu}


def run(app, text, work, scale, seed):
    rmin, rmax = scale * scene_value(text, "radius_min"), scale * scene_value(text, "radius_max")
    count = max(1, round(scene_value(text, "count") / scale ** 3))
    s, cpu = run_scene(app, text, work, {"radius_min": rmin, "radius_max": rmax, "count": count, "seed": seed,
                                         "snapshots": 0})
    if s.get("diverged"):
        raise RuntimeError(f"{work}: the run diverged: {s.get('diverged_reason', '?')}")
    return row_of(s, scale, seed, rmin, rmax, cpu)


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("sweep_dem_wheel.py: no matplotlib, no plot", file=sys.stderr)
        return
    rows = sorted(rows, key=lambda r: r["cpu_seconds"])
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    ax = axes[0]
    ax.semilogx([r["cpu_seconds"] for r in rows], [r["sinkage_mm"] for r in rows], "o", label="rigid wheel, this code")
    labelled = set()
    for r in rows:  # one label per grain size (the seeds' points sit together)
        if r["scale"] in labelled:
            continue
        labelled.add(r["scale"])
        ax.annotate(f"R {1e3 * r['radius_min']:.1f}-{1e3 * r['radius_max']:.1f} mm\n{int(r['spheres'])} spheres",
                    (r["cpu_seconds"], r["sinkage_mm"]), fontsize=7, textcoords="offset points", xytext=(5, -10))
    ax.axhline(PAPER_SINKAGE_MM, color="grey", ls="--", label="paper (FE tyre, R 5-7 mm): 53.6 mm")
    ax.set_xlabel("CPU time of the run (pour + wheel), one thread [s]")
    ax.set_ylabel("rim sinkage, steady stage [mm]")
    ax.set_title("Wheel on gravel: sinkage against cost")
    ax.legend(fontsize=8)
    ax = axes[1]
    rmean = [500 * (r["radius_min"] + r["radius_max"]) for r in rows]
    ax.plot(rmean, [r["vertical_force"] / 1e3 for r in rows], "o", label="vertical force [kN]")
    ax.plot(rmean, [r["tractive_force"] / 1e3 for r in rows], "s", label="tractive force [kN]")
    ax.axhline(10.163, color="grey", ls=":", label="load 10.163 kN")
    ax.axvline(6.0, color="grey", ls="--", lw=0.8, label="the paper's grains (mean R 6 mm)")
    ax.set_xlabel("mean grain radius [mm]")
    ax.set_ylabel("force, steady stage [kN]")
    ax.set_title("Forces against grain size")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--app", default="build/ci/bin/dem_pour")
    p.add_argument("--scene", default="scenes/dem/wheel_gravel_coarse.toml")
    p.add_argument("--scales", type=float, nargs="+", default=[2.0, 1.5])
    p.add_argument("--seeds", type=int, nargs="+", default=[1])
    p.add_argument("--add-summary", action="append", default=[], metavar="FILE:SCALE",
                   help="a run made before (a summary.json of the same scene at SCALE, one thread)")
    p.add_argument("--out", default="out/sweep_dem_wheel")
    p.add_argument("--plot-only", action="store_true", help="redraw OUT/accuracy_cost.png from OUT/sweep.csv")
    a = p.parse_args()
    csv_path = os.path.join(a.out, "sweep.csv")
    if a.plot_only:
        plot(read_rows(csv_path), os.path.join(a.out, "accuracy_cost.png"))
        return
    if not os.path.exists(a.app):
        sys.exit(f"sweep_dem_wheel.py: {a.app} not found (cmake --build --preset ci --target dem_pour)")
    text = open(a.scene).read()
    rows = []
    for spec in a.add_summary:
        path, _, scale = spec.rpartition(":")
        s = json.load(open(path))
        if s.get("threads") != 1:
            sys.exit(f"sweep_dem_wheel.py: {path} ran on {s.get('threads')} threads; the sweep compares one-thread runs")
        scale = float(scale)
        rows.append(row_of(s, scale, scene_value(text, "seed"), scale * scene_value(text, "radius_min"),
                           scale * scene_value(text, "radius_max"), s["wall_seconds"]))
    for scale in a.scales:
        for seed in a.seeds:
            r = run(a.app, text, os.path.join(a.out, f"scale{scale:g}_seed{seed}"), scale, seed)
            rows.append(r)
            print(f"scale {scale:g} (R {1e3 * r['radius_min']:.1f}-{1e3 * r['radius_max']:.1f} mm), seed {seed}: "
                  f"{int(r['spheres'])} spheres, {int(r['steps'])} steps: sinkage {r['sinkage_mm']:.1f} mm, vertical "
                  f"{r['vertical_force']:.0f} N, tractive {r['tractive_force']:.0f} N, {r['cpu_seconds']:.0f} CPU s",
                  flush=True)
            os.makedirs(a.out, exist_ok=True)
            write_rows(csv_path, rows)
    plot(rows, os.path.join(a.out, "accuracy_cost.png"))


if __name__ == "__main__":
    main()
