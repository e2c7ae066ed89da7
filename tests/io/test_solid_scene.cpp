// Solid scenes (io/solid_scene.hpp, issue 34): the shipped scenes/solid/*.toml load; the mesh size the loader
// counts in closed form for the cost estimate equals the model's lattice; the accuracy presets scale every cell
// size; every bad value is refused naming file:line, the key and what is allowed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/registry.hpp"
#include "io/solid_scene.hpp"
#include "solid/micro_cantilever.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
namespace so = polymech::solid;
using polymech::testing::line_of;
using polymech::testing::replace_once;

namespace {

const std::string kBase = R"(title = "micro-cantilever"

[model]
kind = "solid"
effects = ["plasticity"]

[crystal]
C11 = 401.0
C12 = 96.0
C44 = 56.0
yield_stress = 3.0
hardening_exponent = 0.1
R12 = 0.9

[beam]
length = 12.0
width = 2.5
height = 1.5
wall = 0.75
support_length = 6.0
support_width = 20.0
support_depth = 12.0
angles = [0.0, 54.7]
peak_force = 0.25

[mesh]
order = 2
h_root = 0.2

[load]
load_increments = 8
unload_increments = 4

[newton]
tolerance = 1e-8

[inverse]
noise = 0.005
experiment_h_root = 0.15

[inverse.start]
C11 = 320.0
C12 = 120.0
C44 = 70.0
yield_stress = 2.3
hardening_exponent = 0.13
R12 = 1.15

[accuracy]
default = "paper"
)";

fs::path source_dir() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return d ? fs::path(d) : fs::path(".");
}

io::SolidScene load(const std::string& text, const std::string& accuracy = "") {
  polymech::testing::TempDir dir;
  io::SceneOptions o;
  o.accuracy = accuracy;
  return io::load_solid_scene(dir.write("scene.toml", text), o);
}

// The loader refuses `text`, naming the line of `at` and every fragment.
void expect_error(const std::string& text, const std::string& at, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_solid_scene(p); }, line_of(text, at), fragments);
}
void expect_edit_error(const std::string& from, const std::string& to, const std::vector<std::string>& fragments) {
  const std::string text = replace_once(kBase, from, to);
  expect_error(text, to.substr(to.rfind('\n') + 1), fragments);  // the error names the edit's last line
}

}  // namespace

TEST(SolidScenes, ShippedScenesLoad) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(source_dir() / "scenes" / "solid")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    EXPECT_EQ(io::scene_kind_of(e.path()).kind, "solid");
    if (e.path().stem() == "cook_membrane") continue;  // CookScenes.* below
    EXPECT_EQ(io::scene_kind_of(e.path()).app_for(e.path()), "micro_cantilever");
    const auto s = io::load_solid_scene(e.path());
    EXPECT_TRUE(s.plasticity);
    EXPECT_EQ(s.beam.angles.size(), 6u);
    EXPECT_DOUBLE_EQ(s.crystal.C11, 401.0);
    EXPECT_GT(s.size.dofs, 1000.0);
    EXPECT_GT(s.cost.seconds, 0.0);
    ++n;
  }
  EXPECT_GE(n, 2);
  const auto inv = io::load_solid_scene(source_dir() / "scenes" / "solid" / "micro_cantilever_inverse.toml");
  ASSERT_TRUE(inv.inverse.has_value());
  EXPECT_LT(inv.inverse->experiment_h_root, inv.mesh.h_root);
  EXPECT_GT(inv.inverse_cost.seconds, inv.cost.seconds);
}

