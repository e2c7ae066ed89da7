#!/usr/bin/env bash
# The MPI domain decomposition of the Helmholtz model: Debian's OpenMPI and METIS, preset `mpi` (only
# the helmholtz app and its MPI test are built, through ccache), then the test with 2 and 3 ranks
# (mpirun --oversubscribe: any number of cores).
#   bash ci/mpi_test.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
apt_install openmpi-bin libopenmpi-dev libmetis-dev ccache
build_and_test mpi "MPI (helmholtz, test_helmholtz_mpi: 2 and 3 ranks)" 1
