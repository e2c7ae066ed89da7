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

#include "solid/hyperelastic_explicit.hpp"

namespace polymech::solid {

// The largest eigenvalue of M_L^-1 K_t on the free DoFs by power iteration, K_t x by a directional
// difference of the residual at the current state (the constrained and tied DoFs held).
template <class T, int D>
inline double HyperelasticExplicit<T, D>::largest_eigenvalue() {
  const Index n = solid_.dof_count();
  View1<T> x("polymech::solid::fse_power_x", n), r0("polymech::solid::fse_power_r0", n), up("polymech::solid::fse_power_u", n);
  const auto kind = kind_;
  Kokkos::parallel_for(
      "polymech::solid::fse_power_start", range(n), KOKKOS_LAMBDA(const Index i) {
        const unsigned long long hsh = (static_cast<unsigned long long>(i) + 1ull) * 0x9E3779B97F4A7C15ull;
        const T q = T(static_cast<double>((hsh >> 11) & 0xFFFFFull) / double(0xFFFFF)) * T(2) - T(1);
        x(i) = kind(i) == 0 ? q : T(0);
      });
  const double s = o_.load_factor ? o_.load_factor(t_) : 1.0;
  Kokkos::deep_copy(r0, r_);
  // eps: a perturbation ~1e-7 of the body's size per unit |x|_inf (|x|_inf = 1 after each normalisation)
  double size = 0.0;
  for (const double c : solid_.discretization().coordinates) size = std::fmax(size, std::fabs(c));
  const double eps = (std::is_same<T, float>::value ? 1e-3 : 1e-7) * std::fmax(size, 1e-300);
  const auto m = mass_;
  double lambda = 0.0;
  int it = 0;
  for (; it < o_.power_iterations; ++it) {
    const auto u = u_, xx = x, upp = up;
    const T te = static_cast<T>(eps);
    Kokkos::parallel_for(
        "polymech::solid::fse_power_perturb", range(n), KOKKOS_LAMBDA(const Index i) { upp(i) = u(i) + te * xx(i); });
    const double rn = solid_.residual(up, s, work_);
    if (!std::isfinite(rn)) throw std::runtime_error("solid::HyperelasticExplicit: the power iteration's perturbed state does not evaluate");
    const auto w = work_, rr = r0;
    double xkx = 0.0, xmx = 0.0, amax = 0.0;
    const T inv = static_cast<T>(1.0 / eps);
    Kokkos::parallel_reduce(
        "polymech::solid::fse_power_quotient", range(n),
        KOKKOS_LAMBDA(const Index i, double& s1, double& s2) {
          if (kind(i) != 0) return;
          const T kx = (w(i) - rr(i)) * inv;
          s1 += double(xx(i)) * double(kx);
          s2 += double(m(i)) * double(xx(i)) * double(xx(i));
          w(i) = kx / m(i);  // M_L^-1 K x
        },
        xkx, xmx);
    Kokkos::parallel_reduce(
        "polymech::solid::fse_power_norm", range(n),
        KOKKOS_LAMBDA(const Index i, double& mx) {
          const double wi = double(w(i)) < 0.0 ? -double(w(i)) : double(w(i));
          if (kind(i) == 0 && wi > mx) mx = wi;
        },
        Kokkos::Max<double>(amax));
    const double next = xkx / xmx;
    if (!(amax > 0.0)) break;
    const T sc = static_cast<T>(1.0 / amax);
    Kokkos::parallel_for(
        "polymech::solid::fse_power_update", range(n), KOKKOS_LAMBDA(const Index i) { xx(i) = kind(i) == 0 ? sc * w(i) : T(0); });
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
