// Density and free-surface detection of the stabilized ISPH (seed 002 paper 4): the summation density,
// eq. (13) over the fluid then eq. (18) over the IGCB wall points, with the free surface rho_i < beta rho0;
// or the free surface by the divergence of position (Lee et al. 2008). Each is two passes: the fluid sum
// over the fluid-fluid list, then the wall sum over the fluid -> wall point list, whose finish() writes
// the result (kernels/sph/fluid.hpp has the conventions).
#pragma once

#include "sph/fluid.hpp"

namespace polymech::sph {

namespace pass {

template <class T, int D>
struct FluidDensity {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T initial(Index) const { return c.mass * c.w.value(T(0)); }  // eq. (13): j = i
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    acc += c.mass * c.w.value(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.rho(i) = acc; }
};

template <class T, int D>
struct WallDensity {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    acc += c.w.value(pair_distance<T, D>(f.x, i, wp.x, k, r)) * wp.vol(k);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    const T rho = f.rho(i) + c.rho0 * acc;  // eq. (18)
    f.rho(i) = rho;
    if (!c.divergence_surface) f.surface(i) = rho < c.beta * c.rho0 ? 1 : 0;
  }
};

// Divergence of position, div r_i = sum_j V_j (x_j - x_i) . grad_i W_ij = sum_j V_j F_ij |r_ij|^2 (F = -W'/r) over the
// fluid (V_j = m / rho_j, after the density passes) and then the wall points (V = H |J|); the wall pass
// flags the free surface, div r_i < surface_divr (Lee et al. 2008; Params::divergence_surface).
template <class T, int D>
struct FluidPositionDivergence {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T d = pair_distance<T, D>(f.x, i, f.x, j, r);
    acc += c.mass / f.rho(j) * c.w.f(d) * d * d;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.divr(i) = acc; }
};

template <class T, int D>
struct WallPositionDivergence {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T d = pair_distance<T, D>(f.x, i, wp.x, k, r);
    acc += wp.vol(k) * c.w.f(d) * d * d;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    const T divr = f.divr(i) + acc;
    f.divr(i) = divr;
    const T rho = f.rho(i);
    f.surface(i) = ((divr < c.surface_divr && rho < c.rho0) || (c.density_surface_too && rho < c.beta * c.rho0)) ? 1 : 0;
  }
};

}  // namespace pass

template <class T, int D>
using FluidDensity = AdditiveSum<pass::FluidDensity<T, D>>;
template <class T, int D>
using WallDensity = AdditiveSum<pass::WallDensity<T, D>>;
template <class T, int D>
using FluidPositionDivergence = AdditiveSum<pass::FluidPositionDivergence<T, D>>;
template <class T, int D>
using WallPositionDivergence = AdditiveSum<pass::WallPositionDivergence<T, D>>;

}  // namespace polymech::sph
