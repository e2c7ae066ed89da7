#!/usr/bin/python3
"""Accuracy against cost of the ISPH floating cylinder (issue 12; promise 1): the equilibrium draft of a
cylinder of density ratio 0.8 against Archimedes, over the particle spacing (particles across the
cylinder), with the CPU time of each run.

    /usr/bin/python3 bench/sweep_isph_float.py [--app build/ci/bin/isph]
        [--scene scenes/isph/floating_cylinder_small.toml] [--across 4 5 8 10 12.5] [--out out/sweep_isph_float]
        [--precision double|float] [--plot-only]

Each run is the scene with fluid.spacing = D / across and dt = 0.1 s/m x spacing (1e-3 s at 1 cm: CFL 0.4 at
the surge speed allows 1.2e-3 s; --dt-per-spacing changes the 0.1), one thread, no snapshots. Writes OUT/sweep.csv (across, spacing, dt,
particles, steps, both draft readings and their errors against Archimedes, the body's height scatter over the
averaging window, PPE iterations, particles put back, CPU seconds) and OUT/accuracy_cost.png. Optional, outside
ctest.
"""
import argparse
import csv
import os
import sys

from sweep_runner import read_rows, run_scene, scene_value, write_rows


def run(app, text, work, across, dt_per_spacing=0.1, precision="double"):
    D = scene_value(text, "diameter")
    spacing = D / across
    dt = dt_per_spacing * spacing
    s, cpu = run_scene(app, text, work, {"spacing": spacing, "dt": dt}, precision)
    arch = s["archimedes_draft_over_diameter"]
    # the body's height over the averaging window (the series' last draft_average_last seconds)
    rows = list(csv.DictReader(open(os.path.join(work, "series.csv"))))
    end = float(rows[-1]["time"])
    window = scene_value(text, "draft_average_last")
    ys = [float(r["body_y"]) for r in rows if float(r["time"]) >= end - window]
    mean = sum(ys) / len(ys)
    scatter = (sum((y - mean) ** 2 for y in ys) / len(ys)) ** 0.5
    return {"across": across, "precision_bits": 32 if precision == "float" else 64, "spacing": spacing, "dt": dt, "particles": s["particles"], "steps": s["steps"],
            "draft_volume": s["draft_over_diameter"], "draft_surface": s["draft_over_diameter_surface_particles"],
            "archimedes": arch, "error_volume": s["draft_over_diameter"] / arch - 1,
            "error_surface": s["draft_over_diameter_surface_particles"] / arch - 1,
            "body_y_scatter_over_D": scatter / D, "ppe_iterations_mean": s["ppe_iterations_mean"],
            "particles_put_back": s["particles_put_back_inside"], "cpu_seconds": cpu}


def plot(rows, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("sweep_isph_float.py: no matplotlib, no plot", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    # rows of one precision, or of both (--plot-only on the CSVs of a double and a float sweep concatenated)
    groups = sorted({int(r.get("precision_bits", 64)) for r in rows}, reverse=True)
    for bits in groups:
        rs = sorted((r for r in rows if int(r.get("precision_bits", 64)) == bits), key=lambda r: r["cpu_seconds"])
        tag = "" if len(groups) == 1 else (", double" if bits == 64 else ", float")
        t = [r["cpu_seconds"] for r in rs]
        ax.semilogx(t, [100 * r["error_volume"] for r in rs], "o-" if bits == 64 else "^-",
                    label="level from the water's volume" + tag)
        ax.semilogx(t, [100 * r["error_surface"] for r in rs], "s--" if bits == 64 else "v--",
                    label="level from the surface particles" + tag)
        if bits == groups[0]:
            for r in rs:
                ax.annotate(f"D/l0={r['across']:g}", (r["cpu_seconds"], 100 * r["error_volume"]), fontsize=7,
                            textcoords="offset points", xytext=(4, 4))
    for y in (-2, 2):
        ax.axhline(y, color="grey", lw=0.8, ls=":", label="issue: +-2 %" if y < 0 else None)
    ax.axhline(0, color="black", lw=0.6)
    ax.set_xlabel("CPU time [s], one thread")
    ax.set_ylabel("draft / Archimedes - 1 [%]")
    ax.set_title("ISPH floating cylinder (density ratio 0.8): draft against cost")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--app", default="build/ci/bin/isph")
    p.add_argument("--scene", default="scenes/isph/floating_cylinder_small.toml")
    p.add_argument("--across", type=float, nargs="+", default=[4, 5, 8, 10, 12.5])
    p.add_argument("--out", default="out/sweep_isph_float")
    p.add_argument("--dt-per-spacing", type=float, default=0.1,
                   help="dt / spacing in s/m (0.1: 1e-3 s at 1 cm; the held body's excess force falls with dt)")
    p.add_argument("--precision", choices=["double", "float"], default="double",
                   help="floating-point precision of the kernels (the app's --precision)")
    p.add_argument("--plot-only", action="store_true",
                   help="redraw OUT/accuracy_cost.png from OUT/sweep.csv (rows of both precisions: one curve each)")
    a = p.parse_args()
    if a.plot_only:
        rows = read_rows(os.path.join(a.out, "sweep.csv"))
        plot(rows, os.path.join(a.out, "accuracy_cost.png"))
        return
    if not os.path.exists(a.app):
        sys.exit(f"sweep_isph_float.py: {a.app} not found (cmake --build --preset ci --target isph)")
    text = open(a.scene).read()
    rows = []
    for n in a.across:
        r = run(a.app, text, os.path.join(a.out, f"across{n:g}"), n, a.dt_per_spacing, a.precision)
        rows.append(r)
        print(f"D/l0 = {n:g}: {r['particles']} particles, {r['steps']} steps: draft {r['draft_volume']:.4f} "
              f"({100 * r['error_volume']:+.1f} %), surface particles {r['draft_surface']:.4f} "
              f"({100 * r['error_surface']:+.1f} %), {r['cpu_seconds']:.0f} CPU s", flush=True)
        write_rows(os.path.join(a.out, "sweep.csv"), rows)
    plot(rows, os.path.join(a.out, "accuracy_cost.png"))


if __name__ == "__main__":
    main()
