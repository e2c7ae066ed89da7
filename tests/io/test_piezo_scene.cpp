// Piezoelectric harvester scenes (io/piezo_scene.hpp, issue 35): the shipped scenes/piezo/*.toml load through the
// registry; the accuracy presets divide the cell counts (not the time step); the loader's closed-form unknown count
// against the FE beam's; the laminated bender's closed form (models/piezo/harvester_case.hpp) against the bimorph
// formulas of analytic.hpp; and every bad value refused naming file:line, the key and what is allowed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "io/piezo_scene.hpp"
#include "io/registry.hpp"
#include "piezo/harvester_case.hpp"
#include "support/error_messages.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;
namespace pz = polymech::piezo;
using polymech::testing::line_of;
using polymech::testing::replace_once;

namespace {

const std::string kBase = R"(title = "bimorph"

[model]
kind = "piezo"
effects = []
precision = "double"

[beam]
length = 0.055
width = 6.4e-3
dim = 2
plane = "stress"
conducting_host = true

[[beam.layers]]
name = "pzt lower"
thickness = 0.27e-3
material = "pzt5a"
poling = 1
cells = 2

[[beam.layers]]
name = "brass"
thickness = 0.14e-3
material = "brass"

[[beam.layers]]
name = "pzt upper"
thickness = 0.27e-3
material = "pzt5a"
poling = -1
cells = 2

[[electrodes]]
name = "bottom"
surface = "bottom"
kind = "floating"

[[electrodes]]
name = "top"
surface = "top"

[mesh]
order = 2
cells_length = 40

[circuit]
resistors = [{ from = "top", to = "bottom", ohm = 2000.0 }]

[damping]
zeta = 0.01

[analysis]
kind = "transient"
frequency = "resonance"
base_acceleration = 9.81
periods = 20
steps_per_period = 80
scheme = "monolithic"

[accuracy]
default = "paper"
)";

const std::string kStatic = R"(title = "bender"

[model]
kind = "piezo"

[beam]
length = 0.1
width = 5e-3
conducting_host = false

[[beam.layers]]
name = "lower"
thickness = 5e-4
material = "pvdf"
poling = 1

[[beam.layers]]
name = "upper"
thickness = 5e-4
material = "pvdf"
poling = -1

[[electrodes]]
name = "ground"
surface = "bottom"
kind = "grounded"

[[electrodes]]
name = "drive"
surface = "top"
kind = "prescribed"
potential = 100.0

[mesh]
order = 2
cells_length = 40

[analysis]
kind = "static"
)";

fs::path source_dir() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return d ? fs::path(d) : fs::path(".");
}

io::PiezoScene load(const std::string& text, const std::string& accuracy = "", const std::string& precision = "") {
  polymech::testing::TempDir dir;
  return io::load_piezo_scene(dir.write("scene.toml", text), io::SceneOptions{accuracy, precision});
}

void expect_error(const std::string& text, const std::string& at, const std::vector<std::string>& fragments) {
  polymech::testing::expect_load_error(text, [](const fs::path& p) { io::load_piezo_scene(p); }, line_of(text, at), fragments);
}
// kBase (or `base`) with one edit, refused at the edit's last line.
// `at`: a fragment of the edited text that starts on the line the error must name (default: the edit's last line).
void expect_edit_error(const std::string& from, const std::string& to, const std::vector<std::string>& fragments,
                       const std::string& base = kBase, const std::string& at = "") {
  const std::string text = replace_once(base, from, to);
  expect_error(text, at.empty() ? to.substr(to.rfind('\n') + 1) : at, fragments);
}

}  // namespace

