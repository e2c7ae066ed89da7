// ISPH effects: a disabled effect launches and allocates nothing (kernel census through Kokkos Tools).
#include <gtest/gtest.h>

#include "common.hpp"
#include "support/kernel_census.hpp"

using namespace isph_test;

TEST(IsphEffects, ViscosityAndBodyOffLaunchNothingOfTheirs) {
  auto c = tank_config(2, 0.01, 0.1, 0.06, 1e-3);
  c.effects = pm::EffectSet::resolve({}, ip::effect_table());
  pm::testing::KernelCensus census;
  ip::Isph<double, 2> m(c);
  for (int k = 0; k < 3; ++k) m.step();
  EXPECT_EQ(census.launches("polymech::sph::viscosity_fluid"), 0);
  EXPECT_EQ(census.launches("polymech::sph::viscosity_wall"), 0);
  EXPECT_EQ(census.launches("polymech::sph::place_body"), 0);
  EXPECT_EQ(census.launches("polymech::sph::body_force"), 0);
  EXPECT_TRUE(census.allocations_containing("body_offset").empty());
  EXPECT_EQ(census.launches("polymech::sph::predict"), 3);  // gravity only
  EXPECT_EQ(census.launches("polymech::sph::project"), 3);
}

TEST(IsphEffects, ViscosityAndBodyOnLaunchTheirKernelsEachStep) {
  auto c = tank_config(2, 0.01, 0.2, 0.12, 1e-3);
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization", "rigid_body"}, ip::effect_table());
  c.body.diameter = 0.06;
  c.body.centre[0] = 0.1;
  c.body.centre[1] = 0.06;
  pm::testing::KernelCensus census;
  ip::Isph<double, 2> m(c);
  for (int k = 0; k < 3; ++k) m.step();
  EXPECT_EQ(census.launches("polymech::sph::viscosity_fluid"), 3);
  EXPECT_EQ(census.launches("polymech::sph::viscosity_wall"), 3);
  EXPECT_EQ(census.launches("polymech::sph::body_force"), 3);
  EXPECT_EQ(census.launches("polymech::sph::place_body"), 4);  // at construction and after each step
  EXPECT_EQ(census.launches("polymech::sph::predict"), 0);
}
