// The effects of the DEM model (seed 002 paper 2), as plain data: what io/ resolves a scene's
// [model].effects against, without compiling the model.
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::dem {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {
      {"friction", "tangential Mindlin spring with a Coulomb limit (seed 002 paper 2 eqs. (13)-(15)), kept per contact",
       {}, {"polymech::contact::carry_history"},
       "3 reals + 1 int per listed pair (sphere-sphere, sphere-facet), 3 reals per sphere and plane"},
      {"damping", "viscous normal and tangential damping from the restitution coefficient (eqs. (12), (13), (17))",
       {}, {}, "nothing (a coefficient per contact, evaluated in the force kernels)"},
      {"fe_surfaces", "spheres against quadrilateral FE segments by the inside-outside algorithm (eqs. (1)-(10))", {},
       {"polymech::contact::facet_geometry", "polymech::dem::sphere_facet"},
       "the surface mesh (nodes, facets, centroids, normals) and a sphere-facet pair list"},
      {"clumps", "multi-sphere particles: rigid unions of spheres with numerical mass and inertia (sec. 2)", {},
       {"polymech::dem::clump_kick", "polymech::dem::clump_drift", "polymech::dem::clump_members",
        "polymech::dem::clump_loads"},
       "a rigid body per clump (~200 B), a body index and a body-frame offset per sphere"},
      {"rigid_wheel", "the FE surface is a rigid wheel driven over the bed: load and speed schedule, slip (sec. 4)",
       {"fe_surfaces"}, {"polymech::contact::place_rigid_surface", "polymech::dem::wheel_reaction_sum"},
       "one rigid body, the mesh's reference nodes and 6 reals per sphere (what it gives the wheel)"},
      {"fe_tyre", "the FE surface is a deformable tyre (explicit finite strain, inflated, rim tied to the beads) on the wheel's "
       "schedule; contact forces returned to its nodes (sec. 4, issue 37)",
       {"fe_surfaces"}, {"polymech::dem::sphere_deforming_facet", "polymech::dem::surface_node_loads", "polymech::dem::place_tyre_surface",
                         "polymech::dem::tyre_surface_loads", "polymech::dem::tyre_reaction_sum", "polymech::solid::fse_frame_damping"},
       "the tyre's FE model (3 x 6 reals per node, its elements' geometry), 8 reals per sphere-facet entry"},
  };
  return specs;
}

}  // namespace polymech::dem
