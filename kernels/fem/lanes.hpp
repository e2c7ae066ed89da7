// A short vector of L values of one real type, processed together: the value type of the batched
// element kernels (kernels/fem/helmholtz_operator.hpp), where lane l of every array holds the same
// quantity of a different element (and, for complex fields, the real and imaginary parts of one
// element sit in two lanes). Every arithmetic operation of the sum-factorized kernels then acts on
// whole vector registers, with the element index innermost.
//
// On CPUs compiled by GCC or Clang the storage is a GNU vector (`vector_size`), which the compiler
// keeps in SIMD registers; elsewhere (CUDA, other compilers) it is a plain array and the loops over
// the lanes are left to the compiler. On a GPU the kernels use one element per thread (L = 1 or 2).
#pragma once

#include <type_traits>

#include "core/kokkos_shim.hpp"

#if !defined(KOKKOS_ENABLE_CUDA) && !defined(KOKKOS_ENABLE_HIP) && !defined(KOKKOS_ENABLE_SYCL) && \
    (defined(__GNUC__) || defined(__clang__))
#define POLYMECH_GNU_VECTORS 1
#else
#define POLYMECH_GNU_VECTORS 0
#endif

namespace polymech::fem {

// Bytes of the widest SIMD register of the target (host builds); 8 where there is none to use.
inline constexpr int simd_bytes() {
#if !POLYMECH_GNU_VECTORS
  return 8;
#elif defined(__AVX512F__)
  return 64;
#elif defined(__AVX__)
  return 32;
#else
  return 16;
#endif
}

template <class T, int L>
struct Lanes {
  static_assert(L >= 1 && (L & (L - 1)) == 0, "the lane count is a power of two");
  static constexpr int size = L;
#if POLYMECH_GNU_VECTORS
  typedef T vector_type __attribute__((vector_size(sizeof(T) * L)));
  vector_type v;
  KOKKOS_FORCEINLINE_FUNCTION T get(int l) const { return v[l]; }
  KOKKOS_FORCEINLINE_FUNCTION void set(int l, T x) { v[l] = x; }
  KOKKOS_FORCEINLINE_FUNCTION static Lanes broadcast(T x) {
    Lanes r;
    r.v = vector_type{} + x;
    return r;
  }
#define POLYMECH_LANES_OP(op)                                                          \
  KOKKOS_FORCEINLINE_FUNCTION friend Lanes operator op(const Lanes& a, const Lanes& b) { \
    Lanes r;                                                                           \
    r.v = a.v op b.v;                                                                  \
    return r;                                                                          \
  }                                                                                    \
  KOKKOS_FORCEINLINE_FUNCTION friend Lanes operator op(T s, const Lanes& b) {          \
    Lanes r;                                                                           \
    r.v = s op b.v;                                                                    \
    return r;                                                                          \
  }                                                                                    \
  KOKKOS_FORCEINLINE_FUNCTION Lanes& operator op##=(const Lanes& b) {                  \
    v = v op b.v;                                                                      \
    return *this;                                                                      \
  }
#else
  T v[L];
  KOKKOS_FORCEINLINE_FUNCTION T get(int l) const { return v[l]; }
  KOKKOS_FORCEINLINE_FUNCTION void set(int l, T x) { v[l] = x; }
  KOKKOS_FORCEINLINE_FUNCTION static Lanes broadcast(T x) {
    Lanes r;
    for (int l = 0; l < L; ++l) r.v[l] = x;
    return r;
  }
#define POLYMECH_LANES_OP(op)                                                          \
  KOKKOS_FORCEINLINE_FUNCTION friend Lanes operator op(const Lanes& a, const Lanes& b) { \
    Lanes r;                                                                           \
    for (int l = 0; l < L; ++l) r.v[l] = a.v[l] op b.v[l];                             \
    return r;                                                                          \
  }                                                                                    \
  KOKKOS_FORCEINLINE_FUNCTION friend Lanes operator op(T s, const Lanes& b) {          \
    Lanes r;                                                                           \
    for (int l = 0; l < L; ++l) r.v[l] = s op b.v[l];                                  \
    return r;                                                                          \
  }                                                                                    \
  KOKKOS_FORCEINLINE_FUNCTION Lanes& operator op##=(const Lanes& b) {                  \
    for (int l = 0; l < L; ++l) v[l] = v[l] op b.v[l];                                 \
    return *this;                                                                      \
  }
#endif
  POLYMECH_LANES_OP(+)
  POLYMECH_LANES_OP(-)
  POLYMECH_LANES_OP(*)
#undef POLYMECH_LANES_OP
};

// Hint that *p will be read (Write = false) or written soon: a software prefetch on CPUs (the DoFs of
// the next batch of elements, whose indices the hardware prefetchers cannot predict), nothing elsewhere.
template <bool Write = false>
KOKKOS_FORCEINLINE_FUNCTION void prefetch(const void* p) {
#if POLYMECH_GNU_VECTORS
  __builtin_prefetch(p, Write ? 1 : 0, 3);
#else
  (void)p;
#endif
}

// Elements per batch of the element kernels for values with `components` reals each (1 real, 2
// complex): as many as fill one SIMD register of T (at least one; one on a GPU, where each thread
// takes an element).
template <class T, int components>
inline constexpr int default_batch() {
  constexpr int lanes = simd_bytes() / static_cast<int>(sizeof(T));
  return lanes / components >= 1 ? lanes / components : 1;
}

}  // namespace polymech::fem
