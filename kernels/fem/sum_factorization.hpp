// Sum factorization: a tensor-product operator M (x) M (x) M applied to an element's n^3 values as three
// sweeps of the 1D matrix, O(n^4) instead of O(n^6) work per element. The element arrays are small
// local arrays, x fastest: u[i + E0 * (j + E1 * k)].
#pragma once

#include "core/kokkos_shim.hpp"

namespace polymech::fem {

namespace detail {
template <bool Transpose, class Mat>
KOKKOS_FORCEINLINE_FUNCTION auto matrix_entry(const Mat& M, int a, int b) {
  if constexpr (Transpose)
    return M[b][a];
  else
    return M[a][b];
}
}  // namespace detail

// out = M u along dimension Dir of a 3D array with extents (E0, E1, E2), E_Dir = NIn:
//   Transpose = false: M is [NOut][NIn], out(a) = sum_b M[a][b] in(b)
//   Transpose = true:  M is [NIn][NOut], out(a) = sum_b M[b][a] in(b)
// The extent along Dir becomes NOut. Add = true accumulates into out.
template <int Dir, int NIn, int NOut, int E0, int E1, int E2, bool Transpose, bool Add, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void contract(const Mat& M, const V* in, V* out) {
  static_assert(Dir >= 0 && Dir <= 2, "Dir is 0 (x), 1 (y) or 2 (z)");
  if constexpr (Dir == 0) {
    static_assert(E0 == NIn, "extent along x must be NIn");
    for (int jk = 0; jk < E1 * E2; ++jk) {
      const V* src = in + NIn * jk;
      V* dst = out + NOut * jk;
      for (int a = 0; a < NOut; ++a) {
        V s = detail::matrix_entry<Transpose>(M, a, 0) * src[0];
        for (int b = 1; b < NIn; ++b) s += detail::matrix_entry<Transpose>(M, a, b) * src[b];
        if (Add)
          dst[a] += s;
        else
          dst[a] = s;
      }
    }
  } else if constexpr (Dir == 1) {
    static_assert(E1 == NIn, "extent along y must be NIn");
    for (int k = 0; k < E2; ++k)
      for (int a = 0; a < NOut; ++a) {
        V* dst = out + E0 * (a + NOut * k);
        for (int i = 0; i < E0; ++i) {
          V s = detail::matrix_entry<Transpose>(M, a, 0) * in[i + E0 * NIn * k];
          for (int b = 1; b < NIn; ++b) s += detail::matrix_entry<Transpose>(M, a, b) * in[i + E0 * (b + NIn * k)];
          if (Add)
            dst[i] += s;
          else
            dst[i] = s;
        }
      }
  } else {
    static_assert(E2 == NIn, "extent along z must be NIn");
    constexpr int plane = E0 * E1;
    for (int a = 0; a < NOut; ++a) {
      V* dst = out + plane * a;
      for (int ij = 0; ij < plane; ++ij) {
        V s = detail::matrix_entry<Transpose>(M, a, 0) * in[ij];
        for (int b = 1; b < NIn; ++b) s += detail::matrix_entry<Transpose>(M, a, b) * in[ij + plane * b];
        if (Add)
          dst[ij] += s;
        else
          dst[ij] = s;
      }
    }
  }
}

// Values at the Q^3 points from the N^3 nodal values: (B (x) B (x) B) u. tmp holds Q * N * N.
template <int N, int Q, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void interpolate(const Mat& B, const V* u, V* uq, V* tmp1, V* tmp2) {
  contract<0, N, Q, N, N, N, false, false>(B, u, tmp1);
  contract<1, N, Q, Q, N, N, false, false>(B, tmp1, tmp2);
  contract<2, N, Q, Q, Q, N, false, false>(B, tmp2, uq);
}

// The transpose: nodal values from values at the points, (B^T (x) B^T (x) B^T) vq (integration
// against every basis function once the quadrature weights are in vq).
template <int N, int Q, bool Add, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void integrate(const Mat& B, const V* vq, V* v, V* tmp1, V* tmp2) {
  contract<2, Q, N, Q, Q, Q, true, false>(B, vq, tmp1);
  contract<1, Q, N, Q, Q, N, true, false>(B, tmp1, tmp2);
  contract<0, Q, N, Q, N, N, true, Add>(B, tmp2, v);
}

// Reference gradient at the points from values at the points (collocation derivative Dq, exact for
// the interpolant of the element's polynomial): g0 = d/dxi, g1 = d/deta, g2 = d/dzeta.
template <int Q, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void gradient_at_points(const Mat& Dq, const V* uq, V* g0, V* g1, V* g2) {
  contract<0, Q, Q, Q, Q, Q, false, false>(Dq, uq, g0);
  contract<1, Q, Q, Q, Q, Q, false, false>(Dq, uq, g1);
  contract<2, Q, Q, Q, Q, Q, false, false>(Dq, uq, g2);
}

// Its transpose, accumulated: vq += Dq^T f0 (x) + Dq^T f1 (y) + Dq^T f2 (z).
template <int Q, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void gradient_transpose_add(const Mat& Dq, const V* f0, const V* f1, const V* f2, V* vq) {
  contract<0, Q, Q, Q, Q, Q, true, true>(Dq, f0, vq);
  contract<1, Q, Q, Q, Q, Q, true, true>(Dq, f1, vq);
  contract<2, Q, Q, Q, Q, Q, true, true>(Dq, f2, vq);
}

// 2D versions on a face (x fastest, extents (E0, E1)), as the 3D ones with E2 = 1.
template <int N, int Q, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void interpolate_2d(const Mat& B, const V* u, V* uq, V* tmp) {
  contract<0, N, Q, N, N, 1, false, false>(B, u, tmp);
  contract<1, N, Q, Q, N, 1, false, false>(B, tmp, uq);
}
template <int N, int Q, class V, class Mat>
KOKKOS_FORCEINLINE_FUNCTION void integrate_2d(const Mat& B, const V* vq, V* v, V* tmp) {
  contract<1, Q, N, Q, Q, 1, true, false>(B, vq, tmp);
  contract<0, Q, N, Q, N, 1, true, false>(B, tmp, v);
}

// ---- Even-odd decomposition of the 1D kernels ------------------------------------------------------
// The 1D matrices of a symmetric rule (GLL nodes and Gauss points symmetric about 0) satisfy
// M[NOut-1-a][NIn-1-b] = S M[a][b] with S = +1 for values (B) and S = -1 for derivatives (Dq). With
// e_b = u_b + u_(NIn-1-b) and o_b = u_b - u_(NIn-1-b), the top half of the output is
//   out_a = E_a + O_a,   out_(NOut-1-a) = S (E_a - O_a),   E = Me e, O = Mo o,
// with half-size matrices Me[a][b] = (M[a][b] + M[a][NIn-1-b]) / 2 and Mo[a][b] = (M[a][b] -
// M[a][NIn-1-b]) / 2 (and the middle column / row of an odd size kept whole): about half the
// multiplications of the full product, the other half replaced by additions, which run on their own
// units on current CPUs.
template <class T, int NOut, int NIn, int S>
struct EvenOdd {
  static_assert(S == 1 || S == -1, "S is +1 (even matrix) or -1 (odd matrix)");
  static constexpr int HO = NOut / 2, HI = NIn / 2, RO = (NOut + 1) / 2, RI = (NIn + 1) / 2;
  T even[RO][RI];
  T odd[RO][HI];
};

// The even-odd form of M ([NOut][NIn]; Transpose: M is [NIn][NOut] and its transpose is used).
template <int NOut, int NIn, int S, bool Transpose, class T, class Mat>
EvenOdd<T, NOut, NIn, S> make_even_odd(const Mat& M) {
  EvenOdd<T, NOut, NIn, S> k{};
  auto m = [&](int a, int b) { return static_cast<T>(detail::matrix_entry<Transpose>(M, a, b)); };
  using K = EvenOdd<T, NOut, NIn, S>;
  for (int a = 0; a < K::RO; ++a) {
    for (int b = 0; b < K::HI; ++b) {
      k.even[a][b] = T(0.5) * (m(a, b) + m(a, NIn - 1 - b));
      k.odd[a][b] = T(0.5) * (m(a, b) - m(a, NIn - 1 - b));
    }
    if (NIn % 2 == 1) k.even[a][K::HI] = m(a, K::HI);
  }
  return k;
}

namespace detail {

// One line: NIn inputs at stride SI -> NOut outputs at stride SO.
template <int SI, int SO, bool Add, class T, int NOut, int NIn, int S, class V>
KOKKOS_FORCEINLINE_FUNCTION void even_odd_line(const EvenOdd<T, NOut, NIn, S>& k, const V* in, V* out) {
  using K = EvenOdd<T, NOut, NIn, S>;
  V e[K::RI], o[K::HI];
  for (int b = 0; b < K::HI; ++b) {
    e[b] = in[SI * b] + in[SI * (NIn - 1 - b)];
    o[b] = in[SI * b] - in[SI * (NIn - 1 - b)];
  }
  if (NIn % 2 == 1) e[K::HI] = in[SI * K::HI];
  for (int a = 0; a < K::HO; ++a) {
    V E = k.even[a][0] * e[0];
    for (int b = 1; b < K::RI; ++b) E += k.even[a][b] * e[b];
    V O = k.odd[a][0] * o[0];
    for (int b = 1; b < K::HI; ++b) O += k.odd[a][b] * o[b];
    const V top = E + O, bottom = S > 0 ? E - O : O - E;
    if (Add) {
      out[SO * a] += top;
      out[SO * (NOut - 1 - a)] += bottom;
    } else {
      out[SO * a] = top;
      out[SO * (NOut - 1 - a)] = bottom;
    }
  }
  if (NOut % 2 == 1) {  // middle row: only the even (S = +1) or the odd (S = -1) part is non-zero
    V m;
    if (S > 0) {
      m = k.even[K::HO][0] * e[0];
      for (int b = 1; b < K::RI; ++b) m += k.even[K::HO][b] * e[b];
    } else {
      m = k.odd[K::HO][0] * o[0];
      for (int b = 1; b < K::HI; ++b) m += k.odd[K::HO][b] * o[b];
    }
    if (Add)
      out[SO * K::HO] += m;
    else
      out[SO * K::HO] = m;
  }
}

}  // namespace detail

// As contract(): out = M in along dimension Dir of a 3D array with extents (E0, E1, E2), E_Dir = NIn,
// by the even-odd form of M.
template <int Dir, int E0, int E1, int E2, bool Add, class T, int NOut, int NIn, int S, class V>
KOKKOS_FORCEINLINE_FUNCTION void contract_even_odd(const EvenOdd<T, NOut, NIn, S>& k, const V* in, V* out) {
  static_assert(Dir >= 0 && Dir <= 2, "Dir is 0 (x), 1 (y) or 2 (z)");
  if constexpr (Dir == 0) {
    static_assert(E0 == NIn, "extent along x must be NIn");
    for (int jk = 0; jk < E1 * E2; ++jk) detail::even_odd_line<1, 1, Add>(k, in + NIn * jk, out + NOut * jk);
  } else if constexpr (Dir == 1) {
    static_assert(E1 == NIn, "extent along y must be NIn");
    for (int kk = 0; kk < E2; ++kk)
      for (int i = 0; i < E0; ++i)
        detail::even_odd_line<E0, E0, Add>(k, in + i + E0 * NIn * kk, out + i + E0 * NOut * kk);
  } else {
    static_assert(E2 == NIn, "extent along z must be NIn");
    for (int ij = 0; ij < E0 * E1; ++ij) detail::even_odd_line<E0 * E1, E0 * E1, Add>(k, in + ij, out + ij);
  }
}

}  // namespace polymech::fem
