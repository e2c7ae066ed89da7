// What the ISPH cases measure (seed 002 paper 4, docs/VALIDATION.md), from the model's host copies:
// used alike by apps/isph, the tests and the sweeps.
//   - dam break: the surge front (Martin & Moyce's Z = x / a);
//   - hydrostatic tank: the pressure error against rho g (H - y);
//   - every case: the largest particle speed, the interior density over rho0;
//   - floating body: its draft, two readings;
//   - a run of a case: CaseRecord, the samples and the averages under way.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
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

// What a run of an ISPH case records while it runs (apps/isph; the values under way go into every
// checkpoint under the keys keep() names):
//  - a row per sample (columns(dam)): time, PPE iterations and residual, the dam break's front Z = x / a
//    (Martin & Moyce) or the pressure error, the largest speed, and the floating body's height, draft
//    (two readings, over the diameter) and vertical force (0 without a body);
//  - the dam break's T = t sqrt(2 g / a) of every front sample;
//  - the hydrostatic tank's pressure summed after every step of the last `average_last` seconds;
//  - the floating body's drafts summed over the samples of the last `draft_average_last` seconds of the
//    run (time >= end_time - draft_average_last) and its lowest gap to the bottom over the samples.
template <class Model>
struct CaseRecord {
  CaseRecord(const Model& model, bool dam_break, std::int64_t steps, double average_last_, double draft_average_last_,
             double end_time_)
      : m(model),
        dam(dam_break),
        body(model.has_body()),
        average_last(average_last_),
        draft_average_last(draft_average_last_),
        end_time(end_time_),
        average_from(steps - static_cast<std::int64_t>(std::llround(average_last_ / model.config().dt))) {}

  static std::vector<std::string> columns(bool dam_break) {
    return {"time", "ppe_iterations", "ppe_residual", dam_break ? "front_Z" : "pressure_error", "max_speed", "body_y",
            "draft_over_diameter", "draft_over_diameter_surface_particles", "body_force_y"};
  }
  std::size_t written_columns() const { return body ? 9 : 5; }  // series.csv: the body's columns with a body

  // keep(key, value) for every value under way (its checkpoint key).
  template <class Keep>
  void keep(Keep&& keep) {
    keep("isph/fronts_T", fronts_T);
    keep("isph/psum", psum);
    keep("isph/pcount", pcount);
    keep("isph/draft_count", draft_count);
    keep("isph/draft_sum", draft_sum);
    keep("isph/draft_surface_sum", draft_s_sum);
    keep("isph/lowest_gap", lowest_gap);
  }

  // After step k: the pressure into the hydrostatic average.
  void after_step(std::int64_t k) {
    if (dam || k <= average_from || !(average_last > 0)) return;
    const auto p = m.host_pressure();
    if (psum.empty()) psum.assign(p.size(), 0.0);
    for (std::size_t i = 0; i < p.size(); ++i) psum[i] += p[i];
    ++pcount;
  }

  // The sample at time t: a row of columns().
  std::vector<double> sample(double t) {
    const auto& c = m.config();
    const double a = c.fluid[0];
    const double q = dam ? front_position(m) / a : pressure_error(m, m.host_pressure());
    if (dam) fronts_T.push_back(t * std::sqrt(2 * c.gravity / a));
    Draft d;
    if (body) {
      lowest_gap = std::min(lowest_gap, m.body().centre[1] - 0.5 * c.body.diameter);
      d = draft(m);
      if (draft_average_last > 0 && t >= end_time - draft_average_last) {
        draft_sum += d.volume / c.body.diameter;
        draft_s_sum += d.surface / c.body.diameter;
        ++draft_count;
      }
    }
    return {t, double(m.last_solve().iterations), m.last_solve().residual, q, max_speed(m),
            body ? m.body().centre[1] : 0.0, body ? d.volume / c.body.diameter : 0.0, body ? d.surface / c.body.diameter : 0.0,
            body ? m.body().force[1] : 0.0};
  }

  // The pressure averaged over the window (the last pressure where nothing was averaged).
  std::vector<double> averaged_pressure() const {
    std::vector<double> p = m.host_pressure();
    for (std::size_t i = 0; i < p.size() && pcount > 0; ++i) p[i] = psum[i] / pcount;
    return p;
  }
  // A draft reading averaged over its window (`sum`: draft_sum or draft_s_sum), else the last sample's.
  double draft_mean(double sum, const std::vector<double>& samples) const {
    return draft_count > 0 ? sum / draft_count : (samples.empty() ? 0.0 : samples.back());
  }

  const Model& m;
  const bool dam, body;
  const double average_last, draft_average_last, end_time;
  const std::int64_t average_from;  // the hydrostatic average takes the steps after this one
  std::vector<double> fronts_T, psum;
  int pcount = 0, draft_count = 0;
  double draft_sum = 0, draft_s_sum = 0, lowest_gap = 1e300;
};

}  // namespace polymech::isph
