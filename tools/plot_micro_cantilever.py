"""Plot the micro-cantilever studies of bench/sweep_micro_cantilever.cpp (issue 34, seed 002 paper 5).

    /usr/bin/python3 tools/plot_micro_cantilever.py OUT [PREFIX]

reads OUT/micro_cantilever_support.csv and OUT/micro_cantilever_mesh.csv (either may be missing) and writes
OUT/micro_cantilever.png: left, the support-size study (relative change of the tip compliance against the
largest block, per study, both orientations); right, the mesh study (compliance and root stress against
DoFs, relative to the finest order-2 mesh). A missing matplotlib or input is one line on stderr, exit 2.
"""
import csv
import os
import sys


def load(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]


def main():
    if len(sys.argv) < 2 or sys.argv[1] in ("-h", "--help"):
        sys.stdout.write(__doc__)
        return 0 if len(sys.argv) >= 2 else 2
    out = sys.argv[1]
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("plot_micro_cantilever: matplotlib is missing; no PNG written\n")
        return 2
    support = load(os.path.join(out, "micro_cantilever_support.csv"))
    mesh = load(os.path.join(out, "micro_cantilever_mesh.csv"))
    if not support and not mesh:
        sys.stderr.write("plot_micro_cantilever: no micro_cantilever_*.csv in %s\n" % out)
        return 2
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    names = {0: "all three x s", 1: "L_b alone", 2: "W_b alone", 3: "H_b alone"}
    for th, style in ((0.0, "-"), (54.7356, "--")):
        for study, marker in ((0, "o"), (1, "s"), (2, "^"), (3, "v")):
            rows = [r for r in support if r["study"] == study and abs(r["theta"] - th) < 0.01 and r["relative_change"] != 0]
            if not rows:
                continue
            # the size parameter: L_b / 1.5 (joint and L_b), W_b / 5, H_b / 3
            key = {0: "support_length", 1: "support_length", 2: "support_width", 3: "support_depth"}[study]
            base = {0: 1.5, 1: 1.5, 2: 5.0, 3: 3.0}[study]
            xs = [r[key] / base for r in rows]
            ys = [max(abs(r["relative_change"]), 1e-6) * 100 for r in rows]
            ax[0].loglog(xs, ys, style + marker, label="%s, %.1f deg" % (names[study], th))
        clamp = [r for r in support if r["study"] == 4 and abs(r["theta"] - th) < 0.01]
        for r in clamp:
            ax[0].axhline(abs(r["relative_change"]) * 100, ls=style, color="k", lw=0.8)
    ax[0].axhline(0.5, color="r", lw=0.8)
    ax[0].set_xlabel("support size s (block = s (1.5, 5, 3) um)")
    ax[0].set_ylabel("|compliance / largest block - 1| (%)")
    ax[0].set_title("support size (black: clamped root; red: 0.5 %)")
    ax[0].legend(fontsize=6)
    for th, style in ((0.0, "-"), (54.7356, "--")):
        for order, marker in ((2, "o"), (3, "s")):
            rows = [r for r in mesh if r["order"] == order and r["direct"] == 0 and abs(r["theta"] - th) < 0.01]
            if not rows:
                continue
            ref = [r for r in mesh if r["order"] == 2 and r["direct"] == 0 and abs(r["theta"] - th) < 0.01]
            sref = min(ref, key=lambda r: r["h_root"])["sigma_root"]
            rows = [r for r in rows if r["relative_change"] != 0]  # the reference itself
            if not rows:
                continue
            ax[1].loglog([r["dofs"] for r in rows], [max(abs(r["relative_change"]), 1e-7) * 100 for r in rows],
                         style + marker, label="compliance p=%d, %.1f deg" % (order, th))
            ax[1].loglog([r["dofs"] for r in rows], [max(abs(r["sigma_root"] / sref - 1), 1e-7) * 100 for r in rows],
                         style + marker, mfc="none", label="sigma(0.5,0,0) p=%d, %.1f deg" % (order, th))
    ax[1].set_xlabel("DoFs")
    ax[1].set_ylabel("|value / finest order 2 - 1| (%)")
    ax[1].set_title("mesh (finest order-2 mesh = 0)")
    ax[1].legend(fontsize=6)
    fig.tight_layout()
    path = os.path.join(out, "micro_cantilever.png")
    fig.savefig(path, dpi=110)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
