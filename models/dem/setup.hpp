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

// The damping ratio beta (<= 0) for which the damped Hertz law of kernels/dem/hertz_mindlin.hpp (no
// attraction) rebounds with the restitution e in (0, 1]. The usual beta = ln e / sqrt(ln^2 e + pi^2) is
// the linear spring's and gives a larger restitution on a Hertz spring (0.32 for e = 0.2); the law is
// scale-free (the damping grows as delta^(1/4)), so beta depends on e alone: found by bisection on the
// dimensionless equation m x'' = -(x^1.5 + c sqrt(1.5 sqrt(x)) x'), m = 1, v0 = 1, c = -2 sqrt(5/6) beta.
double hertz_damping_ratio(double restitution);
// The restitution that beta gives on the damped Hertz law (the equation above, RK4).
double hertz_restitution(double beta);

// The largest dt a configuration may run with (computed on the host from the configuration alone).
TimeStepLimit time_step_limit(const Config& c);

}  // namespace polymech::dem
