// Matrix-free volume part of the Helmholtz operator, y += (A + m M) x (seed 002 paper 3 eqs. (16)-(18),
// with m = -k^2), applied element by element with sum factorization: interpolate to the Q^3 points,
// take the reference gradient by collocation, multiply by the geometric factors, and integrate back
// with the transposes. Work per element O(N^4); the global matrix is never formed.
//
// Batched across elements: a kernel works on `batch` elements at once (HexElements), every value a
// Lanes<T, L> with the element index innermost, so that every operation of the sum factorization is
// one SIMD instruction over the batch (L = batch for real fields, 2 batch for complex ones: the
// coefficients of A and M are real, so the real and imaginary parts are two more lanes). The 1D
// kernels use the even-odd decomposition (sum_factorization.hpp). Affine batches take their
// geometric factors from one Jacobian per element (hex_elements.hpp). On a GPU, batch = 1: one element
// per thread.
//
// Values V are T (real problems: CG) or Kokkos::complex<T> (the complex symmetric system: COCG).
#pragma once

#include <type_traits>

#include "fem/hex_elements.hpp"
#include "fem/lanes.hpp"

namespace polymech::fem {

template <class V>
struct FieldTraits {  // a real field: one real per value
  using real_type = V;
  static constexpr int components = 1;
  KOKKOS_FORCEINLINE_FUNCTION static V make(real_type re, real_type) { return re; }
  KOKKOS_FORCEINLINE_FUNCTION static real_type part(const V& v, int) { return v; }
};
template <class T>
struct FieldTraits<Kokkos::complex<T>> {  // real and imaginary part
  using real_type = T;
  static constexpr int components = 2;
  KOKKOS_FORCEINLINE_FUNCTION static Kokkos::complex<T> make(T re, T im) { return Kokkos::complex<T>(re, im); }
  KOKKOS_FORCEINLINE_FUNCTION static T part(const Kokkos::complex<T>& v, int c) { return c == 0 ? v.real() : v.imag(); }
};

// Elements per batch of the volume kernels for precision T (complex fields): one SIMD register.
template <class T>
inline constexpr int volume_batch() {
  return default_batch<T, 2>();
}

namespace detail {

// Lane layout of a batch: lane C l + c holds component c (real, imaginary) of element l of the batch.
// A partial batch (count < E elements) fills its missing lanes with the DoFs of element e0 and zero
// geometric factors: they compute exact zeros and add them to e0's DoFs, so no loop needs the count.
template <int E>
KOKKOS_FORCEINLINE_FUNCTION Index lane_element(Index e0, int count, int l) {
  return e0 + (l < count ? l : 0);
}

// u[a] = x at the DoFs of node a of the batch's elements. Constrained: DoFs under a Dirichlet
// condition read as zero.
template <bool Constrained, int Count, int E, class Map, class X, class P>
KOKKOS_FORCEINLINE_FUNCTION void gather_batch(const Map& map, Index e0, int count, const X& x, P* u) {
  using V = typename X::non_const_value_type;
  using F = FieldTraits<V>;
  const Index* idx[E];
  for (int l = 0; l < E; ++l) idx[l] = &map(lane_element<E>(e0, count, l), 0);
  for (int a = 0; a < Count; ++a) {
    P v;
    for (int l = 0; l < E; ++l) {
      const Index d = idx[l][a];
      V xv = x(decode_dof(d));
      if (Constrained) xv = d < 0 ? V(0) : xv;
      for (int c = 0; c < F::components; ++c) v.set(F::components * l + c, F::part(xv, c));
    }
    u[a] = v;
  }
}

// y += u at the DoFs of the batch's elements (Constrained: nothing is added to DoFs under a Dirichlet
// condition). One thread adds the lanes in turn, so elements of a batch may share DoFs.
template <bool Constrained, int Count, int E, class Map, class Y, class P>
KOKKOS_FORCEINLINE_FUNCTION void scatter_batch(const Map& map, Index e0, int count, const P* u, const Y& y) {
  using V = typename Y::non_const_value_type;
  using F = FieldTraits<V>;
  constexpr int C = F::components;
  const Index* idx[E];
  for (int l = 0; l < E; ++l) idx[l] = &map(lane_element<E>(e0, count, l), 0);
  for (int a = 0; a < Count; ++a)
    for (int l = 0; l < E; ++l) {
      const Index d = idx[l][a];
      V v;
      if constexpr (C > 1)
        v = F::make(u[a].get(C * l), u[a].get(C * l + 1));
      else
        v = u[a].get(l);
      if (Constrained) v = d < 0 ? V(0) : v;
      y(decode_dof(d)) += v;
    }
}

// Prefetch of x and y at the DoFs of the batch that starts at element e0 (count elements). Every
// second node only: neighbouring nodes of an element mostly have consecutive DoF numbers (numbered
// in order of first appearance), so they share cache lines, and fewer prefetch instructions measured
// faster (bench_fem, BM_ApplyStep).
template <int Count, int E, class Map, class X, class Y>
KOKKOS_FORCEINLINE_FUNCTION void prefetch_batch(const Map& map, Index e0, int count, const X& x, const Y& y) {
  for (int l = 0; l < E; ++l) {
    if (l >= count) break;
    for (int a = 0; a < Count; a += 2) {
      const Index d = decode_dof(map(e0 + l, a));
      prefetch(&x(d));
      prefetch<true>(&y(d));
    }
  }
}

// The batch's value of a per-element quantity f(l) in the C lanes of element l (zero in the lanes of
// a partial batch's missing elements).
template <int E, int C, class P, class F>
KOKKOS_FORCEINLINE_FUNCTION P element_lanes(int count, const F& f) {
  P v;
  for (int l = 0; l < E; ++l) {
    const auto s = l < count ? f(l) : decltype(f(l))(0);
    for (int c = 0; c < C; ++c) v.set(C * l + c, s);
  }
  return v;
}

// What the volume kernel includes; the partial stages exist to measure where the time goes
// (bench_fem, BM_ApplyStages), the operator always runs `full`.
enum class VolumeStage : int {
  gather_scatter = 0,   // gather and scatter only
  interpolation = 1,    // + interpolation to the points and integration back (B, B^T)
  gradients = 2,        // + collocation gradient and its transpose (Dq, Dq^T), no geometry
  full = 3,             // + the geometric factors at the points: the operator
};

// The 1D kernels of one order in the form the batched kernel uses: even-odd (EvenOddKernels = true)
// or the full matrices. Besides the quadrature kernels (B, Dq and their transposes), the 1D element
// matrices of the Kronecker form for rectilinear elements: mass M_ij = sum_q w_q l_i(x_q) l_j(x_q) and
// stiffness A_ij = sum_q w_q l_i'(x_q) l_j'(x_q) (exact with Q = N Gauss points).
template <class T, int N, bool EvenOddKernels>
struct VolumeKernels {
  static constexpr int Q = N;
  HexBasis<T, N, Q> b;
  T mass1[N][N], stiff1[N][N];
  EvenOdd<T, Q, N, 1> B;    // values at the points
  EvenOdd<T, N, Q, 1> Bt;   // integration
  EvenOdd<T, Q, Q, -1> D;   // collocation derivative
  EvenOdd<T, Q, Q, -1> Dt;  // its transpose
  EvenOdd<T, N, N, 1> M1, A1;
  T w[Q];

