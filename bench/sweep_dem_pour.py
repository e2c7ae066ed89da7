#!/usr/bin/python3
"""Accuracy against cost of the DEM pour (issue 13; promise 1): the packing fraction of a poured bed
against the time step, with the scatter of the random packing measured by repeating each step size
over several seeds (a pour is chaotic: the bed of one seed is one sample of the packing).

    /usr/bin/python3 bench/sweep_dem_pour.py [--app build/ci/bin/dem_pour] [--scene scenes/dem/sphere_pour.toml]
        [--accuracy standard] [--safety 0.8 0.4 0.2 0.1] [--seeds 1 2 3] [--out out/sweep_dem_pour]

Runs `dem_pour` (1 thread, no snapshots) for every time-step safety factor (dt = factor x the Hertz /
Rayleigh limit) and seed; writes OUT/sweep.csv (safety, dt, seed, packing_fraction, final kinetic
energy, steps, CPU seconds) and OUT/accuracy_cost.png (packing fraction, mean and seed range, against
the CPU time). Optional, outside ctest.
"""
import argparse
import json
import os
import re
import resource
import subprocess
import sys


def run(app, scene_text, work, safety, seed, accuracy):
    os.makedirs(work, exist_ok=True)
    text = re.sub(r"(?m)^seed = .*$", f"seed = {seed}", scene_text)
    text = re.sub(r"(?m)^snapshots = .*$", "snapshots = 0", text)
    text = re.sub(r"(?m)^(duration = .*)$", rf"\1\ndt_safety = {safety}", text)
    scene = os.path.join(work, "scene.toml")
    with open(scene, "w") as f:
        f.write(text)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive")
    subprocess.run([app, "--scene", scene, "--accuracy", accuracy, "--threads", "1", "--quiet", "--out", work],
                   check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    s = json.load(open(os.path.join(work, "summary.json")))
    return {"safety": safety, "dt": s["dt"], "seed": seed, "packing_fraction": s["packing_fraction"],
            "final_kinetic_energy": s["final_kinetic_energy"], "steps": s["steps"], "cpu_seconds": cpu}


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--app", default="build/ci/bin/dem_pour")
    p.add_argument("--scene", default="scenes/dem/sphere_pour.toml")
    p.add_argument("--accuracy", default="standard")
    p.add_argument("--safety", type=float, nargs="+", default=[0.8, 0.4, 0.2, 0.1])
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3])
    p.add_argument("--out", default="out/sweep_dem_pour")
    a = p.parse_args()
    if not os.path.exists(a.app):
        sys.exit(f"sweep_dem_pour.py: {a.app} not found (cmake --build --preset ci --target dem_pour)")
    scene_text = open(a.scene).read()
    rows = []
    for safety in a.safety:
        for seed in a.seeds:
            r = run(a.app, scene_text, os.path.join(a.out, f"s{safety}_seed{seed}"), safety, seed, a.accuracy)
            rows.append(r)
            print(f"dt_safety {safety}: dt {r['dt']:.3g} s, seed {seed}: packing {r['packing_fraction']:.4f}, "
                  f"{r['steps']} steps, {r['cpu_seconds']:.1f} CPU s", flush=True)
    keys = list(rows[0].keys())
    with open(os.path.join(a.out, "sweep.csv"), "w") as f:
        f.write(",".join(keys) + "\n")
        for r in rows:
            f.write(",".join(repr(r[k]) for k in keys) + "\n")
    summary = []
    for safety in a.safety:
        sel = [r for r in rows if r["safety"] == safety]
        phi = [r["packing_fraction"] for r in sel]
        summary.append((safety, sel[0]["dt"], sum(phi) / len(phi), min(phi), max(phi),
                        sum(r["cpu_seconds"] for r in sel) / len(sel)))
    print("safety, dt, packing mean, min, max, CPU s per run")
    for s in summary:
        print(f"{s[0]}, {s[1]:.3g}, {s[2]:.4f}, {s[3]:.4f}, {s[4]:.4f}, {s[5]:.1f}")
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5.5, 3.8))
        for s in summary:
            ax.errorbar(s[5], s[2], yerr=[[s[2] - s[3]], [s[4] - s[2]]], fmt="o", capsize=3, label=f"dt = {s[1]:.2g} s")
        ax.set_xscale("log")
        ax.set_xlabel("CPU seconds per run (1 thread)")
        ax.set_ylabel("packing fraction (mean, seed range)")
        ax.set_title("DEM pour: packing fraction against cost")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(a.out, "accuracy_cost.png"), dpi=120)
    except ImportError:
        print("matplotlib not found: no plot")


if __name__ == "__main__":
    main()
