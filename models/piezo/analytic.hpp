// The analytic side of the piezoelectric energy harvester (issue 35; seed 002 paper 1): the distributed-
// parameter model of a symmetric bimorph cantilever under base translation with a resistive load (Erturk &
// Inman 2009, "An experimentally validated bimorph cantilever model for piezoelectric energy harvesting from
// base excitations", Smart Mater. Struct. 18 025009; below "EI09"), N modes or one, series or parallel
// connection, and the static closed forms of a bimorph bender (Hwang & Park 1993 / Tzou & Tseng 1990).
// Plain C++17 on the host, no Kokkos: the reference the finite-element model is verified against.
//
// Beam (EI09 eqs. (1)-(8), Euler-Bernoulli, the piezo layers' plane-stress reduced constants):
//   YI = (2b/3) [Ys hs^3/8 + c11 ((hp + hs/2)^3 - hs^3/8)],   m = b (rho_s hs + 2 rho_p hp)
//   clamped-free modes, mass normalised (int m phi_r phi_s dx = delta_rs):
//   phi_r(x) = (m L)^-1/2 [cosh(l x/L) - cos(l x/L) - s_r (sinh(l x/L) - sin(l x/L))],
//   s_r = (sinh l - sin l)/(cosh l + cos l),  1 + cos l cosh l = 0 (l = lambda_r),  w_r = l^2 sqrt(YI/(m L^4)).
// Electromechanical coupling (EI09 eqs. (16)-(17) series, (32)-(33) parallel):
//   series:   vartheta = e31 b (hp + hs)/2,  Cp = eps33 b L / (2 hp)
//   parallel: vartheta = e31 b (hp + hs),    Cp = 2 eps33 b L / hp
//   theta_r = vartheta dphi_r/dx (L)  (the modal coupling chi_r of EI09).
// Equations (our signs, chosen so that the sum of the two is the energy balance):
//   eta_r'' + 2 zeta_r w_r eta_r' + w_r^2 eta_r - theta_r v = -m (int_0^L phi_r dx) a_b(t)
//   Cp v' + v / R = -sum_r theta_r eta_r'
// For a_b = a0 e^{i w t} (a0 = -w^2 W0, W0 the base displacement amplitude), with D_r = w_r^2 - w^2 + 2 i zeta_r
// w_r w and F_r = -m int phi_r = -2 s_r sqrt(m L)/lambda_r (per unit a0):
//   V / a0 = -i w sum_r (theta_r F_r / D_r) / (1/R + i w Cp + i w sum_r theta_r^2 / D_r)        (EI09 eq. (39))
//   eta_r / a0 = (F_r + theta_r V) / D_r,   w_rel(L) / a0 = sum_r phi_r(L) eta_r                (EI09 eq. (42))
//   I = V / R,  mean power in R: P = |V|^2 / (2 R)   (amplitudes; EI09 plot |V|^2/R, twice this)
// Energy: mean base work P_in = 1/2 Re(sum_r F_r conj(i w eta_r)) = P + P_damp, P_damp = sum_r zeta_r w_r w^2
// |eta_r|^2 (tested). Short-circuit frequencies: w_r. Open-circuit: the roots of Cp + sum_r theta_r^2 /
// (w_r^2 - w^2) = 0; one mode: w_oc = w_1 sqrt(1 + theta_1^2 / (Cp w_1^2)).
// Optimal load at a frequency, exactly (the load admittance matched to the harvester's): with the harvester
// admittance Y(w) = i w Cp + i w sum_r theta_r^2 / D_r, P(R) is largest at R_opt = 1/|Y(w)|; for weak coupling
// (theta_1^2 / (Cp w_1^2) << zeta_1) this tends to the textbook 1/(w Cp).
//
// Static bender (derivation in the docs notes): a constant voltage V gives the constant curvature
// kappa = vartheta V / YI, tip deflection delta = vartheta V L^2 / (2 YI); for two equal layers with no host
// (hs = 0, hp = t/2, series) this is the textbook delta = 3 d31 V L^2 / (2 t^2) (uniaxial stress: sigma_2 = 0,
// the modulus cancels); a wide plate in cylindrical bending (eps_2 = 0, d32 = d31) bends (1 + nu) times more.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "piezo/materials.hpp"

