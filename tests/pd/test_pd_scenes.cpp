// Scenes of the NOSB model: the shipped ones load, and every bad scene stops with one message naming
// the file, the line, the key and what is allowed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>

#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/nosb_pd.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;

namespace {

// A small valid impact scene (draft: 2 mm spacing); tests edit one line of it.
const char* kBase = R"(title = "pd test scene"
[model]
kind = "nosb_pd"
dimension = 3
effects = ["velocity_viscosity", "damage", "contact"]

[discretization]
spacing = 2.0e-3
horizon_ratio = 3.0

[geometry]
shape = "disc"
radius = 0.020
thickness = 0.006

[material]
law = "johnson_cook"
density = 7850.0
youngs_modulus = 200.0e9
poisson_ratio = 0.33
[material.johnson_cook]
A = 490.0e6
B = 807.0e6
n = 0.73

[damage]
critical_stretch = 0.05

[stabilization]
c_v = 0.5
omega_v = 7.0e5

[loading]
kind = "impact"
clamp_radius = 0.014

[projectile]
shape = "blunt_cylinder"
radius = 0.005
length = 0.02
mass = 0.02
velocity = 300.0

[time]
end_time = 2.0e-5

[accuracy]
default = "paper"
)";

using polymech::testing::replace_once;

// Loads `text` as a PD scene and returns the error message (empty if it loaded).
std::string error_of(const std::string& text) {
  return polymech::testing::error_message(text, [](const fs::path& p) { io::load_nosb_pd_scene(p); });
}

// The PD loader refuses `text` naming "scene.toml:<line>:" and every fragment.
void expect_error(const std::string& text, int line, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_nosb_pd_scene(p); }, line, fragments);
}

}  // namespace

TEST(PdScenes, BaseSceneLoadsWithAStableTimeStep) {
  EXPECT_EQ(error_of(kBase), "");
}

TEST(PdScenes, ShippedScenesLoadAtEveryAccuracy) {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  const fs::path dir = (d ? fs::path(d) : fs::path(".")) / "scenes/pd";
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() != ".toml") continue;
    for (const char* acc : {"draft", "standard"}) {
      io::NosbPdSceneOptions o;
      o.accuracy = acc;
      const auto s = io::load_nosb_pd_scene(e.path(), o);
      EXPECT_GT(s.config.dt, 0.0) << e.path();
      EXPECT_LE(s.config.dt, s.stable_dt) << e.path();
    }
    ++n;
  }
  EXPECT_GE(n, 5);
}

TEST(PdScenes, BadValuesNameFileLineKeyAndWhatIsAllowed) {
  expect_error(replace_once(kBase, "spacing = 2.0e-3", "spacing = -2.0e-3"), 8, {"key 'discretization.spacing'", "must be in [1e-09, 100] m"});
  expect_error(replace_once(kBase, "horizon_ratio = 3.0", "horizon_ratio = 0.8"), 9, {"key 'discretization.horizon_ratio' = 0.8", "must be in [1, 8] spacings"});
  expect_error(replace_once(kBase, "horizon_ratio = 3.0", "horizon_ratio = 3.0\nhorizon = 3"), 10,
               {"unknown key 'discretization.horizon'", "horizon_ratio"});
  expect_error(replace_once(kBase, R"(effects = ["velocity_viscosity", "damage", "contact"])", R"(effects = ["viscosity", "damage", "contact"])"), 5,
               {"key 'model.effects'", "unknown effect 'viscosity'", "allowed: weighted_function, velocity_viscosity"});
  expect_error(replace_once(kBase, R"(effects = ["velocity_viscosity", "damage", "contact"])", R"(effects = ["velocity_viscosity", "damage"])"), 34,
               {"key 'loading.kind'", "needs the \"contact\" effect"});
  expect_error(replace_once(kBase, "omega_v = 7.0e5\n", ""), 29, {"stabilization.omega_v", "velocity_viscosity effect needs omega_v > 0"});
  expect_error(replace_once(kBase, "clamp_radius = 0.014", "clamp_radius = 0.03"), 35, {"key 'loading.clamp_radius' = 0.03", "0 < clamp_radius < geometry.radius = 0.02"});
  expect_error(replace_once(kBase, "critical_stretch = 0.05", "critical_stretch = 0.05\nenergy_release_rate = 1e5"), 26,
               {"[damage]", "exactly one of critical_stretch"});
  expect_error(replace_once(kBase, "end_time = 2.0e-5", "end_time = 2.0e-5\ndt = 1.0e-6"), 46, {"key 'time.dt' = 1e-06", "above the stability limit"});
  expect_error(replace_once(kBase, "[material.johnson_cook]\nA = 490.0e6\nB = 807.0e6\nn = 0.73\n", ""), 17,
               {"key 'material.law'", "needs a [material.johnson_cook] table"});
  expect_error(replace_once(kBase, R"(kind = "impact")", R"(kind = "drop")"), 34, {"key 'loading.kind' = \"drop\"", R"(allowed: "none", "tension", "impact")"});
}