TEST(SolidScenes, BaseLoadsWithItsValuesAndDefaults) {
  const auto s = load(kBase);
  EXPECT_EQ(s.header.kind, "solid");
  EXPECT_EQ(s.header.accuracy, "paper");
  EXPECT_EQ(s.header.precision, "double");
  EXPECT_DOUBLE_EQ(s.mesh.h_root, 0.2);
  EXPECT_DOUBLE_EQ(s.mesh.growth, 1.2);  // defaults
  EXPECT_EQ(s.newton.solver, "two_level_pcg");
  EXPECT_EQ(s.crystal.hill_form, "yield_stress_ratio");
  ASSERT_TRUE(s.inverse.has_value());
  EXPECT_DOUBLE_EQ(s.inverse->start.C11, 320.0);
  EXPECT_EQ(s.inverse->seed, 1u);
  EXPECT_DOUBLE_EQ(s.inverse->model_accuracy, 1e-8);  // newton.tolerance
  // no angles: the paper's six; no plasticity: an elastic beam, no plastic keys
  const auto six = load(replace_once(kBase, "angles = [0.0, 54.7]\n", ""));
  EXPECT_EQ(six.beam.angles.size(), 6u);
  EXPECT_NEAR(six.beam.angles.back(), 54.7356103172453, 1e-12);
  std::string elastic = replace_once(kBase, "effects = [\"plasticity\"]", "effects = []");
  elastic = replace_once(elastic, "yield_stress = 3.0\nhardening_exponent = 0.1\nR12 = 0.9\n", "");
  elastic = elastic.substr(0, elastic.find("[inverse]")) + "[accuracy]\ndefault = \"paper\"\n";
  const auto e = load(elastic);
  EXPECT_FALSE(e.plasticity);
  EXPECT_FALSE(e.inverse.has_value());
}

// The closed-form count of the loader against the model's own lattice and discretization.
TEST(SolidScenes, MeshSizeEqualsTheModelsLattice) {
  struct Case {
    double h;
    int order;
    double support_length;
  };
  for (const Case c : {Case{0.8, 2, 6.0}, Case{0.5, 1, 6.0}, Case{0.4, 2, 3.0}, Case{0.75, 1, 0.0}, Case{0.3, 3, 0.0}}) {
    io::SolidBeam b;
    b.support_length = c.support_length;
    io::SolidMesh m;
    m.order = c.order;
    m.h_root = c.h;
    const io::SolidMeshSize size = io::solid_mesh_size(b, m);
    so::MicroCantileverSpec s;
    s.support_length = c.support_length;
    s.order = c.order;
    s.h_root = c.h;
    const auto mesh = so::make_micro_cantilever_mesh(s);
    const auto d = so::discretize(mesh, c.order, 1);
    std::printf("h_root %.2f, order %d, block %.0f: %.0f cells, %.0f nodes (model: %lld, %lld)\n", c.h, c.order,
                c.support_length, size.cells, size.nodes, static_cast<long long>(mesh.active_cell_count()),
                static_cast<long long>(d.nodes));
    EXPECT_EQ(static_cast<long long>(size.cells), mesh.active_cell_count());
    EXPECT_EQ(static_cast<long long>(size.nodes), d.nodes);
  }
}

TEST(SolidScenes, AccuracyPresetsScaleEveryCellSize) {
  const auto paper = load(kBase);
  const auto draft = load(kBase, "draft");
  const auto standard = load(kBase, "standard");
  EXPECT_DOUBLE_EQ(draft.mesh.h_root, 4 * paper.mesh.h_root);
  EXPECT_DOUBLE_EQ(standard.mesh.h_root, 2 * paper.mesh.h_root);
  EXPECT_DOUBLE_EQ(draft.mesh.h_support_max, 4 * paper.mesh.h_support_max);
  EXPECT_DOUBLE_EQ(draft.inverse->experiment_h_root, 4 * paper.inverse->experiment_h_root);
  EXPECT_LT(draft.size.dofs, standard.size.dofs);
  EXPECT_LT(standard.size.dofs, paper.size.dofs);
  EXPECT_LT(draft.cost.seconds, paper.cost.seconds);
  // 0.4 x 4 = 1.6 um is not below the beam's height: refused naming the preset
  polymech::testing::expect_load_error(
      replace_once(kBase, "h_root = 0.2", "h_root = 0.4"),
      [](const fs::path& p) { io::load_solid_scene(p, io::SceneOptions{"draft", ""}); }, line_of(kBase, "h_root = 0.2"),
      {"key 'mesh.h_root'", "preset 'draft' (x4) = 1.6 um", "must be < beam.height = 1.5 um"});
}

