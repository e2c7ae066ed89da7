#!/usr/bin/env bash
# polymech's matrix-free Helmholtz apply next to deal.II's on the same cube, one core, CPU time:
#   bash bench/peers/run_peers.sh [--build DIR] [--repetitions R] [--seconds S] [--orders "2 3 4"] [--out DIR]
# Runs, alternating and R times each: bench_stream (STREAM triad, the bandwidth reference),
# bench_fem BM_MatrixFreeApply<double>/p/n (y = K x, complex double, about 1e6 DoFs) and, when CMake
# finds deal.II (Debian: libdeal.ii-dev), the deal.II peer bench/peers/dealii (real double operator
# A - k^2 M, same cube, p and DoFs). Writes DIR/peers.md (the table of docs/PERFORMANCE.md: DoF/s per
# order for both, their ratio, polymech's traffic model over the STREAM figure of the same run) and
# the raw outputs. Without deal.II the polymech columns are still measured.
# --build: a configured polymech build folder (default build/ci; its bench_fem and bench_stream are built).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$root/build/ci"
reps=3
seconds=3
orders="2 3 4"
out="$root/out/peers"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --repetitions) reps="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --orders) orders="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "run_peers.sh: unknown option '$1' (allowed: --build DIR, --repetitions R, --seconds S, --orders \"2 3 4\", --out DIR)" >&2; exit 2 ;;
  esac
done
case "$reps" in ''|*[!0-9]*) echo "run_peers.sh: --repetitions must be a whole number, got '$reps'" >&2; exit 2 ;; esac
mkdir -p "$out"
export OMP_NUM_THREADS=1 OMP_PROC_BIND=false OMP_WAIT_POLICY=passive

[ -f "$build/build.ninja" ] || { echo "run_peers.sh: $build is not a configured build folder (run: bash ci/build.sh ci)" >&2; exit 2; }
cmake --build "$build" -j 2 --target bench_fem bench_stream >/dev/null

# The deal.II peer: built only when CMake finds deal.II.
dealii=""
peer_build="$root/build/peers-dealii"
if cmake -S "$root/bench/peers/dealii" -B "$peer_build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS="-march=native" >"$out/dealii_configure.log" 2>&1; then
  cmake --build "$peer_build" -j 2 >"$out/dealii_build.log" 2>&1 && dealii="$peer_build/dealii_helmholtz"
else
  echo "run_peers.sh: deal.II not found (see $out/dealii_configure.log); measuring polymech only" >&2
fi

# cube sizes of BM_MatrixFreeApply: (p n + 1)^3 ~ 1e6 DoFs
declare -A cells=([1]=100 [2]=50 [3]=33 [4]=25)
filter=""
for p in $orders; do filter="$filter${filter:+|}MatrixFreeApply<double>/$p/${cells[$p]}/"; done
rm -f "$out"/stream_*.json "$out"/polymech_*.json "$out"/dealii_*.txt
for r in $(seq 1 "$reps"); do
  echo "run_peers.sh: repetition $r of $reps" >&2
  "$build/bench/bench_stream" --benchmark_min_time="$seconds" --benchmark_out="$out/stream_$r.json" \
    --benchmark_out_format=json >/dev/null
  "$build/bench/bench_fem" --benchmark_filter="$filter" --benchmark_min_time="$seconds" \
    --benchmark_out="$out/polymech_$r.json" --benchmark_out_format=json >/dev/null
  if [ -n "$dealii" ]; then
    for p in $orders; do "$dealii" "$p" "${cells[$p]}" "$seconds" >>"$out/dealii_$r.txt"; done
  fi
done
/usr/bin/python3 "$root/bench/peers/peers_table.py" "$out" >"$out/peers.md"
cat "$out/peers.md"
