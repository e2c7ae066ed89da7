#!/usr/bin/python3
"""The command line of every app (issue 33): each app binary is run with malformed, missing, duplicated
and extreme options, and must answer with exit code 2 and one line on stderr that starts with
"<app>: error:" and is shorter than 300 characters: no crash (no exit code >= 128 or signal), nothing
created in the output folder or the working folder. --help and --version exit 0 (--version prints
"<app> polymech <version> (<commit>)"), and a good --dry-run exits 0 without creating its --out.
The polymech app hands the options to the app of the scene's kind, which then reports them.

  /usr/bin/python3 tests/cli/test_cli.py --bin build/ci/bin [--source .] [--verbose]

Standard library only. Exit code 0: all passed, 1: a check failed. ctest: `ctest -L cli`.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

# each app with a small scene (relative to the repository) whose --dry-run is quick
APPS = {
    "mps_point_source": "scenes/mps/point_source.toml",
    "mps_harmonics": "tests/mps/data/harmonics_small.toml",
    "pd_penetration": "scenes/pd/penetration_303.toml",
    "pd_tension": "scenes/pd/tension_conforming.toml",
    "dem_pour": "tests/dem/data/pour_small.toml",
    "dem_benchmark": "scenes/dem/chung_ooi_test1.toml",
    "efg": "scenes/efg/edge_crack_static.toml",
    "helmholtz": "scenes/helmholtz/cube.toml",
    "isph": "scenes/isph/hydrostatic.toml",
    "piezo_harvester": "scenes/piezo/pvdf_bender.toml",
    "turek_hron": "scenes/flow/cfd1.toml",
    "cook_membrane": "scenes/solid/cook_membrane.toml",
    "polymech": "scenes/pd/tension_lattice.toml",  # run by pd_tension
}
DISPATCHED = {"polymech": "pd_tension"}  # the app that reports the options polymech hands on

# options an app refuses because they mean nothing there (issue 33 item 8): (arguments, text of the error line);
# hidden from --help, refused with exit 2 even with --dry-run, never accepted and ignored
REFUSED = {
    "helmholtz": [(["--steps", "5"], "--steps 5: does not apply: a frequency-domain solve", True)],
    "cook_membrane": [(["--steps", "5"], "--steps 5: does not apply: Cook's membrane is one linear solve", True)],
    "pd_tension": [(["--steps", "5"], "--steps 5: does not apply: the pull lasts", True)],
    "dem_benchmark": [(["--steps", "5"], "--steps 5: does not apply", True),
                      (["--accuracy", "draft"], "--accuracy draft: does not apply", True)],
    "efg": [(["--steps", "5"], "--steps 5: does not apply", False)],  # a static scene; the dynamic ones take it
    "turek_hron": [(["--steps", "5"], "--steps 5: does not apply: a steady test", False)],  # cfd3 takes it
    # the record must hold the harmonics probe's analysis window (issue 33 item 3)
    "mps_harmonics": [(["--steps", "10"], "needs at least", False)],
}

LONG = "x" * 5000
WIDE = "é" * 3000  # 6000 bytes of UTF-8


def bad_cases(tmp):
    """(label, arguments, text the error line must contain or None); every one must exit 2."""
    a_file = os.path.join(tmp, "a_file")
    return [
        ("unknown option", ["--bogus"], "unknown option"),
        ("misspelt option", ["--thread", "1"], "did you mean --threads?"),
        ("misspelt option with =", ["--dry-runn=1"], "did you mean --dry-run?"),
        ("positional argument", ["stray"], "unexpected argument"),
        ("--threads 0", ["--threads", "0"], "--threads 0: must be 1 to 256"),
        ("--threads -1", ["--threads", "-1"], "must be 1 to 256"),
        ("--threads 1024", ["--threads", "1024"], "must be 1 to 256"),
        ("--threads abc", ["--threads", "abc"], "must be a whole number"),
        ("--threads 1e300", ["--threads", "1e300"], "must be 1 to 256"),
        ("--threads 2.5", ["--threads", "2.5"], "must be a whole number"),
        ("--threads fullwidth digit", ["--threads", "１"], "--threads"),
        ("--threads without value", ["--threads"], "--threads: needs a value"),
        ("--steps 0", ["--steps", "0"], "--steps 0: must be"),
        ("--steps -5", ["--steps", "-5"], "--steps -5: must be"),
        ("--steps 1e30", ["--steps", "1e30"], "--steps 1e30: must be"),
        ("--steps x", ["--steps", "x"], "--steps x: must be"),
        ("--steps nan", ["--steps", "nan"], "--steps nan: must be"),
        ("--accuracy bogus", ["--accuracy", "bogus"], "must be draft, standard or paper"),
        ("--accuracy non-ASCII", ["--accuracy", "精度"], "must be draft, standard or paper"),
        ("--precision half", ["--precision", "half"], "must be double or float"),
        ("--subnormals maybe", ["--subnormals", "maybe"], "must be flush or keep"),
        ("--scene missing", ["--scene", os.path.join(tmp, "missing.toml")], "scene file not found"),
        ("--scene a folder", ["--scene", tmp], "not a scene file"),
        ("--scene long", ["--scene", LONG], None),
        ("--scene non-ASCII", ["--scene", WIDE + ".toml"], None),
        ("--scene invalid UTF-8", [b"--scene", b"\xff\xfe\xfd.toml"], None),
        ("--out /proc/x", ["--out", "/proc/x"], "--out /proc/x"),
        ("--out /proc/x --dry-run", ["--out", "/proc/x", "--dry-run"], "--out /proc/x"),
        ("--out /proc/x/y --dry-run", ["--out", "/proc/x/y", "--dry-run"], "--out /proc/x/y"),
        ("--out under a file", ["--out", os.path.join(a_file, "out")], "is not a folder"),
        ("--out a file --dry-run", ["--out", a_file, "--dry-run"], "is not a folder"),
        ("--out long name", ["--out", os.path.join(tmp, LONG)], "longer than 255"),
        ("--out without value", ["--out"], "--out: needs a value"),
        ("the same option twice", ["--threads", "1", "--threads", "2"], "more than once"),
        ("--accuracy twice", ["--accuracy", "draft", "--accuracy", "draft"], "more than once"),
        ("very long option", ["--" + LONG], "unknown option"),
        ("very long value", ["--accuracy", LONG], "must be draft"),
        ("non-ASCII option", ["--" + WIDE], "unknown option"),
        ("--restart missing", ["--restart", os.path.join(tmp, "no_run")], None),
    ]


class Checks:
    def __init__(self, verbose):
        self.failures, self.count, self.verbose = [], 0, verbose

    def check(self, ok, what, detail=""):
        self.count += 1
        if ok:
            if self.verbose:
                print(f"  ok   {what}")
        else:
            self.failures.append(what)
            print(f"  FAIL {what}" + (f"\n{detail}" if detail else ""))
        return ok


def run(cmd, cwd, env):
    t0 = time.monotonic()
    p = subprocess.run(cmd, cwd=cwd, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=120)
    out = p.stdout.decode("utf-8", "replace")
    err = p.stderr.decode("utf-8", "replace")
    return p.returncode, out, err, time.monotonic() - t0


def shown(rc, out, err):
    text = (out + err).strip().splitlines()
    return f"       exit code {rc}\n" + "\n".join("       | " + line[:300] for line in text[-8:])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--bin", required=True, help="folder of the app binaries (build/ci/bin)")
    ap.add_argument("--source", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    ap.add_argument("--verbose", action="store_true")
    a = ap.parse_args()
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive")
    env.pop("POLYMECH_DISPATCH_NOTICE", None)
    cores = len(os.sched_getaffinity(0))
    checks = Checks(a.verbose)
    t_start = time.monotonic()
    tmp = tempfile.mkdtemp(prefix="polymech_cli_")
    try:
        with open(os.path.join(tmp, "a_file"), "w") as f:
            f.write("not a folder\n")
        for app, scene_rel in APPS.items():
            exe = os.path.join(os.path.abspath(a.bin), app)
            if not checks.check(os.access(exe, os.X_OK), f"{app}: binary {exe}"):
                continue
            scene = os.path.join(os.path.abspath(a.source), scene_rel)
            reporters = (app, DISPATCHED[app]) if app in DISPATCHED else (app,)
            work = os.path.join(tmp, app)  # the working folder of every run, must stay empty
            os.makedirs(work)
            out = os.path.join(tmp, app + "_out")  # an --out that must never be created
            t_app = time.monotonic()

            # --help, --version
            rc, so, se, _ = run([exe, "--help"], work, env)
            checks.check(rc == 0 and so.strip() != "", f"{app} --help: exit 0 and usage on stdout", shown(rc, so, se))
            usage = so
            if app in DISPATCHED:  # with a scene, the help of the app that runs it (issue 33 item 10)
                rc, so, se, _ = run([exe, "--scene", scene, "--help"], work, env)
                checks.check(rc == 0 and DISPATCHED[app] in so and "--scene" in so,
                             f"{app} --scene ... --help: the help of {DISPATCHED[app]}", shown(rc, so, se))
            rc, so, se, _ = run([exe, "--version"], work, env)
            checks.check(rc == 0 and re.fullmatch(re.escape(app) + r" polymech \d+\.\d+\.\d+\S* \(\S+\)\n", so),
                         f"{app} --version: '{app} polymech <version> (<commit>)'", shown(rc, so, se))

            for args, text, hidden in REFUSED.get(app, []):
                rc, so, se, _ = run([exe, "--scene", scene, "--dry-run", "--out", out] + args, work, env)
                first = se.splitlines()[0] if se.strip() else ""
                checks.check(rc == 2 and first.startswith(app + ": error: ") and text in first,
                             f"{app} {' '.join(args)}: refused, exit 2, '{text}'", shown(rc, so, se))
                if hidden:
                    checks.check(re.search(r"^\s*" + re.escape(args[0]) + r"\b", usage, re.M) is None,
                                 f"{app} --help does not list {args[0]}", usage[-600:])

            # a good dry run: exit 0, its --out not created
            rc, so, se, dt = run([exe, "--scene", scene, "--dry-run", "--threads", "1", "--out", out], work, env)
            checks.check(rc == 0 and "dry run: scene checked" in so and not os.path.exists(out),
                         f"{app} --dry-run: exit 0, --out not created ({dt:.1f} s)", shown(rc, so, se))
            # more threads than cores: accepted, one warning line (none with --quiet)
            many = 64
            rc, so, se, _ = run([exe, "--scene", scene, "--dry-run", "--threads", str(many), "--out", out], work, env)
            warned = f"warning: --threads {many} is more than the {cores} cores" in se
            checks.check(rc == 0 and (warned or cores >= many), f"{app} --threads {many} on {cores} cores: accepted, warned",
                         shown(rc, so, se))
            # OMP_NUM_THREADS, the default thread count, is checked too
            rc, so, se, _ = run([exe, "--scene", scene, "--dry-run", "--out", out], work, dict(env, OMP_NUM_THREADS="1024"))
            first = se.splitlines()[0] if se.strip() else ""
            checks.check(rc == 2 and first.startswith(tuple(r + ": error: OMP_NUM_THREADS=1024" for r in reporters)),
                         f"{app} with OMP_NUM_THREADS=1024: exit 2", shown(rc, so, se))

            for label, args, text in bad_cases(tmp):
                if "--restart" in args and app != "polymech" and "--restart" not in usage:
                    continue  # an app without checkpoints
                gives_scene = any(x in ("--scene", b"--scene") for x in args)
                cmd = [exe] + ([] if gives_scene else ["--scene", scene])
                if not any(x in ("--out", "--restart") for x in args):
                    cmd += ["--out", out]
                if "/proc/x" not in args and "--dry-run" not in args:
                    cmd += ["--dry-run"]  # should the input be accepted after all, nothing runs
                cmd += args
                reporters_here = ("polymech",) if app == "polymech" and gives_scene else reporters
                try:
                    rc, so, se, _ = run(cmd, work, env)
                except subprocess.TimeoutExpired:
                    checks.check(False, f"{app} {label}: ran more than 120 s")
                    continue
                lines = se.splitlines()
                first = lines[0] if lines else ""
                # an option the app refuses outright may be refused before its other checks
                refused = any(h and a[0] in args for a, _, h in REFUSED.get(app, [])) and "does not apply" in first
                ok = (rc == 2 and first.startswith(tuple(r + ": error: " for r in reporters_here))
                      and len(first) < 300 and (text is None or text in first or refused)
                      and not re.search(r"\d{25}", first))
                checks.check(ok, f"{app} {label}: exit 2, one line '<app>: error: ...'", shown(rc, so, se))
                checks.check(not os.path.exists(out) and not os.listdir(work),
                             f"{app} {label}: nothing written", f"       {os.listdir(work)} {os.path.exists(out)}")
                if os.path.exists(out):
                    shutil.rmtree(out, ignore_errors=True)
            # no probe or other folder left next to the output folders
            left = sorted(set(os.listdir(tmp)) - {"a_file"} - {n for n in APPS})
            checks.check(not left, f"{app}: nothing left in the temporary folder", f"       {left}")
            print(f"{app}: checked in {time.monotonic() - t_app:.1f} s")
    finally:
        if not checks.failures:
            shutil.rmtree(tmp, ignore_errors=True)
    wall = time.monotonic() - t_start
    if checks.failures:
        print(f"{len(checks.failures)} of {checks.count} checks failed ({wall:.0f} s); runs kept in {tmp}")
        return 1
    print(f"all {checks.count} checks passed ({wall:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
