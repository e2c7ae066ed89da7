// Matrix-free volume part of the Helmholtz operator, y += (A + m M) x (seed 002 paper 3 eqs. (16)-(18),
// with m = -k^2), applied element by element with sum factorization: interpolate to the Q^3 points,
// take the reference gradient by collocation, multiply by the stored geometric factors, and integrate
// back with the transposes. Work per element O(N^4), storage 7 reals per point; the global matrix is
// never formed.
//
// Values V are T (real problems: CG) or Kokkos::complex<T> (the complex symmetric system: COCG); the
// coefficients of A and M are real, so complex vectors are two real right-hand sides in one sweep.
#pragma once

#include "fem/hex_elements.hpp"

namespace polymech::fem {

namespace detail {

// Squared 1D factors for the diagonal: B^2, D^2 and B D at the points.
template <class T, int N, int Q>
struct SquaredFactors {
  T BB[Q][N], DD[Q][N], BD[Q][N];
};

// Constrained = true: DoFs under a strong Dirichlet condition (negative entries) count as zero on
// input and receive nothing (the operator on the free DoFs). false: every DoF takes part (the lifting
// of Dirichlet data, K g).
template <class V, class T, int N, bool Constrained>
void apply_volume(const char* label, const HexElements<T>& el, T mass_coefficient, const View1<V>& x,
                  const View1<V>& y) {
  constexpr int Q = N, N3 = N * N * N, Q3 = Q * Q * Q;
  const HexBasis<T, N, Q> b = make_hex_basis<T, N, Q>();
  const auto dofs = el.dofs;
  const auto geo = el.geometry;
  parallel_for_colors(label, el, KOKKOS_LAMBDA(const Index e) {
    V u[N3], uq[Q3], g0[Q3], g1[Q3], g2[Q3], t1[Q * Q * N], t2[Q * Q * N];
    gather<Constrained, N3>(dofs, e, x, u);
    interpolate<N, Q>(b.B, u, uq, t1, t2);
    gradient_at_points<Q>(b.Dq, uq, g0, g1, g2);
    const T* G = &geo(e, 0);
    for (int q = 0; q < Q3; ++q) {
      const V a0 = g0[q], a1 = g1[q], a2 = g2[q];
      g0[q] = G[g00 * Q3 + q] * a0 + G[g01 * Q3 + q] * a1 + G[g02 * Q3 + q] * a2;
      g1[q] = G[g01 * Q3 + q] * a0 + G[g11 * Q3 + q] * a1 + G[g12 * Q3 + q] * a2;
      g2[q] = G[g02 * Q3 + q] * a0 + G[g12 * Q3 + q] * a1 + G[g22 * Q3 + q] * a2;
      uq[q] = (mass_coefficient * G[wdetj * Q3 + q]) * uq[q];
    }
    gradient_transpose_add<Q>(b.Dq, g0, g1, g2, uq);
    integrate<N, Q, false>(b.B, uq, u, t1, t2);
    scatter_add<Constrained, N3>(dofs, e, u, y);
  });
}

// Diagonal of the element matrices by sum factorization of the squared 1D factors:
//   diag(i,j,k) = sum_q sum_rs G_rs(q) dphi_r dphi_s + m w det J phi^2,
// where each term is a product of 1D factors (B^2, D^2 or B D) along x, y and z.
template <class V, class T, int N>
void add_volume_diagonal(const HexElements<T>& el, T mass_coefficient, const View1<V>& diag) {
  constexpr int Q = N, N3 = N * N * N, Q3 = Q * Q * Q;
  const HexBasis<T, N, Q> b = make_hex_basis<T, N, Q>();
  SquaredFactors<T, N, Q> s{};
  for (int q = 0; q < Q; ++q)
    for (int i = 0; i < N; ++i) {
      s.BB[q][i] = b.B[q][i] * b.B[q][i];
      s.DD[q][i] = b.D[q][i] * b.D[q][i];
      s.BD[q][i] = b.B[q][i] * b.D[q][i];
    }
  const auto dofs = el.dofs;
  const auto geo = el.geometry;
  parallel_for_colors("polymech::fem::helmholtz_diagonal", el, KOKKOS_LAMBDA(const Index e) {
    T d[N3], f[Q3], t1[Q * Q * N], t2[Q * Q * N];
    for (int a = 0; a < N3; ++a) d[a] = T(0);
    const T* G = &geo(e, 0);
    // one term: coefficient field f at the points, 1D factors X, Y, Z along x, y, z
    auto term = [&](int component, T factor, const T(&X)[Q][N], const T(&Y)[Q][N], const T(&Z)[Q][N]) {
      for (int q = 0; q < Q3; ++q) f[q] = factor * G[component * Q3 + q];
      contract<2, Q, N, Q, Q, Q, true, false>(Z, f, t1);
      contract<1, Q, N, Q, Q, N, true, false>(Y, t1, t2);
      contract<0, Q, N, Q, N, N, true, true>(X, t2, d);
    };
    term(g00, T(1), s.DD, s.BB, s.BB);
    term(g11, T(1), s.BB, s.DD, s.BB);
    term(g22, T(1), s.BB, s.BB, s.DD);
    term(g01, T(2), s.BD, s.BD, s.BB);
    term(g02, T(2), s.BD, s.BB, s.BD);
    term(g12, T(2), s.BB, s.BD, s.BD);
    term(wdetj, mass_coefficient, s.BB, s.BB, s.BB);
    V dv[N3];
    for (int a = 0; a < N3; ++a) dv[a] = V(d[a]);
    scatter_add<true, N3>(dofs, e, dv, diag);
  });
}

}  // namespace detail

// y += (A + m M) x on the free DoFs (constrained DoFs read as zero and receive nothing). y is not
// cleared: the caller zeroes it once and adds the boundary terms.
template <class V, class T>
void apply_helmholtz_volume(const HexElements<T>& el, T mass_coefficient, const View1<V>& x, const View1<V>& y) {
  with_nodes(el.order, [&](auto n) {
    detail::apply_volume<V, T, decltype(n)::value, true>("polymech::fem::helmholtz_apply", el, mass_coefficient, x, y);
  });
}

// y += (A + m M) x over every DoF, constrained ones included: the Dirichlet lifting K g.
template <class V, class T>
void apply_helmholtz_volume_unconstrained(const HexElements<T>& el, T mass_coefficient, const View1<V>& x,
                                          const View1<V>& y) {
  with_nodes(el.order, [&](auto n) {
    detail::apply_volume<V, T, decltype(n)::value, false>("polymech::fem::dirichlet_lift", el, mass_coefficient, x, y);
  });
}

// diag += diagonal of (A + m M) on the free DoFs, without forming the matrix.
template <class V, class T>
void add_helmholtz_volume_diagonal(const HexElements<T>& el, T mass_coefficient, const View1<V>& diag) {
  with_nodes(el.order, [&](auto n) { detail::add_volume_diagonal<V, T, decltype(n)::value>(el, mass_coefficient, diag); });
}

}  // namespace polymech::fem
