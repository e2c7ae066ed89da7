// What io/ needs of the ISPH model without compiling it (Kokkos-free): the particle and wall-point counts
// of a configuration, a time-step check, and the checks of a configuration.
#pragma once

#include <string>

#include "isph/config.hpp"
#include "isph/effect_table.hpp"

namespace polymech::isph {

// Fluid particles and wall integration points the model will create.
Counts count(const Config& c);

// The advective (CFL 0.4 at the dam-break speed 2 sqrt(g H)) and viscous (0.125 l0^2 / nu) limits.
struct TimeStepLimit {
  double cfl = 0.0, viscous = 0.0, limit = 0.0;
  std::string describe() const;
};
TimeStepLimit time_step_limit(const Config& c);

// Empty when the configuration can run; otherwise why not (rigid_body not implemented, fluid outside
// the tank, ...).
std::string check(const Config& c);

}  // namespace polymech::isph
