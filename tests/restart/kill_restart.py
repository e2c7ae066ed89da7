#!/usr/bin/env python3
"""Kill a run with SIGKILL at several moments, restart it each time, and compare its results with an
uninterrupted run (issue 16: checkpoint/restart through the shared run driver).

    /usr/bin/python3 tests/restart/kill_restart.py BUILD_BIN/APP WORK_DIR [--kills 3]
        [--checkpoint-steps N] [--reference DIR] -- APP_ARGS...

1. the reference: APP APP_ARGS --out WORK_DIR/reference, or with --reference DIR the output folder of an
   uninterrupted run made before (`APP APP_ARGS --out DIR --quiet` with the same binary and thread count): a
   run of hours then splits into two halves that can run at different times;
2. the interrupted run: APP APP_ARGS --out WORK_DIR/interrupted --checkpoint-steps N, killed with SIGKILL
   `--kills` times, each time at a different moment after a new checkpoint appeared (at once, a little
   later, later still: inside a step, inside a snapshot or a checkpoint write), and restarted with
   --restart WORK_DIR/interrupted until it finishes;
3. tools/compare_results.py: every summary number (but timings and the restart count), every CSV
   column and every HDF5 dataset must be bitwise equal (--rtol 0).
Exit code 0 when they are; 1 otherwise (or when a run failed).
"""
import argparse
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def checkpoints(out):
    d = os.path.join(out, "checkpoints")
    if not os.path.isdir(d):
        return []
    return sorted(f for f in os.listdir(d) if f.startswith("checkpoint_") and f.endswith(".bin"))


def newest_step(out):
    c = checkpoints(out)
    return int(c[-1][len("checkpoint_"):-len(".bin")]) if c else -1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("app")
    ap.add_argument("work")
    ap.add_argument("--kills", type=int, default=3)
    ap.add_argument("--checkpoint-steps", type=int, default=50)
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--reference", help="an uninterrupted run's output folder to compare with (not run here)")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    a = ap.parse_args(argv[:split])
    args = argv[split + 1:]
    shutil.rmtree(a.work, ignore_errors=True)
    os.makedirs(a.work)
    ref, run = os.path.join(a.work, "reference"), os.path.join(a.work, "interrupted")
    env = dict(os.environ)

    if a.reference:
        ref = a.reference
        if not os.path.isfile(os.path.join(ref, "summary.json")):
            print(f"--reference {ref}: no summary.json there (not a finished run's output folder)")
            return 2
        print(f"reference: {ref} (run before)")
    else:
        t0 = time.time()
        r = subprocess.run([a.app] + args + ["--out", ref, "--quiet"], env=env, capture_output=True, text=True)
        if r.returncode != 0:
            print(f"reference run failed ({r.returncode}):\n{r.stderr}")
            return 1
        print(f"reference run: {time.time() - t0:.1f} s")

    delays = [0.0, 0.15, 0.4, 0.05, 0.25]
    cmd = [a.app] + args + ["--out", run, "--quiet", "--checkpoint-steps", str(a.checkpoint_steps)]
    restarts = 0
    for k in range(a.kills + 1):
        p = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if k == a.kills:
            _, err = p.communicate(timeout=a.timeout)
            if p.returncode != 0:
                print(f"the last restart failed ({p.returncode}):\n{err}")
                return 1
            break
        start = newest_step(run)
        deadline = time.time() + a.timeout
        while newest_step(run) <= start and p.poll() is None and time.time() < deadline:
            time.sleep(0.005)
        if p.poll() is not None:
            _, err = p.communicate()
            print(f"kill {k + 1}: the run ended ({p.returncode}) before a new checkpoint; make the run longer or "
                  f"--checkpoint-steps smaller\n{err}")
            return 1
        time.sleep(delays[k % len(delays)])
        if p.poll() is not None:
            print(f"kill {k + 1}: the run ended ({p.returncode}) within {delays[k % len(delays)]:.2f} s of checkpoint "
                  f"{newest_step(run)}, before the kill; make the run longer")
            return 1
        p.send_signal(signal.SIGKILL)
        p.wait()
        left = sorted(os.listdir(run))
        print(f"kill {k + 1}: SIGKILL {delays[k % len(delays)]:.2f} s after checkpoint {newest_step(run)} appeared "
              f"(was at {start}); the folder holds {', '.join(left)}")
        if any(f in left for f in ("summary.json", "fields.h5", "fields.xdmf")):
            print("a killed run left a file under its final name")
            return 1
        if k == 0:  # the same command again, without --restart: refused, the checkpoints kept (issue 33 item 6)
            again = subprocess.run(cmd, env=env, capture_output=True, text=True, timeout=a.timeout)
            if again.returncode != 2 or "--restart" not in again.stderr or newest_step(run) < 0:
                print(f"the killed run's command again without --restart: expected exit code 2 naming --restart and the "
                      f"checkpoints kept, got {again.returncode}: {again.stderr}")
                return 1
        cmd = [a.app] + args + ["--restart", run, "--quiet", "--checkpoint-steps", str(a.checkpoint_steps)]
        restarts += 1
    left = os.listdir(run)
    if "checkpoints" in left:
        print(f"the finished run kept its checkpoints: {left}")
        return 1
    r = subprocess.run([a.app] + args + ["--restart", run, "--quiet"], env=env, capture_output=True, text=True)
    if r.returncode != 2 or "no checkpoint to restart from" not in r.stderr:
        print(f"--restart of a finished run: expected exit code 2 and 'no checkpoint', got {r.returncode}: {r.stderr}")
        return 1
    sys.path.insert(0, os.path.join(ROOT, "tools"))
    import compare_results  # noqa: E402
    compare_results.TIMING_KEYS.add("restarts")
    sys.argv = ["compare_results.py", ref, run, "--rtol", "0"]
    try:
        compare_results.main()
    except SystemExit as e:
        print(f"{restarts} restarts; results {'bitwise equal' if e.code == 0 else 'DIFFER'}")
        return int(e.code or 0)
    return 0


if __name__ == "__main__":
    sys.exit(main())
