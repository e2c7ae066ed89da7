#!/usr/bin/python3
"""The body's history in ISPH runs with a rigid body: its centre height and the fluid force on it against
time, from the series.csv of one or more runs (the isph app writes it every `time.sample_every`).

    /usr/bin/python3 tools/plot_isph_body.py RUN_DIR[:label] ... [--png body.png] [--weight]

RUN_DIR holds series.csv and summary.json (an isph run's --out folder); the plot goes to --png, by default
body.png in the first RUN_DIR. With --weight the force panel also shows each body's weight less
its buoyancy when immersed (summary keys body_weight, body_buoyancy_immersed), the force a resting body's
support must carry.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot, read_summary, run_folder  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="RUN_DIR[:label]")
    ap.add_argument("--png", help="the plot (default: body.png in the first RUN_DIR)")
    ap.add_argument("--weight", action="store_true", help="draw weight - buoyancy in the force panel")
    a = ap.parse_args()
    runs = []
    for spec in a.runs:
        path, _, label = spec.partition(":")
        run_folder(path, what="an isph run's output folder")
        s = read_summary(path, cases=("hydrostatic", "dam_break"))
        series = os.path.join(path, "series.csv")
        c = load_csv(series, required=("time",))
        if "body_y" not in c:
            raise InputError(f"{series}: no body_y column (a run without a body)")
        runs.append((path, label, s, c))
    png = a.png or os.path.join(runs[0][0], "body.png")
    plt = pyplot()

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(6.4, 5.6), sharex=True)
    for path, label, s, c in runs:
        label = label or s.get("title", path)
        line, = top.plot(c["time"], c["body_y"], label=label)
        bottom.plot(c["time"], c["body_force_y"], lw=0.6, color=line.get_color())
        if a.weight and "body_weight" in s:
            bottom.axhline(s["body_weight"] - s["body_buoyancy_immersed"], color=line.get_color(), ls=":")
    top.set_ylabel("body centre height [m]")
    top.legend(fontsize=7)
    top.grid(alpha=0.3)
    bottom.set_ylabel("fluid force on the body, y [N/m]")
    bottom.set_xlabel("time [s]")
    bottom.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    print(png)


if __name__ == "__main__":
    guarded(main)
