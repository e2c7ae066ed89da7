#!/usr/bin/env bash
# Sanitizers on every change (issue 16): the unit tests built with AddressSanitizer,
# UndefinedBehaviorSanitizer and Kokkos bounds checks on every View access (preset sanitize, -O1,
# through ccache), then run (ctest preset sanitize: label unit, without the long MPS stability runs
# and the determinism pair, which run the same kernels for longer). Any report fails the run.
#   bash ci/sanitize.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
cd "$POLYMECH_ROOT"
export Kokkos_ROOT="$KOKKOS_OPENMP_ROOT"
export CCACHE_DIR="${CCACHE_DIR:-$POLYMECH_CACHE/ccache}"
t0=$SECONDS
if [ ! -f build/sanitize/build.ninja ]; then
  cmake --preset sanitize >/dev/null
fi
cmake --build --preset sanitize -j "$POLYMECH_JOBS"
log "sanitizer build (unit tests) [$((SECONDS - t0)) s]; running them"
ctest --preset sanitize -j "$POLYMECH_JOBS"
log "sanitizers: no report [$((SECONDS - t0)) s]"
