// Moving least squares (MLS) shape functions in 2D for the element-free Galerkin method (seed 004,
// Hagihara et al.): the linear basis p = [1, x, y] (eq. (2)), the weighted least-squares functional
// (eq. (4)) and the quartic spline weight (eq. (5)); shape functions and their first derivatives at a
// batch of points, against the nodes listed for each point by the two-set neighbour search
// (neighbors::NeighborSearch::build_between, then support_rows below).
//
// Supports: node I covers the disc of radius dm(I) around it (its own radius: the model sets
// dm(I) = factor x the local node spacing). A crack (straight segments) limits the supports by the
// visibility criterion (Belytschko et al. 1994): node I does not contribute at x when the segment
// x - x_I crosses a crack segment (strictly: a segment through a crack tip still sees the node).
// Nodes on a crack face are given a position a hair off the face, on their side, so the criterion
// decides them.
//
// The moment matrix A(x) = sum_I w_I p_I p_I^T is checked at every point: when the ratio
// det(A) / (A_00 A_11 A_22) (1 for a well-spread support, 0 when the nodes are collinear or fewer than
// three) falls below `min_ratio`, the point is flagged in `status` (1) and its shape functions are set
// to zero; the host side (models/efg) turns a flag into an error naming the point. Never a NaN.
#pragma once

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/filter.hpp"
#include "neighbors/neighbor_list.hpp"

namespace polymech::mls {

// Crack segments (x0, y0, x1, y1) per row.
template <class T>
using Segments = Kokkos::View<T* [4], Kokkos::LayoutRight, MemSpace>;

// seed 004 eq. (5): w(r) = 1 - 6 r^2 + 8 r^3 - 3 r^4 for r = d / d_m < 1, else 0; and dw/dr.
template <class T>
KOKKOS_INLINE_FUNCTION void quartic_spline(T r, T& w, T& dw_dr) {
  if (r >= T(1)) {
    w = T(0);
    dw_dr = T(0);
    return;
  }
  const T r2 = r * r;
  w = T(1) - T(6) * r2 + T(8) * r2 * r - T(3) * r2 * r2;
  dw_dr = -T(12) * r + T(24) * r2 - T(12) * r2 * r;
}

// True when the open segments a-b and c-d cross at one interior point of both.
template <class T>
KOKKOS_INLINE_FUNCTION bool segments_cross(T ax, T ay, T bx, T by, T cx, T cy, T dx, T dy) {
  const T d1 = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx);
  const T d2 = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx);
  const T d3 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  const T d4 = (bx - ax) * (dy - ay) - (by - ay) * (dx - ax);
  return ((d1 > T(0) && d2 < T(0)) || (d1 < T(0) && d2 > T(0))) &&
         ((d3 > T(0) && d4 < T(0)) || (d3 < T(0) && d4 > T(0)));
}

// Visibility criterion: node at (nx, ny) is seen from (px, py) unless a crack segment is in between.
template <class T>
KOKKOS_INLINE_FUNCTION bool visible(const Segments<T>& crack, T px, T py, T nx, T ny) {
  const auto n = static_cast<Index>(crack.extent(0));
  for (Index s = 0; s < n; ++s)
    if (segments_cross(px, py, nx, ny, crack(s, 0), crack(s, 1), crack(s, 2), crack(s, 3))) return false;
  return true;
}

// Keeps, of a two-set list built with the largest support radius, the nodes j whose own support
// (radius dm(j)) contains point i and which point i sees past the crack.
template <class T>
struct SupportFilter {
  VecView<T, 2> points;
  VecView<T, 2> nodes;
  View1<T> dm;
  Segments<T> crack;
  KOKKOS_INLINE_FUNCTION bool operator()(Index i, Index j, Offset) const {
    const T dx = points(i, 0) - nodes(j, 0);
    const T dy = points(i, 1) - nodes(j, 1);
    if (dx * dx + dy * dy >= dm(j) * dm(j)) return false;
    return visible(crack, points(i, 0), points(i, 1), nodes(j, 0), nodes(j, 1));
  }
};

template <class T>
neighbors::NeighborList support_rows(const neighbors::NeighborList& candidates, const VecView<T, 2>& points,
                                     const VecView<T, 2>& nodes, const View1<T>& dm, const Segments<T>& crack) {
  return neighbors::filter_bonds(candidates, SupportFilter<T>{points, nodes, dm, crack});
}

