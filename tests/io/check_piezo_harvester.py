#!/usr/bin/python3
"""Runs apps/piezo_harvester on a scene at a small size and checks its summary.json and CSV files against the
closed forms (issue 35; seed 002 paper 1):

  check_piezo_harvester.py APP CASE OUT --source DIR

CASE:
  static      scenes/piezo/pvdf_bender.toml at --accuracy draft: the tip deflection within 1 % of the narrow beam's
              3 d31 V L^2 / (2 t^2) = 3.30e-5 m (plane stress), the capacitance eps A / t, deflection.csv
  strain      the same bender in plane strain: within 1 % of the wide plate's (1 + nu) times that
  harmonic    tests/io/data/piezo_sweep_small.toml: f_sc and f_oc against the Erturk-Inman beam with the induced
              potential, the sweep's P_max against the beam model's on the same grid, the files' rows
  transient   scenes/piezo/dutoit_harvester.toml at --accuracy draft: the steady amplitude and mean power against
              the harmonic solve at the same frequency, the energy balance, one solve per step, series.csv
  partitioned tests/io/data/piezo_transient_small.toml with the monolithic and the partitioned scheme: the same
              voltage history (to the loop's tolerance), at most two solves a step after the first
Standard library only. Prints "piezo_harvester CASE: passed" and exits 0, or names what failed and exits 1.
"""
import argparse
import csv
import json
import math
import os
import subprocess
import sys


def run(app, scene, out, *extra):
    cmd = [app, "--scene", scene, "--out", out, "--threads", "1", "--quiet"] + list(extra)
    r = subprocess.run(cmd, capture_output=True, text=True, timeout=600)
    if r.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)}: exit code {r.returncode}\n{r.stderr}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


