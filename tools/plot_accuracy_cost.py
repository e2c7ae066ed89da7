#!/usr/bin/python3
"""Accuracy-cost plot of a sweep CSV: error against cost (CPU time, or wall time), one line per precision.

  /usr/bin/python3 tools/plot_accuracy_cost.py out/accuracy_cost/mps_point_source.csv
  /usr/bin/python3 tools/plot_accuracy_cost.py out/accuracy_cost          # every sweep CSV in the folder

Every column whose name ends in _error or _difference becomes one panel; the finest run (zero by
definition against itself) is left out of the difference panels. Writes <csv>.png next to the CSV. The
CSVs are those of the accuracy-cost sweeps (bench/sweep_*: columns spacing, is_float, wall_seconds or
cpu_seconds, and *_error / *_difference); given a folder, the tool plots each CSV in it that has them,
but the PD sweeps' cv_sweep*.csv / velocity_sweep*.csv (tools/plot_pd_sweeps.py draws those, as
<csv>.png too).
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot, run_parser  # noqa: E402


def is_sweep(header):
    return ({"spacing", "is_float"} <= set(header) and ("wall_seconds" in header or "cpu_seconds" in header)
            and any(h.endswith("_error") or h.endswith("_difference") for h in header))


def main():
    target = run_parser(__doc__, "out/accuracy_cost/mps_point_source.csv").parse_args().run
    if os.path.isdir(target):
        paths = []
        for p in sorted(glob.glob(os.path.join(target, "*.csv"))):
            name = os.path.basename(p)
            if name.startswith("cv_sweep") or name.startswith("velocity_sweep"):
                print(f"left out {p} (tools/plot_pd_sweeps.py draws it)")
                continue
            with open(p) as f:
                if is_sweep(f.readline().strip().split(",")):
                    paths.append(p)
        if not paths:
            raise InputError(f"{target}: no accuracy-cost sweep CSV in this folder (columns spacing, is_float, wall_seconds, "
                             "*_error; written by bench/sweep_*)")
    elif not os.path.exists(target):
        raise InputError(f"{target}: no such file or folder (give a sweep CSV of bench/sweep_* or its folder)")
    else:
        paths = [target]
    for path in paths:
        plot(path)


def plot(path):
    plt = pyplot()
    col = load_csv(path, required=("spacing", "is_float"))
    header = list(col)
    if not is_sweep(header):
        raise InputError(f"{path}: not an accuracy-cost sweep CSV (needs spacing, is_float, wall_seconds or cpu_seconds, "
                         "and a column ending in _error or _difference)")
    metrics = [h for h in header if h.endswith("_error") or h.endswith("_difference")]
    # cost axis: CPU time when the sweep recorded it (steady on a shared machine), else wall time
    cost = "cpu_seconds" if "cpu_seconds" in col else "wall_seconds"
    threads = int(col["threads"][0]) if "threads" in col else None
    fig, axes = plt.subplots(1, len(metrics), figsize=(4.6 * len(metrics), 4.0), squeeze=False)
    for ax, m in zip(axes[0], metrics):
        for is_float, label, marker in ((0.0, "double", "o"), (1.0, "float", "s")):
            sel = (col["is_float"] == is_float) & (col[m] > 0) & np.isfinite(col[m])
            if not np.any(sel):
                continue
            order = np.argsort(col[cost][sel])
            t = col[cost][sel][order]
            e = col[m][sel][order]
            ax.loglog(t, e, marker=marker, label=label)
            for ti, ei, s in zip(t, e, col["spacing"][sel][order]):
                ax.annotate(f"{s * 1e3:.3g} mm", (ti, ei), textcoords="offset points", xytext=(4, 4), fontsize=7)
        ax.set_xlabel(("CPU time" if cost == "cpu_seconds" else "wall time") + " [s]"
                      + (f" ({threads} thread{'s' if threads != 1 else ''})" if threads else ""))
        ax.set_ylabel(m.replace("_", " "))
        ax.grid(True, which="both", alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=8)
    fig.suptitle(os.path.basename(path).replace(".csv", "") + ": error against cost (labels: particle spacing)")
    fig.tight_layout()
    out = os.path.splitext(path)[0] + ".png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"plot: {out}")


if __name__ == "__main__":
    guarded(main)
