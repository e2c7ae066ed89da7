#!/usr/bin/python3
"""Accuracy against cost of the ISPH dam break (issue 12; promise 1): the surge front's error against
Martin & Moyce (1952) over the particle spacing l0 = a / n, in double and in float, with the CPU time of
each run.

    /usr/bin/python3 bench/sweep_isph_dam_break.py [--app build/ci/bin/isph]
        [--scene scenes/isph/dam_break.toml] [--across 10 20 40 80] [--precision double float]
        [--out out/sweep_isph_dam_break] [--plot-only]

Each run is the scene with fluid.spacing = a / n and dt scaled with the spacing from the scene's (2.5e-4 s at
a / 40), one thread, no snapshots. The error is taken at Martin & Moyce's points up to the far wall
(tools/isph_dam_break.py has the points and the fit): rms and largest relative error of Z(T) as run, and of
Z(T - dT) with the one shift dT fitted per run (the experiments' release; docs/VALIDATION.md, ISPH). Writes
OUT/sweep.csv (n, precision, spacing, dt, particles, steps, the errors, the shift, Z at T = 1, 2, 3, PPE
iterations, particles put back, CPU seconds) and OUT/accuracy_cost.png. Optional, outside ctest.
"""
import argparse
import os
import sys

import numpy as np

from sweep_runner import read_rows, run_scene, scene_value, write_rows

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tools"))
from isph_dam_break import MARTIN_MOYCE, WALL, best_shift, relative_errors  # noqa: E402


def run(app, text, work, n, precision):
    spacing0, dt0 = scene_value(text, "spacing"), scene_value(text, "dt")
    spacing = scene_value(text, "water_width") / n
    dt = dt0 * spacing / spacing0
    s, cpu = run_scene(app, text, work, {"spacing": spacing, "dt": dt}, precision)
    f = np.array(s["front_positions"], dtype=float)
    f = f[f[:, 1] < WALL]
    T, Z = f[:, 0], f[:, 1]
    pts = MARTIN_MOYCE[MARTIN_MOYCE[:, 0] <= T[-1]]
    e0 = relative_errors(T, Z, pts, 0.0)
    shift = best_shift(T, Z, pts)
    e = relative_errors(T, Z, pts, shift)
    return {"across": n, "precision_bits": 32 if precision == "float" else 64, "spacing": spacing, "dt": dt,
            "particles": s["particles"], "steps": s["steps"],
            "rms_error": float(np.sqrt(np.mean(e0 ** 2))), "max_error": float(np.abs(e0).max()),
            "shift_T": float(shift), "rms_error_shifted": float(np.sqrt(np.mean(e ** 2))),
            "max_error_shifted": float(np.abs(e).max()),
            "Z_T1": float(np.interp(1.0, T, Z)), "Z_T2": float(np.interp(2.0, T, Z)),
            "Z_T3": float(np.interp(3.0, T, Z)) if T[-1] >= 3.0 else float("nan"),
            "ppe_iterations_mean": s["ppe_iterations_mean"], "particles_put_back": s["particles_put_back_inside"],
            "diverged": int(bool(s.get("diverged", False))), "cpu_seconds": cpu}


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("sweep_isph_dam_break.py: no matplotlib, no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for bits, marker in ((64, "o"), (32, "s")):
        rs = sorted((r for r in rows if int(r["precision_bits"]) == bits), key=lambda r: r["cpu_seconds"])
        if not rs:
            continue
        name = "double" if bits == 64 else "float"
        t = [r["cpu_seconds"] for r in rs]
        ax.loglog(t, [100 * r["rms_error"] for r in rs], marker + "-", label=f"{name}, as run")
        ax.loglog(t, [100 * r["rms_error_shifted"] for r in rs], marker + "--", label=f"{name}, start shifted")
        for r in rs if bits == 64 else []:  # one label per spacing
            ax.annotate(f"a/{r['across']:g}", (r["cpu_seconds"], 100 * r["rms_error"]), fontsize=7,
                        textcoords="offset points", xytext=(4, 4))
    ax.set_xlabel("CPU time [s], one thread")
    ax.set_ylabel("rms error of the front against Martin & Moyce [%]")
    ax.set_title("ISPH dam break: surge-front error against cost")
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--app", default="build/ci/bin/isph")
    p.add_argument("--scene", default="scenes/isph/dam_break.toml")
    p.add_argument("--across", type=float, nargs="+", default=[10, 20, 40, 80], help="n in l0 = a / n")
    p.add_argument("--precision", nargs="+", choices=["double", "float"], default=["double", "float"])
    p.add_argument("--out", default="out/sweep_isph_dam_break")
    p.add_argument("--plot-only", action="store_true", help="redraw OUT/accuracy_cost.png from OUT/sweep.csv")
    a = p.parse_args()
    if a.plot_only:
        rows = read_rows(os.path.join(a.out, "sweep.csv"))
        plot(rows, os.path.join(a.out, "accuracy_cost.png"))
        return
    if not os.path.exists(a.app):
        sys.exit(f"sweep_isph_dam_break.py: {a.app} not found (cmake --build --preset ci --target isph)")
    text = open(a.scene).read()
    rows = []
    for n in a.across:
        for precision in a.precision:
            r = run(a.app, text, os.path.join(a.out, f"a{n:g}_{precision}"), n, precision)
            rows.append(r)
            print(f"a/{n:g} {precision}: {r['particles']} particles, {r['steps']} steps: rms {100 * r['rms_error']:.1f} %"
                  f" (shifted by dT = {r['shift_T']:.3f}: {100 * r['rms_error_shifted']:.1f} %), Z(1, 2, 3) = "
                  f"{r['Z_T1']:.3f} {r['Z_T2']:.3f} {r['Z_T3']:.3f}, {r['cpu_seconds']:.0f} CPU s", flush=True)
            write_rows(os.path.join(a.out, "sweep.csv"), rows)
    plot(rows, os.path.join(a.out, "accuracy_cost.png"))


if __name__ == "__main__":
    main()
