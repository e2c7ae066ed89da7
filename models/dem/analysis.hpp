// What the DEM pour and wheel cases measure (seed 002 paper 2, Figs. 6-10; docs/VALIDATION.md), used
// alike by apps/dem_pour, the tests and the sweeps. The packing fraction, the bed's box and the heap's
// angle of repose are in pour.hpp (Kokkos-free, compiled once).
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "dem/dem.hpp"
#include "dem/pour.hpp"

namespace polymech::dem {

// Every sphere's centre and radius (x, y, z, r), copied to the host.
template <class T>
std::vector<std::array<double, 4>> sphere_rows(const Dem<T>& m) {
  const auto& s = m.spheres();
  auto x0 = Kokkos::create_mirror_view_and_copy(HostSpace(), s.x0);
  auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), s.u);
  auto r = Kokkos::create_mirror_view_and_copy(HostSpace(), s.radius);
  std::vector<std::array<double, 4>> rows(static_cast<std::size_t>(s.size()));
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i] = {double(x0(i, 0) + u(i, 0)), double(x0(i, 1) + u(i, 1)), double(x0(i, 2) + u(i, 2)), double(r(i))};
  return rows;
}

// The columns of a wheel's history (wheel.csv; Figs. 8-10).
inline const std::vector<std::string>& wheel_columns() {
  static const std::vector<std::string> c = {"time", "time_from_start", "x", "z", "sinkage_mm", "vertical_force", "tractive_force",
                                             "driving_torque", "load", "speed"};
  return c;
}
inline std::vector<double> wheel_row(double time, const WheelState& w) {
  return {time, w.time, w.centre[0], w.centre[2], 1e3 * w.sinkage, w.vertical_force, w.tractive_force, w.driving_torque, w.load, w.speed};
}

// Means of the wheel's histories (columns as wheel_columns()) over its steady stage: the last half of the
// time after the speed ramp (the whole drive's last quarter when that is shorter than a quarter of it).
struct WheelMeans {
  double from = 0.0, sinkage = 0.0, vertical = 0.0, tractive = 0.0, torque = 0.0;
  int samples = 0;
};
inline WheelMeans steady_means(const std::vector<std::vector<double>>& w, double speed_to) {
  WheelMeans m;
  if (w[0].empty()) return m;
  const double end = w[1].back();
  m.from = std::max(speed_to + 0.5 * (end - speed_to), 0.75 * end);
  for (std::size_t k = 0; k < w[0].size(); ++k) {
    if (w[1][k] < m.from) continue;
    m.sinkage += w[4][k];
    m.vertical += w[5][k];
    m.tractive += w[6][k];
    m.torque += w[7][k];
    ++m.samples;
  }
  if (m.samples > 0) {
    m.sinkage /= m.samples;
    m.vertical /= m.samples;
    m.tractive /= m.samples;
    m.torque /= m.samples;
  }
  return m;
}

// The bed's surface across the track (Fig. 7): the highest sphere top in columns of 2 r_max in y over
// the x range [x0, x1) the wheel has run over, averaged over x. Columns: y, surface height.
inline std::vector<std::vector<double>> track_profile(const std::vector<std::array<double, 4>>& rows, const PourSpec& p, double x0,
                                                      double x1) {
  const double cell = 2 * p.radius_max;
  const int ny = std::max(1, static_cast<int>(p.bin[1] / cell)), nx = std::max(1, static_cast<int>((x1 - x0) / cell));
  std::vector<double> top(static_cast<std::size_t>(nx * ny), 0.0);
  for (const auto& r : rows) {
    if (r[0] < x0 || r[0] >= x0 + nx * cell || r[1] < 0 || r[1] >= ny * cell) continue;
    const auto k = static_cast<std::size_t>(static_cast<int>((r[0] - x0) / cell) * ny + static_cast<int>(r[1] / cell));
    top[k] = std::max(top[k], r[2] + r[3]);
  }
  std::vector<std::vector<double>> cols(2);
  for (int j = 0; j < ny; ++j) {
    double h = 0;
    for (int i = 0; i < nx; ++i) h += top[static_cast<std::size_t>(i * ny + j)];
    cols[0].push_back((j + 0.5) * cell);
    cols[1].push_back(h / nx);
  }
  return cols;
}

// The bed's mean and top height (the sphere tops) and its kinetic energy: a sample of the pour.
struct PourSample {
  double mean_height = 0.0, top_height = 0.0;
};
inline PourSample pour_sample(const std::vector<std::array<double, 4>>& rows) {
  PourSample s;
  for (const auto& r : rows) {
    s.mean_height += r[2];
    s.top_height = std::max(s.top_height, r[2] + r[3]);
  }
  s.mean_height /= double(rows.size());
  return s;
}

}  // namespace polymech::dem
