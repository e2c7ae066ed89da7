// What the EFG crack cases measure (seed 004, Hagihara et al.; docs/VALIDATION.md), used alike by
// apps/efg, the tests and the sweeps:
//   - static: K_I / (sigma sqrt(pi a)) from the J-integral on every path, against the handbook value;
//   - dynamic: a sample of the stationary or running crack (J' on every path, the crack opening, the
//     energy balance of the average-acceleration rule), its row of the run's history and what the
//     summary reads off the history (the K factor's peak, the energy error);
//   - the displacement and stress at the nodes (MLS values: the nodal coefficients are not the
//     displacements).
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "efg/efg.hpp"

namespace polymech::efg {

// The static J on every path of config().j_radii (seed 004 eq. (13), quasi-static).
struct StaticSif {
  std::vector<double> radii, j, k, factor, error;  // per path; error: factor / handbook - 1
  double mean = 0.0;                               // mean factor over the paths
  double mean_error = 0.0;                         // mean / handbook - 1
  double spread = 0.0;                             // (J_max - J_min) / J_max over the paths
  double max_abs_error() const {
    return std::abs(*std::max_element(error.begin(), error.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }));
  }
  // [radius, factor] per path
  std::vector<std::array<double, 2>> paths() const {
    std::vector<std::array<double, 2>> p;
    for (std::size_t i = 0; i < radii.size(); ++i) p.push_back({radii[i], factor[i]});
    return p;
  }
  // j_paths.csv: a row per path
  static std::vector<std::string> header() { return {"radius_m", "J_N_per_m", "K_Pa_sqrt_m", "K_factor", "handbook_factor_error"}; }
  std::vector<std::vector<double>> columns() const { return {radii, j, k, factor, error}; }
};
template <class Model>
StaticSif static_sif(const Model& model, double handbook) {
  StaticSif s;
  double lo = 1e300, hi = -1e300;
  for (double r : model.config().j_radii) {
    const auto res = model.j_integral(r);
    s.radii.push_back(r);
    s.j.push_back(res.j);
    s.k.push_back(res.k);
    s.factor.push_back(res.factor);
    s.error.push_back(res.factor / handbook - 1);
    lo = std::min(lo, res.j);
    hi = std::max(hi, res.j);
  }
  for (double f : s.factor) s.mean += f;
  s.mean /= static_cast<double>(s.factor.size());
  s.mean_error = s.mean / handbook - 1;
  s.spread = (hi - lo) / hi;
  return s;
}

// The crack's length over the plate's width (edge crack) or half-width (centre crack): the handbook's
// a / w.
inline double a_over_w(const Config& c) {
  return c.crack == CrackKind::edge ? c.crack_length / c.width : c.crack_length / (0.5 * c.width);
}

// One sample of a dynamic run: J' on every path (seed 004 eq. (13)) and the crack opening at the centre.
struct DynamicSample {
  std::vector<double> factor;  // K / (sigma sqrt(pi a0)) per path
  double mean = 0.0;           // over the paths
  double spread = 0.0;         // (J'_max - J'_min) / J'_max
  double opening = 0.0;        // at x = 0
  double energy_balance = 0.0; // kinetic + strain - load work
};
template <class Model>
DynamicSample dynamic_sample(Model& model, int domain_cells) {
  DynamicSample s;
  double lo = 1e300, hi = -1e300, sum = 0.0;
  for (double r : model.config().j_radii) {
    const auto res = model.dynamic_j(r, domain_cells);
    s.factor.push_back(res.factor);
    sum += res.factor;
    lo = std::min(lo, res.j);
    hi = std::max(hi, res.j);
  }
  s.mean = sum / static_cast<double>(s.factor.size());
  s.opening = model.dynamic_opening_at(0.0);
  s.spread = hi > 0 ? (hi - lo) / hi : 0.0;
  s.energy_balance = model.kinetic_energy() + model.strain_energy() - model.load_work();
  return s;
}

