#!/usr/bin/env python3
"""Plots of the EFG dynamic centre crack (seed 004 Figs. 6, 8, 9): K/(sigma sqrt(pi a)) and the crack
opening against time for the node sets of docs/figures/efg/chen_*_sif_history.csv, and the five paths of
the finest one.
  /usr/bin/python3 tools/plot_efg.py [docs/figures/efg]"""
import csv
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "docs/figures/efg"
    runs = []
    for name in ("draft", "standard", "paper"):
        csv_path = os.path.join(d, f"chen_{name}_sif_history.csv")
        js = os.path.join(d, f"chen_{name}_summary.json")
        if os.path.exists(csv_path) and os.path.exists(js):
            with open(js) as f:
                runs.append((name, read(csv_path), json.load(f)))
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


if __name__ == "__main__":
    main()
