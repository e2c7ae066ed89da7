#include "isph/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polymech::isph {

namespace {
long long cells(double length, double l0) { return static_cast<long long>(std::llround(length / l0)); }
std::string g(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}
}  // namespace

Counts count(const Config& c) {
  Counts n;
  const double l0 = c.spacing;
  const long long layers = static_cast<long long>(std::ceil(c.radius_factor - 1e-9));
  n.fluid = cells(c.fluid[0], l0) * cells(c.fluid[1], l0) * (c.dim == 3 ? cells(c.fluid[2], l0) : 1);
  const long long nx = cells(c.tank[0], l0), ny = cells(c.tank[1], l0), nz = c.dim == 3 ? cells(c.tank[2], l0) : 1;
  if (c.dim == 2)
    n.wall_points = (nx + 2 * layers) * (ny + layers) - nx * ny;
  else
    n.wall_points = (nx + 2 * layers) * (ny + layers) * (nz + 2 * layers) - nx * ny * nz;
  return n;
}

std::string TimeStepLimit::describe() const {
  return g(limit) + " s (CFL 0.4 at the surge speed 2 sqrt(g H): " + g(cfl) + " s; viscous 0.125 l0^2/nu: " + g(viscous) +
         " s)";
}

TimeStepLimit time_step_limit(const Config& c) {
  TimeStepLimit t;
  const double speed = 2.0 * std::sqrt(c.gravity * std::max(c.fluid[1], c.spacing));
  t.cfl = 0.4 * c.spacing / speed;
  t.viscous = c.viscosity > 0 ? 0.125 * c.spacing * c.spacing / c.viscosity : 1e300;
  t.limit = std::min(t.cfl, t.viscous);
  return t;
}

std::string check(const Config& c) {
  if (c.dim != 2 && c.dim != 3) return "dim must be 2 or 3";
  if (c.effects.has("rigid_body"))
    return "the effect 'rigid_body' (floating body, eqs. (31)-(43)) is not implemented yet (issue 12 stage 2)";
  for (int k = 0; k < c.dim; ++k) {
    if (c.fluid[k] > c.tank[k] * (1 + 1e-9)) return "the water block is larger than the tank";
    if (cells(c.fluid[k], c.spacing) < 1 || cells(c.tank[k], c.spacing) < 1) return "the spacing is larger than the tank";
  }
  return "";
}

}  // namespace polymech::isph
