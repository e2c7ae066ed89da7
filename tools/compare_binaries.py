#!/usr/bin/env python3
"""Run every shipped scene with two builds of the apps and compare their results (a refactor must leave
them unchanged: issue 32).

    /usr/bin/python3 tools/compare_binaries.py OLD_BIN NEW_BIN [--apps isph efg ...] [--accuracy draft]
                                               [--steps N] [--work DIR] [--skip STEM ...]

OLD_BIN and NEW_BIN hold the app binaries (build/<preset>/bin of the two commits). Each scene of
scenes/<folder>/ runs in the app that takes it, in OLD and NEW, into WORK/<app>/<scene>/{old,new}
(--quiet, --threads 1), then tools/compare_results.py compares the two folders (bitwise unless --rtol).
Prints one line per scene: bitwise, the largest difference and where, or why a run failed; the exit code
is 1 if any scene differs or a run failed in one build only.
"""
import argparse
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# the system Python has h5py (python3-h5py); a virtual environment may not
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable

# app -> the scene folder it runs and the scenes (stems) it does not take
APPS = {
    "mps_point_source": ("mps", lambda s: s.startswith("point_source")),
    "mps_harmonics": ("mps", lambda s: s.startswith("crack")),
    "pd_tension": ("pd", lambda s: s.startswith("tension")),
    "pd_penetration": ("pd", lambda s: s.startswith("penetration")),
    "dem_pour": ("dem", lambda s: not s.startswith("chung_ooi")),
    "dem_benchmark": ("dem", lambda s: s.startswith("chung_ooi")),
    "isph": ("isph", lambda s: True),
    "efg": ("efg", lambda s: True),
    "helmholtz": ("helmholtz", lambda s: True),
    "turek_hron": ("flow", lambda s: True),
    "micro_cantilever": ("solid", lambda s: not s.startswith("cook")),
    "cook_membrane": ("solid", lambda s: s.startswith("cook")),
}


def run(binary, scene, out, args):
    cmd = [binary, "--scene", scene, "--out", out, "--quiet", "--threads", "1"] + args
    t = time.time()
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return p.returncode, time.time() - t, (p.stderr.strip().splitlines() or [""])[-1]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("--apps", nargs="*", default=list(APPS))
    ap.add_argument("--accuracy", default="draft")
    ap.add_argument("--steps", type=int, default=0, help="override every scene's step count (0: the scene's)")
    ap.add_argument("--work", default="/tmp/compare_binaries")
    ap.add_argument("--rtol", default="0")
    ap.add_argument("--skip", nargs="*", default=[], help="scene stems not to run (e.g. the long floating_cylinder)")
    a = ap.parse_args()
    for d in (a.old, a.new):
        if not os.path.isdir(d):
            print(f"compare_binaries: {d}: not a folder of app binaries (build/<preset>/bin)", file=sys.stderr)
            sys.exit(2)
    failed = 0
    for app in a.apps:
        if app not in APPS:
            print(f"compare_binaries: unknown app '{app}' (known: {', '.join(APPS)})", file=sys.stderr)
            sys.exit(2)
        folder, takes = APPS[app]
        sdir = os.path.join(ROOT, "scenes", folder)
        for f in sorted(os.listdir(sdir)):
            stem = f[:-5]
            if not f.endswith(".toml") or not takes(stem) or stem in a.skip:
                continue
            scene = os.path.join(sdir, f)
            # dem_benchmark has no accuracy presets (it refuses --accuracy): its scenes run as written
            args = ([] if app == "dem_benchmark" else ["--accuracy", a.accuracy]) + \
                (["--steps", str(a.steps)] if a.steps > 0 else [])
            outs, rcs, walls = [], [], []
            for side, bindir in (("old", a.old), ("new", a.new)):
                out = os.path.join(a.work, app, stem, side)
                subprocess.run(["rm", "-rf", out])
                rc, wall, last = run(os.path.join(bindir, app), scene, out, args)
                outs.append(out)
                rcs.append(rc)
                walls.append(wall)
            head = f"{app:17s} {stem:36s} rc {rcs[0]}/{rcs[1]} {walls[0]:6.1f}/{walls[1]:6.1f} s"
            if rcs[0] != rcs[1]:
                print(f"{head}  DIFFERENT EXIT CODES ({last})", flush=True)
                failed += 1
                continue
            if rcs[0] == 2:
                print(f"{head}  both refused the scene (exit 2)", flush=True)
                continue
            p = subprocess.run([PYTHON, os.path.join(HERE, "compare_results.py"), outs[0], outs[1], "--rtol", a.rtol],
                               stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
            verdict = "bitwise" if p.returncode == 0 else "DIFFERS"
            print(f"{head}  {verdict}", flush=True)
            if p.returncode != 0:
                failed += 1
                print("    " + p.stdout.strip().replace("\n", "\n    "), flush=True)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
