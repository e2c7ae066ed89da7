#!/usr/bin/python3
"""Plots of the element-free Galerkin (efg) app's runs (seed 004).

  /usr/bin/python3 tools/plot_efg.py out/efg              # one run: its --out folder
  /usr/bin/python3 tools/plot_efg.py docs/figures/efg     # the stored Chen runs (Figs. 6, 8, 9)

A static run (scenes/efg/edge_crack_static.toml, centre_crack_static.toml) writes into its folder
  j_paths.png     K / (sigma sqrt(pi a)) from the J-integral on each path against the handbook value
  stress.png      sigma_yy at the nodes on the deformed plate (fields.h5; displacement magnified)
A dynamic run (chen_centre_crack_*.toml) writes
  sif_history.png K / (sigma sqrt(pi a0)) against time (mean of the paths and each path) and the crack
                  opening at the centre (sif_history.csv)
A folder of stored runs (chen_<name>_sif_history.csv + chen_<name>_summary.json, as in docs/figures/efg)
gets chen_dynamic.png (the node sets and the paths of the finest) and, with chen_running_paper_*,
chen_running.png.
"""
import csv
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, open_h5, pyplot, read_summary, run_parser, snapshot_steps  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        raise InputError(f"{path}: no rows")
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def plot_static(run, s):
    plt = pyplot()
    j = load_csv(os.path.join(run, "j_paths.csv"), required=("radius_m", "K_factor"))
    hb = s["handbook_factor"]
    fig, ax = plt.subplots(figsize=(5.8, 4.2))
    ax.plot(j["radius_m"] * 1e3, j["K_factor"], "o-", label=f"EFG, J on circles ({s['nodes']} nodes)")
    ax.axhline(hb, color="k", ls="--", lw=1, label=f"handbook (Tada, Paris & Irwin) {hb:.4f}")
    ax.set_xlabel("J path radius [mm]")
    ax.set_ylabel("K_I / (sigma sqrt(pi a))")
    ax.set_title(f"{s.get('crack', '')} crack, a/W = {s.get('a_over_w', float('nan')):.3g}: mean {s['sif_mean']:.4f} "
                 f"({100 * s['sif_error']:+.2f} %), J spread {100 * s['j_path_spread']:.2f} %", fontsize=9)
    lo, hi = min(hb, float(np.min(j["K_factor"]))), max(hb, float(np.max(j["K_factor"])))
    pad = max(0.02 * hb, 0.6 * (hi - lo))
    ax.set_ylim(lo - pad, hi + pad)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "j_paths.png"), dpi=110)
    plt.close(fig)
    written = ["j_paths.png"]

    h5 = os.path.join(run, "fields.h5")
    if not os.path.exists(h5):  # runs before the field files had one name
        h5 = os.path.join(run, "efg.h5")
    if os.path.exists(h5):
        with open_h5(h5) as f:
            steps = snapshot_steps(f)
            if steps:
                x = f["mesh/points"][...]
                u = f[steps[-1]]["displacement"][...]
                sig = f[steps[-1]]["stress"][...]
                size = float(np.ptp(x[:, 0])) or 1.0
                umax = float(np.max(np.abs(u))) or 1.0
                mag = 0.05 * size / umax  # the largest displacement drawn as 5 % of the plate
                y = x + mag * u
                syy = sig[:, 1]
                lim = float(np.percentile(np.abs(syy), 98)) or 1.0
                fig, ax = plt.subplots(figsize=(5.2, 6.4))
                sc = ax.scatter(y[:, 0] * 1e3, y[:, 1] * 1e3, c=syy / 1e6, s=6, cmap="coolwarm", vmin=-lim / 1e6, vmax=lim / 1e6)
                ax.set_aspect("equal")
                ax.set_xlabel("x [mm]")
                ax.set_ylabel("y [mm]")
                ax.set_title(f"sigma_yy at the nodes, displacement x {mag:.3g}", fontsize=9)
                fig.colorbar(sc, ax=ax, label="sigma_yy [MPa] (98th percentile of |sigma_yy|)")
                fig.tight_layout()
                fig.savefig(os.path.join(run, "stress.png"), dpi=110)
                plt.close(fig)
                written.append("stress.png")
    print(f"plots in {run}: {', '.join(written)}")


