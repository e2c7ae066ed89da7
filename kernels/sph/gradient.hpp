// Divergence and gradient of the stabilized ISPH (seed 002 paper 4): the PPE right-hand side, eq. (4) with
// the divergence of u*, eqs. (12) + (22); the projection, eq. (5), with the pressure gradient, eqs. (9) +
// (19), and the drift x^{n+1} = x^n + dt u^{n+1}; the wall reactions, eqs. (38)-(43), from the same pair
// terms (kernels/sph/fluid.hpp has the conventions).
#pragma once

#include "sph/fluid.hpp"

namespace polymech::sph {

namespace pass {

// ---- PPE right-hand side: eq. (4) with the divergence eqs. (12) + (22) of u* ----
template <class T, int D>
struct FluidDivergence {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    acc -= c.mass * F * dot(load<D>(f.vstar, j) - load<D>(f.vstar, i), r);  // eq. (12) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.scratch(i) = acc / f.rho(i); }
};

// Finishes b_i = -(rho0/dt div u*_i + alpha (rho0 - rho_i)/dt^2) + 2 sum V F c_ip (the affine part
// of the Neumann wall pressure, eq. (26), moved to the right), row-scaled by inv_diag; stores the
// Jacobi scaling 1 / A_ii with A_ii = 2/rho_i sum m F + 2 sum V F (fluid diagonal from the fluid pass).
template <class T, int D>
struct WallDivergenceRhs {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  View1<T> fluid_diag;
  struct Accumulator {
    T div, diag, affine;
    KOKKOS_INLINE_FUNCTION Accumulator& operator+=(const Accumulator& b) {
      div += b.div;
      diag += b.diag;
      affine += b.affine;
      return *this;
    }
  };
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    const T V = wp.vol(k);
    acc.div -= V * F * dot(load<D>(wp.u, k) - load<D>(f.vstar, i), r);  // eq. (22)
    acc.diag += T(2) * V * F;
    const Vec<T, D> ga = c.g - load<D>(wp.accel, k);
    acc.affine += T(2) * V * F * wp.dist(k) * c.rho0 * dot(ga, load<D>(wp.normal, k));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    if (f.surface(i)) {
      f.inv_diag(i) = T(1);
      f.rhs(i) = T(0);
      return;
    }
    const T div = f.scratch(i) + acc.div;
    const T diag = fluid_diag(i) + acc.diag;
    const T inv = diag > T(0) ? T(1) / diag : T(1);
    const T b = -(c.rho0 / c.dt * div + c.alpha * (c.rho0 - f.rho(i)) / (c.dt * c.dt)) + acc.affine;  // eq. (4)
    f.inv_diag(i) = inv;
    f.rhs(i) = inv * b;
  }
};

// ---- projection, eq. (5), with the pressure gradient eqs. (9) + (19); then the drift ----
template <class T, int D>
struct FluidPressureGradient {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    const T ri = f.rho(i), rj = f.rho(j);
    if (c.difference_gradient)
      acc -= (c.mass * (f.pressure(j) - f.pressure(i)) / (rj * ri) * F) * r;
    else
      acc -= (c.mass * (f.pressure(j) / (rj * rj) + f.pressure(i) / (ri * ri)) * F) * r;  // eq. (9) / rho_i
  }
  // At a free-surface particle (p_i = 0) the sum of eq. (9) covers only the part of the kernel inside
  // the water, sum_j V_j p_j grad W_ij ~ (rho_i / rho0) grad p: it gives about half the hydrostatic
  // support and the surface layer sinks onto the one below. With surface_correction the sum is divided
  // by that share (a Shepard renormalisation; not in the paper, docs/METHODS.md).
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const T s = (c.surface_correction && f.surface(i)) ? c.rho0 : f.rho(i);
    store<D>(f.work, i, s * acc);
  }
};

