// Small-strain, rate-independent Hill (1948) plasticity with cubic symmetry, the paper's power-law isotropic
// hardening and associative flow (seed 002 paper 5 eqs. (1)-(4)); J2 (von Mises) is its isotropic case.
//
// Yield function: f = phi(sigma) - sigma_y(eps_bar), phi^2 = s . P s with s the Voigt stress (tensor
// components) and P the Hill metric rotated to specimen axes. Eq. (3) as printed,
//   3/2 {(s22-s33)^2 + (s33-s11)^2 + (s11-s22)^2} + 3/R12 (s23^2 + s31^2 + s12^2) - sigma^0 = 0,
// adds a squared stress to a stress and does not become von Mises at R12 = 1. Its structure is Hill's
// with cubic symmetry (F = G = H, L = M = N); the default reading (HillForm::yield_stress_ratio) is that
// form with the coefficients of the yield-stress ratios the paper's parameter list names (as in ANSYS' and
// Abaqus' Hill input): tensile yield sigma_y along every <100>, shear yield on the cube planes R12 sigma_y/sqrt3,
//   phi^2 = 1/2 {(s22-s33)^2 + (s33-s11)^2 + (s11-s22)^2} + 3/R12^2 (s23^2 + s31^2 + s12^2),
// which is von Mises at R12 = 1. HillForm::as_printed keeps the printed coefficients under the square root
// (phi^2 = 3/2 {...} + 3/R12 (...)): dimensionally sound, but its <100> yield stress is sigma_y/sqrt3 and it
// equals sqrt3 times von Mises only at R12 = 1/3. docs/METHODS.md has the discussion.
//
// Return mapping: closest-point projection (backward Euler) written for the quadratic form, as Simo & Taylor
// did for plane-stress J2: s(dgamma) = (S + dgamma P)^-1 (eps - eps_p_n), eps_p = eps_p_n + dgamma P s,
// eps_bar = eps_bar_n + dgamma phi; one scalar Newton iteration on dgamma (bracketed) with the full metric;
// the consistent tangent follows by differentiating these in closed form (symmetric).
#pragma once

#include <limits>

#include "materials/cubic_elastic.hpp"

namespace polymech::materials {

// seed 002 paper 5 eq. (4): sigma_y/sigma0 = (sigma_y/sigma0 + 3 G eps_bar/sigma0)^n, implicit in sigma_y,
// with G = C44 in the paper. It is the uniaxial power law sigma/sigma0 = (3 G eps/sigma0)^n written in the
// total strain eps = sigma/(3G) + eps_bar, so sigma_y(0) = sigma0 and the initial slope is 3 G n/(1 - n).
template <class T>
struct PowerLawHardening {
  T sigma0 = T(0);         // initial yield stress (the paper's sigma_y)
  T exponent = T(0);       // n, 0 <= n < 1 (0: perfectly plastic)
  T shear_modulus = T(0);  // G of eq. (4): C44 for the cubic crystal

  // sigma_y(eps_bar) and its slope d sigma_y / d eps_bar. x = sigma_y/sigma0 solves h(x) = x - (x+a)^n = 0,
  // a = 3 G eps_bar/sigma0; h is convex with h' >= 1 - n on x >= 1, and x0 = (1+a)^n <= root, so Newton
  // overshoots once and then descends monotonically onto the unique root.
  KOKKOS_INLINE_FUNCTION T flow_stress(T eps_bar, T& slope) const {
    const T n = exponent;
    if (!(n > T(0)) || !(eps_bar > T(0))) {
      slope = n > T(0) ? T(3) * shear_modulus * n / (T(1) - n) : T(0);
      return sigma0;
    }
    const T a = T(3) * shear_modulus * eps_bar / sigma0;
    T x = kx::exp(n * kx::log(T(1) + a));
    for (int it = 0; it < 60; ++it) {
      const T pw = kx::exp(n * kx::log(x + a));
      const T dx = (x - pw) / (T(1) - n * pw / (x + a));
      x -= dx;
      if (kx::fabs(dx) <= T(4) * std::numeric_limits<T>::epsilon() * x) break;
    }
    // At the root (x+a)^(n-1) = x/(x+a): dx/da = n x / (x + a - n x).
    slope = T(3) * shear_modulus * n * x / (x + a - n * x);
    return sigma0 * x;
  }
};

enum class HillForm { yield_stress_ratio, as_printed };

// The cubic Hill metric in crystal axes (seed 002 paper 5 eq. (3), read as the header explains): the normal
// block 2F on the diagonal and -F off it, the shear diagonal 2L (tensor shear components in s).
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> cubic_hill_metric(T R12, HillForm form = HillForm::yield_stress_ratio) {
  const bool ratio = form == HillForm::yield_stress_ratio;
  const T F = ratio ? T(0.5) : T(1.5);
  const T shear = ratio ? T(3) / (R12 * R12) : T(3) / R12;
  Stiffness6<T> P;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) P.c[i][j] = -F;
    P.c[i][i] = T(2) * F;
    P.c[i + 3][i + 3] = shear;
  }
  return P;
}
template <class T>
KOKKOS_INLINE_FUNCTION Stiffness6<T> von_mises_metric() {
  return cubic_hill_metric(T(1));
}

