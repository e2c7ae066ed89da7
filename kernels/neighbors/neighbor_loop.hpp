// The neighbour loop every particle method runs: for each particle i, gather over its row of a
// neighbour list (a reference bond family or a list of the current positions). The loop strategy is
// chosen here, by a tag, and the physics is a functor, so a team-parallel variant (or a vectorised
// one) is tried by benchmark in one place for every method instead of in each hand-written loop.
//
// A physics functor defines
//
//   using Accumulator = ...;                                                // i's loads and its sums
//   KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const;                // load i, zero the sums
//   KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset k) const;  // bond k = (i, j)
//   KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const;   // write i's results
//
// and, to run with TeamNeighbors, a static join that adds the sums of one accumulator into another:
//
//   KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from);
//
// pair() may write per-bond outputs (index k) and skip bonds (return early); finish() may loop over
// the row again (a rare second pass). With SerialNeighbors the pairs of a row are visited in list
// order by one thread, so results are bitwise the same with any number of threads.
//
// pair(), finish() and gather_row are force-inlined, and the accumulator is never copied: where GCC
// kept one of them as a call or copied the accumulator, it lived on the stack and the NOSB
// deformation-gradient pass (a 30-double accumulator) ran 20-30 % slower than the hand-written loop
// it replaced (docs/PERFORMANCE.md, "The shared neighbour loop").
#pragma once

#include <cstddef>

#include "neighbors/neighbor_list.hpp"

namespace polymech::neighbors {

// One work item per particle; its neighbours in a serial loop, in list order (the default).
struct SerialNeighbors {};

// One team per particle; the row's bonds are dealt round-robin to the team's threads, whose partial
// sums are joined in thread order by one thread of the team (deterministic for a fixed team size).
// team_size 0: Kokkos' recommendation for the functor.
struct TeamNeighbors {
  int team_size = 0;
};

// The serial gather of row i into acc (device code; also the inner loop of nested uses such as probes).
template <class Physics>
KOKKOS_FORCEINLINE_FUNCTION void gather_row(const NeighborList& list, Index i, const Physics& physics,
                                       typename Physics::Accumulator& acc) {
  for (Offset k = list.begin(i); k < list.end(i); ++k) physics.pair(acc, i, list.neighbor(k), k);
}

namespace detail {

template <class Physics>
struct SerialRows {
  NeighborList list;
  Physics physics;
  KOKKOS_INLINE_FUNCTION void operator()(const Index i) const {
    typename Physics::Accumulator acc = physics.start(i);
    gather_row(list, i, physics, acc);
    physics.finish(i, acc);
  }
};

template <class Physics>
struct TeamRows {
  using Accumulator = typename Physics::Accumulator;
  using Member = typename Kokkos::TeamPolicy<ExecSpace>::member_type;
  NeighborList list;
  Physics physics;
  KOKKOS_INLINE_FUNCTION void operator()(const Member& team) const {
    const Index i = static_cast<Index>(team.league_rank());
    const int size = team.team_size(), rank = team.team_rank();
    Accumulator mine = physics.start(i);
    for (Offset k = list.begin(i) + rank; k < list.end(i); k += size) physics.pair(mine, i, list.neighbor(k), k);
    auto* parts = static_cast<Accumulator*>(team.team_shmem().get_shmem(sizeof(Accumulator) * static_cast<std::size_t>(size)));
    parts[rank] = mine;
    team.team_barrier();
    Kokkos::single(Kokkos::PerTeam(team), [&]() {
      Accumulator total = parts[0];
      for (int t = 1; t < size; ++t) Physics::join(total, parts[t]);
      physics.finish(i, total);
    });
  }
};

}  // namespace detail

// Gather over every row of `list` with the chosen strategy; one Kokkos kernel named `label`.
template <class Physics>
void for_each_row(const char* label, const NeighborList& list, const Physics& physics, SerialNeighbors = {}) {
  Kokkos::parallel_for(label, range(list.num_particles), detail::SerialRows<Physics>{list, physics});
}

template <class Physics>
void for_each_row(const char* label, const NeighborList& list, const Physics& physics, TeamNeighbors strategy) {
  using Policy = Kokkos::TeamPolicy<ExecSpace>;
  const detail::TeamRows<Physics> rows{list, physics};
  int size = strategy.team_size;
  if (size <= 0) size = Policy(list.num_particles, 1).team_size_recommended(rows, Kokkos::ParallelForTag());
  const auto bytes = sizeof(typename Physics::Accumulator) * static_cast<std::size_t>(size);
  Kokkos::parallel_for(label, Policy(list.num_particles, size).set_scratch_size(0, Kokkos::PerTeam(bytes)), rows);
}

}  // namespace polymech::neighbors
