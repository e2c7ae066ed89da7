// Laplacians of the stabilized ISPH (seed 002 paper 4): the predictor u* = u + dt (nu lap u + g), eq. (3),
// with the viscous term over the fluid, eq. (11), and the IGCB wall points, eq. (21); and the pressure
// Poisson operator A = -lap, eqs. (10) + (20), row-scaled by its Jacobi diagonal, matrix-free or from pair
// coefficients stored once per step (kernels/sph/fluid.hpp has the conventions).
#pragma once

#include "sph/fluid.hpp"

namespace polymech::sph {

namespace pass {

// ---- predictor, eq. (3) with the viscous term eqs. (11) + (21) ----
template <class T, int D>
struct FluidViscosity {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    acc -= (T(2) * c.mass * F) * (load<D>(f.p.v, i) - load<D>(f.p.v, j));  // eq. (11) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { store<D>(f.work, i, (T(1) / f.rho(i)) * acc); }
};

template <class T, int D>
struct WallViscosityPredict {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    acc -= (T(2) * F * wp.vol(k)) * (load<D>(f.p.v, i) - load<D>(wp.u, k));  // eq. (21)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const Vec<T, D> lap = load<D>(f.work, i) + acc;
    store<D>(f.vstar, i, load<D>(f.p.v, i) + c.dt * (c.nu * lap + c.g));  // eq. (3)
  }
};

// The fluid diagonal 2/rho_i sum m F (for the Jacobi scaling).
template <class T, int D>
struct FluidDiagonal {
  Fluid<T, D> f;
  Params<T, D> c;
  View1<T> out;
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    acc += T(2) * c.mass * c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { out(i) = acc / f.rho(i); }
};

// ---- the PPE operator y = D^-1 A x, A = -(eq. (10) + eq. (20)), matrix-free ----
template <class T, int D>
struct FluidLaplacian {
  Fluid<T, D> f;
  Params<T, D> c;
  View1<T> xin;
  View1<T> stored = {};  // the pair coefficients of StorePairCoefficients (empty: computed here)
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION T coefficient(Index i, Index j, Offset) const {
    Vec<T, D> r;
    return T(2) * c.mass * c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset o) const {
    const T a = stored.extent(0) > 0 ? stored(o) : coefficient(i, j, o);
    const T xj = f.surface(j) ? T(0) : xin(j);  // Dirichlet p = 0 at the free surface
    acc += a * (xin(i) - xj);                   // -eq. (10) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.scratch(i) = acc / f.rho(i); }
};

template <class T, int D>
struct WallLaplacian {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  View1<T> xin, yout;
  View1<T> stored = {};  // the pair coefficients of StorePairCoefficients (empty: computed here)
  using Accumulator = T;
  KOKKOS_FORCEINLINE_FUNCTION T coefficient(Index i, Index k, Offset) const {
    Vec<T, D> r;
    return T(2) * wp.vol(k) * c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset o) const {
    const T a = stored.extent(0) > 0 ? stored(o) : coefficient(i, k, o);
    acc += a * (xin(i) - wp.p(k));  // -eq. (20), p_c,m from the ghost (homogeneous part)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    yout(i) = f.surface(i) ? xin(i) : f.inv_diag(i) * (f.scratch(i) + acc);
  }
};

}  // namespace pass

template <class T, int D>
using FluidViscosity = AdditiveSum<pass::FluidViscosity<T, D>>;
template <class T, int D>
using WallViscosityPredict = AdditiveSum<pass::WallViscosityPredict<T, D>>;
template <class T, int D>
using FluidDiagonal = AdditiveSum<pass::FluidDiagonal<T, D>>;
template <class T, int D>
using FluidLaplacian = AdditiveSum<pass::FluidLaplacian<T, D>>;
template <class T, int D>
using WallLaplacian = AdditiveSum<pass::WallLaplacian<T, D>>;

// The predictor without the viscosity effect: u* = u + dt g, eq. (3) with nu = 0.
template <class T, int D>
void gravity_predict(const Fluid<T, D>& f, const Params<T, D>& c) {
  Kokkos::parallel_for(
      "polymech::sph::predict", range(f.size()),
      KOKKOS_LAMBDA(const Index i) { store<D>(f.vstar, i, polymech::load<D>(f.p.v, i) + c.dt * c.g); });
}

// The PPE operator's pair coefficients, stored once per step (`ppe_operator = "stored"`, the default):
// positions, densities and ghost weights do not change within a solve, so each of its applies reduces to
// three sparse products over the neighbour lists instead of three kernel evaluations per pair. `Pass` is
// GhostPressure, FluidLaplacian or WallLaplacian; out(o) = pass.coefficient(i, j, o) for the pair o of
// row i, formed as the matrix-free pass forms it, so both give the same result to the bit.
template <class T, class Pass>
struct StorePairCoefficients {
  Pass pass;
  View1<T> out;  // one per pair of the pass's list
  struct Accumulator {};
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator&, Index i, Index j, Offset o) const { out(o) = pass.coefficient(i, j, o); }
  KOKKOS_INLINE_FUNCTION void finish(Index, Accumulator&) const {}
  KOKKOS_INLINE_FUNCTION static void join(Accumulator&, const Accumulator&) {}
};

}  // namespace polymech::sph