TEST(PiezoScenes, ShippedScenesLoad) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(source_dir() / "scenes" / "piezo")) {
    if (e.path().extension() != ".toml") continue;
    SCOPED_TRACE(e.path().string());
    EXPECT_EQ(io::scene_kind_of(e.path()).kind, "piezo");
    EXPECT_EQ(io::scene_kind_of(e.path()).app_for(e.path()), "piezo_harvester");
    const auto s = io::load_piezo_scene(e.path());
    EXPECT_EQ(s.header.accuracy, "paper");
    EXPECT_GT(s.unknowns, 500.0);
    EXPECT_GT(s.cost.seconds, 0.0);
    ++n;
  }
  EXPECT_EQ(n, 3);
  const auto sweep = io::load_piezo_scene(source_dir() / "scenes" / "piezo" / "dutoit_sweep.toml");
  ASSERT_EQ(sweep.config.analysis.loads.size(), 25u);
  EXPECT_NEAR(sweep.config.analysis.loads.front(), 100.0, 1e-9);
  EXPECT_NEAR(sweep.config.analysis.loads.back(), 1e6, 1e-6);
  EXPECT_NEAR(sweep.config.analysis.loads[6], 1000.0, 1e-9);  // 4 decades, 6 per decade
  const auto transient = io::load_piezo_scene(source_dir() / "scenes" / "piezo" / "dutoit_harvester.toml");
  EXPECT_GE(transient.config.analysis.periods, 7.0 / (2.0 * pz::kPi * transient.config.zeta));  // the steady state
}

TEST(PiezoScenes, BaseLoadsWithItsValuesAndDefaults) {
  const auto s = load(kBase);
  const auto& c = s.config;
  EXPECT_EQ(s.header.kind, "piezo");
  ASSERT_EQ(c.layers.size(), 3u);
  EXPECT_EQ(c.layers[1].cells, 1);  // default
  EXPECT_EQ(c.layers[2].poling, -1);
  EXPECT_EQ(c.electrodes[1].kind, "floating");  // default
  EXPECT_EQ(c.support, "clamped");
  EXPECT_EQ(c.piezo_material(), "pzt5a");
  EXPECT_EQ(c.analysis.frequency, 0.0);  // "resonance"
  EXPECT_EQ(c.analysis.steps(), 1600);
  EXPECT_EQ(c.analysis.average_periods, 2);
  EXPECT_EQ(c.resistors.at(0).from, "top");
  EXPECT_DOUBLE_EQ(c.resistors.at(0).ohm, 2000.0);
  const auto hz = load(replace_once(kBase, "frequency = \"resonance\"", "frequency = 98.5"));
  EXPECT_DOUBLE_EQ(hz.config.analysis.frequency, 98.5);
  const auto st = load(kStatic);  // no precision, no effects, no accuracy table: double, none, paper
  EXPECT_EQ(st.header.precision, "double");
  EXPECT_EQ(st.header.accuracy, "paper");
  EXPECT_EQ(st.config.plane, "stress");
}

TEST(PiezoScenes, AccuracyPresetsDivideTheCellsNotTheTimeStep) {
  const auto paper = load(kBase), draft = load(kBase, "draft"), standard = load(kBase, "standard");
  EXPECT_EQ(paper.config.cells_length, 40);
  EXPECT_EQ(standard.config.cells_length, 20);
  EXPECT_EQ(draft.config.cells_length, 10);
  EXPECT_EQ(draft.config.layers[0].cells, 1);
  EXPECT_EQ(draft.config.analysis.steps_per_period, 80);  // Newmark's period error must stay below zeta
  EXPECT_LT(draft.unknowns, standard.unknowns);
  EXPECT_LT(standard.unknowns, paper.unknowns);
  EXPECT_LT(draft.cost.seconds, paper.cost.seconds);
}

// The loader's closed-form count of the unknowns is the FE beam's own.
TEST(PiezoScenes, UnknownCountBoundsTheModels) {
  const std::string three_d = replace_once(replace_once(kStatic, "conducting_host = false", "dim = 3"), "cells_length = 40", "cells_length = 8\ncells_width = 2");
  const std::string free = replace_once(kStatic, "conducting_host = false", "conducting_host = false\nsupport = \"free\"");
  const std::string host = replace_once(kBase, "conducting_host = true", "conducting_host = false");
  for (const std::string& text : {kBase, kStatic, three_d, free, host}) {
    for (const char* acc : {"draft", "paper"}) {
      const auto s = load(text, acc);
      const pz::PiezoBeam b(pz::beam_spec(s.config));
      std::printf("%s %s: closed form %.0f, model %lld unknowns\n", s.config.piezo_material().c_str(), acc, s.unknowns,
                  static_cast<long long>(b.unknowns()));
      EXPECT_EQ(static_cast<long long>(s.unknowns), static_cast<long long>(b.unknowns()));
    }
  }
}

