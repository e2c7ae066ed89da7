#!/usr/bin/env bash
# Install what a build needs: Debian packages, and Kokkos 3.4.01 with OpenMP built from the source of
# Debian's trilinos package into the cache prefix (skipped when $Kokkos_ROOT names an installed Kokkos).
# Idempotent: a second run finds everything in place and returns in about a second.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
log "Kokkos (OpenMP): $KOKKOS_OPENMP_ROOT"
