#!/usr/bin/env bash
# Sanitizers on every change (issue 16): the unit tests built with AddressSanitizer,
# UndefinedBehaviorSanitizer and Kokkos bounds checks on every View access (preset sanitize, -O1,
# through ccache), then run (ctest preset sanitize: label unit, without the long MPS stability runs
# and the thread-agreement pair, which run the same kernels for longer), and the scene fuzzer on every
# 50th variant (every 5th takes 4.5 min under ASan; ctest of the normal build runs every 5th). Any
# report fails the run.
#   bash ci/sanitize.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
t0=$SECONDS
build_and_test sanitize "sanitizer (unit tests)"
log "scene fuzzer under the sanitizers (every 50th variant)"
OMP_NUM_THREADS=1 OMP_PROC_BIND=false build/sanitize/tests/fuzz/fuzz_scenes --source "$POLYMECH_ROOT" --stride 50 | grep -E "^BAD|^fuzz_scenes:"
log "sanitizers: no report [$((SECONDS - t0)) s]"
