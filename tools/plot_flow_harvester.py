#!/usr/bin/python3
"""Plots of the flow-driven harvester (issue 36; seed 002 paper 1 case 2, models/fsi/flow_harvester.hpp).

  /usr/bin/python3 tools/plot_flow_harvester.py SERIES.csv [SERIES.csv ...] [--out FILE.png] [--window T]
  /usr/bin/python3 tools/plot_flow_harvester.py --sweep harvester_sweep.csv [--out FILE.png]

A series (bench/sweep_flow_harvester's harvester_L*_U*.csv, or the app's series.csv: columns t, tip, lift,
voltage, power) gets four panels against time: the tip's deflection, the lift on the cylinder and plate, the
voltage across the resistor and the harvested power; several series are drawn over each other (a mesh or time
step comparison), the last `window` seconds shaded. A sweep (harvester_sweep.csv) gets the tip amplitude and the
mean power against the ratio of the wake's frequency (the lift's) to the plate's first frequency, the question of
paper 1 (the most energy where they meet: ratio 1, marked). Writes FILE.png (default: next to the first input).
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot  # noqa: E402


def plot_series(paths, out, window):
    plt = pyplot()
    keys = (("tip", "tip deflection [m]"), ("lift", "lift [N/m]"), ("voltage", "voltage [V]"), ("power", "power [W/m]"))
    fig, axes = plt.subplots(len(keys), 1, figsize=(10, 10), sharex=True)
    t_end = 0.0
    for path in paths:
        s = load_csv(path, required=("t",) + tuple(k for k, _ in keys))
        if len(s["t"]) == 0:
            raise InputError(f"{path}: no rows")
        t_end = max(t_end, s["t"][-1])
        for ax, (k, _) in zip(axes, keys):
            ax.plot(s["t"], s[k], lw=0.7, label=os.path.splitext(os.path.basename(os.path.dirname(path) or path))[0] + "/" + os.path.basename(path))
    for ax, (_, label) in zip(axes, keys):
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        if window > 0:
            ax.axvspan(t_end - window, t_end, color="0.9", zorder=0)
    axes[0].legend(fontsize=7)
    axes[-1].set_xlabel("t [s]")
    axes[0].set_title("flow-driven harvester (seed 002 paper 1 case 2)")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def plot_sweep(path, out):
    s = load_csv(path, required=("ratio_lift_f1", "tip_amplitude_m", "power_mean_W_per_m", "inflow", "length_m"))
    plt = pyplot()
    fig, axes = plt.subplots(2, 1, figsize=(8, 7), sharex=True)
    # the lift's spectral peak where the sweep's table has it (docs/figures/fsi/harvester_l0_speed_sweep.csv), else
    # the frequency from its upward crossings of the mean (bench/sweep_flow_harvester's own column)
    ratio = s["f_lift_fft_Hz"] / s["f1_sc_Hz"] if "f_lift_fft_Hz" in s else s["ratio_lift_f1"]
    for ax, k, label in ((axes[0], "tip_amplitude_m", "tip amplitude [m]"), (axes[1], "power_mean_W_per_m", "mean power [W/m]")):
        ax.semilogy(ratio, s[k], "o-")
        for r, v, u, l in zip(ratio, s[k], s["inflow"], s["length_m"]):
            ax.annotate(f"U {u:.2f}, L {l:.2f}", (r, v), fontsize=7, xytext=(3, 3), textcoords="offset points")
        ax.axvline(1.0, color="k", ls="--", lw=0.8)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3, which="both")
    axes[1].set_xlabel("f_wake / f_1 (the lift's frequency over the plate's first short-circuit frequency)")
    axes[0].set_title("flow-driven harvester across lock-in")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("series", nargs="*", help="time series CSV files")
    p.add_argument("--sweep", help="harvester_sweep.csv of bench/sweep_flow_harvester")
    p.add_argument("--out", help="the PNG to write")
    p.add_argument("--window", type=float, default=0.0, help="seconds at the end to shade (the statistics' window)")
    a = p.parse_args()
    if bool(a.sweep) == bool(a.series):
        raise InputError("give either time series CSV files or --sweep FILE")
    if a.sweep:
        plot_sweep(a.sweep, a.out or os.path.splitext(a.sweep)[0] + ".png")
    else:
        plot_series(a.series, a.out or os.path.splitext(a.series[0])[0] + ".png", a.window)
    return 0


if __name__ == "__main__":
    guarded(main)
