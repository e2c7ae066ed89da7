#!/bin/bash
# Every shipped scene once at draft accuracy, one thread, for tools/cost_table.py (docs/PERFORMANCE.md, "Cost
# estimate against measured time"):
#
#     bash tools/run_drafts.sh BIN RESULTS [ACCURACY]      (BIN: build/<preset>/bin; ACCURACY: draft by default)
#     /usr/bin/python3 tools/cost_table.py BIN RESULTS [--accuracy ACCURACY] --markdown
#
# Results go to RESULTS/<app>/<scene stem>/new (the layout of tools/compare_binaries.py); a scene whose summary is
# already there is skipped, so an interrupted series resumes. Skipped: the scenes without presets (the Chung & Ooi
# tests, a Gmsh mesh) and wheel_gravel (hours at draft). RESULTS/log.txt lists each run's exit code and wall time.
set -u
if [ $# -lt 2 ] || [ ! -x "$1/polymech" ]; then
  echo "usage: bash tools/run_drafts.sh BIN RESULTS [ACCURACY]   (BIN must hold the polymech app)" >&2
  exit 2
fi
BIN=$(cd "$1" && pwd); RES=$2; ACC=${3:-draft}
mkdir -p "$RES" && RES=$(cd "$RES" && pwd)
cd "$(dirname "$0")/.."
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive OMP_PROC_BIND=false
for f in scenes/*/*.toml; do
  stem=$(basename "$f" .toml)
  case $stem in chung_ooi_*|duct_gmsh|wheel_gravel) continue ;; esac
  app=$("$BIN/polymech" --scene "$f" --accuracy "$ACC" --dry-run 2>&1 | sed -n 's/.*-> \([a-z_]*\).*/\1/p' | head -1)
  out=$RES/${app:-unknown}/$stem/new
  [ -f "$out/summary.json" ] && continue
  mkdir -p "$out"
  s=$(date +%s.%N)
  "$BIN/polymech" --scene "$f" --accuracy "$ACC" --out "$out" --quiet --threads 1 > "$out/stdout.log" 2>&1
  rc=$?
  e=$(date +%s.%N)
  echo "${app:-unknown} $stem rc=$rc wall=$(echo "$e - $s" | bc)" | tee -a "$RES/log.txt"
done
