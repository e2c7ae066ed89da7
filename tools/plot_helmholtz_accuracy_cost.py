#!/usr/bin/python3
"""Accuracy-cost (Pareto) plots of the Helmholtz sweep (bench/sweep_helmholtz).

  /usr/bin/python3 tools/plot_helmholtz_accuracy_cost.py [--cpu] out/accuracy_cost/helmholtz_*.csv
  /usr/bin/python3 tools/plot_helmholtz_accuracy_cost.py [--cpu] out/accuracy_cost    # every helmholtz_*.csv in it

For each case: L2 error (eq. (28)) against wall time (set-up + solve) and against DoFs, one line per
order p = 1..4, double (filled markers) and float (open markers); the grey staircase is the Pareto
front over all runs. Writes <csv>.png next to each CSV, and answers "for a target error, which order
is cheapest?" in <csv>_cheapest.md: the fastest run reaching each target, per precision, and the
cost of each order (double) to reach each target (or its best error where it never does).
--cpu measures cost in process CPU time instead of wall time (on a shared machine wall time includes
the time other jobs held the cores; with one thread CPU time is the run's own time).
"""
import argparse
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot  # noqa: E402

COLORS = {1: "tab:blue", 2: "tab:orange", 3: "tab:green", 4: "tab:red"}
TARGETS = [1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8]


def pareto(x, y):
    """Lower-left envelope: runs no other run beats in both cost and error."""
    order = np.argsort(x)
    xs, ys, best = [], [], np.inf
    for i in order:
        if y[i] < best:
            best = y[i]
            xs.append(x[i])
            ys.append(y[i])
    return np.array(xs), np.array(ys)


TIME = "wall_seconds"


def cheapest_table(col, case):
    lines = [f"### {case}: cheapest run reaching a target L2 error", "",
             f"| target | precision | order | elements along x | DoFs | {TIME.replace('_seconds', '')} [s] | error | iterations |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for target in TARGETS:
        for is_float, prec in ((0.0, "double"), (1.0, "float")):
            sel = np.where((col["is_float"] == is_float) & (col["l2_error"] <= target))[0]
            if sel.size == 0:
                continue
            i = sel[np.argmin(col[TIME][sel])]
            lines.append(f"| {target:.0e} | {prec} | {int(col['order'][i])} | {int(col['elements_x'][i])} | "
                         f"{int(col['dofs'][i])} | {col[TIME][i]:.3g} | {col['l2_error'][i]:.2e} | "
                         f"{int(col['iterations'][i])} |")
    return "\n".join(lines) + "\n"


PER_ORDER_TARGETS = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6]


def per_order_table(col, case):
    """Double precision: for each target, the cheapest run of every order p that reaches it."""
    unit = TIME.replace("_seconds", "")
    lines = [f"### {case}: cost of each order to reach a target L2 error (double; {unit} [s] / DoFs)", "",
             "| target | p = 1 | p = 2 | p = 3 | p = 4 |", "| --- | --- | --- | --- | --- |"]
    for target in PER_ORDER_TARGETS:
        cells = []
        for p in (1, 2, 3, 4):
            sel = np.where((col["is_float"] == 0.0) & (col["order"] == p))[0]
            ok = sel[col["l2_error"][sel] <= target]
            if ok.size:
                i = ok[np.argmin(col[TIME][ok])]
                cells.append(f"{col[TIME][i]:.3g} s / {int(col['dofs'][i])}")
            elif sel.size:
                i = sel[np.argmin(col["l2_error"][sel])]
                cells.append(f"not reached (best {col['l2_error'][i]:.1e} at {int(col['dofs'][i])})")
            else:
                cells.append("")
        lines.append(f"| {target:.0e} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def plot(path):
    plt = pyplot()
    col = load_csv(path, required=("is_float", "order", "dofs", "l2_error", "frequency", TIME))
    case = os.path.basename(path).replace("helmholtz_", "").replace(".csv", "")
    freq = col["frequency"][0] if col["frequency"].size else 0
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.4))
    tlabel = "CPU time" if TIME == "cpu_seconds" else "wall time"
    for ax, xname, xlabel in ((axes[0], TIME, f"{tlabel}: set-up + COCG solve [s]"),
                              (axes[1], "dofs", "degrees of freedom")):
        for p in (1, 2, 3, 4):
            for is_float, filled in ((0.0, True), (1.0, False)):
                sel = (col["order"] == p) & (col["is_float"] == is_float)
                if not np.any(sel):
                    continue
                o = np.argsort(col[xname][sel])
                ax.loglog(col[xname][sel][o], col["l2_error"][sel][o], marker="o", ms=5,
                          color=COLORS[p], ls="-" if filled else ":",
                          mfc=COLORS[p] if filled else "none",
                          label=f"p = {p}" + ("" if filled else " (float)"))
        fx, fy = pareto(col[xname], col["l2_error"])
        ax.step(fx, fy, where="post", color="0.6", lw=4, alpha=0.35, zorder=0, label="Pareto front")
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative L2 error, eq. (28)")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7, ncol=2)
    fig.suptitle(f"Helmholtz {case} ({freq:g} Hz): accuracy against cost, order p = 1..4 "
                 "(filled: double, open: float)")
    fig.tight_layout()
    out = os.path.splitext(path)[0] + ".png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    md = os.path.splitext(path)[0] + "_cheapest.md"
    with open(md, "w") as f:
        f.write(cheapest_table(col, case) + "\n" + per_order_table(col, case))
    print(f"plot: {out}\ntable: {md}")


def main():
    global TIME
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv", nargs="*", default=["out/accuracy_cost/helmholtz_cube.csv"],
                    help="CSVs of bench/sweep_helmholtz, or their folder (default: out/accuracy_cost/helmholtz_cube.csv)")
    ap.add_argument("--cpu", action="store_true", help="cost in process CPU time instead of wall time")
    a = ap.parse_args()
    if a.cpu:
        TIME = "cpu_seconds"
    paths = []
    for p in a.csv:
        if os.path.isdir(p):
            found = sorted(glob.glob(os.path.join(p, "helmholtz_*.csv")))
            if not found:
                raise InputError(f"{os.path.join(p, 'helmholtz_*.csv')}: no such files (run bench/sweep_helmholtz --out {p})")
            paths += found
        elif not os.path.exists(p):
            raise InputError(f"{p}: no such file or folder (give a CSV of bench/sweep_helmholtz or its folder)")
        else:
            paths.append(p)
    for p in paths:
        plot(p)


if __name__ == "__main__":
    guarded(main)
