// The stable time step of a NosbPd configuration (included at the end of nosb_pd.hpp).
//
// Largest stable step of velocity Verlet for this discretisation, from a patch of the same layout,
// spacing, horizon, material, weights and hourglass force: 2 / omega with omega^2 the patch's largest
// eigenvalue (models/common/stability.hpp) plus the projectile penalty k / m and the short-range
// springs, and the velocity viscosity's rate limit dt <= 1 / (4 c_v omega_v). Needs no model of the
// full size.
//
// The velocity viscosity (seed 003 eq. (3)) is a damping operator on the half-step velocities,
// which velocity Verlet advances like forward Euler: stable while dt lambda <= 2 for its largest
// rate lambda. For a velocity pattern with neighbour mean vbar = w v, eq. (3) gives
// L^ZE = sum_j W (t_i - t_j) = -2 c_v omega_v rho (1 - w)^2 v, so lambda = 2 c_v omega_v (1 - w)^2,
// largest (8 c_v omega_v) for w = -1: two particles whose only intact bond joins them (fragments,
// a damaged rim). Intact lattices reach w ~ -0.3 only, which is why 1 / (2 c_v omega_v) sufficed
// until bonds broke.
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

template <class T, int D>
double NosbPd<T, D>::stable_time_step(const Config& c) {
  Config patch = c;
  std::vector<std::string> pe;
  if (c.effects.has("weighted_function")) pe.push_back("weighted_function");
  if (c.effects.has("hourglass")) pe.push_back("hourglass");
  patch.effects = EffectSet::resolve(pe, effect_table());
  const double side = (2.0 * std::ceil(c.horizon_ratio) + 2.0) * c.spacing;  // the fastest modes are local
  const Geometry& g = c.geometry;
  const bool thin = g.shape == Shape::box ? std::min({g.length, g.height, D == 3 ? g.width : g.length}) < side
                    : g.shape == Shape::disc ? std::min(2.0 * g.radius, g.thickness) < side
                                             : 2.0 * g.radius < side;
  if (thin) {
    // A body thinner than the patch: every family is cut by its surfaces, and cut families (a smaller shape
    // tensor K) are stiffer than whole ones; a box patch of whole families gave a step that diverged in 50
    // steps (issue 33 item 11: a round bar 2.5 spacings in radius, horizon 7 spacings). The patch is then
    // the body itself, cut to the patch's length where it is longer.
    patch.geometry.length = std::min(g.length, side);
    patch.geometry.width = std::min(g.width, side);
    patch.geometry.height = std::min(g.height, side);
    patch.geometry.radius = g.shape == Shape::round_bar ? g.radius : std::min(g.radius, 0.5 * side);
    patch.geometry.thickness = g.thickness;
  } else {
    patch.geometry.shape = Shape::box;
    if (patch.geometry.layout == Layout::cylindrical) patch.geometry.layout = Layout::jittered;
    patch.geometry.length = patch.geometry.width = patch.geometry.height = side;
  }
  patch.loading = Loading::none;
  patch.material.law = Law::elastic;
  patch.dt = 1.0;  // not used
  NosbPd<double, D> m(patch);
  double omega2 = m.max_eigenvalue();
  const double V = std::pow(c.spacing, D);
  if (c.effects.has("contact"))  // a quarter of a lattice cell: the smallest particle of the layouts
    omega2 += c.contact.penalty * c.material.youngs_modulus * c.spacing / (c.material.density * 0.25 * V);
  if (c.effects.has("short_range"))  // up to 12 touching neighbours, each a spring c_s V / d_s
    omega2 += 12.0 * c.contact.short_range_factor * m.micromodulus() * V /
              (c.contact.short_range_distance * c.spacing * c.material.density);
  double dt = models::leapfrog_stable_step(omega2);
  if (c.effects.has("velocity_viscosity") && c.stabilization.omega_v > 0 && c.stabilization.c_v > 0)
    dt = std::min(dt, 1.0 / (4.0 * c.stabilization.c_v * c.stabilization.omega_v));
  return dt;
}

}  // namespace polymech::nosb_pd
