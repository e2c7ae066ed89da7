// J2 elasto-plasticity with Johnson-Cook hardening, strain-rate and thermal softening (Johnson & Cook
// 1983): sigma_y = (A + B eps_p^n)(1 + C ln(rate / rate0))(1 - T*^m), in a hypoelastic rate form on the
// Cauchy stress with the Jaumann rate (objective for the large rotations of a plug), radial return,
// adiabatic heating dT = chi sigma_y d eps_p / (rho c_p) (Taylor-Quinney); P = J sigma F^-T. Used by
// peridynamics (seed 003) and any method that has a deformation gradient and its rate.
#pragma once

#include <limits>

#include "materials/elastic.hpp"

namespace polymech::materials {

template <class T>
struct JohnsonCook {
  T A = T(0), B = T(0), n = T(1);   // sigma_y0 [Pa], hardening modulus [Pa], exponent
  T C = T(0), rate0 = T(1);         // rate sensitivity, reference strain rate [1/s]
  T m = T(1);                       // thermal softening exponent
  T T_room = T(293), T_melt = T(0);  // [K]; T_melt <= T_room: no thermal softening
  T rho_cp = T(1);                  // rho c_p [J/(m^3 K)]
  T chi = T(0.9);                   // Taylor-Quinney coefficient
  KOKKOS_INLINE_FUNCTION bool thermal() const { return T_melt > T_room; }
};

// Johnson-Cook flow stress at plastic strain eps, rate ratio rate/rate0 (>= 1 counts) and temperature.
template <class T>
KOKKOS_INLINE_FUNCTION T jc_flow_stress(const JohnsonCook<T>& jc, T eps, T rate_ratio, T temperature) {
  const T hard = jc.A + (eps > T(0) ? jc.B * kx::exp(jc.n * kx::log(eps)) : T(0));
  const T rate = rate_ratio > T(1) ? T(1) + jc.C * kx::log(rate_ratio) : T(1);
  T therm = T(1);
  if (jc.thermal()) {
    const T ts = kx::clamp((temperature - jc.T_room) / (jc.T_melt - jc.T_room), T(0), T(1));
    therm = ts > T(0) ? T(1) - kx::exp(jc.m * kx::log(ts)) : T(1);
  }
  return hard * rate * therm;
}

// Radial return of J2 with Johnson-Cook hardening: the plastic increment d >= 0 with
//   g(d) = seq_trial - 3 mu d - sigma_y(eps + d, d / (dt rate0), temperature) = 0,
// where the rate is the plastic strain rate of this step (viscoplastic consistency). g decreases in
// d; Newton with the analytic slope, safeguarded by bisection whenever a step leaves the bracket,
// to a relative residual of sqrt(machine epsilon) / 100. Returns 0 when the trial state is elastic.
template <class T>
KOKKOS_INLINE_FUNCTION T jc_return(const JohnsonCook<T>& jc, T mu, T seq_trial, T eps, T temperature, T dt) {
  const T inv_rate = T(1) / (dt * jc.rate0);
  T therm = T(1);
  if (jc.thermal()) {
    const T ts = kx::clamp((temperature - jc.T_room) / (jc.T_melt - jc.T_room), T(0), T(1));
    therm = ts > T(0) ? T(1) - kx::exp(jc.m * kx::log(ts)) : T(1);
  }
  // g and its slope at d
  auto eval = [&](T d, T& slope) {
    const T e = eps + d;
    const T pw = e > T(0) ? kx::exp(jc.n * kx::log(e)) : T(0);
    const T H = jc.A + jc.B * pw, dH = e > T(0) ? jc.B * jc.n * pw / e : T(0);
    const T x = d * inv_rate;
    const T R = x > T(1) ? T(1) + jc.C * kx::log(x) : T(1), dR = x > T(1) ? jc.C / d : T(0);
    slope = -T(3) * mu - (dH * R + H * dR) * therm;
    return seq_trial - T(3) * mu * d - H * R * therm;
  };
  T slope;
  if (eval(T(0), slope) <= T(0)) return T(0);
  constexpr T eps_T = std::numeric_limits<T>::epsilon();
  const T tol = T(0.01) * kx::sqrt(eps_T) * seq_trial;
  T lo = T(0), hi = seq_trial / (T(3) * mu);  // g(hi) = -sigma_y < 0
  T d = (seq_trial - jc_flow_stress(jc, eps, T(0), temperature)) / (T(3) * mu);  // perfectly plastic guess
  d = d > lo && d < hi ? d : T(0.5) * hi;
  for (int it = 0; it < 50; ++it) {
    const T gd = eval(d, slope);
    if (kx::fabs(gd) <= tol) break;
    if (gd > T(0)) lo = d; else hi = d;
    T next = slope < T(0) ? d - gd / slope : T(0.5) * (lo + hi);
    if (!(next > lo && next < hi)) next = T(0.5) * (lo + hi);
    if (hi - lo <= T(4) * eps_T * hi) break;
    d = next;
  }
  return d;
}

// Result of one J2 update.
template <class T>
struct J2Step {
  Mat3<T> sigma;      // Cauchy stress at the end of the step
  T d_eps_p = T(0);   // plastic strain increment
  T flow_stress = T(0);  // sigma_y at the end of the step (when plastic)
};

// One step of the hypoelastic J2 law: sigma_trial = sigma + dt (lambda tr(D) I + 2 mu D + W sigma - sigma W)
// (Jaumann), then radial return onto the Johnson-Cook yield surface.
template <class T>
KOKKOS_INLINE_FUNCTION J2Step<T> j2_update(const Mat3<T>& sigma, const Mat3<T>& L, T dt, const ElasticConstants<T>& c,
                                           const JohnsonCook<T>& jc, T eps, T temperature) {
  Mat3<T> Dr, W;
  for (int r = 0; r < 3; ++r)
    for (int s = 0; s < 3; ++s) {
      Dr.a[r][s] = T(0.5) * (L.a[r][s] + L.a[s][r]);
      W.a[r][s] = T(0.5) * (L.a[r][s] - L.a[s][r]);
    }
  Mat3<T> rate = (T(2) * c.mu) * Dr + (W * sigma - sigma * W);
  const T lt = c.lambda * trace(Dr);
  for (int k = 0; k < 3; ++k) rate.a[k][k] += lt;
  J2Step<T> out;
  out.sigma = sigma + dt * rate;
  const Mat3<T> s = deviator(out.sigma);
  const T seq = kx::sqrt(T(1.5) * double_dot(s, s));
  const T d = seq > T(0) ? jc_return(jc, c.mu, seq, eps, temperature, dt) : T(0);
  if (d > T(0)) {
    const T p = trace(out.sigma) / T(3);
    out.sigma = (T(1) - T(3) * c.mu * d / seq) * s;
    for (int k = 0; k < 3; ++k) out.sigma.a[k][k] += p;
    out.d_eps_p = d;
    out.flow_stress = seq - T(3) * c.mu * d;
  }
  return out;
}

// Elastic strain energy density of a Cauchy stress (small elastic strains): p^2/(2K) + s:s/(4 mu).
template <class T>
KOKKOS_INLINE_FUNCTION T elastic_energy_of_stress(const Mat3<T>& sigma, const ElasticConstants<T>& c) {
  const T p = trace(sigma) / T(3);
  const Mat3<T> s = deviator(sigma);
  return p * p / (T(2) * c.bulk()) + double_dot(s, s) / (T(4) * c.mu);
}

// The J2 / Johnson-Cook law as a struct. A rate law: it needs the velocity gradient L of the step and
// keeps per-point history (Cauchy stress, equivalent plastic strain, temperature), which the method
// stores; `stored_energy` is the elastic energy density of a stress.
template <class T>
struct J2JohnsonCook {
  static constexpr bool rate_form = true;
  ElasticConstants<T> elastic;
  JohnsonCook<T> hardening;

  KOKKOS_INLINE_FUNCTION J2Step<T> update(const Mat3<T>& sigma, const Mat3<T>& L, T dt, T eps, T temperature) const {
    return j2_update(sigma, L, dt, elastic, hardening, eps, temperature);
  }
  KOKKOS_INLINE_FUNCTION T stored_energy(const Mat3<T>& sigma) const { return elastic_energy_of_stress(sigma, elastic); }
};

}  // namespace polymech::materials
