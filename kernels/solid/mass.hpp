// Mass of the small-strain solid elements (issue 34, structural dynamics): the consistent mass
//   M[(a, c), (b, d)] = delta_cd  int_Omega rho N_a N_b dOmega
// (the same scalar mass for every displacement component, DoFs interleaved as in solid/elements.hpp) and its
// row-sum lumped (diagonal) form
//   m_a = sum_b int rho N_a N_b = int rho N_a dOmega   (the basis is a partition of unity),
// the "row-sum" lumping of Hughes (The Finite Element Method, 2000, ch. 7). For the tensor-product Lagrange
// bases on GLL nodes with the Q = N Gauss rule, m_a of an affine element is rho det J times the product of
// the 1D GLL quadrature weights of a's indices: positive for every order 1..4 (tests/solid/test_solid_dynamics
// checks it, and that sum_a m_a = rho x volume to round-off).
//
// Three forms:
//  - add_mass_apply<Constrained>: y += M x matrix-free by sum factorization (values at the Q^D Gauss points
//    with B along each direction, times rho w det J, back with B^T): O(D N^(D+1)) per element; element by
//    element inside the coloured chunks (fem::parallel_for_batches: no atomics). Constrained = true reads
//    constrained components as zero and adds nothing to them, as the elastic operator does;
//  - add_lumped_mass: diag += m per DoF (every DoF, constrained ones included);
//  - assemble_mass: the assembled consistent mass on the host in double (triplets of the free-free block,
//    the layout of solid::assemble_stiffness, whose identity rows it leaves to the stiffness), for the
//    factorized Newmark effective matrix K + M / (beta dt^2).
#pragma once

#include <cstdint>
#include <vector>

#include "fem/basis.hpp"
#include "fem/sum_factorization.hpp"
#include "solid/assembly.hpp"
#include "solid/elastic_operator.hpp"

