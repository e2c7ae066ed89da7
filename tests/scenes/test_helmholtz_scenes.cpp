// Helmholtz scenes: the shipped ones load (tests/scenes/test_scenes.cpp), the Gmsh duct solves to the
// analytic pressure, and every bad scene stops with one message naming the file, the line, the key and
// what is allowed (including errors inside the .msh file the scene names).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "helmholtz/helmholtz.hpp"
#include "io/helmholtz_scene.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
namespace hz = polymech::helmholtz;

namespace {

fs::path source_dir() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return fs::absolute(d ? fs::path(d) : fs::path("."));
}

// A small valid duct scene; tests edit one line of it.
const char* kBase = R"(title = "test duct"
[model]
kind = "helmholtz"
effects = ["vibrating", "impedance"]

[discretization]
order = 2

[mesh]
kind = "box"
lengths = [1.0, 0.2, 0.1]
elements = [10, 2, 1]

[acoustics]
sound_speed = 343.0
frequency = 500.0
density = 1.3

[[boundary]]
names = ["xmin"]
kind = "vibrating"
velocity = 0.014

[[boundary]]
names = ["xmax"]
kind = "impedance"
impedance = 445.9

[analytic]
kind = "duct"
)";

using polymech::testing::replace_once;

// Loads `text` as scene.toml (with mesh.msh next to it if given) and checks the error.
void expect_error(const std::string& text, int line, const std::vector<std::string>& fragments,
                  const std::string& mesh_text = "", const io::HelmholtzSceneOptions& options = {}) {
  polymech::testing::TempDir dir;
  if (!mesh_text.empty()) dir.write("mesh.msh", mesh_text);
  std::string msg;
  try {
    io::load_helmholtz_scene(dir.write("scene.toml", text), options);
  } catch (const io::SceneError& e) {
    msg = e.what();
  }
  polymech::testing::expect_message(msg, "scene.toml", line, fragments);
}

}  // namespace

TEST(HelmholtzScenes, BaseSceneLoads) {
  polymech::testing::TempDir dir;
  const auto s = io::load_helmholtz_scene(dir.write("scene.toml", kBase));
  EXPECT_EQ(s.config.order, 2);
  EXPECT_EQ(s.config.mesh.element_count(), 20);
  EXPECT_EQ(s.config.boundaries.size(), 2u);
  EXPECT_TRUE(s.config.effects.has("impedance"));
  EXPECT_EQ(s.config.analytic.kind, hz::AnalyticKind::duct);
  EXPECT_DOUBLE_EQ(s.config.analytic.velocity, 0.014);
  EXPECT_DOUBLE_EQ(s.config.analytic.impedance, 445.9);
  EXPECT_DOUBLE_EQ(s.config.analytic.length, 1.0);
  EXPECT_EQ(s.header.accuracy, "paper");  // no [accuracy]: the counts as written
}

TEST(HelmholtzScenes, OrderOutOfRange) {
  expect_error(replace_once(kBase, "order = 2", "order = 0"), 7,
               {"key 'discretization.order' = 0 is out of range", "an integer in [1, 4]"});
  expect_error(replace_once(kBase, "order = 2", "order = 7"), 7, {"= 7 is out of range", "[1, 4]"});
  io::HelmholtzSceneOptions o;
  o.order = 5;
  expect_error(kBase, -1, {"order 5 is not supported; allowed: 1..4"}, "", o);
}

TEST(HelmholtzScenes, BadMeshSizes) {
  expect_error(replace_once(kBase, "lengths = [1.0, 0.2, 0.1]", "lengths = [-1.0, 0.2, 0.1]"), 11,
               {"key 'mesh.lengths'", "-1", "must be in [1e-06, 10000] m"});
  expect_error(replace_once(kBase, "elements = [10, 2, 1]", "elements = [10, 2.5, 1]"), 12,
               {"key 'mesh.elements'", "whole numbers"});
  expect_error(replace_once(kBase, "elements = [10, 2, 1]", "elements = [10, 2]"), 12, {"must have 3 entries"});
  expect_error(replace_once(kBase, "elements = [10, 2, 1]", "elements = [10, 2, 1]\nperturbation = 0.9"), 13,
               {"key 'mesh.perturbation' = 0.9 inverts element", "allowed: a perturbation that keeps every element valid"});
}

TEST(HelmholtzScenes, EffectsAndBoundariesMustAgree) {
  expect_error(replace_once(kBase, R"(effects = ["vibrating", "impedance"])", R"(effects = ["vibrating", "impedance", "gravity"])"),
               4, {"key 'model.effects'", "unknown effect 'gravity'", "allowed: dirichlet, impedance, vibrating"});
  expect_error(replace_once(kBase, R"(effects = ["vibrating", "impedance"])", R"(effects = ["vibrating"])"), 26,
               {"key 'boundary[1].kind' = \"impedance\" needs effect 'impedance' in model.effects"});
  expect_error(replace_once(kBase, R"(effects = ["vibrating", "impedance"])", R"(effects = ["vibrating", "impedance", "dirichlet"])"),
               4, {"lists effect 'dirichlet' but no [[boundary]] has kind = \"dirichlet\""});
}

