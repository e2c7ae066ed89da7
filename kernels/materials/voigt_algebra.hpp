// Small dense algebra on the Voigt 6-vectors and 6x6 matrices of materials/voigt.hpp that anisotropic
// laws need (issue 34): products, a Cholesky solve and inverse for the symmetric positive definite 6x6
// matrices a return mapping meets (S + dgamma P), and the Bond transformations that carry a stiffness,
// a compliance or a yield-function metric from crystal axes to specimen axes.
//
// Rotation convention: Q (3x3) has the specimen axes as its rows, written in crystal coordinates, so a
// vector's specimen components are v_s = Q v_c and a tensor's are sigma_s = Q sigma_c Q^T.
#pragma once

#include "materials/voigt.hpp"

namespace polymech::materials {

template <class T>
KOKKOS_INLINE_FUNCTION T dot6(const Voigt6<T>& a, const Voigt6<T>& b) {
  T s = T(0);
  for (int i = 0; i < 6; ++i) s += a[i] * b[i];
  return s;
}
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> identity6() {
  Stiffness6<T> I;
  for (int i = 0; i < 6; ++i) I.c[i][i] = T(1);
  return I;
}
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> transpose6(const Stiffness6<T>& A) {
  Stiffness6<T> R;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) R.c[i][j] = A.c[j][i];
  return R;
}
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> product6(const Stiffness6<T>& A, const Stiffness6<T>& B) {
  Stiffness6<T> R;
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k)
      for (int j = 0; j < 6; ++j) R.c[i][j] += A.c[i][k] * B.c[k][j];
  return R;
}
// A v for a 6x6 matrix stored as Stiffness6 (also a compliance or a metric).
template <class T>
KOKKOS_INLINE_FUNCTION Voigt6<T> apply6(const Stiffness6<T>& A, const Voigt6<T>& v) {
  return A * v;
}
// a . A b
template <class T>
KOKKOS_INLINE_FUNCTION T quadratic6(const Voigt6<T>& a, const Stiffness6<T>& A, const Voigt6<T>& b) {
  return dot6(a, A * b);
}

// Cholesky factor L (lower) of a symmetric positive definite A; false when a pivot is not positive
// (kernels cannot throw: the caller decides what a failed factorization means).
template <class T>
KOKKOS_INLINE_FUNCTION bool cholesky6(const Stiffness6<T>& A, Stiffness6<T>& L) {
  for (int j = 0; j < 6; ++j) {
    T d = A.c[j][j];
    for (int k = 0; k < j; ++k) d -= L.c[j][k] * L.c[j][k];
    if (!(d > T(0))) return false;
    const T ljj = kx::sqrt(d);
    L.c[j][j] = ljj;
    for (int i = j + 1; i < 6; ++i) {
      T s = A.c[i][j];
      for (int k = 0; k < j; ++k) s -= L.c[i][k] * L.c[j][k];
      L.c[i][j] = s / ljj;
    }
    for (int i = 0; i < j; ++i) L.c[i][j] = T(0);
  }
  return true;
}
// Solve L L^T x = b with the factor of cholesky6.
template <class T>
KOKKOS_INLINE_FUNCTION Voigt6<T> cholesky_solve6(const Stiffness6<T>& L, const Voigt6<T>& b) {
  Voigt6<T> y;
  for (int i = 0; i < 6; ++i) {
    T s = b[i];
    for (int k = 0; k < i; ++k) s -= L.c[i][k] * y[k];
    y[i] = s / L.c[i][i];
  }
  Voigt6<T> x;
  for (int i = 5; i >= 0; --i) {
    T s = y[i];
    for (int k = i + 1; k < 6; ++k) s -= L.c[k][i] * x[k];
    x[i] = s / L.c[i][i];
  }
  return x;
}
// Inverse of a symmetric positive definite 6x6 (a stiffness from its compliance and back). A matrix that
// is not positive definite gives NaN entries, which the callers' finiteness checks report.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> spd_inverse6(const Stiffness6<T>& A) {
  Stiffness6<T> L, R;
  if (!cholesky6(A, L)) {
    const T nan = kx::sqrt(T(-1));
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) R.c[i][j] = nan;
    return R;
  }
  for (int j = 0; j < 6; ++j) {
    Voigt6<T> e;
    e[j] = T(1);
    const Voigt6<T> x = cholesky_solve6(L, e);
    for (int i = 0; i < 6; ++i) R.c[i][j] = x[i];
  }
  return R;
}

// Bond matrix of a stress vector: s_s = M s_c for sigma_s = Q sigma_c Q^T (tensor components in both).
// Entry (K, L) collects the products Q_pa Q_qb over the index pairs (a, b) that Voigt slot L stands for.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> bond_stress(const Mat3<T>& Q) {
  Stiffness6<T> M;
  for (int K = 0; K < 6; ++K) {
    const int p = voigt_i(K), q = voigt_j(K);
    for (int L = 0; L < 6; ++L) {
      const int a = voigt_i(L), b = voigt_j(L);
      M.c[K][L] = Q.a[p][a] * Q.a[q][b] + (a != b ? Q.a[p][b] * Q.a[q][a] : T(0));
    }
  }
  return M;
}
// Bond matrix of an engineering-shear strain vector: e_s = N e_c. Because the work s . e is invariant,
// N = M^-T; for an orthogonal Q that is M with the shear rows doubled and the shear columns halved.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> bond_strain(const Mat3<T>& Q) {
  Stiffness6<T> N = bond_stress(Q);
  for (int K = 0; K < 6; ++K)
    for (int L = 0; L < 6; ++L) {
      const T row = K < 3 ? T(1) : T(2), col = L < 3 ? T(1) : T(0.5);
      N.c[K][L] *= row * col;
    }
  return N;
}
// A * B * A^T
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> congruence6(const Stiffness6<T>& A, const Stiffness6<T>& B) {
  return product6(product6(A, B), transpose6(A));
}
// Stiffness in specimen axes: s_s = M C_c M^T e_s, since e_c = N^-1 e_s = M^T e_s.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> rotate_stiffness(const Stiffness6<T>& C, const Mat3<T>& Q) {
  return congruence6(bond_stress(Q), C);
}
// A compliance or a quadratic yield metric (both act on stress vectors: e = S s, phi^2 = s . P s) in
// specimen axes: N S N^T.
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> rotate_compliance(const Stiffness6<T>& S, const Mat3<T>& Q) {
  return congruence6(bond_strain(Q), S);
}

}  // namespace polymech::materials
