#!/usr/bin/env bash
# Shared helpers for the set-up, test, demo and CUDA-check entry points.
# Sourced, not run. Everything here is idempotent: a second run skips finished work.

set -euo pipefail

POLYMECH_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
POLYMECH_CACHE="${POLYMECH_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/polymech}"
POLYMECH_JOBS="${POLYMECH_JOBS:-2}"
KOKKOS_VERSION_WANTED="3.4.01"

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

log() { printf '[polymech] %s\n' "$*" >&2; }
die() { printf '[polymech] error: %s\n' "$*" >&2; exit 1; }

# True when every named Debian package is installed.
packages_installed() {
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || return 1
  done
}

# --- a busy apt -------------------------------------------------------------------------------------
# Another apt or dpkg process (unattended-upgrades, a user's apt-get) may hold apt's locks when this runs:
# wait for them, up to POLYMECH_APT_WAIT seconds (default 900), saying who holds them, rather than fail.
# POLYMECH_APT_LOCKS replaces the list of lock files (tests/ci/test_apt_wait.sh uses its own).
APT_LOCKS="${POLYMECH_APT_LOCKS:-/var/lib/dpkg/lock-frontend /var/lib/dpkg/lock /var/lib/apt/lists/lock /var/cache/apt/archives/lock}"
POLYMECH_APT_WAIT="${POLYMECH_APT_WAIT:-900}"
POLYMECH_APT_POLL="${POLYMECH_APT_POLL:-5}"

# The PID of a process holding one of APT_LOCKS (a POSIX lock in /proc/locks on the file's inode), or nothing.
apt_lock_holder() {
  local f ino pid
  for f in $APT_LOCKS; do
    [ -e "$f" ] || continue
    ino="$(stat -c %i "$f")"
    pid="$(awk -v ino="$ino" '$2 != "->" { n = split($6, p, ":"); if (p[n] == ino) { print $5; exit } }' /proc/locks)"
    if [ -n "$pid" ]; then echo "$pid ($f)"; return 0; fi
  done
}

apt_wait_for_lock() {
  local waited=0 holder
  while holder="$(apt_lock_holder)"; [ -n "$holder" ]; do
    if [ "$waited" -eq 0 ]; then
      log "apt is busy: process $holder holds its lock ($(ps -o comm= -p "${holder%% *}" 2>/dev/null || echo 'gone')); waiting up to ${POLYMECH_APT_WAIT} s (POLYMECH_APT_WAIT)"
    fi
    if [ "$waited" -ge "$POLYMECH_APT_WAIT" ]; then
      die "apt is still busy after ${POLYMECH_APT_WAIT} s: process $holder holds its lock; let it finish and run this again, or set POLYMECH_APT_WAIT=<seconds> to wait longer"
    fi
    sleep "$POLYMECH_APT_POLL"
    waited=$((waited + POLYMECH_APT_POLL))
  done
  if [ "$waited" -gt 0 ]; then log "apt is free after ${waited} s"; fi
  return 0
}

# apt-get after waiting for its locks; apt itself also waits for the dpkg lock (DPkg::Lock::Timeout) in
# case another process takes it between the check and the call.
apt_get() {
  apt_wait_for_lock
  $SUDO apt-get -o DPkg::Lock::Timeout="$POLYMECH_APT_WAIT" "$@"
}