// The laminated bender of harvester_case.hpp: the two-layer PVDF bimorph is 3 d31 V L^2 / (2 t^2) as a beam and
// (1 + nu) times that as a plate; the duToit bimorph at +-V/2 is the beam model's vartheta V L^2 / (2 YI).
TEST(PiezoScenes, LaminatedBenderIsTheBimorphClosedForm) {
  const pz::Pvdf p{};
  const auto bender = pz::laminated_bender(load(kStatic).config);
  ASSERT_TRUE(bender.not_applicable.empty()) << bender.not_applicable;
  EXPECT_NEAR(bender.beam / -pz::series_bimorph_tip_deflection(p.d31, 100.0, 0.1, 1e-3), 1.0, 1e-12);
  EXPECT_NEAR(bender.plate / -pz::series_bimorph_tip_deflection_plane_strain(p.d31, 100.0, 0.1, 1e-3, p.nu), 1.0, 1e-12);
  std::string text = replace_once(kBase, "kind = \"transient\"", "kind = \"static\"");
  text = text.substr(0, text.find("[circuit]")) + "[analysis]\nkind = \"static\"\n";
  text = replace_once(text, "surface = \"bottom\"\nkind = \"floating\"", "surface = \"bottom\"\nkind = \"prescribed\"\npotential = -5.0");
  text = replace_once(text, "surface = \"top\"\n", "surface = \"top\"\nkind = \"prescribed\"\npotential = 5.0\n");
  const auto dutoit = pz::laminated_bender(load(text).config);
  const pz::BimorphHarvester beam(pz::dutoit_wardle_2007_case());
  ASSERT_TRUE(dutoit.not_applicable.empty()) << dutoit.not_applicable;
  EXPECT_NEAR(std::fabs(dutoit.beam) / std::fabs(beam.static_tip_deflection(10.0)), 1.0, 1e-12);
  // a floating face: no closed form, and why
  const auto open = pz::laminated_bender(load(replace_once(text, "kind = \"prescribed\"\npotential = 5.0", "kind = \"floating\"")).config);
  EXPECT_NE(open.not_applicable.find("known potentials"), std::string::npos);
}

TEST(PiezoScenes, ModelAndPrecisionAreRefused) {
  expect_edit_error("effects = []", "effects = [\"rotation\"]", {"rotation"});
  polymech::testing::expect_load_error(
      kBase, [](const fs::path& f) { io::load_piezo_scene(f, io::SceneOptions{"", "float"}); }, line_of(kBase, "precision"),
      {"key 'model.precision' = \"float\" (--precision)", "double precision only", "allowed: \"double\""});
  expect_edit_error("precision = \"double\"", "precision = \"float\"", {"key 'model.precision' = \"float\"", "allowed: \"double\""});
}

TEST(PiezoScenes, BadBeamIsRefusedWithTheKeyAndWhatIsAllowed) {
  expect_edit_error("length = 0.055", "length = -1", {"key 'beam.length' = -1 is out of range", "m (the cantilever's length)"});
  expect_edit_error("length = 0.055", "length = 5e-4", {"key 'beam.length' = 0.0005", "not longer than the layers' 0.00068 m"});
  expect_edit_error("dim = 2", "dim = 4", {"key 'beam.dim'", "[2, 3]"});
  expect_edit_error("plane = \"stress\"", "plane = \"membrane\"", {"key 'beam.plane'", "\"stress\", \"strain\""});
  expect_edit_error("dim = 2\nplane = \"stress\"", "dim = 3\nplane = \"stress\"", {"key 'beam.plane' applies to 2D beams only"});
  expect_edit_error("material = \"brass\"", "material = \"steel\"", {"key 'beam.layers[1].material'", "\"pzt5a\", \"pvdf\", \"brass\""});
  expect_edit_error("material = \"brass\"", "material = \"pvdf\"", {"key 'beam.layers[1].material' = \"pvdf\"", "one piezoelectric law",
                                                                  "allowed: \"pzt5a\" or \"brass\""});
  expect_edit_error("poling = -1", "poling = 0", {"key 'beam.layers[2].poling' = 0", "+1"});
  expect_edit_error("material = \"brass\"", "material = \"brass\"\npoling = +1", {"key 'beam.layers[1].poling' applies to piezoelectric"});
  expect_edit_error("thickness = 0.14e-3", "thickness = 0.0", {"key 'beam.layers[1].thickness' = 0 is out of range"});
  expect_edit_error("name = \"brass\"", "name = \"pzt lower\"", {"key 'beam.layers[1].name' = \"pzt lower\" names two layers"}, kBase,
                    "name = \"pzt lower\"\nthickness = 0.14e-3");
  expect_edit_error("cells = 2\n\n[[beam.layers]]\nname = \"brass\"", "cells = 0\n\n[[beam.layers]]\nname = \"brass\"",
                    {"key 'beam.layers[0].cells' = 0", "[1, 1000]"}, kBase, "cells = 0");
  expect_edit_error("cells_length = 40", "cells_length = 0", {"key 'mesh.cells_length' = 0", "[1, 100000]"});
  expect_edit_error("order = 2", "order = 5", {"key 'mesh.order' = 5", "[1, 4]"});
  expect_edit_error("cells_length = 40", "cells_length = 40\ncells_width = 2", {"key 'mesh.cells_width' applies to 3D beams"});
  expect_edit_error("conducting_host = true", "conducting_host = true\nsupport = \"free\"", {"key 'beam.support' = \"free\" applies to static"});
}