// The stress vector of a unit uniaxial stress along the unit direction n: s = n (x) n.
template <class T>
KOKKOS_INLINE_FUNCTION Voigt6<T> uniaxial_stress_vector(const Vec3<T>& n) {
  Voigt6<T> v;
  v[0] = n[0] * n[0]; v[1] = n[1] * n[1]; v[2] = n[2] * n[2];
  v[3] = n[1] * n[2]; v[4] = n[0] * n[2]; v[5] = n[0] * n[1];
  return v;
}
// Uniaxial yield stress along n over sigma_y: 1 / sqrt(v . P v), v = n (x) n (P and n in the same axes).
template <class T>
KOKKOS_INLINE_FUNCTION T hill_uniaxial_yield_ratio(const Stiffness6<T>& P, const Vec3<T>& n) {
  const Voigt6<T> v = uniaxial_stress_vector(n);
  return T(1) / kx::sqrt(quadratic6(v, P, v));
}

// History of a quadrature point: plastic strain (engineering shear, like every strain vector) and the
// equivalent plastic strain, work-conjugate to phi (sigma : d eps_p = phi d eps_bar).
template <class T>
struct PlasticState {
  Voigt6<T> plastic_strain;
  T equivalent_plastic_strain = T(0);
};

template <class T>
struct HillPlasticity {
  using History = PlasticState<T>;
  static constexpr bool has_history = true;
  Stiffness6<T> C;  // elastic stiffness in specimen axes
  Stiffness6<T> S;  // its inverse, kept so that a step solves with S + dgamma P and never inverts C
  Stiffness6<T> P;  // Hill metric in specimen axes
  PowerLawHardening<T> hardening;

  KOKKOS_INLINE_FUNCTION T equivalent_stress(const Voigt6<T>& s) const {
    const T q = quadratic6(s, P, s);
    return q > T(0) ? kx::sqrt(q) : T(0);
  }