namespace polymech::piezo {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kGravity = 9.81;  // 1 g [m/s^2], the unit of the per-g responses

// The r-th root (r = 1, 2, ...) of 1 + cos(l) cosh(l) = 0 (the clamped-free beam), solved as
// cos(l) + 1/cosh(l) = 0 (bounded for large l) by bisection on ((r-1) pi, r pi) and Newton polishing.
inline double clamped_free_lambda(int r) {
  if (r < 1) throw std::invalid_argument("clamped_free_lambda: r >= 1");
  auto f = [](double l) { return std::cos(l) + 1.0 / std::cosh(l); };
  double a = (r - 1) * kPi, b = r * kPi;
  double fa = f(a);
  for (int k = 0; k < 60; ++k) {
    const double c = 0.5 * (a + b), fc = f(c);
    if ((fc > 0) == (fa > 0)) {
      a = c;
      fa = fc;
    } else {
      b = c;
    }
  }
  double l = 0.5 * (a + b);
  for (int k = 0; k < 3; ++k) {
    const double df = -std::sin(l) - std::tanh(l) / std::cosh(l);
    l -= f(l) / df;
  }
  return l;
}

// One clamped-free mode shape without the normalisation: the values and slopes of
// g(xi) = cosh(l xi) - cos(l xi) - s (sinh(l xi) - sin(l xi)), xi in [0, 1], computed without the cancellation
// of cosh and s sinh (s -> 1 as l grows): cosh y - s sinh y = (e^-y (1 + s) + e^y (1 - s)) / 2 with
// 1 - s = (e^-l + cos l + sin l) / (cosh l + cos l).
struct ClampedFreeShape {
  double l, s, one_minus_s;
  explicit ClampedFreeShape(double lambda)
      : l(lambda),
        s((std::sinh(lambda) - std::sin(lambda)) / (std::cosh(lambda) + std::cos(lambda))),
        one_minus_s((std::exp(-lambda) + std::cos(lambda) + std::sin(lambda)) /
                    (std::cosh(lambda) + std::cos(lambda))) {}
  double value(double xi) const {
    const double y = l * xi;
    return 0.5 * (std::exp(-y) * (1.0 + s) + std::exp(y) * one_minus_s) - std::cos(y) + s * std::sin(y);
  }
  // d g / d xi
  double slope(double xi) const {
    const double y = l * xi;
    return l * (0.5 * (std::exp(y) * one_minus_s - std::exp(-y) * (1.0 + s)) + std::sin(y) + s * std::cos(y));
  }
  double integral() const { return 2.0 * s / l; }  // int_0^1 g d xi (closed form, see the docs notes)
};

enum class Connection { series, parallel };
inline const char* to_string(Connection c) { return c == Connection::series ? "series" : "parallel"; }

// A symmetric bimorph cantilever: host of thickness hs between two piezo layers of thickness hp each, poled
// oppositely (series) or alike (parallel), electrodes covering the whole length, no tip mass.
struct BimorphSpec {
  double L = 0, b = 0, hs = 0, hp = 0;  // [m]
  IsotropicElastic host{};
  ReducedPiezo piezo{};
  Connection connection = Connection::series;
  std::vector<double> zeta{0.01};  // modal damping ratios; the last entry serves the higher modes
  int modes = 1;
  // EI09 takes the field uniform through each layer. In bending it is not: with both faces of a layer at
  // fixed potentials, the strain's linear variation about the layer's own mid-plane induces a potential
  // quadratic through the thickness (zero mean), which stiffens that part of the layer by e31^2 / eps33:
  //   YI += 2 b (e31_bar^2 / eps33_bar) hp^3 / 12   (both layers; the coupling and Cp are unchanged).
  // A converged 2D or 3D finite-element model has this effect (PZT-5A: +1.7 % in YI, +0.83 % in frequency
  // for the duToit bimorph); true adds it to the beam, false is EI09 as published.
  bool induced_potential = false;
};

// The steady response at one frequency to a unit base acceleration amplitude (a_b = 1 m/s^2 e^{i w t}).
struct Response {
  double omega = 0, R = 0;
  std::complex<double> V, I;          // load voltage [V], current through R [A]
  std::complex<double> tip_rel;       // tip displacement relative to the base [m]
  std::complex<double> tip_abs;       // absolute tip displacement (base W0 = -1/w^2 added) [m]
  std::vector<std::complex<double>> eta;  // modal coordinates
  double power = 0;                   // mean power in R, |V|^2/(2R) [W]
  double power_in = 0;                // mean power the base puts in [W]
  double power_damping = 0;           // mean power of the modal damping [W]
};

class BimorphHarvester {
 public:
  explicit BimorphHarvester(const BimorphSpec& s) : s_(s) {
    if (s.L <= 0 || s.b <= 0 || s.hp <= 0 || s.hs < 0 || s.modes < 1 || s.zeta.empty())
      throw std::invalid_argument("BimorphHarvester: L, b, hp > 0, hs >= 0, modes >= 1, zeta given");
    if (s.modes > 60) throw std::invalid_argument("BimorphHarvester: at most 60 modes");
    const double hs3 = s.hs * s.hs * s.hs / 8.0, ht = s.hp + 0.5 * s.hs;
    YI_ = 2.0 * s.b / 3.0 * (s.host.E * hs3 + s.piezo.c11 * (ht * ht * ht - hs3));
    if (s.induced_potential)
      YI_ += 2.0 * s.b * s.piezo.e31 * s.piezo.e31 / s.piezo.eps33 * s.hp * s.hp * s.hp / 12.0;
    m_ = s.b * (s.host.rho * s.hs + 2.0 * s.piezo.rho * s.hp);
    const double vs = s.piezo.e31 * s.b * (s.hp + s.hs) / 2.0;
    const double Cs = s.piezo.eps33 * s.b * s.L / (2.0 * s.hp);
    vartheta_ = s.connection == Connection::series ? vs : 2.0 * vs;
    Cp_ = s.connection == Connection::series ? Cs : 4.0 * Cs;
    const double norm = 1.0 / std::sqrt(m_ * s.L);
    for (int r = 1; r <= s.modes; ++r) {
      const ClampedFreeShape g(clamped_free_lambda(r));
      shapes_.push_back(g);
      omega_.push_back(g.l * g.l * std::sqrt(YI_ / (m_ * s.L * s.L * s.L * s.L)));
      theta_.push_back(vartheta_ * norm * g.slope(1.0) / s.L);
      forcing_.push_back(-m_ * norm * s.L * g.integral());
      phi_tip_.push_back(norm * g.value(1.0));
      zeta_.push_back(s.zeta[std::min<std::size_t>(static_cast<std::size_t>(r - 1), s.zeta.size() - 1)]);
    }
  }

