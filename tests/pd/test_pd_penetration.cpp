// Plate perforation (seed 003 §3(3)-§4, Figs. 4-6), reduced in size from scenes/pd/penetration_303.toml
// (2 mm spacing, 6 particle layers through the 12 mm Weldox 460 E plate, a 16 mm clamped span): the
// blunt 197 g projectile at 303.5 m/s perforates the plate with velocity viscosity, which fails at the
// projectile's rim (a plug); without zero-energy control the impact zone collapses, as the report
// found (Fig. 5). Energy is accounted for throughout the controlled run.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/impact.hpp"
#include "nosb_pd/run.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

std::filesystem::path scene_file() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return (d ? std::filesystem::path(d) : std::filesystem::path(".")) / "scenes/pd/penetration_303.toml";
}

// The shipped scene at draft accuracy (2 mm), on a smaller clamped span.
np::Config reduced(bool velocity_viscosity) {
  auto scene = pm::io::load_nosb_pd_scene(scene_file());
  np::Config c = scene.config;
  c.clamp_radius = 0.016;
  // c_v = 0.3 rather than the scene's 6.0: at this coarse resolution c_v = 6 stops the projectile
  // (docs/VALIDATION.md); the test is about plugging vs collapse and the energy balance, not about c_v
  c.stabilization.c_v = 0.3;
  c.dt = c.dt_safety * np::NosbPd<double, 3>::stable_time_step(c);
  c.geometry.radius = c.clamp_radius + c.horizon();
  if (!velocity_viscosity) {
    std::vector<std::string> e;
    for (const auto& name : c.effects.names())
      if (name != "velocity_viscosity") e.push_back(name);
    c.effects = pm::EffectSet::resolve(e, np::NosbPd<double, 3>::effects());
    c.dt = 0.0;  // the stable step without the viscosity's limit
  }
  return c;
}

}  // namespace

TEST(PdPenetration, VelocityViscosityGivesPerforationByPluggingWithBalancedEnergy) {
  np::Impact<double, 3> m(reduced(true));
  ASSERT_TRUE(m.config().effects.has("velocity_viscosity"));
  np::RunHooks hooks;
  hooks.sample_every = 10;
  const auto stats = np::run(m, static_cast<std::int64_t>(std::ceil(90e-6 / m.dt())), hooks);
  ASSERT_TRUE(stats.finite);
  const auto s = np::analyse_impact(m);
  // the projectile is through the plate (nose two spacings below its bottom face)
  EXPECT_LT(m.projectile().position[2], -0.012 - 2 * m.config().spacing);
  // a residual velocity in the experiment's range at this coarse resolution (experiment: 200.6 m/s)
  EXPECT_GT(s.residual_velocity, 120.0);
  EXPECT_LT(s.residual_velocity, 280.0);
  // shear plugging: the rim fails before the core under the projectile
  EXPECT_GT(s.rim_damage, s.core_damage + 0.05) << "rim " << s.rim_damage << " core " << s.core_damage;
  EXPECT_LT(s.core_damage, 0.6) << "rim " << s.rim_damage << " core " << s.core_damage << " residual " << s.residual_velocity;
  // energy: kinetic + stored + plastic + dissipated stays the initial kinetic energy within 10 %
  EXPECT_LT(stats.energy_error(), 0.10);
  const auto& e = stats.samples.back().energy;
  EXPECT_GT(e.plastic, 0.1 * stats.initial_energy) << "plastic work in the plugging zone";
  EXPECT_LT(e.viscous, 0.0) << "velocity viscosity dissipates";
  std::printf("[penetration] c_v = 0.3: residual %.1f m/s, core damage %.2f, rim damage %.2f, energy error %.3f\n",
              s.residual_velocity, s.core_damage, s.rim_damage, stats.energy_error());
}

TEST(PdPenetration, WithoutZeroEnergyControlTheImpactZoneCollapses) {
  np::Impact<double, 3> m(reduced(false));
  ASSERT_FALSE(m.config().effects.has("velocity_viscosity"));
  np::RunHooks hooks;
  hooks.sample_every = 10;
  const auto stats = np::run(m, static_cast<std::int64_t>(std::ceil(90e-6 / m.dt())), hooks);
  ASSERT_TRUE(stats.finite);
  const auto s = np::analyse_impact(m);
  std::printf("[penetration] without control: residual %.1f m/s, core damage %.2f, rim damage %.2f, energy error %.3f\n",
              s.residual_velocity, s.core_damage, s.rim_damage, stats.energy_error());
  // Fig. 5: the material under the projectile is destroyed (the controlled run keeps its core, < 0.6,
  // and fails at the rim); crushed particles fail, so the energy stays balanced (pd::CrushLimits)
  EXPECT_GT(s.core_damage, 0.6) << "core " << s.core_damage;
  EXPECT_LT(stats.energy_error(), 0.15);
}
