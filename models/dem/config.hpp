// The configuration of a DEM model (plain data, free of Kokkos): what io/ fills from a scene and tests
// fill directly. Units SI.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dem/clump_shapes.hpp"
#include "dem/wheel.hpp"
#include "effects.hpp"

namespace polymech::dem {

struct Material {
  double young = 0.0;    // E (Pa); for a wall, 0 stands for rigid
  double poisson = 0.0;  // nu
  double density = 0.0;  // rho (kg/m^3); unused for a wall
};

struct SphereInit {
  std::array<double, 3> position{}, velocity{}, omega{};
  double radius = 0.0;
};

struct PlaneInit {
  std::array<double, 3> point{}, normal{};  // normal: towards the spheres' side (need not be unit)
};

// A surface of quadrilaterals (and triangles): nodes n x 3, facet sizes (3 or 4) and their node indices.
struct SurfaceInit {
  std::vector<double> nodes;
  std::vector<int> facet_sizes;
  std::vector<std::int64_t> facet_nodes;
  bool empty() const { return facet_sizes.empty(); }
};

// A clump (the `clumps` effect): a rigid union of the spheres of one of Config::clump_shapes.
struct ClumpInit {
  int shape = 0;                                   // index into Config::clump_shapes
  double scale = 1.0;                              // the shape's lengths times this (e.g. its bounding radius)
  std::array<double, 3> position{};                // the centre of mass
  std::array<double, 4> orientation{1, 0, 0, 0};   // quaternion (w, x, y, z): shape frame -> world
  std::array<double, 3> velocity{}, omega{};       // of the centre of mass; angular velocity (world)
};

struct Config {
  Material particle;             // every sphere
  Material wall;                 // planes and FE surfaces
  double restitution = 1.0;      // e of sphere-sphere and sphere-wall contacts (the `damping` effect)
  double friction = 0.0;         // mu (the `friction` effect)
  std::array<double, 3> gravity{};
  double dt = 0.0;               // <= 0: dt_safety x the time-step limit
  double dt_safety = 0.5;
  double skin = 0.0;             // Verlet skin; <= 0: 0.2 x the smallest radius
  double max_speed = 0.0;        // largest approach speed the limit must resolve; <= 0: from the spheres
  std::vector<SphereInit> spheres;
  std::vector<PlaneInit> planes;
  SurfaceInit surface;           // the `fe_surfaces` effect
  WheelSpec wheel;               // the `rigid_wheel` effect: `surface` is the wheel's, relative to its centre
  std::vector<ClumpShape> clump_shapes;  // the `clumps` effect
  std::vector<ClumpInit> clumps;
  int mass_columns = 200;        // columns across a shape for its mass properties (clump_shapes.hpp)
  EffectSet effects;
};

}  // namespace polymech::dem
