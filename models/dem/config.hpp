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

// The deformable tyre of the `fe_tyre` effect (seed 002 paper 2 §4; issue 37; models/dem/tyre_drive.hpp): the
// tyre 37x12.5R16.5 of models/solid/tyre.hpp (its outer radius and width are WheelSpec's) as an explicit
// finite-strain solid whose beads are tied to the rim, a rigid body that carries WheelSpec's load, speed and slip.
struct TyreInit {
  int around = 24, across = 8, through = 1;  // cells round the wheel, along the section's contour, through the wall
  int order = 2;                             // Lagrange order of the cells
  double pressure = 0.35e6;                  // inflation (Pa), a follower pressure on the inner surface
  double inflate_to = 0.010;                 // its ramp from set-down (s; paper 2: 0-10 ms)
  double damping = 200.0;                    // 1/s, mass-proportional, relative to the rim's rigid motion
  double tread_young = 6.0e6;                // the tread rubber's E and nu for the sphere-tread Hertz law
  double tread_poisson = 0.49;
  double mass = 37.6;                        // kg: the tyre's own mass (its density follows from its volume)
  bool layered = false;                      // the wall: false, the smeared law; true, rubber / cord layer / rubber
                                             // (solid::TyreSpec::layered; needs an odd `through` >= 3)
  bool belt_rebar = false;                   // the steel belt over the crown as two +-20 deg cord families in the
                                             // layer outside the cord layer (solid::TyreSpec::belt_rebar; needs layered)
  std::array<double, 2> deflate{};          // s after the set-down: the pressure ramps from full to zero over
                                             // [deflate[0], deflate[1]] (the hard case of a flat tyre); {0, 0}: never
  double crown_radius = 0.0;                 // m, the inner tread arc's transverse radius R_t; 0: solid::TyreSpec's
                                             // default (0.35 m, assumed)
  int substeps = 1;                          // the tyre's steps per DEM step (dem/tyre_drive.hpp): 1, one common step
                                             // (the smaller); 0, as many as the tyre needs under the DEM's; n > 1, n
};

struct Config {
  Material particle;             // every sphere
  Material wall;                 // planes and FE surfaces
  double restitution = 1.0;      // e of sphere-sphere and sphere-wall contacts (the `damping` effect)
  double friction = 0.0;         // mu (the `friction` effect)
  double pour_friction = -1.0;   // mu of the sphere-sphere and sphere-plane contacts before pour_friction_until (s), the
  double pour_friction_until = 0.0;  // `friction` effect's mu from then on: a denser bed (< 0: none; docs/METHODS.md
                                     // "A denser bed: the pour's friction")
  std::array<double, 3> gravity{};
  double dt = 0.0;               // <= 0: dt_safety x the time-step limit
  double dt_safety = 0.5;
  double skin = 0.0;             // Verlet skin; <= 0: 0.2 x the smallest radius
  double max_speed = 0.0;        // largest approach speed the limit must resolve; <= 0: from the spheres
  std::vector<SphereInit> spheres;
  std::vector<PlaneInit> planes;
  SurfaceInit surface;           // the `fe_surfaces` effect
  WheelSpec wheel;               // the `rigid_wheel` effect: `surface` is the wheel's, relative to its centre;
                                 // the `fe_tyre` effect: the schedule of the tyre's rim
  TyreInit tyre;                 // the `fe_tyre` effect (its surface is built from the tyre, not `surface`)
  std::vector<ClumpShape> clump_shapes;  // the `clumps` effect
  std::vector<ClumpInit> clumps;
  int mass_columns = 200;        // columns across a shape for its mass properties (clump_shapes.hpp)
  EffectSet effects;
};

}  // namespace polymech::dem
