// Small wheel and tyre cases on one layer of spheres (the tests of tests/dem/test_dem_wheel.cpp and the tyre
// benchmark of bench/bench_dem.cpp): a box of planes just wide enough for nx x ny spheres of radius r on its
// floor, the gravel's contact law, and the wheel's effects.
#pragma once

#include "dem/dem.hpp"
#include "dem/pour.hpp"

namespace polymech::dem::cases {

// nx x ny spheres of radius r in one layer on the floor of a box, gravel's contact law, the wheel's effect
// ("rigid_wheel" or "fe_tyre").
inline Config layer(double r, int nx, int ny, const char* wheel_effect) {
  Config c;
  c.particle = {5e7, 0.3, 2650};
  c.wall = {5e7, 0.3, 2650};
  c.restitution = 0.4;
  c.friction = 0.5;
  c.gravity = {0, 0, -9.81};
  c.effects = EffectSet::resolve({"friction", "damping", "fe_surfaces", wheel_effect}, effect_table());
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      SphereInit s;
      s.radius = r;
      s.position = {r + 2 * r * i, r + 2 * r * j, r};
      c.spheres.push_back(s);
    }
  c.planes = box_planes(2 * r * nx, 2 * r * ny);
  return c;
}

// The deformable tyre (effect fe_tyre, issue 37): the paper's tyre 37x12.5R16.5 on a coarse lattice (16 x 6 x 1
// order-1 cells: 672 DoFs) on one layer of 20 mm spheres (15 x 10) on the floor of a box, set down at once,
// inflated to 0.35 MPa over 5 ms, loaded with the paper's 10 163 N from 5 ms to `load_to`, driven at `speed`
// (over load_to .. load_to + 3 ms, 20 % slip); a light rim (10 kg).
inline Config tyre_on_a_layer(double speed, double load_to) {
  Config c = layer(0.02, 15, 10, "fe_tyre");
  auto& w = c.wheel;
  w.radius = 0.445;
  w.width = 0.31;
  w.mass = 10.0;
  w.load = 10163.0;
  w.load_from = 0.005;
  w.load_to = load_to;
  w.speed = speed;
  w.speed_from = load_to;
  w.speed_to = load_to + 0.003;
  w.slip = 0.2;
  w.start = 0.0;
  w.x_start = 0.2;
  w.y_centre = 0.2;
  w.parked = {0.2, 0.2, 2.0};
  c.tyre.around = 16;
  c.tyre.across = 6;
  c.tyre.through = 1;
  c.tyre.order = 1;
  c.tyre.inflate_to = 0.005;
  c.max_speed = 1.0;
  return c;
}

}  // namespace polymech::dem::cases
