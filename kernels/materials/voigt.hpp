// The Voigt convention every small-strain solid law and element of polymech shares (issue 34).
//
// Order: (11, 22, 33, 23, 13, 12). Strain vectors carry ENGINEERING shear strains (gamma_23 = 2 eps_23, ...),
// stress vectors the tensor components, so sigma = C eps with C symmetric and the strain energy density is
// sigma . eps / 2. A 2D element uses the same 6-vectors (plane strain: eps_33 = gamma_23 = gamma_13 = 0; plane
// stress: the law is condensed to sigma_33 = sigma_23 = sigma_13 = 0 by `plane_stress_condensed`).
#pragma once

#include "core/small_math.hpp"

namespace polymech::materials {

template <class T>
struct Voigt6 {
  T v[6] = {T(0), T(0), T(0), T(0), T(0), T(0)};
  KOKKOS_INLINE_FUNCTION T& operator[](int i) { return v[i]; }
  KOKKOS_INLINE_FUNCTION const T& operator[](int i) const { return v[i]; }
};

// A 6x6 stiffness (or compliance) in the order above; symmetric for every law that has an energy.
template <class T>
struct Stiffness6 {
  T c[6][6] = {};
  KOKKOS_INLINE_FUNCTION Voigt6<T> operator*(const Voigt6<T>& e) const {
    Voigt6<T> s;
    for (int i = 0; i < 6; ++i) {
      T a = T(0);
      for (int j = 0; j < 6; ++j) a += c[i][j] * e[j];
      s[i] = a;
    }
    return s;
  }
};

// Index pairs of the Voigt order.
KOKKOS_INLINE_FUNCTION constexpr int voigt_i(int k) { return k < 3 ? k : (k == 3 ? 1 : 0); }
KOKKOS_INLINE_FUNCTION constexpr int voigt_j(int k) { return k < 3 ? k : (k == 5 ? 1 : 2); }

// Symmetric 3x3 strain tensor -> Voigt strain (engineering shear) and stress Voigt -> 3x3 tensor.
template <class T>
KOKKOS_INLINE_FUNCTION Voigt6<T> strain_to_voigt(const Mat3<T>& e) {
  Voigt6<T> v;
  v[0] = e.a[0][0]; v[1] = e.a[1][1]; v[2] = e.a[2][2];
  v[3] = e.a[1][2] + e.a[2][1]; v[4] = e.a[0][2] + e.a[2][0]; v[5] = e.a[0][1] + e.a[1][0];
  return v;
}
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> stress_from_voigt(const Voigt6<T>& s) {
  Mat3<T> m;
  m.a[0][0] = s[0]; m.a[1][1] = s[1]; m.a[2][2] = s[2];
  m.a[1][2] = m.a[2][1] = s[3]; m.a[0][2] = m.a[2][0] = s[4]; m.a[0][1] = m.a[1][0] = s[5];
  return m;
}

// Isotropic linear elasticity from Young's modulus and Poisson's ratio.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> isotropic_stiffness(T young, T poisson) {
  Stiffness6<T> C;
  const T lambda = young * poisson / ((T(1) + poisson) * (T(1) - T(2) * poisson));
  const T mu = young / (T(2) * (T(1) + poisson));
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C.c[i][j] = lambda;
    C.c[i][i] = lambda + T(2) * mu;
    C.c[i + 3][i + 3] = mu;
  }
  return C;
}

// Plane stress: eliminate the out-of-plane components (33, 23, 13) by static condensation,
// C_pp - C_po C_oo^-1 C_op with p = {11, 22, 12}, o = {33, 23, 13}; rows and columns of o are zero in the result.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> plane_stress_condensed(const Stiffness6<T>& C) {
  constexpr int p[3] = {0, 1, 5}, o[3] = {2, 3, 4};
  Mat3<T> Coo;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) Coo.a[i][j] = C.c[o[i]][o[j]];
  const Mat3<T> inv = inverse(Coo);
  Stiffness6<T> R;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      T s = C.c[p[i]][p[j]];
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s -= C.c[p[i]][o[k]] * inv.a[k][l] * C.c[o[l]][p[j]];
      R.c[p[i]][p[j]] = s;
    }
  return R;
}

}  // namespace polymech::materials