TEST(SolidScenes, BadGeometryIsRefusedWithTheKeyAndTheRange) {
  expect_edit_error("length = 12.0", "length = -12.0", {"key 'beam.length' = -12 is out of range", "must be in (0, 10000] um"});
  expect_edit_error("width = 2.5", "width = 0", {"key 'beam.width' = 0 is out of range"});
  expect_edit_error("wall = 0.75", "wall = 1.6", {"key 'beam.wall' = 1.6", "must be in (0, beam.height = 1.5 um]"});
  expect_edit_error("support_width = 20.0", "support_width = 2.0", {"key 'beam.support_width' = 2", "> beam.width = 2.5 um"});
  expect_edit_error("support_depth = 12.0", "support_depth = 1.0", {"key 'beam.support_depth' = 1", "> beam.height = 1.5 um"});
  expect_edit_error("angles = [0.0, 54.7]", "angles = [0.0, 95.0]", {"key 'beam.angles", "95", "[0, 90] degrees"});
  expect_edit_error("angles = [0.0, 54.7]", "angles = []", {"key 'beam.angles' is empty"});
  expect_edit_error("peak_force = 0.25", "peak_force = 0.0", {"key 'beam.peak_force' = 0 is out of range", "mN"});
  expect_edit_error("peak_force = 0.25", "peak_force = -1", {"key 'beam.peak_force'"});
}

TEST(SolidScenes, BadMeshLoadAndNewtonValuesAreRefused) {
  expect_edit_error("order = 2", "order = 5", {"key 'mesh.order'", "1", "4"});
  expect_edit_error("order = 2", "order = 0", {"key 'mesh.order'"});
  expect_edit_error("h_root = 0.2", "h_root = 1.5", {"key 'mesh.h_root' = 1.5", "must be < beam.height = 1.5 um"});
  expect_edit_error("h_root = 0.2", "h_root = -0.2", {"key 'mesh.h_root' = -0.2 is out of range"});
  expect_edit_error("h_root = 0.2", "h_root = 0.2\nh_beam_max = 0.1", {"key 'mesh.h_beam_max' = 0.1", ">= mesh.h_root"});
  expect_edit_error("h_root = 0.2", "h_root = 0.2\ngrowth = 0.9", {"key 'mesh.growth' = 0.9", "[1, 10]"});
  expect_edit_error("load_increments = 8", "load_increments = 0", {"key 'load.load_increments'"});
  expect_edit_error("unload_increments = 4", "unload_increments = -1", {"key 'load.unload_increments'"});
  expect_edit_error("tolerance = 1e-8", "tolerance = 0.5", {"key 'newton.tolerance' = 0.5", "[1e-14, 0.01]"});
  expect_edit_error("tolerance = 1e-8", "solver = \"cholesky\"", {"key 'newton.solver'", "elastic_pcg", "direct"});
}

TEST(SolidScenes, BadCrystalValuesAreRefused) {
  expect_edit_error("hardening_exponent = 0.1", "hardening_exponent = 1.0", {"key 'crystal.hardening_exponent' = 1", "[0, 1)"});
  expect_edit_error("R12 = 0.9", "R12 = 0.0", {"key 'crystal.R12' = 0 is out of range", "(0, 100]"});
  expect_edit_error("yield_stress = 3.0", "yield_stress = 0", {"key 'crystal.yield_stress' = 0", "GPa"});
  // not positive definite: each of the three conditions
  expect_edit_error("C12 = 96.0", "C12 = 450.0", {"key 'crystal.C12' = 450", "not a positive definite cubic stiffness", "C11 > |C12|"});
  expect_edit_error("C12 = 96.0", "C12 = -250.0", {"key 'crystal.C12' = -250", "C11 + 2 C12 > 0"});
  expect_edit_error("C44 = 56.0", "C44 = 0.0", {"key 'crystal.C44' = 0", "C44 > 0"});
  expect_edit_error("hardening_exponent = 0.1", "hardening_exponent = 0.1\nhill_form = \"printed\"",
                    {"key 'crystal.hill_form'", "yield_stress_ratio", "as_printed"});
  // plastic values without the effect
  const std::string elastic = replace_once(kBase, "effects = [\"plasticity\"]", "effects = []");
  expect_error(elastic, "yield_stress = 3.0", {"key 'crystal.yield_stress'", "needs the effect \"plasticity\""});
}

TEST(SolidScenes, UnknownKeysAndEffectsAreRefused) {
  expect_edit_error("peak_force = 0.25", "peak_force = 0.25\npeak_froce = 0.3", {"unknown key 'beam.peak_froce'", "allowed in [beam]", "peak_force"});
  expect_edit_error("C44 = 56.0", "C44 = 56.0\nC66 = 10.0", {"unknown key 'crystal.C66'"});
  expect_edit_error("effects = [\"plasticity\"]", "effects = [\"damage\"]", {"unknown effect 'damage'", "allowed: plasticity"});
  expect_edit_error("[load]", "[loads]", {"unknown key 'loads'"});
}