TEST(PiezoScenes, BadElectrodesAndCircuitAreRefused) {
  expect_edit_error("surface = \"top\"", "surface = \"side\"", {"key 'electrodes[1].surface' = \"side\"", "\"bottom\", \"top\", \"interface 1\", \"interface 2\""});
  expect_edit_error("surface = \"top\"", "surface = \"interface 3\"", {"key 'electrodes[1].surface' = \"interface 3\""});
  expect_edit_error("surface = \"top\"", "surface = \"bottom\"", {"key 'electrodes[1].surface' = \"bottom\" already carries an electrode"}, kBase,
                    "surface = \"bottom\"\n\n[mesh]");
  expect_edit_error("surface = \"top\"", "surface = \"interface 1\"", {"key 'electrodes[1].kind' = \"floating\"", "grounded conducting host",
                                                                     "allowed: \"grounded\""}, kBase, "[[electrodes]]\nname = \"top\"");
  expect_edit_error("name = \"top\"", "name = \"bottom\"", {"key 'electrodes[1].name' = \"bottom\" names two electrodes"}, kBase,
                    "name = \"bottom\"\nsurface = \"top\"");
  expect_edit_error("name = \"top\"", "name = \"ground\"", {"key 'electrodes[1].name' = \"ground\"", "kind = \"grounded\" electrode only"});
  expect_edit_error("kind = \"floating\"", "kind = \"prescribed\"", {"key 'electrodes[0].kind' = \"prescribed\" applies to analysis.kind = \"static\""});
  expect_edit_error("kind = \"floating\"", "kind = \"floating\"\npotential = 3.0", {"key 'electrodes[0].potential' applies to kind = \"prescribed\""});
  expect_edit_error("kind = \"floating\"", "kind = \"sticky\"", {"key 'electrodes[0].kind'", "\"floating\", \"grounded\", \"prescribed\""});
  expect_edit_error("resistors = [{ from = \"top\", to = \"bottom\", ohm = 2000.0 }]", "resistors = [{ from = \"top\", to = \"left\", ohm = 2000.0 }]",
                    {"key 'circuit.resistors[0].to' = \"left\" is not a floating electrode", "allowed: \"ground\", \"bottom\", \"top\""});
  expect_edit_error("resistors = [{ from = \"top\", to = \"bottom\", ohm = 2000.0 }]", "resistors = [{ from = \"top\", to = \"top\", ohm = 2000.0 }]",
                    {"key 'circuit.resistors[0].to' = \"top\" is the resistor's other end too"});
  expect_edit_error("resistors = [{ from = \"top\", to = \"bottom\", ohm = 2000.0 }]", "resistors = [{ from = \"top\", to = \"ground\", ohm = 0 }]",
                    {"key 'circuit.resistors[0].ohm' = 0 is out of range", "ohm"});
  expect_edit_error("resistors = [{ from = \"top\", to = \"bottom\", ohm = 2000.0 }]", "resistors = [{ from = \"top\", to = \"ground\", R = 5 }]",
                    {"key 'circuit.resistors[0].ohm' is missing"});
  expect_edit_error("resistors = [{ from = \"top\", to = \"bottom\", ohm = 2000.0 }]", "", {"key 'circuit' has no resistors", "a transient run needs resistors"}, kBase, "[circuit]");
  expect_edit_error("zeta = 0.01", "zeta = 0.01\nbeta = 1e-5", {"key 'damping.beta' and damping.zeta exclude each other"});
  expect_edit_error("zeta = 0.01", "zeta = 1.5", {"key 'damping.zeta' = 1.5 is out of range"});
  // static: the circuit means nothing, a load is needed
  expect_edit_error("kind = \"static\"", "kind = \"static\"\nperiods = 3", {"key 'analysis.periods' applies to analysis.kind = \"transient\""}, kStatic);
  expect_edit_error("potential = 100.0", "potential = 1e9", {"key 'electrodes[1].potential' = 1e+09 is out of range", "V"}, kStatic);
  expect_error(replace_once(kStatic, "kind = \"prescribed\"\npotential = 100.0", "kind = \"grounded\""), "[[electrodes]]",
               {"key 'electrodes'", "no kind = \"prescribed\" electrode"});
  expect_error(kStatic + "\n[circuit]\nresistors = []\n", "[circuit]", {"[circuit]: means nothing to analysis.kind = \"static\""});
}

