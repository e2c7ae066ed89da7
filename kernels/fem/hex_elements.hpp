// Device data of a mesh of order-p Lagrange hexahedra and the geometry kernel (isoparametric map,
// seed 002 paper 3 eq. (21) taken to order p).
//
// Layout (domain decomposition, models/helmholtz/distribute.hpp): DoFs are local indices of one part,
// owned DoFs first [0, owned) and ghost copies of neighbours' DoFs after them [owned, owned + ghost).
// Element kernels gather and scatter local indices; reductions run over owned entries
// (kernels/solvers). With one part there are no ghosts.
//
// Element-to-DoF map: dofs(e, a) for the N^3 nodes a = i + N (j + N k) of element e (GLL node i along
// xi, j along eta, k along zeta). A DoF under a strong Dirichlet condition is stored as -1 - d, so the
// constrained operator skips it with a sign test and the unconstrained one decodes it.
//
// Elements are stored in chunks (runs of neighbouring elements), the chunks grouped by colour: chunks
// of one colour share no DoF, so each colour is one parallel launch over its chunks that scatter-adds
// without atomics, and results do not depend on the thread count. A thread works through a chunk's
// elements in order, in batches of `batch` elements (the SIMD lanes of the volume kernel), which keeps
// the DoFs they share in cache (on the host a chunk is ~8000 nodes; on a GPU, one element).
#pragma once

#include <algorithm>
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

// Geometric factors at quadrature point q of an element: the symmetric G = w det(J) J^-1 J^-T (6
// values) and w det(J), so that
//   (A_e)_ab = sum_q grad_ref(phi_a)^T G grad_ref(phi_b),  (M_e)_ab = sum_q w det(J) phi_a phi_b.
enum GeometryComponent : int { g00 = 0, g01, g02, g11, g12, g22, wdetj, geometry_components };

// Elements are processed in batches of `batch` consecutive elements of a chunk (the SIMD lanes of the
// batched kernels; the last batch of a chunk may be partial). The geometric factors are stored per
// batch, in one of two forms:
//  - affine batch (every element's map is affine, which is detected from J at every node and point,
//    not assumed): J is constant, so only the 7 values of the element, G / w and det J, are kept,
//    affine(e, component), and the kernel multiplies by the weight w_q of each point;
//  - any other batch: the 7 values at every point, geometry(slot, (component Q^3 + q) batch + lane),
//    in a row `slot` = geometry_slot(first element of the batch) of its own.
// geometry_slot(e) is affine_slot (-1) for the elements of affine batches and rectilinear_slot (-2) for
// those of rectilinear ones (affine with J diagonal: G diagonal, applied in Kronecker form).
inline constexpr Index affine_slot = -1, rectilinear_slot = -2;

template <class T>
struct HexElements {
  int order = 1;
  int batch = 1;               // elements per batch (the lanes of the batched kernels)
  Index owned = 0, ghost = 0;  // DoF layout of this part
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> dofs;  // [elements][N^3], storage order
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> affine;    // [elements][7]: G / w, det J (affine batches)
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> geometry;  // [non-affine batches][7 Q^3 batch]
  View1<Index> geometry_slot;                                 // [elements]: row of the batch in geometry, or < 0
  Kokkos::View<Index*, MemSpace> chunk_offsets;  // chunk k is elements [chunk_offsets(k), chunk_offsets(k + 1))
  std::vector<Index> color_offsets;  // host: colour c is chunks [color_offsets[c], color_offsets[c + 1])
  Index affine_batches = 0, rectilinear_batches = 0, general_batches = 0;  // host: how the batches are stored

  int nodes_1d() const { return order + 1; }
  Index elements() const { return static_cast<Index>(dofs.extent(0)); }
  Index local_size() const { return owned + ghost; }
  int colors() const { return static_cast<int>(color_offsets.size()) - 1; }
};

// The geometric factors as the kernels capture them (Views only).
template <class T>
struct GeometryViews {
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> affine, geometry;
  View1<Index> slot;
  int batch = 1;

  GeometryViews() = default;
  explicit GeometryViews(const HexElements<T>& el)
      : affine(el.affine), geometry(el.geometry), slot(el.geometry_slot), batch(el.batch) {}

