// The pour of tests/dem (a small pile in a box of planes), shared by the settling and at-rest tests.
#pragma once

#include <random>

#include "dem/dem.hpp"
#include "dem/pour.hpp"

inline constexpr double kBox = 0.05;  // the box's side [m]

// 96 spheres (radii 4.5-5 mm, a soft material so the step is large) on a jittered lattice above the
// floor of a 5 cm box of planes, with gravity, friction and damping.
inline polymech::dem::Config pour_into_a_box() {
  namespace pm = polymech;
  namespace dm = polymech::dem;
  dm::Config c;
  c.particle = {1e7, 0.3, 2500};  // a soft material keeps the step large (a test of seconds)
  c.wall = {1e7, 0.3, 2500};
  c.restitution = 0.3;
  c.friction = 0.5;
  c.gravity = {0, 0, -9.81};
  c.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
  const double r = 0.005, box = kBox;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2 * r, 0.2 * r);
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i) {
        dm::SphereInit s;
        s.radius = r * (0.9 + 0.1 * ((i + j + k) % 3) / 2.0);
        s.position = {0.01 + 0.01 * i + jitter(rng), 0.01 + 0.01 * j + jitter(rng), 0.01 + 0.0125 * k};
        c.spheres.push_back(s);
      }
  c.planes = dm::box_planes(box, box);
  c.max_speed = 2.0;
  return c;
}