def plot_dynamic(run, s):
    plt = pyplot()
    h = load_csv(os.path.join(run, "sif_history.csv"), required=("t_us", "K_factor_mean", "crack_opening_m"))
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    ax[0].plot(h["t_us"], h["K_factor_mean"], "k-", lw=2, label="mean of the paths")
    for k in h:
        if k.startswith("K_factor_r"):
            ax[0].plot(h["t_us"], h[k], lw=0.8, label=k.replace("K_factor_r", "r = "))
    running = "sif_running" in s
    if running and "growth_start_us" in s:
        for a in ax:
            a.axvline(s["growth_start_us"], color="0.5", ls=":", lw=1, label=f"growth starts ({s.get('growth_speed', 0):.0f} m/s)")
    ax[0].set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a0))",
              title=f"{'running' if running else 'stationary'} crack, {s['nodes']} nodes: peak {s['sif_peak']:.3f} at {s['sif_peak_time_us']:.2f} us")
    ax[1].plot(h["t_us"], h["crack_opening_m"] * 1e6)
    ax[1].set(xlabel="t [us]", ylabel="crack opening at the centre [um]", title=f"energy error {s.get('energy_error', float('nan')):.2e}")
    for a in ax:
        a.grid(alpha=0.3)
        a.title.set_fontsize(9)
    ax[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "sif_history.png"), dpi=110)
    plt.close(fig)
    print(f"plots in {run}: sif_history.png")


def plot_stored(d):
    """The stored Chen runs of docs/figures/efg (chen_<name>_sif_history.csv + chen_<name>_summary.json)."""
    runs = []
    for name in ("draft", "standard", "paper"):
        csv_path = os.path.join(d, f"chen_{name}_sif_history.csv")
        js = os.path.join(d, f"chen_{name}_summary.json")
        if os.path.exists(csv_path) and os.path.exists(js):
            with open(js) as f:
                runs.append((name, read(csv_path), json.load(f)))
    if not runs:
        raise InputError(f"{os.path.join(d, 'summary.json')}: not found, nor chen_<draft|standard|paper>_sif_history.csv "
                         f"(give an efg run's --out folder, or a folder of stored Chen runs such as docs/figures/efg)")
    plt = pyplot()
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.2))
    for name, h, s in runs:
        label = f"{s['nodes']} nodes"
        ax[0].plot(h["t_us"], h["K_factor_mean"], label=label)
        ax[1].plot(h["t_us"], [1e6 * x for x in h["crack_opening_m"]], label=label)
    name, h, s = runs[-1]
    for k in h:
        if k.startswith("K_factor_r"):
            ax[2].plot(h["t_us"], h[k], label=k.replace("K_factor_r", "r = "))
    ax[0].set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a)) (mean of 5 paths)", title="stationary crack, node sets")
    ax[1].set(xlabel="t [us]", ylabel="crack opening at the centre [um]", title="crack opening")
    ax[2].set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a))", title=f"paths, {s['nodes']} nodes")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=8)
    fig.tight_layout()
    out = os.path.join(d, "chen_dynamic.png")
    fig.savefig(out, dpi=110)
    print(out)
    run = os.path.join(d, "chen_running_paper_sif_history.csv")
    if os.path.exists(run):
        h = read(run)
        fig, ax = plt.subplots(figsize=(6, 4.2))
        ax.plot(h["t_us"], h["K_factor_mean"], label="running (1000 m/s from 4.4 us), nodes on the path (the paper's)")
        nopath = os.path.join(d, "chen_running_nopath_sif_history.csv")
        if os.path.exists(nopath):
            hn = read(nopath)
            ax.plot(hn["t_us"], hn["K_factor_mean"], ":", label="running, no nodes on the path")
        name, hs, s = runs[-1]
        ax.plot(hs["t_us"], hs["K_factor_mean"], "--", label="stationary")
        ax.set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a0))", title="Chen's plate, EFG")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, loc="upper left")
        fig.tight_layout()
        out = os.path.join(d, "chen_running.png")
        fig.savefig(out, dpi=110)
        print(out)


def main():
    d = run_parser(__doc__, "docs/figures/efg").parse_args().run
    if not os.path.exists(d):
        raise InputError(f"{d}: no such folder (give an efg run's --out folder)")
    if not os.path.isdir(d):
        raise InputError(f"{d}: not a folder (give an efg run's --out folder, which holds summary.json)")
    if not os.path.exists(os.path.join(d, "summary.json")):
        return plot_stored(d)
    s = read_summary(d, cases=("efg",))
    if s.get("mode") == "dynamic" or os.path.exists(os.path.join(d, "sif_history.csv")):
        return plot_dynamic(d, s)
    if "sif_static" in s or os.path.exists(os.path.join(d, "j_paths.csv")):
        return plot_static(d, s)
    raise InputError(f"{os.path.join(d, 'summary.json')}: neither a static (j_paths.csv) nor a dynamic (sif_history.csv) efg run")


if __name__ == "__main__":
    guarded(main)