// A dynamic run's history, one row per sample: time [us], the mean factor, the crack opening, the energy
// balance, the load's work, the J' spread, then the factor on each path of `radii` ("K_factor_r<r>mm").
// sif_history.csv holds the first four and the paths' (history_csv_columns).
inline std::vector<std::string> history_columns(const std::vector<double>& radii) {
  std::vector<std::string> columns = {"t_us", "K_factor_mean", "crack_opening_m", "energy_balance_J", "load_work", "j_spread"};
  for (double r : radii) {
    char name[64];
    std::snprintf(name, sizeof name, "K_factor_r%.3gmm", r * 1e3);
    columns.push_back(name);
  }
  return columns;
}
inline std::vector<std::string> history_csv_columns(const std::vector<std::string>& columns) {
  std::vector<std::string> csv = {"t_us", "K_factor_mean", "crack_opening_m", "energy_balance_J"};
  csv.insert(csv.end(), columns.begin() + 6, columns.end());
  return csv;
}
inline std::vector<double> history_row(double t_us, const DynamicSample& s, double load_work) {
  std::vector<double> row = {t_us, s.mean, s.opening, s.energy_balance, load_work, s.spread};
  row.insert(row.end(), s.factor.begin(), s.factor.end());
  return row;
}

// The samples of a dynamic run: each one's row of the history (history_row) and the time spent on
// the J-integrals (a timing of the summary; in the run's checkpoints).
template <class Model>
struct DynamicRecord {
  DynamicRecord(Model& model, int domain_cells) : m(model), cells(domain_cells) {}
  // One sample now (dynamic_sample) and its row.
  std::vector<double> sample(DynamicSample& s) {
    const auto t0 = std::chrono::steady_clock::now();
    s = dynamic_sample(m, cells);
    j_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return history_row(m.time() * 1e6, s, m.load_work());
  }
  Model& m;
  int cells = 0;
  double j_seconds = 0.0;
};

// What the summary reads off the history (columns as history_columns): the mean factor and the crack
// opening over time [t_us, value], the factor's peak (its time, its J' spread), and the energy error:
// the largest |energy balance| over the largest |load work| (0 without work).
struct DynamicHistory {
  std::vector<std::array<double, 2>> sif, opening;
  double peak = -1.0, peak_time_us = 0.0, peak_spread = 0.0, energy_error = 0.0;
};
inline DynamicHistory dynamic_history(const std::vector<std::vector<double>>& h) {
  DynamicHistory d;
  double worst_energy = 0.0, max_work = 0.0;
  for (std::size_t i = 0; i < h[0].size(); ++i) {
    const double t_us = h[0][i], f = h[1][i];
    d.sif.push_back({t_us, f});
    d.opening.push_back({t_us, h[2][i]});
    worst_energy = std::max(worst_energy, std::abs(h[3][i]));
    max_work = std::max(max_work, std::abs(h[4][i]));
    if (f > d.peak) {
      d.peak = f;
      d.peak_time_us = t_us;
      d.peak_spread = h[5][i];
    }
  }
  d.energy_error = max_work > 0 ? worst_energy / max_work : 0.0;
  return d;
}

// The displacement (2 per node) and stress (sigma_xx, sigma_yy, sigma_xy per node, Hooke's law of the
// plane state) at the layout's nodes.
struct NodalFields {
  std::vector<double> displacement, stress;
};
template <class Model>
NodalFields nodal_fields(const Model& model) {
  const auto& nodes = model.layout().nodes;
  const auto v = model.fields_at(nodes, "node");
  const auto& cf = model.config();
  const double nu = cf.poisson, mu = cf.young / (2 * (1 + nu));
  double lam = cf.young * nu / ((1 + nu) * (1 - 2 * nu));
  if (!cf.plane_strain) lam = 2 * lam * mu / (lam + 2 * mu);
  NodalFields f;
  for (std::size_t i = 0; i < v.size() / 6; ++i) {
    const double* g = &v[6 * i];
    f.displacement.insert(f.displacement.end(), {g[0], g[1]});
    f.stress.insert(f.stress.end(), {(lam + 2 * mu) * g[2] + lam * g[5], lam * g[2] + (lam + 2 * mu) * g[5], mu * (g[3] + g[4])});
  }
  return f;
}

}  // namespace polymech::efg
