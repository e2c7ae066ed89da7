#!/usr/bin/env bash
# The MPI domain decomposition of the Helmholtz model: Debian's OpenMPI and METIS, preset `mpi` (only
# the helmholtz app and its MPI test are built, through ccache), then the test with 2 and 3 ranks
# (mpirun --oversubscribe: any number of cores).
#   bash ci/mpi_test.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
apt_install openmpi-bin libopenmpi-dev libmetis-dev ccache
cd "$POLYMECH_ROOT"
export Kokkos_ROOT="$KOKKOS_OPENMP_ROOT"
export CCACHE_DIR="${CCACHE_DIR:-$POLYMECH_CACHE/ccache}"
t0=$SECONDS
if [ ! -f build/mpi/build.ninja ]; then
  cmake --preset mpi >/dev/null
fi
cmake --build --preset mpi -j "$POLYMECH_JOBS"
log "MPI build (helmholtz, test_helmholtz_mpi) [$((SECONDS - t0)) s]; running the 2- and 3-rank tests"
ctest --preset mpi
