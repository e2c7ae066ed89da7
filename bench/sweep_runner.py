"""Shared by the accuracy-cost sweeps (bench/sweep_isph_*.py, bench/sweep_dem_impacts.py): run an app on a
scene with some of its values replaced, one thread, no snapshots, and keep the sweep's rows in a CSV."""
import csv
import json
import os
import re
import resource
import subprocess


def scene_value(text, key):
    """The number of the scene line `key = value` (the first one)."""
    return float(re.search(rf"(?m)^{key} = ([0-9.eE+-]+)", text).group(1))


def replace_values(text, values):
    """TEXT with each scene line `key = ...` of VALUES (a dict) given the new value; a key the scene does not
    have is refused (a sweep that changes nothing would measure nothing)."""
    for key, value in values.items():
        text, n = re.subn(rf"(?m)^{key} = .*$", f"{key} = {value!r}", text)
        if n == 0:
            raise KeyError(f"the scene has no line '{key} = ...' to replace")
    return text


def run_scene(app, text, work, values, precision="double"):
    """Write WORK/scene.toml (TEXT with each `key = ...` line of VALUES replaced and snapshots off), run APP
    on it with one thread in PRECISION, and return (summary.json as a dict, the run's CPU seconds)."""
    os.makedirs(work, exist_ok=True)
    text = replace_values(text, values)
    text = re.sub(r"(?m)^snapshot_every = .*$", "snapshot_every = 0.0", text)
    scene = os.path.join(work, "scene.toml")
    with open(scene, "w") as f:
        f.write(text)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false", OMP_WAIT_POLICY="passive")
    subprocess.run([app, "--scene", scene, "--threads", "1", "--precision", precision, "--quiet", "--out", work],
                   check=True, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(work, "summary.json")) as f:
        return json.load(f), cpu


def write_rows(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)


def read_rows(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
