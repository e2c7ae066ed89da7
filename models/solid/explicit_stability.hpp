// The critical time step of solid::HyperelasticExplicit (issue 34): the largest eigenvalue of M_L^-1 K_t by
// power iteration on directional differences of the residual (the member largest_eigenvalue; the model:
// models/solid/hyperelastic_explicit.hpp, include models/solid/finite_strain_explicit.hpp).
//
// Stability: dt <= dt_crit = 2 / omega_max, omega_max^2 the largest eigenvalue of M_L^-1 K_t, K_t the tangent at
// the current state, estimated by power iteration on directional differences of the residual (matrix-free:
// K_t x ~ (r(u + eps x) - r(u)) / eps) with the tied and constrained DoFs held. A requested dt above safety x
// dt_crit is refused unless allow_unstable; an evaluation that fails (J <= 0, a non-finite stress) stops the run
// with the time and the reason, never a NaN state.
#pragma once

#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "solid/explicit_dynamics.hpp"
#include "solid/hyperelastic_explicit.hpp"

namespace polymech::solid {

// The largest eigenvalue of M_L^-1 K_t on the free DoFs by power iteration, K_t x by a directional
// difference of the residual at the current state (the constrained and tied DoFs held).
template <class T, int D>
inline double HyperelasticExplicit<T, D>::largest_eigenvalue() {
  const Index n = solid_.dof_count();
  View1<T> x("polymech::solid::fse_power_x", n), r0("polymech::solid::fse_power_r0", n), up("polymech::solid::fse_power_u", n);
  explicit_power_start(n, kind_, x);
  const double s = o_.load_factor ? o_.load_factor(t_) : 1.0;
  Kokkos::deep_copy(r0, r_);
  // eps: a perturbation ~1e-7 of the body's size per unit |x|_inf (|x|_inf = 1 after each normalisation)
  double size = 0.0;
  for (const double c : solid_.discretization().coordinates) size = std::fmax(size, std::fabs(c));
  const double eps = (std::is_same<T, float>::value ? 1e-3 : 1e-7) * std::fmax(size, 1e-300);
  double lambda = 0.0;
  int it = 0;
  for (; it < o_.power_iterations; ++it) {
    explicit_power_perturb(n, u_, x, static_cast<T>(eps), up);
    const double rn = solid_.residual(up, s, work_);
    if (!std::isfinite(rn)) throw std::runtime_error("solid::HyperelasticExplicit: the power iteration's perturbed state does not evaluate");
    double xkx = 0.0, xmx = 0.0, amax = 0.0;
    explicit_power_quotient(n, kind_, work_, r0, x, mass_, static_cast<T>(1.0 / eps), xkx, xmx);  // work_: M_L^-1 K x
    explicit_power_norm(n, kind_, work_, amax);
    const double next = xkx / xmx;
    if (!(amax > 0.0)) break;
    explicit_power_update(n, kind_, work_, static_cast<T>(1.0 / amax), x);
    const bool done = it > 0 && std::fabs(next - lambda) <= o_.power_tolerance * next;
    lambda = next;
    if (done) break;
  }
  power_its_ = it + 1;
  solid_.residual(u_, s, r_);  // restore the state's residual (and strain energy)
  if (!(lambda > 0.0)) throw std::runtime_error("solid::HyperelasticExplicit: the power iteration found no positive eigenvalue of M_L^-1 K_t");
  return lambda;
}

}  // namespace polymech::solid
