#!/usr/bin/env bash
# The tests once more, built for any x86-64-v2 CPU (issue 31): no -march=native, so 128-bit vectors and
# no fused multiply-add, where the ci build uses this machine's vector units and FMA. A user's CPU (AVX2
# or AVX-512, Intel or AMD) rounds differently from the developer's; a test whose tolerance holds only
# for one CPU's round-off fails here, on the developer's machine, not on the user's. Runs every test with
# one thread (the ci run checks that thread counts agree) but the restart, fuzzing, ci, plot-tool and
# command-line ones and those that run the polymech app (they compare a build with itself, or test scripts
# and messages). Only the test binaries and the two apps whose physics tests run are built (target
# polymech_test_binaries: no other app, no benchmark); compiler output is cached (ccache).
#   bash ci/portable_test.sh
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
setup_host
build_and_test portable "portable (-march=x86-64-v2)"
