#!/usr/bin/env bash
# Test binaries for a GPU, built here and run on the lent GPU machine (which has no compiler set up for
# them): the CUDA gate's toolchain and Kokkos (ci/cuda_check.sh), the gate's flags (-O0: a correctness run,
# not a timing), and one Kokkos file recompiled with its architecture check relaxed.
#   bash ci/gpu_tests.sh [test targets...]     (default: the kernel tests below)
#   then, on the GPU machine, from the repository root with build/gpu/run carried:
#   bash build/gpu/run/run.sh                  (each test's log into $OUT, when set)
# Why the one file: Kokkos 3.4.01 knows no Hopper architecture; built for sm_80 it embeds compute_80 PTX,
# which the driver compiles for a newer GPU at load, but Kokkos::Cuda::initialize aborts unless the major
# compute capability matches ("running kernels compiled for compute capability 8.0 on device with compute
# capability 9.0 is not supported"). The copy refuses only a device older than the code, so an H100 or H200
# (9.0) runs the sm_80 build with a warning. A Kokkos >= 4 built with Kokkos_ARCH_HOPPER90 needs none of this.
source "$(dirname "${BASH_SOURCE[0]}")/lib.sh"
cd "$POLYMECH_ROOT"

targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(test_neighbors test_pd_kernels test_fem_operator test_solid_operator)

setup_cuda_toolchain
KOKKOS_CUDA_ROOT="$(cuda_kokkos_root)"
export Kokkos_ROOT="$KOKKOS_CUDA_ROOT"
src="$(kokkos_source_dir)/core/src/Cuda/Kokkos_Cuda_Instance.cpp"
[ -f "$src" ] || die "gpu tests: $src not found (the Kokkos source ci/lib.sh unpacks)"

work="build/gpu"
mkdir -p "$work"
patched="$work/cuda_instance_newer_devices.cpp"
/usr/bin/python3 - "$src" "$patched" <<'PY'
import sys
text = open(sys.argv[1]).read()
check = "if (compiled_major != cudaProp.major || compiled_minor > cudaProp.minor) {"
relaxed = "if (compiled_major > cudaProp.major || (compiled_major == cudaProp.major && compiled_minor > cudaProp.minor)) {"
open(sys.argv[2], "w").write(text.replace(check, relaxed))
PY
grep -q 'compiled_major > cudaProp.major ||' "$patched" || die "gpu tests: the architecture check of $src was not found (another Kokkos version?)"
object="$PWD/$work/cuda_instance_newer_devices.o"
log "gpu tests: compiling Kokkos' CUDA instance with the relaxed architecture check"
"$KOKKOS_CUDA_ROOT/bin/nvcc_wrapper" -std=c++17 -O2 -DNDEBUG -I"$KOKKOS_CUDA_ROOT/include" -I"$(dirname "$src")/.." \
  -arch=sm_80 --expt-extended-lambda --expt-relaxed-constexpr -c "$patched" -o "$object"

build_dir="${POLYMECH_GPU_BUILD_DIR:-build/gpu-tests}"
if [ ! -f "$build_dir/build.ninja" ]; then
  cmake --preset cuda-check -B "$build_dir" -DCMAKE_EXE_LINKER_FLAGS="$object" >"$work/configure.log" 2>&1 ||
    { cat "$work/configure.log" >&2; die "gpu tests: configuring $build_dir failed"; }
fi
log "gpu tests: building ${targets[*]}"
cmake --build "$build_dir" -j "$POLYMECH_JOBS" --target "${targets[@]}"

run="$work/run"
rm -rf "$run"
mkdir -p "$run"
for t in "${targets[@]}"; do
  exe="$(find "$build_dir/tests" -type f -name "$t" -perm -u+x | head -n 1)"
  [ -n "$exe" ] || die "gpu tests: $t was not built"
  strip -o "$run/$t" "$exe"
done
# the CUDA 11.8 runtime the binaries link (the GPU machine's toolkit may be another)
cudart="$(ldd "$run/${targets[0]}" | awk '/libcudart/ { print $3 }')"
[ -n "$cudart" ] && cp -L "$cudart" "$run/"
cat >"$run/run.sh" <<'RUN'
#!/usr/bin/env bash
# Runs every test binary of this folder on the GPU; logs into $OUT (or here); exit 1 if one failed.
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
out="${OUT:-$here}"
export LD_LIBRARY_PATH="$here${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" CUDA_CACHE_MAXSIZE=4294967296
nvidia-smi --query-gpu=name,driver_version,compute_cap --format=csv,noheader
status=0
for t in "$here"/test_*; do
  name="$(basename "$t")"
  start=$(date +%s)
  timeout 300 "$t" >"$out/$name.log" 2>&1
  rc=$?
  echo "$name: exit $rc, $(( $(date +%s) - start )) s, $(grep -E '^\[  PASSED  \]|FAILED TEST' "$out/$name.log" | tr '\n' ' ')"
  [ $rc -eq 0 ] || status=1
done
exit $status
RUN
chmod +x "$run/run.sh"
log "gpu tests: $(du -sh "$run" | cut -f1) in $run; on the GPU machine: bash $run/run.sh (carry $run)"
