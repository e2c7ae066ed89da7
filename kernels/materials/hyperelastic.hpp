// Finite-strain hyperelastic laws on the deformation gradient F (issue 34: the tyre and the fluid-structure
// benchmarks): compressible neo-Hookean, compressible (decoupled) Mooney-Rivlin, and the tangent of the
// St. Venant-Kirchhoff law of materials/elastic.hpp. Each gives the energy density W(F) per reference
// volume, the first Piola-Kirchhoff stress P = dW/dF and the tangent A = dP/dF (A_iJkL, needed by a Newton
// solve of the total-Lagrangian residual), all in closed form.
//
// A law has the small-strain laws' shape (materials/cubic_elastic.hpp, hill_plasticity.hpp) with F in place
// of the strain: update(F, history, P, A), History = NoHistory. J = det F <= 0 gives NaN (ln J, J^(-2/3)),
// which the solver's finiteness checks report: an inverted element is the solver's to cut back.
#pragma once

#include "materials/cubic_elastic.hpp"
#include "materials/elastic.hpp"

namespace polymech::materials {

// dP_iJ / dF_kL, stored as a 9x9 (row 3i+J, column 3k+L); symmetric (A_iJkL = A_kLiJ) for every law here.
template <class T>
struct PiolaTangent {
  T a[9][9] = {};
  KOKKOS_INLINE_FUNCTION T& operator()(int i, int J, int k, int L) { return a[3 * i + J][3 * k + L]; }
  KOKKOS_INLINE_FUNCTION const T& operator()(int i, int J, int k, int L) const { return a[3 * i + J][3 * k + L]; }
  // dP = A : dF
  KOKKOS_INLINE_FUNCTION Mat3<T> operator*(const Mat3<T>& dF) const {
    Mat3<T> dP = Mat3<T>::zero();
    for (int r = 0; r < 9; ++r)
      for (int c = 0; c < 9; ++c) dP.a[r / 3][r % 3] += a[r][c] * dF.a[c / 3][c % 3];
    return dP;
  }
};

// Compressible neo-Hookean (Ogden's form, as in Simo & Hughes / Bonet & Wood):
//   W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2, P = mu F + (lambda ln J - mu) F^-T,
// which is linear isotropic elasticity with the Lame constants lambda, mu at small strain.
template <class T>
struct NeoHookean {
  static constexpr bool rate_form = false;
  using History = NoHistory;
  static constexpr bool has_history = false;
  ElasticConstants<T> elastic;

  KOKKOS_INLINE_FUNCTION T energy_density(const Mat3<T>& F) const {
    T i1 = T(0);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) i1 += F.a[r][c] * F.a[r][c];
    const T lnJ = kx::log(det(F));
    return T(0.5) * elastic.mu * (i1 - T(3) - T(2) * lnJ) + T(0.5) * elastic.lambda * lnJ * lnJ;
  }
  KOKKOS_INLINE_FUNCTION Mat3<T> first_piola_kirchhoff(const Mat3<T>& F) const {
    const Mat3<T> Fit = transpose(inverse(F));
    return elastic.mu * F + (elastic.lambda * kx::log(det(F)) - elastic.mu) * Fit;
  }
  // A_iJkL = mu d_ik d_JL + lambda Fi_Ji Fi_Lk + (mu - lambda ln J) Fi_Jk Fi_Li, Fi = F^-1
  // (from d ln J/dF = F^-T and d(F^-T)_iJ/dF_kL = -Fi_Jk Fi_Li).
  KOKKOS_INLINE_FUNCTION PiolaTangent<T> tangent(const Mat3<T>& F) const {
    const Mat3<T> Fi = inverse(F);
    const T c = elastic.mu - elastic.lambda * kx::log(det(F));
    PiolaTangent<T> A;
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            A(i, J, k, L) = (i == k && J == L ? elastic.mu : T(0)) + elastic.lambda * Fi.a[J][i] * Fi.a[L][k] +
                            c * Fi.a[J][k] * Fi.a[L][i];
    return A;
  }
  KOKKOS_INLINE_FUNCTION int update(const Mat3<T>& F, History& /*history*/, Mat3<T>& P, PiolaTangent<T>& A) const {
    P = first_piola_kirchhoff(F);
    A = tangent(F);
    return 0;
  }
};

// Compressible Mooney-Rivlin in the decoupled (isochoric / volumetric) form of Abaqus and most FSI codes:
//   W = C10 (I1b - 3) + C01 (I2b - 3) + kappa/2 (J - 1)^2, I1b = J^-2/3 I1, I2b = J^-4/3 I2,
// I1 = tr C, I2 = (I1^2 - tr C^2)/2, C = F^T F. Small-strain shear modulus 2 (C10 + C01), bulk modulus kappa;
// C01 = 0 is the decoupled neo-Hookean.
template <class T>
struct MooneyRivlin {
  static constexpr bool rate_form = false;
  using History = NoHistory;
  static constexpr bool has_history = false;
  T C10 = T(0), C01 = T(0), kappa = T(0);