  const BimorphSpec& spec() const { return s_; }
  int modes() const { return s_.modes; }
  double YI() const { return YI_; }
  double mass_per_length() const { return m_; }
  double capacitance() const { return Cp_; }  // Cp of the connection [F]
  double vartheta() const { return vartheta_; }
  // 0-based mode index r
  double lambda(int r) const { return shapes_[r].l; }
  double omega(int r) const { return omega_[r]; }    // short-circuit natural frequency [rad/s]
  double theta(int r) const { return theta_[r]; }    // modal coupling chi_r [N/V per unit modal coordinate]
  double forcing(int r) const { return forcing_[r]; }  // -m int phi_r dx
  double zeta(int r) const { return zeta_[r]; }
  double phi(int r, double x) const { return shapes_[r].value(x / s_.L) / std::sqrt(m_ * s_.L); }
  double dphi(int r, double x) const { return shapes_[r].slope(x / s_.L) / (s_.L * std::sqrt(m_ * s_.L)); }
  double phi_tip(int r) const { return phi_tip_[r]; }

  // The steady response at w [rad/s] and load R [ohm] (R = 0: short circuit, R = inf: open circuit).
  Response response(double w, double R) const {
    using C = std::complex<double>;
    const C i(0.0, 1.0);
    const int N = s_.modes;
    std::vector<C> D(N);
    C num = 0.0, sum2 = 0.0;
    for (int r = 0; r < N; ++r) {
      D[r] = C(omega_[r] * omega_[r] - w * w, 2.0 * zeta_[r] * omega_[r] * w);
      num += theta_[r] * forcing_[r] / D[r];
      sum2 += theta_[r] * theta_[r] / D[r];
    }
    Response o;
    o.omega = w;
    o.R = R;
    if (R > 0.0) {
      const double G = std::isinf(R) ? 0.0 : 1.0 / R;
      o.V = -i * w * num / (G + i * w * Cp_ + i * w * sum2);
      o.I = o.V * G;
      o.power = 0.5 * std::norm(o.V) * G;
    } else {  // short circuit: v = 0, the current is -sum theta_r eta_r'
      o.V = 0.0;
      o.I = -i * w * num;
    }
    o.eta.resize(N);
    for (int r = 0; r < N; ++r) {
      o.eta[r] = (forcing_[r] + theta_[r] * o.V) / D[r];
      o.tip_rel += phi_tip_[r] * o.eta[r];
      o.power_in += 0.5 * std::real(forcing_[r] * std::conj(i * w * o.eta[r]));
      o.power_damping += zeta_[r] * omega_[r] * w * w * std::norm(o.eta[r]);
    }
    o.tip_abs = o.tip_rel - 1.0 / (w * w);
    return o;
  }

