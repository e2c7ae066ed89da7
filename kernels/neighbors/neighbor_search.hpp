// Neighbour-list construction on the uniform cell grid: count, scan, fill.
//
// Pairs with |x_j - x_i| <= radius are listed (inclusive, so particles exactly at the cut-off are
// neighbours; kernels whose weight vanishes at the cut-off are unaffected). Work is O(N) for a
// bounded number of particles per cell; the workspace is kept between builds and only grows.
#pragma once

#include <string>

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/cell_grid.hpp"
#include "neighbors/neighbor_list.hpp"

namespace polymech::neighbors {

namespace detail {

// Visit every point j of x in the 3^D cells around the position xi whose distance to xi is <= radius,
// except `self` and, for half lists, j < self, in a fixed order: cells lexicographically (the first
// coordinate fastest), then ascending index. visit(j, r2) gets the squared distance.
template <class T, int D, class PositionView, class Visit>
KOKKOS_INLINE_FUNCTION void for_each_point_near(const CellGrid<T, D>& grid, const PositionView& x, const Vec<T, D>& xi,
                                                Index self, T radius2, bool half, Visit&& visit) {
  std::int64_t lo[D], hi[D], cc[D];
  for (int k = 0; k < D; ++k) {
    const std::int64_t c = grid.cell_coord(xi[k], k);
    lo[k] = c > 0 ? c - 1 : 0;
    hi[k] = c + 1 < grid.dims[k] ? c + 1 : grid.dims[k] - 1;
    cc[k] = lo[k];
  }
  // The cells lo[0]..hi[0] along the first axis are consecutive in the grid's order, so their points are
  // one run of cell_particles (cell by cell, each in ascending index): one loop over the run per row of
  // cells, not one per cell (the same points in the same order, a third of the loops' overhead in 3D).
  const std::int64_t run = hi[0] - lo[0] + 1;
  while (true) {
    const std::int64_t l = grid.linear(cc);
    const Offset end = grid.cell_start(l + run);
    for (Offset a = grid.cell_start(l); a < end; ++a) {
      const Index j = grid.cell_particles(a);
      if (j == self || (half && j < self)) continue;
      T r2 = T(0);
      for (int k = 0; k < D; ++k) {
        const T d = x(j, k) - xi[k];
        r2 += d * d;
      }
      if (r2 <= radius2) visit(j, r2);
    }
    int k = 1;
    while (k < D && ++cc[k] > hi[k]) {
      cc[k] = lo[k];
      ++k;
    }
    if (k == D) break;
  }
}

// offsets(i + 1) holds row i's count; turns them into row starts, returns the total. (A free
// function: under CUDA a KOKKOS_LAMBDA may not sit in a private member.)
inline Offset scan_offsets(const Kokkos::View<Offset*, MemSpace>& offsets, Index n) {
  Offset total = 0;
  Kokkos::parallel_scan(
      "polymech::neighbors::scan", range(static_cast<std::int64_t>(n) + 1),
      KOKKOS_LAMBDA(const std::int64_t i, Offset& partial, const bool final) {
        const Offset c = i == 0 ? Offset(0) : offsets(i);
        partial += c;
        if (final) offsets(i) = partial;
      },
      total);
  return total;
}

inline void reserve_neighbors(NeighborList& out, Offset total) {
  if (out.neighbors.extent(0) < static_cast<std::size_t>(total))
    out.neighbors = Kokkos::View<Index*, MemSpace>(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, "polymech::neighbors::neighbors"),
        static_cast<std::size_t>(total + total / 8 + 16));
}

// Query points of a search: a point set's own particles (excluding themselves) or another set.
template <class T, int D>
struct SelfQueries {
  VecView<T, D> x;
  KOKKOS_INLINE_FUNCTION Vec<T, D> position(Index i) const { return load<D>(x, i); }
  KOKKOS_INLINE_FUNCTION Index self(Index i) const { return i; }
};
template <class T, int D>
struct OtherQueries {
  VecView<T, D> x;
  KOKKOS_INLINE_FUNCTION Vec<T, D> position(Index i) const { return load<D>(x, i); }
  KOKKOS_INLINE_FUNCTION Index self(Index) const { return Index(-1); }
};

// The rows of `out` for n queries against the binned points: count, scan, fill. With `sizes` (one set
// only: sizes of the points), a pair is listed only within sizes(i) + sizes(j) + margin (<= radius).
// With a scratch of `capacity` entries per row, the count pass keeps each row's first `capacity`
// neighbours and the fill copies them (a row that has more is searched again): one search, not two,
// for short rows (the DEM's sphere pairs), the same list.
template <class T, int D, class Queries>
void list_rows(const CellGrid<T, D>& grid, const VecView<T, D>& points, const Queries& queries, Index n, T radius,
               bool half, NeighborList& out, const View1<T>& sizes = View1<T>(), T margin = T(0),
               const Kokkos::View<Index*, MemSpace>& scratch = Kokkos::View<Index*, MemSpace>(), int capacity = 0) {
  if (out.offsets.extent(0) < static_cast<std::size_t>(n) + 1)
    out.offsets = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::offsets", static_cast<std::size_t>(n) + 1);
  const T radius2 = radius * radius;
  const bool sized = sizes.extent(0) > 0;
  const Offset cap = scratch.extent(0) >= static_cast<std::size_t>(n) * static_cast<std::size_t>(capacity) ? capacity : 0;
  auto offsets = out.offsets;
  Kokkos::parallel_for(
      "polymech::neighbors::count", range(n), KOKKOS_LAMBDA(const Index i) {
        Offset count = 0;
        const T si = sized ? sizes(i) + margin : T(0);
        const Offset row = static_cast<Offset>(i) * cap;
        for_each_point_near<T, D>(grid, points, queries.position(i), queries.self(i), radius2, half, [&](Index j, T r2) {
          if (sized) {
            const T c = si + sizes(j);
            if (r2 > c * c) return;
          }
          if (count < cap) scratch(row + count) = j;
          ++count;
        });
        offsets(i + 1) = count;
      });
  const Offset total = scan_offsets(offsets, n);
  reserve_neighbors(out, total);
  auto neighbors = out.neighbors;
  Kokkos::parallel_for(
      "polymech::neighbors::fill", range(n), KOKKOS_LAMBDA(const Index i) {
        Offset slot = offsets(i);
        if (offsets(i + 1) - slot <= cap) {  // the row is in the scratch
          const Offset row = static_cast<Offset>(i) * cap;
          for (Offset m = 0; slot < offsets(i + 1); ++m) neighbors(slot++) = scratch(row + m);
          return;
        }
        const T si = sized ? sizes(i) + margin : T(0);
        for_each_point_near<T, D>(grid, points, queries.position(i), queries.self(i), radius2, half, [&](Index j, T r2) {
          if (sized) {
            const T c = si + sizes(j);
            if (r2 > c * c) return;
          }
          neighbors(slot++) = j;
        });
      });
  out.num_particles = n;
  out.num_pairs = total;
  out.radius = static_cast<double>(radius);
}

}  // namespace detail

