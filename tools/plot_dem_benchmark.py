#!/usr/bin/python3
"""Plots of the Chung & Ooi (2011) DEM benchmark from dem_benchmark's summary.json: the test-1 and test-2
normal impacts against Hertz theory, the test-4 rebound angles of the contact point and of the centre
against the incidence angle (with the gross-sliding closed forms and the experiment), and the test-3
restitution measured against the input.

  /usr/bin/python3 tools/plot_dem_benchmark.py out/dem_benchmark [out_dir]
  /usr/bin/python3 tools/plot_dem_benchmark.py docs/figures/dem/summary.json [out_dir]

Takes the run's folder (or its summary.json) and writes, for the tests the summary holds, next to the
summary (or into out_dir):
  test12_hertz.png          tests 1 and 2 (and the meshed wall of test 2): maximum force against maximum
                            overlap on the Hertz curve, and the errors of force, overlap, contact time and
                            restitution (1 for an elastic impact)
  test3_restitution.png     measured against input coefficient of restitution
  test4_rebound.png         rebound angle of the contact point against incidence
  test4_centre_rebound.png  the centre of mass's rebound angle with Kharaz et al.'s measured points
                            (tests/dem/data/kharaz2001_centre_rebound.csv)
A summary without any of them (not a dem_benchmark run) is an error (exit code 2).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded, pyplot, read_json, run_parser  # noqa: E402


MU, E = 0.092, 0.98  # scenes/dem/chung_ooi_test4.toml
KHARAZ = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "dem", "data",
                      "kharaz2001_centre_rebound.csv")


def plot_test4(rows, impulse, impulse_label, what, title, path, experiment=None):
    """Rebound angle against incidence (rows [[incidence, rebound], ...]) with the gross-sliding closed form
    tan r = (tan i - impulse) / e, where impulse is 3.5 mu (1+e) for the contact point and mu (1+e) for the
    centre; `experiment` is a CSV of measured [incidence, rebound] rows to draw too."""
    plt = pyplot()
    onset = math.degrees(math.atan(3.5 * MU * (1 + E)))  # gross sliding throughout from here on
    fine = [onset + k * (89 - onset) / 100 for k in range(101)]
    closed = [math.degrees(math.atan((math.tan(math.radians(a)) - impulse) / E)) for a in fine]
    fig, ax = plt.subplots(figsize=(5.5, 4.2))
    ax.plot([r[0] for r in rows], [r[1] for r in rows], "o-", label="polymech (Hertz-Mindlin, 400 steps per contact)")
    ax.plot(fine, closed, "k--", lw=1, label=f"gross sliding: tan r = (tan i - {impulse_label}) / e")
    if experiment and os.path.exists(experiment):
        with open(experiment) as f:
            measured = [line.split(",") for line in f.read().split()[1:]]
        ax.plot([float(r[0]) for r in measured], [float(r[1]) for r in measured], "s", mfc="none", color="C3",
                label="experiment (Kharaz et al. 2001)")
        ax.plot([0, 89], [0, 89], color="0.7", lw=0.5, label="rebound = incidence")
    else:
        ax.axhline(0, color="0.6", lw=0.5)
    ax.set_xlabel("incidence angle (deg)")
    ax.set_ylabel(f"rebound angle of {what} (deg)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


# the normal impacts against Hertz theory: (summary key prefix, label)
NORMAL_IMPACTS = (("test1_", "test 1: glass sphere on glass sphere"), ("test2_", "test 2: sphere on a plane wall"),
                  ("test2_mesh_", "test 2: sphere on a meshed wall"))


def plot_normal_impacts(s, path):
    """Tests 1 and 2: (max overlap, max force) of each run on the Hertz curve F = F_H (delta / delta_H)^1.5
    (both normalised by the Hertz values of its own impact), and |relative error| of the maximum force, the
    maximum overlap, the contact time and the restitution (1 for the elastic impacts)."""
    plt = pyplot()
    runs = [(p, label) for p, label in NORMAL_IMPACTS if p + "max_force" in s]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    d = [k / 100 for k in range(106)]
    left.plot(d, [x ** 1.5 for x in d], "k-", lw=1, label="Hertz: F / F_H = (delta / delta_H)^1.5")
    measures = (("max_force", "max. force"), ("max_overlap", "max. overlap"), ("contact_time", "contact time"),
                ("restitution", "restitution - 1"))
    width = 0.8 / len(runs)
    for k, (p, label) in enumerate(runs):
        x = s[p + "max_overlap"] / s[p + "hertz_max_overlap"]
        y = s[p + "max_force"] / s[p + "hertz_max_force"]
        left.plot([x], [y], "o", ms=8 - 2 * k, mfc="none" if k else None, label=f"{label}: F_max {s[p + 'max_force']:.5g} N")
        errors = [s[p + "max_force_error"], s[p + "max_overlap_error"], s[p + "contact_time_error"],
                  s.get(p + "restitution", 1.0) - 1.0]
        xs = [i + (k - (len(runs) - 1) / 2) * width for i in range(len(measures))]
        bars = right.bar(xs, [max(abs(e), 1e-12) * 100 for e in errors], width=width, label=label)
        for b, e in zip(bars, errors):
            right.annotate(f"{100 * e:+.1e}", (b.get_x() + b.get_width() / 2, b.get_height()), ha="center", va="bottom",
                           fontsize=6, rotation=90, xytext=(0, 2), textcoords="offset points")
    left.set(xlabel="max. overlap / Hertz max. overlap", ylabel="max. force / Hertz max. force",
             title="Chung & Ooi tests 1-2: normal impacts against Hertz theory")
    left.grid(alpha=0.3)
    left.legend(fontsize=7, loc="upper left")
    right.set_yscale("log")
    lo, hi = right.get_ylim()
    right.set_ylim(lo, hi * 100)  # room for the labels and the legend
    right.set_xticks(range(len(measures)))
    right.set_xticklabels([m[1] for m in measures])
    right.set(ylabel="|relative error| [%] (labels: signed, %)", title="errors against Hertz (restitution: against 1)")
    right.grid(alpha=0.3, axis="y", which="both")
    right.legend(fontsize=7)
    for a in (left, right):
        a.title.set_fontsize(9)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main():
    p = run_parser(__doc__, "docs/figures/dem/summary.json")
    p.add_argument("out_dir", nargs="?", help="where the PNGs go (default: next to the summary)")
    a = p.parse_args()
    path = os.path.join(a.run, "summary.json") if os.path.isdir(a.run) else a.run
    if not os.path.exists(a.run):
        raise InputError(f"{a.run}: no such folder or file (give dem_benchmark's --out folder or its summary.json)")
    s = read_json(path)
    out = a.out_dir or os.path.dirname(path) or "."
    plots = [k for k in ("test1_max_force", "test2_max_force", "test2_mesh_max_force", "test3_restitution",
                         "test4_rebound_angles", "test4_centre_rebound_angles") if k in s]
    if not plots:
        hint = f" (a '{s['case']}' run)" if "case" in s else ""
        raise InputError(f"{path}: no Chung & Ooi test results (test1_*, test2_*, test3_restitution, test4_*){hint}; "
                         "give the output of dem_benchmark")
    os.makedirs(out, exist_ok=True)
    plt = pyplot()
    written = []
    if any(k.endswith("max_force") for k in plots):
        plot_normal_impacts(s, os.path.join(out, "test12_hertz.png"))
        written.append("test12_hertz.png")
    if "test4_rebound_angles" in s:
        plot_test4(s["test4_rebound_angles"], 3.5 * MU * (1 + E), "3.5 mu (1+e)", "the contact point",
                   "Chung & Ooi test 4: alumina sphere, 3.9 m/s", os.path.join(out, "test4_rebound.png"))
        written.append("test4_rebound.png")
    if "test4_centre_rebound_angles" in s:
        plot_test4(s["test4_centre_rebound_angles"], MU * (1 + E), "mu (1+e)", "the centre of mass",
                   "Chung & Ooi test 4 against the experiment", os.path.join(out, "test4_centre_rebound.png"), KHARAZ)
        written.append("test4_centre_rebound.png")
    if "test3_restitution" in s:
        e_in = [r[0] for r in s["test3_restitution"]]
        e_out = [r[1] for r in s["test3_restitution"]]
        fig, ax = plt.subplots(figsize=(4.5, 4.2))
        ax.plot([0, 1], [0, 1], "k--", lw=1, label="measured = input")
        ax.plot(e_in, e_out, "o", label="polymech (beta calibrated on Hertz)")
        ax.set_xlabel("coefficient of restitution, input")
        ax.set_ylabel("coefficient of restitution, measured")
        ax.set_title("Chung & Ooi test 3")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(os.path.join(out, "test3_restitution.png"), dpi=120)
        plt.close(fig)
        written.append("test3_restitution.png")
    print(f"plots in {out}: {', '.join(written)}")


if __name__ == "__main__":
    guarded(main)
