// Remove bonds from a CSR list: keeps the pairs (i, j) for which keep(i, j) is true, in the same
// order. Used to cut a reference family along a crack (seed 000 §4: the elastic operators do not act
// across the crack faces), or to drop any other set of bonds decided at set-up.
#pragma once

#include "neighbors/neighbor_list.hpp"

namespace polymech::neighbors {

// keep: a device-callable functor bool(Index i, Index j).
template <class Keep>
NeighborList filter_bonds(const NeighborList& in, const Keep& keep) {
  NeighborList out;
  const Index n = in.num_particles;
  out.num_particles = n;
  out.radius = in.radius;
  out.kind = in.kind;
  out.offsets = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::filtered_offsets", static_cast<std::size_t>(n) + 1);
  auto offsets = out.offsets;
  const NeighborList src = in;
  Kokkos::parallel_for(
      "polymech::neighbors::filter_count", range(n), KOKKOS_LAMBDA(const Index i) {
        Offset c = 0;
        for (Offset k = src.begin(i); k < src.end(i); ++k) c += keep(i, src.neighbor(k)) ? 1 : 0;
        offsets(i + 1) = c;
      });
  Offset total = 0;
  Kokkos::parallel_scan(
      "polymech::neighbors::filter_scan", range(static_cast<std::int64_t>(n) + 1),
      KOKKOS_LAMBDA(const std::int64_t i, Offset& partial, const bool final) {
        partial += i == 0 ? Offset(0) : offsets(i);
        if (final) offsets(i) = partial;
      },
      total);
  out.neighbors = Kokkos::View<Index*, MemSpace>(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, "polymech::neighbors::filtered_neighbors"),
      static_cast<std::size_t>(total));
  auto neighbors = out.neighbors;
  Kokkos::parallel_for(
      "polymech::neighbors::filter_fill", range(n), KOKKOS_LAMBDA(const Index i) {
        Offset slot = offsets(i);
        for (Offset k = src.begin(i); k < src.end(i); ++k) {
          const Index j = src.neighbor(k);
          if (keep(i, j)) neighbors(slot++) = j;
        }
      });
  out.num_pairs = total;
  return out;
}

}  // namespace polymech::neighbors
