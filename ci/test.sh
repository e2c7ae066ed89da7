#!/usr/bin/env bash
# The README's test command: install what is missing, build with warnings as errors, run the test
# suite, the same tests built for any x86-64-v2 CPU (ci/portable_test.sh), the MPI tests
# (ci/mpi_test.sh), the unit tests under AddressSanitizer, UBSan and Kokkos bounds checks
# (ci/sanitize.sh), then the CUDA compile gate (every kernel, model, kernel test and benchmark built
# for CUDA).
#   bash ci/test.sh            # everything, as CI runs it
#   bash ci/test.sh --quick    # skip the CUDA compile gate
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
quick=0
for a in "$@"; do
  case "$a" in
    --quick) quick=1 ;;
    *) die "unknown option '$a' (allowed: --quick)" ;;
  esac
done
cd "$POLYMECH_ROOT"
bash ci/build.sh ci
log "running the test suite (ctest, preset ci)"
ctest --preset ci -j "$POLYMECH_JOBS"
bash ci/portable_test.sh  # the tests again, built for x86-64-v2 (no FMA): tolerances that hold on any CPU
bash ci/mpi_test.sh  # the Helmholtz domain decomposition with 2 and 3 MPI ranks
bash ci/sanitize.sh  # ASan + UBSan + Kokkos bounds checks on the unit tests
if [ "$quick" -eq 0 ] && [ -f ci/cuda_check.sh ]; then
  bash ci/cuda_check.sh
fi
log "all tests passed"