TEST(PdScenes, MissingFileIsAClearError) {
  try {
    io::load_nosb_pd_scene("/nonexistent/pd.toml");
    FAIL() << "no error";
  } catch (const io::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/pd.toml: scene file not found"), std::string::npos) << e.what();
  }
}

// Issue 16: implausible values and runs too large for the memory are refused by the loader.
TEST(PdScenes, ImplausibleValuesAreRefusedWithTheirRange) {
  expect_error(replace_once(kBase, "horizon_ratio = 3.0", "horizon_ratio = 1e300"), 9,
               {"key 'discretization.horizon_ratio' = 1e+300 is out of range", "in [1, 8] spacings"});
  expect_error(replace_once(kBase, "youngs_modulus = 200.0e9", "youngs_modulus = 1e-300"), 19, {"key 'material.youngs_modulus'", "Pa"});
  expect_error(replace_once(kBase, "velocity = 300.0", "velocity = inf"), 42, {"key 'projectile.velocity' = inf", "20 km/s"});
  expect_error(replace_once(kBase, "end_time = 2.0e-5", "end_time = 1e300"), 45, {"key 'time.end_time' = 1e+300", "a plausible duration"});
  expect_error(replace_once(kBase, "density = 7850.0", "density = 0.01"), 18, {"key 'material.density' = 0.01", "P-wave speed"});
}

TEST(PdScenes, ARunLargerThanTheMemoryIsRefusedNamingItsSizeKeys) {
  ::setenv("POLYMECH_MEMORY_LIMIT", "1M", 1);
  expect_error(kBase, 7, {"[discretization]: the run needs about", "discretization.spacing = 0.002 m",
                          "discretization.horizon_ratio = 3", "geometry.radius = 0.02 m", "geometry.thickness = 0.006 m"});
  ::unsetenv("POLYMECH_MEMORY_LIMIT");
}

TEST(PdScenes, TheCostEstimateHasParticlesBondsAndSteps) {
  polymech::testing::TempDir t;
  const auto s = io::load_nosb_pd_scene(t.write("scene.toml", kBase));
  // what the model builds (issue 33 item 8: a full family per particle of the body's volume was 40 % off):
  // R / h = 10, 316 lattice points per layer, 3 layers; the families cut by the faces
  const polymech::nosb_pd::NosbPd<double, 3> built(s.config);
  EXPECT_EQ(s.cost.items, 948.0);
  EXPECT_EQ(s.cost.items, static_cast<double>(built.particles()));
  EXPECT_EQ(s.cost.pairs, static_cast<double>(built.bonds()));
  EXPECT_DOUBLE_EQ(s.cost.steps, std::ceil(s.end_time / s.config.dt));
  EXPECT_GT(s.cost.seconds, 0.0);
}
