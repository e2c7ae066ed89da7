// The data every ISPH operator reads (seed 002 paper 4): the fluid particles, the IGCB wall integration
// points with their ghosts, the parameters of the fractional step; and AdditiveSum, the one join (and the
// zero start) of every neighbour sum the operators are.
//
// Conventions: r_ij = x_i - x_j, grad W_ij = W'(r) r_ij / r = -F(r) r_ij with F = -W'/r >= 0
// (kernels/sph/kernel.hpp). Fluid particles share one mass m; a wall integration point carries the
// volume H_m |J_c,m| (`vol`). The pressure Poisson equation is solved for A p = b with A = -lap
// (positive on the diagonal); free-surface particles (flag 1) are Dirichlet rows p = 0.
#pragma once

#include <cstdint>
#include <type_traits>
#include <utility>

#include "neighbors/neighbor_loop.hpp"
#include "particles/particle_set.hpp"
#include "sph/kernel.hpp"

namespace polymech::sph {

using Flags = Kokkos::View<std::uint8_t*, MemSpace>;

// Fluid particles: the shared particle set (x0, u, v, a) and the fields of the fractional step.
template <class T, int D>
struct Fluid {
  particles::ParticleSet<T, D> p;
  VecView<T, D> x;      // current position x0 + u
  VecView<T, D> vstar;  // u* of eq. (3)
  VecView<T, D> work;   // scratch vector (the fluid part of a two-pass operator)
  View1<T> rho;         // summation density, eqs. (13) + (18)
  View1<T> pressure;    // p^{n+1}
  View1<T> rhs;         // right-hand side of the PPE (row-scaled)
  View1<T> inv_diag;    // Jacobi scaling of the PPE rows
  View1<T> scratch;     // scalar scratch (fluid part of the PPE operator, divergence)
  Flags surface;        // 1: free-surface particle (p = 0)
  View1<T> divr;        // divergence of position (Params::divergence_surface only)
  Index size() const { return p.size(); }
};

// Wall integration points of the IGCB cells (one Gauss point per cell, or more), with their ghosts.
template <class T, int D>
struct WallPoints {
  VecView<T, D> x;        // x_c,m
  View1<T> vol;           // H_m |J_c,m|
  VecView<T, D> normal;   // n: from the fluid into the wall, eq. (25)
  VecView<T, D> ghost;    // the ghost point mirrored into the fluid
  View1<T> dist;          // d = |x_c,m - ghost|, eq. (26)
  VecView<T, D> velocity; // v_Gamma of the wall at the point
  VecView<T, D> accel;    // a_Gamma
  View1<T> p;             // p_c,m, eq. (26)
  VecView<T, D> u;        // u_c,m, eqs. (27)-(30)
  View1<T> shepard;       // sum_j V_j W_gj at the ghost (0: no fluid near it)
  VecView<T, D + 1> interp;  // ghost interpolation weights: value_g = sum_j V_j W_gj (c0 + c . (x_j - x_g)) f_j
  Index size() const { return static_cast<Index>(x.extent(0)); }
};

template <class T, int D>
struct Params {
  Wendland<T, D> w;
  T mass = T(0);      // m of every fluid particle
  T rho0 = T(0);      // rho^0 (and rho_c of the walls, eq. (18))
  T nu = T(0);        // kinematic viscosity (0: effect off)
  T dt = T(0);
  T alpha = T(0);     // density relaxation, eq. (4) (0: effect off)
  T beta = T(0.9);    // free surface: rho_i < beta rho0
  Vec<T, D> g;
  bool slip = false;  // eqs. (27)-(28) instead of (29)-(30)
  bool difference_gradient = false;  // grad p by (p_j - p_i), (p_c - p_i) instead of eqs. (9), (19)
  bool divergence_surface = false;  // free surface by the divergence of position (< surface_divr), not the density
  T surface_divr = T(1.5);
  bool density_surface_too = false;  // with divergence_surface: also flag rho < beta rho0 (either test)
  bool linear_ghosts = true;  // ghost values by a linear fit (exact for a hydrostatic field); false: Shepard, eq. (23)
  bool surface_correction = true;  // free-surface particles: eq. (9) divided by rho_i / rho0 (the kernel's
                                   // share inside the fluid), see FluidPressureGradient
};

template <class T, int D>
KOKKOS_INLINE_FUNCTION T pair_distance(const VecView<T, D>& xa, Index i, const VecView<T, D>& xb, Index j,
                                       Vec<T, D>& rij) {
  rij = load<D>(xa, i) - load<D>(xb, j);
  return norm(rij);
}

namespace detail {
template <class Pass, class = void>
struct has_initial : std::false_type {};
template <class Pass>
struct has_initial<Pass, std::void_t<decltype(std::declval<const Pass&>().initial(std::declval<Index>()))>> : std::true_type {};
}  // namespace detail

// Every ISPH operator is a sum over a row of a neighbour list whose partial sums add. `Pass` is the
// physics (a plain aggregate: its Views and parameters, `Accumulator`, `pair`, `finish`, and `initial(i)`
// where the sum does not start at zero); AdditiveSum<Pass> adds what neighbors::for_each_row needs besides:
// `start` (zero, or `initial`) and the `join` of two partial sums (`+=`: a scalar, a Vec, or a struct of
// sums with its own `+=`). The operators are the aliases `Name<T, D> = AdditiveSum<pass::Name<T, D>>`,
// built as the pass is: `FluidDensity<T, D>{f, c}`.
template <class Pass>
struct AdditiveSum : Pass {
  using Accumulator = typename Pass::Accumulator;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const {
    if constexpr (detail::has_initial<Pass>::value) {
      return Pass::initial(i);
    } else {
      (void)i;
      return Accumulator{};  // value-initialised: every sum 0
    }
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) { into += from; }
};

// Position update helper: x = x0 + u.
template <class T, int D>
void current_positions(const Fluid<T, D>& f) {
  auto x = f.x;
  auto p = f.p;
  Kokkos::parallel_for(
      "polymech::sph::positions", range(f.size()), KOKKOS_LAMBDA(const Index i) { store<D>(x, i, p.position(i)); });
}

}  // namespace polymech::sph
