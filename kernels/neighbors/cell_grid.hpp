// Uniform-grid cell binning: particles sorted by cell, cell_start in CSR form.
//
// The grid covers the particles' bounding box with cubic cells of edge >= the search radius, so the
// 3^D cells around a particle's cell hold every particle within the radius. Within a cell particles
// are ordered by index, which makes everything built on the grid independent of the thread count.
#pragma once

#include <cstdint>
#include <string>

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::neighbors {

template <class T, int D>
struct CellGrid {
  Vec<T, D> origin{};          // lower corner of the bounding box
  T cell_size = T(0);          // cell edge, >= the search radius
  std::int64_t dims[D] = {};   // cells per direction
  std::int64_t num_cells = 0;
  Kokkos::View<Offset*, MemSpace> cell_start;     // num_cells + 1
  Kokkos::View<Index*, MemSpace> cell_particles;  // particle indices, grouped by cell
  Kokkos::View<Index*, MemSpace> particle_cell;   // cell of each particle
  Kokkos::View<Offset*, MemSpace> cursor;         // workspace of the fill pass

  KOKKOS_INLINE_FUNCTION std::int64_t cell_coord(T xk, int k) const {
    auto c = static_cast<std::int64_t>(kx::floor((xk - origin[k]) / cell_size));
    return c < 0 ? 0 : (c >= dims[k] ? dims[k] - 1 : c);
  }
  KOKKOS_INLINE_FUNCTION std::int64_t linear(const std::int64_t (&c)[D]) const {
    std::int64_t l = c[D - 1];
    for (int k = D - 2; k >= 0; --k) l = l * dims[k] + c[k];
    return l;
  }
};

namespace detail {

template <class T, int D>
struct Bounds {
  T lo[D], hi[D];
};

// Axis-aligned bounding box of the points (one reduction per direction keeps the code to reducers
// that exist from Kokkos 3.4 on).
template <class T, int D>
Bounds<T, D> bounding_box(const VecView<T, D>& x) {
  Bounds<T, D> b{};
  const auto n = static_cast<std::int64_t>(x.extent(0));
  for (int k = 0; k < D; ++k) {
    T lo = T(0), hi = T(0);
    Kokkos::parallel_reduce(
        "polymech::neighbors::bounds", range(n),
        KOKKOS_LAMBDA(const std::int64_t i, T& l, T& h) {
          l = x(i, k) < l ? x(i, k) : l;
          h = x(i, k) > h ? x(i, k) : h;
        },
        Kokkos::Min<T>(lo), Kokkos::Max<T>(hi));
    b.lo[k] = lo;
    b.hi[k] = hi;
  }
  return b;
}

template <class V>
void ensure_size(V& v, std::size_t n, const char* label) {
  if (v.extent(0) < n) v = V(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), n + n / 8 + 16);
}

}  // namespace detail

// Cell edge and grid dimensions for a radius; the edge grows when the bounding box would need more
// than max_cells cells (sparse clouds with far outliers), which keeps memory bounded.
template <class T, int D>
void size_grid(CellGrid<T, D>& g, const detail::Bounds<T, D>& b, T radius, std::int64_t max_cells) {
  T h = radius > T(0) ? radius : T(1);
  bool sized = false;
  for (int attempt = 0; attempt < 64 && !sized; ++attempt) {
    std::int64_t total = 1;
    bool fits = true;
    for (int k = 0; k < D && fits; ++k) {
      const double extent = static_cast<double>(b.hi[k]) - static_cast<double>(b.lo[k]);
      const double cells = extent / static_cast<double>(h) + 1.0;  // in double: no integer overflow
      g.dims[k] = cells > static_cast<double>(max_cells) ? max_cells + 1 : static_cast<std::int64_t>(cells);
      fits = total <= max_cells / g.dims[k];
      if (fits) total *= g.dims[k];
    }
    if (fits && total <= max_cells) {
      g.num_cells = total;
      sized = true;
    } else {
      h *= T(1.5);
    }
  }
  if (!sized) {  // unreachable for finite coordinates (h grew by 1.5^64); one cell is always correct
    for (int k = 0; k < D; ++k) g.dims[k] = 1;
    g.num_cells = 1;
    const double span = static_cast<double>(b.hi[0]) - static_cast<double>(b.lo[0]);
    h = static_cast<T>(span > 0 ? span : 1.0);
  }
  g.cell_size = h;
  for (int k = 0; k < D; ++k) g.origin[k] = b.lo[k];
}

