// Binary impacts as DEM configurations (free of Kokkos: io/ builds them from scenes): two identical
// spheres head on, a sphere onto a plane or a meshed wall at an incidence angle, with the time step a
// fraction of the Hertz contact time. The Chung & Ooi (2011) benchmark materials (Granular Matter
// 13:643-656; docs/VALIDATION.md says where each value comes from). Tests 3 and 4 share the alumina
// sphere (r = 2.5 mm, 3.9 m/s).
#pragma once

#include "dem/config.hpp"

namespace polymech::dem {

struct Case {
  Material particle, wall;  // wall.young = 0: rigid
  double radius = 0, speed = 0;
};
inline Case chung_ooi_test1_glass() { return {{4.8e10, 0.20, 2800}, {}, 0.010, 10.0}; }
inline Case chung_ooi_test2_aluminium() { return {{7.0e10, 0.30, 2699}, {0.0, 0.0, 0.0}, 0.10, 0.2}; }
inline Case chung_ooi_test2_magnesium() { return {{4.0e10, 0.35, 1800}, {0.0, 0.0, 0.0}, 0.10, 0.2}; }
inline Case chung_ooi_alumina() { return {{3.8e11, 0.23, 4000}, {0.0, 0.0, 0.0}, 0.0025, 3.9}; }
inline Case chung_ooi_cast_iron() { return {{1.0e11, 0.25, 7000}, {0.0, 0.0, 0.0}, 0.0025, 3.9}; }

double sphere_mass(const Case& k);

// Test 1: two identical spheres head on along x, each at k.speed, 1e-3 r apart; dt = t_c / steps_per_contact.
Config two_spheres(const Case& k, double steps_per_contact);

// Tests 2-4: a sphere onto the plane z = 0 (meshed: a 4 x 4 grid of quadrilaterals of side r there) at
// k.speed, angle_deg from the normal; dt = the Hertz contact time of the normal speed / steps_per_contact.
Config sphere_on_wall(const Case& k, double steps_per_contact, double angle_deg = 0.0, bool meshed = false);

}  // namespace polymech::dem
