"""Table of bench/peers/run_peers.sh: polymech's complex apply next to deal.II's real apply, per order.

  /usr/bin/python3 bench/peers/peers_table.py out/peers > out/peers/peers.md

Reads DIR/stream_<r>.json, DIR/polymech_<r>.json (Google Benchmark JSON) and DIR/dealii_<r>.txt (the
peer's key=value lines); takes the median over the repetitions of the CPU-time rates.
"""
import glob
import json
import os
import statistics
import sys


def load_json(pattern):
    runs = []
    for f in sorted(glob.glob(pattern)):
        with open(f) as fh:
            runs.append(json.load(fh)["benchmarks"])
    return runs


def seconds(b):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
    return b["cpu_time"] * scale


def main(folder):
    stream = []
    for run in load_json(os.path.join(folder, "stream_*.json")):
        for b in run:
            if b["name"].startswith("BM_StreamTriad/8388608"):
                stream.append(3 * 8 * 8388608 / seconds(b))
    poly = {}
    for run in load_json(os.path.join(folder, "polymech_*.json")):
        for b in run:
            if not b["name"].startswith("BM_MatrixFreeApply<double>/"):
                continue
            p = int(b["name"].split("/")[1])
            rate = b["dofs"] / seconds(b)
            poly.setdefault(p, {"dofs": int(b["dofs"]), "rates": [], "bytes_per_dof": b["bytes_per_dof"]})["rates"].append(rate)
    deal = {}
    version, lanes = "", ""
    for f in sorted(glob.glob(os.path.join(folder, "dealii_*.txt"))):
        for line in open(f):
            if not line.startswith("dealii "):
                continue
            kv = dict(item.split("=", 1) for item in line.split()[1:])
            p = int(kv["p"])
            deal.setdefault(p, {"dofs": int(kv["dofs"]), "rates": []})["rates"].append(float(kv["dofs_per_second_cpu"]))
            version, lanes = kv["version"], kv["vector_lanes"]
    bw = statistics.median(stream) if stream else float("nan")
    print("STREAM triad, 1 thread, CPU time (median of %d): %.1f GB/s" % (len(stream), bw / 1e9))
    if deal:
        print("deal.II %s, VectorizedArray<double> lanes: %s" % (version, lanes))
    print()
    print("| p | polymech DoFs | polymech complex DoF/s | deal.II DoFs | deal.II real DoF/s | ratio | polymech traffic model | of STREAM |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for p in sorted(poly):
        r = statistics.median(poly[p]["rates"])
        bpd = poly[p]["bytes_per_dof"]
        d = deal.get(p)
        dr = statistics.median(d["rates"]) if d else None
        print("| %d | %d | %.1f M | %s | %s | %s | %.0f B/DoF, %.1f GB/s | %.0f %% |" % (
            p, poly[p]["dofs"], r / 1e6, d["dofs"] if d else "-", "%.1f M" % (dr / 1e6) if d else "-",
            "%.2fx" % (r / dr) if d else "-", bpd, r * bpd / 1e9, 100 * r * bpd / bw))
    print()
    print("(medians of %d repetitions; rates are DoFs per CPU second of one apply, one thread)" % len(stream))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: peers_table.py <folder of run_peers.sh>")
    main(sys.argv[1])