// Bin the points into the grid (counting sort by cell, then sort each cell by index).
template <class T, int D>
void bin_particles(CellGrid<T, D>& g, const VecView<T, D>& x, T radius) {
  const auto n = static_cast<std::int64_t>(x.extent(0));
  detail::Bounds<T, D> b{};
  if (n > 0) b = detail::bounding_box<T, D>(x);
  const std::int64_t max_cells = 4 * n + 64;
  size_grid<T, D>(g, b, radius, max_cells);

  detail::ensure_size(g.particle_cell, static_cast<std::size_t>(n), "polymech::neighbors::particle_cell");
  detail::ensure_size(g.cell_particles, static_cast<std::size_t>(n), "polymech::neighbors::cell_particles");
  detail::ensure_size(g.cursor, static_cast<std::size_t>(g.num_cells), "polymech::neighbors::cursor");
  if (g.cell_start.extent(0) < static_cast<std::size_t>(g.num_cells + 1))
    g.cell_start = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::cell_start", g.num_cells + 1 + g.num_cells / 8);
  else
    Kokkos::deep_copy(Kokkos::subview(g.cell_start, Kokkos::pair<std::int64_t, std::int64_t>(0, g.num_cells + 1)), Offset(0));

  const CellGrid<T, D> grid = g;  // device copy of the geometry and views
  auto cell_start = g.cell_start;
  auto particle_cell = g.particle_cell;
  auto cell_particles = g.cell_particles;
  const std::int64_t ncell = g.num_cells;

  // counts land in cell_start(c + 1) so an inclusive scan gives the start offsets directly
  Kokkos::parallel_for(
      "polymech::neighbors::bin_count", range(n), KOKKOS_LAMBDA(const std::int64_t i) {
        std::int64_t c[D];
        for (int k = 0; k < D; ++k) c[k] = grid.cell_coord(x(i, k), k);
        const std::int64_t l = grid.linear(c);
        particle_cell(i) = static_cast<Index>(l);
        Kokkos::atomic_add(&cell_start(l + 1), Offset(1));
      });
  Kokkos::parallel_scan(
      "polymech::neighbors::bin_scan", range(ncell + 1),
      KOKKOS_LAMBDA(const std::int64_t c, Offset& partial, const bool final) {
        partial += cell_start(c);
        if (final) cell_start(c) = partial;
      });
  // fill through a per-cell cursor; the order atomics give is fixed by the sort below
  auto cursor = g.cursor;
  Kokkos::parallel_for(
      "polymech::neighbors::bin_cursor", range(ncell), KOKKOS_LAMBDA(const std::int64_t c) { cursor(c) = cell_start(c); });
  Kokkos::parallel_for(
      "polymech::neighbors::bin_fill", range(n), KOKKOS_LAMBDA(const std::int64_t i) {
        const Offset slot = Kokkos::atomic_fetch_add(&cursor(particle_cell(i)), Offset(1));
        cell_particles(slot) = static_cast<Index>(i);
      });
  // insertion sort inside each cell: cells hold a handful of particles
  Kokkos::parallel_for(
      "polymech::neighbors::bin_sort", range(ncell), KOKKOS_LAMBDA(const std::int64_t c) {
        const Offset b0 = cell_start(c), e0 = cell_start(c + 1);
        for (Offset a = b0 + 1; a < e0; ++a) {
          const Index v = cell_particles(a);
          Offset k = a;
          while (k > b0 && cell_particles(k - 1) > v) {
            cell_particles(k) = cell_particles(k - 1);
            --k;
          }
          cell_particles(k) = v;
        }
      });
}

}  // namespace polymech::neighbors
