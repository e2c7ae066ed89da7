// The Turek-Hron CFD tests (Turek & Hron 2006, "Proposal for numerical benchmarking of fluid-structure
// interaction between an elastic object and laminar incompressible flow", section 3.1 and Table 6): the channel
// with the cylinder and a rigid flag, rho = 1000, nu = 1e-3, the parabolic inflow
//   U(0, y) = 1.5 Ubar y (H - y) / (H / 2)^2,
// ramped in time by (1 - cos(pi t / 2)) / 2 for t < 2 s (CFD3); no slip on the walls, cylinder and flag;
// do-nothing outflow. CFD1: Ubar = 0.2 (Re 20), CFD2: Ubar = 1 (Re 100), steady; CFD3: Ubar = 2 (Re 200),
// periodic. Drag and lift are the forces on the cylinder and flag together (newtons per metre).
// And what the periodic case reports: the mean and amplitude over the last period, and the frequency.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/navier_stokes.hpp"

namespace polymech::flow {

struct TurekHronReference {
  double drag = 0.0, lift = 0.0;                 // steady (CFD1, CFD2) or the means (CFD3)
  double drag_amplitude = 0.0, lift_amplitude = 0.0, frequency = 0.0;
};
// Turek & Hron 2006, Table 12 (CFD1, CFD2) and Table 13 (CFD3, the finest level).
inline TurekHronReference turek_hron_reference(int test) {
  switch (test) {
    case 1: return {14.29, 1.119, 0.0, 0.0, 0.0};
    case 2: return {136.7, 10.53, 0.0, 0.0, 0.0};
    case 3: return {439.45, -11.893, 5.6183, 437.81, 4.3956};
    default: throw std::invalid_argument("turek-hron: CFD test " + std::to_string(test) + " is not 1, 2 or 3");
  }
}

struct TurekHronCase {
  double mean_velocity = 0.2;  // Ubar
  double ramp_time = 0.0;      // 0: the full inflow from t = 0 (steady tests); 2 s for CFD3
  double rho = 1000.0, nu = 1e-3;
  int level = 1;
  // An optional kick that breaks the symmetry so a periodic run (CFD3) sheds sooner: the cylinder and flag turn
  // as one rigid body about the cylinder's centre with angular velocity omega(t) = kick_omega sin^2(pi s),
  // s = (t - kick_start) / kick_duration in [0, 1] (zero outside), imposed as the no-slip velocity
  // omega x (x - c) on the obstacle's nodes (a rigid motion: no net flux); the geometry does not move.
  // 0: none (the benchmark as published; shedding then grows from round-off).
  double kick_omega = 0.0, kick_start = 2.0, kick_duration = 0.25;
};

inline FlowConfig turek_hron_config(const TurekHronCase& c, const TurekHronGeometry& g = {}) {
  // 0: no inflow, the fluid at rest unless a wall moves (the weakly coupled flap, models/fsi/turek_hron_fsi.hpp)
  if (!(c.mean_velocity >= 0)) throw std::invalid_argument("turek-hron: the mean inflow velocity must not be negative");
  FlowConfig cfg;
  cfg.rho = c.rho;
  cfg.nu = c.nu;
  cfg.dirichlet_tags = kInflow | kWall | kObstacle;
  if (c.kick_omega != 0.0 && !(c.kick_duration > 0.0)) throw std::invalid_argument("turek-hron: the kick's duration must be positive");
  const double H = g.height, Ubar = c.mean_velocity, ramp = c.ramp_time;
  const double kw = c.kick_omega, k0 = c.kick_start, kd = c.kick_duration, cx = g.cx, cy = g.cy;
  cfg.boundary_velocity = [H, Ubar, ramp, kw, k0, kd, cx, cy](unsigned tags, double x, double y, double t) -> Vec2 {
    const double pi = 3.14159265358979323846;
    if ((tags & kObstacle) && kw != 0.0 && t > k0 && t < k0 + kd) {
      const double s = std::sin(pi * (t - k0) / kd), w = kw * s * s;
      return {-w * (y - cy), w * (x - cx)};
    }
    if (!(tags & kInflow) || (tags & (kWall | kObstacle))) return {0.0, 0.0};
    const double factor = (ramp > 0.0 && t < ramp) ? 0.5 * (1.0 - std::cos(pi * t / ramp)) : 1.0;
    return {factor * 1.5 * Ubar * y * (H - y) / (0.25 * H * H), 0.0};
  };
  return cfg;
}

// Mean, amplitude and frequency of a periodic signal over its last full period, as the benchmark defines them:
// mean = (max + min) / 2, amplitude = (max - min) / 2 between the last two maxima of `period_signal` (the lift:
// the drag oscillates at twice its frequency), frequency = 1 / that period. Maxima are refined by the parabola
// through the sample and its neighbours. Returns false when fewer than two maxima are found.
struct PeriodicStats {
  double mean = 0.0, amplitude = 0.0, frequency = 0.0, t_begin = 0.0, t_end = 0.0;
};
inline bool last_period(const std::vector<double>& t, const std::vector<double>& period_signal, double& t0, double& t1) {
  std::vector<double> peaks;
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    const double a = period_signal[k - 1], b = period_signal[k], c = period_signal[k + 1];
    if (b > a && b >= c) {
      const double den = a - 2 * b + c, h = t[k + 1] - t[k];
      const double off = den != 0.0 ? 0.5 * (a - c) / den : 0.0;
      peaks.push_back(t[k] + off * h);
    }
  }
  if (peaks.size() < 2) return false;
  t0 = peaks[peaks.size() - 2];
  t1 = peaks.back();
  return t1 > t0;
}
inline PeriodicStats periodic_stats(const std::vector<double>& t, const std::vector<double>& s, double t0, double t1) {
  PeriodicStats p;
  p.t_begin = t0;
  p.t_end = t1;
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 1; k + 1 < t.size(); ++k) {
    if (t[k] < t0 - (t[k + 1] - t[k]) || t[k] > t1 + (t[k] - t[k - 1])) continue;
    const double a = s[k - 1], b = s[k], c = s[k + 1];  // the parabola's extreme near a sample extreme
    const double den = a - 2 * b + c;
    double v = b;
    if (den != 0.0 && ((b >= a && b >= c) || (b <= a && b <= c))) v = b - 0.125 * (a - c) * (a - c) / den;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  p.mean = 0.5 * (hi + lo);
  p.amplitude = 0.5 * (hi - lo);
  p.frequency = 1.0 / (t1 - t0);
  return p;
}

}  // namespace polymech::flow
