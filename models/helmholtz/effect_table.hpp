// The effects of the Helmholtz model (seed 002 paper 3), as plain data: what io/ resolves a scene's
// [model].effects against, without compiling the model.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::helmholtz {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"dirichlet",
       "strong Dirichlet values on boundaries of kind dirichlet (the analytic field, eq. (27), or a constant)",
       {},
       {"polymech::fem::dirichlet_values", "polymech::fem::dirichlet_rows", "polymech::fem::dirichlet_lift",
        "polymech::fem::dirichlet_fill"},
       "1 index + 1 complex per constrained DoF"},
      {"impedance",
       "impedance boundaries dPhi/dn = -j omega rho Phi / Zn (eqs. (7), (19)): the C term of eq. (16)",
       {},
       {"polymech::fem::face_geometry", "polymech::fem::impedance_apply", "polymech::fem::impedance_diagonal"},
       "(p+1)^2 indices + (p+1)^2 reals + 1 complex per impedance face"},
      {"vibrating",
       "vibrating boundaries with normal velocity v (eqs. (8), (20)): the source q of eq. (16)",
       {},
       {"polymech::fem::face_geometry", "polymech::fem::boundary_load"},
       "(p+1)^2 indices + (p+1)^2 reals + 1 complex per vibrating face"},
  };
  return specs;
}

}  // namespace polymech::helmholtz
