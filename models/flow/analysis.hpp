// What the flow cases measure (issue 36), on the host, for the app, the tests and the sweeps alike: the node
// spacing of a Q2 cell, the Courant number of the flow, and the benchmark's statistics of a periodic run over
// a chosen lift period (models/flow/turek_hron.hpp: last_period, periodic_stats).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "flow/navier_stokes.hpp"
#include "flow/turek_hron.hpp"

namespace polymech::flow {

// The shortest edge of cell e (its four corner nodes; the node spacing of the Q2 cell is half of it).
inline double shortest_cell_edge(const QuadMesh& m, std::int64_t e) {
  const int corners[4] = {0, 2, 8, 6};
  double h = 1e300;
  for (int k = 0; k < 4; ++k) {
    const auto a = static_cast<std::size_t>(m.elements[static_cast<std::size_t>(9 * e + corners[k])]);
    const auto b = static_cast<std::size_t>(m.elements[static_cast<std::size_t>(9 * e + corners[(k + 1) % 4])]);
    h = std::min(h, std::hypot(m.x[2 * a] - m.x[2 * b], m.x[2 * a + 1] - m.x[2 * b + 1]));
  }
  return h;
}

// The shortest cell edge of the mesh.
inline double shortest_cell_edge(const QuadMesh& m) {
  double h = 1e300;
  for (std::int64_t e = 0; e < m.element_count(); ++e) h = std::min(h, shortest_cell_edge(m, e));
  return h;
}

// The Courant number of the flow now: max over the cells of |u| at the cell's centre node x dt / the node
// spacing (half the cell's shortest edge).
inline double flow_cfl(const NavierStokes2D& ns, double dt) {
  const auto& m = ns.mesh();
  const auto& u = ns.state();
  double c = 0.0;
  for (std::int64_t e = 0; e < m.element_count(); ++e) {
    const double h = shortest_cell_edge(m, e);
    const auto n = static_cast<std::size_t>(m.elements[static_cast<std::size_t>(9 * e + 4)]);
    c = std::max(c, std::hypot(u[2 * n], u[2 * n + 1]) * dt / (0.5 * h));
  }
  return c;
}

// The stats of the lift period that ends at the k-th last maximum (back = 0: the last period); false when
// there are not enough maxima.
inline bool period_stats(const std::vector<double>& t, const std::vector<double>& drag, const std::vector<double>& lift, int back,
                         PeriodicStats& d, PeriodicStats& l) {
  std::size_t n = t.size();
  for (int b = 0; b < back; ++b) {
    double t0, t1;
    if (!last_period(std::vector<double>(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n)),
                     std::vector<double>(lift.begin(), lift.begin() + static_cast<std::ptrdiff_t>(n)), t0, t1))
      return false;
    while (n > 0 && t[n - 1] > t1) --n;  // drop the last period: it ends at the sample at or before t1
  }
  const std::vector<double> tt(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(n));
  const std::vector<double> ll(lift.begin(), lift.begin() + static_cast<std::ptrdiff_t>(n));
  const std::vector<double> dd(drag.begin(), drag.begin() + static_cast<std::ptrdiff_t>(n));
  double t0, t1;
  if (!last_period(tt, ll, t0, t1)) return false;
  d = periodic_stats(tt, dd, t0, t1);
  l = periodic_stats(tt, ll, t0, t1);
  return true;
}

}  // namespace polymech::flow
