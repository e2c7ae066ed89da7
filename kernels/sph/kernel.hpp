// The SPH weight function of the stabilized ISPH (seed 002 paper 4). The paper names only the radius
// re = 3.3 l0 (Table 1), not the kernel: we take the Wendland C2 function (Wendland 1995; Dehnen & Aly
// 2012), W(r) = a_D (1 - q)^4 (1 + 4 q), q = r / re, support exactly re. Why: it is positive definite
// (no pairing instability at the 3.3 l0 radius, where the cubic spline clumps), smooth (C2), and its
// support is the radius the paper gives, with no h/re convention to guess.
//   a_2 = 7 / (pi re^2),  a_3 = 21 / (2 pi re^3).
// `scale` divides every value: set to the lattice sum l0^D sum_j W(r_j) so that the density of a full
// square lattice is exactly rho0 (a correction below 1 %, docs/METHODS.md).
#pragma once

#include "core/kokkos_shim.hpp"
#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::sph {

template <class T, int D>
struct Wendland {
  T re = T(0);     // support radius
  T norm = T(0);   // a_D / scale
  T inv_re = T(0);

  static Wendland make(double re, double scale = 1.0) {
    Wendland w;
    const double pi = 3.14159265358979323846;
    const double a = D == 2 ? 7.0 / (pi * re * re) : 21.0 / (2.0 * pi * re * re * re);
    w.re = T(re);
    w.norm = T(a / scale);
    w.inv_re = T(1.0 / re);
    return w;
  }
  KOKKOS_INLINE_FUNCTION T value(T r) const {
    const T q = r * inv_re;
    if (q >= T(1)) return T(0);
    const T s = T(1) - q;
    return norm * s * s * s * s * (T(1) + T(4) * q);
  }
  // dW/dr = -20 a q (1 - q)^3 / re
  KOKKOS_INLINE_FUNCTION T derivative(T r) const {
    const T q = r * inv_re;
    if (q >= T(1)) return T(0);
    const T s = T(1) - q;
    return -T(20) * norm * q * s * s * s * inv_re;
  }
  // F(r) = -W'(r) / r >= 0 (finite at r = 0): the Laplacian eqs. (10), (11), (20), (21) use
  // (r_ij / |r_ij|^2) . grad W_ij = W'(r) / r = -F(r).
  KOKKOS_INLINE_FUNCTION T f(T r) const {
    const T q = r * inv_re;
    if (q >= T(1)) return T(0);
    const T s = T(1) - q;
    return T(20) * norm * s * s * s * inv_re * inv_re;
  }
  // grad_i W(|x_i - x_j|) for r_ij = x_i - x_j: W'(r) r_ij / r = -F(r) r_ij.
  KOKKOS_INLINE_FUNCTION Vec<T, D> gradient(const Vec<T, D>& rij, T r) const { return (-f(r)) * rij; }
};

// l0^D sum over a square (cubic) lattice of spacing l0, self included, of the unscaled kernel: the
// `scale` that makes a full lattice's summation density exactly rho0 (host).
template <int D>
double lattice_sum(double re, double l0) {
  const Wendland<double, D> w = Wendland<double, D>::make(re, 1.0);
  const int n = static_cast<int>(re / l0) + 1;
  double s = 0.0;
  if constexpr (D == 2) {
    for (int a = -n; a <= n; ++a)
      for (int b = -n; b <= n; ++b) s += w.value(l0 * std::sqrt(double(a * a + b * b)));
    return s * l0 * l0;
  } else {
    for (int a = -n; a <= n; ++a)
      for (int b = -n; b <= n; ++b)
        for (int c = -n; c <= n; ++c) s += w.value(l0 * std::sqrt(double(a * a + b * b + c * c)));
    return s * l0 * l0 * l0;
  }
}

}  // namespace polymech::sph