template <class T, int D>
struct WallPressureCorrect {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    const T pi = c.difference_gradient ? -f.pressure(i) : f.pressure(i);
    acc -= ((wp.p(k) + pi) * F * wp.vol(k)) * r;  // eq. (19)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const Vec<T, D> grad = load<D>(f.work, i) + acc;
    const Vec<T, D> vnew = load<D>(f.vstar, i) - (c.dt / f.rho(i)) * grad;  // eq. (5)
    store<D>(f.p.a, i, (T(1) / c.dt) * (vnew - load<D>(f.p.v, i)));
    store<D>(f.p.v, i, vnew);
    store<D>(f.p.u, i, load<D>(f.p.u, i) + c.dt * vnew);  // x^{n+1} = x^n + dt u^{n+1}
  }
};

}  // namespace pass

template <class T, int D>
using FluidDivergence = AdditiveSum<pass::FluidDivergence<T, D>>;
template <class T, int D>
using WallDivergenceRhs = AdditiveSum<pass::WallDivergenceRhs<T, D>>;
template <class T, int D>
using FluidPressureGradient = AdditiveSum<pass::FluidPressureGradient<T, D>>;
template <class T, int D>
using WallPressureCorrect = AdditiveSum<pass::WallPressureCorrect<T, D>>;

// Wall reaction of pair (i, (c,m)), eqs. (39)-(41): the force the point gives particle i, its pressure
// part (eq. (40)) and its viscous part (eq. (41)).
template <class T, int D>
KOKKOS_INLINE_FUNCTION void wall_pair_force_parts(const Fluid<T, D>& f, const WallPoints<T, D>& wp, const Params<T, D>& c,
                                                  Index i, Index k, Vec<T, D>& pressure, Vec<T, D>& viscous) {
  Vec<T, D> r;
  const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
  const T pi = c.difference_gradient ? -f.pressure(i) : f.pressure(i);
  const Vec<T, D> gradp = (-(wp.p(k) + pi) * F * wp.vol(k)) * r;                         // eq. (40)
  const Vec<T, D> lapu = (-T(2) * F * wp.vol(k)) * (load<D>(f.p.v, i) - load<D>(wp.u, k));  // eq. (41)
  pressure = (-c.mass / c.rho0) * gradp;                                                 // eq. (39)
  viscous = (c.mass * c.nu) * lapu;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> wall_pair_force(const Fluid<T, D>& f, const WallPoints<T, D>& wp, const Params<T, D>& c,
                                                 Index i, Index k) {
  Vec<T, D> fp, fv;
  wall_pair_force_parts<T, D>(f, wp, c, i, k, fp, fv);
  return fp + fv;
}

namespace pass {

// The wall force on each fluid particle, f_i^wall = sum over its wall points, eq. (38).
template <class T, int D>
struct WallForceOnFluid {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  VecView<T, D> out;
  using Accumulator = Vec<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    acc += wall_pair_force<T, D>(f, wp, c, i, k);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { store<D>(out, i, acc); }
};

}  // namespace pass

template <class T, int D>
using WallForceOnFluid = AdditiveSum<pass::WallForceOnFluid<T, D>>;

// The reaction of every (particle, wall point) pair of `list` (fluid -> wall points), eq. (42), one row
// per pair: out(k) = the wall_pair_force of pair k, the force the point gives the particle.
template <class T, int D>
void wall_pair_forces(const neighbors::NeighborList& list, const Fluid<T, D>& f, const WallPoints<T, D>& wp,
                      const Params<T, D>& c, const View2<T>& out) {
  Kokkos::parallel_for(
      "polymech::sph::wall_pair_forces", range(list.num_particles), KOKKOS_LAMBDA(const Index i) {
        for (Offset k = list.begin(i); k < list.end(i); ++k) {
          const Vec<T, D> fk = wall_pair_force<T, D>(f, wp, c, i, list.neighbor(k));
          for (int d = 0; d < D; ++d) out(k, d) = fk[d];
        }
      });
}

}  // namespace polymech::sph
