// CSR neighbour lists: for particle i, neighbors(offsets(i)) .. neighbors(offsets(i+1)-1).
//
// One representation serves every method (MPS, SPH, peridynamics, EFG support search, DEM broad
// phase). A full list holds both (i, j) and (j, i); a half list only j > i, for kernels that apply
// a pair force to both ends (atomics or a scatter view). Within a row, neighbours are ordered by
// cell, then by index, so a list built with 1 or N threads is the same list.
#pragma once

#include "core/types.hpp"

namespace polymech::neighbors {

enum class ListKind { full, half };

struct NeighborList {
  Kokkos::View<Offset*, MemSpace> offsets;  // num_particles + 1 entries
  Kokkos::View<Index*, MemSpace> neighbors;  // capacity >= num_pairs
  Index num_particles = 0;
  Offset num_pairs = 0;  // entries in use: offsets(num_particles)
  double radius = 0.0;   // pairs with |x_j - x_i| <= radius are listed (inclusive)
  ListKind kind = ListKind::full;

  KOKKOS_INLINE_FUNCTION Offset begin(Index i) const { return offsets(i); }
  KOKKOS_INLINE_FUNCTION Offset end(Index i) const { return offsets(i + 1); }
  KOKKOS_INLINE_FUNCTION Index count(Index i) const { return static_cast<Index>(offsets(i + 1) - offsets(i)); }
  KOKKOS_INLINE_FUNCTION Index neighbor(Offset k) const { return neighbors(k); }
};

// Reference-configuration neighbour family: the neighbours each particle has in the initial
// configuration (MPS, peridynamic horizon). Built once, never rebuilt; the radius is the influence
// radius r_e (MPS) or the horizon delta (peridynamics).
using BondFamily = NeighborList;

}  // namespace polymech::neighbors
