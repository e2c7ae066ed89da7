// Device data of a mesh of order-p Lagrange hexahedra and the geometry kernel (isoparametric map,
// seed 002 paper 3 eq. (21) taken to order p).
//
// Layout (ready for a later domain decomposition): DoFs are local indices of one part, owned DoFs
// first [0, owned) and ghost copies of neighbours' DoFs after them [owned, owned + ghost). Element
// kernels gather and scatter local indices; reductions run over owned entries (kernels/solvers). With
// one part there are no ghosts.
//
// Element-to-DoF map: dofs(e, a) for the N^3 nodes a = i + N (j + N k) of element e (GLL node i along
// xi, j along eta, k along zeta). A DoF under a strong Dirichlet condition is stored as -1 - d, so the
// constrained operator skips it with a sign test and the unconstrained one decodes it.
//
// Elements are stored in chunks (runs of neighbouring elements), the chunks grouped by colour: chunks
// of one colour share no DoF, so each colour is one parallel launch over its chunks that scatter-adds
// without atomics, and results do not depend on the thread count. A thread works through a chunk's
// elements in order, which keeps the DoFs they share in cache (on the host a chunk is ~8000 nodes; on
// a GPU, one element).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "fem/basis.hpp"
#include "fem/sum_factorization.hpp"

namespace polymech::fem {

KOKKOS_INLINE_FUNCTION Index decode_dof(Index d) { return d >= 0 ? d : -1 - d; }
KOKKOS_INLINE_FUNCTION Index constrained_dof(Index d) { return -1 - d; }

// u[a] = x(map(i, a)) for the Count nodes of item i (element or face). Constrained = true: DoFs under
// a Dirichlet condition read as zero (the operator on the free DoFs); false: every DoF is read.
template <bool Constrained, int Count, class Map, class X, class V>
KOKKOS_FORCEINLINE_FUNCTION void gather(const Map& map, Index i, const X& x, V* u) {
  for (int a = 0; a < Count; ++a) {
    const Index d = map(i, a);
    if (Constrained)
      u[a] = d >= 0 ? x(d) : V(0);
    else
      u[a] = x(decode_dof(d));
  }
}

// y(map(i, a)) += u[a]; Constrained = true skips DoFs under a Dirichlet condition. Callers launch one
// colour at a time, so no two items of a launch touch the same DoF.
template <bool Constrained, int Count, class Map, class Y, class V>
KOKKOS_FORCEINLINE_FUNCTION void scatter_add(const Map& map, Index i, const V* u, const Y& y) {
  for (int a = 0; a < Count; ++a) {
    const Index d = map(i, a);
    if (Constrained) {
      if (d >= 0) y(d) += u[a];
    } else {
      y(decode_dof(d)) += u[a];
    }
  }
}

// One launch per colour of items (elements or faces) grouped by colour: items [offsets[c], offsets[c+1])
// share no DoF, so f can scatter-add without atomics.
template <class F>
void parallel_for_colors(const char* label, const std::vector<Index>& offsets, const F& f) {
  for (std::size_t c = 0; c + 1 < offsets.size(); ++c)
    Kokkos::parallel_for(label, Kokkos::RangePolicy<ExecSpace>(offsets[c], offsets[c + 1]), f);
}

// Geometric factors stored per quadrature point q of an element: the symmetric
// G = w det(J) J^-1 J^-T (6 values) and w det(J), so that
//   (A_e)_ab = sum_q grad_ref(phi_a)^T G grad_ref(phi_b),  (M_e)_ab = sum_q w det(J) phi_a phi_b.
enum GeometryComponent : int { g00 = 0, g01, g02, g11, g12, g22, wdetj, geometry_components };

template <class T>
struct HexElements {
  int order = 1;
  Index owned = 0, ghost = 0;  // DoF layout of this part
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> dofs;  // [elements][N^3], storage order
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> geometry;  // [elements][7 Q^3], component-major
  Kokkos::View<Index*, MemSpace> chunk_offsets;  // chunk k is elements [chunk_offsets(k), chunk_offsets(k + 1))
  std::vector<Index> color_offsets;  // host: colour c is chunks [color_offsets[c], color_offsets[c + 1])

