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

// Visit every particle j in the 3^D cells around x_i whose distance to x_i is <= radius (j != i,
// and j > i for half lists), in a fixed order: cells lexicographically, then ascending index.
template <class T, int D, class PositionView, class Visit>
KOKKOS_INLINE_FUNCTION void for_each_candidate(const CellGrid<T, D>& grid, const PositionView& x, Index i,
                                               T radius2, bool half, Visit&& visit) {
  Vec<T, D> xi;
  std::int64_t c[D];
  for (int k = 0; k < D; ++k) {
    xi[k] = x(i, k);
    c[k] = grid.cell_coord(xi[k], k);
  }
  std::int64_t lo[D], hi[D];
  for (int k = 0; k < D; ++k) {
    lo[k] = c[k] > 0 ? c[k] - 1 : 0;
    hi[k] = c[k] + 1 < grid.dims[k] ? c[k] + 1 : grid.dims[k] - 1;
  }
  std::int64_t cc[D];
  if constexpr (D == 2) {
    for (cc[1] = lo[1]; cc[1] <= hi[1]; ++cc[1])
      for (cc[0] = lo[0]; cc[0] <= hi[0]; ++cc[0]) {
        const std::int64_t l = grid.linear(cc);
        for (Offset a = grid.cell_start(l); a < grid.cell_start(l + 1); ++a) {
          const Index j = grid.cell_particles(a);
          if (j == i || (half && j < i)) continue;
          T r2 = T(0);
          for (int k = 0; k < D; ++k) {
            const T d = x(j, k) - xi[k];
            r2 += d * d;
          }
          if (r2 <= radius2) visit(j);
        }
      }
  } else {
    for (cc[2] = lo[2]; cc[2] <= hi[2]; ++cc[2])
      for (cc[1] = lo[1]; cc[1] <= hi[1]; ++cc[1])
        for (cc[0] = lo[0]; cc[0] <= hi[0]; ++cc[0]) {
          const std::int64_t l = grid.linear(cc);
          for (Offset a = grid.cell_start(l); a < grid.cell_start(l + 1); ++a) {
            const Index j = grid.cell_particles(a);
            if (j == i || (half && j < i)) continue;
            T r2 = T(0);
            for (int k = 0; k < D; ++k) {
              const T d = x(j, k) - xi[k];
              r2 += d * d;
            }
            if (r2 <= radius2) visit(j);
          }
        }
  }
}

}  // namespace detail

// Builds neighbour lists; keeps the cell grid and list storage between builds so a rebuild in a
// time loop allocates nothing unless the list grows.
template <class T, int D>
class NeighborSearch {
 public:
  // Lists every pair within `radius` of the positions x into `out` (resized only when it grows).
  void build(const VecView<T, D>& x, T radius, ListKind kind, NeighborList& out) {
    const auto n = static_cast<Index>(x.extent(0));
    bin_particles<T, D>(grid_, x, radius);
    if (out.offsets.extent(0) < static_cast<std::size_t>(n) + 1)
      out.offsets = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::offsets", static_cast<std::size_t>(n) + 1);

    const CellGrid<T, D> grid = grid_;
    const T radius2 = radius * radius;
    const bool half = kind == ListKind::half;
    auto offsets = out.offsets;
    Kokkos::parallel_for(
        "polymech::neighbors::count", range(n), KOKKOS_LAMBDA(const Index i) {
          Offset count = 0;
          detail::for_each_candidate<T, D>(grid, x, i, radius2, half, [&](Index) { ++count; });
          offsets(i + 1) = count;
        });
    Offset total = 0;
    Kokkos::parallel_scan(
        "polymech::neighbors::scan", range(static_cast<std::int64_t>(n) + 1),
        KOKKOS_LAMBDA(const std::int64_t i, Offset& partial, const bool final) {
          const Offset c = i == 0 ? Offset(0) : offsets(i);
          partial += c;
          if (final) offsets(i) = partial;
        },
        total);
    if (out.neighbors.extent(0) < static_cast<std::size_t>(total))
      out.neighbors = Kokkos::View<Index*, MemSpace>(
          Kokkos::view_alloc(Kokkos::WithoutInitializing, "polymech::neighbors::neighbors"),
          static_cast<std::size_t>(total + total / 8 + 16));
    auto neighbors = out.neighbors;
    Kokkos::parallel_for(
        "polymech::neighbors::fill", range(n), KOKKOS_LAMBDA(const Index i) {
          Offset slot = offsets(i);
          detail::for_each_candidate<T, D>(grid, x, i, radius2, half, [&](Index j) { neighbors(slot++) = j; });
        });
    out.num_particles = n;
    out.num_pairs = total;
    out.radius = static_cast<double>(radius);
    out.kind = kind;
  }

  const CellGrid<T, D>& grid() const { return grid_; }

 private:
  CellGrid<T, D> grid_;
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
