#!/usr/bin/python3
"""Probe records of a harmonics sweep: the transmitted wave at probe A with and without the crack, one
panel per resolution, the analysis window shaded (3 drive periods from `window_start`).

  /usr/bin/python3 tools/plot_harmonics_series.py out/accuracy_cost/crack_p_wave [double|float] [period]
  /usr/bin/python3 tools/plot_harmonics_series.py out/accuracy_cost [double|float] [period]   # every prefix in it

reads <prefix>_series_<precision>_c<factor>.csv (written by bench/sweep_mps_harmonics) and writes
<prefix>_series_<precision>.png. `period` is the drive period in seconds (default 5e-7, the paper's 2 MHz).
Given the sweep's folder, it does so for every <prefix> with such files in it.
"""
import argparse
import glob
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, pyplot  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("prefix", nargs="?", default="out/accuracy_cost/crack_p_wave",
                    help="<folder>/<case> of the sweep's files, or the folder (default: out/accuracy_cost/crack_p_wave)")
    ap.add_argument("precision", nargs="?", default="double", choices=("double", "float"))
    ap.add_argument("period", nargs="?", type=float, default=5e-7, help="drive period [s] (default 5e-7)")
    a = ap.parse_args()
    if os.path.isdir(a.prefix):
        files = glob.glob(os.path.join(a.prefix, f"*_series_{a.precision}_c*.csv"))
        prefixes = sorted({re.sub(rf"_series_{a.precision}_c[0-9.]+\.csv$", "", f) for f in files})
        if not prefixes:
            raise InputError(f"{a.prefix}: no <case>_series_{a.precision}_c*.csv in this folder: run bench/sweep_mps_harmonics first")
    else:
        prefixes = [a.prefix]
    for prefix in prefixes:
        plot(prefix, a.precision, a.period)


def plot(prefix, precision, period):
    plt = pyplot()
    files = glob.glob(f"{prefix}_series_{precision}_c*.csv")
    if not files:
        raise InputError(f"{prefix}_series_{precision}_c*.csv: no such files: run bench/sweep_mps_harmonics first")
    factor = lambda f: float(re.search(r"_c([0-9.]+)\.csv$", f).group(1))  # noqa: E731
    files.sort(key=factor, reverse=True)
    fig, axes = plt.subplots(len(files), 1, figsize=(9, 2.4 * len(files)), sharex=True, squeeze=False)
    for ax, path in zip(axes[:, 0], files):
        d = np.genfromtxt(path, delimiter=",", names=True)
        t = d["time"] * 1e6
        ax.plot(t, d["intact"] * 1e9, label="no crack", lw=1)
        ax.plot(t, d["crack"] * 1e9, label="crack", lw=1)
        w = d["window_start"][0] * 1e6
        ax.axvspan(w, w + 3 * period * 1e6, color="0.9", zorder=0, label="analysis window")
        ax.set_ylabel("u at A [nm]")
        ax.set_title(f"spacing factor {factor(path):g} ({precision})", fontsize=9)
        ax.legend(fontsize=7, loc="upper left")
    axes[-1, 0].set_xlabel("time [us]")
    fig.tight_layout()
    out = f"{prefix}_series_{precision}.png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(out)


if __name__ == "__main__":
    guarded(main)
