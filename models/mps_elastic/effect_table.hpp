// The effects of the MPS elastic-wave model (seed 000), as plain data: what io/ resolves a scene's
// [model].effects against, without compiling the model.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::mps_elastic {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"rotation",
       "relative displacement with particle rotation (seed 000 eqs. (6)-(7)) and the rotation equation (12)",
       {},
       {"polymech::mps::volumetric_strain_with_rotation", "polymech::mps::elastic_acceleration_with_rotation",
        "polymech::mps::rotation_update"},
       "5 reals per particle (theta, omega, alpha, sin theta, (1 - cos theta)/2)"},
      {"crack_contact.open_close",
       "crack faces open and close: penalty repulsion between S+ and S- pairs (seed 000 eqs. (17)-(19))",
       {},
       {"polymech::contact::crack_open_close", "polymech::contact::crack_apply_forces"},
       "per crack pair: state (1 int) and force (2 reals)"},
      {"crack_contact.slip",
       "crack faces stick and slip: Coulomb friction with a fixed or contact normal force (seed 000 eqs. (20)-(21))",
       {},
       {"polymech::contact::crack_slip", "polymech::contact::crack_apply_forces"},
       "per crack pair: state, force, anchor (2 reals), preload, slip sign; + normal force with open_close"},
  };
  return specs;
}

}  // namespace polymech::mps_elastic
