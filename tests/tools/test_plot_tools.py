#!/usr/bin/python3
"""Every plot tool of tools/ on small outputs of every app (issue 33): each app runs briefly (one thread,
tiny scenes or a few steps) into a temporary folder, then each plot tool on it; a tool must exit 0 and
write the PNGs it names. The tools that read sweeps get copies of the sweep CSVs stored in docs/figures.
Every tool must also answer --help (exit 0), and a missing folder, a file given for a folder and another
app's folder must give one line on stderr naming the path, exit code 2 and no Python traceback.

  /usr/bin/python3 tests/tools/test_plot_tools.py --bin build/ci/bin [--source .] [--work DIR] [--verbose]

Exit codes: 0 all passed, 1 a check failed, 77 skipped (no matplotlib, numpy or h5py in this Python: use
Debian's /usr/bin/python3, which ci/lib.sh sets up). ctest: `ctest -R plot_tools` (label tools).
"""
import argparse
import glob
import importlib.util
import os
import shutil
import subprocess
import sys
import tempfile
import time

SKIP = 77


class Checks:
    def __init__(self, verbose):
        self.failures = []
        self.count = 0
        self.verbose = verbose

    def ok(self, what):
        self.count += 1
        if self.verbose:
            print(f"  ok   {what}")

    def fail(self, what, detail=""):
        self.count += 1
        self.failures.append(what)
        print(f"  FAIL {what}" + (f"\n{detail}" if detail else ""))


def run(cmd, env, cwd, timeout=120):
    t0 = time.monotonic()
    p = subprocess.run(cmd, env=env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=timeout)
    return p, time.monotonic() - t0