// Shape functions of the points: phi(k) and dphi(k, 0..1) for the k-th entry of the rows of `rows`
// (node rows(k)); ratio(i) the moment check of point i, status(i) = 1 where it failed.
template <class T>
struct ShapeFunctions {
  neighbors::NeighborList rows;
  View1<T> phi;
  Kokkos::View<T* [2], Kokkos::LayoutRight, MemSpace> dphi;
  View1<T> ratio;
  View1<int> status;
  Index points = 0;
};

namespace detail {

// x = S^{-1} b for a symmetric 3x3 S given its inverse's adjugate form.
template <class T>
KOKKOS_INLINE_FUNCTION void sym3_inverse(const T a[3][3], T inv[3][3], T& det) {
  const T c00 = a[1][1] * a[2][2] - a[1][2] * a[2][1];
  const T c01 = a[1][2] * a[2][0] - a[1][0] * a[2][2];
  const T c02 = a[1][0] * a[2][1] - a[1][1] * a[2][0];
  det = a[0][0] * c00 + a[0][1] * c01 + a[0][2] * c02;
  const T s = T(1) / det;
  inv[0][0] = c00 * s;
  inv[1][0] = c01 * s;
  inv[2][0] = c02 * s;
  inv[0][1] = (a[0][2] * a[2][1] - a[0][1] * a[2][2]) * s;
  inv[1][1] = (a[0][0] * a[2][2] - a[0][2] * a[2][0]) * s;
  inv[2][1] = (a[0][1] * a[2][0] - a[0][0] * a[2][1]) * s;
  inv[0][2] = (a[0][1] * a[1][2] - a[0][2] * a[1][1]) * s;
  inv[1][2] = (a[0][2] * a[1][0] - a[0][0] * a[1][2]) * s;
  inv[2][2] = (a[0][0] * a[1][1] - a[0][1] * a[1][0]) * s;
}

}  // namespace detail