  // One strain-driven step: given the total strain at the end of the step and the history at its start
  // (overwritten by the history at its end), the stress and the consistent tangent d stress / d strain.
  // A global Newton iteration must call it with a copy of the converged history of the previous step.
  // Returns the number of residual evaluations of the local Newton iteration (0: elastic; the last one
  // confirms convergence), or -1 when the local iteration failed;
  // then the history is left as it was and the stress is NaN, so the global solver's finiteness check
  // sees it and cuts the step (kernels cannot throw).
  KOKKOS_INLINE_FUNCTION int update(const Voigt6<T>& strain, History& h, Voigt6<T>& stress,
                                    Stiffness6<T>& tangent) const {
    Voigt6<T> ee;  // trial elastic strain
    for (int i = 0; i < 6; ++i) ee[i] = strain[i] - h.plastic_strain[i];
    const Voigt6<T> s_trial = C * ee;
    T H;
    const T sy_n = hardening.flow_stress(h.equivalent_plastic_strain, H);
    if (equivalent_stress(s_trial) <= sy_n) {
      stress = s_trial;
      tangent = C;
      return 0;
    }
    constexpr T eps = std::numeric_limits<T>::epsilon();
    // The residual r(dgamma) = 1 - sigma_y(eps_bar_n + dgamma phi) / phi(s(dgamma)) decreases from r(0) > 0.
    // Divided by phi, it is linear in dgamma for J2 with linear hardening (phi = phi_trial / (1 + 3 G dgamma)),
    // so Newton needs one step there and few for Hill; phi - sigma_y itself curves like 1/dgamma and took
    // 6 to 11 iterations on J2. [lo, hi] brackets the root once a step has overshot (hi < 0: none yet).
    T dg = T(0), lo = T(0), hi = T(-1), phi = T(0);
    Stiffness6<T> A, L;
    Voigt6<T> s, Ps, XiPs;
    for (int it = 1; it <= 60; ++it) {
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) A.c[i][j] = S.c[i][j] + dg * P.c[i][j];
      if (!cholesky6(A, L)) break;
      s = cholesky_solve6(L, ee);
      Ps = P * s;
      phi = kx::sqrt(kx::max(dot6(s, Ps), T(0)));
      if (!(phi > T(0))) break;
      XiPs = cholesky_solve6(L, Ps);
      const T dphi = -dot6(Ps, XiPs) / phi;
      const T sy = hardening.flow_stress(h.equivalent_plastic_strain + dg * phi, H);
      const T r = T(1) - sy / phi;
      if (kx::fabs(r) <= T(64) * eps) return finish(h, dg, phi, s, Ps, XiPs, L, H, stress, tangent, it);
      const T dr = -H * (phi + dg * dphi) / phi + sy * dphi / (phi * phi);
      if (r > T(0)) lo = dg; else hi = dg;
      T next = dg - r / dr;
      if (!(next > lo) || (hi >= T(0) && !(next < hi))) next = hi >= T(0) ? T(0.5) * (lo + hi) : T(2) * lo;
      if (next > T(0) && kx::fabs(next - dg) <= T(4) * eps * next)  // the step is round-off: r is as small as it gets
        return finish(h, dg, phi, s, Ps, XiPs, L, H, stress, tangent, it);
      dg = next;
    }
    const T nan = kx::sqrt(T(-1));
    for (int i = 0; i < 6; ++i) stress[i] = nan;
    tangent = C;
    return -1;
  }

 private:
  // History at the end of the step and the consistent tangent at dgamma (derivation: docs/METHODS.md):
  //   d s = Xi d eps - Xi P s d dgamma, Xi = (S + dgamma P)^-1, and the linearised r = 0 give
  //   D = Xi - beta (Xi n)(Xi n)^T, n = P s/phi, beta = (1 - H dgamma) / ((1 - H dgamma) n.Xi n + H).
  KOKKOS_INLINE_FUNCTION int finish(History& h, T dg, T phi, const Voigt6<T>& s, const Voigt6<T>& Ps,
                                    const Voigt6<T>& XiPs, const Stiffness6<T>& L, T H, Voigt6<T>& stress,
                                    Stiffness6<T>& tangent, int iterations) const {
    stress = s;
    for (int i = 0; i < 6; ++i) h.plastic_strain[i] += dg * Ps[i];
    h.equivalent_plastic_strain += dg * phi;
    for (int j = 0; j < 6; ++j) {
      Voigt6<T> e;
      e[j] = T(1);
      const Voigt6<T> col = cholesky_solve6(L, e);
      for (int i = 0; i < 6; ++i) tangent.c[i][j] = col[i];
    }
    const T nXin = dot6(Ps, XiPs) / (phi * phi);
    const T one_minus = T(1) - H * dg;
    const T beta = one_minus / (one_minus * nXin + H) / (phi * phi);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) tangent.c[i][j] -= beta * XiPs[i] * XiPs[j];
    return iterations;
  }
};

// The paper's six parameters (seed 002 paper 5, after eq. (4)): C11, C12, C44, the initial yield stress,
// the hardening exponent n and the yield stress ratio R12.
template <class T>
struct CubicHillParameters {
  CubicConstants<T> elastic;
  T yield_stress = T(0);
  T hardening_exponent = T(0);
  T R12 = T(1);
  HillForm form = HillForm::yield_stress_ratio;
};

// The law of a crystal whose specimen axes are the rows of Q (crystal coordinates): stiffness, compliance
// and metric rotated with the Bond matrices; eq. (4)'s G is C44.
template <class T>
KOKKOS_INLINE_FUNCTION HillPlasticity<T> make_cubic_hill(const CubicHillParameters<T>& p, const Mat3<T>& Q) {
  HillPlasticity<T> law;
  law.C = rotate_stiffness(cubic_stiffness(p.elastic), Q);
  law.S = rotate_compliance(cubic_compliance(p.elastic), Q);
  law.P = rotate_compliance(cubic_hill_metric(p.R12, p.form), Q);
  law.hardening.sigma0 = p.yield_stress;
  law.hardening.exponent = p.hardening_exponent;
  law.hardening.shear_modulus = p.elastic.C44;
  return law;
}

// J2 (von Mises) plasticity of an isotropic solid with the same hardening law (G = the shear modulus).
template <class T>
KOKKOS_INLINE_FUNCTION HillPlasticity<T> make_j2(T young, T poisson, T yield_stress, T hardening_exponent) {
  HillPlasticity<T> law;
  law.C = isotropic_stiffness(young, poisson);
  law.S = spd_inverse6(law.C);
  law.P = von_mises_metric<T>();
  law.hardening.sigma0 = yield_stress;
  law.hardening.exponent = hardening_exponent;
  law.hardening.shear_modulus = young / (T(2) * (T(1) + poisson));
  return law;
}

}  // namespace polymech::materials
