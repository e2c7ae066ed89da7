// Effects: a model runs exactly the kernels of the effects a scene lists. Proven by counting kernel
// launches and View allocations by name through Kokkos Tools callbacks.
#include <gtest/gtest.h>

#include <set>

#include "mps_elastic/mps_elastic.hpp"
#include "support/kernel_census.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;
using Model = me::MpsElastic<double>;

namespace {

me::Config small_scene(const std::vector<std::string>& effects) {
  me::Config c;
  c.width = c.height = 24 * 1e-4;
  c.spacing = 1e-4;
  c.dt = 4e-9;
  c.excitation.kind = me::ExcitationKind::point;
  c.probes.push_back({"A", 12e-4, 12e-4});
  c.effects = pm::EffectSet::resolve(effects, Model::effects());
  return c;
}

void run_steps(Model& m, int n) {
  for (int s = 0; s < n; ++s) m.step();
  (void)m.energy();
  (void)m.probes();
}

}  // namespace

TEST(Effects, DisabledRotationLaunchesAndAllocatesNothing) {
  pm::testing::KernelCensus census;
  Model m(small_scene({}));
  run_steps(m, 20);
  EXPECT_TRUE(census.kernels_containing("rotation").empty());
  EXPECT_TRUE(census.allocations_containing("rotation").empty());
  // the base model did run
  EXPECT_EQ(census.launches("polymech::mps::volumetric_strain"), 20 + 400);  // 20 steps + power iteration
  EXPECT_GE(census.launches("polymech::mps::elastic_acceleration"), 20);
  EXPECT_EQ(census.launches("polymech::particles::symplectic_euler"), 20);
  EXPECT_EQ(census.launches("polymech::mps::sample_probes"), 20);
}

TEST(Effects, EnabledRotationLaunchesEveryKernelItDeclares) {
  pm::testing::KernelCensus census;
  Model m(small_scene({"rotation"}));
  run_steps(m, 20);
  for (const auto& spec : Model::effects()) {
    if (spec.name != "rotation") continue;
    for (const auto& kernel : spec.kernels) EXPECT_GE(census.launches(kernel), 20) << kernel;
  }
  EXPECT_EQ(census.launches("polymech::mps::volumetric_strain"), 0);  // replaced by the rotation variant
  const auto labels = census.allocations_containing("rotation_");  // model and its stability patch
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()).size(), 5u);  // theta, omega, alpha, sin, 1-cos
}

TEST(Effects, UnknownDuplicateAndMissingRequirementAreClearErrors) {
  try {
    pm::EffectSet::resolve({"rotaton"}, Model::effects());
    FAIL() << "no error";
  } catch (const pm::EffectError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown effect 'rotaton'; allowed: rotation"), std::string::npos) << e.what();
  }
  EXPECT_THROW(pm::EffectSet::resolve({"rotation", "rotation"}, Model::effects()), pm::EffectError);
  const std::vector<pm::EffectSpec> declared = {{"contact", "", {}, {}, ""}, {"slip", "", {"contact"}, {}, ""}};
  try {
    pm::EffectSet::resolve({"slip"}, declared);
    FAIL() << "no error";
  } catch (const pm::EffectError& e) {
    EXPECT_NE(std::string(e.what()).find("'slip' requires effect 'contact'"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(pm::EffectSet::resolve({"slip", "contact"}, declared).has("slip"));
}
