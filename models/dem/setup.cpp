#include "dem/setup.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dem/hertz_mindlin.hpp"
#include "dem/impacts.hpp"

namespace polymech::dem {

namespace {
std::string g(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}
}  // namespace

std::string TimeStepLimit::describe() const {
  std::string s = g(limit) + " s (0.2 x the Rayleigh time: " + g(rayleigh) + " s";
  if (hertz > 0) s += "; the Hertz contact time at " + g(approach_speed) + " m/s over 20 steps: " + g(hertz) + " s";
  return s + ")";
}

TimeStepLimit time_step_limit(const Config& config) {
  TimeStepLimit t;
  Config with_members;
  const bool clumped = !config.clumps.empty();
  if (clumped) {
    with_members.spheres = config.spheres;
    const auto members = expand_clumps(config).members;
    with_members.spheres.insert(with_members.spheres.end(), members.begin(), members.end());
  }
  const auto& spheres = clumped ? with_members.spheres : config.spheres;
  const Config& c = config;
  if (spheres.empty()) return t;
  double r_min = spheres[0].radius, v_max = 0.0;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = spheres[0].position[k];
  for (const auto& s : spheres) {
    r_min = std::min(r_min, s.radius);
    double v2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      v2 += s.velocity[k] * s.velocity[k];
      lo[k] = std::min(lo[k], s.position[k]);
      hi[k] = std::max(hi[k], s.position[k]);
    }
    v_max = std::max(v_max, std::sqrt(v2));
  }
  const double& E = c.particle.young;
  const double& nu = c.particle.poisson;
  t.rayleigh = 0.2 * rayleigh_time_step(r_min, c.particle.density, E, nu);
  t.limit = t.rayleigh;
  // the approach speed: two spheres at the largest speed head on, plus a free fall across the spheres' extent
  double g2 = 0.0, extent2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    g2 += c.gravity[k] * c.gravity[k];
    extent2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
  }
  t.approach_speed = c.max_speed > 0 ? c.max_speed : 2.0 * v_max + std::sqrt(2.0 * std::sqrt(g2) * std::sqrt(extent2));
  if (t.approach_speed > 0) {
    const double m = c.particle.density * 4.0 / 3.0 * kPi * r_min * r_min * r_min;
    const double pp = hertz_contact_time(0.5 * m, 0.5 * r_min, effective_modulus(E, nu, E, nu), t.approach_speed);
    const double pw = hertz_contact_time(m, r_min, effective_modulus(E, nu, c.wall.young, c.wall.poisson),
                                         t.approach_speed);
    t.hertz = std::min(pp, pw) / 20.0;
    t.limit = std::min(t.limit, t.hertz);
  }
  return t;
}

}  // namespace polymech::dem

namespace polymech::dem {

double sphere_mass(const Case& k) { return k.particle.density * 4.0 / 3.0 * kPi * std::pow(k.radius, 3); }

Config two_spheres(const Case& k, double steps_per_contact) {
  Config c;
  c.particle = k.particle;
  const double gap = 1e-3 * k.radius;
  SphereInit a, b;
  a.radius = b.radius = k.radius;
  a.position = {-k.radius - gap, 0, 0};
  b.position = {k.radius + gap, 0, 0};
  a.velocity = {k.speed, 0, 0};
  b.velocity = {-k.speed, 0, 0};
  c.spheres = {a, b};
  const double m = sphere_mass(k);
  const double e_star = effective_modulus(k.particle.young, k.particle.poisson, k.particle.young, k.particle.poisson);
  c.dt = hertz_contact_time(0.5 * m, 0.5 * k.radius, e_star, 2 * k.speed) / steps_per_contact;
  return c;
}

Config sphere_on_wall(const Case& k, double steps_per_contact, double angle_deg, bool meshed) {
  Config c;
  c.particle = k.particle;
  c.wall = k.wall;
  const double th = angle_deg * kPi / 180.0;
  SphereInit s;
  s.radius = k.radius;
  s.position = {0, 0, k.radius * 1.0005};
  s.velocity = {k.speed * std::sin(th), 0, -k.speed * std::cos(th)};
  c.spheres = {s};
  if (meshed) {
    const int n = 4;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        c.surface.nodes.push_back((i - n / 2) * k.radius);
        c.surface.nodes.push_back((j - n / 2) * k.radius);
        c.surface.nodes.push_back(0.0);
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::int64_t n0 = j * (n + 1) + i;
        c.surface.facet_sizes.push_back(4);
        c.surface.facet_nodes.push_back(n0);
        c.surface.facet_nodes.push_back(n0 + 1);
        c.surface.facet_nodes.push_back(n0 + n + 2);
        c.surface.facet_nodes.push_back(n0 + n + 1);
      }
  } else {
    PlaneInit p;
    p.normal = {0, 0, 1};
    c.planes = {p};
  }
  const double vn = k.speed * std::cos(th);
  const double e_star = effective_modulus(k.particle.young, k.particle.poisson, k.wall.young, k.wall.poisson);
  c.dt = hertz_contact_time(sphere_mass(k), k.radius, e_star, vn > 0 ? vn : k.speed) / steps_per_contact;
  return c;
}

}  // namespace polymech::dem
