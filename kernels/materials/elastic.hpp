// Elastic constitutive laws any method can use (device functions, always on 3x3 tensors; 2D methods
// embed plane strain with F33 = 1), and the tensor helpers the laws share.
//
// St. Venant-Kirchhoff: Green-Lagrange strain E = (F^T F - I)/2, S = lambda tr(E) I + 2 mu E, first
// Piola-Kirchhoff stress P = F S (seed 003 §1: "Green-Lagrange strain and a constitutive law").
//
// A law is a small struct; a method picks it by type (std::variant in the model, a template parameter
// in the kernel), never by an `if` on a flag. Hyperelastic laws give P from F (`rate_form = false`);
// rate laws (kernels/materials/johnson_cook.hpp) update a stress from the velocity gradient.
#pragma once

#include "core/small_math.hpp"

namespace polymech::materials {

template <class T>
struct ElasticConstants {
  T lambda = T(0), mu = T(0);
  KOKKOS_INLINE_FUNCTION T bulk() const { return lambda + T(2) / T(3) * mu; }
};

// Deviator, double contraction and von Mises equivalent stress of 3x3 tensors.
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> deviator(const Mat3<T>& s) {
  Mat3<T> d = s;
  const T p = trace(s) / T(3);
  for (int k = 0; k < 3; ++k) d.a[k][k] -= p;
  return d;
}
template <class T>
KOKKOS_INLINE_FUNCTION T double_dot(const Mat3<T>& a, const Mat3<T>& b) {
  T s = T(0);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) s += a.a[r][c] * b.a[r][c];
  return s;
}
template <class T>
KOKKOS_INLINE_FUNCTION T von_mises(const Mat3<T>& s) {
  const Mat3<T> d = deviator(s);
  return kx::sqrt(T(1.5) * double_dot(d, d));
}

// seed 003 §1 (Green-Lagrange strain, St. Venant-Kirchhoff).
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> green_lagrange(const Mat3<T>& F) {
  Mat3<T> E = transpose(F) * F;
  for (int k = 0; k < 3; ++k) E.a[k][k] -= T(1);
  return T(0.5) * E;
}
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> svk_second_pk(const Mat3<T>& E, const ElasticConstants<T>& c) {
  Mat3<T> S = (T(2) * c.mu) * E;
  const T le = c.lambda * trace(E);
  for (int k = 0; k < 3; ++k) S.a[k][k] += le;
  return S;
}
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> svk_first_pk(const Mat3<T>& F, const ElasticConstants<T>& c) {
  return F * svk_second_pk(green_lagrange(F), c);
}
// Strain energy density W = lambda/2 (tr E)^2 + mu E:E per reference volume.
template <class T>
KOKKOS_INLINE_FUNCTION T svk_energy(const Mat3<T>& F, const ElasticConstants<T>& c) {
  const Mat3<T> E = green_lagrange(F);
  T ee = T(0);
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) ee += E.a[r][s] * E.a[r][s];
  const T t = trace(E);
  return T(0.5) * c.lambda * t * t + c.mu * ee;
}

// The St. Venant-Kirchhoff law as a struct: P(F) and W(F).
template <class T>
struct StVenantKirchhoff {
  static constexpr bool rate_form = false;
  ElasticConstants<T> elastic;

  KOKKOS_INLINE_FUNCTION Mat3<T> first_piola_kirchhoff(const Mat3<T>& F) const { return svk_first_pk(F, elastic); }
  KOKKOS_INLINE_FUNCTION T energy_density(const Mat3<T>& F) const { return svk_energy(F, elastic); }
};

}  // namespace polymech::materials
