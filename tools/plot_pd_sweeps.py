#!/usr/bin/python3
"""Figures 6 and 7 of seed 003 from sweep_pd_penetration CSVs.

  /usr/bin/python3 tools/plot_pd_sweeps.py out/pd_sweeps/cv_sweep.csv [out/pd_sweeps/velocity_sweep.csv]
  /usr/bin/python3 tools/plot_pd_sweeps.py out/pd_sweeps      # the folder: cv_sweep*.csv and velocity_sweep*.csv in it

Fig. 6: residual velocity against the velocity-viscosity coefficient c_v at 303.5 m/s, with the
experiment's 200.6 m/s. Fig. 7 (second CSV, rows at several impact velocities): residual against
initial velocity, with the experiment and the Recht-Ipson curve v_r = a (v_i^2 - v_bl^2)^(1/2) of the
blunt-projectile tests (ballistic limit v_bl = 184.5 m/s, Borvik et al. 2002; a = m_p / (m_p + m_plug)
= 0.197 / (0.197 + 0.0296) for a plug of the projectile's diameter through 12 mm). Writes <csv>.png.
"""
import glob
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot  # noqa: E402

COLUMNS = ("spacing", "particles", "velocity", "c_v", "residual_velocity")

V_EXPERIMENT, VR_EXPERIMENT, V_BL = 303.5, 200.6, 184.5
A_RECHT_IPSON = 0.197 / (0.197 + 7850 * np.pi * 0.01**2 * 0.012)


def label_of(c, sel):
    n = int(np.median(c["particles"][sel]))
    return f"spacing {np.median(c['spacing'][sel]) * 1e3:.2g} mm ({n} particles)"


def cv_figure(path):
    plt = pyplot()
    c = load_csv(path, required=COLUMNS)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    for h in np.unique(c["spacing"]):
        sel = (c["spacing"] == h) & (np.abs(c["velocity"] - V_EXPERIMENT) < 0.05)
        order = np.argsort(c["c_v"][sel])
        ax.plot(c["c_v"][sel][order], c["residual_velocity"][sel][order], "o-", label=label_of(c, sel))
    ax.axhline(VR_EXPERIMENT, color="k", ls="--", label="experiment 200.6 m/s")
    ax.set_xscale("symlog", linthresh=0.1)
    ax.set_xlabel("velocity viscosity coefficient c_v")
    ax.set_ylabel("residual velocity [m/s]")
    ax.set_title("v0 = 303.5 m/s (seed 003 Fig. 6)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.splitext(path)[0] + ".png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"plot: {out}")


def velocity_figure(path):
    plt = pyplot()
    c = load_csv(path, required=COLUMNS)
    fig, ax = plt.subplots(figsize=(5.5, 4))
    v = np.linspace(V_BL, 320, 100)
    ax.plot(v, A_RECHT_IPSON * np.sqrt(np.maximum(v**2 - V_BL**2, 0)), "k:", label="Recht-Ipson, v_bl = 184.5 m/s")
    ax.plot([V_EXPERIMENT], [VR_EXPERIMENT], "ks", label="experiment (report)")
    for h in np.unique(c["spacing"]):
        sel = c["spacing"] == h
        order = np.argsort(c["velocity"][sel])
        ax.plot(c["velocity"][sel][order], c["residual_velocity"][sel][order], "o-", label="NOSB-PD, " + label_of(c, sel))
    ax.set_xlabel("initial velocity [m/s]")
    ax.set_ylabel("residual velocity [m/s]")
    ax.set_title("seed 003 Fig. 7")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.splitext(path)[0] + ".png"
    fig.savefig(out, dpi=110)
    plt.close(fig)
    print(f"plot: {out}")


def main():
    import argparse

    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cv_csv", nargs="?", default="out/pd_sweeps/cv_sweep.csv",
                    help="the c_v sweep's CSV, or the sweeps' folder (default: out/pd_sweeps/cv_sweep.csv)")
    ap.add_argument("velocity_csv", nargs="?", help="the velocity sweep's CSV (Fig. 7)")
    a = ap.parse_args()
    if os.path.isdir(a.cv_csv):
        cv = sorted(glob.glob(os.path.join(a.cv_csv, "cv_sweep*.csv")))
        vel = sorted(glob.glob(os.path.join(a.cv_csv, "velocity_sweep*.csv")))
        if not cv and not vel:
            raise InputError(f"{os.path.join(a.cv_csv, 'cv_sweep.csv')}: not found, nor velocity_sweep*.csv "
                             "(give the CSVs of bench/sweep_pd_penetration or their folder)")
    else:
        if not os.path.exists(a.cv_csv):
            raise InputError(f"{a.cv_csv}: no such file or folder (give the CSVs of bench/sweep_pd_penetration or their folder)")
        cv, vel = [a.cv_csv], [a.velocity_csv] if a.velocity_csv else []
    for p in cv:
        cv_figure(p)
    for p in vel:
        velocity_figure(p)


if __name__ == "__main__":
    guarded(main)
