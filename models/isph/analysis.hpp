// What the ISPH cases measure (seed 002 paper 4, docs/VALIDATION.md), from the model's host copies:
// used alike by apps/isph, the tests and the sweeps.
//   - dam break: the surge front (Martin & Moyce's Z = x / a);
//   - hydrostatic tank: the pressure error against rho g (H - y);
//   - every case: the largest particle speed, the interior density over rho0;
//   - floating body: its draft, two readings.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "isph/isph.hpp"

namespace polymech::isph {

// The surge front: the largest x of a fluid particle near the floor (y < 2 l0), plus l0 / 2.
template <class Model>
double front_position(const Model& m) {
  constexpr int D = Model::dimension;
  const auto x = m.host_positions();
  const double l0 = m.config().spacing;
  double front = 0.0;
  for (std::size_t i = 0; i < x.size() / D; ++i)
    if (x[i * D + 1] < 2 * l0) front = std::max(front, x[i * D]);
  return front + 0.5 * l0;
}

// Relative L2 error of the pressures `p` of the particles off the free surface against the hydrostatic
// rho g (H - y), H the fluid's initial height.
template <class Model>
double pressure_error(const Model& m, const std::vector<double>& p) {
  constexpr int D = Model::dimension;
  const auto x = m.host_positions();
  const auto s = m.host_surface();
  const double rg = m.config().density * m.config().gravity, H = m.config().fluid[1];
  double e = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (s[i]) continue;
    const double a = rg * (H - x[i * D + 1]);
    e += (p[i] - a) * (p[i] - a);
    n += a * a;
  }
  return n > 0 ? std::sqrt(e / n) : 0.0;
}

// The largest particle speed.
template <class Model>
double max_speed(const Model& m) {
  constexpr int D = Model::dimension;
  const auto v = m.host_velocities();
  double s = 0;
  for (std::size_t i = 0; i < v.size() / D; ++i) {
    double a = 0;
    for (int d = 0; d < D; ++d) a += v[i * D + d] * v[i * D + d];
    s = std::max(s, std::sqrt(a));
  }
  return s;
}

// The mean summation density of the particles off the free surface, over rho0 (density drift).
template <class Model>
double interior_density_ratio(const Model& m) {
  const auto rho = m.host_density();
  const auto srf = m.host_surface();
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < rho.size(); ++i)
    if (!srf[i]) {
      sum += rho[i];
      ++n;
    }
  return n > 0 ? sum / n / m.config().density : 0.0;
}

// The floating body's draft, two readings (docs/VALIDATION.md, ISPH floating body), both the water level
// minus the body's lowest point, with the level
//  - from the volume (`volume`): the height L of a flat free surface over the tank's width W holding the
//    water (N l0^2) and the part of the body below L: W L = N l0^2 + A_seg(L - y_low), the undisturbed
//    level of Archimedes' principle;
//  - from the particles (`surface`): the mean height of the surface particles more than one diameter from
//    the body, plus l0/2 (where the eye puts it; the surface layer settles 0.2-0.5 l0 below the water's
//    level, see the hydrostatic tank).
struct Draft {
  double volume = 0.0, surface = 0.0;
};
template <class Model>
Draft draft(const Model& m) {
  constexpr int D = Model::dimension;
  const auto& c = m.config();
  const auto x = m.host_positions();
  const auto srf = m.host_surface();
  const auto& b = m.body();
  const double diameter = c.body.diameter, R = 0.5 * diameter, W = m.tank_size(0);
  const double bottom = b.centre[1] - R;
  double sum = 0;
  int n = 0;
  for (std::size_t i = 0; i < srf.size(); ++i)
    if (srf[i] && std::fabs(x[i * D] - b.centre[0]) > diameter) {
      sum += x[i * D + 1];
      ++n;
    }
  const double water = double(m.particles()) * c.spacing * c.spacing;
  double lo = 0.0, hi = c.tank[1] + 2 * R;  // W L - A_seg(L - bottom) rises with L (W > 2R): bisection
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    (W * mid - segment_area(R, mid - bottom) < water ? lo : hi) = mid;
  }
  Draft d;
  d.volume = 0.5 * (lo + hi) - bottom;
  d.surface = (n > 0 ? sum / n + 0.5 * c.spacing : c.fluid[1]) - bottom;
  return d;
}

}  // namespace polymech::isph
