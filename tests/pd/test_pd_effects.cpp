// Effects of the NOSB model: a scene's effects are exactly the kernels that run. A disabled effect
// launches nothing and allocates nothing (counted through Kokkos Tools by kernel name and View label);
// an enabled one launches every kernel it declares.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "nosb_pd/impact.hpp"
#include "support/kernel_census.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;
using Model = np::NosbPd<double, 3>;

namespace {

// A small elasto-plastic plate hit by a sphere: every effect has work to do.
np::Config plate(const std::vector<std::string>& effects) {
  np::Config c;
  c.dimension = 3;
  c.spacing = 2e-3;
  c.horizon_ratio = 2.0;
  c.geometry.shape = np::Shape::disc;
  c.geometry.radius = 0.014;
  c.geometry.thickness = 0.006;
  c.clamp_radius = 0.010;
  c.material.law = np::Law::johnson_cook;
  c.material.jc_a = 490e6;
  c.material.jc_b = 807e6;
  c.material.jc_n = 0.73;
  c.damage.critical_stretch = 0.01;
  c.stabilization.omega_v = 1e6;
  c.loading = np::Loading::impact;
  c.projectile.shape = np::ProjectileShape::sphere;
  c.projectile.radius = 0.004;
  c.projectile.mass = 0.01;
  c.projectile.velocity = 300;
  c.projectile.standoff = 0.0;
  c.effects = pm::EffectSet::resolve(effects, Model::effects());
  return c;
}

const std::vector<std::string> kAll = {"weighted_function", "velocity_viscosity", "hourglass", "damage", "contact", "short_range"};

// The plate hit by the projectile (the impact's coupled model runs the contact effect).
void run(const std::vector<std::string>& effects, int steps = 20) {
  np::Impact<double, 3> m(plate(effects));
  for (int s = 0; s < steps; ++s) m.step();
  (void)m.energy();
}

}  // namespace

TEST(PdEffects, EveryEnabledEffectLaunchesTheKernelsItDeclares) {
  pm::testing::KernelCensus census;
  run(kAll);
  for (const auto& spec : Model::effects())
    for (const auto& kernel : spec.kernels) EXPECT_GE(census.launches(kernel), 20) << spec.name << ": " << kernel;
  EXPECT_GE(census.launches("polymech::pd::bond_forces_with_hourglass_velocity_viscosity"), 20);
  EXPECT_EQ(census.launches("polymech::pd::bond_forces"), 0) << "the plain force kernel does not run when the controls are on";
}

TEST(PdEffects, ADisabledEffectLaunchesAndAllocatesNothing) {
  // effect -> the text its kernels and Views carry (effects another requires are disabled together)
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"velocity_viscosity"}, "velocity_viscosity"},
      {{"hourglass"}, "hourglass"},
      {{"damage", "short_range"}, "damage"},
      {{"short_range"}, "short_range"},
      {{"contact"}, "projectile"},
  };
  for (const auto& [off, marker] : cases) {
    std::vector<std::string> on;
    for (const auto& e : kAll)
      if (std::find(off.begin(), off.end(), e) == off.end()) on.push_back(e);
    if (std::find(off.begin(), off.end(), "contact") != off.end()) {
      // impact loading needs contact: run the same plate without a projectile
      pm::testing::KernelCensus census;
      auto c = plate(on);
      c.loading = np::Loading::none;
      Model m(c);
      for (int s = 0; s < 20; ++s) m.step();
      EXPECT_TRUE(census.kernels_containing("projectile").empty());
      EXPECT_TRUE(census.allocations_containing("contact_force").empty());
      continue;
    }
    pm::testing::KernelCensus census;
    run(on);
    EXPECT_TRUE(census.kernels_containing(marker).empty()) << marker << ": " << census.kernels_containing(marker).front();
    EXPECT_TRUE(census.allocations_containing(marker).empty()) << marker;
    EXPECT_GE(census.launches("polymech::pd::deformation_gradient") + census.launches("polymech::pd::deformation_gradient_with_damage"), 20);
  }
}

TEST(PdEffects, TheElasticLawAllocatesNoPlasticState) {
  pm::testing::KernelCensus census;
  auto c = plate({"damage", "contact"});
  c.material.law = np::Law::elastic;
  np::Impact<double, 3> m(c);
  for (int s = 0; s < 5; ++s) m.step();
  EXPECT_TRUE(census.allocations_containing("plastic_").empty());
  EXPECT_EQ(census.launches("polymech::pd::stress_johnson_cook"), 0);
  EXPECT_GE(census.launches("polymech::pd::stress_elastic"), 5);
}

TEST(PdEffects, UnknownAndInconsistentEffectsAreClearErrors) {
  try {
    pm::EffectSet::resolve({"velocity_viscocity"}, Model::effects());
    FAIL() << "no error";
  } catch (const pm::EffectError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown effect 'velocity_viscocity'; allowed: weighted_function, velocity_viscosity"),
              std::string::npos)
        << e.what();
  }
  try {
    pm::EffectSet::resolve({"short_range"}, Model::effects());
    FAIL() << "no error";
  } catch (const pm::EffectError& e) {
    EXPECT_NE(std::string(e.what()).find("'short_range' requires effect 'damage'"), std::string::npos) << e.what();
  }
}