TEST(PiezoScenes, BadAnalysisIsRefused) {
  expect_edit_error("kind = \"transient\"", "kind = \"modal\"", {"key 'analysis.kind'", "\"static\", \"harmonic\", \"transient\""});
  expect_edit_error("frequency = \"resonance\"", "frequency = \"peak\"", {"key 'analysis.frequency' must be \"resonance\"", "or a number"});
  expect_edit_error("frequency = \"resonance\"", "frequency = -5", {"key 'analysis.frequency' = -5 is out of range", "Hz"});
  expect_edit_error("periods = 20", "periods = 0", {"key 'analysis.periods' = 0 is out of range"});
  expect_edit_error("periods = 20", "periods = 1", {"key 'analysis.average_periods' = 2 is out of range", "<= analysis.periods = 1"}, kBase,
                    "[analysis]");
  expect_edit_error("steps_per_period = 80", "steps_per_period = 2", {"key 'analysis.steps_per_period' = 2", "[4, 100000]"});
  expect_edit_error("scheme = \"monolithic\"", "scheme = \"staggered\"", {"key 'analysis.scheme'", "\"monolithic\", \"partitioned\""});
  expect_edit_error("base_acceleration = 9.81", "base_acceleration = 0", {"key 'analysis.base_acceleration' = 0 is out of range", "m/s^2"});
  expect_edit_error("periods = 20", "periods = 20\npoints = 10", {"key 'analysis.points' applies to analysis.kind = \"harmonic\""});
  const std::string harmonic = replace_once(kBase, "frequency = \"resonance\"\nbase_acceleration = 9.81\nperiods = 20\nsteps_per_period = 80\nscheme = \"monolithic\"",
                                            "loads = [100.0, 1e4]\npoints = 30");
  const std::string h = replace_once(harmonic, "kind = \"transient\"", "kind = \"harmonic\"");
  const auto s = load(h);
  EXPECT_EQ(s.config.analysis.loads.size(), 2u);
  EXPECT_EQ(s.config.analysis.points, 30);
  EXPECT_EQ(load(h, "draft").config.analysis.points, 11);  // 30 / 4 -> at least 11
  expect_edit_error("loads = [100.0, 1e4]", "loads = [100.0, -1]", {"key 'analysis.loads' has the element -1, out of range"}, h);
  expect_edit_error("loads = [100.0, 1e4]", "loads = []", {"key 'analysis.loads' is empty"}, h);
  expect_edit_error("loads = [100.0, 1e4]", "load_range = [1e4, 100.0]\nload_points = 5", {"key 'analysis.load_range' must be [lo, hi]"}, h, "load_range");
  expect_edit_error("loads = [100.0, 1e4]", "loads = [100.0, 1e4]\nload_range = [1.0, 2.0]", {"key 'analysis.load_range' and analysis.loads exclude"}, h);
  expect_edit_error("points = 30", "points = 30\nfmin = 120\nfmax = 100", {"key 'analysis.fmax' = 100 is out of range", "> analysis.fmin = 120 Hz"}, h);
  expect_edit_error("points = 30", "points = 30\nperiods = 4", {"key 'analysis.periods' applies to analysis.kind = \"transient\""}, h);
  expect_edit_error("scheme = \"monolithic\"", "scheme = \"monolithic\"\ncolour = 1", {"unknown key 'analysis.colour'"});
}
