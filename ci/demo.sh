#!/usr/bin/env bash
# The README's demo command: install what is missing, build, run the MPS point-source scene
# (seed 000 §5.1) at draft accuracy, plot, and print where the results are.
#   bash ci/demo.sh [--accuracy draft|standard|paper] [--out DIR] [--force]
# A second run with the same binary, scene and options reuses the results (--force reruns).
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
accuracy=draft
out=out/mps_point_source
force=0
while [ $# -gt 0 ]; do
  case "$1" in
    --accuracy) [ $# -ge 2 ] || die "--accuracy needs a value (draft, standard, paper)"; accuracy="$2"; shift 2 ;;
    --out) [ $# -ge 2 ] || die "--out needs a folder"; out="$2"; shift 2 ;;
    --force) force=1; shift ;;
    *) die "unknown option '$1' (allowed: --accuracy draft|standard|paper, --out DIR, --force)" ;;
  esac
done
case "$accuracy" in draft|standard|paper) ;; *) die "unknown accuracy '$accuracy' (allowed: draft, standard, paper)" ;; esac

cd "$POLYMECH_ROOT"
bash ci/build.sh release mps_point_source
app=build/release/bin/mps_point_source
scene=scenes/mps/point_source.toml
stamp="$out/.demo-stamp"
key="$(cat "$app" "$scene" | sha256sum | cut -c1-16) $accuracy"
if [ "$force" -eq 0 ] && [ -f "$out/summary.json" ] && [ "$(cat "$stamp" 2>/dev/null)" = "$key" ]; then
  log "results for this build, scene and accuracy are already in $out (use --force to rerun)"
else
  rm -f "$stamp"
  export OMP_PROC_BIND="${OMP_PROC_BIND:-spread}" OMP_PLACES="${OMP_PLACES:-threads}"
  "$app" --scene "$scene" --accuracy "$accuracy" --out "$out"
  echo "$key" >"$stamp"
fi
/usr/bin/python3 tools/plot_mps_point_source.py "$out"
log "demo results in $out/:"
log "  summary.json (measured vs analytic wave speeds, energy drift, wall time), probes.csv, energy.csv"
log "  fields.xdmf + fields.h5 (open fields.xdmf in ParaView), snapshots.png, probe_A.png, arrivals.png"
log "the other apps and the benchmarks (README, 'Apps and scenes'): bash ci/build.sh release"