  // The load that maximises the mean power at w, exactly: 1/|Y(w)| (see the header comment).
  double optimal_load(double w) const {
    using C = std::complex<double>;
    C sum2 = 0.0;
    for (int r = 0; r < s_.modes; ++r)
      sum2 += theta_[r] * theta_[r] / C(omega_[r] * omega_[r] - w * w, 2.0 * zeta_[r] * omega_[r] * w);
    return 1.0 / std::abs(C(0.0, w) * (Cp_ + sum2));
  }

  // The open-circuit natural frequencies [rad/s] (undamped), one above each short-circuit one: the roots of
  // g(w^2) = Cp + sum theta_r^2 / (w_r^2 - w^2), bisected in w^2 on (w_r^2, w_{r+1}^2) and, for the last, on
  // (w_N^2, w_N^2 + sum theta^2 / Cp] where g >= 0.
  std::vector<double> open_circuit_frequencies() const {
    const int N = s_.modes;
    double t2 = 0.0;
    for (int r = 0; r < N; ++r) t2 += theta_[r] * theta_[r];
    auto g = [&](double w2) {
      double v = Cp_;
      for (int r = 0; r < N; ++r) v += theta_[r] * theta_[r] / (omega_[r] * omega_[r] - w2);
      return v;
    };
    std::vector<double> out;
    for (int r = 0; r < N; ++r) {
      double a = omega_[r] * omega_[r];
      double b = r + 1 < N ? omega_[r + 1] * omega_[r + 1] : a + t2 / Cp_;
      for (int k = 0; k < 200 && b - a > 1e-15 * b; ++k) {
        const double c = 0.5 * (a + b);
        (g(c) < 0.0 ? a : b) = c;
      }
      out.push_back(std::sqrt(0.5 * (a + b)));
    }
    return out;
  }
  // One mode: the closed form w_oc = w_r sqrt(1 + theta_r^2 / (Cp w_r^2)) (EI09 section 5).
  double open_circuit_frequency_single_mode(int r) const {
    return omega_[r] * std::sqrt(1.0 + theta_[r] * theta_[r] / (Cp_ * omega_[r] * omega_[r]));
  }
  // The open-circuit frequency of mode r of the continuous beam (all modes, exactly): with no current the
  // electrode voltage is v = -vartheta w'(L) / Cp, and the tip moment condition YI w''(L) - vartheta v = 0
  // becomes a rotational spring k = vartheta^2 / Cp at the free end. With y = beta L, K = k L / YI, the
  // clamped / spring-and-free-shear beam has the characteristic equation
  //   1 + cos y cosh y + (K / y) (sinh y cos y + sin y cosh y) = 0      (divided by cosh y below),
  // bisected on [lambda_r, (4r - 1) pi / 4 + 0.1] (the root moves from lambda_r, K = 0, towards the guided-end
  // root of tan y = -tanh y as K grows). The N-mode open_circuit_frequencies() converge to it like 1/N.
  double open_circuit_frequency_exact(int r) const {
    const double K = vartheta_ * vartheta_ / Cp_ * s_.L / YI_;
    auto f = [K](double y) {
      return 1.0 / std::cosh(y) + std::cos(y) + K / y * (std::tanh(y) * std::cos(y) + std::sin(y));
    };
    double a = clamped_free_lambda(r + 1), b = (4.0 * (r + 1) - 1.0) * kPi / 4.0 + 0.1;
    double fa = f(a);
    if ((fa > 0) == (f(b) > 0)) throw std::runtime_error("open_circuit_frequency_exact: no bracket");
    for (int k = 0; k < 200 && b - a > 1e-15 * b; ++k) {
      const double c = 0.5 * (a + b), fc = f(c);
      if ((fc > 0) == (fa > 0)) {
        a = c;
        fa = fc;
      } else {
        b = c;
      }
    }
    const double y = 0.5 * (a + b);
    return y * y * std::sqrt(YI_ / (m_ * s_.L * s_.L * s_.L * s_.L));
  }
  // The effective coupling of mode r, k_r^2 = theta_r^2 / (Cp w_r^2) = (w_oc/w_sc)^2 - 1 (one mode).
  double coupling_k2(int r) const { return theta_[r] * theta_[r] / (Cp_ * omega_[r] * omega_[r]); }

