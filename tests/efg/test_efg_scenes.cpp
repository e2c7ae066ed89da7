// EFG scenes: the shipped scenes/efg/*.toml load with the handbook factor of their plate; bad scenes are
// refused naming file:line and key (a contour leaving the plate, h_max below h_min, an unknown precision).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "io/efg_scene.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
using polymech::testing::line_of;
using polymech::testing::replace_once;

namespace {

const std::string kBase = R"(title = "edge crack"

[model]
kind = "efg"
effects = []

[plate]
crack = "edge"
width = 1.0
height = 3.0
crack_length = 0.5

[material]
youngs_modulus = 1.0e9
poisson_ratio = 0.3
density = 1000.0

[loading]
stress = 1.0e6

[discretization]
h_min = 0.0125
h_max = 0.05
gauss = 4

[j_integral]
radii = [0.2, 0.3]
)";

void expect_error(const std::string& text, const std::string& at, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_efg_scene(p); }, line_of(text, at), fragments);
}

}  // namespace

TEST(EfgScenes, EveryShippedSceneLoads) {
  const char* src = std::getenv("POLYMECH_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(src) / "scenes" / "efg")) {
    if (e.path().extension() != ".toml") continue;
    const auto s = io::load_efg_scene(e.path());
    EXPECT_GT(s.handbook, 1.0) << e.path();
    EXPECT_GT(s.cost.items, 100.0) << e.path();
    // the cost estimate counts the nodes the layout places, and names the method that runs
    EXPECT_EQ(s.cost.items, static_cast<double>(polymech::efg::make_layout(s.config).node_count())) << e.path();
    if (s.dynamic) {
      EXPECT_NE(s.cost.method.find("Newmark"), std::string::npos) << e.path();
      EXPECT_EQ(s.cost.steps, std::ceil(s.duration / s.dt - 1e-9)) << e.path();
    } else {
      EXPECT_NE(s.cost.method.find("static"), std::string::npos) << e.path();
    }
    ++n;
  }
  EXPECT_GE(n, 2);
}

// The running-crack keys of Model 4's scene: path nodes and their release load; a release that is not
// one of the two is refused at its line.
TEST(EfgScenes, PathNodeKeys) {
  const char* src = std::getenv("POLYMECH_SOURCE_DIR");
  ASSERT_NE(src, nullptr);
  std::ifstream in(fs::path(src) / "scenes" / "efg" / "chen_centre_crack_running.toml");
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  ASSERT_NE(text.find("path_nodes = true"), std::string::npos);
  polymech::testing::TempDir dir;
  const auto s = io::load_efg_scene(dir.write("running.toml", text));
  EXPECT_TRUE(s.config.path_nodes);
  EXPECT_FALSE(s.config.path_release_gradual);
  const auto g = io::load_efg_scene(
      dir.write("gradual.toml", replace_once(text, "path_nodes = true", "path_nodes = true\npath_release = \"gradual\"")));
  EXPECT_TRUE(g.config.path_release_gradual);
  expect_error(replace_once(text, "path_nodes = true", "path_nodes = true\npath_release = \"slow\""), "path_release = \"slow\"",
               {"dynamic.path_release", "sudden", "gradual"});
}

TEST(EfgScenes, BaseLoadsWithTadasFactor) {
  polymech::testing::TempDir dir;
  const auto s = io::load_efg_scene(dir.write("scene.toml", kBase));
  EXPECT_NEAR(s.handbook, 1.12 - 0.231 * 0.5 + 10.55 * 0.25 - 21.72 * 0.125 + 30.39 * 0.0625, 1e-12);
  EXPECT_TRUE(s.config.plane_strain);
  EXPECT_EQ(s.config.j_radii.size(), 2u);
  // draft coarsens the spacing x4
  // float (the shape functions and the stiffness kernel in float, the solve in double) is offered
  EXPECT_EQ(io::load_efg_scene(dir.write("float.toml", kBase), {"", "float"}).header.precision, "float");
  const auto d = io::load_efg_scene(dir.write("scene.toml", kBase), {"draft", ""});
  EXPECT_NEAR(d.config.h_min, 4 * s.config.h_min, 1e-15);
}

TEST(EfgScenes, BadScenesAreRefusedAtTheirKey) {
  expect_error(replace_once(kBase, "radii = [0.2, 0.3]", "radii = [0.2, 0.6]"), "radii = [0.2, 0.6]",
               {"j_integral.radii", "inside the plate"});
  expect_error(replace_once(kBase, "h_max = 0.05", "h_max = 0.01"), "h_max = 0.01", {"discretization.h_max", "h_min"});
  expect_error(replace_once(kBase, "crack_length = 0.5", "crack_length = 0.9"), "crack_length = 0.9", {"plate.crack_length"});
  expect_error(replace_once(kBase, "effects = []", "effects = []\nprecision = \"half\""), "precision = \"half\"",
               {"model.precision", "double"});
  expect_error(replace_once(kBase, "stress = 1.0e6", "stress = nan"), "stress = nan", {"loading.stress"});
}

// The J-integral band (j_integral.band, x the local node spacing): loads, and is refused where the band
// of a path would reach the tip or leave the plate, or out of its range.
TEST(EfgScenes, JIntegralBand) {
  polymech::testing::TempDir dir;
  const std::string banded = replace_once(kBase, "radii = [0.2, 0.3]", "radii = [0.2, 0.3]\nband = 1.0");
  const auto s = io::load_efg_scene(dir.write("scene.toml", banded));
  EXPECT_EQ(s.config.j_band, 1.0);
  EXPECT_EQ(io::load_efg_scene(dir.write("scene.toml", kBase)).config.j_band, 0.0);
  // h(0.005) = 0.0125 + 0.25 x 0.005: the band's half-width 0.0069 > 0.005
  expect_error(replace_once(banded, "radii = [0.2, 0.3]", "radii = [0.005, 0.3]"), "band = 1.0", {"j_integral.band", "reaches the tip"});
  // h(0.49) = h_max = 0.05: the band reaches 0.515, past the room of 0.5
  expect_error(replace_once(banded, "radii = [0.2, 0.3]", "radii = [0.2, 0.49]"), "radii = [0.2, 0.49]", {"j_integral.radii", "band to"});
  expect_error(replace_once(banded, "band = 1.0", "band = 5.0"), "band = 5.0", {"j_integral.band"});
}
