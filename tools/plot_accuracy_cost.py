#!/usr/bin/python3
"""Accuracy-cost plot of a sweep CSV: error against cost (CPU time, or wall time), one line per precision.

  /usr/bin/python3 tools/plot_accuracy_cost.py out/accuracy_cost/mps_point_source.csv

Every column whose name ends in _error or _difference becomes one panel; the finest run (zero by
definition against itself) is left out of the difference panels. Writes <csv>.png next to the CSV.
"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "out/accuracy_cost/mps_point_source.csv"
    with open(path) as f:
        header = f.readline().strip().split(",")
    data = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    col = {name: data[:, k] for k, name in enumerate(header)}
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
        ax.legend(fontsize=8)
    fig.suptitle(os.path.basename(path).replace(".csv", "") + ": error against cost (labels: particle spacing)")
    fig.tight_layout()
    out = os.path.splitext(path)[0] + ".png"
    fig.savefig(out, dpi=110)
    print(f"plot: {out}")


if __name__ == "__main__":
    main()