class Checks:
    def __init__(self):
        self.failed = []

    def near(self, what, value, reference, rtol):
        ok = value is not None and reference not in (None, 0) and abs(value / reference - 1) <= rtol
        print(f"  {what}: {value:.6g} against {reference:.6g} ({100 * (value / reference - 1):+.3f} %, allowed {100 * rtol:g} %)"
              if ok or (value is not None and reference) else f"  {what}: {value} against {reference}")
        if not ok:
            self.failed.append(what)

    def true(self, what, cond):
        print(f"  {what}: {'yes' if cond else 'NO'}")
        if not cond:
            self.failed.append(what)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("app")
    ap.add_argument("case", choices=["static", "strain", "harmonic", "transient", "partitioned"])
    ap.add_argument("out")
    ap.add_argument("--source", default=".")
    a = ap.parse_args()
    src = lambda *p: os.path.join(a.source, *p)  # noqa: E731
    c = Checks()
    d31, nu, V, L, t = 2.2e-11, 0.29, 100.0, 0.1, 1e-3
    beam = 1.5 * d31 * V * L * L / (t * t)  # 3.30e-5 m
    if a.case in ("static", "strain"):
        scene = src("scenes", "piezo", "pvdf_bender.toml")
        if a.case == "strain":
            os.makedirs(a.out, exist_ok=True)
            text = open(scene).read().replace('plane = "stress"', 'plane = "strain"')
            scene = os.path.join(a.out, "pvdf_bender_strain.toml")
            with open(scene, "w") as f:
                f.write(text)
        out = os.path.join(a.out, "run")
        j = run(a.app, scene, out, "--accuracy", "draft")
        if a.case == "static":
            c.near("|tip_deflection| / (3 d31 V L^2 / (2 t^2))", abs(j["tip_deflection"]), beam, 0.01)
            c.near("tip_deflection_beam_theory", -j["tip_deflection_beam_theory"], beam, 1e-9)
            c.near("capacitance_drive / (eps33 A / t)", j["capacitance_drive"], 12 * 8.8541878128e-12 * L * 5e-3 / t, 0.01)
            c.true("tip_deflection_error_beam reported", abs(j["tip_deflection_error_beam"]) < 0.01)
        else:
            c.near("|tip_deflection| / ((1 + nu) 3 d31 V L^2 / (2 t^2))", abs(j["tip_deflection"]), (1 + nu) * beam, 0.01)
            c.near("tip_deflection_plate_theory", -j["tip_deflection_plate_theory"], (1 + nu) * beam, 1e-9)
        r = rows(os.path.join(out, "deflection.csv"))
        x = [float(e["x"]) for e in r]
        w = [float(e["deflection"]) for e in r]
        c.true("deflection.csv from the root (w = 0) to the tip", abs(min(x)) < 1e-15 and abs(max(x) - L) < 1e-12 and w[x.index(min(x))] == 0)
        c.near("deflection.csv at the tip against tip_deflection", w[x.index(max(x))], j["tip_deflection"], 0.01)
    elif a.case == "harmonic":
        out = os.path.join(a.out, "run")
        j = run(a.app, src("tests", "io", "data", "piezo_sweep_small.toml"), out)
        for k in ("f_sc", "f_oc", "f_sc_ei09", "f_oc_ei09", "f_sc_ei09_induced_potential", "f_oc_ei09_induced_potential",
                  "R_opt", "P_max", "R_opt_ei09_induced_potential", "P_max_ei09_induced_potential", "wall_seconds"):
            c.true(f"summary has {k}", isinstance(j.get(k), (int, float)))
        c.near("f_sc (FE) against EI09 with the induced potential", j["f_sc"], j["f_sc_ei09_induced_potential"], 0.01)
        c.near("f_oc (FE) against EI09 with the induced potential", j["f_oc"], j["f_oc_ei09_induced_potential"], 0.01)
        c.true("f_oc > 1.02 f_sc (k^2 ~ 6.7 %)", j["f_oc"] > 1.02 * j["f_sc"])
        c.near("P_max (FE) against EI09 with the induced potential on the same grid", j["P_max"], j["P_max_ei09_induced_potential"], 0.05)
        frf, per = rows(os.path.join(out, "frf.csv")), rows(os.path.join(out, "power_R.csv"))
        c.true("frf.csv: loads x points rows", len(frf) == int(j["loads"]) * int(j["points"]))
        c.true("power_R.csv: one row per load", len(per) == int(j["loads"]))
        c.true("R_opt is the load of the largest P_max", max(per, key=lambda e: float(e["P_max"]))["R_ohm"] and
               abs(float(max(per, key=lambda e: float(e["P_max"]))["R_ohm"]) / j["R_opt"] - 1) < 1e-12)
    elif a.case == "transient":
        out = os.path.join(a.out, "run")
        j = run(a.app, src("scenes", "piezo", "dutoit_harvester.toml"), out, "--accuracy", "draft")
        c.near("steady voltage amplitude against the harmonic solve", j["voltage_amplitude"], j["harmonic_voltage_amplitude"], 0.01)
        c.near("mean power over the last periods against the harmonic solve", j["mean_power"], j["harmonic_mean_power"], 0.02)
        c.true("|energy_balance_error| < 1e-6", abs(j["energy_balance_error"]) < 1e-6)
        c.true("one solve per step (monolithic)", j["solves"] == j["steps"])
        c.true("not diverged", j["diverged"] is False)
        s = rows(os.path.join(out, "series.csv"))
        c.true("series.csv: steps + 1 rows", len(s) == j["steps"] + 1)
        c.true("series.csv columns", set(s[0]) >= {"t", "base_acceleration", "V", "tip", "power", "work_in", "work_circuit"})
    else:
        base = src("tests", "io", "data", "piezo_transient_small.toml")
        os.makedirs(a.out, exist_ok=True)
        part = os.path.join(a.out, "partitioned.toml")
        with open(part, "w") as f:
            f.write(open(base).read().replace('scheme = "monolithic"', 'scheme = "partitioned"'))
        jm = run(a.app, base, os.path.join(a.out, "monolithic"))
        jp = run(a.app, part, os.path.join(a.out, "partitioned"))
        vm = [float(e["V"]) for e in rows(os.path.join(a.out, "monolithic", "series.csv"))]
        vp = [float(e["V"]) for e in rows(os.path.join(a.out, "partitioned", "series.csv"))]
        peak = max(abs(v) for v in vm)
        diff = max(abs(x - y) for x, y in zip(vm, vp))
        print(f"  max |V_partitioned - V_monolithic| = {diff:.3e} V of {peak:.4g} V")
        c.true("same voltage history (1e-6 of the peak)", len(vm) == len(vp) and diff <= 1e-6 * peak)
        c.true("partitioned: at most 2 solves a step (+ the first step's Jacobian)", jp["solves"] <= 2 * jp["steps"] + 4)
        c.near("steady amplitude against the harmonic solve", jp["voltage_amplitude"], jp["harmonic_voltage_amplitude"], 0.01)
        c.true("|energy_balance_error| < 1e-6 (partitioned)", abs(jp["energy_balance_error"]) < 1e-6)
        c.true("scheme recorded", jm["scheme"] == "monolithic" and jp["scheme"] == "partitioned")
    if c.failed:
        print(f"piezo_harvester {a.case}: FAILED: {', '.join(c.failed)}")
        return 1
    print(f"piezo_harvester {a.case}: passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
