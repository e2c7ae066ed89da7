#!/usr/bin/env python3
"""The ISPH dam break's surge front against the experiments, and the time shift that would align them.

Reads the `front_positions` ([[T, Z], ...], T = t sqrt(2 g / a), Z = x / a) of one or more summary.json
files, prints Z against Martin & Moyce (1952) and Koshizuka & Oka (1996) at their points, fits the one
shift dT that minimises the squared relative error of Z(T - dT) against each experiment (a start that
lags in the experiment: the gate or diaphragm takes a while to clear the column, so its front starts
late), and plots Z(T) with both experiments and the shifted curve.

  /usr/bin/python3 tools/isph_dam_break.py out/isph_dam[:label] ...        # run folders: front.png in the first
  /usr/bin/python3 tools/isph_dam_break.py docs/figures/isph/dam_break/summary.json[:label] ... \
      [--a 0.146] [--png docs/figures/isph/dam_break/front.png]

Each run is an isph dam-break run's output folder (the app's --out) or its summary.json. The plot goes to
--png; without --png it goes to front.png in the first run given as a folder (only the table is printed
when every run was given as a summary.json).

The experimental points are those of tests/isph/test_isph_cases.cpp and docs/VALIDATION.md (Martin &
Moyce's n^2 = 2 column, Tables 2 and 6; Koshizuka & Oka's as digitised from their figure).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, pyplot, read_json  # noqa: E402

MARTIN_MOYCE = np.array([(0.41, 1.11), (0.84, 1.22), (1.19, 1.44), (1.43, 1.67), (1.63, 1.89), (1.83, 2.11),
                         (1.98, 2.33), (2.20, 2.56), (2.32, 2.78), (2.51, 3.00), (2.65, 3.22), (2.83, 3.44),
                         (2.98, 3.67), (3.11, 3.89)])
KOSHIZUKA_OKA = np.array([(0.381, 1.111), (0.769, 1.252), (1.153, 1.505), (1.537, 1.892), (1.935, 2.241),
                          (2.323, 2.615), (2.719, 3.003), (3.096, 3.624)])
EXPERIMENTS = (("Martin & Moyce", MARTIN_MOYCE), ("Koshizuka & Oka", KOSHIZUKA_OKA))
WALL = 3.95  # Z at which the front reaches the far wall (tank 4a wide): later samples are not a front


def relative_errors(T, Z, points, shift):
    """Z(T - shift) / Z_exp - 1 at the experiment's points (linear interpolation of the run)."""
    return np.interp(points[:, 0] - shift, T, Z) / points[:, 1] - 1.0


def best_shift(T, Z, points):
    shifts = np.arange(0.0, 0.6, 0.0025)
    return min(shifts, key=lambda s: float(np.sum(relative_errors(T, Z, points, s) ** 2)))


def front_of(path, label=""):
    """(label, T, Z) of a dam-break summary.json: the front positions before it reaches the far wall."""
    s = read_json(path)
    if "front_positions" not in s:
        raise InputError(f"{path}: no front_positions (not a dam-break summary: case '{s.get('case')}')")
    f = np.array(s["front_positions"], dtype=float).reshape(-1, 2)
    keep = f[:, 1] < WALL
    if np.count_nonzero(keep) < 2:
        raise InputError(f"{path}: fewer than two front positions before the far wall (a run of too few steps)")
    return (label or f"{s.get('particles', '?')} particles", f[keep, 0], f[keep, 1])


def fit_table(runs, t_unit_ms):
    """Prints the table of errors and shifts; returns the fits [(label, experiment, shift), ...]."""
    print("| run | experiment | rms / max error, as run | best shift dT (ms) | rms / max error, shifted | from T = 0.8 on, shifted |")
    print("|---|---|---|---|---|---|")
    fits = []
    for label, T, Z in runs:
        for name, pts in EXPERIMENTS:
            pts = pts[pts[:, 0] <= T[-1]]
            if len(pts) == 0:
                print(f"| {label} | {name} | no measured point before T = {T[-1]:.2f} |  |  |  |")
                continue
            e0 = relative_errors(T, Z, pts, 0.0)
            s = best_shift(T, Z, pts)
            e = relative_errors(T, Z, pts, s)
            late = e[pts[:, 0] >= 0.8]
            fits.append((label, name, s))
            late_text = f"{100 * math.sqrt(np.mean(late ** 2)):.1f} / {100 * np.abs(late).max():.1f} %" if len(late) else "-"
            print(f"| {label} | {name} | {100 * math.sqrt(np.mean(e0 ** 2)):.1f} / {100 * np.abs(e0).max():.1f} % | "
                  f"{s:.3f} ({s * t_unit_ms:.1f}) | {100 * math.sqrt(np.mean(e ** 2)):.1f} / {100 * np.abs(e).max():.1f} % | "
                  f"{late_text} |")
            print("|  |  | per point, shifted: " + " ".join(f"{t:.2f}: {100 * x:+.1f}" for t, x in zip(pts[:, 0], e)) + " |  |  |  |")
    return fits


def plot_fronts(runs, fits, png):
    """Z(T) of each run, shifted by its best Martin & Moyce shift too, with both experiments."""
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for name, pts in EXPERIMENTS:
        ax.plot(pts[:, 0], pts[:, 1], "o" if name.startswith("Martin") else "s", mfc="none", label=name)
    for label, T, Z in runs:
        line, = ax.plot(T, Z, label=f"ISPH, {label}")
        s = next((sh for (lb, nm, sh) in fits if lb == label and nm.startswith("Martin")), None)
        if s is not None:
            ax.plot(T + s, Z, "--", color=line.get_color(), alpha=0.6, label=f"ISPH, {label}, shifted by dT = {s:.2f}")
    ax.set(xlabel="T = t sqrt(2 g / a)", ylabel="Z = x / a", title="Dam break: surge front")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", help="RUN_DIR[:label] or summary.json[:label]")
    ap.add_argument("--a", type=float, default=0.146, help="column width a [m] (for the shift in ms)")
    ap.add_argument("--g", type=float, default=9.8)
    ap.add_argument("--png", default=None, help="the plot (default: front.png in the first run folder given)")
    args = ap.parse_args()
    runs = []
    for spec in args.runs:
        path, _, label = spec.partition(":")
        if not os.path.exists(path):
            raise InputError(f"{path}: no such folder or file (give an isph dam-break run's --out folder or its summary.json)")
        if os.path.isdir(path):
            if args.png is None:
                args.png = os.path.join(path, "front.png")
            path = os.path.join(path, "summary.json")
        runs.append(front_of(path, label))
    fits = fit_table(runs, 1e3 * math.sqrt(args.a / (2 * args.g)))
    if args.png:
        plot_fronts(runs, fits, args.png)
        print(args.png)


if __name__ == "__main__":
    guarded(main)
