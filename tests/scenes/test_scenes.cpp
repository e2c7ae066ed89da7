// Scenes: every shipped scene loads, and every bad scene stops with one message naming the file, the
// line, the key and what is allowed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <regex>

#include "io/helmholtz_scene.hpp"
#include "io/mps_elastic_scene.hpp"
#include "io/nosb_pd_scene.hpp"
#include "io/registry.hpp"
#include "support/error_messages.hpp"
#include "io/scene.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;

namespace {

fs::path source_dir() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return d ? fs::path(d) : fs::path(".");
}

// A small valid MPS scene (coarse, fast to validate); tests edit one line of it.
const char* kBase = R"(title = "test scene"
[model]
kind = "mps_elastic"
effects = ["rotation"]

[domain]
width = 0.004
height = 0.004
spacing = 2.0e-4
influence_radius = 2.1

[material]
density = 7850.0
c13 = 121.1e9
c55 = 80.8e9

[time]
dt = 8.0e-9
steps = 100

[excitation]
kind = "point"

[[probes]]
name = "A"
x1 = 0.002
x3 = 0.002

[accuracy]
default = "paper"
)";

using polymech::testing::replace_once;

// The MPS loader refuses `text` naming "scene.toml:<line>:" and every fragment.
void expect_error(const std::string& text, int line, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_mps_elastic_scene(p); }, line, fragments);
}

}  // namespace

TEST(Scenes, BaseSceneLoads) {
  polymech::testing::TempDir t;
  const auto s = io::load_mps_elastic_scene(t.write("scene.toml", kBase));
  EXPECT_EQ(s.header.accuracy, "paper");
  EXPECT_EQ(s.header.title, "test scene");
  EXPECT_EQ(s.header.kind, "mps_elastic");
  EXPECT_DOUBLE_EQ(s.config.spacing, 2e-4);
  EXPECT_TRUE(s.config.effects.has("rotation"));
  EXPECT_EQ(s.config.probes.size(), 1u);
  EXPECT_GT(s.stable_dt, s.config.dt);
}

TEST(Scenes, MissingFile) {
  try {
    io::load_mps_elastic_scene("/nonexistent/scene.toml");
    FAIL() << "no error";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.toml: scene file not found"), std::string::npos) << e.what();
  }
}

TEST(Scenes, SyntaxError) { expect_error(replace_once(kBase, "width = 0.004", "width = = 0.004"), 7, {"TOML syntax error"}); }

TEST(Scenes, UnknownKey) {
  expect_error(replace_once(kBase, "spacing = 2.0e-4", "spacing = 2.0e-4\nspcing = 1.0"), 10,
               {"unknown key 'domain.spcing'", "allowed in [domain]:", "spacing", "influence_radius"});
  expect_error(replace_once(kBase, "[accuracy]", "[acuracy]"), 29, {"unknown key 'acuracy'", "allowed at the top level", "accuracy"});
}

TEST(Scenes, UnknownEffect) {
  expect_error(replace_once(kBase, R"(effects = ["rotation"])", R"(effects = ["rotation", "gravity"])"), 4,
               {"key 'model.effects'", "unknown effect 'gravity'", "allowed: rotation"});
}

TEST(Scenes, NegativeSpacing) {
  expect_error(replace_once(kBase, "spacing = 2.0e-4", "spacing = -2.0e-4"), 9, {"key 'domain.spacing' = -0.0002", "must be in [1e-09, 100] m"});
}

TEST(Scenes, InfluenceRadiusBelowSpacing) {
  expect_error(replace_once(kBase, "influence_radius = 2.1", "influence_radius = 0.8"), 10,
               {"key 'domain.influence_radius' = 0.8", "must be in (1, 5] spacings"});
}

TEST(Scenes, NonPositiveTimeStep) {
  expect_error(replace_once(kBase, "dt = 8.0e-9", "dt = 0.0"), 18, {"key 'time.dt' = 0", "must be in [1e-15, 1000] s"});
  expect_error(replace_once(kBase, "dt = 8.0e-9", "dt = -1e-9"), 18, {"key 'time.dt'", "must be in [1e-15, 1000] s"});
}

TEST(Scenes, ProbeOutsideTheDomain) {
  expect_error(replace_once(kBase, "x3 = 0.002", "x3 = 0.005"), 27,
               {"key 'probes[0].x3' = 0.005", "probe 'A' outside the domain", "0 <= x3 <= height = 0.004"});
}

TEST(Scenes, TimeStepAboveTheStabilityLimit) {
  expect_error(replace_once(kBase, "dt = 8.0e-9", "dt = 4.0e-8"), 18,
               {"key 'time.dt' = 4e-08", "above the stability limit", "allowed: 0 < dt <= 2.4"});
}

