#include "isph/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "contact/damping.hpp"

namespace polymech::isph {

namespace {
long long cells(double length, double l0) { return static_cast<long long>(std::llround(length / l0)); }
std::string g(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}
}  // namespace

static bool has_body(const Config& c) { return c.effects.has("rigid_body") && c.body.diameter > 0 && c.dim == 2; }

std::vector<double> fluid_positions(const Config& c) {
  const double l0 = c.spacing;
  const long long n[3] = {cells(c.fluid[0], l0), cells(c.fluid[1], l0), c.dim == 3 ? cells(c.fluid[2], l0) : 1};
  const bool body = has_body(c);
  const double R = 0.5 * c.body.diameter;
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n[0] * n[1] * n[2] * c.dim));
  const int rings = body ? c.body.fluid_rings : 0;
  const double cut = R + (rings + c.body.fluid_clearance) * l0;  // the lattice starts there (Body::fluid_rings)
  for (long long k = 0; k < n[2]; ++k)
    for (long long j = 0; j < n[1]; ++j)
      for (long long i = 0; i < n[0]; ++i) {
        const double x = (i + 0.5) * l0, y = (j + 0.5) * l0;
        if (body && std::hypot(x - c.body.centre[0], y - c.body.centre[1]) < cut) continue;
        out.push_back(x);
        out.push_back(y);
        if (c.dim == 3) out.push_back((k + 0.5) * l0);
      }
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < rings; ++k) {  // concentric with the body's cells (body_cells), outwards
    const double r = R + (k + 0.5) * l0;
    const long long m = std::llround(2 * pi * r / l0);
    for (long long q = 0; q < m; ++q) {
      const double th = (q + 0.5) * 2 * pi / double(m);
      const double x = c.body.centre[0] + r * std::cos(th), y = c.body.centre[1] + r * std::sin(th);
      // inside the water block, a quarter spacing off its sides and its surface, as the lattice is half a spacing
      if (x < 0.25 * l0 || x > (n[0] - 0.25) * l0 || y < 0.25 * l0 || y > (n[1] - 0.25) * l0) continue;
      out.push_back(x);
      out.push_back(y);
    }
  }
  return out;
}

BodyCells body_cells(const Config& c) {
  BodyCells b;
  if (!has_body(c)) return b;
  const double pi = 3.14159265358979323846;
  const double R = 0.5 * c.body.diameter;
  const long long rings = std::max<long long>(1, cells(R, c.spacing));
  const double dr = R / double(rings);
  for (long long k = 0; k < rings; ++k) {
    const double r = R - (k + 0.5) * dr;
    const long long m = std::max<long long>(3, std::llround(2 * pi * r / c.spacing));
    const double dth = 2 * pi / double(m);
    for (long long q = 0; q < m; ++q) {
      const double th = (q + 0.5) * dth;
      b.offset.push_back(r * std::cos(th));
      b.offset.push_back(r * std::sin(th));
      b.weight.push_back(r * dr * dth);
    }
  }
  return b;
}

MassProperties mass_properties(const Config& c, const BodyCells& b) {
  MassProperties p;
  const std::size_t n = b.weight.size();
  for (std::size_t k = 0; k < n; ++k) {  // eqs. (33), (34)
    p.area += b.weight[k];
    p.centroid[0] += b.offset[2 * k] * b.weight[k];
    p.centroid[1] += b.offset[2 * k + 1] * b.weight[k];
  }
  if (p.area <= 0) return p;
  p.centroid[0] /= p.area;
  p.centroid[1] /= p.area;
  const double rho_r = c.body.density_ratio * c.density;
  for (std::size_t k = 0; k < n; ++k) {  // eq. (35)
    const double dx = b.offset[2 * k] - p.centroid[0], dy = b.offset[2 * k + 1] - p.centroid[1];
    p.inertia += rho_r * (dx * dx + dy * dy) * b.weight[k];
  }
  p.mass = rho_r * p.area;
  return p;
}

