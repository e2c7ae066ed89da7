// Element data of vector-valued Lagrange solid elements of order 1..4 (issue 34): hexahedra (D = 3) and
// quadrilaterals (D = 2) on the tensor-product bases of kernels/fem (GLL nodes, Q = N Gauss points per
// direction, basis.hpp).
//
// Topology: `cells` is a fem::HexElements<T> used for what it shares with the scalar operator only: the
// element-to-node table dofs(e, a) for the N^D nodes a = i + N (j + N k), the chunks of neighbouring
// elements grouped by colour (one colour scatters without atomics; fem::parallel_for_batches), the batch
// size and the order. Its Laplacian geometry (G = w det J J^-1 J^-T) is not what elasticity needs and
// stays empty. The displacement DoFs are interleaved, DoF = D node + component, so a node's components
// share a cache line. A node with a Dirichlet condition on any component is stored as -1 - node (the
// encoding of fem::decode_dof) and its constrained components are the bits of fixed_mask(node).
//
// Geometry: the small-strain element needs J^-1 (the physical gradient grad u = grad_ref u J^-1) and
// w det J (the measure). Stored per batch like the scalar operator (hex_elements.hpp): an affine batch
// (J constant over each element, detected, never assumed) keeps D^2 + 1 values per element (J^-1, det J)
// and the kernel multiplies det J by the weight of each point; any other batch keeps the D^2 + 1 values
// (J^-1, w det J) at every point, geometry(row, (component Q^D + q) batch + lane).
//
// Material: a Voigt stiffness (kernels/materials/voigt.hpp) per element, material(e, 6 i + j); in 2D only
// the (11, 22, 12) block is read, so plane strain passes the 3D C and plane stress its condensed form.
#pragma once

#include <string>
#include <vector>

#include "core/small_math.hpp"
#include "fem/hex_elements.hpp"
#include "materials/voigt.hpp"

namespace polymech::solid {

// Points per element and geometry values per point of a D-dimensional element with Q points per direction.
template <int D>
KOKKOS_INLINE_FUNCTION constexpr int power(int n) {
  return D == 2 ? n * n : n * n * n;
}
template <int D>
inline constexpr int geometry_values = D * D + 1;  // J^-1 (row-major), then (w) det J

// Voigt components a D-dimensional element carries: 3D all six, 2D (11, 22, 12).
template <int D>
inline constexpr int strain_components = D == 3 ? 6 : 3;
template <int D>
KOKKOS_INLINE_FUNCTION constexpr int voigt_component(int s) {
  return D == 3 ? s : (s == 2 ? 5 : s);
}

template <class T, int D>
struct SolidElements {
  static_assert(D == 2 || D == 3, "solid elements are quadrilaterals (2) or hexahedra (3)");
  fem::HexElements<T> cells;                                  // node table, chunks, colours, batch, order
  View1<unsigned char> fixed_mask;                            // [nodes]: bit c = component c constrained
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> affine;    // [elements][D^2 + 1]: J^-1, det J
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> geometry;  // [general batches][(D^2 + 1) Q^D batch]
  View1<Index> geometry_slot;                                 // [elements]: row in geometry, or fem::affine_slot
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> material;  // [elements][36]: Voigt C, row-major
  Index nodes = 0;
  Index affine_batches = 0, general_batches = 0;  // host: how the batches are stored

  int order() const { return cells.order; }
  Index elements() const { return cells.elements(); }
  Index dof_count() const { return D * nodes; }
};

// The geometry as the kernels capture it (Views only).
template <class T, int D>
struct GeometryViews {
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> affine, geometry;
  View1<Index> slot;
  int batch = 1;

  GeometryViews() = default;
  explicit GeometryViews(const SolidElements<T, D>& el)
      : affine(el.affine), geometry(el.geometry), slot(el.geometry_slot), batch(el.cells.batch) {}