TEST(Scenes, WrongTypeMissingKeyAndBadChoice) {
  expect_error(replace_once(kBase, "steps = 100", "steps = \"many\""), 19, {"key 'time.steps'", "must be an integer", "got a string"});
  expect_error(replace_once(kBase, "steps = 100", "steps = 1.5"), 19, {"key 'time.steps'", "must be an integer"});
  expect_error(replace_once(kBase, "c55 = 80.8e9\n", ""), 12, {"key 'material.c55' is missing", "required"});
  expect_error(replace_once(kBase, R"(kind = "point")", R"(kind = "laser")"), 22,
               {"key 'excitation.kind' = \"laser\"", R"(allowed: "none", "point", "plane_p", "plane_s")"});
  expect_error(replace_once(kBase, "[time]\n", "[tim]\n"), 1, {"[time] is missing"});
}

TEST(Scenes, AccuracyPresetsScaleSpacingTimeStepAndSteps) {
  polymech::testing::TempDir t;
  const auto path = t.write("scene.toml", kBase);
  io::MpsSceneOptions o;
  o.accuracy = "standard";  // x2
  const auto s = io::load_mps_elastic_scene(path, o);
  EXPECT_DOUBLE_EQ(s.config.spacing, 4e-4);
  EXPECT_DOUBLE_EQ(s.config.dt, 16e-9);
  EXPECT_EQ(s.config.steps, 50);
  o.accuracy = "exquisite";
  try {
    io::load_mps_elastic_scene(path, o);
    FAIL() << "no error";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("accuracy 'exquisite' is unknown; allowed: draft, standard, paper"), std::string::npos);
  }
}

// Every scene shipped under scenes/ loads at its default accuracy, through the registry of scene kinds.
TEST(Scenes, EveryShippedSceneLoads) {
  int count = 0;
  for (const auto& e : fs::recursive_directory_iterator(source_dir() / "scenes")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    const io::SceneKind& kind = io::scene_kind_of(e.path());
    EXPECT_NO_THROW(kind.check(e.path()));
    EXPECT_NE(std::find(kind.apps.begin(), kind.apps.end(), kind.app_for(e.path())), kind.apps.end());
    ++count;
  }
  EXPECT_GE(count, 1);
}

TEST(Scenes, UnknownModelKindNamesTheKnownOnes) {
  polymech::testing::expect_load_error(
      replace_once(kBase, R"(kind = "mps_elastic")", R"(kind = "mps_plastic")"), [](const fs::path& p) { io::scene_kind_of(p); },
      3, {"key 'model.kind' = \"mps_plastic\"", "allowed: \"mps_elastic\", \"nosb_pd\", \"helmholtz\""});
}

// Issue 16: values far outside what any solid has are refused by the loader, not run into NaN.
TEST(Scenes, ImplausibleValuesAreRefusedWithTheirRange) {
  expect_error(replace_once(kBase, "density = 7850.0", "density = 1e300"), 13,
               {"key 'material.density' = 1e+300 is out of range", "in [0.001, 100000] kg/m^3"});
  expect_error(replace_once(kBase, "density = 7850.0", "density = 1e-300"), 13, {"key 'material.density'", "kg/m^3"});
  expect_error(replace_once(kBase, "c13 = 121.1e9", "c13 = 1e300"), 14, {"key 'material.c13' = 1e+300", "Pa"});
  expect_error(replace_once(kBase, "c55 = 80.8e9", "c55 = nan"), 15, {"key 'material.c55' = nan is out of range"});
  expect_error(replace_once(kBase, "width = 0.004", "width = inf"), 7, {"key 'domain.width' = inf", "m (a plausible size"});
  expect_error(replace_once(kBase, "spacing = 2.0e-4", "spacing = 1e-300"), 9, {"key 'domain.spacing'", "1e-09"});
  expect_error(replace_once(kBase, "dt = 8.0e-9", "dt = 1e300"), 18, {"key 'time.dt' = 1e+300", "a plausible time step"});
}

TEST(Scenes, AnImplausibleWaveSpeedIsRefusedAtTheDensity) {
  // each constant plausible, together a P-wave speed of 1.7e7 m/s
  expect_error(replace_once(kBase, "density = 7850.0", "density = 1.0"), 13,
               {"key 'material.density' = 1", "P-wave speed", "allowed: a wave speed in [1, 100000] m/s"});
}

TEST(Scenes, AnEmptyProbeNameIsRefused) {
  expect_error(replace_once(kBase, R"(name = "A")", R"(name = "")"), 25, {"key 'probes[0].name' is empty", "required"});
}

