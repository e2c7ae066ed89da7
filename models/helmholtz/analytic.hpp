// Analytic fields of the paper's verification cases, device-callable (the L2 error of eq. (28) and the
// Dirichlet data are evaluated in kernels):
//  - plane cosines, eq. (27): Phi = cos kx + cos ky + cos kz solves (nabla^2 + k^2) Phi = 0 (eq. (3));
//  - duct, eq. (29): p(x) = rho c (Zn cos k(l - x) + j rho c sin k(l - x)) / (rho c cos kl + j Zn sin kl) v0
//    with Phi = p / (j omega rho) (eq. (4)); x measured from the vibrating end.
#pragma once

#include "core/kokkos_shim.hpp"
#include "helmholtz/config.hpp"

namespace polymech::helmholtz {

struct AnalyticField {
  AnalyticKind kind = AnalyticKind::none;
  double k = 0.0, omega = 0.0, rho = 0.0, c = 0.0;
  double x0 = 0.0, length = 1.0, v0 = 0.0, zn = 1.0;

  static AnalyticField from(const Config& cfg) {
    AnalyticField a;
    a.kind = cfg.analytic.kind;
    a.k = cfg.wavenumber();
    a.omega = cfg.omega();
    a.rho = cfg.density;
    a.c = cfg.sound_speed;
    a.x0 = cfg.analytic.x0;
    a.length = cfg.analytic.length;
    a.v0 = cfg.analytic.velocity;
    a.zn = cfg.analytic.impedance;
    return a;
  }

  // Acoustic pressure of the duct, eq. (29).
  KOKKOS_INLINE_FUNCTION Kokkos::complex<double> duct_pressure(double x) const {
    using C = Kokkos::complex<double>;
    const double s = k * (length - (x - x0)), rc = rho * c;
    const C num(zn * kx::cos(s), rc * kx::sin(s));
    const C den(rc * kx::cos(k * length), zn * kx::sin(k * length));
    return C(rc * v0) * num / den;
  }

  KOKKOS_INLINE_FUNCTION Kokkos::complex<double> operator()(double x, double y, double z) const {
    using C = Kokkos::complex<double>;
    if (kind == AnalyticKind::plane_cosines) return C(kx::cos(k * x) + kx::cos(k * y) + kx::cos(k * z), 0.0);
    if (kind == AnalyticKind::duct) return duct_pressure(x) / C(0.0, omega * rho);  // Phi = p / (j omega rho)
    return C(0.0, 0.0);
  }
};

}  // namespace polymech::helmholtz