# apt-get with the machine's own sources (used for packages from 'main').
apt_install() {
  local missing=() p
  for p in "$@"; do packages_installed "$p" || missing+=("$p"); done
  [ ${#missing[@]} -eq 0 ] && return 0
  log "installing Debian packages: ${missing[*]}"
  apt_get update -qq
  DEBIAN_FRONTEND=noninteractive apt_get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# A private apt configuration derived from the machine's own sources: the same mirrors and suites,
# with deb and deb-src entries for main, contrib, non-free and non-free-firmware. The system's lists
# are never edited; the private list lives in the cache and apt is pointed at it with -o options.
PRIVATE_APT_DIR="$POLYMECH_CACHE/apt"
private_apt() {
  apt_get -o Dir::Etc::SourceList="$PRIVATE_APT_DIR/sources.list" \
    -o Dir::Etc::SourceParts=/dev/null -o Dir::State::Lists="$PRIVATE_APT_DIR/lists" "$@"
}

# Print "URI SUITE" for every 'deb' entry of the machine's apt sources (one-line and deb822 forms).
system_apt_entries() {
  local f
  if [ -f /etc/apt/sources.list ]; then
    sed -e 's/#.*//' /etc/apt/sources.list | awk '$1 == "deb" { i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ } print $i, $(i + 1) }'
  fi
  for f in /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    sed -e 's/#.*//' "$f" | awk '$1 == "deb" { i = 2; if ($2 ~ /^\[/) { while ($i !~ /\]$/) i++; i++ } print $i, $(i + 1) }'
  done
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    awk 'BEGIN { RS = ""; FS = "\n" }
      {
        types = ""; uris = ""; suites = "";
        for (k = 1; k <= NF; k++) {
          line = $k; sub(/#.*/, "", line);
          if (line ~ /^Types:/) { sub(/^Types:[ \t]*/, "", line); types = line }
          else if (line ~ /^URIs:/) { sub(/^URIs:[ \t]*/, "", line); uris = line }
          else if (line ~ /^Suites:/) { sub(/^Suites:[ \t]*/, "", line); suites = line }
        }
        if (types !~ /(^|[ \t])deb([ \t]|$)/) next;
        nu = split(uris, U, /[ \t]+/); ns = split(suites, S, /[ \t]+/);
        for (a = 1; a <= nu; a++) for (b = 1; b <= ns; b++) if (U[a] != "" && S[b] != "") print U[a], S[b];
      }' "$f"
  done
}

private_apt_setup() {
  local stamp="$PRIVATE_APT_DIR/updated.stamp"
  mkdir -p "$PRIVATE_APT_DIR/lists/partial"
  if [ ! -s "$PRIVATE_APT_DIR/sources.list" ]; then
    local entries
    entries="$(system_apt_entries | grep -E '(debian|ubuntu)' | sort -u || true)"
    [ -n "$entries" ] || die "no Debian 'deb' entries found in /etc/apt/sources.list{,.d/} to derive a deb-src entry from"
    echo "$entries" | while read -r uri suite; do
      echo "deb $uri $suite main contrib non-free non-free-firmware"
      echo "deb-src $uri $suite main contrib non-free non-free-firmware"
    done >"$PRIVATE_APT_DIR/sources.list.tmp"
    mv "$PRIVATE_APT_DIR/sources.list.tmp" "$PRIVATE_APT_DIR/sources.list"
  fi
  # Refresh the private index at most once a day.
  if [ ! -f "$stamp" ] || [ -n "$(find "$stamp" -mmin +1440 2>/dev/null)" ]; then
    log "updating the private apt index ($PRIVATE_APT_DIR/sources.list)"
    $SUDO mkdir -p "$PRIVATE_APT_DIR/lists/partial"
    private_apt update -qq
    touch "$stamp"
  fi
}

# Install packages that may come from contrib / non-free (e.g. nvidia-cuda-toolkit).
private_apt_install() {
  local missing=() p
  for p in "$@"; do packages_installed "$p" || missing+=("$p"); done
  [ ${#missing[@]} -eq 0 ] && return 0
  private_apt_setup
  log "installing Debian packages (private sources): ${missing[*]}"
  DEBIAN_FRONTEND=noninteractive apt_get -o Dir::Etc::SourceList="$PRIVATE_APT_DIR/sources.list" \
    -o Dir::Etc::SourceParts=/dev/null -o Dir::State::Lists="$PRIVATE_APT_DIR/lists" \
    install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

# The Kokkos source tree: packages/kokkos from Debian's trilinos source package, extracted once.
kokkos_source_dir() {
  local src="$POLYMECH_CACHE/src/kokkos-$KOKKOS_VERSION_WANTED"
  if [ ! -f "$src/CMakeLists.txt" ]; then
    private_apt_setup
    local dl="$POLYMECH_CACHE/src/download"
    mkdir -p "$dl"
    if ! ls "$dl"/trilinos_*.orig.tar.* >/dev/null 2>&1; then
      log "downloading Debian's trilinos source package (for packages/kokkos)"
      (cd "$dl" && private_apt source --download-only -qq trilinos >/dev/null 2>&1) ||
        die "apt-get source --download-only trilinos failed (private list: $PRIVATE_APT_DIR/sources.list)"
    fi
    local tarball
    tarball="$(ls "$dl"/trilinos_*.orig.tar.* | head -n 1)"
    log "extracting packages/kokkos from $(basename "$tarball")"
    rm -rf "$src.tmp" && mkdir -p "$src.tmp"
    tar -xf "$tarball" -C "$src.tmp" --strip-components=3 --wildcards '*/packages/kokkos/*'
    grep -q "Kokkos_VERSION_MINOR 4" "$src.tmp/CMakeLists.txt" ||
      die "the trilinos source package does not carry Kokkos $KOKKOS_VERSION_WANTED"
    rm -rf "$src" && mv "$src.tmp" "$src"
  fi
  echo "$src"
}

# build_kokkos <name> <cmake args...>: build and install Kokkos into $POLYMECH_CACHE/<name> once.
build_kokkos() {
  local name="$1"; shift
  local prefix="$POLYMECH_CACHE/$name"
  if [ -f "$prefix/.polymech-complete" ]; then echo "$prefix"; return 0; fi
  local src build
  src="$(kokkos_source_dir)"
  build="$POLYMECH_CACHE/build/$name"
  rm -rf "$build" "$prefix" && mkdir -p "$build"
  log "building Kokkos $KOKKOS_VERSION_WANTED ($name) into $prefix"
  (cd "$build" && cmake "$src" -G Ninja -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_CXX_STANDARD=17 -DKokkos_ENABLE_SERIAL=ON -DKokkos_ENABLE_TESTS=OFF "$@" >"$build/configure.log" 2>&1 &&
    cmake --build . -j "$POLYMECH_JOBS" >"$build/build.log" 2>&1 && cmake --install . >"$build/install.log" 2>&1) ||
    die "Kokkos build failed; see $build/configure.log and $build/build.log"
  touch "$prefix/.polymech-complete"
  rm -rf "$build"
  echo "$prefix"
}

# The host packages every build needs.
HOST_PACKAGES=(build-essential cmake ninja-build pkg-config libeigen3-dev libhdf5-dev libbenchmark-dev
  libgtest-dev libgmock-dev libtomlplusplus-dev libcli11-dev libfmt-dev nlohmann-json3-dev libfftw3-dev
  python3 python3-matplotlib python3-h5py python3-numpy xz-utils ccache)

# The OpenMP Kokkos to build against: $Kokkos_ROOT if the user points at one, else the cached build.
openmp_kokkos_root() {
  if [ -n "${Kokkos_ROOT:-}" ]; then echo "$Kokkos_ROOT"; return 0; fi
  build_kokkos "kokkos-$KOKKOS_VERSION_WANTED-openmp" -DKokkos_ENABLE_OPENMP=ON \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON
}

# build_and_test PRESET WHAT [CTEST_JOBS]: configure PRESET once, build it (ccache), then run its ctest
# preset; WHAT names it in the log. Needs setup_host first.
build_and_test() {
  local preset="$1" what="$2" jobs="${3:-$POLYMECH_JOBS}" t0=$SECONDS
  cd "$POLYMECH_ROOT"
  export Kokkos_ROOT="$KOKKOS_OPENMP_ROOT"
  if [ ! -f "build/$preset/build.ninja" ]; then
    cmake --preset "$preset" >/dev/null
  fi
  cmake --build --preset "$preset" -j "$POLYMECH_JOBS"
  log "$what build [$((SECONDS - t0)) s]; running its tests"
  ctest --preset "$preset" -j "$jobs"
  log "$what tests passed [$((SECONDS - t0)) s]"
}

setup_host() {
  apt_install "${HOST_PACKAGES[@]}"
  KOKKOS_OPENMP_ROOT="$(openmp_kokkos_root)"
  export KOKKOS_OPENMP_ROOT
  # compiler output cached across runs (CMakeLists.txt uses ccache when it finds it)
  export CCACHE_DIR="${CCACHE_DIR:-$POLYMECH_CACHE/ccache}"
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$POLYMECH_ROOT}"  # hits across clones in other folders
  # The sanitizer build has debug info (-g1), and with -g ccache hashes the working directory too, so every
  # clone missed: the stage took 19 of its 21 minutes compiling (2026-11-26). Without it the cached objects'
  # debug info names the folder of the clone that compiled them first (the sanitizers' stack traces still name
  # the right files, relative to base_dir).
  export CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
}

# --- CUDA compile gate (ci/cuda_check.sh) ----------------------------------------------------------
# Debian's CUDA 11.8 toolkit (non-free) and g++-11, the newest GCC that CUDA 11.8 accepts as host compiler.
CUDA_PACKAGES=(nvidia-cuda-toolkit g++-11)
# Where Debian puts the real nvcc (/usr/bin/nvcc is a shell wrapper around it); headers and libraries
# live in /usr/include and /usr/lib/x86_64-linux-gnu. POLYMECH_CUDA_ROOT overrides it (a toolkit whose
# bin/nvcc Kokkos 3.4 accepts, i.e. CUDA 11.x).
POLYMECH_CUDA_ROOT="${POLYMECH_CUDA_ROOT:-/usr/lib/nvidia-cuda-toolkit}"
POLYMECH_CUDA_HOST_CXX="${POLYMECH_CUDA_HOST_CXX:-g++-11}"

# Install the CUDA toolchain when missing and point every later nvcc / nvcc_wrapper / CMake lookup at it:
# a newer toolkit (e.g. CUDA 12/13 in /usr/local/cuda) may sit earlier on PATH.
setup_cuda_toolchain() {
  if [ "$POLYMECH_CUDA_ROOT" = /usr/lib/nvidia-cuda-toolkit ]; then
    private_apt_install "${CUDA_PACKAGES[@]}"
  fi
  [ -x "$POLYMECH_CUDA_ROOT/bin/nvcc" ] || die "no nvcc at $POLYMECH_CUDA_ROOT/bin/nvcc (set POLYMECH_CUDA_ROOT)"
  command -v "$POLYMECH_CUDA_HOST_CXX" >/dev/null || die "host compiler '$POLYMECH_CUDA_HOST_CXX' not found"
  local path_head="$POLYMECH_CUDA_ROOT/bin"
  if [ "$POLYMECH_CUDA_ROOT" = /usr/lib/nvidia-cuda-toolkit ]; then
    # Debian's nvcc finds ptxas, fatbinary, nvlink, cudafe++ ... on PATH (they live in /usr/bin), so a
    # newer toolkit's bin earlier on PATH would hand CUDA 13 tools to CUDA 11.8 nvcc. A cache folder of
    # links to exactly the package's tools goes first instead; nothing else on PATH is shadowed.
    local tools="$POLYMECH_CACHE/cuda-debian-bin" t
    if [ ! -f "$tools/.complete" ]; then
      rm -rf "$tools" && mkdir -p "$tools"
      for t in $(dpkg -L nvidia-cuda-toolkit | grep -E '^/usr/bin/[^/]+$'); do ln -s "$t" "$tools/"; done
      touch "$tools/.complete"
    fi
    path_head="$POLYMECH_CUDA_ROOT/bin:$tools"
  fi
  export PATH="$path_head:$PATH"
  export CUDA_ROOT="$POLYMECH_CUDA_ROOT"             # nvcc_wrapper runs $CUDA_ROOT/bin/nvcc
  # CMake's FindCUDAToolkit (Kokkos' CUDA TPL) looks for include/cuda_runtime.h next to bin/nvcc: for
  # Debian's split layout that is /usr (/usr/bin/nvcc, /usr/include, /usr/lib/x86_64-linux-gnu).
  if [ "$POLYMECH_CUDA_ROOT" = /usr/lib/nvidia-cuda-toolkit ]; then
    export CUDAToolkit_ROOT=/usr
  else
    export CUDAToolkit_ROOT="$POLYMECH_CUDA_ROOT"
  fi
  export NVCC_WRAPPER_DEFAULT_COMPILER="$POLYMECH_CUDA_HOST_CXX"
  unset CUDA_HOME CUDA_PATH CUDACXX || true
}

# The CUDA Kokkos (Serial + CUDA, sm_80) the gate builds against; needs setup_cuda_toolchain first.
cuda_kokkos_root() {
  local src
  src="$(kokkos_source_dir)"
  build_kokkos "kokkos-$KOKKOS_VERSION_WANTED-cuda" -DCMAKE_CXX_COMPILER="$src/bin/nvcc_wrapper" \
    -DKokkos_ENABLE_CUDA=ON -DKokkos_ENABLE_CUDA_LAMBDA=ON -DKokkos_ARCH_AMPERE80=ON \
    -DCUDAToolkit_ROOT="$CUDAToolkit_ROOT"
}
