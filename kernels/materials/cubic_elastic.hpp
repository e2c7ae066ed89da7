// Rotated anisotropic linear elasticity for cubic single crystals (seed 002 paper 5 eqs. (1)-(2): sigma = C eps
// with three constants C11, C12, C44 in crystal axes), the rotation of the paper's micro-cantilevers, the
// closed-form uniaxial modulus along a direction, and the small-strain elastic law every element can
// template on (`AnisotropicElastic`, no history).
//
// The paper's beams lie on a (110) wafer: the top face is the (110) plane and the beam axis is a direction
// IN that plane at angle theta from [001] (0, 5, 10, 20, 30, 54.7 deg; 54.7 deg is [1-11], a <111>).
#pragma once

#include "materials/voigt_algebra.hpp"

namespace polymech::materials {

template <class T>
struct CubicConstants {
  T C11 = T(0), C12 = T(0), C44 = T(0);
  // Compliances of the cubic crystal: S = C^-1 in closed form (the 3x3 normal block is inverted through
  // its eigenvalues C11 + 2 C12 (hydrostatic) and C11 - C12 (deviatoric)).
  KOKKOS_INLINE_FUNCTION T S11() const { return (C11 + C12) / ((C11 - C12) * (C11 + T(2) * C12)); }
  KOKKOS_INLINE_FUNCTION T S12() const { return -C12 / ((C11 - C12) * (C11 + T(2) * C12)); }
  KOKKOS_INLINE_FUNCTION T S44() const { return T(1) / C44; }
  // Zener's anisotropy ratio 2 C44 / (C11 - C12): 1 for an isotropic solid.
  KOKKOS_INLINE_FUNCTION T zener_ratio() const { return T(2) * C44 / (C11 - C12); }
};

// Cubic 8YSZ (ZrO2 with 8 mol% Y2O3) at room temperature, in GPa: the values quoted for that composition
// in the literature docs/METHODS.md cites (with how far the source was verified). Zener ratio 0.37, so
// <100> is the stiff direction and <111> the compliant one: E<100> = 364 GPa, E<111> = 154 GPa.
template <class T>
KOKKOS_INLINE_FUNCTION CubicConstants<T> ysz8_constants_gpa() {
  CubicConstants<T> c;
  c.C11 = T(401);
  c.C12 = T(96);
  c.C44 = T(56);
  return c;
}

// seed 002 paper 5 eq. (2): the cubic stiffness in crystal axes (Voigt order 11,22,33,23,13,12; engineering
// shear strains, so the shear diagonal is C44 itself).
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> cubic_stiffness(const CubicConstants<T>& k) {
  Stiffness6<T> C;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) C.c[i][j] = k.C12;
    C.c[i][i] = k.C11;
    C.c[i + 3][i + 3] = k.C44;
  }
  return C;
}
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> cubic_compliance(const CubicConstants<T>& k) {
  Stiffness6<T> S;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) S.c[i][j] = k.S12();
    S.c[i][i] = k.S11();
    S.c[i + 3][i + 3] = k.S44();
  }
  return S;
}

// Uniaxial (Young's) modulus along the unit crystal direction n, closed form (docs/METHODS.md derives it):
// 1/E(n) = n_i n_j n_k n_l S_ijkl = S11 - 2 (S11 - S12 - S44/2) (n1^2 n2^2 + n2^2 n3^2 + n3^2 n1^2).
template <class T>
KOKKOS_INLINE_FUNCTION T cubic_uniaxial_modulus(const CubicConstants<T>& k, const Vec3<T>& n) {
  const T a = n[0] * n[0], b = n[1] * n[1], c = n[2] * n[2];
  const T gamma = a * b + b * c + c * a;
  return T(1) / (k.S11() - T(2) * (k.S11() - k.S12() - T(0.5) * k.S44()) * gamma);
}

// The micro-cantilever's axes in crystal coordinates (rows of Q; see voigt_algebra.hpp):
//   x (beam axis)   = cos(theta) [001] + sin(theta) [1-10]/sqrt2, a direction in the (110) top face,
//   z (top normal)  = [110]/sqrt2, pointing out of the wafer,
//   y (width)       = z x x, in the top face, so (x, y, z) is right-handed.
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> cantilever_rotation(T theta) {
  const T c = kx::cos(theta), s = kx::sin(theta), r = T(1) / kx::sqrt(T(2));
  Mat3<T> Q;
  Q.a[0][0] = s * r; Q.a[0][1] = -s * r; Q.a[0][2] = c;  // beam axis
  Q.a[1][0] = c * r; Q.a[1][1] = -c * r; Q.a[1][2] = -s;  // width
  Q.a[2][0] = r;     Q.a[2][1] = r;      Q.a[2][2] = T(0);  // top-face normal [110]
  return Q;
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> cantilever_axis(T theta) {
  const Mat3<T> Q = cantilever_rotation(theta);
  return Vec3<T>{{Q.a[0][0], Q.a[0][1], Q.a[0][2]}};
}

// The cubic stiffness in the specimen axes of Q.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> rotated_cubic_stiffness(const CubicConstants<T>& k, const Mat3<T>& Q) {
  return rotate_stiffness(cubic_stiffness(k), Q);
}

// The state a quadrature point keeps when a law has no history: empty, so a model holding
// `Kokkos::View<typename Law::History*>` for such a law allocates nothing (`Law::has_history` is false).
struct NoHistory {};

// Small-strain linear elasticity with any (rotated, anisotropic) stiffness: seed 002 paper 5 eq. (1). The
// same `update` signature as HillPlasticity (materials/hill_plasticity.hpp), so an element templates on the
// law; the tangent is C itself.
template <class T>
struct AnisotropicElastic {
  using History = NoHistory;
  static constexpr bool has_history = false;
  Stiffness6<T> C;

  // Returns the number of local iterations, always 0 (HillPlasticity::update returns its own).
  KOKKOS_INLINE_FUNCTION int update(const Voigt6<T>& strain, History& /*history*/, Voigt6<T>& stress,
                                    Stiffness6<T>& tangent) const {
    stress = C * strain;
    tangent = C;
    return 0;
  }
  KOKKOS_INLINE_FUNCTION Voigt6<T> stress(const Voigt6<T>& strain) const { return C * strain; }
  // sigma . eps / 2 per unit volume.
  KOKKOS_INLINE_FUNCTION T energy_density(const Voigt6<T>& strain) const { return T(0.5) * dot6(C * strain, strain); }
};

template <class T>
KOKKOS_INLINE_FUNCTION AnisotropicElastic<T> make_cubic_elastic(const CubicConstants<T>& k, const Mat3<T>& Q) {
  AnisotropicElastic<T> law;
  law.C = rotated_cubic_stiffness(k, Q);
  return law;
}

}  // namespace polymech::materials
