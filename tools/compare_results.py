#!/usr/bin/env python3
"""Compare two result folders of the same app and scene (a run before and after a change).

    /usr/bin/python3 tools/compare_results.py OLD_DIR NEW_DIR [--rtol 0]

Every summary.json number (except timings), every CSV column and every HDF5 dataset is compared; the
largest relative difference per file is printed, and the exit code is 1 if any exceeds --rtol (0: the
results must be bitwise equal). Keys that exist on one side only are listed. --per-column: CSV values
relative to their column's largest magnitude (as HDF5 datasets always are). Used to show that a
refactor leaves results unchanged (docs/PERFORMANCE.md, docs/DEVELOPING.md).
"""
import argparse
import csv
import json
import math
import os
import sys

# summary keys that measure the machine, not the physics
TIMING_KEYS = {"wall_seconds", "shape_function_evaluations_per_second", "wall_seconds_intact", "wall_seconds_crack", "steps_per_second", "sphere_steps_per_second", "threads", "command",
               "scene",
               # how the run treated subnormal numbers (flush or keep): a setting of the run, like the threads
               "subnormals", "version", "commit",  # and the build that ran (apps::summary_header)
               # the ISPH app's timings
               "particle_steps_per_second", "ppe_share_of_step",
               # the EFG app's timings
               "assembly_seconds", "shape_seconds", "factor_seconds", "solve_seconds", "step_seconds_per_step", "j_seconds",
               # the flow apps' CPU split (turek_hron: seconds per part of the solve)
               "cpu_split", "fluid_split", "cpu_seconds_per_step"}


def rel(a, b):
    if a == b or (isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b)):
        return 0.0
    scale = max(abs(a), abs(b))
    return abs(a - b) / scale if scale > 0 else 0.0


def compare_json(a, b, path, out):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k in TIMING_KEYS or k.endswith(("_seconds", "_per_second")) or k.startswith("subnormal_census"):
                continue  # timings, and the subnormal census (a diagnostic of the run, issue 39)
            if k not in a or k not in b:
                out["only"].append(f"{path}.{k}")
                continue
            compare_json(a[k], b[k], f"{path}.{k}", out)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            out["only"].append(f"{path} (length {len(a)} vs {len(b)})")
            return
        for i, (x, y) in enumerate(zip(a, b)):
            compare_json(x, y, f"{path}[{i}]", out)
    elif isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        d = rel(float(a), float(b))
        if d > out["max"]:
            out["max"], out["where"] = d, path
    elif a != b:
        out["only"].append(f"{path} ({a!r} vs {b!r})")


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def compare_csv(pa, pb, out, per_column=False):
    """Each value against its counterpart; with PER_COLUMN, the difference relative to the column's largest
    magnitude (as HDF5 datasets are compared), so a probe's 1e-316 against 0 ahead of a wave front counts
    as what it is against the wave's amplitude."""
    ha, ra = read_csv(pa)
    hb, rb = read_csv(pb)
    if ha != hb or len(ra) != len(rb):
        out["only"].append(f"header or row count ({len(ra)} vs {len(rb)} rows)")
        return
    scale = [max([abs(r[j]) for r in ra + rb if math.isfinite(r[j])] + [0.0]) for j in range(len(ha))]
    for i, (x, y) in enumerate(zip(ra, rb)):
        for j, (p, q) in enumerate(zip(x, y)):
            if per_column and p != q and math.isfinite(p) and math.isfinite(q):
                d = abs(p - q) / scale[j] if scale[j] > 0 else 0.0
            else:
                d = rel(p, q)
            if d > out["max"]:
                out["max"], out["where"] = d, f"row {i}, column {ha[j]}"


def compare_h5(pa, pb, out):
    import h5py
    import numpy as np
    with h5py.File(pa, "r") as fa, h5py.File(pb, "r") as fb:
        names = []
        fa.visit(lambda n: names.append(n) if isinstance(fa[n], h5py.Dataset) else None)
        for n in names:
            if n not in fb:
                out["only"].append(n)
                continue
            x, y = np.asarray(fa[n], dtype=float), np.asarray(fb[n], dtype=float)
            if x.shape != y.shape:
                out["only"].append(f"{n} shape {x.shape} vs {y.shape}")
                continue
            scale = max(np.max(np.abs(x)) if x.size else 0.0, 1e-300)
            d = float(np.max(np.abs(x - y)) / scale) if x.size else 0.0
            if d > out["max"]:
                out["max"], out["where"] = d, n


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--rtol", type=float, default=0.0)
    ap.add_argument("--per-column", action="store_true",
                    help="CSV differences relative to the column's largest magnitude, not to each value")
    args = ap.parse_args()
    worst = 0.0
    failed = False
    for name in sorted(os.listdir(args.old)):
        pa, pb = os.path.join(args.old, name), os.path.join(args.new, name)
        if not os.path.isfile(pa):
            continue
        if not os.path.exists(pb):
            print(f"{name}: missing in {args.new}")
            failed = True
            continue
        out = {"max": 0.0, "where": "", "only": []}
        if name.endswith(".json"):
            with open(pa) as fa, open(pb) as fb:
                compare_json(json.load(fa), json.load(fb), "", out)
        elif name.endswith(".csv"):
            compare_csv(pa, pb, out, args.per_column)
        elif name.endswith(".h5"):
            compare_h5(pa, pb, out)
        else:
            continue
        worst = max(worst, out["max"])
        bad = out["max"] > args.rtol or out["only"]
        failed = failed or bool(bad)
        where = f" at {out['where']}" if out["max"] > 0 else ""
        print(f"{name}: max relative difference {out['max']:.3g}{where}" +
              (f"; differing or one-sided: {', '.join(out['only'][:6])}" if out["only"] else ""))
    print(f"largest relative difference: {worst:.3g} ({'within' if not failed else 'above'} rtol {args.rtol:g})")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
