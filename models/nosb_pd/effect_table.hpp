// The effects of the NOSB peridynamics model (seed 003), as plain data: what io/ resolves a scene's
// [model].effects against, without compiling the model. `contact` is the projectile of an impact,
// realised by the coupled model of models/nosb_pd/impact.hpp.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::nosb_pd {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"weighted_function", "W'_ij = beta V (1 - |xi|^2/delta^2) in place of V_ij (seed 003 eq. (2)): irregular layouts",
       {}, {}, "nothing (weights are evaluated per bond)"},
      {"velocity_viscosity", "zero-energy control by velocity viscosity (seed 003 eq. (3), c_v and omega_v)",
       {}, {"polymech::pd::velocity_viscosity_state"},
       "3D+2 reals per particle (mean velocity, horizon volume, force state, force, work)"},
      {"hourglass", "zero-energy control by a stabilising force state (Silling 2017)", {},
       {}, "D+1 reals per particle (force, work)"},
      {"damage", "bonds break above a critical stretch (or the one of a critical energy release rate)", {},
       {"polymech::pd::deformation_gradient_with_damage"}, "1 byte per bond, 1 real per particle"},
      {"contact", "rigid projectile (blunt cylinder or sphere) against the particles by penalty (impact loading)", {},
       {"polymech::contact::projectile_penalty"}, "D reals per particle (contact force)"},
      {"short_range", "short-range repulsion of close particles: fracture faces, fragments (Silling & Askari 2005)",
       {"damage"}, {"polymech::contact::pd_current_positions", "polymech::contact::pd_short_range"},
       "D+1 reals per particle and a Verlet list (radius d_s + skin) over the current positions"},
  };
  return specs;
}

}  // namespace polymech::nosb_pd
