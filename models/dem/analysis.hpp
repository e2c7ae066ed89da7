// What the DEM pour and wheel cases measure (seed 002 paper 2, Figs. 6-10; docs/VALIDATION.md), used
// alike by apps/dem_pour, the tests and the sweeps. The packing fraction, the bed's box and the heap's
// angle of repose are in pour.hpp (Kokkos-free, compiled once); here, what is read off the model's
// spheres: their rows, the snapshots' fields, the bed's box and packing fraction, the wheel's means and
// the track's profile.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
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

// What the snapshots of a pour show beside the motion: every sphere's position (at the start: the mesh),
// radius, and the clump it belongs to (-1: a free sphere; the members follow the free spheres, clump
// after clump).
struct SphereLayout {
  std::vector<double> points, radius, clump;
};
template <class T>
SphereLayout sphere_layout(const Dem<T>& m, const Config& c) {
  SphereLayout l;
  l.clump.assign(static_cast<std::size_t>(m.sphere_count()), -1.0);
  for (const auto& row : sphere_rows(m)) {
    l.points.insert(l.points.end(), row.begin(), row.begin() + 3);
    l.radius.push_back(row[3]);
  }
  for (std::size_t i = c.spheres.size(), b = 0, k = 0; i < l.clump.size(); ++i) {
    l.clump[i] = double(b);
    if (++k == c.clump_shapes[static_cast<std::size_t>(c.clumps[b].shape)].spheres.size()) {
      k = 0;
      ++b;
    }
  }
  return l;
}

// Every sphere's displacement from the start and velocity (3 per sphere), copied to the host.
struct SphereMotion {
  std::vector<double> u, v;
};
template <class T>
SphereMotion sphere_motion(const Dem<T>& m) {
  const auto& s = m.spheres();
  auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), s.u);
  auto v = Kokkos::create_mirror_view_and_copy(HostSpace(), s.v);
  return {std::vector<double>(u.data(), u.data() + u.size()), std::vector<double>(v.data(), v.data() + v.size())};
}

// The settled bed (bed_box, packing_fraction of pour.hpp): its measuring box and the packing fraction on
// an 80^3 grid; no bed (NaN) when the box is empty: a bed thinner than 2 radius_max.
struct Bed {
  std::array<double, 3> lo{}, hi{};
  bool measured = false;
  double packing_fraction = 0.0;
};
inline Bed settled_bed(const std::vector<std::array<double, 4>>& rows, const PourSpec& p) {
  Bed b;
  bed_box(rows, p, b.lo, b.hi);
  b.measured = b.hi[2] > b.lo[2];
  b.packing_fraction = b.measured ? packing_fraction(rows, b.lo, b.hi, 80) : NAN;
  return b;
}

// The columns of a wheel's history (wheel.csv; Figs. 8-10).
inline const std::vector<std::string>& wheel_columns() {
  static const std::vector<std::string> c = {"time", "time_from_start", "x", "z", "sinkage_mm", "vertical_force", "tractive_force",
                                             "driving_torque", "load", "speed", "tread_sinkage_mm"};
  return c;
}
// sinkage_mm: the rim's (the bed's level less its centre's height less R: for a tyre, its deflection included);
// tread_sinkage_mm: the tread's lowest point below the bed's level (the rut under it; a rigid wheel: the same).
inline std::vector<double> wheel_row(double time, const WheelState& w) {
  return {time, w.time, w.centre[0], w.centre[2], 1e3 * w.sinkage, w.vertical_force, w.tractive_force, w.driving_torque, w.load,
          w.speed, 1e3 * (w.bed_level - w.tread_low)};
}

// Means of the wheel's histories (columns as wheel_columns()) over its steady stage: the last half of the
// time after the speed ramp (the whole drive's last quarter when that is shorter than a quarter of it).
struct WheelMeans {
  double from = 0.0, sinkage = 0.0, vertical = 0.0, tractive = 0.0, torque = 0.0, tread_sinkage = 0.0;
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
    m.tread_sinkage += w[10][k];
    ++m.samples;
  }
  if (m.samples > 0) {
    m.sinkage /= m.samples;
    m.vertical /= m.samples;
    m.tractive /= m.samples;
    m.torque /= m.samples;
    m.tread_sinkage /= m.samples;
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
// ... over the x range the wheel `w` (configuration `wc`) has run over (at least 2 radius_max).
inline std::vector<std::vector<double>> track_profile(const std::vector<std::array<double, 4>>& rows, const PourSpec& p,
                                                      const WheelSpec& wc, const WheelState& w) {
  return track_profile(rows, p, wc.x_start, std::max(wc.x_start + 2 * p.radius_max, w.centre[0]));
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

// The pour's history (energy.csv): time, kinetic energy, the bed's mean and top height.
inline const std::vector<std::string>& pour_columns() {
  static const std::vector<std::string> c = {"time", "kinetic_energy", "mean_height", "top_height"};
  return c;
}
template <class T>
std::vector<double> pour_row(const Dem<T>& m) {
  const auto s = pour_sample(sphere_rows(m));
  return {m.time(), m.kinetic_energy(), s.mean_height, s.top_height};
}

// A released heap (PourSpec::release_at): its angle of repose (repose_angle, pour.hpp; NaN: no slope)
// and its surface profile, columns x, surface height.
struct Heap {
  double angle = 0.0;
  std::vector<std::vector<double>> profile;
};
inline Heap heap(const std::vector<std::array<double, 4>>& rows, const PourSpec& p) {
  std::vector<std::array<double, 2>> profile;
  Heap h;
  h.angle = repose_angle(rows, p, &profile);
  h.profile.resize(2);
  for (const auto& r : profile) {
    h.profile[0].push_back(r[0]);
    h.profile[1].push_back(r[1]);
  }
  return h;
}

}  // namespace polymech::dem