double segment_area(double R, double h) {
  h = std::min(std::max(h, 0.0), 2 * R);
  return R * R * std::acos((R - h) / R) - (R - h) * std::sqrt(std::max(0.0, 2 * R * h - h * h));
}

double archimedes_draft_over_diameter(double s) {
  // the draft h of a unit-radius disc whose submerged segment has the area s pi (segment_area rises with h)
  const double pi = 3.14159265358979323846;
  double lo = 0.0, hi = 2.0;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (segment_area(1.0, mid) < s * pi ? lo : hi) = mid;
  }
  return 0.25 * (lo + hi);
}

Counts count(const Config& c) {
  Counts n;
  const double l0 = c.spacing;
  const long long layers = static_cast<long long>(std::ceil(c.radius_factor - 1e-9));
  n.fluid = has_body(c) ? static_cast<long long>(fluid_positions(c).size()) / c.dim
                        : cells(c.fluid[0], l0) * cells(c.fluid[1], l0) * (c.dim == 3 ? cells(c.fluid[2], l0) : 1);
  const long long nx = cells(c.tank[0], l0), ny = cells(c.tank[1], l0), nz = c.dim == 3 ? cells(c.tank[2], l0) : 1;
  if (c.dim == 2)
    n.wall_points = (nx + 2 * layers) * (ny + layers) - nx * ny;
  else
    n.wall_points = (nx + 2 * layers) * (ny + layers) * (nz + 2 * layers) - nx * ny * nz;
  n.wall_points += static_cast<long long>(body_cells(c).weight.size());
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

BodyContact body_contact(const Config& c) {
  BodyContact b;
  const double R = 0.5 * c.body.diameter, pi = 3.14159265358979323846;
  b.mass = c.body.density_ratio * c.density * pi * R * R;
  b.reference_speed = std::sqrt(2.0 * c.gravity * c.tank[1]);
  if (!(R > 0) || !(b.reference_speed > 0)) return b;
  // Hertz impact time t = 2.87 (m^2 / (R E*^2 v))^(1/5) (contact::hertz_contact_time), solved for E*
  const double target = 20.0 * c.dt;
  b.e_star = c.body.contact_modulus > 0
                 ? c.body.contact_modulus
                 : std::sqrt(b.mass * b.mass / (R * b.reference_speed * std::pow(target / 2.87, 5.0)));
  b.contact_time = 2.87 * std::pow(b.mass * b.mass / (R * b.e_star * b.e_star * b.reference_speed), 0.2);
  b.beta = contact::hertz_damping_ratio(c.body.restitution);
  b.mu = c.body.friction;
  return b;
}

std::string check(const Config& c) {
  if (c.dim != 2 && c.dim != 3) return "dim must be 2 or 3";
  if (c.ppe_preconditioner == Config::Preconditioner::two_level && !c.ppe_stored)
    return "the two-level PPE preconditioner needs the stored operator (fluid.ppe_operator = \"stored\")";
  if (c.effects.has("rigid_body")) {
    if (c.dim != 2) return "the effect 'rigid_body' (eqs. (31)-(43)) is 2D only";
    if (!(c.body.diameter > 2 * c.spacing)) return "the body's diameter must be more than 2 particle spacings";
    const double R = 0.5 * c.body.diameter;
    if (c.body.centre[0] - R < 0 || c.body.centre[0] + R > c.tank[0] || c.body.centre[1] - R < 0 ||
        c.body.centre[1] + R > c.tank[1])
      return "the body is not inside the tank";
    const BodyContact bc = body_contact(c);
    if (bc.contact_time < 10.0 * c.dt)
      return "the body's contact with the tank lasts " + g(bc.contact_time) + " s at " + g(bc.reference_speed) +
             " m/s, fewer than 10 steps: lower body.contact_modulus or dt";
  }
  for (int k = 0; k < c.dim; ++k) {
    if (c.fluid[k] > c.tank[k] * (1 + 1e-9)) return "the water block is larger than the tank";
    if (cells(c.fluid[k], c.spacing) < 1 || cells(c.tank[k], c.spacing) < 1) return "the spacing is larger than the tank";
  }
  return "";
}

}  // namespace polymech::isph