// seed 004 eqs. (2)-(5): phi_I(x) = p(x)^T A(x)^{-1} w_I(x) p(x_I) with A = sum_I w_I p(x_I) p(x_I)^T,
// and d phi_I / dx_k = (A^{-1}(p_,k - A_,k gamma))^T w_I p_I + gamma^T w_I,k p_I with gamma = A^{-1} p.
// The basis is taken in coordinates centred at the point and scaled by the largest support radius of
// its row (same span, so the same shape functions; the moment matrix stays O(1) whatever the units).
template <class T>
void evaluate(const VecView<T, 2>& points, const VecView<T, 2>& nodes, const View1<T>& dm, T min_ratio,
              ShapeFunctions<T>& out) {
  const auto rows = out.rows;
  const Index n = rows.num_particles;
  out.points = n;
  if (out.phi.extent(0) < static_cast<std::size_t>(rows.num_pairs) || out.phi.extent(0) == 0) {
    out.phi = View1<T>("polymech::mls::phi", static_cast<std::size_t>(rows.num_pairs) + 1);
    out.dphi = Kokkos::View<T* [2], Kokkos::LayoutRight, MemSpace>("polymech::mls::dphi",
                                                                  static_cast<std::size_t>(rows.num_pairs) + 1);
  }
  if (out.ratio.extent(0) < static_cast<std::size_t>(n) || out.ratio.extent(0) == 0) {
    out.ratio = View1<T>("polymech::mls::ratio", static_cast<std::size_t>(n) + 1);
    out.status = View1<int>("polymech::mls::status", static_cast<std::size_t>(n) + 1);
  }
  const auto phi = out.phi;
  const auto dphi = out.dphi;
  const auto ratio = out.ratio;
  const auto status = out.status;
  Kokkos::parallel_for(
      "polymech::mls::shape_functions", range(n), KOKKOS_LAMBDA(const Index i) {
        const T px = points(i, 0), py = points(i, 1);
        const Offset b = rows.offsets(i), e = rows.offsets(i + 1);
        T scale = T(0);
        for (Offset k = b; k < e; ++k) scale = kx::max(scale, dm(rows.neighbors(k)));
        if (!(scale > T(0))) scale = T(1);
        const T inv_s = T(1) / scale;
        T a[3][3] = {}, ax[3][3] = {}, ay[3][3] = {};
        for (Offset k = b; k < e; ++k) {
          const Index j = rows.neighbors(k);
          const T dx = px - nodes(j, 0), dy = py - nodes(j, 1);
          const T d = kx::sqrt(dx * dx + dy * dy);
          T w, dw;
          quartic_spline(d / dm(j), w, dw);
          const T dwx = d > T(0) ? dw * dx / (d * dm(j)) : T(0);
          const T dwy = d > T(0) ? dw * dy / (d * dm(j)) : T(0);
          const T p[3] = {T(1), -dx * inv_s, -dy * inv_s};
          for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
              a[r][c] += w * p[r] * p[c];
              ax[r][c] += dwx * p[r] * p[c];
              ay[r][c] += dwy * p[r] * p[c];
            }
        }
        const T diag = a[0][0] * a[1][1] * a[2][2];
        T inv[3][3], det = T(0);
        T q = T(0);
        if (diag > T(0)) {
          detail::sym3_inverse(a, inv, det);
          q = det / diag;
        }
        ratio(i) = q;
        if (!(q >= min_ratio) || !(q > T(0))) {
          status(i) = 1;
          for (Offset k = b; k < e; ++k) {
            phi(k) = T(0);
            dphi(k, 0) = T(0);
            dphi(k, 1) = T(0);
          }
          return;
        }
        status(i) = 0;
        // gamma = A^{-1} p(x), p(x) = (1, 0, 0) in the centred basis; p_,x = (0, 1/s, 0), p_,y = (0, 0, 1/s)
        T g[3], gx[3], gy[3];
        for (int r = 0; r < 3; ++r) g[r] = inv[r][0];
        T rx[3], ry[3];
        for (int r = 0; r < 3; ++r) {
          rx[r] = (r == 1 ? inv_s : T(0)) - (ax[r][0] * g[0] + ax[r][1] * g[1] + ax[r][2] * g[2]);
          ry[r] = (r == 2 ? inv_s : T(0)) - (ay[r][0] * g[0] + ay[r][1] * g[1] + ay[r][2] * g[2]);
        }
        for (int r = 0; r < 3; ++r) {
          gx[r] = inv[r][0] * rx[0] + inv[r][1] * rx[1] + inv[r][2] * rx[2];
          gy[r] = inv[r][0] * ry[0] + inv[r][1] * ry[1] + inv[r][2] * ry[2];
        }
        for (Offset k = b; k < e; ++k) {
          const Index j = rows.neighbors(k);
          const T dx = px - nodes(j, 0), dy = py - nodes(j, 1);
          const T d = kx::sqrt(dx * dx + dy * dy);
          T w, dw;
          quartic_spline(d / dm(j), w, dw);
          const T dwx = d > T(0) ? dw * dx / (d * dm(j)) : T(0);
          const T dwy = d > T(0) ? dw * dy / (d * dm(j)) : T(0);
          const T p1 = -dx * inv_s, p2 = -dy * inv_s;
          const T gp = g[0] + g[1] * p1 + g[2] * p2;
          phi(k) = w * gp;
          dphi(k, 0) = dwx * gp + w * (gx[0] + gx[1] * p1 + gx[2] * p2);
          dphi(k, 1) = dwy * gp + w * (gy[0] + gy[1] * p1 + gy[2] * p2);
        }
      });
}

// The number of flagged points and the first of them (-1: none).
inline Index first_flagged(const View1<int>& status, Index n, Index& count) {
  Index first = n;
  Kokkos::parallel_reduce(
      "polymech::mls::first_flagged", range(n),
      KOKKOS_LAMBDA(const Index i, Index& lo) {
        if (status(i) != 0 && i < lo) lo = i;
      },
      Kokkos::Min<Index>(first));
  Index c = 0;
  Kokkos::parallel_reduce(
      "polymech::mls::count_flagged", range(n), KOKKOS_LAMBDA(const Index i, Index& cnt) { cnt += status(i) != 0 ? 1 : 0; },
      c);
  count = c;
  return first < n ? first : Index(-1);
}

}  // namespace polymech::mls
