// The watchdog's speed check of a particle set (models/common/particle_health.hpp): the first particle
// faster than a bound the model derives from what its discretization assumes (ISPH: ten spacings per step;
// PD: one spacing per step; DEM: the neighbour lists' skin per step).
#pragma once

#include "core/types.hpp"

namespace polymech::particles {

// The first particle with |v| > vmax (or a speed that is not a number), or -1.
template <class T, int D>
Index first_faster_than(const VecView<T, D>& v, T vmax) {
  const Index n = static_cast<Index>(v.extent(0));
  Index first = n;
  Kokkos::parallel_reduce(
      "polymech::particles::first_faster_than", range(n),
      KOKKOS_LAMBDA(const Index i, Index& m) {
        T s2 = T(0);
        for (int d = 0; d < D; ++d) s2 += v(i, d) * v(i, d);
        if (!(s2 <= vmax * vmax) && i < m) m = i;
      },
      Kokkos::Min<Index>(first));
  return first < n ? first : Index(-1);
}

}  // namespace polymech::particles
