#!/usr/bin/env bash
# The CUDA compile gate: build every kernel, model, app, test and benchmark with nvcc_wrapper against a
# CUDA-enabled Kokkos, warnings as errors for project code, at -O0 (host and ptxas: the gate checks that
# everything compiles and links, it never runs; -O3 took half as long again), through ccache (depend mode). io/ (free of Kokkos; toml++ does not
# compile under nvcc) is compiled by the host compiler through nvcc_wrapper --host-only, and the apps
# link it. Nothing runs on a GPU; the binaries are only compiled and linked.
#   bash ci/cuda_check.sh
# Steps (each skipped when already done, so a second run only re-checks the build):
#   1. Debian's CUDA 11.8 toolkit (non-free) and g++-11 via the private apt sources (ci/lib.sh);
#   2. Kokkos 3.4.01 with Serial + CUDA (sm_80, CUDA lambdas) into $POLYMECH_CACHE/kokkos-3.4.01-cuda;
#   3. cmake --preset cuda-check and cmake --build --preset cuda-check.
# POLYMECH_CUDA_ROOT / POLYMECH_CUDA_HOST_CXX select another CUDA 11.x toolkit and host compiler.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$POLYMECH_ROOT"

# The host packages (Eigen, GoogleTest, Google Benchmark, CMake, Ninja ...) are shared with the host build.
apt_install "${HOST_PACKAGES[@]}"

# nvcc_wrapper's calls are cached by ccache in its depend mode (CMakeLists.txt); the cache is the host
# builds' one, paths relative to the clone (hits across clones in other folders).
export CCACHE_DIR="${CCACHE_DIR:-$POLYMECH_CACHE/ccache}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$POLYMECH_ROOT}"

t0=$SECONDS
log "CUDA gate: toolchain ($POLYMECH_CUDA_ROOT, host compiler $POLYMECH_CUDA_HOST_CXX)"
setup_cuda_toolchain
log "CUDA gate: $("$POLYMECH_CUDA_ROOT/bin/nvcc" --version | tail -n 1) [$((SECONDS - t0)) s]"

t1=$SECONDS
KOKKOS_CUDA_ROOT="$(cuda_kokkos_root)"
log "CUDA gate: Kokkos (CUDA): $KOKKOS_CUDA_ROOT [$((SECONDS - t1)) s]"

t2=$SECONDS
export Kokkos_ROOT="$KOKKOS_CUDA_ROOT"
build_dir="build/cuda-check"
# Reconfigure when the build folder belongs to another Kokkos or compiler (e.g. a moved cache) or to
# another build type (the gate compiles at -O0 since issue 31's CI time: a third less nvcc time).
if [ -f "$build_dir/CMakeCache.txt" ] &&
  { ! grep -qx "CMAKE_CXX_COMPILER:[A-Z]*=$KOKKOS_CUDA_ROOT/bin/nvcc_wrapper" "$build_dir/CMakeCache.txt" ||
    ! grep -qx "CMAKE_BUILD_TYPE:[A-Z]*=CudaGate" "$build_dir/CMakeCache.txt"; }; then
  log "CUDA gate: $build_dir was configured with another compiler or build type; starting it afresh"
  rm -rf "$build_dir"
fi
if [ ! -f "$build_dir/build.ninja" ]; then
  log "CUDA gate: configuring preset cuda-check"
  mkdir -p "$build_dir"
  if ! cmake --preset cuda-check >"$build_dir/configure.log" 2>&1; then
    cat "$build_dir/configure.log" >&2
    rm -f "$build_dir/build.ninja"
    die "CUDA gate: cmake --preset cuda-check failed (log above)"
  fi
fi
log "CUDA gate: building preset cuda-check (kernels, models, apps, tests, benchmarks) with nvcc_wrapper"
cmake --build --preset cuda-check -j "$POLYMECH_JOBS"

# Every test binary ctest knows, every benchmark and every app must exist, linked (nothing runs: no GPU
# assumed).
missing="$(cd "$build_dir" && ctest --show-only=json-v1 | python3 -c '
import json, os, sys
cmds = [t["command"][0] for t in json.load(sys.stdin).get("tests", []) if t.get("command")]
bench = [os.path.join("bench", f) for f in os.listdir("bench") if f.startswith("bench_")] if os.path.isdir("bench") else []
apps = [os.path.join("bin", f) for f in os.listdir("bin")] if os.path.isdir("bin") else []
if not cmds or not bench or not apps:
    print("(no tests, benchmarks or apps were configured)")
for c in sorted(set(c for c in cmds if os.path.isabs(c) or "/" in c)) + sorted(bench) + sorted(apps):
    if not (os.path.isfile(c) and os.access(c, os.X_OK)):
        print(c)
')"
[ -z "$missing" ] || die "CUDA gate: not built: $missing"
log "CUDA gate passed: every kernel, model, app, test and benchmark builds for CUDA [$((SECONDS - t2)) s]"