TEST(HelmholtzScenes, BoundaryNamesAndValues) {
  expect_error(replace_once(kBase, R"(names = ["xmax"])", R"(names = ["outlet"])"), 25,
               {"key 'boundary[1].names' names boundary 'outlet', which the mesh does not have",
                "xmin, xmax, ymin, ymax, zmin, zmax"});
  expect_error(replace_once(kBase, R"(names = ["xmax"])", R"(names = ["xmin"])"), 25, {"a second time"});
  expect_error(replace_once(kBase, "impedance = 445.9", "impedance = -1.0"), 27,
               {"key 'boundary[1].impedance' = -1 is out of range: must be in [0.001, 1e+12]"});
  expect_error(replace_once(kBase, "impedance = 445.9\n", ""), 24, {"key 'boundary[1].impedance' is missing"});
  expect_error(replace_once(kBase, "velocity = 0.014", "velocity = 0.014\nimpedance = 3.0"), 23,
               {"unknown key 'boundary[0].impedance'", "kind, names, velocity"});
  expect_error(replace_once(kBase, R"(kind = "vibrating")", R"(kind = "absorbing")"), 21,
               {"key 'boundary[0].kind' = \"absorbing\"", R"("rigid", "dirichlet", "impedance", "vibrating")"});
}

TEST(HelmholtzScenes, UnknownKeysAndMissingTables) {
  expect_error(replace_once(kBase, "density = 1.3", "density = 1.3\nspeed = 3.0"), 18,
               {"unknown key 'acoustics.speed'", "density, frequency, sound_speed"});
  expect_error(replace_once(kBase, "[acoustics]\n", "[acoustic]\n"), 1, {"[acoustics] is missing"});
  expect_error(replace_once(kBase, "frequency = 500.0", "frequency = -500.0"), 16,
               {"key 'acoustics.frequency' = -500", "must be in [0.001, 1e+10] Hz"});
}

// [solver] preconditioner: jacobi, none, chebyshev, pmg (+ the shifted Laplacian's settings).
TEST(HelmholtzScenes, SolverPreconditioner) {
  const std::string solver = std::string(kBase) + "\n[solver]\npreconditioner = \"pmg\"\nshift = 0.5\nsmoothing_degree = 4\n";
  polymech::testing::TempDir dir;
  const auto s = io::load_helmholtz_scene(dir.write("scene.toml", solver));
  EXPECT_EQ(s.config.preconditioner, hz::Preconditioner::pmg);
  EXPECT_DOUBLE_EQ(s.config.shifted.shift, 0.5);
  EXPECT_EQ(s.config.shifted.smoothing_degree, 4);
  expect_error(replace_once(solver, R"(preconditioner = "pmg")", R"(preconditioner = "ilu")"), 33,
               {"key 'solver.preconditioner'", "jacobi", "none", "chebyshev", "pmg"});
  expect_error(replace_once(solver, "shift = 0.5", "shift = 0.0"), 34, {"key 'solver.shift'", "(0, 100)"});
  expect_error(replace_once(solver, "smoothing_degree = 4", "smoothing_degree = 0"), 35,
               {"key 'solver.smoothing_degree'", "[1, 50]"});
}

TEST(HelmholtzScenes, GmshMeshErrorsNameBothFiles) {
  const std::string gmsh = replace_once(replace_once(kBase, "kind = \"box\"\nlengths = [1.0, 0.2, 0.1]\nelements = [10, 2, 1]",
                                           "kind = \"gmsh\"\nfile = \"mesh.msh\""),
                                   "[analytic]", "[accuracy]\ndefault = \"draft\"\n\n[analytic]");
  expect_error(gmsh, 28, {"accuracy presets scale box meshes"});
  const std::string plain = replace_once(kBase, "kind = \"box\"\nlengths = [1.0, 0.2, 0.1]\nelements = [10, 2, 1]",
                                    "kind = \"gmsh\"\nfile = \"mesh.msh\"");
  expect_error(plain, 11, {"key 'mesh.file' = \"mesh.msh\": no such file"});
  expect_error(plain, 11, {"key 'mesh.file' = \"mesh.msh\" cannot be used", "mesh.msh:2: MSH version 2.2 is not supported"},
               "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n");
  io::HelmholtzSceneOptions o;
  o.accuracy = "draft";
  expect_error(plain, -1, {"presets scale box meshes and this scene reads a Gmsh mesh"},
               "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", o);
}

