#!/usr/bin/python3
"""The histories of wheels on gravel side by side (seed 002 paper 2, Figs. 7-10; issue 37): vertical force,
tractive force and rim sinkage against the time since the set-down, and the track's profile, for each run's
wheel.csv and track_profile.csv (dem_pour with a [wheel]: the rigid wheel or the FE tyre).

    /usr/bin/python3 bench/plot_wheel_histories.py --run "rigid wheel" docs/figures/dem/wheel_coarse \
        --run "FE tyre" docs/figures/dem/tyre_coarse --out docs/figures/dem/tyre_vs_rigid_histories.png

Each --run LABEL PREFIX reads PREFIX_wheel.csv and PREFIX_track_profile.csv (or PREFIX/wheel.csv and
PREFIX/track_profile.csv for an output folder). The paper's 53.6 mm rim sinkage is drawn. Optional, outside ctest.
"""
import argparse
import csv
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

PAPER_SINKAGE_MM = 53.6


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def files(prefix):
    if os.path.isdir(prefix):
        return os.path.join(prefix, "wheel.csv"), os.path.join(prefix, "track_profile.csv")
    return prefix + "_wheel.csv", prefix + "_track_profile.csv"


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--run", nargs=2, action="append", metavar=("LABEL", "PREFIX"), required=True)
    p.add_argument("--out", default="wheel_histories.png")
    a = p.parse_args()
    fig, ax = plt.subplots(2, 2, figsize=(11, 7.5))
    for label, prefix in a.run:
        wheel, track = files(prefix)
        w = read(wheel)
        t = [1e3 * x for x in w["time_from_start"]]
        line, = ax[0][0].plot(t, [1e-3 * x for x in w["vertical_force"]], label=label)
        colour = line.get_color()  # one colour per run in every panel
        ax[0][1].plot(t, [1e-3 * x for x in w["tractive_force"]], color=colour, label=label)
        ax[1][0].plot(t, w["sinkage_mm"], color=colour, label=label + " (rim)")
        if "tread_sinkage_mm" in w and any(abs(x - y) > 1e-9 for x, y in zip(w["tread_sinkage_mm"], w["sinkage_mm"])):
            ax[1][0].plot(t, w["tread_sinkage_mm"], "--", color=colour, label=label + " (tread's lowest point)")
        if os.path.exists(track):
            tr = read(track)
            ax[1][1].plot(tr["y"], [1e3 * z for z in tr["surface_height"]], color=colour, label=label)
    load = read(files(a.run[0][1])[0])["load"]
    ax[0][0].axhline(1e-3 * max(load), color="k", lw=0.8, ls=":", label="load")
    ax[1][0].axhline(PAPER_SINKAGE_MM, color="k", lw=0.8, ls=":", label="paper (FE tyre, R 5-7 mm gravel)")
    ax[0][0].set(xlabel="time since set-down (ms)", ylabel="vertical force (kN)", title="Fig. 8: vertical force")
    ax[0][1].set(xlabel="time since set-down (ms)", ylabel="tractive force (kN)", title="Fig. 9: tractive force (+: pulls)")
    ax[1][0].set(xlabel="time since set-down (ms)", ylabel="sinkage (mm)", title="Fig. 10: sinkage")
    ax[1][1].set(xlabel="y across the bin (m)", ylabel="surface height (mm)", title="Fig. 7: the track's profile")
    for row in ax:
        for x in row:
            x.grid(alpha=0.3)
            x.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print("wrote", a.out)


if __name__ == "__main__":
    main()