  // J^-1 (into Ji) and the returned w det J at point q of lane l of the batch that starts at e0, whose row
  // is slot(e0); w: the 1D Gauss weights of the Q-point rule.
  template <int Q, class W>
  KOKKOS_INLINE_FUNCTION T at(Index row, Index e0, int l, int q, const W& w, T (&Ji)[D][D]) const {
    constexpr int QD = power<D>(Q);
    if (row >= 0) {
      for (int v = 0; v < D * D; ++v) Ji[v / D][v % D] = geometry(row, (v * QD + q) * batch + l);
      return geometry(row, (D * D * QD + q) * batch + l);
    }
    for (int v = 0; v < D * D; ++v) Ji[v / D][v % D] = affine(e0 + l, v);
    T wq = w[q % Q] * w[(q / Q) % Q];
    if (D == 3) wq *= w[q / (Q * Q)];
    return wq * affine(e0 + l, D * D);
  }
};

// Node coordinates of a solid mesh, double: [nodes][D].
template <int D>
using NodeCoordinates = Kokkos::View<double* [D], Kokkos::LayoutRight, MemSpace>;

namespace detail {

// Reference gradient of the coordinates of element e at the Q^D points (J[c][d][q] = dx_c/dxi_d) and at the
// N^D nodes (Jn), with the fem sum-factorization sweeps (full matrices: set-up only, in double).
template <int D, int N, int Q>
struct ElementJacobians {
  double J[D][D][power<D>(Q)];
  double Jn[D][D][power<D>(N)];
  double Xq[D][power<D>(Q)];
};

template <int D, int N, int Q, class Dofs, class X>
KOKKOS_INLINE_FUNCTION void element_jacobians(const fem::HexBasis<double, N, Q>& b, const Dofs& dofs, Index e,
                                              const X& x, ElementJacobians<D, N, Q>& out) {
  constexpr int ND = power<D>(N);
  constexpr int E2 = D == 3 ? N : 1, Q2 = D == 3 ? Q : 1;
  double X1[power<D>(N)], t1[power<D>(Q)], t2[power<D>(Q)];
  for (int c = 0; c < D; ++c) {
    for (int a = 0; a < ND; ++a) X1[a] = x(fem::decode_dof(dofs(e, a)), c);
    // values at the points (B along every direction), then the collocation derivative Dq
    fem::contract<0, N, Q, N, N, E2, false, false>(b.B, X1, t1);
    if constexpr (D == 3) {
      fem::contract<1, N, Q, Q, N, E2, false, false>(b.B, t1, t2);
      fem::contract<2, N, Q, Q, Q, E2, false, false>(b.B, t2, out.Xq[c]);
    } else {
      fem::contract<1, N, Q, Q, N, 1, false, false>(b.B, t1, out.Xq[c]);
    }
    fem::contract<0, Q, Q, Q, Q, Q2, false, false>(b.Dq, out.Xq[c], out.J[c][0]);
    fem::contract<1, Q, Q, Q, Q, Q2, false, false>(b.Dq, out.Xq[c], out.J[c][1]);
    if constexpr (D == 3) fem::contract<2, Q, Q, Q, Q, Q2, false, false>(b.Dq, out.Xq[c], out.J[c][D - 1]);
    fem::contract<0, N, N, N, N, E2, false, false>(b.Dn, X1, out.Jn[c][0]);
    fem::contract<1, N, N, N, N, E2, false, false>(b.Dn, X1, out.Jn[c][1]);
    if constexpr (D == 3) fem::contract<2, N, N, N, N, E2, false, false>(b.Dn, X1, out.Jn[c][D - 1]);
  }
}

template <int D>
KOKKOS_INLINE_FUNCTION double jacobian_det(const double (&m)[D][D]) {
  if constexpr (D == 2)
    return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  else
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

template <int D>
KOKKOS_INLINE_FUNCTION void jacobian_inverse(const double (&m)[D][D], double (&inv)[D][D]) {
  const double s = 1.0 / jacobian_det<D>(m);
  if constexpr (D == 2) {
    inv[0][0] = s * m[1][1];
    inv[0][1] = -s * m[0][1];
    inv[1][0] = -s * m[1][0];
    inv[1][1] = s * m[0][0];
  } else {
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {  // adjugate: cofactor of (j, i)
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        inv[i][j] = s * (m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]);
      }
  }
}

// Geometry of every element in double: geo(e, v Q^D + q) for the D^2 + 1 values v (J^-1, w det J), the
// element's map kind (affine: J the same at every point and node up to the rounding of the coordinates),
// and the worst det J / (volume / 2^D) over nodes and points (<= 0: an inverted element).
template <int D, int N>
fem::JacobianCheck compute_geometry(const Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>& dofs,
                                    const NodeCoordinates<D>& x,
                                    const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& geo,
                                    const View1<char>& is_affine) {
  constexpr int Q = N, QD = power<D>(Q), ND = power<D>(N);
  const fem::HexBasis<double, N, Q> b = fem::make_hex_basis<double, N, Q>();
  using MinLoc = Kokkos::MinLoc<double, Index>;
  typename MinLoc::value_type worst;
  Kokkos::parallel_reduce(
      "polymech::solid::geometry", range(static_cast<Index>(dofs.extent(0))),
      KOKKOS_LAMBDA(const Index e, typename MinLoc::value_type& w) {
        ElementJacobians<D, N, Q> j;
        element_jacobians<D, N, Q>(b, dofs, e, x, j);
        double volume = 0.0, min_det = 1e300, scale = 0.0, deviation = 0.0, xmax = 0.0;
        for (int q = 0; q < QD; ++q) {
          double m[D][D], inv[D][D];
          for (int c = 0; c < D; ++c)
            for (int d = 0; d < D; ++d) m[c][d] = j.J[c][d][q];
          const double det = jacobian_det<D>(m);
          jacobian_inverse<D>(m, inv);
          double wq = b.w[q % Q] * b.w[(q / Q) % Q];
          if (D == 3) wq *= b.w[q / (Q * Q)];
          for (int r = 0; r < D; ++r)
            for (int c = 0; c < D; ++c) geo(e, (D * r + c) * QD + q) = inv[r][c];
          geo(e, D * D * QD + q) = wq * det;
          volume += wq * det;
          min_det = kx::min(min_det, det);
        }
        for (int a = 0; a < ND; ++a) {
          double m[D][D];
          for (int c = 0; c < D; ++c)
            for (int d = 0; d < D; ++d) m[c][d] = j.Jn[c][d][a];
          min_det = kx::min(min_det, jacobian_det<D>(m));
        }
        const double ratio = volume > 0 ? min_det / (volume / (D == 3 ? 8.0 : 4.0)) : -1.0;
        if (ratio < w.val) {
          w.val = ratio;
          w.loc = e;
        }
        for (int c = 0; c < D; ++c)
          for (int d = 0; d < D; ++d) {
            scale = kx::max(scale, kx::fabs(j.J[c][d][0]));
            for (int q = 1; q < QD; ++q) deviation = kx::max(deviation, kx::fabs(j.J[c][d][q] - j.J[c][d][0]));
            for (int a = 0; a < ND; ++a) deviation = kx::max(deviation, kx::fabs(j.Jn[c][d][a] - j.J[c][d][0]));
          }
        for (int c = 0; c < D; ++c)
          for (int q = 0; q < QD; ++q) xmax = kx::max(xmax, kx::fabs(j.Xq[c][q]));
        // the tolerance of the scalar operator (hex_elements.hpp, fem::detail::affine_tolerance)
        const double allowed = fem::detail::affine_tolerance * scale + 64.0 * N * N * 2.220446049250313e-16 * xmax;
        is_affine(e) = deviation <= allowed ? 1 : 0;
      },
      MinLoc(worst));
  return {worst.val, worst.loc};
}

}  // namespace detail

// Geometry of every element from the node coordinates (computed in double, stored in T), batch by batch:
// affine batches as D^2 + 1 values per element unless allow_affine is false. el.cells (dofs, chunks,
// colours, batch, order) must be set. Returns the worst Jacobian; the caller refuses min_ratio <= 0.
template <class T, int D>
fem::JacobianCheck compute_geometry(SolidElements<T, D>& el, const NodeCoordinates<D>& x, bool allow_affine = true) {
  fem::JacobianCheck check;
  const Index ne = el.elements();
  fem::with_nodes(el.order(), [&](auto n) {
    constexpr int N = decltype(n)::value, Q = N, QD = power<D>(Q), G = geometry_values<D>;
    Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> geo("polymech::solid::geometry_double", ne, G * QD);
    View1<char> kind("polymech::solid::is_affine", ne);
    check = detail::compute_geometry<D, N>(el.cells.dofs, x, geo, kind);
    const auto g = Kokkos::create_mirror_view_and_copy(HostSpace(), geo);
    const auto kh = Kokkos::create_mirror_view_and_copy(HostSpace(), kind);
    const auto chunks = Kokkos::create_mirror_view_and_copy(HostSpace(), el.cells.chunk_offsets);
    const fem::HexBasis<double, N, Q> b = fem::make_hex_basis<double, N, Q>();
    const double w0 = D == 3 ? b.w[0] * b.w[0] * b.w[0] : b.w[0] * b.w[0];
    const int B = el.cells.batch;
    std::vector<Index> slot(static_cast<std::size_t>(ne), fem::affine_slot);
    std::vector<Index> batch_start;  // first element of each general batch
    el.affine_batches = el.general_batches = 0;
    for (std::size_t k = 0; k + 1 < chunks.extent(0); ++k)
      for (Index e0 = chunks(k); e0 < chunks(k + 1); e0 += B) {
        const Index e1 = std::min<Index>(e0 + B, chunks(k + 1));
        bool affine = allow_affine;
        for (Index e = e0; e < e1; ++e) affine = affine && kh(e) == 1;
        if (affine) {
          ++el.affine_batches;
          continue;
        }
        for (Index e = e0; e < e1; ++e) slot[e] = el.general_batches;
        ++el.general_batches;
        batch_start.push_back(e0);
      }
    el.affine = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::solid::affine_geometry", ne, G);
    el.geometry = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::solid::geometry", el.general_batches,
                                                                   G * QD * B);  // zero: missing lanes add nothing
    el.geometry_slot = View1<Index>("polymech::solid::geometry_slot", ne);
    auto ah = Kokkos::create_mirror_view(el.affine);
    auto gh = Kokkos::create_mirror_view(el.geometry);
    auto sh = Kokkos::create_mirror_view(el.geometry_slot);
    for (Index e = 0; e < ne; ++e) {
      sh(e) = slot[e];
      for (int v = 0; v < G; ++v) ah(e, v) = static_cast<T>(v < D * D ? g(e, v * QD) : g(e, v * QD) / w0);
    }
    for (std::size_t r = 0; r < batch_start.size(); ++r)
      for (Index e = batch_start[r]; e < ne && slot[e] == static_cast<Index>(r); ++e)
        for (int v = 0; v < G; ++v)
          for (int q = 0; q < QD; ++q) gh(r, (v * QD + q) * B + (e - batch_start[r])) = static_cast<T>(g(e, v * QD + q));
    Kokkos::deep_copy(el.affine, ah);
    Kokkos::deep_copy(el.geometry, gh);
    Kokkos::deep_copy(el.geometry_slot, sh);
  });
  return check;
}

// One Voigt stiffness for every element.
template <class T, int D>
void set_uniform_material(SolidElements<T, D>& el, const materials::Stiffness6<double>& C) {
  el.material = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::solid::material", el.elements(), 36);
  auto h = Kokkos::create_mirror_view(el.material);
  for (Index e = 0; e < el.elements(); ++e)
    for (int k = 0; k < 36; ++k) h(e, k) = static_cast<T>(C.c[k / 6][k % 6]);
  Kokkos::deep_copy(el.material, h);
}

}  // namespace polymech::solid