TEST(Scenes, ARunLargerThanTheMemoryIsRefusedNamingItsSizeKeys) {
  // 400 particles fit in 30 MB, 40 000 do not
  ::setenv("POLYMECH_MEMORY_LIMIT", "30M", 1);
  {
    polymech::testing::TempDir t;  // (expect_error below uses a folder of the same name)
    EXPECT_DOUBLE_EQ(io::load_mps_elastic_scene(t.write("scene.toml", kBase)).cost.items, 400.0);
  }
  expect_error(replace_once(kBase, "width = 0.004", "width = 0.4"), 6,
               {"[domain]: the run needs about", "(40000 particles, 480000 bonds) but 30 MB is available (POLYMECH_MEMORY_LIMIT)",
                "domain.width = 0.4 m", "domain.spacing = 0.0002 m"});
  ::unsetenv("POLYMECH_MEMORY_LIMIT");
  polymech::testing::TempDir t;
  const auto s = io::load_mps_elastic_scene(t.write("scene.toml", replace_once(kBase, "width = 0.004", "width = 0.4")));
  EXPECT_DOUBLE_EQ(s.cost.items, 2000.0 * 20.0);
}

TEST(Scenes, TheCostEstimateCountsParticlesBondsStepsMemoryAndTime) {
  polymech::testing::TempDir t;
  const auto s = io::load_mps_elastic_scene(t.write("scene.toml", kBase));
  EXPECT_DOUBLE_EQ(s.cost.items, 400.0);          // 20 x 20 particles
  EXPECT_DOUBLE_EQ(s.cost.pairs, 400.0 * 12.0);   // 12 lattice neighbours within 2.1 spacings
  EXPECT_DOUBLE_EQ(s.cost.steps, 100.0);
  // docs/PERFORMANCE.md: 264 B per particle (double, rotation), on top of what the process holds anyway
  EXPECT_GT(s.cost.bytes, 20e6 + 400.0 * 264.0);
  EXPECT_LT(s.cost.bytes, 20e6 + 400.0 * 500.0);
  EXPECT_NEAR(s.cost.seconds, 400.0 * 100.0 / 6.25e6, 1e-9);  // the apps' draft runs, one thread (io/cost.cpp)
  EXPECT_EQ(s.cost.rate_threads, 1);
  const std::string text = io::describe(s.cost);
  EXPECT_NE(text.find("400 particles, 4800 bonds, 100 steps"), std::string::npos) << text;
  EXPECT_NE(text.find("docs/PERFORMANCE.md"), std::string::npos) << text;
  EXPECT_EQ(io::lattice_neighbours(2, 2.1), 12.0);
  EXPECT_EQ(io::lattice_neighbours(3, 3.0), 122.0);
}

TEST(Scenes, TheMemoryLimitOverrideIsChecked) {
  ::setenv("POLYMECH_MEMORY_LIMIT", "2G", 1);
  EXPECT_DOUBLE_EQ(io::available_memory(), 2e9);
  ::setenv("POLYMECH_MEMORY_LIMIT", "lots", 1);
  EXPECT_THROW(io::available_memory(), std::invalid_argument);
  ::unsetenv("POLYMECH_MEMORY_LIMIT");
  EXPECT_GT(io::available_memory(), 0.0);
}

// [crop] (the accuracy-cost sweep's reduced crack case, `polymech plan`): the plate is cut to width x
// (depth + below) around the crack, the probes that fall outside are dropped, the run ends when the burst has
// passed the harmonics probe, and the cost counts the cropped plate; a crop with no crack is refused.
TEST(Scenes, CropCutsTheCrackCaseDown) {
  io::MpsSceneOptions o;
  o.accuracy = "draft";
  const auto full = io::load_mps_elastic_scene(source_dir() / "scenes/mps/crack_p_wave.toml", o);
  const auto crop = io::load_mps_elastic_scene(source_dir() / "scenes/mps/crack_p_wave_cropped.toml", o);
  EXPECT_DOUBLE_EQ(crop.config.width, 0.04);
  EXPECT_NEAR(crop.config.height, 0.022, 1e-15);
  EXPECT_NEAR(crop.config.crack.x1, 0.02, 1e-15);
  EXPECT_NEAR(crop.config.crack.x3, 0.012, 1e-15);
  ASSERT_EQ(crop.config.probes.size(), 2u);  // A and A_far keep their offsets from the crack
  EXPECT_EQ(crop.config.probes[0].name, "A");
  EXPECT_NEAR(crop.config.probes[0].x3, 0.0115, 1e-15);
  EXPECT_NEAR(crop.config.probes[1].x3, 0.0045, 1e-15);
  // the burst crosses 10.5 mm to A at c_p ~ 5.9 km/s (1.8 us), then 6 periods of 0.5 us: 4.8 us at dt 8 ns
  EXPECT_EQ(crop.config.steps, 594);
  EXPECT_LT(crop.cost.seconds, 0.5 * full.cost.seconds);
  polymech::testing::TempDir t;
  const std::string text = std::string(kBase) + "\n[crop]\nwidth = 0.003\ndepth = 0.001\nbelow = 0.001\n";
  try {
    io::load_mps_elastic_scene(t.write("scene.toml", text));
    FAIL() << "a crop without a crack loaded";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a [crack] to crop around"), std::string::npos) << e.what();
  }
}