TEST(SolidScenes, BadInverseTablesAreRefused) {
  expect_edit_error("noise = 0.005", "noise = 0.0", {"key 'inverse.noise' = 0 is out of range", "um"});
  expect_edit_error("experiment_h_root = 0.15", "experiment_h_root = 0.3", {"key 'inverse.experiment_h_root' = 0.3", "<= mesh.h_root = 0.2 um"});
  // the start and the truth inside the estimator's bounds
  const std::string start_c11 = "[inverse.start]\nC11 = 320.0";
  expect_edit_error(start_c11, "[inverse.start]\nC11 = 2500.0", {"key 'inverse.start.C11' = 2500", "estimator's start", "[50, 2000]"});
  expect_edit_error("R12 = 1.15", "R12 = 9.0", {"key 'inverse.start.R12' = 9", "[0.2, 5]"});
  expect_edit_error("R12 = 0.9", "R12 = 7.0", {"key 'crystal.R12' = 7", "hidden truth", "[0.2, 5]"});
  expect_edit_error("C44 = 70.0", "C44 = 70.0\nC66 = 3.0", {"unknown key 'inverse.start.C66'"});
  // a start missing a parameter (located at its table)
  expect_error(replace_once(kBase, "yield_stress = 2.3", "yield_stres = 2.3"), "[inverse.start]",
               {"key 'inverse.start.yield_stress' is missing"});
  // the study needs the plastic law and the estimator's Hill form
  std::string elastic = replace_once(kBase, "effects = [\"plasticity\"]", "effects = []");
  elastic = replace_once(elastic, "yield_stress = 3.0\nhardening_exponent = 0.1\nR12 = 0.9\n", "");
  expect_error(elastic, "[inverse]\n", {"[inverse]: needs the effect \"plasticity\""});
  expect_edit_error("R12 = 0.9", "R12 = 0.9\nhill_form = \"as_printed\"", {"key 'crystal.hill_form'", "estimator uses \"yield_stress_ratio\""});
}

// Cook's membrane (apps/cook_membrane): the shipped scene goes to its app, the presets divide the cells, and
// the loader refuses plasticity, nu = 0.5 and a tolerance for the direct solve naming the line and key.
TEST(CookScenes, ShippedSceneLoadsWithItsPresets) {
  const fs::path f = source_dir() / "scenes" / "solid" / "cook_membrane.toml";
  EXPECT_EQ(io::scene_kind_of(f).app_for(f), "cook_membrane");
  const int cells[3] = {16, 32, 64};
  const char* presets[3] = {"draft", "standard", "paper"};
  for (int k = 0; k < 3; ++k) {
    io::SceneOptions o;
    o.accuracy = presets[k];
    const auto s = io::load_cook_scene(f, o);
    EXPECT_EQ(s.cells, cells[k]);
    EXPECT_EQ(s.order, 2);
    EXPECT_EQ(s.plane, "stress");
    EXPECT_DOUBLE_EQ(s.traction, 6250.0);
    EXPECT_DOUBLE_EQ(s.cost.items, 2.0 * (2.0 * cells[k] + 1.0) * (2.0 * cells[k] + 1.0));
    EXPECT_GT(s.cost.seconds, 0.0);
  }
}

TEST(CookScenes, RefusesWhatItCannotRun) {
  const std::string base = R"(title = "cook"

[model]
kind = "solid"
effects = []

[case]
test = "cook_membrane"

[material]
poisson_ratio = 0.3

[load]
shear_traction = 1.0

[mesh]
cells = 4

[solver]
kind = "direct"
)";
  const auto refused = [](const std::string& text, const std::string& at, const std::vector<std::string>& fragments) {
    polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_cook_scene(p); }, line_of(text, at), fragments);
  };
  refused(replace_once(base, "poisson_ratio = 0.3", "poisson_ratio = 0.5"), "poisson_ratio = 0.5", {"poisson_ratio", "0.5"});
  refused(replace_once(base, "effects = []", "effects = [\"plasticity\"]"), "effects = [\"plasticity\"]", {"effects", "linear elastic"});
  refused(replace_once(base, "kind = \"direct\"", "kind = \"direct\"\ntolerance = 1e-8"), "tolerance = 1e-8", {"tolerance", "cg"});
  refused(replace_once(base, "shear_traction = 1.0", "shear_traction = 0.0"), "shear_traction = 0.0", {"shear_traction", "non-zero"});
}