  int nodes_1d() const { return order + 1; }
  Index elements() const { return static_cast<Index>(dofs.extent(0)); }
  Index local_size() const { return owned + ghost; }
  int colors() const { return static_cast<int>(color_offsets.size()) - 1; }
};

// One launch per colour of the element chunks; f(e) runs for every element, a chunk's elements in order
// by one thread.
template <class T, class F>
void parallel_for_colors(const char* label, const HexElements<T>& el, const F& f) {
  const auto chunks = el.chunk_offsets;
  for (std::size_t c = 0; c + 1 < el.color_offsets.size(); ++c)
    Kokkos::parallel_for(
        label, Kokkos::RangePolicy<ExecSpace>(el.color_offsets[c], el.color_offsets[c + 1]),
        KOKKOS_LAMBDA(const Index k) {
          for (Index e = chunks(k); e < chunks(k + 1); ++e) f(e);
        });
}

// Calls f(std::integral_constant<int, N>{}) with N = order + 1 for order 1..4.
template <class F>
void with_nodes(int order, F&& f) {
  switch (order) {
    case 1: f(std::integral_constant<int, 2>{}); break;
    case 2: f(std::integral_constant<int, 3>{}); break;
    case 3: f(std::integral_constant<int, 4>{}); break;
    case 4: f(std::integral_constant<int, 5>{}); break;
    default: throw std::invalid_argument("fem: order " + std::to_string(order) + " is not supported; allowed: 1..4");
  }
}

// Worst Jacobian of the mesh: min over elements of det(J) / (element volume / 8) at the GLL nodes and
// the quadrature points (1 for an undistorted parallelepiped, <= 0 for an inverted or folded element).
struct JacobianCheck {
  double min_ratio = 0.0;
  Index element = -1;  // storage (colour-sorted) index of the worst element
};

namespace detail {

template <int N, int Q>
JacobianCheck compute_geometry(const Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>& dofs,
                               const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                               const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& geo) {
  const HexBasis<double, N, Q> b = make_hex_basis<double, N, Q>();
  constexpr int N3 = N * N * N, Q3 = Q * Q * Q;
  using MinLoc = Kokkos::MinLoc<double, Index>;
  typename MinLoc::value_type worst;
  Kokkos::parallel_reduce(
      "polymech::fem::geometry", range(static_cast<Index>(dofs.extent(0))),
      KOKKOS_LAMBDA(const Index e, typename MinLoc::value_type& w) {
        double X[3][N3], Xq[Q3], t1[Q * Q * N], t2[Q * Q * N], J[3][3][Q3];
        for (int a = 0; a < N3; ++a) {
          const Index d = decode_dof(dofs(e, a));
          for (int c = 0; c < 3; ++c) X[c][a] = x(d, c);
        }
        for (int c = 0; c < 3; ++c) {
          interpolate<N, Q>(b.B, X[c], Xq, t1, t2);
          gradient_at_points<Q>(b.Dq, Xq, J[c][0], J[c][1], J[c][2]);
        }
        double volume = 0.0, min_det = 1e300;
        for (int q = 0; q < Q3; ++q) {
          Mat3<double> m;
          for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) m(c, d) = J[c][d][q];
          const double det = polymech::det(m);
          const double wq = b.w[q % Q] * b.w[(q / Q) % Q] * b.w[q / (Q * Q)];
          const Mat3<double> inv = inverse(m);
          // G = w det J J^-1 J^-T
          double G[6];
          const int ij[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
          for (int s = 0; s < 6; ++s) {
            const int r = ij[s][0], c = ij[s][1];
            G[s] = wq * det * (inv(r, 0) * inv(c, 0) + inv(r, 1) * inv(c, 1) + inv(r, 2) * inv(c, 2));
          }
          for (int s = 0; s < 6; ++s) geo(e, s * Q3 + q) = G[s];
          geo(e, wdetj * Q3 + q) = wq * det;
          volume += wq * det;
          if (det < min_det) min_det = det;
        }
        // det J at the GLL nodes (corners included): differentiate the nodal coordinates directly
        double Jn[3][3][N3];
        for (int c = 0; c < 3; ++c) {
          contract<0, N, N, N, N, N, false, false>(b.Dn, X[c], Jn[c][0]);
          contract<1, N, N, N, N, N, false, false>(b.Dn, X[c], Jn[c][1]);
          contract<2, N, N, N, N, N, false, false>(b.Dn, X[c], Jn[c][2]);
        }
        for (int a = 0; a < N3; ++a) {
          Mat3<double> m;
          for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) m(c, d) = Jn[c][d][a];
          const double det = polymech::det(m);
          if (det < min_det) min_det = det;
        }
        const double ratio = volume > 0 ? min_det / (volume / 8.0) : -1.0;
        if (ratio < w.val) {
          w.val = ratio;
          w.loc = e;
        }
      },
      MinLoc(worst));
  return {worst.val, worst.loc};
}

// The geometric factors in precision T: the double View itself, or a rounded copy.
inline void store_geometry(const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& from,
                           Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& to) {
  to = from;
}
template <class T>
void store_geometry(const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& from,
                    Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>& out) {
  out = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::fem::geometry", from.extent(0), from.extent(1));
  const auto to = out;
  const Index m = static_cast<Index>(from.extent(1));
  Kokkos::parallel_for(
      "polymech::fem::geometry_to_precision", range(static_cast<Index>(from.extent(0))), KOKKOS_LAMBDA(const Index e) {
        for (Index k = 0; k < m; ++k) to(e, k) = static_cast<T>(from(e, k));
      });
}

}  // namespace detail

// Geometric factors of every element from the DoF coordinates x (double, local DoFs x 3), computed in
// double and stored in T, with Q = N Gauss points per direction (exact mass and stiffness matrices on
// parallelepipeds). Returns the worst Jacobian; the caller refuses a mesh with min_ratio <= 0.
template <class T>
JacobianCheck compute_geometry(HexElements<T>& el, const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x) {
  JacobianCheck check;
  with_nodes(el.order, [&](auto n) {
    constexpr int N = decltype(n)::value;
    constexpr int Q = N;
    Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> geo("polymech::fem::geometry", el.elements(),
                                                              geometry_components * Q * Q * Q);
    check = detail::compute_geometry<N, Q>(el.dofs, x, geo);
    detail::store_geometry(geo, el.geometry);
  });
  return check;
}

}  // namespace polymech::fem
