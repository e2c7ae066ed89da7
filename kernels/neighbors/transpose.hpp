// The transpose of a half neighbour list: for each particle j, the entries k of the list whose
// neighbour is j (the pairs (i, j), i < j, of which j is the second member), in increasing k. A pair
// kernel over a half list computes each pair once and adds to its first member; the second member
// then gathers from its transposed entries in a fixed order: no atomics in the force kernels, and the
// sums do not depend on the thread count (kernels/dem/contact_forces.hpp).
//
//   neighbors::ListTranspose t;
//   neighbors::transpose(list, t);               // after each rebuild of the list
//   for (Offset e = t.begin(j); e < t.end(j); ++e) { const Offset k = t.entry(e); ... }
#pragma once

#include "neighbors/neighbor_list.hpp"
#include "neighbors/neighbor_search.hpp"

namespace polymech::neighbors {

struct ListTranspose {
  Kokkos::View<Offset*, MemSpace> offsets;  // num_particles + 1
  Kokkos::View<Offset*, MemSpace> entries;  // list entries k, grouped by their neighbour
  Kokkos::View<Offset*, MemSpace> cursor;   // fill counters (scratch)

  KOKKOS_INLINE_FUNCTION Offset begin(Index j) const { return offsets(j); }
  KOKKOS_INLINE_FUNCTION Offset end(Index j) const { return offsets(j + 1); }
  KOKKOS_INLINE_FUNCTION Offset entry(Offset e) const { return entries(e); }
};

// Kernels "polymech::neighbors::transpose_count", "..._fill", "..._sort": count the entries per
// neighbour, scan, fill (atomic cursors: any order), then sort each group by k (insertion sort: a
// group holds a particle's few lower-index contacts), so the result is the same for any thread count.
// `targets`: the number of points the neighbour indices refer to, for a two-set list (spheres -> facets:
// for each facet the entries that list it); < 0: the list's own particles.
inline void transpose(const NeighborList& list, ListTranspose& out, Index targets = -1) {
  const Index n = targets >= 0 ? targets : list.num_particles;
  const Index rows = list.num_particles;
  const auto un = static_cast<std::size_t>(n);
  if (out.offsets.extent(0) < un + 1) {
    out.offsets = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::transpose_offsets", un + 1);
    out.cursor = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::transpose_cursor", un + 1);
  }
  if (out.entries.extent(0) < static_cast<std::size_t>(list.num_pairs))
    out.entries = Kokkos::View<Offset*, MemSpace>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::neighbors::transpose_entries")),
                                                  static_cast<std::size_t>(list.num_pairs + list.num_pairs / 8 + 16));
  const auto offsets = out.offsets, cursor = out.cursor, entries = out.entries;
  Kokkos::deep_copy(offsets, Offset(0));
  Kokkos::deep_copy(cursor, Offset(0));
  Kokkos::parallel_for(
      "polymech::neighbors::transpose_count", range(rows), KOKKOS_LAMBDA(const Index i) {
        for (Offset k = list.begin(i); k < list.end(i); ++k) Kokkos::atomic_increment(&offsets(list.neighbor(k) + 1));
      });
  detail::scan_offsets(offsets, n);
  Kokkos::parallel_for(
      "polymech::neighbors::transpose_fill", range(rows), KOKKOS_LAMBDA(const Index i) {
        for (Offset k = list.begin(i); k < list.end(i); ++k) {
          const Index j = list.neighbor(k);
          entries(offsets(j) + Kokkos::atomic_fetch_add(&cursor(j), Offset(1))) = k;
        }
      });
  Kokkos::parallel_for(
      "polymech::neighbors::transpose_sort", range(n), KOKKOS_LAMBDA(const Index j) {
        for (Offset a = offsets(j) + 1; a < offsets(j + 1); ++a) {
          const Offset v = entries(a);
          Offset b = a;
          for (; b > offsets(j) && entries(b - 1) > v; --b) entries(b) = entries(b - 1);
          entries(b) = v;
        }
      });
}

}  // namespace polymech::neighbors
