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
  EXPECT_EQ(census.launches("polymech::dem::sphere_plane"), 0);  // the planes are in sphere_sphere's rows
  EXPECT_EQ(census.launches("polymech::dem::kick_drift"), 20);     // with start_forces and the list's check
  EXPECT_EQ(census.launches("polymech::dem::start_forces"), 1);    // the initial forces
  EXPECT_EQ(census.launches("polymech::dem::sphere_sphere_gather"), 1);
  EXPECT_EQ(census.launches("polymech::dem::sphere_sphere_gather_kick"), 20);  // the second half kick
  EXPECT_EQ(census.launches("polymech::dem::kick"), 0);
  EXPECT_EQ(census.launches("polymech::neighbors::max_displacement"), 0);
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
  for (const auto& spec : dm::effect_table())  // all but rigid_wheel and fe_tyre (below): their kernels stay idle here
    for (const auto& kernel : spec.kernels)
      if (spec.name == "rigid_wheel" || spec.name == "fe_tyre")
        EXPECT_EQ(census.launches(kernel), 0) << kernel;
      else
        EXPECT_GE(census.launches(kernel), 1) << kernel;
  EXPECT_TRUE(census.allocations_containing("wheel").empty());
  EXPECT_TRUE(census.allocations_containing("tyre").empty());
  EXPECT_TRUE(census.allocations_containing("polymech::solid::fse_").empty());
  EXPECT_EQ(census.launches("polymech::dem::sphere_facet"), 21);
  EXPECT_FALSE(census.allocations_containing("sphere_pairs_history").empty());
  EXPECT_FALSE(census.allocations_containing("facet_pairs_history").empty());
  EXPECT_FALSE(census.allocations_containing("clump_bodies").empty());
}

TEST(DemEffects, TheRigidWheelPlacesItsMeshAndSumsItsLoadEachStep) {
  pm::testing::KernelCensus census;
  auto c = scene({"friction", "damping", "fe_surfaces", "rigid_wheel"}, false);
  auto& w = c.wheel;
  w.radius = 0.1;
  w.width = 0.05;
  w.around = 32;
  w.across = 2;
  w.mass = 1.0;
  w.load = 1.0;
  w.load_to = w.speed_to = 1.0;
  w.x_start = 0.2;
  w.parked = {0.2, 0.0, 2.0};
  c.surface = dm::wheel_surface(w);
  dm::Dem<double> m(c);
  run_steps(m, 20);
  EXPECT_TRUE(m.wheel().placed);
  EXPECT_EQ(census.launches("polymech::dem::wheel_reaction_sum"), 21);
  EXPECT_EQ(census.launches("polymech::contact::place_rigid_surface"), 21);  // parked at the start, then each step
  EXPECT_FALSE(census.allocations_containing("wheel_reaction").empty());
  EXPECT_THROW(pm::EffectSet::resolve({"rigid_wheel"}, dm::effect_table()), pm::EffectError);  // requires fe_surfaces
  auto no_wheel = c;
  no_wheel.wheel = dm::WheelSpec{};
  EXPECT_THROW(dm::Dem<double> bad(no_wheel), std::invalid_argument);
}

// The deformable tyre (fe_tyre): parked, its FE model is built but not stepped and no facet kernel runs; set down,
// each step places its surface, runs the deforming-surface contacts, gathers the node loads, steps the tyre
// (with the damping relative to the rim) and sums the reaction; the rigid wheel's kernels stay idle.
TEST(DemEffects, TheTyreIsSteppedWithTheSpheresOnceSetDown) {
  pm::testing::KernelCensus census;
  auto c = scene({"friction", "damping", "fe_surfaces", "fe_tyre"}, false);
  auto& w = c.wheel;
  w.radius = 0.445;
  w.width = 0.31;
  w.mass = 10.0;
  w.load = 1.0;
  w.load_to = w.speed_to = 1.0;
  w.x_start = 0.2;
  w.start = 10 * 1e-5;
  w.parked = {0.2, 0.0, 5.0};
  c.tyre.around = 12;
  c.tyre.across = 4;
  c.tyre.order = 2;  // its stable step (~1e-5 s, the wall's node spacing) below the spheres' limit
  const double given = c.dt;
  c.dt = 0.0;  // automatic: the smaller of the spheres' and the tyre's step
  dm::Dem<double> m(c);
  EXPECT_EQ(m.dt(), 0.9 * m.tyre().solid().critical_time_step());
  run_steps(m, 5);
  EXPECT_FALSE(m.wheel().placed);
  EXPECT_EQ(census.launches("polymech::dem::sphere_deforming_facet"), 0);
  EXPECT_EQ(census.launches("polymech::dem::place_tyre_surface"), 0);
  while (!m.wheel().placed) m.step();
  const char* kernels[] = {"polymech::dem::sphere_deforming_facet", "polymech::dem::surface_node_loads", "polymech::dem::place_tyre_surface",
                           "polymech::dem::tyre_reaction_sum", "polymech::solid::fse_frame_damping", "polymech::dem::tyre_surface_loads"};
  std::vector<int> at;
  for (const char* k : kernels) at.push_back(census.launches(k));
  run_steps(m, 100);
  for (std::size_t k = 0; k < at.size(); ++k) EXPECT_EQ(census.launches(kernels[k]) - at[k], 100) << kernels[k];
  EXPECT_EQ(census.launches("polymech::dem::sphere_facet"), 0);
  EXPECT_EQ(census.launches("polymech::contact::place_rigid_surface"), 0);
  EXPECT_TRUE(census.allocations_containing("wheel_reaction").empty());
  auto both = c;
  both.effects = pm::EffectSet::resolve({"fe_surfaces", "fe_tyre", "rigid_wheel"}, dm::effect_table());
  EXPECT_THROW(dm::Dem<double> bad(both), std::invalid_argument);
  auto fast = c;  // a step the spheres allow but above the tyre's stable one: refused, naming it
  const double tyre_dt = 0.9 * m.tyre().solid().critical_time_step();
  ASSERT_LT(tyre_dt, m.limit().limit);
  fast.dt = given;
  ASSERT_GT(fast.dt, tyre_dt);
  try {
    dm::Dem<double> bad(fast);
    ADD_FAILURE() << "a step above the tyre's stable one was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("critical step"), std::string::npos) << e.what();
  }
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
