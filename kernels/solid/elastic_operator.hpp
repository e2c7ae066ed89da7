// Matrix-free small-strain solid operator (issue 34): for the weak form
//   find u:  int_Omega eps(v) : sigma(eps(u)) dOmega = int_Omega v . b dOmega + int_Gamma_t v . t dGamma  for all v,
// the internal force f_int(u)_a,c = int dN_a/dx_j sigma_cj dOmega (sigma = C eps for linear elasticity, eps
// the symmetric gradient, Voigt convention of kernels/materials/voigt.hpp), element by element with sum
// factorization: gather each component's nodal values, interpolate to the Q^D Gauss points and take the
// reference gradient by collocation (the scalar operator's 1D even-odd kernels, fem::detail::VolumeKernels),
//   grad u = grad_ref u J^-1,   sigma = law(eps(grad u)),   f_ref(c, r) = w det J sum_j sigma_cj J^-1_rj,
// and integrate back with the transposes (Dq^T, then B^T), scattering D components per node. Work per element
// O(D^2 N^(D+1)) plus O(D^2 S) per point; no matrix is formed.
//
// Batched across elements as the scalar operator (fem::helmholtz_operator.hpp): every value a Lanes<T, E>
// with E elements in the lanes (one SIMD register of T; one element per thread on a GPU), elements in
// chunks by colour (fem::parallel_for_batches), so the scatter needs no atomics and the result does not
// depend on the thread count. The law is a template parameter (solid/laws.hpp): the linear operator K x,
// a tangent apply and a nonlinear residual are the same kernel.
//
// Dirichlet conditions: Constrained = true reads constrained components as zero and adds nothing to them
// (the operator on the free DoFs); ElasticOperator puts identity rows on them, so the constrained system is
// symmetric positive definite and CG applies (the data enter as the lifting f - K g).
#pragma once

#include <stdexcept>
#include <string>

#include "fem/dirichlet.hpp"
#include "solvers/vector_ops.hpp"
#include "solid/laws.hpp"

