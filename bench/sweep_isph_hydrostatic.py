#!/usr/bin/python3
"""The ISPH hydrostatic tank's pressure error against the particle spacing and wall time (issue 12; promise 1),
with the paper's choices (density free-surface test, alpha = 5e-3) and with the divergence test and
alpha = 0.1 (docs/VALIDATION.md, ISPH stage 6).

    /usr/bin/python3 bench/sweep_isph_hydrostatic.py [--app build/ci/bin/isph] [--spacings 10 8 5 4 2.5]
        [--out out/sweep_isph_hydrostatic] [--plot-only]

Each run is scenes/isph/hydrostatic.toml with fluid.spacing = the given mm, dt = 5e-4 s (2.5e-4 s below
4 mm, where 5e-4 s is above the CFL limit), no snapshots, one thread. Writes OUT/sweep.csv (choice, spacing,
particles, steps, the averaged and instantaneous relative L2 errors, PPE iterations, particles put back,
wall seconds) and OUT/hydrostatic_convergence.png. Optional, outside ctest.
"""
import argparse
import csv
import json
import os
import re
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CHOICES = {"paper": {}, "divergence": {"alpha": "0.1", "surface_detection": '"divergence"'}}


def scene_text(spacing_mm, choice):
    text = open(os.path.join(ROOT, "scenes/isph/hydrostatic.toml")).read()
    l0 = spacing_mm * 1e-3
    dt = 5e-4 if spacing_mm >= 4 else 2.5e-4
    text = re.sub(r"(?m)^spacing = .*$", f"spacing = {l0!r}", text)
    text = re.sub(r"(?m)^dt = .*$", f"dt = {dt!r}", text)
    text = re.sub(r"(?m)^snapshot_every = .*$", "snapshot_every = 0", text)
    extra = CHOICES[choice]
    if "alpha" in extra:
        text = re.sub(r"(?m)^alpha = .*$", f"alpha = {extra['alpha']}", text)
    if "surface_detection" in extra:
        text = re.sub(r"(?m)^(surface_threshold = .*)$", r"\1\nsurface_detection = " + extra["surface_detection"], text)
    return text


def collect(work, choice, spacing_mm):
    s = json.load(open(os.path.join(work, "summary.json")))
    return {"choice": choice, "spacing_mm": spacing_mm, "particles": s["particles"], "steps": s["steps"],
            "error": s["hydrostatic_pressure_error"], "error_instantaneous": s["hydrostatic_pressure_error_instantaneous"],
            "ppe_iterations_mean": s["ppe_iterations_mean"], "particles_put_back": s["particles_put_back_inside"],
            "wall_seconds": s["wall_seconds"]}


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(1, 2, figsize=(10, 4))
    for choice, mark in (("paper", "o-"), ("divergence", "s-")):
        r = sorted((x for x in rows if x["choice"] == choice), key=lambda x: -x["spacing_mm"])
        if not r:
            continue
        ax[0].loglog([x["spacing_mm"] for x in r], [100 * x["error"] for x in r], mark, label=choice)
        ax[1].loglog([x["wall_seconds"] for x in r], [100 * x["error"] for x in r], mark, label=choice)
    for a in ax:
        a.axhline(1.0, color="grey", ls="--", lw=0.8)
        a.set_ylabel("pressure error, averaged over the last 0.5 s [%]")
        a.legend()
        a.grid(True, which="both", alpha=0.3)
    ax[0].set_xlabel("particle spacing l0 [mm]")
    ax[1].set_xlabel("wall time [s] (1 thread, shared machine)")
    fig.suptitle("ISPH hydrostatic tank 0.2 m x 0.2 m: pressure error against spacing and cost")
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--app", default=os.path.join(ROOT, "build/ci/bin/isph"))
    ap.add_argument("--spacings", type=float, nargs="+", default=[10, 8, 5, 4, 2.5])
    ap.add_argument("--out", default=os.path.join(ROOT, "out/sweep_isph_hydrostatic"))
    ap.add_argument("--plot-only", action="store_true")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for choice in CHOICES:
        for mm in a.spacings:
            work = os.path.join(a.out, f"{choice}_{mm:g}mm")
            if not a.plot_only:
                os.makedirs(work, exist_ok=True)
                scene = os.path.join(work, "scene.toml")
                open(scene, "w").write(scene_text(mm, choice))
                env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
                subprocess.run([a.app, "--scene", scene, "--threads", "1", "--quiet", "--out", work], check=True,
                               env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
            if os.path.exists(os.path.join(work, "summary.json")):
                rows.append(collect(work, choice, mm))
    with open(os.path.join(a.out, "sweep.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(a.out, "hydrostatic_convergence.png"))
    for r in rows:
        print(f"{r['choice']:>10} {r['spacing_mm']:5g} mm  {r['particles']:6d} particles  error {100 * r['error']:.3f} %")


if __name__ == "__main__":
    main()
