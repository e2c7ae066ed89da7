#!/usr/bin/python3
"""Plot of one turek_hron run (issue 36: the Turek-Hron CFD tests, seed 002 paper 1).

  /usr/bin/python3 tools/plot_turek_hron.py out/turek_hron [--forces FILE]

Writes forces.png into the run folder from summary.json and forces.csv (a transient run, CFD3): drag and
lift on the cylinder and flag against time, the window of the last period the summary's mean and amplitude
come from shaded, and the published reference (Turek & Hron 2006: drag 439.45 +- 5.6183, lift -11.893 +-
437.81, 4.3956 Hz) as lines. An FSI2 / FSI3 run (series.csv) gets four panels, drag, lift, ux(A) and uy(A),
with its summary's reference (Table 13). A harvester run (seed 002 paper 1 case 2, series.csv) gets four panels,
the plate's tip, the lift, the voltage and the power, the summary's window shaded. A steady run (CFD1, CFD2, FSI1)
has no time series: it is refused with the reason.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot, read_summary, run_folder, run_parser  # noqa: E402

REFERENCE = {"drag": (439.45, 5.6183), "lift": (-11.893, 437.81), "frequency": 4.3956}


def main():
    p = run_parser(__doc__, "out/turek_hron")
    p.add_argument("--forces", help="the time series (default: forces.csv in the run folder)")
    args = p.parse_args()
    run = run_folder(args.run)
    s = read_summary(run, cases=("turek_hron",))
    if s.get("analysis") != "transient":
        raise InputError(f"{os.path.join(run, 'summary.json')}: a steady run (no forces.csv to plot); its drag and lift are in the summary")
    if s.get("test") == "harvester":
        return harvester(run, s, args.forces)
    fsi = s.get("test") in ("fsi2", "fsi3")
    keys = ("drag", "lift", "ux", "uy") if fsi else ("drag", "lift")
    f = load_csv(args.forces or os.path.join(run, "series.csv" if fsi else "forces.csv"), required=("t",) + keys)
    reference = dict(REFERENCE)
    if fsi:
        r = s.get("reference") or {}
        reference = {k: (r.get(f"{k}_mean", float("nan")), r.get(f"{k}_amplitude", float("nan"))) for k in keys}
        reference["frequency"] = r.get("frequency")
    plt = pyplot()
    fig, axes = plt.subplots(len(keys), 1, figsize=(10, 3.2 * len(keys)), sharex=True)
    window = s.get("period_window")
    for ax, key in zip(axes, keys):
        ax.plot(f["t"], f[key], lw=0.8, label=f"polymech, level {s.get('level')}, dt {s.get('dt')}")
        mean, amp = reference[key]
        ax.axhline(mean + amp, color="k", ls="--", lw=0.7, label="reference mean +- amplitude")
        ax.axhline(mean - amp, color="k", ls="--", lw=0.7)
        if window:
            ax.axvspan(window[0], window[1], color="0.85", label="last period")
        if f"{key}_mean" in s:
            ax.set_title(f"{key}: {s[f'{key}_mean']:.4g} +- {s[f'{key}_amplitude']:.4g} (reference {mean} +- {amp})", fontsize=9)
        ax.set_ylabel(f"{key} [m]" if key in ("ux", "uy") else f"{key} [N/m]")
        ax.legend(fontsize=7, loc="lower left")
    axes[-1].set_xlabel("t [s]")
    freq = s.get("frequency")
    name = s.get("test", "cfd3").upper()
    fig.suptitle(f"Turek-Hron {name}: frequency {freq:.4f} Hz (reference {reference['frequency']})" if freq else f"Turek-Hron {name}")
    fig.tight_layout()
    out = os.path.join(run, "forces.png")
    fig.savefig(out, dpi=110)
    print(out)


def harvester(run, s, series):
    """The flow-driven harvester: tip, lift, voltage and power against time, the summary's window shaded."""
    keys = ("tip", "lift", "voltage", "power")
    units = {"tip": "m", "lift": "N/m", "voltage": "V", "power": "W/m"}
    f = load_csv(series or os.path.join(run, "series.csv"), required=("t",) + keys)
    plt = pyplot()
    fig, axes = plt.subplots(len(keys), 1, figsize=(10, 2.8 * len(keys)), sharex=True)
    window = s.get("window")
    for ax, key in zip(axes, keys):
        ax.plot(f["t"], f[key], lw=0.7, label=f"polymech, level {s.get('level')}, dt {s.get('dt')}")
        if window:
            ax.axvspan(window[0], window[1], color="0.85", label="the summary's window")
        if f"{key}_mean" in s and f"{key}_amplitude" in s:
            extra = f", {s[f'{key}_frequency']:.4g} Hz" if f"{key}_frequency" in s else ""
            ax.set_title(f"{key}: {s[f'{key}_mean']:.4g} +- {s[f'{key}_amplitude']:.4g} {units[key]}{extra}", fontsize=9)
        elif key == "voltage" and "voltage_amplitude" in s:
            ax.set_title(f"voltage: amplitude {s['voltage_amplitude']:.4g} V over the window", fontsize=9)
        elif key == "power" and "power_mean" in s:
            ax.set_title(f"power: mean {s['power_mean']:.4g} W/m over the window", fontsize=9)
        ax.set_ylabel(f"{key} [{units[key]}]")
        ax.legend(fontsize=7, loc="lower left")
    axes[-1].set_xlabel("t [s]")
    f1, ratio = s.get("f1_sc_Hz"), s.get("lift_frequency_ratio")
    title = f"flow-driven harvester: D {s.get('side', 0):.4g} m, Re {s.get('reynolds', 0):.0f}"
    if f1:
        title += f", f1 {f1:.4g} Hz, lift frequency / f1 {ratio:.3f}" if ratio is not None else f", f1 {f1:.4g} Hz"
    fig.suptitle(title)
    fig.tight_layout()
    out = os.path.join(run, "series.png")
    fig.savefig(out, dpi=110)
    print(out)


if __name__ == "__main__":
    guarded(main)
