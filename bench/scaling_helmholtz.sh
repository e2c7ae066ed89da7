#!/usr/bin/env bash
# Domain decomposition of the Helmholtz model (seed 002 paper 3 §4, Table 3, Figs. 9-11): the cube of
# eq. (27) on the paper's meshes (1331 ... 29 791 nodes, p = 1) and larger ones, with 1 .. R ranks of
# the MPI build (preset mpi), one OpenMP thread per rank. Every run's summary.json goes to
#   <out>/<case>/ranks<n>/summary.json
# and tools/helmholtz_scaling.py turns them into the table of docs/PERFORMANCE.md (time, speed-up,
# efficiency, halo volume per part; measured where the machine has a core per rank, a model beyond).
# bench/mpi_probe (same build) measures the MPI costs the model uses (out/probe.txt).
#   bash bench/scaling_helmholtz.sh [--ranks "1 2 3 4 5 6 7 8"] [--repeat 3] [--out out/scaling]
#                                   [--cases "p1n10 p1n15 p1n20 p1n25 p1n30 p1n60 p3n20"]
# Ranks beyond the cores run oversubscribed (--oversubscribe): their times are not speed-ups, their
# halo volumes, iterations and L2 errors are exact. Each (case, ranks) with a core per rank runs
# `repeat` times and the fastest solve is kept (the machine is shared); oversubscribed ones run once.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ranks="1 2 3 4 5 6 7 8"
repeat=3
out="$root/out/scaling"
cases="p1n10 p1n15 p1n20 p1n25 p1n30 p1n60 p3n20"
while [ $# -gt 0 ]; do
  case "$1" in
    --ranks) ranks="$2"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --cases) cases="$2"; shift 2 ;;
    *) echo "scaling_helmholtz.sh: unknown option '$1' (allowed: --ranks, --repeat, --out, --cases)" >&2; exit 2 ;;
  esac
done
app="$root/build/mpi/bin/helmholtz"
[ -x "$app" ] || { echo "scaling_helmholtz.sh: $app missing; build it with: bash ci/mpi_test.sh" >&2; exit 2; }
export OMP_NUM_THREADS=1 OMP_PROC_BIND=false OMP_WAIT_POLICY=passive
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
# MPI costs on this machine (allreduce, neighbour exchange) for the speed-up model
probe="$root/build/mpi/bench/mpi_probe"
if [ -x "$probe" ]; then mpirun -np 2 --oversubscribe "$probe" 2000 >"$out/probe.txt"; fi
for c in $cases; do
  p="${c#p}"; p="${p%%n*}"; n="${c##*n}"
  scene="$out/$c.toml"
  sed -e "s/^elements = .*/elements = [$n, $n, $n]/" -e "s/^field = true/field = false/" \
    "$root/scenes/helmholtz/cube.toml" >"$scene"
  for r in $ranks; do
    best=""
    mkdir -p "$out/$c/ranks$r"
    times="$repeat"
    [ "$r" -le "$(nproc)" ] || times=1
    for k in $(seq 1 "$times"); do
      dir="$out/$c/ranks$r/run$k"
      mpirun -np "$r" --oversubscribe "$app" --scene "$scene" --accuracy paper --order "$p" --threads 1 \
        --out "$dir" --quiet >"$dir.log" 2>&1 || { cat "$dir.log" >&2; exit 1; }
      s=$(/usr/bin/python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['solve_seconds'])" "$dir/summary.json")
      if [ -z "$best" ] || /usr/bin/python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) < float(sys.argv[2]) else 1)" "$s" "$best"; then
        best="$s"; cp "$dir/summary.json" "$out/$c/ranks$r/summary.json"
      fi
    done
    echo "scaling: $c, $r ranks: best solve $best s" >&2
  done
done
/usr/bin/python3 "$root/tools/helmholtz_scaling.py" "$out" | tee "$out/scaling.md"
