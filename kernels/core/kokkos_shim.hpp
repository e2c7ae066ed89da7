// Kokkos 3.4 .. 5.x API differences, kept in one place.
//
// What moved between versions and is used here:
//  - math functions: Kokkos::Experimental::sqrt (3.x) -> Kokkos::sqrt (4.0+, Experimental removed later);
//  - Kokkos::InitArguments (3.x, removed in 4.x) -> Kokkos::InitializationSettings (3.7+);
//  - Kokkos::Tools callbacks: same names in 3.4 and 4.x (Kokkos::Tools::Experimental::set_*_callback).
// Everything else the project uses (View, RangePolicy, parallel_for/reduce/scan, atomics, reducers,
// ScatterView) has the same spelling from 3.4 to 5.x.
#pragma once

#include <Kokkos_Core.hpp>

#include <cmath>

#include "core/float_env.hpp"

#if !defined(KOKKOS_VERSION)
#error "polymech needs Kokkos >= 3.4 (KOKKOS_VERSION is not defined)"
#endif
#if KOKKOS_VERSION < 30400
#error "polymech needs Kokkos >= 3.4"
#endif

#define POLYMECH_KOKKOS_AT_LEAST(major, minor) (KOKKOS_VERSION >= ((major)*10000 + (minor)*100))

namespace polymech::kx {

#if POLYMECH_KOKKOS_AT_LEAST(4, 0)
#define POLYMECH_KX_MATH(name)                        \
  template <class T>                                  \
  KOKKOS_INLINE_FUNCTION auto name(T x) {             \
    return Kokkos::name(x);                           \
  }
#else
#define POLYMECH_KX_MATH(name)                        \
  template <class T>                                  \
  KOKKOS_INLINE_FUNCTION auto name(T x) {             \
    return Kokkos::Experimental::name(x);             \
  }
#endif

POLYMECH_KX_MATH(sqrt)
POLYMECH_KX_MATH(cbrt)
POLYMECH_KX_MATH(sin)
POLYMECH_KX_MATH(cos)
POLYMECH_KX_MATH(exp)
POLYMECH_KX_MATH(log)
POLYMECH_KX_MATH(fabs)
POLYMECH_KX_MATH(floor)
POLYMECH_KX_MATH(ceil)
POLYMECH_KX_MATH(isfinite)
#undef POLYMECH_KX_MATH

template <class T>
KOKKOS_INLINE_FUNCTION T atan2(T y, T x) {
#if POLYMECH_KOKKOS_AT_LEAST(4, 0)
  return Kokkos::atan2(y, x);
#else
  return Kokkos::Experimental::atan2(y, x);
#endif
}

template <class T>
KOKKOS_INLINE_FUNCTION T min(T a, T b) {
  return a < b ? a : b;
}
template <class T>
KOKKOS_INLINE_FUNCTION T max(T a, T b) {
  return a < b ? b : a;
}
template <class T>
KOKKOS_INLINE_FUNCTION T clamp(T x, T lo, T hi) {
  return x < lo ? lo : (hi < x ? hi : x);
}

// Threads (or GPU lanes) the given execution space uses; concurrency() became non-static in 4.x.
template <class ExecSpace>
inline int concurrency() {
  return static_cast<int>(ExecSpace().concurrency());
}

// Kokkos::initialize with a thread count, for tests and apps; works from 3.4 to 5.x. Then sets the
// subnormal mode (float_env.hpp: flushed to zero unless POLYMECH_SUBNORMALS=keep or the app says so)
// on the calling thread and on every host thread; a bad POLYMECH_SUBNORMALS is refused before Kokkos starts.
inline void initialize(int num_threads = -1, Subnormals subnormals = subnormals_from_environment()) {
#if POLYMECH_KOKKOS_AT_LEAST(3, 7)
  Kokkos::InitializationSettings settings;
  if (num_threads > 0) settings.set_num_threads(num_threads);
  Kokkos::initialize(settings);
#else
  Kokkos::InitArguments args;
  args.num_threads = num_threads;
  Kokkos::initialize(args);
#endif
  set_host_subnormals(subnormals);
}

}  // namespace polymech::kx
