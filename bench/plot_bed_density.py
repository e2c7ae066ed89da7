#!/usr/bin/python3
"""The wheel's sinkage and tractive force against the bed's packing fraction (seed 002 paper 2, sec. 4; issue 37):
beds of the same grains poured with a lower friction while they settle (`[contact] pour_friction`, docs/METHODS.md
"A denser bed: the pour's friction") are denser; each run's summary.json gives the packing fraction, the steady
stage's rim sinkage (and the tread's) and its tractive force; the packing fraction and bed height are the bed's as
the wheel meets it (summary `bed_at_set_down`; a summary without it: its packing_fraction, the run's end).

    /usr/bin/python3 bench/plot_bed_density.py --out docs/figures/dem/wheel_bed_density.png \
        --csv docs/figures/dem/wheel_bed_density.csv \
        --run "rigid wheel" "mu_p 0.5 (poured)" out/s15/summary.json --run "rigid wheel" "mu_p 0.1" out/s15_mu0.1/summary.json ...

Each --run SERIES LABEL SUMMARY adds one point to SERIES (one line per series, points in the order given);
SUMMARY@BED takes the bed's packing and height from the summary BED (another run of the same pour). The
paper's 53.6 mm rim sinkage and zero traction are drawn. Writes the points to --csv. Optional, outside ctest.
"""
import argparse
import csv
import json

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER_SINKAGE_MM = 53.6
FIELDS = ["series", "label", "packing_fraction", "bed_height", "sinkage_mm", "tread_sinkage_mm", "vertical_force",
          "tractive_force", "spheres", "summary"]


def point(series, label, path):
    path, _, bed_path = path.partition("@")  # SUMMARY@BED: the bed's numbers from BED (a run of the same pour)
    with open(path) as f:
        s = json.load(f)
    b = s
    if bed_path:
        with open(bed_path) as f:
            b = json.load(f)
    bed = b.get("bed_at_set_down") or {"packing_fraction": b["packing_fraction"], "bed_height": b["bed_height"]}
    return {"series": series, "label": label, "packing_fraction": bed["packing_fraction"], "bed_height": bed["bed_height"],
            "sinkage_mm": s["sinkage_mm"], "tread_sinkage_mm": s.get("tread_sinkage_mm", s["sinkage_mm"]),
            "vertical_force": s["vertical_force"], "tractive_force": s["tractive_force"], "spheres": s["spheres"],
            "summary": path}


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", nargs=3, action="append", metavar=("SERIES", "LABEL", "SUMMARY"), required=True)
    p.add_argument("--out", default="wheel_bed_density.png")
    p.add_argument("--csv", default="")
    a = p.parse_args()
    points = [point(*r) for r in a.run]
    if a.csv:
        with open(a.csv, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=FIELDS)
            w.writeheader()
            w.writerows(points)
    series = list(dict.fromkeys(q["series"] for q in points))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for name in series:
        pts = [q for q in points if q["series"] == name]
        x = [q["packing_fraction"] for q in pts]
        line, = axes[0].plot(x, [q["sinkage_mm"] for q in pts], "o-", label=name + ": rim")
        if any(q["tread_sinkage_mm"] != q["sinkage_mm"] for q in pts):
            axes[0].plot(x, [q["tread_sinkage_mm"] for q in pts], "s--", color=line.get_color(), label=name + ": tread")
        axes[1].plot(x, [q["tractive_force"] / 1e3 for q in pts], "o-", color=line.get_color(), label=name)
        for q in pts:
            axes[0].annotate(q["label"], (q["packing_fraction"], q["sinkage_mm"]), textcoords="offset points",
                             xytext=(4, 4), fontsize=7)
    axes[0].axhline(PAPER_SINKAGE_MM, color="k", ls=":", label="paper, FE tyre (rim)")
    axes[0].set_xlabel("packing fraction of the bed")
    axes[0].set_ylabel("steady sinkage (mm)")
    axes[0].legend(fontsize=8)
    axes[1].axhline(0.0, color="k", ls=":", lw=0.8)
    axes[1].set_xlabel("packing fraction of the bed")
    axes[1].set_ylabel("steady tractive force (kN; > 0 pulls)")
    axes[1].legend(fontsize=8)
    fig.suptitle("The wheel against the bed's density (beds poured with a lower friction)", fontsize=10)
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print(f"wrote {a.out}" + (f" and {a.csv}" if a.csv else ""))


if __name__ == "__main__":
    main()
