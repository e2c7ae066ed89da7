#!/usr/bin/python3
"""Plots of one helmholtz app run (out/<run>/): the COCG convergence history and, if the scene asked
for a profile, the pressure along the line next to the analytic one (seed 002 paper 3 Figs. 5-6).

  /usr/bin/python3 tools/plot_helmholtz_run.py out/helmholtz_duct

Writes convergence.png and profile.png into the run folder.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import guarded, load_csv, pyplot, read_summary, run_folder, run_parser  # noqa: E402


def main():
    run = run_folder(run_parser(__doc__, "out/helmholtz").parse_args().run)
    s = read_summary(run, cases=("helmholtz",))
    title = f"{s['title']}\np = {s['order']}, {s['dofs']} DoFs, {s['precision']}"
    c = load_csv(os.path.join(run, "convergence.csv"), required=("iteration", "relative_residual"))
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.semilogy(c["iteration"], c["relative_residual"])
    ax.axhline(s["tolerance"], color="0.5", ls="--", label=f"tolerance {s['tolerance']:g}")
    ax.set_xlabel("COCG iteration")
    ax.set_ylabel("relative residual |r| / |b|")
    ax.set_title(f"{title}: {s['status']} after {s['iterations']} iterations", fontsize=8)
    ax.legend()
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(run, "convergence.png"), dpi=110)
    print(f"plot: {os.path.join(run, 'convergence.png')}")
    prof = os.path.join(run, "profile.csv")
    if os.path.exists(prof):
        p = load_csv(prof)
        fig, ax = plt.subplots(figsize=(7, 4))
        ax.plot(p["x"], p["pressure_re"], "o", ms=3, label="Re p, FEM")
        ax.plot(p["x"], p["pressure_im"], "s", ms=3, label="Im p, FEM")
        if "exact_pressure_re" in p:
            ax.plot(p["x"], p["exact_pressure_re"], "-", lw=1, label="Re p, analytic")
            ax.plot(p["x"], p["exact_pressure_im"], "-", lw=1, label="Im p, analytic")
        ax.set_xlabel("x [m]")
        ax.set_ylabel("pressure p = j omega rho Phi [Pa]")
        err = s.get("l2_error")
        ax.set_title(title + (f", L2 error {err:.2e}" if err is not None else ""), fontsize=8)
        ax.legend(fontsize=8)
        ax.grid(True, alpha=0.3)
        fig.tight_layout()
        fig.savefig(os.path.join(run, "profile.png"), dpi=110)
        print(f"plot: {os.path.join(run, 'profile.png')}")


if __name__ == "__main__":
    guarded(main)
