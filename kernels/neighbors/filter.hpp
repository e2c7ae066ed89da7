// Remove bonds from a CSR list: keeps the bonds k = (i, j) for which keep(i, j, k) is true, in the
// same order. Used to cut a reference family along a crack (seed 000 §4: the elastic operators do not
// act across the crack faces), or to drop any other set of bonds decided at set-up.
#pragma once

#include "neighbors/neighbor_loop.hpp"

namespace polymech::neighbors {

namespace detail {

template <class Keep>
struct FilterCount {
  NeighborList src;
  Keep keep;
  Kokkos::View<Offset*, MemSpace> offsets;
  struct Accumulator {
    Offset count;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {0}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset k) const { acc.count += keep(i, j, k) ? 1 : 0; }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { offsets(i + 1) = acc.count; }
};

template <class Keep>
struct FilterFill {
  NeighborList src;
  Keep keep;
  Kokkos::View<Offset*, MemSpace> offsets;
  Kokkos::View<Index*, MemSpace> neighbors;
  struct Accumulator {
    Offset slot;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {offsets(i)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset k) const {
    if (keep(i, j, k)) neighbors(acc.slot++) = j;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index, Accumulator&) const {}
};

}  // namespace detail

// keep: a device-callable functor bool(Index i, Index j, Offset k).
template <class Keep>
NeighborList filter_bonds(const NeighborList& in, const Keep& keep) {
  NeighborList out;
  const Index n = in.num_particles;
  out.num_particles = n;
  out.radius = in.radius;
  out.kind = in.kind;
  out.offsets = Kokkos::View<Offset*, MemSpace>("polymech::neighbors::filtered_offsets", static_cast<std::size_t>(n) + 1);
  auto offsets = out.offsets;
  for_each_row("polymech::neighbors::filter_count", in, detail::FilterCount<Keep>{in, keep, offsets});
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
  for_each_row("polymech::neighbors::filter_fill", in, detail::FilterFill<Keep>{in, keep, offsets, out.neighbors});
  out.num_pairs = total;
  return out;
}

}  // namespace polymech::neighbors