  KOKKOS_INLINE_FUNCTION T energy_density(const Mat3<T>& F) const {
    const Mat3<T> C = transpose(F) * F;
    const T i1 = trace(C), i2 = T(0.5) * (i1 * i1 - double_dot(C, C)), J = det(F);
    const T j23 = T(1) / kx::cbrt(J * J);
    return C10 * (j23 * i1 - T(3)) + C01 * (j23 * j23 * i2 - T(3)) + T(0.5) * kappa * (J - T(1)) * (J - T(1));
  }
  // P = C10 J^-2/3 (2F - 2/3 I1 F^-T) + C01 J^-4/3 (2 I1 F - 2 F C - 4/3 I2 F^-T) + kappa (J - 1) J F^-T
  // (dI1/dF = 2F, dI2/dF = 2(I1 F - F C), dJ/dF = J F^-T).
  KOKKOS_INLINE_FUNCTION Mat3<T> first_piola_kirchhoff(const Mat3<T>& F) const {
    const Parts p(F);
    Mat3<T> P;
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) {
        const T fit = p.Fi.a[J][i];
        P.a[i][J] = C10 * p.j23 * (T(2) * F.a[i][J] - T(2) / T(3) * p.i1 * fit) +
                    C01 * p.j23 * p.j23 * (T(2) * p.i1 * F.a[i][J] - T(2) * p.FC.a[i][J] - T(4) / T(3) * p.i2 * fit) +
                    kappa * (p.J - T(1)) * p.J * fit;
      }
    return P;
  }
  // Each term of P differentiated by the product rule with d(F^-T)_iJ/dF_kL = -Fi_Jk Fi_Li,
  // d J^a/dF_kL = a J^a Fi_Lk and d(F C)_iJ/dF_kL = d_ik C_LJ + F_iL F_kJ + b_ik d_JL (b = F F^T).
  KOKKOS_INLINE_FUNCTION PiolaTangent<T> tangent(const Mat3<T>& F) const {
    const Parts p(F);
    const Mat3<T> b = F * transpose(F);
    PiolaTangent<T> A;
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L) {
            const T dFF = (i == k && J == L) ? T(1) : T(0);        // dF_iJ/dF_kL
            const T dFit = -p.Fi.a[J][k] * p.Fi.a[L][i];           // d(F^-T)_iJ/dF_kL
            const T dlnJ = p.Fi.a[L][k];                           // d ln J/dF_kL
            const T dI1 = T(2) * F.a[k][L];
            const T dI2 = T(2) * (p.i1 * F.a[k][L] - p.FC.a[k][L]);
            const T dFC = (i == k ? p.C.a[L][J] : T(0)) + F.a[i][L] * F.a[k][J] + (J == L ? b.a[i][k] : T(0));
            const T fit = p.Fi.a[J][i];
            // C10 J^-2/3 (2 F - 2/3 I1 F^-T)
            const T t1 = T(2) * F.a[i][J] - T(2) / T(3) * p.i1 * fit;
            const T d1 = T(-2) / T(3) * dlnJ * t1 + T(2) * dFF - T(2) / T(3) * (dI1 * fit + p.i1 * dFit);
            // C01 J^-4/3 (2 I1 F - 2 F C - 4/3 I2 F^-T)
            const T t2 = T(2) * p.i1 * F.a[i][J] - T(2) * p.FC.a[i][J] - T(4) / T(3) * p.i2 * fit;
            const T d2 = T(-4) / T(3) * dlnJ * t2 + T(2) * (dI1 * F.a[i][J] + p.i1 * dFF) - T(2) * dFC -
                         T(4) / T(3) * (dI2 * fit + p.i2 * dFit);
            // kappa (J^2 - J) F^-T
            const T d3 = kappa * ((T(2) * p.J * p.J - p.J) * dlnJ * fit + (p.J * p.J - p.J) * dFit);
            A(i, J, k, L) = C10 * p.j23 * d1 + C01 * p.j23 * p.j23 * d2 + d3;
          }
    return A;
  }
  KOKKOS_INLINE_FUNCTION int update(const Mat3<T>& F, History& /*history*/, Mat3<T>& P, PiolaTangent<T>& A) const {
    P = first_piola_kirchhoff(F);
    A = tangent(F);
    return 0;
  }

 private:
  // The invariants and products P and A share.
  struct Parts {
    Mat3<T> C, FC, Fi;
    T i1, i2, J, j23;
    KOKKOS_INLINE_FUNCTION explicit Parts(const Mat3<T>& F) {
      C = transpose(F) * F;
      FC = F * C;
      Fi = inverse(F);
      i1 = trace(C);
      i2 = T(0.5) * (i1 * i1 - double_dot(C, C));
      J = det(F);
      j23 = T(1) / kx::cbrt(J * J);
    }
  };
};

// The tangent of St. Venant-Kirchhoff (materials/elastic.hpp: P = F S, S = lambda tr(E) I + 2 mu E):
//   A_iJkL = d_ik S_JL + F_iM D_MJNL F_kN, D = lambda d_MJ d_NL + mu (d_MN d_JL + d_ML d_JN).
template <class T>
KOKKOS_INLINE_FUNCTION PiolaTangent<T> svk_tangent(const Mat3<T>& F, const ElasticConstants<T>& c) {
  const Mat3<T> S = svk_second_pk(green_lagrange(F), c);
  const Mat3<T> b = F * transpose(F);
  PiolaTangent<T> A;
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L)
          // F_iM D_MJNL F_kN = lambda F_iJ F_kL + mu (b_ik d_JL + F_iL F_kJ)
          A(i, J, k, L) = (i == k ? S.a[J][L] : T(0)) + c.lambda * F.a[i][J] * F.a[k][L] +
                          c.mu * ((J == L ? b.a[i][k] : T(0)) + F.a[i][L] * F.a[k][J]);
  return A;
}

}  // namespace polymech::materials