  // Factor `component` at point q = i + Q (j + Q k) (weights w of the Q-point rule) of lane `lane` of
  // the batch that starts at element e0, whose row is slot(e0).
  template <int Q, class W>
  KOKKOS_FORCEINLINE_FUNCTION T at(Index row, Index e0, int lane, int component, int q, const W& w) const {
    constexpr int Q3 = Q * Q * Q;
    if (row < 0) return w[q % Q] * w[(q / Q) % Q] * w[q / (Q * Q)] * affine(e0 + lane, component);
    return geometry(row, (component * Q3 + q) * batch + lane);
  }
};

// One launch per colour of the element chunks; f(e0, count, next) runs for every batch (elements e0 ..
// e0 + count - 1, count <= el.batch), a chunk's batches in order by one thread; the next batch of the
// chunk has `next` elements from e0 + el.batch on (0 after the last batch).
template <class T, class F>
void parallel_for_batches(const char* label, const HexElements<T>& el, const F& f) {
  const auto chunks = el.chunk_offsets;
  const Index B = el.batch;
  for (std::size_t c = 0; c + 1 < el.color_offsets.size(); ++c)
    Kokkos::parallel_for(
        label, Kokkos::RangePolicy<ExecSpace>(el.color_offsets[c], el.color_offsets[c + 1]),
        KOKKOS_LAMBDA(const Index k) {
          const Index end = chunks(k + 1);
          for (Index e0 = chunks(k); e0 < end; e0 += B) {
            const Index rest = end - e0 - B;
            f(e0, static_cast<int>(end - e0 < B ? end - e0 : B), static_cast<int>(rest <= 0 ? 0 : rest < B ? rest : B));
          }
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

// How an element maps from the reference cube (detected from J, never assumed):
enum MapKind : char {
  general_map = 0,      // J varies over the element: factors at every point
  affine_map = 1,       // J constant: one set of factors per element
  rectilinear_map = 2,  // J constant and diagonal (a box along the axes): G diagonal, a Kronecker form
};

// Relative variation of J over an element below which its map counts as affine, on top of the
// variation the rounding of the node coordinates explains (a vertex moved by 1e-9 h counts as curved).
inline constexpr double affine_tolerance = 1e-13;

template <int N, int Q>
JacobianCheck compute_geometry(const Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>& dofs,
                               const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                               const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& geo,
                               const View1<char>& is_affine) {
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
        // affine map: J the same at every point and node, up to what the rounding of the node
        // coordinates (|X| eps, amplified by the derivative matrices, ~N^2) and of J itself explain
        double scale = 0.0, deviation = 0.0, xmax = 0.0;
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d) scale = kx::max(scale, kx::fabs(J[c][d][0]));
        for (int c = 0; c < 3; ++c)
          for (int a = 0; a < N3; ++a) xmax = kx::max(xmax, kx::fabs(X[c][a]));
        for (int c = 0; c < 3; ++c)
          for (int d = 0; d < 3; ++d) {
            for (int q = 1; q < Q3; ++q) deviation = kx::max(deviation, kx::fabs(J[c][d][q] - J[c][d][0]));
            for (int a = 0; a < N3; ++a) deviation = kx::max(deviation, kx::fabs(Jn[c][d][a] - J[c][d][0]));
          }
        const double allowed = affine_tolerance * scale + 64.0 * N * N * 2.220446049250313e-16 * xmax;
        // rectilinear: affine with G diagonal (edges along the axes), to the same relative tolerance
        const double off = kx::max(kx::fabs(geo(e, g01 * Q3)), kx::max(kx::fabs(geo(e, g02 * Q3)), kx::fabs(geo(e, g12 * Q3))));
        const double diag = kx::max(geo(e, g00 * Q3), kx::max(geo(e, g11 * Q3), geo(e, g22 * Q3)));
        const bool affine = deviation <= allowed;
        is_affine(e) = !affine ? general_map : off <= (allowed / kx::max(scale, 1e-300)) * diag ? rectilinear_map : affine_map;
      },
      MinLoc(worst));
  return {worst.val, worst.loc};
}