namespace polymech::solid {

// Elements per batch of the solid kernels for precision T: one SIMD register of T (real components).
template <class T>
inline constexpr int solid_batch() {
  return fem::default_batch<T, 1>();
}

namespace detail {

// out (+)= M in along direction Dir of an N^D array (Q = N).
template <int D, int N, int Dir, bool Add, class EO, class P>
KOKKOS_FORCEINLINE_FUNCTION void sweep(const EO& m, const P* in, P* out) {
  fem::contract_even_odd<Dir, N, N, D == 3 ? N : 1, Add>(m, in, out);
}

// Values at the points from the nodal values in a (a is overwritten); returns where they are (a or t).
template <int D, int N, class K, class P>
KOKKOS_FORCEINLINE_FUNCTION P* values_at_points(const K& k, P* a, P* t) {
  sweep<D, N, 0, false>(k.B, a, t);
  sweep<D, N, 1, false>(k.B, t, a);
  if constexpr (D == 2) {
    return a;
  } else {
    sweep<D, N, 2, false>(k.B, a, t);
    return t;
  }
}

// Nodal values from the weighted values at the points in a (a is overwritten): B^T along every direction.
template <int D, int N, class K, class P>
KOKKOS_FORCEINLINE_FUNCTION P* integrate_points(const K& k, P* a, P* t) {
  sweep<D, N, 1, false>(k.Bt, a, t);
  sweep<D, N, 0, false>(k.Bt, t, a);
  if constexpr (D == 2) {
    return a;
  } else {
    sweep<D, N, 2, false>(k.Bt, a, t);
    return t;
  }
}

// u[a] = component c of x at node a of the batch's elements (lanes). Constrained: constrained components
// read as zero. A partial batch's missing lanes repeat element e0 (fem::detail::lane_element).
template <bool Constrained, int D, int Count, int E, class Mask, class X, class P>
KOKKOS_FORCEINLINE_FUNCTION void gather_component(const Index* const (&idx)[E], const Mask& mask, int c, const X& x,
                                                  P* u) {
  using V = typename X::non_const_value_type;
  for (int a = 0; a < Count; ++a) {
    P v;
    for (int l = 0; l < E; ++l) {
      const Index d = idx[l][a];
      const Index node = fem::decode_dof(d);
      V xv = x(D * node + c);
      if (Constrained && d < 0 && ((mask(node) >> c) & 1)) xv = V(0);
      v.set(l, xv);
    }
    u[a] = v;
  }
}

// y += component c of u at the batch's nodes, lane after lane (elements of a batch may share nodes).
template <bool Constrained, int D, int Count, int E, class Mask, class Y, class P>
KOKKOS_FORCEINLINE_FUNCTION void scatter_component(const Index* const (&idx)[E], const Mask& mask, int c, const P* u,
                                                   const Y& y) {
  using V = typename Y::non_const_value_type;
  for (int a = 0; a < Count; ++a)
    for (int l = 0; l < E; ++l) {
      const Index d = idx[l][a];
      const Index node = fem::decode_dof(d);
      V v = u[a].get(l);
      if (Constrained && d < 0 && ((mask(node) >> c) & 1)) v = V(0);
      y(D * node + c) += v;
    }
}

// At point q: the reference gradients g[c][r][q] of the displacement become the weighted reference fluxes
// w det J sum_j sigma_cj J^-1_rj (in place); Ji = J^-1, wdet = w det J of the batch's lanes.
template <int D, int QD, class LawBatch, class P>
KOKKOS_FORCEINLINE_FUNCTION void point_stress(const LawBatch& law, int q, const P (&Ji)[D][D], const P& wdet,
                                              P (&g)[D][D][QD]) {
  constexpr int S = strain_components<D>;
  P H[D][D];  // du_c / dx_j
  for (int c = 0; c < D; ++c)
    for (int j = 0; j < D; ++j) {
      P s = g[c][0][q] * Ji[0][j];
      for (int r = 1; r < D; ++r) s += g[c][r][q] * Ji[r][j];
      H[c][j] = s;
    }
  P eps[S], sig[S];
  voigt_strain<D>(H, eps);
  law.stress(q, eps, sig);
  for (int c = 0; c < D; ++c) {
    P ws[D];
    for (int j = 0; j < D; ++j) ws[j] = wdet * sig[pair_index<D>(c, j)];
    for (int r = 0; r < D; ++r) {
      P s = ws[0] * Ji[r][0];
      for (int j = 1; j < D; ++j) s += ws[j] * Ji[r][j];
      g[c][r][q] = s;
    }
  }
}

template <class T, int D, int N, int E, bool Constrained, class Law>
void apply_batches(const char* label, const SolidElements<T, D>& el, const Law& law, const View1<T>& x,
                   const View1<T>& y) {
  constexpr int Q = N, ND = power<D>(N), QD = power<D>(Q);
  using P = fem::Lanes<T, E>;
  using K = fem::detail::VolumeKernels<T, N, true>;
  if (el.cells.batch != E)
    throw std::invalid_argument("solid: the elements are stored in batches of " + std::to_string(el.cells.batch) +
                                ", the kernel was compiled for " + std::to_string(E));
  const K k;
  const auto dofs = el.cells.dofs;
  const auto mask = el.fixed_mask;
  const GeometryViews<T, D> geo(el);
  fem::parallel_for_batches(label, el.cells, KOKKOS_LAMBDA(const Index e0, const int count, const int next) {
    P a[ND], t[ND], g[D][D][QD];
    const Index* idx[E];
    for (int l = 0; l < E; ++l) idx[l] = &dofs(fem::detail::lane_element<E>(e0, count, l), 0);
    for (int c = 0; c < D; ++c) {
      gather_component<Constrained, D, ND, E>(idx, mask, c, x, a);
      const P* uq = values_at_points<D, N>(k, a, t);
      for (int r = 0; r < D; ++r) {
        if (r == 0) sweep<D, N, 0, false>(k.D, uq, g[c][0]);
        if (r == 1) sweep<D, N, 1, false>(k.D, uq, g[c][1]);
        if constexpr (D == 3)
          if (r == 2) sweep<D, N, 2, false>(k.D, uq, g[c][2]);
      }
    }
    for (int l = 0; l < E && l < next; ++l)  // the next batch's nodes (fem::detail::prefetch_batch)
      for (int n = 0; n < ND; n += 2) {
        const Index node = fem::decode_dof(dofs(e0 + E + l, n));
        fem::prefetch(&x(D * node));
        fem::prefetch<true>(&y(D * node));
      }
    const auto lb = law.template batch<D, E, P>(e0, count);
    const Index row = geo.slot(e0);
    if (row < 0) {  // affine: J^-1 and det J of each element, the weight of each point
      P Ji[D][D];
      for (int r = 0; r < D; ++r)
        for (int j = 0; j < D; ++j)
          Ji[r][j] = fem::detail::element_lanes<E, 1, P>(count, [&](int l) { return geo.affine(e0 + l, D * r + j); });
      const P det = fem::detail::element_lanes<E, 1, P>(count, [&](int l) { return geo.affine(e0 + l, D * D); });
      for (int q = 0; q < QD; ++q) {
        T wq = k.w[q % Q] * k.w[(q / Q) % Q];
        if constexpr (D == 3) wq *= k.w[q / (Q * Q)];
        point_stress<D, QD>(lb, q, Ji, wq * det, g);
      }
    } else {
      const T* Gp = &geo.geometry(row, 0);
      for (int q = 0; q < QD; ++q) {
        P Ji[D][D];
        for (int r = 0; r < D; ++r)
          for (int j = 0; j < D; ++j)
            Ji[r][j] = fem::detail::element_lanes<E, 1, P>(E, [&](int l) { return Gp[((D * r + j) * QD + q) * E + l]; });
        const P wdet = fem::detail::element_lanes<E, 1, P>(E, [&](int l) { return Gp[(D * D * QD + q) * E + l]; });
        point_stress<D, QD>(lb, q, Ji, wdet, g);
      }
    }
    for (int c = 0; c < D; ++c) {
      sweep<D, N, 0, false>(k.Dt, g[c][0], a);
      sweep<D, N, 1, true>(k.Dt, g[c][1], a);
      if constexpr (D == 3) sweep<D, N, 2, true>(k.Dt, g[c][2], a);
      const P* r = integrate_points<D, N>(k, a, t);
      scatter_component<Constrained, D, ND, E>(idx, mask, c, r, y);
    }
  });
}

// Squared 1D factors of the diagonal: B^2, D^2 and B D at the points ([Q][N]).
template <class T, int N>
struct DiagonalFactors {
  T BB[N][N], DD[N][N], BD[N][N];
};

// diag(a, c) += sum_q sum_rs G^c_rs(q) dN_a/dxi_r dN_a/dxi_s with G^c_rs = w det J sum_jl J^-1_rj C_cjcl J^-1_sl
// (the energy of u = N_a e_c), each term a product of 1D factors (B^2, D^2 or B D) per direction, summed by
// sum factorization. Element by element (set-up only); constrained components receive nothing.
template <class T, int D, int N>
void add_diagonal(const SolidElements<T, D>& el, const View1<T>& diag) {
  constexpr int Q = N, ND = power<D>(N), QD = power<D>(Q), S = strain_components<D>;
  const fem::HexBasis<T, N, Q> b = fem::make_hex_basis<T, N, Q>();
  DiagonalFactors<T, N> f{};
  for (int q = 0; q < Q; ++q)
    for (int i = 0; i < N; ++i) {
      f.BB[q][i] = b.B[q][i] * b.B[q][i];
      f.DD[q][i] = b.D[q][i] * b.D[q][i];
      f.BD[q][i] = b.B[q][i] * b.D[q][i];
    }
  const auto dofs = el.cells.dofs;
  const auto mask = el.fixed_mask;
  const auto material = el.material;
  const GeometryViews<T, D> geo(el);
  const char* label = "polymech::solid::elastic_diagonal";
  fem::parallel_for_batches(label, el.cells, KOKKOS_LAMBDA(const Index e0, const int count, int) {
    const Index row = geo.slot(e0);
    for (int l = 0; l < count; ++l) {
      const Index e = e0 + l;
      T C[S][S];
      for (int i = 0; i < S; ++i)
        for (int j = 0; j < S; ++j) C[i][j] = material(e, 6 * voigt_component<D>(i) + voigt_component<D>(j));
      for (int c = 0; c < D; ++c) {
        T d[ND], fq[D][D][QD], t1[ND], t2[ND];
        for (int a = 0; a < ND; ++a) d[a] = T(0);
        for (int q = 0; q < QD; ++q) {
          T Ji[D][D];
          const T wdet = geo.template at<Q>(row, e0, l, q, b.w, Ji);
          for (int r = 0; r < D; ++r)
            for (int s = 0; s < D; ++s) {
              T sum = T(0);
              for (int j = 0; j < D; ++j)
                for (int m = 0; m < D; ++m) sum += Ji[r][j] * C[pair_index<D>(c, j)][pair_index<D>(c, m)] * Ji[s][m];
              fq[r][s][q] = wdet * sum;
            }
        }
        for (int r = 0; r < D; ++r)
          for (int s = r; s < D; ++s) {
            // factor along direction t: D^2 if both derivatives are along t, B D if one is, B^2 if none
            const T(*X[3])[N];
            for (int dir = 0; dir < D; ++dir) X[dir] = (dir == r && dir == s) ? f.DD : (dir == r || dir == s) ? f.BD : f.BB;
            T w[QD];
            for (int q = 0; q < QD; ++q) w[q] = (r == s ? T(1) : T(2)) * fq[r][s][q];
            if constexpr (D == 3) {
              fem::contract<2, Q, N, Q, Q, Q, true, false>(X[2], w, t1);
              fem::contract<1, Q, N, Q, Q, N, true, false>(X[1], t1, t2);
              fem::contract<0, Q, N, Q, N, N, true, true>(X[0], t2, d);
            } else {
              fem::contract<1, Q, N, Q, Q, 1, true, false>(X[1], w, t1);
              fem::contract<0, Q, N, Q, N, 1, true, true>(X[0], t1, d);
            }
          }
        for (int a = 0; a < ND; ++a) {
          const Index dd = dofs(e, a), node = fem::decode_dof(dd);
          if (dd < 0 && ((mask(node) >> c) & 1)) continue;
          diag(D * node + c) += d[a];
        }
      }
    }
  });
}

}  // namespace detail

// y += f_int(x) for a law (solid/laws.hpp); Constrained: the operator on the free DoFs (constrained
// components read as zero and receive nothing), otherwise every DoF (the lifting K g of Dirichlet data).
template <bool Constrained, class T, int D, class Law>
void add_internal_force(const char* label, const SolidElements<T, D>& el, const Law& law, const View1<T>& x,
                        const View1<T>& y) {
  fem::with_nodes(el.order(), [&](auto n) {
    detail::apply_batches<T, D, decltype(n)::value, solid_batch<T>(), Constrained>(label, el, law, x, y);
  });
}

// y += K x of linear elasticity with the elements' stiffness.
template <bool Constrained = true, class T, int D>
void add_elastic_apply(const SolidElements<T, D>& el, const View1<T>& x, const View1<T>& y) {
  add_internal_force<Constrained>(Constrained ? "polymech::solid::elastic_apply" : "polymech::solid::elastic_lift", el,
                                  ElementStiffness<T>{el.material}, x, y);
}

// diag += the diagonal of K on the free DoFs, without forming K.
template <class T, int D>
void add_elastic_diagonal(const SolidElements<T, D>& el, const View1<T>& diag) {
  fem::with_nodes(el.order(), [&](auto n) { detail::add_diagonal<T, D, decltype(n)::value>(el, diag); });
}

// The constrained linear operator for the Krylov solvers (kernels/solvers/krylov.hpp): y = K x on the free
// DoFs and y = x on the constrained ones (identity rows; `constrained` lists those DoFs).
template <class T, int D>
struct ElasticOperator {
  using value_type = T;
  SolidElements<T, D> el;
  View1<Index> constrained;

  Index local_size() const { return el.dof_count(); }
  Index owned_size() const { return el.dof_count(); }
  void apply(const View1<T>& x, const View1<T>& y) const {
    Kokkos::deep_copy(y, T(0));
    add_elastic_apply<true>(el, x, y);
    fem::copy_constrained_rows(constrained, x, y);
  }
  // Jacobi: the inverse diagonal, 1 on the constrained rows.
  View1<T> inverse_diagonal() const {
    View1<T> d("polymech::solid::diagonal", el.dof_count()), inv("polymech::solid::inverse_diagonal", el.dof_count());
    add_elastic_diagonal(el, d);
    fem::fill_constrained(constrained, T(1), d);
    const solvers::DiagonalSummary s = solvers::jacobi_inverse(el.dof_count(), el.dof_count(), d, inv);
    if (!(s.min_abs > 0.0) || s.non_finite > 0)
      throw std::runtime_error("solid: the stiffness diagonal vanishes or is not finite at DoF " + std::to_string(s.argmin) +
                               " (a DoF no element or law stiffens)");
    return inv;
  }
};

}  // namespace polymech::solid
