#!/usr/bin/env bash
# polymech's DEM pour next to LIGGGHTS (Debian package `liggghts`) on the same spheres, one core:
#   bash bench/peers/liggghts/run_pour.sh [--build DIR] [--steps N] [--repetitions R] [--accuracy A] [--out DIR]
# dem_pour (scenes/dem/sphere_pour.toml) writes the initial spheres as a data file; LIGGGHTS runs the
# same spheres, material, Hertz law with tangential history, walls, dt and number of steps. Runs
# alternate, R times each; CPU time (user + sys) of each whole process, and the loop times each prints.
# Writes DIR/pour_peers.md: sphere-steps per CPU second for both and their ratio. Optional, outside ctest.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
build="$root/build/ci"
steps=20000
reps=2
accuracy=paper
out="$root/out/peers_dem"
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build="$2"; shift 2 ;;
    --steps) steps="$2"; shift 2 ;;
    --repetitions) reps="$2"; shift 2 ;;
    --accuracy) accuracy="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    *) echo "run_pour.sh: unknown option '$1' (allowed: --build DIR, --steps N, --repetitions R, --accuracy A, --out DIR)" >&2; exit 2 ;;
  esac
done
case "$steps$reps" in *[!0-9]*) echo "run_pour.sh: --steps and --repetitions must be whole numbers" >&2; exit 2 ;; esac
command -v liggghts >/dev/null || { echo "run_pour.sh: liggghts not found (apt-get install liggghts)" >&2; exit 2; }
[ -x "$build/bin/dem_pour" ] || cmake --build "$build" -j 2 --target dem_pour >/dev/null
mkdir -p "$out"
export OMP_NUM_THREADS=1 OMP_PROC_BIND=false OMP_WAIT_POLICY=passive
# the shipped scene without snapshots (LIGGGHTS writes no dumps either)
scene="$out/sphere_pour.toml"
sed -e 's|^snapshots = .*|snapshots = 0|' "$root/scenes/dem/sphere_pour.toml" >"$scene"

# the data file and the run's parameters, from a dry pass of one step
"$build/bin/dem_pour" --scene "$scene" --accuracy "$accuracy" --steps 1 --quiet --threads 1 --out "$out/setup" \
  --lammps-data "$out/pour.data" >/dev/null 2>&1
read -r dt skin <<<"$(/usr/bin/python3 -c "
import json; s = json.load(open('$out/setup/summary.json'))
print(s['dt'], 0.2 * 0.005)")"
sed -e "s|@DATA@|$out/pour.data|" -e "s|@SKIN@|$skin|" -e "s|@E@|5e7|" -e "s|@NU@|0.3|" -e "s|@E_REST@|0.4|" \
    -e "s|@MU@|0.5|" -e "s|@DT@|$dt|" -e "s|@LX@|0.12|" -e "s|@LY@|0.12|" -e "s|@THERMO@|$steps|" -e "s|@STEPS@|$steps|" \
    "$root/bench/peers/liggghts/in.pour.template" >"$out/in.pour"

cpu() { /usr/bin/time -f "%U %S" -o "$1" "${@:2}"; }
rm -f "$out"/polymech_*.time "$out"/liggghts_*.time
for r in $(seq 1 "$reps"); do
  echo "run_pour.sh: repetition $r of $reps" >&2
  cpu "$out/polymech_$r.time" "$build/bin/dem_pour" --scene "$scene" --accuracy "$accuracy" --steps "$steps" --quiet \
    --threads 1 --out "$out/polymech_$r" >/dev/null 2>&1
  (cd "$out" && cpu "$out/liggghts_$r.time" liggghts -in "$out/in.pour" -echo none -log "$out/liggghts_$r.log" >/dev/null 2>&1)
done
/usr/bin/python3 - "$out" "$reps" "$steps" <<'PY'
import json, re, sys
out, reps, steps = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
def cpu(f):
    u, s = open(f).read().split()[-2:]
    return float(u) + float(s)
rows = []
for r in range(1, reps + 1):
    s = json.load(open(f"{out}/polymech_{r}/summary.json"))
    log = open(f"{out}/liggghts_{r}.log").read()
    m = re.search(r"Loop time of ([0-9.eE+-]+) on 1 procs for (\d+) steps with (\d+) atoms", log)
    rows.append((s["spheres"], cpu(f"{out}/polymech_{r}.time"), s["wall_seconds"], cpu(f"{out}/liggghts_{r}.time"),
                 float(m.group(1)), int(m.group(3))))
n = rows[0][0]
print(f"| run | spheres | steps | polymech CPU s | polymech loop s | LIGGGHTS CPU s | LIGGGHTS loop s | LIGGGHTS atoms at end |")
print("|---|---|---|---|---|---|---|---|")
for k, (n_, pc, pl, lc, ll, la) in enumerate(rows, 1):
    print(f"| {k} | {n_} | {steps} | {pc:.2f} | {pl:.2f} | {lc:.2f} | {ll:.2f} | {la} |")
best_p = min(r[2] for r in rows); best_l = min(r[4] for r in rows)
print()
print(f"loop, best of {reps}: polymech {n * steps / best_p:.3g} sphere-steps/s, LIGGGHTS {n * steps / best_l:.3g} "
      f"sphere-steps/s: ratio polymech / LIGGGHTS = {best_l / best_p:.2f}")
best_pc = min(r[1] for r in rows); best_lc = min(r[3] for r in rows)
print(f"whole process CPU time, best of {reps}: polymech {best_pc:.2f} s, LIGGGHTS {best_lc:.2f} s: ratio {best_lc / best_pc:.2f}")
PY