def tail(p, n=12):
    text = (p.stdout + p.stderr).strip().splitlines()
    return "\n".join("       | " + line for line in text[-n:])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True, help="folder of the app binaries (build/ci/bin)")
    ap.add_argument("--source", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."),
                    help="the repository (default: two folders up from this script)")
    ap.add_argument("--work", help="work folder (default: a temporary folder, removed when every check passed)")
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    src = os.path.abspath(a.source)
    a.bin = os.path.abspath(a.bin)
    tools = os.path.join(src, "tools")
    py = sys.executable
    lacking = [m for m in ("matplotlib", "numpy", "h5py") if importlib.util.find_spec(m) is None]
    if lacking:
        print(f"SKIP: {py} lacks {', '.join(lacking)} (the plot tools need matplotlib, numpy and h5py: use /usr/bin/python3)")
        return SKIP
    work = os.path.abspath(a.work) if a.work else tempfile.mkdtemp(prefix="polymech_plot_tools_")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive", MPLBACKEND="Agg")
    env.pop("POLYMECH_TRACEBACK", None)
    c = Checks(a.verbose)
    t_start = time.monotonic()

    def app(name, out, *args):
        """Runs an app into work/out; True when it exited 0 and wrote summary.json."""
        exe = os.path.join(a.bin, name)
        if not os.access(exe, os.X_OK):
            c.fail(f"{name}: {exe} not found (build the apps first)")
            return False
        p, dt = run([exe, "--out", os.path.join(work, out), "--threads", "1", "--quiet", *args], env, src)
        what = f"{name} {' '.join(args)} -> {out} ({dt:.1f} s)"
        if p.returncode != 0 or not os.path.isfile(os.path.join(work, out, "summary.json")):
            c.fail(what, f"       exit code {p.returncode}\n{tail(p)}")
            return False
        c.ok(what)
        return True

    def tool(script, args, pngs, folder=None):
        """Runs tools/<script> ARGS (paths relative to work); it must exit 0 and write each of pngs (relative
        to work/folder, or to work), new."""
        base = os.path.join(work, folder) if folder else work
        paths = [os.path.join(base, p) for p in pngs]
        for p in paths:
            if os.path.exists(p):
                os.remove(p)
        p, dt = run([py, os.path.join(tools, script), *args], env, work)
        what = f"{script} {' '.join(args)} ({dt:.1f} s)"
        missing = [os.path.relpath(x, work) for x in paths if not os.path.isfile(x) or os.path.getsize(x) == 0]
        if p.returncode != 0 or missing or "Traceback" in p.stderr:
            c.fail(what, f"       exit code {p.returncode}, missing: {', '.join(missing) or '-'}\n{tail(p)}")
        else:
            c.ok(what + ": " + ", ".join(pngs))

    def refused(script, args, path):
        """tools/<script> ARGS must exit 2 with one line naming `path` and no traceback."""
        p, _ = run([py, os.path.join(tools, script), *args], env, work)
        lines = [line for line in p.stderr.strip().splitlines() if line.strip()]
        what = f"{script} {' '.join(args)}: exit 2, one line naming {path}"
        if p.returncode != 2 or len(lines) != 1 or path not in lines[0] or "Traceback" in p.stderr:
            c.fail(what, f"       exit code {p.returncode}\n{tail(p)}")
        else:
            c.ok(what)

    scenes = os.path.join(src, "scenes")
    data = os.path.join(src, "tests")
    print(f"apps in {a.bin}, outputs in {work}")

    # --- the apps, briefly, and their plot tools ---------------------------------------------------------
    if app("mps_point_source", "mps", "--scene", os.path.join(data, "tools", "data", "point_source_small.toml")):
        tool("plot_mps_point_source.py", ["mps"], ["snapshots.png", "probe_A.png", "arrivals.png"], "mps")
    if app("mps_harmonics", "harmonics", "--scene", os.path.join(data, "tools", "data", "harmonics_tiny.toml")):
        tool("plot_mps_harmonics.py", ["harmonics"], ["time_history.png", "spectrum.png", "contact_states.png"], "harmonics")
    if app("pd_penetration", "penetration", "--scene", os.path.join(scenes, "pd", "penetration_303.toml"), "--accuracy", "draft",
           "--steps", "40"):
        tool("plot_pd_penetration.py", ["penetration"], ["projectile.png", "energy.png", "damage.png"], "penetration")
    if app("pd_tension", "tension", "--scene", os.path.join(scenes, "pd", "tension_conforming.toml")):
        tool("plot_pd_tension.py", ["tension"], ["tension.png"], "tension")
    if app("pd_tension", "tension_2d", "--scene", os.path.join(scenes, "pd", "tension_jittered.toml")):
        tool("plot_pd_tension.py", ["tension_2d"], ["tension.png"], "tension_2d")
    if app("dem_benchmark", "dem_test1", "--scene", os.path.join(scenes, "dem", "chung_ooi_test1.toml")):
        tool("plot_dem_benchmark.py", ["dem_test1/summary.json", "dem_test1/plots"], ["test12_hertz.png"], "dem_test1/plots")
    if app("dem_benchmark", "dem_all", "--scene", os.path.join(scenes, "dem", "chung_ooi_test1.toml"), "--all"):
        tool("plot_dem_benchmark.py", ["dem_all"],
             ["test12_hertz.png", "test3_restitution.png", "test4_rebound.png", "test4_centre_rebound.png"], "dem_all")
    if app("dem_pour", "wheel", "--scene", os.path.join(data, "dem", "data", "wheel_small.toml")):
        tool("plot_dem_pour.py", ["wheel"], ["pour.png", "particles.png", "wheel.png", "track_profile.png"], "wheel")
    if app("dem_pour", "heap", "--scene", os.path.join(data, "tools", "data", "heap_small.toml")):
        tool("plot_dem_pour.py", ["heap"], ["pour.png", "particles.png", "heap.png"], "heap")
    if app("efg", "efg_static", "--scene", os.path.join(scenes, "efg", "edge_crack_static.toml")):
        tool("plot_efg.py", ["efg_static"], ["j_paths.png", "stress.png"], "efg_static")
    if app("efg", "efg_dynamic", "--scene", os.path.join(scenes, "efg", "chen_centre_crack_dynamic.toml"), "--accuracy", "draft"):
        tool("plot_efg.py", ["efg_dynamic"], ["sif_history.png"], "efg_dynamic")
    if app("helmholtz", "helmholtz", "--scene", os.path.join(scenes, "helmholtz", "duct.toml")):
        tool("plot_helmholtz_run.py", ["helmholtz"], ["convergence.png", "profile.png"], "helmholtz")
    # the hydrostatic tank at standard accuracy (400 particles): its draft (100 particles, dt x 4) blows up
    if app("turek_hron", "cfd3", "--scene", os.path.join(scenes, "flow", "cfd3.toml"), "--accuracy", "draft", "--steps", "5"):
        tool("plot_turek_hron.py", ["cfd3"], ["forces.png"], "cfd3")
    if app("turek_hron", "harvester", "--scene", os.path.join(src, "tests", "io", "data", "harvester_partitioned.toml"), "--steps", "20"):
        tool("plot_turek_hron.py", ["harvester"], ["series.png"], "harvester")
    if app("isph", "hydrostatic", "--scene", os.path.join(scenes, "isph", "hydrostatic.toml"), "--accuracy", "standard",
           "--steps", "260"):
        tool("plot_isph.py", ["hydrostatic"], ["series.png", "particles.png", "pressure_profile.png"], "hydrostatic")
    if app("isph", "dam_break", "--scene", os.path.join(scenes, "isph", "dam_break.toml"), "--accuracy", "draft", "--steps", "160"):
        tool("plot_isph.py", ["dam_break"], ["series.png", "particles.png", "front.png"], "dam_break")
        tool("isph_dam_break.py", ["dam_break"], ["front.png"], "dam_break")
        tool("isph_dam_break.py", ["dam_break/summary.json:draft", "--png", "front_file.png"], ["front_file.png"])
    if app("isph", "floating", "--scene", os.path.join(scenes, "isph", "floating_cylinder_small.toml"), "--accuracy", "draft",
           "--steps", "100"):
        tool("plot_isph_body.py", ["floating", "floating:again", "--weight"], ["body.png"], "floating")

    # --- the tools that read sweeps or stored runs: copies of the CSVs in docs/figures -----------------------
    figures = os.path.join(src, "docs", "figures")
    sweeps = os.path.join(work, "sweeps")
    os.makedirs(sweeps, exist_ok=True)
    for rel in ("mps/mps_point_source.csv", "pd/cv_sweep.csv", "pd/velocity_sweep.csv", "helmholtz/helmholtz_duct.csv"):
        shutil.copy(os.path.join(figures, rel), sweeps)
    tool("plot_accuracy_cost.py", ["sweeps"], ["mps_point_source.png"], "sweeps")
    tool("plot_pd_sweeps.py", ["sweeps/cv_sweep.csv", "sweeps/velocity_sweep.csv"], ["cv_sweep.png", "velocity_sweep.png"], "sweeps")
    tool("plot_helmholtz_accuracy_cost.py", ["--cpu", "sweeps"], ["helmholtz_duct.png", "helmholtz_duct_cheapest.md"], "sweeps")
    # two resolutions of a harmonics probe record, as bench/sweep_mps_harmonics writes them
    for factor in (4, 2):
        with open(os.path.join(sweeps, f"crack_p_wave_series_double_c{factor}.csv"), "w") as f:
            f.write("time,intact,crack,window_start\n")
            for k in range(200):
                t = k * 2e-8
                f.write(f"{t},{1e-9 * (k % 25) / 25},{0.9e-9 * (k % 25) / 25},1e-6\n")
    tool("plot_harmonics_series.py", ["sweeps/crack_p_wave", "double"], ["crack_p_wave_series_double.png"], "sweeps")
    stored = os.path.join(work, "efg_stored")
    os.makedirs(stored, exist_ok=True)
    for f in glob.glob(os.path.join(figures, "efg", "chen_*_s*.*")):
        if f.endswith(".csv") or f.endswith(".json"):
            shutil.copy(f, stored)
    tool("plot_efg.py", ["efg_stored"], ["chen_dynamic.png", "chen_running.png"], "efg_stored")
    tool("efg_freund.py", [os.path.join(figures, "efg", "chen_freund_stationary"), os.path.join(figures, "efg", "chen_freund_v1000") + ":1000 m/s",
                           "--png", "freund.png"], ["freund.png"])

    # --- every tool: --help, and refusals ---------------------------------------------------------------------
    scripts = sorted(os.path.basename(f) for f in glob.glob(os.path.join(tools, "*.py")))
    # the shared helpers; the result comparisons and the cost table (not plots; they check their folders themselves)
    not_tools = {"plotting.py", "compare_results.py", "compare_binaries.py", "cost_table.py"}
    for script in scripts:
        if script in not_tools:
            continue
        p, _ = run([py, os.path.join(tools, script), "--help"], env, work)
        what = f"{script} --help"
        if p.returncode != 0 or not p.stdout.strip() or "Traceback" in p.stderr:
            c.fail(what, f"       exit code {p.returncode}\n{tail(p)}")
        else:
            c.ok(what)
    missing = os.path.join(work, "no_such_run")
    a_file = os.path.join(work, "mps", "summary.json")
    wrong = {  # a result folder each tool does not plot (another app's), where it plots result folders
        "plot_mps_point_source.py": "harmonics", "plot_mps_harmonics.py": "mps", "plot_pd_penetration.py": "tension",
        "plot_pd_tension.py": "penetration", "plot_dem_benchmark.py": "mps", "plot_dem_pour.py": "dem_test1",
        "plot_efg.py": "helmholtz", "plot_helmholtz_run.py": "efg_static", "plot_isph.py": "wheel",
        "isph_dam_break.py": "hydrostatic", "plot_isph_body.py": "dam_break", "plot_turek_hron.py": "mps",
    }
    for script in scripts:
        if script in not_tools:
            continue
        if script == "plot_efg_accuracy_cost.py":  # runs the app itself: a missing app or scene
            refused(script, ["--app", missing], missing)
            refused(script, ["--app", os.path.join(a.bin, "efg"), "--scene", missing], missing)
            continue
        args = [missing, missing + "_too"] if script == "efg_freund.py" else [missing]
        refused(script, args, missing)
        if script in wrong:
            if os.path.isfile(os.path.join(work, wrong[script], "summary.json")):
                refused(script, [wrong[script]], wrong[script])
            # a file for a folder: the shared check (plotting.run_folder) once, and the tools with their own
            if script in ("plot_mps_point_source.py", "plot_efg.py", "plot_isph_body.py") and os.path.isfile(a_file):
                refused(script, [a_file], a_file)

    print(f"{c.count - len(c.failures)} of {c.count} checks passed in {time.monotonic() - t_start:.1f} s")
    if c.failures:
        print(f"{len(c.failures)} failed (outputs kept in {work}):")
        for f in c.failures:
            print(f"  {f}")
        return 1
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