  // Static tip deflection under an applied voltage V (the bender): vartheta V L^2 / (2 YI).
  double static_tip_deflection(double V) const { return vartheta_ * V * s_.L * s_.L / (2.0 * YI_); }

 private:
  BimorphSpec s_;
  double YI_ = 0, m_ = 0, Cp_ = 0, vartheta_ = 0;
  std::vector<ClampedFreeShape> shapes_;
  std::vector<double> omega_, theta_, forcing_, phi_tip_, zeta_;
};

// The maximum of a unimodal f on [a, b] by golden-section search: returns the argument.
template <class F>
double golden_max(F&& f, double a, double b, double rel_tol = 1e-12) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a), fc = f(c), fd = f(d);
  for (int k = 0; k < 400 && (b - a) > rel_tol * (std::fabs(a) + std::fabs(b)); ++k) {
    if (fc > fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - g * (b - a);
      fc = f(c);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + g * (b - a);
      fd = f(d);
    }
  }
  return 0.5 * (a + b);
}

// The frequency [rad/s] of the largest |V| (R > 0) or |I| (R = 0) within [w_lo, w_hi].
inline double peak_frequency(const BimorphHarvester& h, double R, double w_lo, double w_hi) {
  return golden_max(
      [&](double w) {
        const Response o = h.response(w, R);
        return R > 0 ? std::abs(o.V) : std::abs(o.I);
      },
      w_lo, w_hi);
}

// The load [ohm] of the largest mean power at w, found numerically (golden section in log R on
// [R_lo, R_hi]); compare with BimorphHarvester::optimal_load, its closed form.
inline double optimal_load_numeric(const BimorphHarvester& h, double w, double R_lo, double R_hi) {
  const double x = golden_max([&](double lr) { return h.response(w, std::exp(lr)).power; }, std::log(R_lo),
                              std::log(R_hi), 1e-13);
  return std::exp(x);
}

// Static bimorph bender closed forms (Tzou & Tseng 1990; Hwang & Park 1993; derivation in the docs notes).
// Series bimorph, two equal layers of total thickness t, no host, uniaxial stress (a beam: sigma_2 = 0):
//   delta = 3 d31 V L^2 / (2 t^2)
inline double series_bimorph_tip_deflection(double d31, double V, double L, double t) {
  return 1.5 * d31 * V * L * L / (t * t);
}
// The same bender as a wide plate in cylindrical bending (eps_2 = 0, d32 = d31): (1 + nu) times the above.
inline double series_bimorph_tip_deflection_plane_strain(double d31, double V, double L, double t, double nu) {
  return (1.0 + nu) * series_bimorph_tip_deflection(d31, V, L, t);
}
// A parallel-plate capacitor: eps A / t. The free layer (stress free): eps33^T; a layer clamped in all
// strains: eps33^S; a layer bonded in a beam (uniaxial stress): eps33_bar = eps33^T - d31^2/s11^E.
inline double plate_capacitance(double eps, double area, double t) { return eps * area / t; }

// The two cases of the sweep tool and the tests.
// "erturk": EI09 Table 1, the PZT-5H bimorph without tip mass (series; reported short/open-circuit
// frequencies 502.5 / 524.7 Hz). zeta defaults to 0.027, EI09's identified mode-1 damping as recalled, not
// checked against the paper (the frequencies do not depend on it, the powers scale about as 1/zeta).
inline BimorphSpec erturk_inman_2009_case() {
  BimorphSpec s;
  s.L = 24.53e-3;
  s.b = 6.4e-3;
  s.hp = 0.265e-3;
  s.hs = 0.14e-3;
  s.host = brass();
  s.piezo = pzt5h_erturk_inman_2009();
  s.connection = Connection::series;
  s.zeta = {0.027};
  s.modes = 1;
  return s;
}
// "dutoit": seed 002 paper 1's cantilever (duToit & Wardle 2007): brass 0.14 mm, PZT-5A 0.27 mm on both faces,
// 55 mm long; width 6.4 mm (not given; the docs notes say why), series, zeta 0.01 (not given).
inline BimorphSpec dutoit_wardle_2007_case() {
  BimorphSpec s;
  s.L = 55e-3;
  s.b = 6.4e-3;
  s.hp = 0.27e-3;
  s.hs = 0.14e-3;
  s.host = brass();
  s.piezo = reduce(pzt5a());
  s.connection = Connection::series;
  s.zeta = {0.01};
  s.modes = 1;
  return s;
}

}  // namespace polymech::piezo
