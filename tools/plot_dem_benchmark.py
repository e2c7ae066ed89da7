#!/usr/bin/python3
"""Plots of the Chung & Ooi (2011) DEM benchmark from dem_benchmark's summary.json: the test-4 rebound
angles of the contact point and of the centre against the incidence angle (with the gross-sliding closed
forms and the experiment), and the
test-3 restitution measured against the input.

  /usr/bin/python3 tools/plot_dem_benchmark.py docs/figures/dem/summary.json [out_dir]

Writes test4_rebound.png, test4_centre_rebound.png (the centre of mass's rebound angle with Kharaz et
al.'s measured points, tests/dem/data/kharaz2001_centre_rebound.csv) and test3_restitution.png next to
the summary (or into out_dir).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


MU, E = 0.092, 0.98  # scenes/dem/chung_ooi_test4.toml
KHARAZ = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "dem", "data",
                      "kharaz2001_centre_rebound.csv")


def plot_test4(rows, impulse, impulse_label, what, title, path, experiment=None):
    """Rebound angle against incidence (rows [[incidence, rebound], ...]) with the gross-sliding closed form
    tan r = (tan i - impulse) / e, where impulse is 3.5 mu (1+e) for the contact point and mu (1+e) for the
    centre; `experiment` is a CSV of measured [incidence, rebound] rows to draw too."""
    onset = math.degrees(math.atan(3.5 * MU * (1 + E)))  # gross sliding throughout from here on
    fine = [onset + k * (89 - onset) / 100 for k in range(101)]
    closed = [math.degrees(math.atan((math.tan(math.radians(a)) - impulse) / E)) for a in fine]
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    ax.plot([r[0] for r in rows], [r[1] for r in rows], "o-", label="polymech (Hertz-Mindlin, 400 steps per contact)")
    ax.plot(fine, closed, "k--", lw=1, label=f"gross sliding: tan r = (tan i - {impulse_label}) / e")
    if experiment and os.path.exists(experiment):
        with open(experiment) as f:
            measured = [line.split(",") for line in f.read().split()[1:]]
        ax.plot([float(r[0]) for r in measured], [float(r[1]) for r in measured], "s", mfc="none", color="C3",
                label="experiment (Kharaz et al. 2001)")
        ax.plot([0, 89], [0, 89], color="0.7", lw=0.5, label="rebound = incidence")
    else:
        ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("incidence angle (deg)")
    ax.set_ylabel(f"rebound angle of {what} (deg)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "docs/figures/dem/summary.json"
    out = sys.argv[2] if len(sys.argv) > 2 else os.path.dirname(path)
    with open(path) as f:
        s = json.load(f)
    os.makedirs(out, exist_ok=True)
    if "test4_rebound_angles" in s:
        plot_test4(s["test4_rebound_angles"], 3.5 * MU * (1 + E), "3.5 mu (1+e)", "the contact point",
                   "Chung & Ooi test 4: alumina sphere, 3.9 m/s", os.path.join(out, "test4_rebound.png"))
    if "test4_centre_rebound_angles" in s:
        plot_test4(s["test4_centre_rebound_angles"], MU * (1 + E), "mu (1+e)", "the centre of mass",
                   "Chung & Ooi test 4 against the experiment", os.path.join(out, "test4_centre_rebound.png"), KHARAZ)
    if "test3_restitution" in s:
        e_in = [r[0] for r in s["test3_restitution"]]
        e_out = [r[1] for r in s["test3_restitution"]]
        fig, ax = plt.subplots(figsize=(4.5, 4.2))
        ax.plot([0, 1], [0, 1], "k--", lw=1, label="measured = input")
        ax.plot(e_in, e_out, "o", label="polymech (beta calibrated on Hertz)")
        ax.set_xlabel("coefficient of restitution, input")
        ax.set_ylabel("coefficient of restitution, measured")
        ax.set_title("Chung & Ooi test 3")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "test3_restitution.png"), dpi=120)


if __name__ == "__main__":
    main()