// The shipped unstructured Gmsh duct (coarsest mesh, order 2) against eq. (29).
TEST(HelmholtzScenes, GmshDuctSolvesToTheAnalyticPressure) {
  const fs::path scene = source_dir() / "scenes/helmholtz/duct_gmsh.toml";
  std::ifstream in(scene);
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string text = buffer.str();
  text = replace_once(text, "meshes/duct_lc050.msh", (source_dir() / "scenes/helmholtz/meshes/duct_lc100.msh").string());
  polymech::testing::TempDir dir;
  io::HelmholtzSceneOptions o;
  o.order = 2;
  const auto s = io::load_helmholtz_scene(dir.write("scene.toml", text), o);
  EXPECT_EQ(s.config.mesh.element_count(), 23);
  hz::Helmholtz<double> model(s.config);
  const auto r = model.solve();
  EXPECT_TRUE(r.converged()) << r.reason;
  EXPECT_LT(model.l2_error().relative(), 1e-2);  // 4.9e-3 on 23 unstructured hexahedra
}

// Issue 16: implausible values, profiles outside the mesh and corrupted meshes are refused by the loader.
TEST(HelmholtzScenes, ImplausibleValuesAreRefusedWithTheirRange) {
  expect_error(replace_once(kBase, "frequency = 500.0", "frequency = 1e300"), 16,
               {"key 'acoustics.frequency' = 1e+300 is out of range", "Hz"});
  expect_error(replace_once(kBase, "lengths = [1.0, 0.2, 0.1]", "lengths = [1e300, 1, 1]"), 11,
               {"key 'mesh.lengths' has the element 1e+300", "m (a plausible size"});
  expect_error(replace_once(kBase, "sound_speed = 343.0", "sound_speed = 1e-300"), 15, {"key 'acoustics.sound_speed'", "m/s"});
  expect_error(replace_once(kBase, "impedance = 445.9", "impedance = inf"), 27, {"key 'boundary[1].impedance' = inf"});
}

TEST(HelmholtzScenes, ProfilesOutsideTheMeshOrOfZeroLengthAreRefused) {
  const std::string with_profile = std::string(kBase) + "\n[output]\nprofile_from = [0.0, 0.1, 0.05]\nprofile_to = [1.0, 0.1, 0.05]\n";
  expect_error(replace_once(with_profile, "profile_to = [1.0, 0.1, 0.05]", "profile_to = [2.0, 0.1, 0.05]"), 34,
               {"key 'output.profile_to' = (2, 0.1, 0.05) is outside the mesh", "bounding box (0, 0, 0) .. (1, 0.2, 0.1)"});
  expect_error(replace_once(with_profile, "profile_from = [0.0, 0.1, 0.05]", "profile_from = [0.0, -0.1, 0.05]"), 33,
               {"key 'output.profile_from'", "outside the mesh"});
  expect_error(replace_once(with_profile, "profile_to = [1.0, 0.1, 0.05]", "profile_to = [0.0, 0.1, 0.05]"), 34,
               {"key 'output.profile_to'", "the same point as profile_from", "length > 0"});
  polymech::testing::TempDir dir;
  EXPECT_TRUE(io::load_helmholtz_scene(dir.write("scene.toml", with_profile)).has_profile);
}

TEST(HelmholtzScenes, ARunLargerThanTheMemoryIsRefusedNamingItsSizeKeys) {
  ::setenv("POLYMECH_MEMORY_LIMIT", "10K", 1);
  expect_error(kBase, 9, {"[mesh]: the run needs about", "mesh.elements = [10, 2, 1]", "discretization.order = 2"});
  ::unsetenv("POLYMECH_MEMORY_LIMIT");
  // 1e15 elements are refused before any mesh is built
  expect_error(replace_once(kBase, "elements = [10, 2, 1]", "elements = [100000, 100000, 100000]"), 9,
               {"[mesh]: the run would have", "DoFs, more than"});
}

TEST(HelmholtzScenes, EmptyMeshFileAndCorruptedMeshesAreRefused) {
  const std::string plain = replace_once(kBase, "kind = \"box\"\nlengths = [1.0, 0.2, 0.1]\nelements = [10, 2, 1]",
                                         "kind = \"gmsh\"\nfile = \"mesh.msh\"");
  expect_error(replace_once(plain, "file = \"mesh.msh\"", "file = \"\""), 11, {"key 'mesh.file' is empty"});
  const std::string head = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  expect_error(plain, 11, {"key 'mesh.file'", "mesh.msh:5: numNodes = -3 is out of range"}, head + "$Nodes\n1 -3 1 3\n");
  expect_error(plain, 11, {"mesh.msh:6: numNodesInBlock = 1000000 is out of range; allowed: 0 .. 2"},
               head + "$Nodes\n1 2 1 2\n3 1 0 1000000\n");
  expect_error(plain, 11, {"mesh.msh:8: 'nan' is not a finite number (node coordinates x y z)"},
               head + "$Nodes\n1 1 1 1\n3 1 0 1\n1\nnan 0 0\n$EndNodes\n");
  expect_error(plain, 11, {"mesh.msh:6: unexpected end of file in a node tag"}, head + "$Nodes\n1 2 1 2\n3 1 0 2\n");
  expect_error(plain, 11, {"mesh.msh:4: a second $MeshFormat section"}, head + head);
}
