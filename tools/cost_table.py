#!/usr/bin/env python3
"""Predicted against measured wall time of every shipped scene (docs/PERFORMANCE.md, "Cost estimate
against measured time").

    /usr/bin/python3 tools/cost_table.py BIN RESULTS [--accuracy draft] [--markdown]

BIN holds the apps (build/<preset>/bin); RESULTS is the folder of tools/run_drafts.sh or the --work folder of tools/compare_binaries.py
(RESULTS/<app>/<scene>/new/summary.json, runs with --threads 1). For each scene the prediction is what
`polymech --scene FILE --accuracy A --dry-run` prints ("predicted wall time about X s"), the
measurement the summary's wall_seconds (for mps_harmonics: both runs). Prints one row per scene with
the ratio measured / predicted; rows outside 0.77..1.3 (30 %) are marked.
"""
import argparse
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
UNITS = {"s": 1.0, "min": 60.0, "h": 3600.0, "ms": 1e-3}


def predicted(binary, scene, accuracy):
    # --threads 1: the measured runs are on one thread (without it the estimate is scaled to the host's threads)
    p = subprocess.run([binary, "--scene", scene, "--accuracy", accuracy, "--dry-run", "--threads", "1"], stdout=subprocess.PIPE,
                       stderr=subprocess.STDOUT, text=True)
    m = re.search(r"predicted wall time about ([0-9.eE+-]+) (ms|s|min|h)", p.stdout)
    return float(m.group(1)) * UNITS[m.group(2)] if m else None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bin")
    ap.add_argument("results")
    ap.add_argument("--accuracy", default="draft")
    ap.add_argument("--markdown", action="store_true")
    a = ap.parse_args()
    for d, what in ((a.bin, "a folder of app binaries (build/<preset>/bin)"), (a.results, "the --work folder of compare_binaries.py")):
        if not os.path.isdir(d):
            print(f"cost_table: {d}: not {what}", file=sys.stderr)
            sys.exit(2)
    rows = []
    for app in sorted(d for d in os.listdir(a.results) if os.path.isdir(os.path.join(a.results, d))):
        for stem in sorted(os.listdir(os.path.join(a.results, app))):
            summary = os.path.join(a.results, app, stem, "new", "summary.json")
            folder = [f for f in os.listdir(os.path.join(ROOT, "scenes")) if os.path.exists(os.path.join(ROOT, "scenes", f, stem + ".toml"))]
            if not os.path.exists(summary) or not folder:
                continue
            scene = os.path.join("scenes", folder[0], stem + ".toml")
            with open(summary) as f:
                j = json.load(f)
            wall = j.get("wall_seconds")
            if wall is None and "solve_seconds" in j:  # helmholtz, cook_membrane: set-up and solve, no wall_seconds
                wall = j.get("setup_seconds", 0.0) + j["solve_seconds"]
            pred = predicted(os.path.join(a.bin, "polymech"), os.path.join(ROOT, scene), a.accuracy)
            ratio = wall / pred if wall and pred else None
            flag = "" if ratio is None or 1 / 1.3 <= ratio <= 1.3 else "  <-- off by more than 30 %"
            rows.append((app, scene, pred, wall, ratio, flag))
    if a.markdown:
        print("| app | scene | predicted [s] | measured [s] | measured / predicted |")
        print("| --- | --- | ---: | ---: | ---: |")
        for app, scene, pred, wall, ratio, _ in rows:
            fmt = lambda x: "-" if x is None else f"{x:.3g}"
            print(f"| {app} | `{scene}` | {fmt(pred)} | {fmt(wall)} | {fmt(ratio)} |")
    else:
        for app, scene, pred, wall, ratio, flag in rows:
            fmt = lambda x: "     -" if x is None else f"{x:8.3g}"
            print(f"{app:17s} {scene:48s} {fmt(pred)} {fmt(wall)} {fmt(ratio)}{flag}")


if __name__ == "__main__":
    main()
