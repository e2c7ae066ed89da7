// MPS weight function and particle number density (seed 000 eqs. (1)-(2)).
#pragma once

#include <cmath>

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/neighbor_loop.hpp"

namespace polymech::mps {

// seed 000 eq. (1): w(r) = re / r - 1 for 0 < r <= re, 0 otherwise. r = 0 (coincident particles)
// returns 0 rather than infinity: MPS pairs are never coincident in a valid configuration, and a
// kernel must not produce inf from bad input.
template <class T>
KOKKOS_INLINE_FUNCTION T weight(T r, T re) {
  return (r > T(0) && r <= re) ? re / r - T(1) : T(0);
}

// seed 000 eq. (2): n_i = sum_{j != i} w(|r_j - r_i|), over the neighbour family of i.
template <class T, int D>
struct NumberDensity {
  VecView<T, D> x;
  T re;
  View1<T> n;
  struct Accumulator {
    Vec<T, D> xi;
    T sum;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {load<D>(x, i), T(0)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset) const {
    acc.sum += weight(norm(load<D>(x, j) - acc.xi), re);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { n(i) = acc.sum; }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) { into.sum += from.sum; }
};

template <class T, int D>
void number_density(const neighbors::NeighborList& family, const VecView<T, D>& x, T re, const View1<T>& n) {
  neighbors::for_each_row("polymech::mps::number_density", family, NumberDensity<T, D>{x, re, n});
}

// n0 as the paper defines it: the mean initial number density over all particles (seed 000 §2.1).
template <class T>
T mean_number_density(const View1<T>& n) {
  T sum = T(0);
  Kokkos::parallel_reduce(
      "polymech::mps::mean_number_density", range(static_cast<std::int64_t>(n.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i, T& s) { s += n(i); }, sum);
  return n.extent(0) > 0 ? sum / static_cast<T>(n.extent(0)) : T(0);
}

// n0 of a particle with a full neighbourhood on the square (2D) or cubic (3D) lattice of spacing l0:
// the value the paper's Table 1 lists (6.53 for re = 2.1 l0 in 2D). Host function.
inline double lattice_number_density(int dim, double l0, double re) {
  const int m = static_cast<int>(re / l0) + 1;
  double n = 0.0;
  for (int a = -m; a <= m; ++a)
    for (int b = -m; b <= m; ++b)
      for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); ++c) {
        if (a == 0 && b == 0 && c == 0) continue;
        const double r = l0 * std::sqrt(double(a * a + b * b + c * c));
        n += r <= re ? re / r - 1.0 : 0.0;
      }
  return n;
}

}  // namespace polymech::mps
