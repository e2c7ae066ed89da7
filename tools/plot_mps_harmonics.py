#!/usr/bin/python3
"""Plots of an mps_harmonics run (seed 000 section 5.2), like the paper's Figs. 7-10.

  /usr/bin/python3 tools/plot_mps_harmonics.py out/crack_p_wave

writes into the run folder:
  time_history.png    the transmitted wave at the probe, crack (red dashed) and no crack (blue)  (Figs. 7, 9)
  spectrum.png        spectra normalised by the drive-frequency peak, harmonics marked          (Figs. 8, 10)
  contact_states.png  fractions of crack pairs in separation / stick / slip over time
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, pyplot, read_summary, run_folder, run_parser  # noqa: E402


def main():
    run = run_folder(run_parser(__doc__, "out/mps_harmonics").parse_args().run)
    s = read_summary(run, cases=("mps_harmonics",))
    plt = pyplot()
    comp, f0 = s["component"], s["drive_frequency"]
    title = f"{s['title']}\n{s['accuracy']} accuracy, {s['particles']} particles, {s['precision']}"

    th = load_csv(os.path.join(run, "time_history.csv"))
    fig, ax = plt.subplots(figsize=(8, 3.6))
    ax.plot(th["time"] * 1e6, th[comp + "_intact"] / 1e-9, "b-", lw=1, label="no crack")
    ax.plot(th["time"] * 1e6, th[comp + "_crack"] / 1e-9, "r--", lw=1, label="crack")
    ax.axvspan(s["window_start"] * 1e6, (s["window_start"] + 3 / f0) * 1e6, color="0.9", zorder=0,
               label="steady window (harmonic ratios)")
    ax.set_xlabel("time [us]")
    ax.set_ylabel(f"{comp} at {s['probe']} [nm]")
    ax.set_title(title, fontsize=9)
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "time_history.png"), dpi=110)
    plt.close(fig)

    sp = load_csv(os.path.join(run, "spectrum.csv"))
    fig, ax = plt.subplots(figsize=(8, 3.8))
    fmhz = sp["frequency"] / 1e6
    ax.semilogy(fmhz, np.maximum(sp["intact"], 1e-6), "b-", lw=1, label="no crack")
    ax.semilogy(fmhz, np.maximum(sp["crack"], 1e-6), "r--", lw=1, label="crack")
    for n, (rc, ri) in enumerate(zip(s["spectrum_ratios_crack"], s["spectrum_ratios_intact"]), start=1):
        ax.axvline(n * f0 / 1e6, color="gray", lw=0.5, ls=":")
        ax.annotate(f"{n}f: {rc:.2g} / {ri:.2g}", (n * f0 / 1e6, 1.5), fontsize=7, rotation=90, va="bottom", ha="right")
    ax.set_xlim(0, 6 * f0 / 1e6)
    ax.set_ylim(1e-5, 20)
    ax.set_xlabel("frequency [MHz]")
    ax.set_ylabel("amplitude / amplitude at f")
    ax.set_title(title + "  (labels: spectrum A_n/A_1, crack / no crack)", fontsize=9)
    ax.legend(loc="lower left")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(os.path.join(run, "spectrum.png"), dpi=110)
    plt.close(fig)

    path = os.path.join(run, "contact_states.csv")
    if os.path.exists(path):
        cs = load_csv(path)
        fig, ax = plt.subplots(figsize=(8, 3))
        t = cs["time"] * 1e6
        ax.stackplot(t, cs["separation"], cs["stick"], cs["slip"], labels=["separation", "stick", "slip"],
                     colors=["#9ecae1", "#fdae6b", "#e6550d"])
        ax.set_xlabel("time [us]")
        ax.set_ylabel("fraction of crack pairs")
        ax.set_ylim(0, 1)
        ax.legend(loc="upper left", fontsize=8)
        ax.set_title("crack-face contact states", fontsize=9)
        fig.tight_layout()
        fig.savefig(os.path.join(run, "contact_states.png"), dpi=110)
        plt.close(fig)
    print(f"plots in {run}: time_history.png, spectrum.png" + (", contact_states.png" if os.path.exists(path) else ""))


if __name__ == "__main__":
    guarded(main)
