// One binary collision run and measured: the Chung & Ooi (2011) benchmark impacts (two spheres head on,
// a sphere on a plane or on a meshed wall, oblique impacts). Shared by tests/dem and apps/dem_benchmark.
//
// The measures: the largest contact force (|m (a - g)| of the first sphere after each step), the
// largest overlap, the contact time (overlap > 0, its start and end interpolated linearly between
// steps), the velocities and spins after the contact, and the rebound angle of the contact point; and
// what the benchmark compares them with (Hertz theory) or tabulates (the rebound angles of test 4).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/dem.hpp"
#include "dem/impacts.hpp"

namespace polymech::dem {

struct ImpactMeasure {
  double max_force = 0, max_overlap = 0, contact_time = 0;
  double v_before[3] = {0, 0, 0}, v_after[3] = {0, 0, 0}, omega_after[3] = {0, 0, 0};
  std::int64_t steps = 0;
  double normal_restitution = 0;  // -v_n after / v_n before (sphere 0; along z for a plane, x for two spheres)
};

// Overlap of the collision: sphere 0 against sphere 1 (when there are two) or against the plane or
// surface at z = wall_z (normal +z).
template <class T>
double impact_overlap(const Dem<T>& m, double wall_z) {
  const auto a = m.sphere(0);
  const double r0 = m.config().spheres[0].radius;
  if (m.config().spheres.size() >= 2) {
    const auto b = m.sphere(1);
    const double d = std::sqrt((a.x[0] - b.x[0]) * (a.x[0] - b.x[0]) + (a.x[1] - b.x[1]) * (a.x[1] - b.x[1]) +
                               (a.x[2] - b.x[2]) * (a.x[2] - b.x[2]));
    return r0 + m.config().spheres[1].radius - d;
  }
  return r0 - (a.x[2] - wall_z);
}

// Runs until the contact has ended (or max_steps) and measures it; T is the kernels' precision.
template <class T = double>
ImpactMeasure run_impact(const Config& c, double wall_z = 0.0, std::int64_t max_steps = 2000000) {
  Dem<T> m(c);
  ImpactMeasure out;
  for (int k = 0; k < 3; ++k) out.v_before[k] = c.spheres[0].velocity[k];
  m.prepare();
  double prev = impact_overlap(m, wall_z), t_start = -1, t_end = -1;
  while (m.step_index() < max_steps) {
    m.step();
    const double ov = impact_overlap(m, wall_z);
    const double t = m.time();
    if (ov > 0 && prev <= 0 && t_start < 0) t_start = t - m.dt() * ov / (ov - prev);
    if (ov > 0) {
      out.max_overlap = std::max(out.max_overlap, ov);
      out.max_force = std::max(out.max_force, m.contact_force(0));
    }
    if (ov <= 0 && prev > 0 && t_start >= 0) {
      t_end = t - m.dt() * (-ov) / (prev - ov);
      break;
    }
    prev = ov;
  }
  out.steps = m.step_index();
  out.contact_time = t_end > 0 ? t_end - t_start : 0.0;
  const auto s = m.sphere(0);
  for (int k = 0; k < 3; ++k) {
    out.v_after[k] = s.v[k];
    out.omega_after[k] = s.omega[k];
  }
  const int axis = c.spheres.size() >= 2 ? 0 : 2;
  out.normal_restitution = -out.v_after[axis] / out.v_before[axis];
  return out;
}

// Hertz theory of a Chung & Ooi impact (tests 1-2): two identical spheres head on, each at k.speed
// (m* = m / 2, R* = r / 2, E* of the two spheres, approach speed 2 v), or a sphere onto a wall (m, r,
// E* of the sphere and the wall, v); the largest force, the largest overlap and the contact time.
struct HertzImpact {
  double m_star = 0, r_star = 0, e_star = 0, speed = 0;
  double max_force = 0, max_overlap = 0, contact_time = 0;
};
inline HertzImpact hertz_impact(const Case& k, bool two_spheres) {
  HertzImpact h;
  const double m = sphere_mass(k);
  if (two_spheres) {
    h.m_star = 0.5 * m;
    h.r_star = 0.5 * k.radius;
    h.e_star = effective_modulus(k.particle.young, k.particle.poisson, k.particle.young, k.particle.poisson);
    h.speed = 2 * k.speed;
  } else {
    h.m_star = m;
    h.r_star = k.radius;
    h.e_star = effective_modulus(k.particle.young, k.particle.poisson, k.wall.young, k.wall.poisson);
    h.speed = k.speed;
  }
  h.max_force = hertz_max_force(h.m_star, h.r_star, h.e_star, h.speed);
  h.max_overlap = hertz_max_overlap(h.m_star, h.r_star, h.e_star, h.speed);
  h.contact_time = hertz_contact_time(h.m_star, h.r_star, h.e_star, h.speed);
  return h;
}

// A measured impact against Hertz theory: the relative errors measured / Hertz - 1.
struct HertzErrors {
  double max_force = 0, max_overlap = 0, contact_time = 0;
};
inline HertzErrors hertz_errors(const ImpactMeasure& got, const HertzImpact& h) {
  return {got.max_force / h.max_force - 1, got.max_overlap / h.max_overlap - 1, got.contact_time / h.contact_time - 1};
}

// Rebound angle (degrees) of the contact point of a sphere leaving a plane z = const: atan of its
// tangential (x) over its normal (z) velocity, v_c = v + omega x (-r e_z).
inline double rebound_angle_deg(const ImpactMeasure& m, double radius) {
  const double vcx = m.v_after[0] - radius * m.omega_after[1];
  return std::atan2(vcx, m.v_after[2]) * 180.0 / kPi;
}

// Rebound angle (degrees) of the centre of mass from the normal: atan of its tangential (x) over its
// normal (z) velocity after the impact (what Kharaz et al. 2001 measured, their Fig. of the rebound angle).
inline double centre_rebound_angle_deg(const ImpactMeasure& m) {
  return std::atan2(m.v_after[0], m.v_after[2]) * 180.0 / kPi;
}

// Oblique impacts (test 4), one row per incidence angle: both rebound angles, the velocity (x, z) and
// the spin (y) after the impact; the columns of test4.csv.
struct ReboundTable {
  std::vector<double> incidence, contact_point, centre, vx, vz, spin;
  void add(double incidence_deg, const ImpactMeasure& got, double radius) {
    incidence.push_back(incidence_deg);
    contact_point.push_back(rebound_angle_deg(got, radius));
    centre.push_back(centre_rebound_angle_deg(got));
    vx.push_back(got.v_after[0]);
    vz.push_back(got.v_after[2]);
    spin.push_back(got.omega_after[1]);
  }
  static std::vector<std::string> header() {
    return {"incidence_deg", "rebound_contact_point_deg", "rebound_centre_deg", "vx_after", "vz_after", "spin_y_after"};
  }
  std::vector<std::vector<double>> columns() const { return {incidence, contact_point, centre, vx, vz, spin}; }
};

}  // namespace polymech::dem