  VolumeKernels() : b(make_hex_basis<T, N, Q>()) {
    const HexBasis<double, N, Q> bd = make_hex_basis<double, N, Q>();
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) {
        double m = 0, a = 0;
        for (int q = 0; q < Q; ++q) {
          m += bd.w[q] * bd.B[q][i] * bd.B[q][j];
          a += bd.w[q] * bd.D[q][i] * bd.D[q][j];
        }
        mass1[i][j] = static_cast<T>(m);
        stiff1[i][j] = static_cast<T>(a);
      }
    B = make_even_odd<Q, N, 1, false, T>(b.B);
    Bt = make_even_odd<N, Q, 1, true, T>(b.B);
    D = make_even_odd<Q, Q, -1, false, T>(b.Dq);
    Dt = make_even_odd<Q, Q, -1, true, T>(b.Dq);
    M1 = make_even_odd<N, N, 1, false, T>(mass1);
    A1 = make_even_odd<N, N, 1, false, T>(stiff1);
    for (int q = 0; q < Q; ++q) w[q] = b.w[q];
  }

  // out (+)= M in along direction Dir of an N^3 (= Q^3) array, M one of the 1D matrices.
  enum Matrix { values, integration, derivative, derivative_transpose, mass, stiffness };
  template <Matrix Which, int Dir, bool Add, class P>
  KOKKOS_FORCEINLINE_FUNCTION void sweep(const P* in, P* out) const {
    if constexpr (EvenOddKernels) {
      if constexpr (Which == values)
        contract_even_odd<Dir, N, N, N, Add>(B, in, out);
      else if constexpr (Which == integration)
        contract_even_odd<Dir, N, N, N, Add>(Bt, in, out);
      else if constexpr (Which == derivative)
        contract_even_odd<Dir, N, N, N, Add>(D, in, out);
      else if constexpr (Which == derivative_transpose)
        contract_even_odd<Dir, N, N, N, Add>(Dt, in, out);
      else if constexpr (Which == mass)
        contract_even_odd<Dir, N, N, N, Add>(M1, in, out);
      else
        contract_even_odd<Dir, N, N, N, Add>(A1, in, out);
    } else {
      if constexpr (Which == values || Which == integration)
        contract<Dir, N, N, N, N, N, Which == integration, Add>(b.B, in, out);
      else if constexpr (Which == derivative || Which == derivative_transpose)
        contract<Dir, N, N, N, N, N, Which == derivative_transpose, Add>(b.Dq, in, out);
      else if constexpr (Which == mass)
        contract<Dir, N, N, N, N, N, false, Add>(mass1, in, out);
      else
        contract<Dir, N, N, N, N, N, false, Add>(stiff1, in, out);
    }
  }
};

// The quadrature path of one batch (seed 002 paper 3 eqs. (17), (18), (24), (25)): u (nodal values) ->
// values and reference gradients at the points, times the geometric factors, integrated back into u.
// `row`: the batch's geometry (affine_slot: one Jacobian per element; >= 0: factors per point).
template <class K, int E, int C, VolumeStage Stage, class T, class P>
KOKKOS_FORCEINLINE_FUNCTION void quadrature_batch(const K& k, const GeometryViews<T>& geo, Index row, Index e0,
                                                  int count, T m, P* u, P* uq, P* g0, P* g1, P* g2) {
  constexpr int Q = K::Q, Q3 = Q * Q * Q;
  // t1, t2 of the interpolation / integration share storage with g0, g1
  k.template sweep<K::values, 0, false>(u, g0);
  k.template sweep<K::values, 1, false>(g0, g1);
  k.template sweep<K::values, 2, false>(g1, uq);
  if (Stage != VolumeStage::interpolation) {
    k.template sweep<K::derivative, 0, false>(uq, g0);
    k.template sweep<K::derivative, 1, false>(uq, g1);
    k.template sweep<K::derivative, 2, false>(uq, g2);
    if (Stage == VolumeStage::full && row < 0) {
      // affine: G(q) = w_q G_e, w det J (q) = w_q det J_e
      P G[geometry_components];
      for (int c = 0; c < geometry_components; ++c)
        G[c] = element_lanes<E, C, P>(count, [&](int l) { return geo.affine(e0 + l, c); });
      const P mass = m * G[wdetj];
      for (int q = 0; q < Q3; ++q) {
        const T wq = k.w[q % Q] * k.w[(q / Q) % Q] * k.w[q / (Q * Q)];
        const P a0 = wq * g0[q], a1 = wq * g1[q], a2 = wq * g2[q];
        g0[q] = G[g00] * a0 + G[g01] * a1 + G[g02] * a2;
        g1[q] = G[g01] * a0 + G[g11] * a1 + G[g12] * a2;
        g2[q] = G[g02] * a0 + G[g12] * a1 + G[g22] * a2;
        uq[q] = (wq * mass) * uq[q];
      }
    } else if (Stage == VolumeStage::full) {
      const T* Gp = &geo.geometry(row, 0);
      for (int q = 0; q < Q3; ++q) {
        P G[geometry_components];
        for (int c = 0; c < geometry_components; ++c)
          G[c] = element_lanes<E, C, P>(E, [&](int l) { return Gp[(c * Q3 + q) * E + l]; });
        const P a0 = g0[q], a1 = g1[q], a2 = g2[q];
        g0[q] = G[g00] * a0 + G[g01] * a1 + G[g02] * a2;
        g1[q] = G[g01] * a0 + G[g11] * a1 + G[g12] * a2;
        g2[q] = G[g02] * a0 + G[g12] * a1 + G[g22] * a2;
        uq[q] = (m * G[wdetj]) * uq[q];
      }
    }
    k.template sweep<K::derivative_transpose, 0, true>(g0, uq);
    k.template sweep<K::derivative_transpose, 1, true>(g1, uq);
    k.template sweep<K::derivative_transpose, 2, true>(g2, uq);
  }
  k.template sweep<K::integration, 2, false>(uq, g0);
  k.template sweep<K::integration, 1, false>(g0, g1);
  k.template sweep<K::integration, 0, false>(g1, u);
}

// The Kronecker path of a rectilinear batch: with G diagonal and constant, the element matrix is
//   K_e = G_xx Mz (x) My (x) Ax + G_yy Mz (x) Ay (x) Mx + G_zz Az (x) My (x) Mx + m det J Mz (x) My (x) Mx
// (G = det J J^-1 J^-T, 1D mass M and stiffness A), applied to the nodal values u as
//   a = Mx u;  v = My (G_xx Ax u + m det J a) + Ay (G_yy a);  u = Mz v + Az (G_zz My a),
// seven 1D sweeps instead of twelve and no work at the points.
template <class K, int N, int E, int C, class T, class P>
KOKKOS_FORCEINLINE_FUNCTION void rectilinear_batch(const K& k, const GeometryViews<T>& geo, Index e0, int count, T m,
                                                   P* u, P* a, P* b, P* v, P* s) {
  constexpr int N3 = N * N * N;
  const P gx = element_lanes<E, C, P>(count, [&](int l) { return geo.affine(e0 + l, g00); });
  const P gy = element_lanes<E, C, P>(count, [&](int l) { return geo.affine(e0 + l, g11); });
  const P gz = element_lanes<E, C, P>(count, [&](int l) { return geo.affine(e0 + l, g22); });
  const P mdet = m * element_lanes<E, C, P>(count, [&](int l) { return geo.affine(e0 + l, wdetj); });
  k.template sweep<K::mass, 0, false>(u, a);
  k.template sweep<K::stiffness, 0, false>(u, b);
  for (int i = 0; i < N3; ++i) {
    b[i] = gx * b[i] + mdet * a[i];
    s[i] = gy * a[i];
  }
  k.template sweep<K::mass, 1, false>(b, v);
  k.template sweep<K::stiffness, 1, true>(s, v);
  k.template sweep<K::mass, 1, false>(a, b);
  for (int i = 0; i < N3; ++i) s[i] = gz * b[i];
  k.template sweep<K::mass, 2, false>(v, u);
  k.template sweep<K::stiffness, 2, true>(s, u);
}

// y += (A + m M) x for the batches of el (batch size E = el.batch), V = T or Kokkos::complex<T>.
// Constrained = true: DoFs under a strong Dirichlet condition (negative entries) count as zero on
// input and receive nothing (the operator on the free DoFs). false: every DoF takes part (the lifting
// of Dirichlet data, K g). Rectilinear batches take the Kronecker path unless Kronecker = false.
template <class V, class T, int N, int E, bool Constrained, bool EvenOddKernels = true,
          VolumeStage Stage = VolumeStage::full, bool Prefetch = true, bool Kronecker = true>
void apply_volume(const char* label, const HexElements<T>& el, T mass_coefficient, const View1<V>& x,
                  const View1<V>& y) {
  constexpr int N3 = N * N * N, C = FieldTraits<V>::components;
  using P = Lanes<T, C * E>;
  using K = VolumeKernels<T, N, EvenOddKernels>;
  if (el.batch != E)
    throw std::invalid_argument("fem: the elements are stored in batches of " + std::to_string(el.batch) +
                                ", the kernel was compiled for " + std::to_string(E));
  const K k;
  const auto dofs = el.dofs;
  const GeometryViews<T> geo(el);
  const T m = mass_coefficient;
  parallel_for_batches(label, el, KOKKOS_LAMBDA(const Index e0, const int count, const int next) {
    P u[N3], uq[N3], g0[N3], g1[N3], g2[N3];
    gather_batch<Constrained, N3, E>(dofs, e0, count, x, u);
    if (Prefetch) prefetch_batch<N3, E>(dofs, e0 + E, next, x, y);
    if (Stage != VolumeStage::gather_scatter) {
      const Index row = geo.slot(e0);
      if (Kronecker && Stage == VolumeStage::full && row == rectilinear_slot)
        rectilinear_batch<K, N, E, C>(k, geo, e0, count, m, u, uq, g0, g1, g2);
      else
        quadrature_batch<K, E, C, Stage>(k, geo, row < 0 ? affine_slot : row, e0, count, m, u, uq, g0, g1, g2);
    }
    scatter_batch<Constrained, N3, E>(dofs, e0, count, u, y);
  });
}

// Squared 1D factors for the diagonal: B^2, D^2 and B D at the points.
template <class T, int N, int Q>
struct SquaredFactors {
  T BB[Q][N], DD[Q][N], BD[Q][N];
};

// Diagonal of the element matrices by sum factorization of the squared 1D factors:
//   diag(i,j,k) = sum_q sum_rs G_rs(q) dphi_r dphi_s + m w det J phi^2,
// where each term is a product of 1D factors (B^2, D^2 or B D) along x, y and z. Element by element
// (set-up only).
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
  const GeometryViews<T> geo(el);
  parallel_for_batches("polymech::fem::helmholtz_diagonal", el, KOKKOS_LAMBDA(const Index e0, const int count, int) {
    const Index row = geo.slot(e0);
    for (int l = 0; l < count; ++l) {
      const Index e = e0 + l;
      T d[N3], f[Q3], t1[Q * Q * N], t2[Q * Q * N];
      for (int a = 0; a < N3; ++a) d[a] = T(0);
      // one term: coefficient field f at the points, 1D factors X, Y, Z along x, y, z
      auto term = [&](int component, T factor, const T(&X)[Q][N], const T(&Y)[Q][N], const T(&Z)[Q][N]) {
        for (int q = 0; q < Q3; ++q) f[q] = factor * geo.template at<Q>(row, e0, l, component, q, b.w);
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
    }
  });
}

// The volume kernel of order N - 1 in the production configuration (batch volume_batch<T>()).
template <class V, class T, bool Constrained>
void apply_volume_of_order(const char* label, const HexElements<T>& el, T m, const View1<V>& x, const View1<V>& y) {
  with_nodes(el.order, [&](auto n) {
    apply_volume<V, T, decltype(n)::value, volume_batch<T>(), Constrained>(label, el, m, x, y);
  });
}

}  // namespace detail

// y += (A + m M) x on the free DoFs (constrained DoFs read as zero and receive nothing). y is not
// cleared: the caller zeroes it once and adds the boundary terms.
template <class V, class T>
void apply_helmholtz_volume(const HexElements<T>& el, T mass_coefficient, const View1<V>& x, const View1<V>& y) {
  detail::apply_volume_of_order<V, T, true>("polymech::fem::helmholtz_apply", el, mass_coefficient, x, y);
}

// y += (A + m M) x over every DoF, constrained ones included: the Dirichlet lifting K g.
template <class V, class T>
void apply_helmholtz_volume_unconstrained(const HexElements<T>& el, T mass_coefficient, const View1<V>& x,
                                          const View1<V>& y) {
  detail::apply_volume_of_order<V, T, false>("polymech::fem::dirichlet_lift", el, mass_coefficient, x, y);
}

// diag += diagonal of (A + m M) on the free DoFs, without forming the matrix.
template <class V, class T>
void add_helmholtz_volume_diagonal(const HexElements<T>& el, T mass_coefficient, const View1<V>& diag) {
  with_nodes(el.order, [&](auto n) { detail::add_volume_diagonal<V, T, decltype(n)::value>(el, mass_coefficient, diag); });
}

}  // namespace polymech::fem
