// The ISPH model's checks on its particles (seed 002 paper 4 has neither): the safety net that puts a
// particle that left the tank back inside.
#pragma once

#include "particles/speed_limit.hpp"  // the watchdog's speed check (was here)
#include "sph/fluid.hpp"

namespace polymech::sph {

// Puts every fluid particle outside the box [lo, hi] back on its face, its velocity component out of the
// box zeroed; returns how many it moved.
template <class T, int D>
long long keep_inside(const Fluid<T, D>& f, const Vec<T, D>& lo, const Vec<T, D>& hi) {
  long long n = 0;
  Kokkos::parallel_reduce(
      "polymech::sph::keep_inside", range(f.size()),
      KOKKOS_LAMBDA(const Index i, long long& count) {
        bool moved = false;
        Vec<T, D> x = f.p.position(i);
        for (int k = 0; k < D; ++k) {
          if (x[k] < lo[k]) {
            f.p.u(i, k) += lo[k] - x[k];
            if (f.p.v(i, k) < T(0)) f.p.v(i, k) = T(0);
            moved = true;
          } else if (x[k] > hi[k]) {
            f.p.u(i, k) += hi[k] - x[k];
            if (f.p.v(i, k) > T(0)) f.p.v(i, k) = T(0);
            moved = true;
          }
        }
        if (moved) ++count;
      },
      n);
  return n;
}

}  // namespace polymech::sph
