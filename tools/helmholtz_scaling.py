"""Tables of bench/scaling_helmholtz.sh: the Helmholtz cube split into 1 .. R MPI parts.

  /usr/bin/python3 tools/helmholtz_scaling.py out/scaling > out/scaling/scaling.md

For every case (pXnY: order X, Y^3 elements) and rank count: COCG iterations, L2 error (eq. (28)),
solve time, speed-up S_n = T_1 / T_n and efficiency E_n = S_n / n (seed 002 paper 3 eqs. (30), (31)),
and the halo volume per part (ghost DoFs received, owned DoFs sent; largest part). Times are measured
only where a rank has a core (this machine: 1 and 2 ranks); for every rank count a MODEL gives the
time from the measured one-rank costs and the partition of that run:
  T_n = iterations_n x (max_r elements_r x t_element + max_r local_dofs_r x t_vector
                        + t_exchange(max_r halo bytes_r) + 2 t_allreduce),
with t_element, t_vector from the one-rank run (apply time per element, rest of an iteration per
DoF), t_exchange(b) = alpha + b / beta and t_allreduce from bench/mpi_probe (DIR/probe.txt, medians:
MPI on this machine when both ranks run) or, without it, fitted to the two-rank runs.
"""
import glob
import json
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plotting import InputError, guarded  # noqa: E402


def load(folder):
    runs = {}
    for f in glob.glob(os.path.join(folder, "*", "ranks*", "summary.json")):
        case = f.split(os.sep)[-3]
        r = int(f.split(os.sep)[-2][5:])
        runs.setdefault(case, {})[r] = json.load(open(f))
    return runs


def part_stats(s):
    parts = s["parts"]
    local = [p["owned_dofs"] + p["ghost_dofs"] for p in parts]
    return {
        "elements": max(p["elements"] for p in parts),
        "local": max(local),
        "ghost": max(p["ghost_dofs"] for p in parts),
        "send": max(p["halo_send_dofs"] for p in parts),
        "halo_s": max(p["halo_seconds"] / p["halo_exchanges"] if p["halo_exchanges"] else 0.0 for p in parts),
    }


def main(folder):
    if not os.path.isdir(folder):
        raise InputError(f"{folder}: no such folder (give the --out folder of bench/scaling_helmholtz.sh)")
    runs = load(folder)
    if not runs:
        raise InputError(f"{os.path.join(folder, '<case>', 'ranks<R>', 'summary.json')}: no such files "
                         "(give the --out folder of bench/scaling_helmholtz.sh)")
    bytes_per_dof = 16  # complex double
    # one-rank costs and two-rank communication, per case
    base, fit = {}, []
    for case, rr in runs.items():
        if 1 not in rr:
            continue
        s = rr[1]
        t_apply = s["dofs"] / s["apply_dofs_per_second"]
        t_iter = s["solve_seconds"] / (s["iterations"] + 3)
        base[case] = {"t_element": t_apply / s["elements"], "t_vector": max(0.0, t_iter - t_apply) / s["dofs"]}
        if 2 in rr:
            st = part_stats(rr[2])
            fit.append((bytes_per_dof * max(st["send"], st["ghost"]), st["halo_s"]))
    # t_exchange(b) = alpha + b / beta, least squares over the two-rank runs
    alpha, inv_beta = 0.0, 0.0
    probe = os.path.join(folder, "probe.txt")
    probed = {}
    if os.path.exists(probe):
        for line in open(probe):
            kv = dict(item.split("=", 1) for item in line.split()[2:])
            probed[line.split()[1] + kv.get("bytes", "")] = float(kv["median_seconds"])
    if "exchange1024" in probed and "exchange262144" in probed:
        inv_beta = (probed["exchange262144"] - probed["exchange1024"]) / (262144 - 1024)
        alpha = max(0.0, probed["exchange1024"] - 1024 * inv_beta)
    elif len(fit) >= 2:
        mb = statistics.mean(b for b, _ in fit)
        mt = statistics.mean(t for _, t in fit)
        var = sum((b - mb) ** 2 for b, _ in fit)
        inv_beta = max(0.0, sum((b - mb) * (t - mt) for b, t in fit) / var) if var > 0 else 0.0
        alpha = max(0.0, mt - inv_beta * mb)
    elif fit:
        alpha = fit[0][1]

    def model(case, s, t_red):
        b = base[case]
        st = part_stats(s)
        per_it = st["elements"] * b["t_element"] + st["local"] * b["t_vector"]
        if s["ranks"] > 1:
            per_it += alpha + inv_beta * bytes_per_dof * max(st["send"], st["ghost"]) + 2 * t_red
        return (s["iterations"] + 3) * per_it

    red = []
    for case, rr in runs.items():
        if 2 in rr and case in base:
            no_red = model(case, rr[2], 0.0)
            red.append(max(0.0, (rr[2]["solve_seconds"] - no_red) / (rr[2]["iterations"] + 3) / 2))
    t_red = probed.get("allreduce", statistics.median(red) if red else 0.0)
    print("Model constants (%s): exchange alpha = %.2f us, 1/beta = %.3f ns/byte (%.1f GB/s), allreduce %.2f us"
          % ("bench/mpi_probe" if probed else "fitted to the two-rank runs", alpha * 1e6, inv_beta * 1e9,
             1e-9 / inv_beta if inv_beta > 0 else float("inf"), t_red * 1e6))
    print()
    print("| case | nodes (DoFs) | ranks | iterations | L2 error | solve measured | S_n measured | E_n measured "
          "| solve model | S_n model | E_n model | ghost DoFs / part (max) | sent DoFs / part (max) |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    order = sorted(runs, key=lambda c: (int(c[1:c.index("n")]), runs[c][min(runs[c])]["dofs"]))
    for case in order:
        rr = runs[case]
        t1 = rr[1]["solve_seconds"] if 1 in rr else None
        m1 = model(case, rr[1], t_red) if 1 in rr and case in base else None
        for r in sorted(rr):
            s = rr[r]
            st = part_stats(s)
            measured = r <= 2
            sn = t1 / s["solve_seconds"] if (t1 and measured) else None
            mod = model(case, s, t_red) if case in base else None
            smod = m1 / mod if (m1 and mod) else None
            print("| %s | %d | %d | %d | %.10e | %s | %s | %s | %s | %s | %s | %d | %d |" % (
                case, s["dofs"], r, s["iterations"], s["l2_error"],
                "%.4f s" % s["solve_seconds"] if measured else "(oversubscribed)",
                "%.2f" % sn if sn else "-", "%.0f %%" % (100 * sn / r) if sn else "-",
                "%.4f s" % mod if mod else "-", "%.2f" % smod if smod else "-",
                "%.0f %%" % (100 * smod / r) if smod else "-", st["ghost"], st["send"]))


if __name__ == "__main__":
    import argparse

    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("folder", help="the output folder of bench/scaling_helmholtz.sh")
    guarded(lambda: main(ap.parse_args().folder))