// Stores the factors of geo (double, [elements][7 Q^3]) in el, batch by batch (HexElements): affine
// batches as 7 values per element, the others per point, in precision T. Host loop (set-up only).
template <class T, int Q>
void store_geometry(HexElements<T>& el, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& geo,
                    const View1<char>& is_affine, bool allow_affine) {
  constexpr int Q3 = Q * Q * Q;
  const double w0 = [] {
    std::vector<double> x, w;
    gauss_legendre(Q, x, w);
    return w[0] * w[0] * w[0];
  }();
  const auto g = Kokkos::create_mirror_view_and_copy(HostSpace(), geo);
  const auto affine_h = Kokkos::create_mirror_view_and_copy(HostSpace(), is_affine);
  const auto chunks = Kokkos::create_mirror_view_and_copy(HostSpace(), el.chunk_offsets);
  const Index ne = el.elements();
  const int B = el.batch;
  std::vector<Index> slot(static_cast<std::size_t>(ne), affine_slot);
  Index rows = 0;
  el.affine_batches = el.rectilinear_batches = el.general_batches = 0;
  for (std::size_t k = 0; k + 1 < chunks.extent(0); ++k)
    for (Index e0 = chunks(k); e0 < chunks(k + 1); e0 += B) {
      const Index e1 = std::min<Index>(e0 + B, chunks(k + 1));
      int kind = allow_affine ? rectilinear_map : general_map;  // the batch's: the least special of its elements
      for (Index e = e0; e < e1; ++e) kind = std::min<int>(kind, affine_h(e));
      if (kind == rectilinear_map) {
        ++el.rectilinear_batches;
        for (Index e = e0; e < e1; ++e) slot[e] = rectilinear_slot;
        continue;
      }
      if (kind == affine_map) {
        ++el.affine_batches;
        continue;
      }
      ++el.general_batches;
      for (Index e = e0; e < e1; ++e) slot[e] = rows;
      ++rows;
    }
  el.affine = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::fem::affine_geometry", ne, geometry_components);
  el.geometry = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::fem::geometry", rows,
                                                                 geometry_components * Q3 * B);
  el.geometry_slot = View1<Index>("polymech::fem::geometry_slot", ne);
  auto ah = Kokkos::create_mirror_view(el.affine);
  auto gh = Kokkos::create_mirror_view(el.geometry);
  auto sh = Kokkos::create_mirror_view(el.geometry_slot);
  Index first = 0;  // first element of the current batch
  for (std::size_t k = 0; k + 1 < chunks.extent(0); ++k)
    for (first = chunks(k); first < chunks(k + 1); first += B)
      for (Index e = first; e < std::min<Index>(first + B, chunks(k + 1)); ++e) {
        sh(e) = slot[e];
        for (int c = 0; c < geometry_components; ++c) ah(e, c) = static_cast<T>(g(e, c * Q3) / w0);
        if (slot[e] < 0) continue;
        for (int c = 0; c < geometry_components; ++c)
          for (int q = 0; q < Q3; ++q) gh(slot[e], (c * Q3 + q) * B + (e - first)) = static_cast<T>(g(e, c * Q3 + q));
      }
  Kokkos::deep_copy(el.affine, ah);
  Kokkos::deep_copy(el.geometry, gh);
  Kokkos::deep_copy(el.geometry_slot, sh);
}

}  // namespace detail

// Geometric factors of every element from the DoF coordinates x (double, local DoFs x 3), computed in
// double and stored in T, with Q = N Gauss points per direction (exact mass and stiffness matrices on
// parallelepipeds); el.dofs, el.chunk_offsets and el.batch must be set. Batches of affine elements
// keep one set of factors per element unless allow_affine is false. Returns the worst Jacobian; the
// caller refuses a mesh with min_ratio <= 0.
template <class T>
JacobianCheck compute_geometry(HexElements<T>& el, const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                               bool allow_affine = true) {
  JacobianCheck check;
  with_nodes(el.order, [&](auto n) {
    constexpr int N = decltype(n)::value;
    constexpr int Q = N;
    Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> geo("polymech::fem::geometry", el.elements(),
                                                              geometry_components * Q * Q * Q);
    View1<char> is_affine("polymech::fem::is_affine", el.elements());
    check = detail::compute_geometry<N, Q>(el.dofs, x, geo, is_affine);
    detail::store_geometry<T, Q>(el, geo, is_affine, allow_affine);
  });
  return check;
}

}  // namespace polymech::fem
