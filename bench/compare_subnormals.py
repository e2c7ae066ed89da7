#!/usr/bin/env python3
"""Every app's draft case with subnormal numbers flushed to zero (the default) and kept (issue 39): CPU time
of each, the largest relative difference of the results (tools/compare_results.py: every summary number,
CSV column and HDF5 dataset, relative to the dataset's largest value), and the share of subnormal values in
the kept run's state (POLYMECH_SUBNORMAL_CENSUS=100: every 100 steps the share of subnormal values in each
View of the model's state, in summary.json; apps without the shared run driver have none). Runs alternate (flush, keep, then keep, flush) so a
noisy machine slows both alike.

    /usr/bin/python3 bench/compare_subnormals.py [--bin build/release/bin] [--out out/subnormals]
        [--threads 1] [--repeats 2] [--cases mps_point_source,isph_dam_break] [--csv FILE]
    /usr/bin/python3 bench/compare_subnormals.py --bench build/release/bench [--bench-filter REGEX]
        [--bench-min-time 0.3] [--threads 1] [--repeats 2] [--csv FILE]

With --bench: every Google Benchmark binary of that folder (bench_*) instead, with POLYMECH_SUBNORMALS=flush
and =keep alternating, each benchmark's least CPU time per iteration of the repeats; rows: binary,
benchmark, cpu_flush, cpu_keep (ms), keep_over_flush.

Writes one row per case to --csv (default OUT/subnormals.csv): case, cpu_flush, cpu_keep (the least CPU
seconds over the repeats), keep_over_flush, max_relative_difference, the worst compared file, and the
largest subnormal share of any View of the kept run's state and which View.
"""
import argparse
import json
import os
import resource
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "bench"))
from sweep_runner import write_rows  # noqa: E402

# name, app, scene, extra options: every app's shipped draft case (the README's demo first; the Helmholtz
# solves at standard accuracy, their drafts take milliseconds)
CASES = [
    ("mps_point_source", "mps_point_source", "scenes/mps/point_source.toml", ["--accuracy", "draft"]),
    ("mps_point_source_float", "mps_point_source", "scenes/mps/point_source.toml", ["--accuracy", "draft", "--precision", "float"]),
    ("mps_crack_p_wave", "mps_harmonics", "scenes/mps/crack_p_wave.toml", ["--accuracy", "draft"]),
    ("mps_crack_s_wave", "mps_harmonics", "scenes/mps/crack_s_wave.toml", ["--accuracy", "draft"]),
    ("pd_penetration_303", "pd_penetration", "scenes/pd/penetration_303.toml", ["--accuracy", "draft"]),
    ("pd_tension_conforming", "pd_tension", "scenes/pd/tension_conforming.toml", ["--accuracy", "draft"]),
    ("dem_sphere_pour", "dem_pour", "scenes/dem/sphere_pour.toml", ["--accuracy", "draft"]),
    ("dem_chung_ooi_test1", "dem_benchmark", "scenes/dem/chung_ooi_test1.toml", []),
    ("efg_edge_crack_static", "efg", "scenes/efg/edge_crack_static.toml", []),
    ("efg_chen_dynamic", "efg", "scenes/efg/chen_centre_crack_dynamic.toml", ["--accuracy", "draft"]),
    ("helmholtz_cube", "helmholtz", "scenes/helmholtz/cube.toml", ["--accuracy", "standard"]),  # draft: 1 331 DoFs, ms
    ("helmholtz_duct", "helmholtz", "scenes/helmholtz/duct.toml", ["--accuracy", "standard"]),
    ("isph_dam_break", "isph", "scenes/isph/dam_break.toml", ["--accuracy", "draft"]),
    ("isph_floating_small", "isph", "scenes/isph/floating_cylinder_small.toml", ["--accuracy", "draft"]),
]


