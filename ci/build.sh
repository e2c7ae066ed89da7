#!/usr/bin/env bash
# Configure and build one CMake preset (default: release) after making sure dependencies exist.
#   bash ci/build.sh [preset] [targets...]
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
preset="${1:-release}"; shift || true
setup_host
cd "$POLYMECH_ROOT"
export Kokkos_ROOT="$KOKKOS_OPENMP_ROOT"
if [ ! -f "build/$preset/build.ninja" ]; then
  cmake --preset "$preset"
fi
if [ $# -gt 0 ]; then
  cmake --build --preset "$preset" -j "$POLYMECH_JOBS" --target "$@"
else
  cmake --build --preset "$preset" -j "$POLYMECH_JOBS"
fi
