// ISPH scenes: every shipped scenes/isph/*.toml loads; bad scenes are refused naming file:line and key.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/isph_scene.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
using polymech::testing::line_of;
using polymech::testing::replace_once;

namespace {

const std::string kBase = R"(title = "tank"

[model]
kind = "isph"
effects = ["viscosity", "stabilization"]

[fluid]
density = 1000.0
spacing = 0.01

[tank]
case = "dam_break"
width = 0.4
height = 0.3
water_width = 0.1
water_height = 0.2

[time]
dt = 5e-4
end_time = 0.1
)";

void expect_error(const std::string& text, const std::string& at, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_isph_scene(p); }, line_of(text, at),
                                       fragments);
}

}  // namespace

TEST(IsphScenes, EveryShippedSceneLoads) {
  const char* src = std::getenv("POLYMECH_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(src) / "scenes" / "isph")) {
    if (e.path().extension() != ".toml") continue;
    const auto s = io::load_isph_scene(e.path());
    EXPECT_GT(s.steps, 0) << e.path();
    EXPECT_LE(s.config.dt, s.limit.limit) << e.path();
    EXPECT_GT(s.cost.items, 0.0);
    ++n;
  }
  EXPECT_GE(n, 3);
}

TEST(IsphScenes, BaseLoads) {
  polymech::testing::TempDir dir;
  const auto s = io::load_isph_scene(dir.write("scene.toml", kBase));
  EXPECT_EQ(s.case_name, "dam_break");
  EXPECT_EQ(s.steps, 200);
  EXPECT_EQ(s.cost.items, 200.0);
  // without the keys, the paper's forms (eqs. (9), (19) and (23)); the others only when asked for
  EXPECT_EQ(s.config.pressure_gradient, polymech::isph::PressureGradient::symmetric);
  EXPECT_EQ(s.config.ghost_interpolation, polymech::isph::GhostInterpolation::shepard);
  const auto o = io::load_isph_scene(dir.write(
      "options.toml", replace_once(kBase, "[model]", "[model]\npressure_gradient = \"difference\"\nghost_interpolation = \"linear\"")));
  EXPECT_EQ(o.config.pressure_gradient, polymech::isph::PressureGradient::difference);
  EXPECT_EQ(o.config.ghost_interpolation, polymech::isph::GhostInterpolation::linear);
  EXPECT_EQ(s.config.surface_detection, polymech::isph::SurfaceDetection::density);
  const auto d = io::load_isph_scene(dir.write("divr.toml", replace_once(kBase, "[fluid]", "[fluid]\nsurface_detection = \"divergence\"")));
  EXPECT_EQ(d.config.surface_detection, polymech::isph::SurfaceDetection::divergence);
}

TEST(IsphScenes, BadValuesAreRefused) {
  expect_error(replace_once(kBase, "[model]", "[model]\npressure_gradient = \"sum\""), "pressure_gradient",
               {"model.pressure_gradient", "symmetric", "difference"});
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nsurface_detection = \"curvature\""), "surface_detection",
               {"fluid.surface_detection", "density", "divergence"});
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nsurface_divergence = 7.0"), "surface_divergence",
               {"fluid.surface_divergence"});
  expect_error(replace_once(kBase, "dt = 5e-4", "dt = 5e-3"), "dt = 5e-3", {"time.dt", "above the limit"});
  expect_error(replace_once(kBase, "water_width = 0.1", "water_width = 0.5"), "water_width = 0.5",
               {"tank.water_width", "larger than the tank"});
  expect_error(replace_once(kBase, "water_width = 0.1", "water_width = 0.4"), "water_width = 0.4",
               {"tank.water_width", "dam break"});
  expect_error(replace_once(kBase, "spacing = 0.01", "spacing = 1e300"), "spacing = 1e300", {"fluid.spacing"});
  expect_error(replace_once(kBase, "effects = [\"viscosity\", \"stabilization\"]", "effects = [\"rigid_body\"]"),
               "effects = [\"rigid_body\"]", {"rigid_body", "[body]"});
  expect_error(replace_once(kBase, "case = \"dam_break\"", "case = \"sloshing\""), "case = \"sloshing\"",
               {"tank.case", "hydrostatic"});
  // the PPE options of 2026-11-24
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nppe_operator = \"assembled\""), "ppe_operator",
               {"fluid.ppe_operator", "stored", "matrix_free"});
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nppe_preconditioner = \"ilu\""), "ppe_preconditioner",
               {"fluid.ppe_preconditioner", "jacobi", "two_level"});
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nppe_operator = \"matrix_free\"\nppe_preconditioner = \"two_level\""),
               "ppe_preconditioner", {"fluid.ppe_preconditioner", "stored", "jacobi"});
  expect_error(replace_once(kBase, "[fluid]", "[fluid]\nppe_coarse_cell = 0.5"), "ppe_coarse_cell", {"fluid.ppe_coarse_cell"});
}
