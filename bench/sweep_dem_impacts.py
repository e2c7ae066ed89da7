#!/usr/bin/python3
"""Accuracy against cost of the Chung & Ooi impacts (issue 13; promise 1): how many time steps a contact
needs, in double and in float.

    /usr/bin/python3 bench/sweep_dem_impacts.py [--app build/ci/bin/dem_benchmark]
        [--steps-per-contact 40 60 100 200 400 1000 4000 20000] [--precision double float]
        [--out out/sweep_dem_impacts] [--plot-only]

For every steps_per_contact (dt = the Hertz contact time / it) and precision, one thread:
- test 1 (scenes/dem/chung_ooi_test1.toml, two spheres head on): the maximum force and the contact time
  against Hertz theory (the summary's own errors);
- test 4 (scenes/dem/chung_ooi_test4.toml, 17 incidence angles): the rebound angles against the closed form
  of gross sliding, tan(theta_r) = (tan(theta) - 3.5 mu (1 + e)) / e, where it holds (incidence above
  atan(3.5 mu (1 + e)) plus a margin of 2 degrees), and against the finest double run at every angle (below
  gross sliding no closed form exists: the sticking spring's history sets the angle).
The smallest default, 40, sits just above the refusal: the time-step limit allows 20 steps per Hertz contact
at twice the impact speed. Writes OUT/sweep.csv and OUT/accuracy_cost.png (errors against steps per contact and against CPU time).
The CPU time of one process (Kokkos start-up included) is what a user pays for the 17 impacts; the steps
are the work. Optional, outside ctest.
"""
import argparse
import math
import os
import sys

from sweep_runner import read_rows, run_scene, scene_value, write_rows

SCENE1 = "scenes/dem/chung_ooi_test1.toml"
SCENE4 = "scenes/dem/chung_ooi_test4.toml"


def sliding_rebound(text4):
    """(the incidence angle from which gross sliding holds, the closed form as a function of the angle)."""
    mu = scene_value(text4, "friction")
    e = scene_value(text4, "restitution")
    k = 3.5 * mu * (1 + e)
    onset = math.degrees(math.atan(k))
    return onset, lambda a: math.degrees(math.atan((math.tan(math.radians(a)) - k) / e))


def run(app, out, spc, precision):
    work = os.path.join(out, f"{precision}_spc{spc:g}")
    text1, text4 = open(SCENE1).read(), open(SCENE4).read()
    s1, cpu1 = run_scene(app, text1, os.path.join(work, "test1"), {"steps_per_contact": float(spc)}, precision)
    s4, cpu4 = run_scene(app, text4, os.path.join(work, "test4"), {"steps_per_contact": float(spc)}, precision)
    onset, closed = sliding_rebound(text4)
    angles = s4["test4_rebound_angles"]
    sliding = [abs(r - closed(a)) for a, r in angles if a >= onset + 2.0]
    return {"steps_per_contact": spc, "precision_bits": 32 if precision == "float" else 64,
            "test1_max_force_error": s1["test1_max_force_error"],
            "test1_contact_time_error": s1["test1_contact_time_error"],
            "test1_steps": s1["steps"], "test1_cpu_seconds": cpu1,
            "test4_sliding_max_abs_error_deg": max(sliding), "test4_steps": s4["steps"], "test4_cpu_seconds": cpu4,
            **{f"rebound_{a:g}": r for a, r in angles}}


def add_reference_errors(rows):
    """Each row's largest deviation over all angles from the finest double run's rebound angles."""
    ref = max((r for r in rows if r["precision_bits"] == 64), key=lambda r: r["steps_per_contact"])
    keys = [k for k in ref if k.startswith("rebound_")]
    for r in rows:
        r["test4_max_abs_deviation_from_finest_deg"] = max(abs(r[k] - ref[k]) for k in keys)
    return ref["steps_per_contact"]


