// Subnormal numbers on the host: flushed to zero in every compute thread (the default), or kept.
//
// Why: a wave entering a quiet region (the MPS plate ahead of its front, a PD target before the impact)
// leaves displacements and velocities that decay smoothly through the subnormal range (below 2.2e-308
// in double, 1.2e-38 in float). On Intel cores every operation on such a number takes a microcode
// path of ~100 cycles; the MPS force kernel ran 3.6x slower on an AVX-512 Xeon (issue 39). Flushing
// them changes no physical result: a subnormal displacement or velocity is 1e-300 of the smallest
// value any model resolves (round-off of quantities of order 1e-8 and larger); docs/METHODS.md,
// "Subnormal numbers".
//
// How: x86-64 has two bits in MXCSR, FTZ (results that would be subnormal become 0) and DAZ (subnormal
// inputs read as 0); AArch64 has FZ in FPCR. They are per-thread state: set on the thread that starts
// Kokkos (host code between kernels) and in every thread of the OpenMP pool; threads created later
// inherit the creating thread's floating-point environment (POSIX pthread_create).
//
// CUDA: device code does not read these bits. nvcc flushes float subnormals only under -ftz=true (or
// --use_fast_math), which polymech does not use; double is never flushed on the device, and NVIDIA's
// FMA units handle subnormal operands at full speed, so no device flag is wanted.
//
// Choose with POLYMECH_SUBNORMALS=flush|keep in the environment (tests, benchmarks) or the apps'
// --subnormals flush|keep; kx::initialize (kokkos_shim.hpp) applies it once.
#pragma once

#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>

#if (defined(__x86_64__) || defined(_M_X64) || defined(__SSE2__)) && !defined(__CUDA_ARCH__)
#include <xmmintrin.h>
#define POLYMECH_FLOAT_ENV_X86 1
#elif defined(__aarch64__) && !defined(__CUDA_ARCH__)
#define POLYMECH_FLOAT_ENV_ARM64 1
#endif

#include <Kokkos_Core.hpp>

namespace polymech::kx {

enum class Subnormals { flush, keep };

inline const char* to_string(Subnormals s) { return s == Subnormals::flush ? "flush" : "keep"; }

// "flush" or "keep"; anything else is refused with the allowed values (what: where the value came from).
inline Subnormals parse_subnormals(const std::string& value, const std::string& what) {
  if (value == "flush") return Subnormals::flush;
  if (value == "keep") return Subnormals::keep;
  throw std::invalid_argument(what + " = '" + value + "': allowed values are 'flush' (the default) and 'keep'");
}

// POLYMECH_SUBNORMALS from the environment; flush when it is unset or empty.
inline Subnormals subnormals_from_environment() {
  const char* v = std::getenv("POLYMECH_SUBNORMALS");
  if (v == nullptr || *v == '\0') return Subnormals::flush;
  return parse_subnormals(v, "POLYMECH_SUBNORMALS");
}

// Whether this CPU's floating-point environment can flush at all (false: the setting is ignored).
inline bool subnormal_control_available() {
#if defined(POLYMECH_FLOAT_ENV_X86) || defined(POLYMECH_FLOAT_ENV_ARM64)
  return true;
#else
  return false;
#endif
}

namespace detail {
#if defined(POLYMECH_FLOAT_ENV_X86)
constexpr unsigned mxcsr_ftz = 0x8000u;  // flush to zero
constexpr unsigned mxcsr_daz = 0x0040u;  // denormals are zero
#elif defined(POLYMECH_FLOAT_ENV_ARM64)
constexpr std::uint64_t fpcr_fz = std::uint64_t(1) << 24;
inline std::uint64_t read_fpcr() {
  std::uint64_t r;
  __asm__ __volatile__("mrs %0, fpcr" : "=r"(r));
  return r;
}
inline void write_fpcr(std::uint64_t r) { __asm__ __volatile__("msr fpcr, %0" : : "r"(r)); }
#endif
}  // namespace detail

// Sets the mode of the calling thread only.
inline void set_thread_subnormals(Subnormals s) {
#if defined(POLYMECH_FLOAT_ENV_X86)
  const unsigned bits = detail::mxcsr_ftz | detail::mxcsr_daz;
  const unsigned csr = _mm_getcsr();
  _mm_setcsr(s == Subnormals::flush ? (csr | bits) : (csr & ~bits));
#elif defined(POLYMECH_FLOAT_ENV_ARM64)
  const std::uint64_t r = detail::read_fpcr();
  detail::write_fpcr(s == Subnormals::flush ? (r | detail::fpcr_fz) : (r & ~detail::fpcr_fz));
#else
  (void)s;
#endif
}

// The mode of the calling thread (keep where the CPU has no control).
inline Subnormals thread_subnormals() {
#if defined(POLYMECH_FLOAT_ENV_X86)
  const unsigned bits = detail::mxcsr_ftz | detail::mxcsr_daz;
  return (_mm_getcsr() & bits) == bits ? Subnormals::flush : Subnormals::keep;
#elif defined(POLYMECH_FLOAT_ENV_ARM64)
  return (detail::read_fpcr() & detail::fpcr_fz) ? Subnormals::flush : Subnormals::keep;
#else
  return Subnormals::keep;
#endif
}

// Sets the mode on the calling thread and on every thread of the host backend's pool (OpenMP); call
// after Kokkos::initialize. Threads the pool creates later inherit it from the calling thread.
inline void set_host_subnormals(Subnormals s) {
  set_thread_subnormals(s);
#if defined(KOKKOS_ENABLE_OPENMP)
  const int n = static_cast<int>(Kokkos::OpenMP().concurrency());
#pragma omp parallel num_threads(n)
  { set_thread_subnormals(s); }
#endif
}

}  // namespace polymech::kx
