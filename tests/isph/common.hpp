// Helpers of the ISPH tests: configurations of the reduced cases and their measurements.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "isph/analysis.hpp"
#include "isph/isph.hpp"

namespace isph_test {

namespace pm = polymech;
namespace ip = polymech::isph;

inline ip::Config tank_config(int dim, double l0, double width, double height, double dt) {
  ip::Config c;
  c.dim = dim;
  c.spacing = l0;
  c.tank[0] = c.tank[2] = width;
  c.tank[1] = height + 4 * l0;
  c.fluid[0] = c.fluid[2] = width;
  c.fluid[1] = height;
  c.dt = dt;
  c.viscosity = 1e-3;  // Table 1
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization"}, ip::effect_table());
  return c;
}

struct Hydrostatic {
  double error_surface = 0.0;  // relative L2 against rho g (H_s - y), H_s: mean height of the surface particles
  double error_height = 0.0;   // against rho g (H - y), H: the initial water height
  double max_speed = 0.0;
  double surface_height = 0.0;
  int surface_particles = 0;
};

// The pressure of each particle averaged over the steps it is given (particles of a settled tank move
// less than 1 % of l0 in that time).
struct AveragedPressure {
  std::vector<double> sum;
  int count = 0;
  template <class Model>
  void add(const Model& m) {
    const auto p = m.host_pressure();
    if (sum.empty()) sum.assign(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) sum[i] += p[i];
    ++count;
  }
  std::vector<double> mean() const {
    std::vector<double> out(sum);
    for (auto& v : out) v /= count;
    return out;
  }
};

template <class Model>
Hydrostatic measure_hydrostatic(const Model& m, double height, std::vector<double> p = {}) {
  constexpr int D = Model::dimension;
  const auto x = m.host_positions();
  if (p.empty()) p = m.host_pressure();
  const auto s = m.host_surface();
  const double rg = m.config().density * m.config().gravity;
  Hydrostatic h;
  double hs = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (s[i]) {
      hs += x[i * D + 1];
      ++h.surface_particles;
    }
  h.surface_height = h.surface_particles > 0 ? hs / h.surface_particles : height;
  double e1 = 0, e2 = 0, n1 = 0, n2 = 0;
  h.max_speed = ip::max_speed(m);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (s[i]) continue;
    const double a = rg * (h.surface_height - x[i * D + 1]), b = rg * (height - x[i * D + 1]);
    e1 += (p[i] - a) * (p[i] - a);
    n1 += a * a;
    e2 += (p[i] - b) * (p[i] - b);
    n2 += b * b;
  }
  h.error_surface = std::sqrt(e1 / n1);
  h.error_height = std::sqrt(e2 / n2);
  return h;
}

// The surge front and the largest speed: what the app measures (models/isph/analysis.hpp).
using polymech::isph::front_position;

}  // namespace isph_test

namespace isph_test {

// The dam break of Koshizuka & Oka (1996): a water column a wide and 2a high (n^2 = 2) at the left wall
// of a tank 4a wide.
inline ip::Config dam_break_config(double a, int particles_across, double dt) {
  ip::Config c;
  c.dim = 2;
  c.spacing = a / particles_across;
  c.tank[0] = 4 * a;
  c.tank[1] = 3 * a;
  c.fluid[0] = a;
  c.fluid[1] = 2 * a;
  c.dt = dt;
  c.viscosity = 1e-6;
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization"}, ip::effect_table());
  return c;
}

// Martin & Moyce (1952), n^2 = 2, a = 2.25 in: surge front Z = x / a against T = t sqrt(2 g / a), as
// tabulated in public SPH validation scripts (their Tables 2 and 6; the primary was not available here).
inline const std::vector<std::pair<double, double>>& martin_moyce() {
  static const std::vector<std::pair<double, double>> d = {
      {0.41, 1.11}, {0.84, 1.22}, {1.19, 1.44}, {1.43, 1.67}, {1.63, 1.89}, {1.83, 2.11}, {1.98, 2.33},
      {2.20, 2.56}, {2.32, 2.78}, {2.51, 3.00}, {2.65, 3.22}, {2.83, 3.44}, {2.98, 3.67}, {3.11, 3.89}};
  return d;
}
// Koshizuka & Oka (1996) experiment (a = 0.146 m), points digitised from their figure (as distributed
// with public SPH example scripts).
inline const std::vector<std::pair<double, double>>& koshizuka_oka() {
  static const std::vector<std::pair<double, double>> d = {{0.0, 1.000},   {0.381, 1.111}, {0.769, 1.252},
                                                           {1.153, 1.505}, {1.537, 1.892}, {1.935, 2.241},
                                                           {2.323, 2.615}, {2.719, 3.003}, {3.096, 3.624}};
  return d;
}
inline double interpolate(const std::vector<std::pair<double, double>>& d, double T) {
  if (T <= d.front().first) return d.front().second;
  for (std::size_t k = 1; k < d.size(); ++k)
    if (T <= d[k].first)
      return d[k - 1].second + (d[k].second - d[k - 1].second) * (T - d[k - 1].first) / (d[k].first - d[k - 1].first);
  return d.back().second;
}

}  // namespace isph_test
