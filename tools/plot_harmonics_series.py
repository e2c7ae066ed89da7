#!/usr/bin/python3
"""Probe records of a harmonics sweep: the transmitted wave at probe A with and without the crack, one
panel per resolution, the analysis window shaded (3 drive periods from `window_start`).

  /usr/bin/python3 tools/plot_harmonics_series.py out/accuracy_cost/crack_p_wave [double|float] [period]

reads <prefix>_series_<precision>_c<factor>.csv (written by bench/sweep_mps_harmonics) and writes
<prefix>_series_<precision>.png. `period` is the drive period in seconds (default 5e-7, the paper's 2 MHz).
"""
import glob
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def main():
    prefix = sys.argv[1] if len(sys.argv) > 1 else "out/accuracy_cost/crack_p_wave"
    precision = sys.argv[2] if len(sys.argv) > 2 else "double"
    period = float(sys.argv[3]) if len(sys.argv) > 3 else 5e-7
    files = glob.glob(f"{prefix}_series_{precision}_c*.csv")
    if not files:
        sys.exit(f"no {prefix}_series_{precision}_c*.csv: run bench/sweep_mps_harmonics first")
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
    print(out)


if __name__ == "__main__":
    main()
