// DEM effects: a disabled effect launches and allocates nothing (kernel census through Kokkos Tools).
#include <gtest/gtest.h>

#include "dem/benchmark.hpp"
#include "support/kernel_census.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

dm::Config scene(const std::vector<std::string>& effects, bool meshed) {
  auto c = dm::sphere_on_wall(dm::chung_ooi_test2_aluminium(), 50, 30.0, meshed);
  dm::SphereInit other = c.spheres[0];
  other.position = {0.2, 0.0, 0.1005};  // touching sphere 0: one listed pair
  c.spheres.push_back(other);
  c.friction = 0.3;
  c.restitution = 0.8;
  c.effects = pm::EffectSet::resolve(effects, dm::effect_table());
  return c;
}

void run_steps(dm::Dem<double>& m, int n) {
  for (int s = 0; s < n; ++s) m.step();
}

}  // namespace

TEST(DemEffects, NoEffectsLaunchesOnlyTheBaseKernelsAndAllocatesNoHistory) {
  pm::testing::KernelCensus census;
  dm::Dem<double> m(scene({}, false));
  run_steps(m, 20);
  EXPECT_TRUE(census.allocations_containing("history").empty());
  EXPECT_TRUE(census.allocations_containing("surface").empty());
  EXPECT_TRUE(census.allocations_containing("clump").empty());
  EXPECT_TRUE(census.allocations_containing("polymech::dem::body").empty());
  EXPECT_EQ(census.launches("polymech::contact::carry_history"), 0);
  EXPECT_EQ(census.launches("polymech::dem::sphere_facet"), 0);
  EXPECT_EQ(census.launches("polymech::contact::facet_geometry"), 0);
  EXPECT_EQ(census.launches("polymech::dem::sphere_sphere"), 21);  // 20 steps + the initial forces
  EXPECT_EQ(census.launches("polymech::dem::sphere_plane"), 21);
  EXPECT_EQ(census.launches("polymech::dem::kick_rotation"), 40);
}

TEST(DemEffects, EveryEffectLaunchesItsKernelsAndAllocatesItsState) {
  pm::testing::KernelCensus census;
  auto c = scene({"friction", "damping", "fe_surfaces", "clumps"}, true);
  c.skin = 1e-5;  // rebuilds, so the history is carried
  c.clump_shapes = dm::gravel_shapes();
  dm::ClumpInit k;
  k.shape = 2;
  k.scale = 0.3;
  k.position = {1.0, 1.0, 0.5};
  c.clumps = {k};
  dm::Dem<double> m(c);
  run_steps(m, 20);
  for (const auto& spec : dm::effect_table())
    for (const auto& kernel : spec.kernels) EXPECT_GE(census.launches(kernel), 1) << kernel;
  EXPECT_EQ(census.launches("polymech::dem::sphere_facet"), 21);
  EXPECT_FALSE(census.allocations_containing("sphere_pairs_history").empty());
  EXPECT_FALSE(census.allocations_containing("facet_pairs_history").empty());
  EXPECT_FALSE(census.allocations_containing("clump_bodies").empty());
}

TEST(DemEffects, UnknownEffectAndSurfaceWithoutMeshAreErrors) {
  EXPECT_THROW(pm::EffectSet::resolve({"rolling_resistance"}, dm::effect_table()), pm::EffectError);
  auto c = scene({"fe_surfaces"}, false);
  EXPECT_THROW(dm::Dem<double> m(c), std::invalid_argument);
  auto no_clumps = scene({"clumps"}, false);
  EXPECT_THROW(dm::Dem<double> m(no_clumps), std::invalid_argument);
  auto no_effect = scene({}, false);
  no_effect.clump_shapes = dm::gravel_shapes();
  no_effect.clumps.resize(1);
  EXPECT_THROW(dm::Dem<double> m(no_effect), std::invalid_argument);
}
