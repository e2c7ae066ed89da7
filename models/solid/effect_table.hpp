// The effects of the finite-element solid model (issue 34, seed 002 paper 5), as plain data: what io/
// resolves a scene's [model].effects against, without compiling the model.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::solid {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"plasticity",
       "Hill (1948) plasticity with cubic symmetry and power-law hardening at every quadrature point (seed 002 paper 5 "
       "eqs. (1)-(4)); without it the solid is linear elastic",
       {},
       {"polymech::solid::plastic_internal_force", "polymech::solid::tangent_apply"},
       "per quadrature point: the converged and trial history (2 x 7 reals), the consistent tangent (36 reals), a status"},
  };
  return specs;
}

}  // namespace polymech::solid
