// The tyre's section options (solid::TyreSpec) from a scene's wheel and tyre (issue 37): the one place that maps
// WheelSpec + TyreInit onto the FE tyre, used by the scene reader's section check (io/dem_pour_scene.cpp) and by the
// model (dem/tyre_drive.hpp). Free of Kokkos.
#pragma once

#include "dem/config.hpp"
#include "solid/tyre_section.hpp"

namespace polymech::dem {

// The outer radius and section width are the wheel's; the rebar belt implies the belted, layered wall; a crown
// radius of 0 keeps solid::TyreSpec's default.
inline solid::TyreSpec tyre_spec(const WheelSpec& wheel, const TyreInit& tyre) {
  solid::TyreSpec ts;
  ts.outer_radius = wheel.radius;
  ts.width = wheel.width;
  ts.mass = tyre.mass;
  ts.layered = tyre.layered || tyre.belt_rebar;
  ts.belted = ts.belt_rebar = tyre.belt_rebar;
  if (tyre.crown_radius > 0) ts.crown_radius = tyre.crown_radius;
  return ts;
}

}  // namespace polymech::dem