def plot(rows, finest, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("sweep_dem_impacts.py: no matplotlib, no plot", file=sys.stderr)
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for bits, mark in ((64, "o-"), (32, "^--")):
        rs = sorted((r for r in rows if r["precision_bits"] == bits), key=lambda r: r["steps_per_contact"])
        if not rs:
            continue
        tag = "double" if bits == 64 else "float"
        n = [r["steps_per_contact"] for r in rs]
        tiny = 1e-12  # a zero error drawn at the floor of the log axis
        series = [("test 1 max force vs Hertz [-]", [abs(r["test1_max_force_error"]) for r in rs]),
                  ("test 1 contact time vs Hertz [-]", [abs(r["test1_contact_time_error"]) for r in rs]),
                  ("test 4 sliding rebound vs closed form [deg]", [r["test4_sliding_max_abs_error_deg"] for r in rs]),
                  (f"test 4 rebound vs {finest:g} steps/contact [deg]",
                   [r["test4_max_abs_deviation_from_finest_deg"] for r in rs])]
        coarser = [i for i, r in enumerate(rs) if r["steps_per_contact"] < finest]  # the reference run: no error
        for label, ys in series:
            keep = coarser if "steps/contact" in label else range(len(rs))
            axes[0].loglog([n[i] for i in keep], [max(ys[i], tiny) for i in keep], mark, label=f"{label}, {tag}", ms=4)
        t = [r["test4_cpu_seconds"] for r in rs]
        axes[1].loglog([t[i] for i in coarser], [rs[i]["test4_max_abs_deviation_from_finest_deg"] for i in coarser],
                       mark, label=f"all angles vs finest, {tag}", ms=4)
        axes[1].loglog(t, [max(r["test4_sliding_max_abs_error_deg"], tiny) for r in rs], mark[0] + ":",
                       label=f"sliding vs closed form, {tag}", ms=4)
        if bits == 64:
            for r in rs:
                axes[1].annotate(f"{r['steps_per_contact']:g}", (r["test4_cpu_seconds"],
                                 max(r["test4_sliding_max_abs_error_deg"], tiny)), fontsize=7,
                                 textcoords="offset points", xytext=(4, 4))
    axes[0].set_xlabel("time steps per Hertz contact time")
    axes[0].set_ylabel("error (relative, or degrees)")
    axes[0].set_title("Chung & Ooi tests 1 and 4: error against the step")
    axes[0].legend(fontsize=7)
    axes[1].set_xlabel("CPU time of test 4 (17 impacts, one process, one thread) [s]")
    axes[1].set_ylabel("largest rebound-angle error [deg]")
    axes[1].set_title("Test 4: rebound angle against cost (labels: steps/contact)")
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--app", default="build/ci/bin/dem_benchmark")
    p.add_argument("--steps-per-contact", type=float, nargs="+", default=[40, 60, 100, 200, 400, 1000, 4000, 20000])
    p.add_argument("--precision", nargs="+", choices=["double", "float"], default=["double", "float"])
    p.add_argument("--out", default="out/sweep_dem_impacts")
    p.add_argument("--plot-only", action="store_true", help="redraw OUT/accuracy_cost.png from OUT/sweep.csv")
    a = p.parse_args()
    csv_path = os.path.join(a.out, "sweep.csv")
    if a.plot_only:
        rows = read_rows(csv_path)
        plot(rows, add_reference_errors(rows), os.path.join(a.out, "accuracy_cost.png"))
        return
    if not os.path.exists(a.app):
        sys.exit(f"sweep_dem_impacts.py: {a.app} not found (cmake --build --preset ci --target dem_benchmark)")
    rows = []
    for precision in a.precision:
        for spc in a.steps_per_contact:
            rows.append(run(a.app, a.out, spc, precision))
    finest = add_reference_errors(rows)
    for r in rows:
        print(f"{'double' if r['precision_bits'] == 64 else 'float '} {r['steps_per_contact']:6g} steps/contact: "
              f"test 1 force {r['test1_max_force_error']:+.2e}, time {r['test1_contact_time_error']:+.2e}; "
              f"test 4 sliding {r['test4_sliding_max_abs_error_deg']:.3g} deg, vs finest "
              f"{r['test4_max_abs_deviation_from_finest_deg']:.3g} deg, {r['test4_cpu_seconds']:.2f} CPU s", flush=True)
    write_rows(csv_path, rows)
    plot(rows, finest, os.path.join(a.out, "accuracy_cost.png"))


if __name__ == "__main__":
    main()
