#!/usr/bin/python3
"""Plot of one micro_cantilever run (seed 002 paper 5: the 8YSZ micro-cantilever, issue 34).

  /usr/bin/python3 tools/plot_micro_cantilever_run.py out/micro_cantilever

Writes into the run folder, from summary.json and curves.csv:
  curves.png  the load-unload curve (force against the tip deflection) of every angle, the closed-form
              uniaxial modulus along the beam axis in the legend
and, after --inverse (fitted.csv):
  fit.png     per angle the measured deflections (noise), the noise-free experiment and the fitted curve,
              the estimate against the truth in the title
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, pyplot, read_summary, run_folder, run_parser  # noqa: E402


def main():
    run = run_folder(run_parser(__doc__, "out/micro_cantilever").parse_args().run, need=("summary.json", "curves.csv"))
    s = read_summary(run, cases=("micro_cantilever",))
    c = load_csv(os.path.join(run, "curves.csv"), required=("angle", "step", "force", "deflection"))
    import numpy as np

    moduli = {round(float(e["angle"]), 6): float(e["uniaxial_modulus"]) for e in s["curves"]}
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.6))
    for a in sorted(set(np.round(c["angle"], 6))):
        m = np.isclose(c["angle"], a)
        # the curve starts at the origin (the CSV lists the steps after it)
        d = np.concatenate([[0.0], c["deflection"][m]])
        f = np.concatenate([[0.0], c["force"][m]])
        e = moduli.get(round(float(a), 6))
        ax.plot(d, f, "o-", ms=3, label=f"{a:.4g} deg" + (f" (E = {e:.0f} GPa)" if e else ""))
    ax.set_xlabel("tip deflection [um]")
    ax.set_ylabel("force [mN]")
    ax.set_title(f"{s['title']}\n{s['accuracy']}, order {s['order']}, h_root {s['h_root']:.3g} um, {s['dofs']} DoFs",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(run, "curves.png")
    fig.savefig(out, dpi=130)
    print(out)

    fitted = os.path.join(run, "fitted.csv")
    if "inverse" in s and os.path.isfile(fitted):
        t = load_csv(fitted, required=("angle", "force", "measured", "experiment", "fitted"))
        angles = sorted(set(np.round(t["angle"], 6)))
        cols = min(3, len(angles))
        rows = (len(angles) + cols - 1) // cols
        fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 3.4 * rows), squeeze=False)
        for k, a in enumerate(angles):
            ax = axes[k // cols][k % cols]
            m = np.isclose(t["angle"], a)
            ax.plot(t["measured"][m], t["force"][m], "o", ms=4, label="measured (noise)")
            ax.plot(t["experiment"][m], t["force"][m], "k:", lw=1, label="experiment, no noise")
            ax.plot(t["fitted"][m], t["force"][m], "-", lw=1.2, label="fitted")
            ax.set_title(f"{a:.4g} deg", fontsize=9)
            ax.set_xlabel("tip deflection [um]")
            ax.set_ylabel("force [mN]")
            ax.grid(alpha=0.3)
            if k == 0:
                ax.legend(fontsize=7)
        for k in range(len(angles), rows * cols):
            axes[k // cols][k % cols].axis("off")
        names = s["parameter_names"]
        est = [p["value"] for p in s["inverse"]["parameters"]]
        text = ", ".join(f"{n} {v:.4g} ({tr:.4g})" for n, v, tr in zip(names, est, s["truth"]))
        fig.suptitle(f"fit: {s['inverse']['reason']}, {s['forward_runs']} forward runs; estimate (truth): {text}", fontsize=8)
        fig.tight_layout()
        out = os.path.join(run, "fit.png")
        fig.savefig(out, dpi=130)
        print(out)
    return 0


if __name__ == "__main__":
    guarded(main)
