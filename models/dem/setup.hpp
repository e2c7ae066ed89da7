// What io/ needs of the DEM model without compiling it (this header is free of Kokkos): the time-step
// limit of a configuration, and why.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "contact/damping.hpp"
#include "dem/config.hpp"
#include "dem/effect_table.hpp"

namespace polymech::dem {

struct TimeStepLimit {
  double rayleigh = 0.0;      // 0.2 x the Rayleigh time of the smallest sphere
  double hertz = 0.0;         // the Hertz contact time at the largest approach speed / 20 (0: no speed)
  double limit = 0.0;         // the smaller of the two
  double approach_speed = 0.0;
  std::string describe() const;  // "1.2e-06 s (0.2 x Rayleigh time 6e-06 s; Hertz contact time ...)"
};

// The damping ratio beta (<= 0) for which the damped Hertz law rebounds with the restitution e in (0, 1],
// and the restitution a beta gives: kernels/contact/damping.hpp (shared with the ISPH body).
using contact::hertz_damping_ratio;
using contact::hertz_restitution;

// The clumps of a configuration as member spheres (world frame, after the free spheres in the model) and
// rigid bodies: mass M = rho V s^3 and principal moments rho I s^5 of the union of the shape's spheres
// (clump_shapes.hpp, computed once per shape), body axes along the principal axes, angular momentum
// L = R I R^T omega. Throws std::invalid_argument for an unknown shape index or a bad scale.
struct ClumpBodies {
  struct Body {
    double mass = 0.0;
    std::array<double, 3> inertia{};                 // principal moments
    std::array<double, 3> position{}, velocity{}, angular_momentum{};
    std::array<double, 4> orientation{1, 0, 0, 0};   // body (principal) frame -> world
  };
  std::vector<Body> bodies;
  std::vector<SphereInit> members;                    // world positions and velocities at the start
  std::vector<int> member_body;                       // the body of each member
  std::vector<std::array<double, 3>> member_offset;   // in the body frame
};
ClumpBodies expand_clumps(const Config& c);

// The largest dt a configuration may run with (computed on the host from the configuration alone).
TimeStepLimit time_step_limit(const Config& c);

}  // namespace polymech::dem
