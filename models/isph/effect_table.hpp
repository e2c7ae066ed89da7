// The effects of the stabilized ISPH model (seed 002 paper 4), as plain data.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::isph {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"viscosity", "viscous term nu lap u of the predictor, eqs. (3), (11), (21) (wall velocities from the ghosts)", {},
       {"polymech::sph::viscosity_fluid", "polymech::sph::viscosity_wall"}, "nothing (scratch shared with the PPE)"},
      {"stabilization", "density relaxation alpha (rho0 - rho^n) / dt^2 in the PPE source, eq. (4)", {}, {},
       "nothing (a term of the right-hand side)"},
      {"rigid_body", "a floating 2D cylinder of IGCB cells coupled through its integration points, eqs. (31)-(43)", {},
       {"polymech::sph::place_body", "polymech::sph::body_force"}, "the body's cells (wall points) and their offsets"},
  };
  return specs;
}

}  // namespace polymech::isph
