// Short-range repulsion between peridynamic particles (seed 003: contact between fracture surfaces and
// fragments), in the form of Silling & Askari (2005, "A meshfree method based on the peridynamic model
// of solid mechanics", Comput. Struct. 83): any pair closer than d_s repels with
//   f_ij = -c_s (d_s - |y_ij|) / d_s  e_ij   [force per volume^2],   L_i = sum_j f_ij V_j,
// the force of the pair potential U_ij = c_s V_i V_j (d_s - r)^2 / (2 d_s). It acts on every pair, not
// only on damaged particles: a switch on damage would let two particles be pressed together while
// intact and then push them apart from a deep overlap when a bond breaks (energy from nothing). With
// d_s < spacing it acts in intact material only beyond ~10 % compression. Pairs come from the shared
// Verlet list (neighbors::VerletList over the current positions, radius d_s plus a skin); the true
// distance is tested here. Gather over a full list: thread-count independent.
#pragma once

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/neighbor_loop.hpp"

namespace polymech::contact {

// Kernel "polymech::contact::pd_current_positions": y = x0 + u (what the Verlet list is built on).
template <class T, int D>
void pd_current_positions(const VecView<T, D>& x0, const VecView<T, D>& u, const VecView<T, D>& y) {
  Kokkos::parallel_for(
      "polymech::contact::pd_current_positions", range(static_cast<std::int64_t>(x0.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        for (int k = 0; k < D; ++k) y(i, k) = x0(i, k) + u(i, k);
      });
}

template <class T>
struct ShortRangeParams {
  T distance = T(0);     // d_s
  T coefficient = T(0);  // c_s [N/m^6]
  T density = T(1);
};

// Kernel "polymech::contact::pd_short_range": a_i += L_i / rho.
template <class T, int D>
struct ShortRangeForce {
  VecView<T, D> y;
  View1<T> volume;
  VecView<T, D> a;
  T ds, c, inv_rho;
  struct Accumulator {
    Vec<T, D> yi, L;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {load<D>(y, i), Vec<T, D>::zero()}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset) const {
    const Vec<T, D> d = load<D>(y, j) - acc.yi;
    const T r2 = norm2(d);
    if (r2 >= ds * ds || !(r2 > T(0))) return;
    const T r = kx::sqrt(r2);
    acc.L -= (c * (ds - r) * volume(j) / r) * d;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    for (int k = 0; k < D; ++k) a(i, k) += inv_rho * acc.L[k];
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) { into.L += from.L; }
};

template <class T, int D>
void pd_short_range(const neighbors::NeighborList& list, const VecView<T, D>& y, const View1<T>& volume,
                    const ShortRangeParams<T>& p, const VecView<T, D>& a) {
  neighbors::for_each_row("polymech::contact::pd_short_range", list,
                          ShortRangeForce<T, D>{y, volume, a, p.distance, p.coefficient / p.distance, T(1) / p.density});
}

// Potential energy of the short-range springs, sum over pairs of c_s V_i V_j (d_s - r)^2 / (2 d_s);
// per particle half of its pairs' energy into e[i] (a full list holds each pair twice).
template <class T, int D>
struct ShortRangeEnergy {
  VecView<T, D> y;
  View1<T> volume;
  View1<T> e;
  T ds, c;
  struct Accumulator {
    Vec<T, D> yi;
    T s;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {load<D>(y, i), T(0)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    const T r = norm(load<D>(y, j) - acc.yi);
    if (r < ds) acc.s += T(0.25) * c * volume(i) * volume(j) * (ds - r) * (ds - r);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { e(i) = acc.s; }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) { into.s += from.s; }
};

template <class T, int D>
void pd_short_range_energy(const neighbors::NeighborList& list, const VecView<T, D>& y, const View1<T>& volume,
                           const ShortRangeParams<T>& p, const View1<T>& e) {
  neighbors::for_each_row("polymech::contact::pd_short_range_energy", list,
                          ShortRangeEnergy<T, D>{y, volume, e, p.distance, p.coefficient / p.distance});
}

}  // namespace polymech::contact
