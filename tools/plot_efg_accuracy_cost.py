#!/usr/bin/env python3
"""Accuracy-cost of the EFG static edge crack (issue 14): K_I error against the handbook and J path
spread versus node count, support factor, Gauss points per cell and precision (double, float: the MLS
shape functions and the stiffness kernel in float, the sparse solve in double), with wall time. Writes scene variants
of scenes/efg/edge_crack_static.toml, runs build/ci/bin/efg on each (1 thread), and writes
<out>/accuracy_cost.csv and <out>/accuracy_cost.png.
  /usr/bin/python3 tools/plot_efg_accuracy_cost.py [--app build/ci/bin/efg] [--out docs/figures/efg]"""
import argparse
import csv
import json
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, pyplot  # noqa: E402


def variant(text, key, value):
    return re.sub(rf"^{key} = [^#\n]*", f"{key} = {value}", text, count=1, flags=re.M)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--app", default="build/ci/bin/efg", help="the efg binary (default: build/ci/bin/efg)")
    ap.add_argument("--scene", default="scenes/efg/edge_crack_static.toml", help="the scene the variants are made of")
    ap.add_argument("--out", default="docs/figures/efg", help="where accuracy_cost.csv and .png go")
    a = ap.parse_args()
    if not os.access(a.app, os.X_OK):
        raise InputError(f"{a.app}: no such program (build it: cmake --build --preset ci --target efg; or give --app)")
    if not os.path.isfile(a.scene):
        raise InputError(f"{a.scene}: not found (give --scene)")
    os.makedirs(a.out, exist_ok=True)
    plt = pyplot()
    base = open(a.scene).read()
    rows = []
    env = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false")
    with tempfile.TemporaryDirectory() as tmp:
        for scale in (4.0, 2.0, 1.0, 0.5):
            for factor in (1.5, 2.0):
                for gauss, precision in ((4, "double"), (10, "double"), (4, "float"), (10, "float")):
                    t = variant(base, "h_min", f"{0.0005 * scale:.6g}")
                    t = variant(t, "h_max", f"{0.002 * scale:.6g}")
                    t = variant(t, "support_factor", factor)
                    t = variant(t, "gauss", gauss)
                    path = os.path.join(tmp, "scene.toml")
                    open(path, "w").write(t)
                    out = os.path.join(tmp, "run")
                    subprocess.run([a.app, "--scene", path, "--out", out, "--threads", "1", "--quiet", "--precision", precision],
                                   check=True, env=env,
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
                    s = json.load(open(os.path.join(out, "summary.json")))
                    rows.append({"nodes": s["nodes"], "h_min_m": 0.0005 * scale, "support_factor": factor, "gauss": gauss,
                                 "sif_error": s["sif_error"], "sif_max_abs_error": s["sif_max_abs_error"],
                                 "j_path_difference": s["j_path_spread"], "wall_seconds": s["wall_seconds"], "is_float": int(precision == "float")})
                    print(rows[-1])
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "accuracy_cost.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    for factor in (1.5, 2.0):
        for gauss in (4, 10):
            for is_float in (0, 1):
                sel = [r for r in rows if r["support_factor"] == factor and r["gauss"] == gauss and r["is_float"] == is_float]
                lab = f"support {factor}, {gauss}x{gauss} Gauss, {'float' if is_float else 'double'}"
                style = "s--" if is_float else "o-"
                ax[0].loglog([r["nodes"] for r in sel], [abs(r["sif_max_abs_error"]) for r in sel], style, label=lab)
                ax[1].loglog([r["wall_seconds"] for r in sel], [abs(r["sif_max_abs_error"]) for r in sel], style, label=lab)
    ax[0].set(xlabel="nodes", ylabel="largest |K/K_handbook - 1| over 5 paths", title="edge crack a/W = 0.5")
    ax[1].set(xlabel="wall time [s] (1 thread)", ylabel="largest |K/K_handbook - 1| over 5 paths", title="accuracy-cost")
    for x in ax:
        x.grid(alpha=0.3, which="both")
        x.legend(fontsize=6)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "accuracy_cost.png"), dpi=110)
    print(f"plot: {os.path.join(a.out, 'accuracy_cost.png')}")


if __name__ == "__main__":
    guarded(main)