namespace polymech::solid {

namespace detail {

// Values at the Q^D points (Q = N) of the nodal values u (N^D), into uq; t1, t2 scratch.
template <int D, int N, class B, class V>
KOKKOS_FORCEINLINE_FUNCTION void mass_interpolate(const B& b, const V* u, V* uq, V* t1, V* t2) {
  if constexpr (D == 3) {
    fem::interpolate<N, N>(b, u, uq, t1, t2);
  } else {
    (void)t2;
    fem::interpolate_2d<N, N>(b, u, uq, t1);
  }
}
// Nodal values (N^D) from the weighted point values vq (Q^D), into v; t1, t2 scratch.
template <int D, int N, class B, class V>
KOKKOS_FORCEINLINE_FUNCTION void mass_integrate(const B& b, const V* vq, V* v, V* t1, V* t2) {
  if constexpr (D == 3) {
    fem::integrate<N, N, false>(b, vq, v, t1, t2);
  } else {
    (void)t2;
    fem::integrate_2d<N, N>(b, vq, v, t1);
  }
}

template <class T, int D, int N, bool Constrained>
void mass_apply(const SolidElements<T, D>& el, T rho, const View1<T>& x, const View1<T>& y) {
  constexpr int ND = power<D>(N);
  const fem::HexBasis<T, N, N> b = fem::make_hex_basis<T, N, N>();
  const auto dofs = el.cells.dofs;
  const auto mask = el.fixed_mask;
  const GeometryViews<T, D> geo(el);
  fem::parallel_for_batches("polymech::solid::mass_apply", el.cells, KOKKOS_LAMBDA(const Index e0, const int count, int) {
    const Index row = geo.slot(e0);
    for (int l = 0; l < count; ++l) {
      const Index e = e0 + l;
      T wdet[ND];
      for (int q = 0; q < ND; ++q) {
        T Ji[D][D];
        wdet[q] = rho * geo.template at<N>(row, e0, l, q, b.w, Ji);
      }
      for (int c = 0; c < D; ++c) {
        T u[ND], uq[ND], t1[ND], t2[ND];
        for (int a = 0; a < ND; ++a) {
          const Index d = dofs(e, a), node = fem::decode_dof(d);
          u[a] = (Constrained && d < 0 && ((mask(node) >> c) & 1)) ? T(0) : x(D * node + c);
        }
        mass_interpolate<D, N>(b.B, u, uq, t1, t2);
        for (int q = 0; q < ND; ++q) uq[q] *= wdet[q];
        mass_integrate<D, N>(b.B, uq, u, t1, t2);
        for (int a = 0; a < ND; ++a) {
          const Index d = dofs(e, a), node = fem::decode_dof(d);
          if (Constrained && d < 0 && ((mask(node) >> c) & 1)) continue;
          y(D * node + c) += u[a];
        }
      }
    }
  });
}

template <class T, int D, int N>
void lumped_mass(const SolidElements<T, D>& el, T rho, const View1<T>& m) {
  constexpr int ND = power<D>(N);
  const fem::HexBasis<T, N, N> b = fem::make_hex_basis<T, N, N>();
  const auto dofs = el.cells.dofs;
  const GeometryViews<T, D> geo(el);
  fem::parallel_for_batches("polymech::solid::lumped_mass", el.cells, KOKKOS_LAMBDA(const Index e0, const int count, int) {
    const Index row = geo.slot(e0);
    for (int l = 0; l < count; ++l) {
      const Index e = e0 + l;
      T wq[ND], v[ND], t1[ND], t2[ND];
      for (int q = 0; q < ND; ++q) {
        T Ji[D][D];
        wq[q] = rho * geo.template at<N>(row, e0, l, q, b.w, Ji);
      }
      mass_integrate<D, N>(b.B, wq, v, t1, t2);
      for (int a = 0; a < ND; ++a) {
        const Index node = fem::decode_dof(dofs(e, a));
        for (int c = 0; c < D; ++c) m(D * node + c) += v[a];
      }
    }
  });
}

}  // namespace detail

// y += M x (consistent mass, density rho). Constrained: the free-free block (constrained components read
// as zero and receive nothing); otherwise every DoF.
template <bool Constrained = true, class T, int D>
void add_mass_apply(const SolidElements<T, D>& el, T rho, const View1<T>& x, const View1<T>& y) {
  fem::with_nodes(el.order(), [&](auto n) { detail::mass_apply<T, D, decltype(n)::value, Constrained>(el, rho, x, y); });
}

// m += the row-sum lumped mass per DoF (every DoF; the D components of a node carry the same value).
template <class T, int D>
void add_lumped_mass(const SolidElements<T, D>& el, T rho, const View1<T>& m) {
  fem::with_nodes(el.order(), [&](auto n) { detail::lumped_mass<T, D, decltype(n)::value>(el, rho, m); });
}

// The consistent mass of the free DoFs assembled on the host (double): triplets of the free-free block only
// (no identity rows: combine with assemble_stiffness, which has them). Direct evaluation of the full
// tensor-product basis at the Gauss points (the check of the matrix-free form; O(N^(2D)) per element).
inline Triplets assemble_mass(const AssemblyInput& in, double rho) {
  const int D = in.dim, N = in.order + 1;
  const int ND = D == 3 ? N * N * N : N * N, QD = ND;  // Q = N points per direction
  const fem::GaussTables tables = fem::gauss_tables(N);
  const std::int64_t ne = static_cast<std::int64_t>(in.element_nodes.size()) / ND;
  Triplets t;
  t.n = static_cast<std::int64_t>(in.constrained.size());
  std::vector<double> phi(static_cast<std::size_t>(ND)), grad(static_cast<std::size_t>(ND) * D),
      Me(static_cast<std::size_t>(ND) * ND);
  for (std::int64_t e = 0; e < ne; ++e) {
    const std::int64_t* en = &in.element_nodes[static_cast<std::size_t>(e) * ND];
    std::fill(Me.begin(), Me.end(), 0.0);
    for (int q = 0; q < QD; ++q) {
      double w;
      const double det = fem::tensor_point(tables, D, q, en, in.coordinates, phi.data(), grad.data(), w);
      for (int a = 0; a < ND; ++a)
        for (int b = 0; b < ND; ++b) Me[static_cast<std::size_t>(a) * ND + b] += rho * w * det * phi[a] * phi[b];
    }
    for (int a = 0; a < ND; ++a)
      for (int c = 0; c < D; ++c) {
        const std::int64_t r = D * en[a] + c;
        if (in.constrained[static_cast<std::size_t>(r)]) continue;
        for (int b = 0; b < ND; ++b) {
          const std::int64_t col = D * en[b] + c;
          if (in.constrained[static_cast<std::size_t>(col)]) continue;
          t.rows.push_back(r);
          t.cols.push_back(col);
          t.values.push_back(Me[static_cast<std::size_t>(a) * ND + b]);
        }
      }
  }
  return t;
}

}  // namespace polymech::solid