// Builds neighbour lists; keeps the cell grid and list storage between builds so a rebuild in a
// time loop allocates nothing unless the list grows.
template <class T, int D>
class NeighborSearch {
 public:
  // Lists every pair within `radius` of the positions x into `out` (resized only when it grows). With
  // `sizes` (one per point, e.g. sphere radii), only the pairs within sizes(i) + sizes(j) + margin, which
  // must not exceed radius (the cells' size).
  void build(const VecView<T, D>& x, T radius, ListKind kind, NeighborList& out, const View1<T>& sizes = View1<T>(),
             T margin = T(0)) {
    bin_particles<T, D>(grid_, x, radius);
    const auto need = x.extent(0) * static_cast<std::size_t>(row_capacity_);
    if (scratch_.extent(0) < need)
      scratch_ = Kokkos::View<Index*, MemSpace>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::neighbors::row_scratch")), need);
    detail::list_rows<T, D>(grid_, x, detail::SelfQueries<T, D>{x}, static_cast<Index>(x.extent(0)), radius,
                            kind == ListKind::half, out, sizes, margin, scratch_, row_capacity_);
    out.kind = kind;
  }

  // A search of one point set against another: for every query point i, the points j of `points`
  // within `radius` (quadrature points against nodes, spheres against facets, fluid particles against
  // wall integration points). Rows are ordered as in build(); the list is full by construction.
  void build_between(const VecView<T, D>& queries, const VecView<T, D>& points, T radius, NeighborList& out) {
    bin_particles<T, D>(grid_, points, radius);
    detail::list_rows<T, D>(grid_, points, detail::OtherQueries<T, D>{queries}, static_cast<Index>(queries.extent(0)),
                            radius, false, out);
    out.kind = ListKind::full;
  }

  const CellGrid<T, D>& grid() const { return grid_; }
  // build() keeps up to `capacity` neighbours per row from its count pass (capacity x points indices of
  // scratch): rows no longer than that are not searched twice. 0 (the default): no scratch.
  void set_row_capacity(int capacity) { row_capacity_ = capacity > 0 ? capacity : 0; }

 private:
  CellGrid<T, D> grid_;
  int row_capacity_ = 0;
  Kokkos::View<Index*, MemSpace> scratch_;
};

// Reference-configuration bond family: the neighbours within `radius` of the initial positions.
template <class T, int D>
BondFamily build_bond_family(const VecView<T, D>& x0, T radius, ListKind kind = ListKind::full) {
  NeighborSearch<T, D> search;
  BondFamily family;
  search.build(x0, radius, kind, family);
  return family;
}

}  // namespace polymech::neighbors
