#!/usr/bin/python3
"""Plot of one piezo_harvester run (seed 002 paper 1: the piezoelectric energy harvester, issue 35).

  /usr/bin/python3 tools/plot_piezo_harvester.py out/piezo_harvester

Writes into the run folder, from summary.json and the analysis' CSV files:
  static     deflection.png  the deflection along the beam against the laminated bender's closed form
             (w = tip (x / L)^2, beam and plate theory)
  harmonic   power_R.png     the sweep's peak power against the load R (the FE beam; the Erturk-Inman model with
                             and without the induced potential on the same grid), R_opt marked
             frf.png         the load voltage and the power against the frequency, one curve per load (at most 8
                             shown, log-spaced through the sweep), f_sc and f_oc marked
  transient  voltage.png     the load voltage's time history (paper 1's Fig. 4), the steady amplitude of the
                             harmonic solve dashed; below it the harvested power and its mean over the last periods
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, load_csv, pyplot, read_summary, run_folder, run_parser  # noqa: E402


def save(fig, run, name):
    fig.tight_layout()
    out = os.path.join(run, name)
    fig.savefig(out, dpi=130)
    print(out)


def static(run, s, plt, np):
    d = load_csv(os.path.join(run, "deflection.csv"), required=("x", "deflection"))
    o = np.argsort(d["x"])
    x, w = d["x"][o], d["deflection"][o]
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(1e3 * x, 1e6 * w, "o", ms=3, label=f"FE (tip {1e6 * s['tip_deflection']:.4g} um)")
    L = x.max() if len(x) else 1.0
    xs = np.linspace(0, L, 200)
    for key, style, name in (("tip_deflection_beam_theory", "-", "beam theory"), ("tip_deflection_plate_theory", "--", "plate theory")):
        if isinstance(s.get(key), (int, float)):
            ax.plot(1e3 * xs, 1e6 * s[key] * (xs / L) ** 2, style, lw=1, label=f"{name} (tip {1e6 * s[key]:.4g} um)")
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("deflection [um]")
    ax.set_title(f"{s['title']}\n{s['accuracy']}, {int(s['unknowns'])} unknowns", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, run, "deflection.png")


def harmonic(run, s, plt, np):
    p = load_csv(os.path.join(run, "power_R.csv"), required=("R_ohm", "P_max", "f_peak_hz"))
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.loglog(p["R_ohm"], 1e3 * p["P_max"], "o-", ms=3, label="FE, peak over the sweep")
    for key, style, name in (("P_max_ei09", ":", "EI09"), ("P_max_ei09_induced", "--", "EI09 + induced potential")):
        if key in p and np.all(np.isfinite(p[key])):
            ax.loglog(p["R_ohm"], 1e3 * p[key], style, lw=1.2, label=name)
    ax.axvline(s["R_opt"], color="k", lw=0.6, ls=":")
    ax.set_xlabel("load R [ohm]")
    ax.set_ylabel("mean power [mW]")
    ax.set_title(f"{s['title']}\nR_opt {s['R_opt']:.4g} ohm, P_max {1e3 * s['P_max']:.4g} mW at {s['f_at_P_max']:.2f} Hz "
                 f"({s['base_acceleration']:g} m/s^2)", fontsize=9)
    ax.grid(alpha=0.3, which="both")
    ax.legend(fontsize=8)
    save(fig, run, "power_R.png")

    f = load_csv(os.path.join(run, "frf.csv"), required=("R_ohm", "f_hz", "V_amplitude", "power"))
    loads = np.unique(f["R_ohm"])
    shown = loads if len(loads) <= 8 else loads[np.unique(np.round(np.linspace(0, len(loads) - 1, 8)).astype(int))]
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(6.4, 6.4), sharex=True)
    for R in shown:
        m = f["R_ohm"] == R
        a1.semilogy(f["f_hz"][m], f["V_amplitude"][m], lw=1, label=f"{R:.3g} ohm")
        a2.semilogy(f["f_hz"][m], 1e3 * f["power"][m], lw=1)
    for a in (a1, a2):
        for key, name in (("f_sc", "f_sc"), ("f_oc", "f_oc")):
            a.axvline(s[key], color="k", lw=0.6, ls=":")
        a.grid(alpha=0.3, which="both")
    a1.set_ylabel("load voltage amplitude [V]")
    a2.set_ylabel("mean power [mW]")
    a2.set_xlabel("frequency [Hz]")
    a1.set_title(f"{s['title']}\nf_sc {s['f_sc']:.3f} Hz, f_oc {s['f_oc']:.3f} Hz (FE, {int(s['unknowns'])} unknowns)", fontsize=9)
    a1.legend(fontsize=7, ncol=2)
    save(fig, run, "frf.png")


def transient(run, s, plt, np):
    c = load_csv(os.path.join(run, "series.csv"), required=("t", "V", "power"))
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(7.2, 6.0), sharex=True)
    a1.plot(c["t"], c["V"], lw=0.6, label="load voltage (FE, time domain)")
    h = s.get("harmonic_voltage_amplitude")
    if isinstance(h, (int, float)):
        for sign in (1, -1):
            a1.axhline(sign * h, color="k", lw=0.8, ls="--", label="harmonic solve amplitude" if sign > 0 else None)
    a1.set_ylabel("V [V]")
    a1.legend(fontsize=8, loc="lower right")
    a1.grid(alpha=0.3)
    amp = s.get("voltage_amplitude")
    a1.set_title(f"{s['title']}\n{s['frequency']:.3f} Hz, {s['load_ohm']:g} ohm, dt = T/{int(s['steps_per_period'])}, "
                 f"steady |V| {amp if amp is None else f'{amp:.4g}'} V (harmonic {h:.4g} V)", fontsize=9)
    a2.plot(c["t"], 1e3 * c["power"], lw=0.6, label="instantaneous power")
    if isinstance(s.get("mean_power"), (int, float)):
        a2.axhline(1e3 * s["mean_power"], color="C3", lw=1, label=f"mean over the last periods {1e3 * s['mean_power']:.4g} mW")
    a2.set_xlabel("t [s]")
    a2.set_ylabel("power [mW]")
    a2.legend(fontsize=8, loc="lower right")
    a2.grid(alpha=0.3)
    save(fig, run, "voltage.png")


def main():
    run = run_folder(run_parser(__doc__, "out/piezo_harvester").parse_args().run)
    s = read_summary(run, cases=("piezo_harvester",))
    kind = s.get("analysis")
    if kind not in ("static", "harmonic", "transient"):
        raise InputError(f"{run}/summary.json: analysis {kind!r} (expected static, harmonic or transient)")
    import numpy as np

    {"static": static, "harmonic": harmonic, "transient": transient}[kind](run, s, pyplot(), np)
    return 0


if __name__ == "__main__":
    guarded(main)
