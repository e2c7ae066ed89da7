"""Plot the accuracy-cost study of the finite-element harvester (bench/sweep_piezo_fe.cpp, issue 35).

    /usr/bin/python3 tools/plot_piezo_accuracy_cost.py OUT

reads OUT/piezo_fe_mesh.csv and OUT/piezo_fe_time.csv and writes OUT/piezo_fe_accuracy_cost.png: left, the
short-circuit frequency's error against wall time per order (one thread, set-up + both frequencies + two
harmonic solves); middle, the power at 2000 ohm likewise; right, the Newmark steady voltage's error against the
harmonic solve for steps per period. A missing matplotlib or input is one line on stderr, exit 2.
"""
import csv
import os
import sys


def load(path):
    if not os.path.exists(path):
        raise FileNotFoundError(path)
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
        sys.stderr.write("plot_piezo_accuracy_cost: matplotlib is not installed (apt-get install python3-matplotlib)\n")
        return 2
    try:
        mesh = load(os.path.join(out, "piezo_fe_mesh.csv"))
        time = load(os.path.join(out, "piezo_fe_time.csv"))
    except FileNotFoundError as e:
        sys.stderr.write(f"plot_piezo_accuracy_cost: {e.args[0]} is missing (run bench/sweep_piezo_fe --out {out})\n")
        return 2
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.5))
    for p in sorted({int(r["order"]) for r in mesh}):
        # the reference's own length mesh (p = 4, 80 cells) is left out: its "error" is the cells per layer only
        rows = [r for r in mesh if int(r["order"]) == p and not (p == 4 and int(r["cells_length"]) == 80)]
        cpl = min(int(r["cells_per_layer"]) for r in rows)
        rows = sorted((r for r in rows if int(r["cells_per_layer"]) == cpl), key=lambda r: r["seconds"])
        for k, key in ((0, "err_f_sc"), (1, "err_P2000")):
            ax[k].loglog([r["seconds"] for r in rows], [abs(r[key]) for r in rows], "o-", label=f"p = {p}, {cpl} cell(s)/layer")
    ax[0].set_title("short-circuit frequency")
    ax[1].set_title("power at 2000 ohm, at the model's f_sc")
    for a in ax[:2]:
        a.set_xlabel("wall time [s] (1 thread)")
        a.set_ylabel("relative error against p = 4, 80 x 2 cells")
        a.grid(True, which="both", alpha=0.3)
        a.legend(fontsize=8)
    ax[2].loglog([r["steps_per_period"] for r in time], [abs(r["err_V"]) for r in time], "s-")
    ax[2].set_xlabel("Newmark steps per period")
    ax[2].set_ylabel("steady |V|: relative error against the harmonic solve")
    ax[2].set_title("time step (p = 2, 20 cells, zeta 0.05)")
    ax[2].grid(True, which="both", alpha=0.3)
    fig.suptitle("duToit harvester (seed 002 paper 1), 2D plane stress: accuracy against cost")
    fig.tight_layout()
    path = os.path.join(out, "piezo_fe_accuracy_cost.png")
    fig.savefig(path, dpi=110)
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
