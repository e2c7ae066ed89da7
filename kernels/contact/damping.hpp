// The damping ratio of the damped Hertz law (kernels/contact/hertz_mindlin.hpp, seed 002 paper 2,
// eqs. (12), (13), (17)) for a restitution: shared by the DEM (models/dem) and the ISPH rigid body
// against the tank (models/isph). Host-only, free of Kokkos (the models' Kokkos-free set-up units and
// io/ include it through them).
//
// The usual beta = ln e / sqrt(ln^2 e + pi^2) (contact::damping_ratio) is the linear spring's and gives
// a larger restitution on a Hertz spring (0.32 for e = 0.2); the Hertz law is scale-free (the damping
// grows as delta^(1/4)), so beta depends on e alone: found by bisection on the dimensionless equation
//   m x'' = -(x^1.5 + c sqrt(1.5 sqrt(x)) x'),  m = 1, x(0) = 0, x'(0) = 1, c = -2 sqrt(5/6) beta
// (eq. (12)'s F_n with (4/3) E* sqrt(R*) and m* scaled out), no attraction in the recoil.
#pragma once

#include <cmath>

namespace polymech::contact {

// The restitution that beta (<= 0) gives on the damped Hertz law (the equation above, RK4, h = 1e-3).
inline double hertz_restitution(double beta) {
  const double c = -2.0 * std::sqrt(5.0 / 6.0) * beta;
  auto acc = [c](double x, double v) {
    if (x <= 0) return 0.0;
    const double f = x * std::sqrt(x) + c * std::sqrt(1.5 * std::sqrt(x)) * v;
    return f > 0 ? -f : 0.0;
  };
  const double h = 1e-3;  // the undamped contact lasts 3.2 time units: 3200 steps
  double x = 0, v = 1;
  for (int k = 0; k < 1000000; ++k) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x < 0) return -v;
  }
  return 0.0;  // still in contact after 1000 time units: fully damped
}

// The damping ratio beta (<= 0) for which the damped Hertz law rebounds with the restitution e in (0, 1]
// (60 bisections of hertz_restitution over [-20, 0]).
inline double hertz_damping_ratio(double restitution) {
  if (restitution >= 1.0) return 0.0;
  double lo = -20.0, hi = 0.0;  // restitution(beta) rises from ~0 at lo to 1 at 0
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid) < restitution ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace polymech::contact
