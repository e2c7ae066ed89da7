#!/usr/bin/env python3
"""Freund's onset test of the EFG running crack (issue 14; docs/VALIDATION.md, "Running crack"): reads the
sif_history.csv of a stationary run and of running runs of scenes/efg/chen_centre_crack_freund.toml (same
node set, same dt), prints K_running / K_stationary after the onset against Freund's universal function
k(v), the J' path spread while running and after the arrest, and plots the histories.
  /usr/bin/python3 tools/efg_freund.py STAT_DIR RUN_DIR[:label] ... [--png out.png]
Each DIR holds summary.json and sif_history.csv (or give DIR/prefix to read prefix_summary.json and
prefix_sif_history.csv)."""
import csv
import json
import math
import os
import sys


def paths(d):
    if os.path.isdir(d):
        return os.path.join(d, "summary.json"), os.path.join(d, "sif_history.csv")
    return d + "_summary.json", d + "_sif_history.csv"


def read(d):
    js, cs = paths(d)
    with open(cs) as f:
        rows = list(csv.DictReader(f))
    h = {k: [float(r[k]) for r in rows] for k in rows[0]}
    with open(js) as f:
        s = json.load(f)
    return h, s


def wave_speeds(E, nu, rho, plane_strain=True):
    mu = E / (2 * (1 + nu))
    lam = E * nu / ((1 + nu) * (1 - 2 * nu))
    if not plane_strain:
        lam = 2 * lam * mu / (lam + 2 * mu)
    cs = math.sqrt(mu / rho)
    cd = math.sqrt((lam + 2 * mu) / rho)
    k = (cs / cd) ** 2
    # Rayleigh: (2 - x)^2 = 4 sqrt(1 - k x) sqrt(1 - x), x = (c_R / c_s)^2, by bisection
    f = lambda x: (2 - x) ** 2 - 4 * math.sqrt(1 - k * x) * math.sqrt(1 - x)
    lo, hi = 0.5, 1 - 1e-12
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if f(lo) * f(m) <= 0:
            hi = m
        else:
            lo = m
    return cd, cs, cs * math.sqrt(lo)


def velocity_factor(v, cd, cs, nu):
    # Freund's A_I(v): J' = A_I K^2 / E' (plane strain nu)
    ad = math.sqrt(1 - v * v / cd ** 2)
    a_s = math.sqrt(1 - v * v / cs ** 2)
    D = 4 * ad * a_s - (1 + a_s * a_s) ** 2
    return v * v * ad / ((1 - nu) * cs * cs * D)


def spread(h, i):
    ks = [h[k][i] for k in h if k.startswith("K_factor_r")]
    j = [x * x for x in ks]
    return (max(j) - min(j)) / max(j) if max(j) > 0 else 0.0


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    png = None
    if "--png" in sys.argv:
        png = sys.argv[sys.argv.index("--png") + 1]
        args = [a for a in args if a != png]
    E, nu, rho = 7.562e9, 0.394, 1191.0
    cd, cs, cR = wave_speeds(E, nu, rho)
    print(f"plane strain: c_d = {cd:.1f} m/s, c_s = {cs:.1f} m/s, c_R = {cR:.1f} m/s")
    hs, ss = read(args[0])
    ts = hs["t_us"]
    runs = []
    for a in args[1:]:
        d, _, label = a.partition(":")
        h, s = read(d)
        runs.append((label or os.path.basename(d), h, s))
    print("| run | v [m/s] | k_a(v) | k_g(v) | K_run/K_stat at t0+dt | mean over (t0, t0+0.5 us] | mean while running | J' spread running (mean / max) | after arrest (mean / max) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for label, h, s in runs:
        v = s["growth_speed"]
        t0 = s["growth_start_us"]
        a0 = s["j_radii"] and None
        dt = s["dt"] * 1e6
        t_end = t0 + (s["final_crack_length"] - 0.0024) / v * 1e6
        ka = (1 - v / cR) / math.sqrt(1 - v / cd)
        kg = math.sqrt((1 - v / cR) / velocity_factor(v, cd, cs, nu))
        ratio = []
        sp_run, sp_arr = [], []
        for i, t in enumerate(h["t_us"]):
            j = min(range(len(ts)), key=lambda q: abs(ts[q] - t))
            if t0 + 0.5 * dt < t <= t_end + 0.01 * dt:
                ratio.append((t, h["K_factor_mean"][i] / hs["K_factor_mean"][j]))
                sp_run.append(spread(h, i))
            elif t > t_end + 0.5 * dt:
                sp_arr.append(spread(h, i))
        first = ratio[0][1]
        early = [r for t, r in ratio if t <= t0 + 0.5 + 1e-6]
        mean_early = sum(early) / len(early)
        mean_all = sum(r for _, r in ratio) / len(ratio)
        fmt = lambda x: f"{100 * sum(x) / len(x):.1f} % / {100 * max(x):.1f} %" if x else "-"
        print(f"| {label} | {v:.0f} | {ka:.3f} | {kg:.3f} | {first:.3f} | {mean_early:.3f} | {mean_all:.3f} | {fmt(sp_run)} | {fmt(sp_arr)} |")
    if png:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        fig, ax = plt.subplots(figsize=(7, 4.5))
        ax.plot(ts, hs["K_factor_mean"], "k-", label="stationary (same nodes)")
        for label, h, s in runs:
            v = s["growth_speed"]
            ka = (1 - v / cR) / math.sqrt(1 - v / cd)
            ax.plot(h["t_us"], h["K_factor_mean"], "o-", ms=3, label=f"running, {label}")
            t0 = s["growth_start_us"]
            tt = [t for t in ts if t >= t0 and t <= t0 + (s["final_crack_length"] - 0.0024) / v * 1e6 + 1e-6]
            ax.plot(tt, [ka * hs["K_factor_mean"][ts.index(t)] for t in tt], "--", label=f"k(v) K_stat, v = {v:.0f} m/s")
        ax.set(xlabel="t [us]", ylabel="K / (sigma sqrt(pi a0))", xlim=(6, max(ts)), title="Chen's plate: onset of growth vs Freund's k(v)")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        print(png)


if __name__ == "__main__":
    main()
