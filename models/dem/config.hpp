// The configuration of a DEM model (plain data, free of Kokkos): what io/ fills from a scene and tests
// fill directly. Units SI.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

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
  EffectSet effects;
};

}  // namespace polymech::dem
