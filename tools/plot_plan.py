#!/usr/bin/env python3
"""Pareto plots of `polymech plan --run` (issue 38): one PNG per method, the Pareto front of predicted error
against predicted CPU time the plan chose from (the sweep's own measurements beside it), and each planned
run: its target (dotted), its prediction (open marker) and what it achieved (filled), joined by a line.
Also writes <out>/plan_runs.md, the table of target, choice, predicted and achieved error and time.

    /usr/bin/python3 tools/plot_plan.py RUN [RUN ...] [--out docs/figures/plan]

RUN is a --out folder of `polymech plan --run` (holding plan.json) or a plan.json itself. Plans of the same
method and scene share a plot."""
import argparse
import json
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, pyplot  # noqa: E402


def load(path):
    f = os.path.join(path, "plan.json") if os.path.isdir(path) else path
    if not os.path.isfile(f):
        raise InputError(f"{f}: no plan.json (run `polymech plan ... --run --out {path}`)")
    try:
        j = json.load(open(f))
    except json.JSONDecodeError as e:
        raise InputError(f"{f}: not JSON ({e})")
    for key in ("method", "scene", "choice", "pareto", "target_error", "cpu_seconds"):
        if key not in j:
            raise InputError(f"{f}: no key '{key}' (not a plan.json of polymech plan --run)")
    j["_file"] = f
    return j


def slug(text):
    return re.sub(r"[^a-z0-9]+", "_", text.lower()).strip("_")


def g3(x):
    return "-" if x is None else f"{x:.3g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="--out folders of polymech plan --run (or their plan.json)")
    ap.add_argument("--out", default="docs/figures/plan", help="where the PNGs and plan_runs.md go")
    a = ap.parse_args()
    plans = [load(r) for r in a.runs]
    os.makedirs(a.out, exist_ok=True)
    plt = pyplot()
    groups = {}
    for p in plans:
        groups.setdefault((p["method"], os.path.splitext(os.path.basename(p["scene"]))[0], p.get("quantity", "")), []).append(p)
    rows = []
    for (method, stem, quantity), ps in groups.items():
        ps.sort(key=lambda p: -p["target_error"])
        fig, ax = plt.subplots(figsize=(6.4, 4.6))
        # the front of the first plan (every plan of a scene and quantity reads the same sweep)
        front = sorted(ps[0]["pareto"], key=lambda c: c["predicted_seconds"])
        ax.loglog([c["predicted_seconds"] for c in front], [c["predicted_error"] for c in front], "-", color="0.5",
                  drawstyle="steps-post", label="Pareto front (predicted)")
        ax.loglog([c["sweep_seconds"] for c in front], [max(c["sweep_error"], 1e-300) for c in front], "x", color="0.6",
                  label="the sweep's runs, as it timed them")
        colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
        for k, p in enumerate(ps):
            col = colours[k % len(colours)]
            c = p["choice"]
            ach = p.get("achieved_error")
            ax.axhline(p["target_error"], color=col, ls=":", lw=1)
            ax.loglog([c["predicted_seconds"]], [c["predicted_error"]], "o", mfc="none", color=col, ms=8)
            if ach is not None:
                ax.loglog([c["predicted_seconds"], p["cpu_seconds"]], [c["predicted_error"], ach], "-", color=col, lw=1)
                ax.loglog([p["cpu_seconds"]], [ach], "o", color=col, ms=6,
                          label=f"target {p['target_error']:.3g}: {c['setting']}")
            rows.append((method, stem, quantity, p, c, ach))
        ax.set(xlabel="CPU time [s] (one thread)", ylabel=f"relative error of {quantity}",
               title=f"polymech plan: {method}, {stem}")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=6.5, loc="best")
        fig.text(0.01, 0.01, "open: predicted, filled: achieved; dotted: the targets", fontsize=6.5)
        fig.tight_layout()
        png = os.path.join(a.out, f"plan_{slug(method)}_{slug(stem)}_{slug(quantity)}.png")
        fig.savefig(png, dpi=110)
        plt.close(fig)
        print(f"plot: {png}")
    md = os.path.join(a.out, "plan_runs.md")
    with open(md, "w") as f:
        f.write("| method, scene, quantity | target | choice | predicted error | achieved error | met | predicted CPU s | "
                "measured CPU s | measured / predicted |\n")
        f.write("| --- | ---: | --- | ---: | ---: | --- | ---: | ---: | ---: |\n")
        for method, stem, quantity, p, c, ach in rows:
            ratio = p["cpu_seconds"] / c["predicted_seconds"] if c["predicted_seconds"] > 0 else None
            f.write(f"| {method}, {stem}, {quantity} | {p['target_error']:.3g} | {c['setting']} | {g3(c['predicted_error'])} | "
                    f"{g3(ach)} | {'yes' if p.get('target_met') else 'NO'} | {g3(c['predicted_seconds'])} | "
                    f"{g3(p['cpu_seconds'])} | {g3(ratio)} |\n")
    print(f"table: {md}")


if __name__ == "__main__":
    guarded(main)