def run(app_path, scene, extra, out, mode, threads):
    """Runs one case into OUT with --subnormals MODE; returns its CPU seconds (user + system)."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive",
               POLYMECH_SUBNORMAL_CENSUS="100")
    env.pop("POLYMECH_SUBNORMALS", None)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([app_path, "--scene", os.path.join(ROOT, scene), "--out", out, "--threads", str(threads),
                        "--quiet", "--subnormals", mode] + extra, env=env, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        raise RuntimeError(f"{os.path.basename(app_path)} {scene} --subnormals {mode}: exit {r.returncode}\n{r.stderr[-2000:]}")
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def compare(a, b):
    """(largest relative difference, the line of the file where it is largest) by tools/compare_results.py."""
    r = subprocess.run([sys.executable, os.path.join(ROOT, "tools", "compare_results.py"), "--per-column", a, b],
                       stdout=subprocess.PIPE, text=True)
    worst, where = 0.0, ""
    for line in r.stdout.splitlines():
        if ": max relative difference " in line:
            v = float(line.split(": max relative difference ")[1].split()[0].rstrip(";"))
            if v >= worst:
                worst, where = v, line.strip()
        elif "differing or one-sided" in line or "missing in" in line:
            where = (where + " | " if where else "") + line.strip()
    return worst, where


def save(rows, path):
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    write_rows(path, rows)
    print(f"rows in {path}")


def census(out):
    """(largest subnormal share of any View at any census, 'View at step N') from OUT/summary.json; (nan, '')
    when the app took no census (it does not use the shared run driver)."""
    with open(os.path.join(out, "summary.json")) as f:
        j = json.load(f)
    best, where = float("nan"), ""
    for key in ("subnormal_census", "subnormal_census_intact", "subnormal_census_crack"):
        for view, c in j.get(key, {}).items():
            if not (best >= c["largest_share"]):
                best, where = c["largest_share"], f"{view} at step {c['at_step']}"
    return best, where


def run_bench(binary, mode, threads, flt, min_time):
    """{benchmark name: CPU ms per iteration} of one run of BINARY with POLYMECH_SUBNORMALS=MODE."""
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive",
               POLYMECH_SUBNORMALS=mode)
    args = [binary, "--benchmark_format=json", f"--benchmark_min_time={min_time}"]
    if flt:
        args.append(f"--benchmark_filter={flt}")
    r = subprocess.run(args, env=env, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    if r.returncode != 0:
        raise RuntimeError(f"{binary} (POLYMECH_SUBNORMALS={mode}): exit {r.returncode}")
    j = json.loads(r.stdout)
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    return {b["name"]: b["cpu_time"] * scale[b.get("time_unit", "ns")] for b in j["benchmarks"]
            if b.get("run_type", "iteration") == "iteration"}


def bench_main(a):
    rows = []
    binaries = sorted(f for f in os.listdir(a.bench) if f.startswith("bench_") and f != "bench_stream")
    for name in binaries:
        best = {"flush": {}, "keep": {}}
        for k in range(a.repeats):
            for mode in (("flush", "keep") if k % 2 == 0 else ("keep", "flush")):
                for b, t in run_bench(os.path.join(a.bench, name), mode, a.threads, a.bench_filter, a.bench_min_time).items():
                    best[mode][b] = min(t, best[mode].get(b, float("inf")))
        for b in best["flush"]:
            if b not in best["keep"]:
                continue
            row = {"binary": name, "benchmark": b, "cpu_flush": best["flush"][b], "cpu_keep": best["keep"][b],
                   "keep_over_flush": best["keep"][b] / best["flush"][b]}
            rows.append(row)
            print(f"{name} {b}: {row['cpu_flush']:.4g} ms flushed, {row['cpu_keep']:.4g} ms kept (x{row['keep_over_flush']:.2f})",
                  flush=True)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", default=os.path.join(ROOT, "build", "release", "bin"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "subnormals"))
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--repeats", type=int, default=2)
    ap.add_argument("--cases", default="", help="comma-separated case names (default: all)")
    ap.add_argument("--csv", default="")
    ap.add_argument("--bench", default="", help="a folder of Google Benchmark binaries: compare those instead")
    ap.add_argument("--bench-filter", default="")
    ap.add_argument("--bench-min-time", type=float, default=0.3)
    a = ap.parse_args()
    if a.bench:
        if not os.path.isdir(a.bench):
            print(f"compare_subnormals: error: --bench {a.bench} is not a folder", file=sys.stderr)
            sys.exit(2)
        rows = bench_main(a)
        save(rows, a.csv or os.path.join(a.out, "subnormals_bench.csv"))
        return
    names = [c for c in a.cases.split(",") if c]
    known = {c[0] for c in CASES}
    for n in names:
        if n not in known:
            print(f"compare_subnormals: error: unknown case '{n}' (allowed: {', '.join(sorted(known))})", file=sys.stderr)
            sys.exit(2)
    rows = []
    for name, app, scene, extra in CASES:
        if names and name not in names:
            continue
        app_path = os.path.join(a.bin, app)
        if not os.path.exists(app_path):
            print(f"compare_subnormals: error: {app_path} not found (build it: bash ci/build.sh release)", file=sys.stderr)
            sys.exit(2)
        cpu = {"flush": [], "keep": []}
        for k in range(a.repeats):
            for mode in (("flush", "keep") if k % 2 == 0 else ("keep", "flush")):
                cpu[mode].append(run(app_path, scene, extra, os.path.join(a.out, name, mode), mode, a.threads))
        diff, where = compare(os.path.join(a.out, name, "flush"), os.path.join(a.out, name, "keep"))
        keep_share, keep_view = census(os.path.join(a.out, name, "keep"))
        flush_share, _ = census(os.path.join(a.out, name, "flush"))
        row = {"case": name, "cpu_flush": min(cpu["flush"]), "cpu_keep": min(cpu["keep"]),
               "keep_over_flush": min(cpu["keep"]) / min(cpu["flush"]), "max_relative_difference": diff,
               "worst_file": where, "subnormal_share_keep": keep_share, "subnormal_view": keep_view,
               "subnormal_share_flush": flush_share}
        rows.append(row)
        print(f"{name}: CPU {row['cpu_flush']:.2f} s flushed, {row['cpu_keep']:.2f} s kept (x{row['keep_over_flush']:.2f}); "
              f"results differ by {diff:.3g} relative; subnormal share (kept) {100 * row['subnormal_share_keep']:.3g} % "
              f"({row['subnormal_view'] or 'no census'})", flush=True)
    save(rows, a.csv or os.path.join(a.out, "subnormals.csv"))


if __name__ == "__main__":
    main()
