// A DEM run restarted from a checkpoint continues bit for bit (issue 16): the spheres' state, both
// contact lists and the tangential springs of their pairs are in the checkpoint. The pour of pile.hpp
// with friction, damping and a meshed floor (sphere-facet pairs with springs), saved mid-pour while the
// spheres collide, loaded into a fresh model and run on next to the uninterrupted one.
#include <gtest/gtest.h>

#include <cstring>

#include "pile.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

// The pour with the floor plane replaced by a 4 x 4 quadrilateral mesh (the `fe_surfaces` effect).
dm::Config pour_onto_a_meshed_floor() {
  dm::Config c = pour_into_a_box();
  c.planes.erase(c.planes.begin());  // the floor
  const int n = 4;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) c.surface.nodes.insert(c.surface.nodes.end(), {kBox * i / n, kBox * j / n, 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::int64_t a = j * (n + 1) + i;
      c.surface.facet_sizes.push_back(4);
      c.surface.facet_nodes.insert(c.surface.facet_nodes.end(), {a, a + 1, a + n + 2, a + n + 1});
    }
  c.effects = pm::EffectSet::resolve({"friction", "damping", "fe_surfaces"}, dm::effect_table());
  return c;
}

bool same_bits(const dm::SphereState& a, const dm::SphereState& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

int spheres_that_differ(const dm::Dem<double>& a, const dm::Dem<double>& b, std::size_t n) {
  int differ = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!same_bits(a.sphere(static_cast<pm::Index>(i)), b.sphere(static_cast<pm::Index>(i)))) ++differ;
  return differ;
}

}  // namespace

TEST(DemRestart, ARestartedPourContinuesBitForBit) {
  const dm::Config c = pour_onto_a_meshed_floor();
  dm::Dem<double> whole(c);
  const std::int64_t first = static_cast<std::int64_t>(0.07 / whole.dt()), second = 1000;
  pm::models::run(whole, first);
  ASSERT_GT(whole.sphere_list_builds(), 1);

  pm::models::Archive a;
  whole.save(a, "dem/");
  dm::Dem<double> restarted(c);
  restarted.load(a, "dem/");
  EXPECT_EQ(restarted.step_index(), first);

  // The same checkpoint without the contact lists: the springs start from zero (what a restart without
  // them would do), and the run departs from the uninterrupted one: the springs matter here.
  pm::models::Archive without_springs;
  whole.state().save(without_springs, "dem/state/");
  without_springs.put("dem/step", whole.step_index());
  without_springs.put("dem/sphere_pairs/builds", 0);
  without_springs.put("dem/facet_pairs/builds", 0);
  dm::Dem<double> forgetful(c);
  forgetful.load(without_springs, "dem/");

  pm::models::run(whole, second);
  pm::models::run(restarted, second);
  pm::models::run(forgetful, second);
  EXPECT_EQ(restarted.step_index(), whole.step_index());
  EXPECT_EQ(spheres_that_differ(whole, restarted, c.spheres.size()), 0);
  EXPECT_GT(spheres_that_differ(whole, forgetful, c.spheres.size()), 10);
}

TEST(DemRestart, ARestartAcrossThePoursFrictionSwitchContinuesBitForBit) {
  // Config::pour_friction: the pour settles with mu_p = 0.1 until a time 500 steps after the checkpoint, then has
  // the scene's mu. The switch is a step index from the configuration, so the restarted run switches at the same
  // step as the uninterrupted one; a run without the pour's friction departs from both (the switch mattered).
  dm::Config c = pour_onto_a_meshed_floor();
  dm::Dem<double> probe(c);  // the step, to place the switch
  const std::int64_t first = static_cast<std::int64_t>(0.07 / probe.dt()), second = 1000;
  c.pour_friction = 0.1;
  c.pour_friction_until = (first + 500) * probe.dt();
  dm::Dem<double> whole(c);
  pm::models::run(whole, first);
  pm::models::Archive a;
  whole.save(a, "dem/");
  dm::Dem<double> restarted(c);
  restarted.load(a, "dem/");
  dm::Config plain_config = c;
  plain_config.pour_friction = -1.0;
  dm::Dem<double> plain(plain_config);
  pm::models::run(plain, first + second);
  pm::models::run(whole, second);
  pm::models::run(restarted, second);
  EXPECT_EQ(spheres_that_differ(whole, restarted, c.spheres.size()), 0);
  EXPECT_GT(spheres_that_differ(whole, plain, c.spheres.size()), 10);
}
