// What io/ needs of the DEM model without compiling it (this header is free of Kokkos): the time-step
// limit of a configuration, and why.
#pragma once

#include <string>

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

// The largest dt a configuration may run with (computed on the host from the configuration alone).
TimeStepLimit time_step_limit(const Config& c);

}  // namespace polymech::dem
