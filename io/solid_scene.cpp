#include "io/solid_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/ranges.hpp"
#include "solid/effect_table.hpp"
#include "solid/mesh.hpp"

namespace polymech::io {

namespace {

// The paper's six angles of the beam axis from [001] in the (110) plane (solid::paper_angles(); 54.7: [1-11]).
const std::vector<double> kPaperAngles = {0.0, 5.0, 10.0, 20.0, 30.0, 54.7356103172453};

Range um(double lo, bool lo_open, const char* what) { return Range{lo, 1e4, lo_open, false, std::string("um (") + what + ")"}; }
Range gpa(double lo, double hi, bool lo_open, const char* what) { return Range{lo, hi, lo_open, false, std::string("GPa (") + what + ")"}; }

// The elastic constants of a cubic crystal, refused unless the stiffness is positive definite.
void read_elastic(const SceneTable& t, SolidCrystal& c, bool required) {
  const Range r = gpa(-1e4, 1e4, false, "a cubic elastic constant");
  c.C11 = required ? t.real("C11", r) : t.real("C11", c.C11, r);
  c.C12 = required ? t.real("C12", r) : t.real("C12", c.C12, r);
  c.C44 = required ? t.real("C44", r) : t.real("C44", c.C44, r);
  const std::string set = "C11 = " + format_number(c.C11) + ", C12 = " + format_number(c.C12) + ", C44 = " +
                          format_number(c.C44) + " GPa is not a positive definite cubic stiffness; allowed: ";
  if (!(c.C44 > 0)) t.fail("C44", "= " + format_number(c.C44) + ": " + set + "C44 > 0");
  if (!(c.C11 > std::fabs(c.C12))) t.fail("C12", "= " + format_number(c.C12) + ": " + set + "C11 > |C12|");
  if (!(c.C11 + 2.0 * c.C12 > 0)) t.fail("C12", "= " + format_number(c.C12) + ": " + set + "C11 + 2 C12 > 0");
}

void read_plastic(const SceneTable& t, SolidCrystal& c) {
  c.yield_stress = t.real("yield_stress", gpa(0.0, 1e3, true, "the yield stress sigma_0 of eq. (4)"));
  c.hardening_exponent = t.real("hardening_exponent", Range{0.0, 1.0, false, true, "(n of eq. (4))"});
  c.R12 = t.real("R12", Range{0.0, 100.0, true, false, "(the Hill ratio of eq. (3))"});
}

// The estimator's bounds (models/solid/micro_cantilever_case.hpp, run_inverse_study): a start or a truth
// outside them cannot be reached.
struct Bound {
  const char* key;
  double lo, hi;
};
const Bound kBounds[] = {{"C11", 50.0, 2000.0},        {"C12", 1.0, 1000.0},          {"C44", 5.0, 500.0},
                         {"yield_stress", 0.05, 50.0}, {"hardening_exponent", 1e-3, 0.9}, {"R12", 0.2, 5.0}};
double value_of(const SolidCrystal& c, int k) {
  const double v[] = {c.C11, c.C12, c.C44, c.yield_stress, c.hardening_exponent, c.R12};
  return v[k];
}
void check_bounds(const SceneTable& t, const SolidCrystal& c, const std::string& role) {
  for (int k = 0; k < 6; ++k) {
    const double x = value_of(c, k);
    if (!(x >= kBounds[k].lo && x <= kBounds[k].hi))
      t.fail(kBounds[k].key, "= " + format_number(x) + " (" + role + ") is outside the estimator's bounds: must be in [" +
                                 format_number(kBounds[k].lo) + ", " + format_number(kBounds[k].hi) + "]");
  }
}

std::string um_text(double x) { return format_number(x) + " um"; }

}  // namespace

SolidMeshSize solid_mesh_size(const SolidBeam& b, const SolidMesh& m, double h_root) {
  const double h = h_root > 0 ? h_root : m.h_root;
  // the section lattice (solid::micro_cantilever_section): an even column count across the width, at least two
  // rows over the height, graded columns and rows outward into the block
  const int nyb = 2 * std::max(1, static_cast<int>(std::ceil(b.width / (2.0 * h) - 1e-9)));
  const int nzb = std::max(2, static_cast<int>(std::ceil(b.height / h - 1e-9)));
  const bool block = b.support_length > 0;
  int nout = 0, nbelow = 0, nxs = 0;
  const double h_max = std::max(m.h_support_max, h);
  if (block) {
    nout = static_cast<int>(
               solid::graded_planes(0.5 * b.width, 0.5 * b.support_width, b.width / nyb, m.support_growth, h_max).size()) - 1;
    nbelow = static_cast<int>(
                 solid::graded_planes(b.height, b.support_depth, b.height / nzb, m.support_growth, h_max).size()) - 1;
    nxs = static_cast<int>(solid::graded_planes(0.0, -b.support_length, h, m.support_growth, h_max).size()) - 1;
  }
  const int nxb = static_cast<int>(solid::graded_planes(0.0, b.length, h, m.growth, std::max(m.h_beam_max, h)).size()) - 1;
  const double p = m.order;
  const double ny = nyb + 2 * nout, nz = nzb + nbelow;
  SolidMeshSize s;
  s.cells = double(nxs) * ny * nz + double(nxb) * nyb * nzb;
  // the block's full lattice, then the beam's nodes in front of the root plane
  s.nodes = block ? (p * nxs + 1) * (p * ny + 1) * (p * nz + 1) + p * nxb * (p * nyb + 1) * (p * nzb + 1)
                  : (p * nxb + 1) * (p * nyb + 1) * (p * nzb + 1);
  s.dofs = 3.0 * s.nodes;
  s.points = s.cells * (p + 1) * (p + 1) * (p + 1);
  return s;
}

// Rates measured with apps/micro_cantilever (the notes h-app-docs, for docs/PERFORMANCE.md).
CostEstimate solid_cost(const SolidMeshSize& size, int order, bool plasticity, bool single, double curves, int increments,
                        const std::string& solver) {
  CostEstimate c;
  c.method = std::string("FE solid, order ") + std::to_string(order) + (plasticity ? ", Hill plasticity" : ", linear elastic");
  c.item_name = "DoFs";
  c.items = size.dofs;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  c.steps = curves * increments;
  c.step_name = "load steps (" + format_number(curves) + (curves == 1 ? " curve)" : " curves)");
  const double real = single ? 4.0 : 8.0;
  const double n = size.dofs / 17307.0;  // relative to the draft mesh
  double per_curve = 0.0;                // CPU seconds of a 12-step curve on one thread
  if (solver == "two_level_pcg") {
    // measured with the defaults of 2026-11-27 (one thread, theta 0, Intel Xeon, docs/PERFORMANCE.md): resident
    // 38 MB at 17 307 DoFs, 107 MB at 50 463, 359 MB at 152 661 (the float coarse LU, the per-point history and
    // tangent); CPU 2.05 s, 12.1 s, 82.4 s per curve: about DoFs^1.7 (the CG iterations grow with the mesh)
    c.bytes = 10e6 + size.dofs * 1.2e3 * std::pow(n, 0.2) + size.points * (10.0 + (plasticity ? 50.0 : 0.0)) * real;
    per_curve = 0.1 + 2.05 * std::pow(n, 1.7);
    c.rate = "a curve of 12 steps ~ 0.1 s + 2.05 s x (DoFs / 17 307)^1.7";
  } else {
    // the order-p LU of the elastic stiffness ("elastic_pcg") or of the tangent ("direct"): 343 MB at 17 307 DoFs
    // and 1.30 GB at 50 463 (order 2); 0.15 s at 1 260 DoFs (order 1, 6 steps), 15 s at 17 307, 110 s at 50 463
    // (elastic_pcg, notes h-app-docs): a linear part and one that grows like DoFs^2 (the LU's fill)
    c.bytes = 20e6 + size.dofs * (18e3 * std::pow(n, 0.3)) + size.points * (10.0 + (plasticity ? 50.0 : 0.0)) * real;
    per_curve = 2.4e-4 * size.dofs + 11.0 * n * n;
    c.rate = "a curve of 12 steps ~ 2.4e-4 s x DoFs + 11 s x (DoFs / 17 307)^2";
  }
  c.seconds = curves * (increments / 12.0) * per_curve * (plasticity ? 1.0 : 0.3);
  c.rate += std::string(plasticity ? "" : " x 0.3 (elastic: one Newton iteration per step)") + " (apps/micro_cantilever, " +
            solver + ", 1 thread)";
  c.rate_threads = 1;
  return c;
}

CostEstimate solid_scene_cost(const SolidScene& s, std::size_t n_angles, bool inverse) {
  const bool single = s.header.precision == "float";
  const int increments = s.load_increments + s.unload_increments;
  const double angles = static_cast<double>(n_angles);
  const std::vector<std::string> keys = {"mesh.h_root = " + um_text(s.mesh.h_root) + " (after the preset)",
                                         "mesh.order = " + std::to_string(s.mesh.order), "beam.support_* (the block)"};
  if (!inverse || !s.inverse) {
    CostEstimate c = solid_cost(s.size, s.mesh.order, s.plasticity, single, angles, increments, s.newton.solver);
    c.size_keys = keys;
    return c;
  }
  // the experiment's curves (finer mesh), then the fit: per Levenberg-Marquardt iteration six runs per angle for
  // the forward-difference Jacobian and two or three trial residuals, about 8 iterations (measured: 72 runs per
  // angle in 8 iterations, notes h-app-docs), and the fitted curves
  const double iterations = std::min(s.inverse->max_iterations, 8);
  const double runs = angles * (1.0 + 9.0 * iterations + 1.0);
  const CostEstimate e = solid_cost(s.inverse->experiment_size, s.mesh.order, true, single, angles, increments, s.newton.solver);
  CostEstimate c = solid_cost(s.size, s.mesh.order, true, single, runs, increments, s.newton.solver);
  c.method += ", inverse study";
  c.seconds += e.seconds;
  c.steps += e.steps;
  c.bytes = std::max(c.bytes, e.bytes);
  c.step_name = "load steps (" + format_number(runs) + " forward curves estimated + " + format_number(angles) +
                " experiment curves)";
  c.size_keys = keys;
  c.size_keys.push_back("inverse.experiment_h_root = " + um_text(s.inverse->experiment_h_root));
  return c;
}

SolidScene load_solid_scene(const std::filesystem::path& file, const SceneOptions& options) {
  SolidScene out;
  const OpenScene s = open_scene(file, "solid", solid::effect_table(), options.precision);
  out.header = s.header;
  const SceneTable& root = s.root;
  if (const auto c = root.optional_table("case"))
    c->fail_table("belongs to another solid case (Cook's membrane: run it with the cook_membrane app, or `polymech "
                  "--scene`); the micro-cantilever's scenes have no [case] table");
  s.model.finish();
  out.plasticity = out.header.effects.has("plasticity");
  out.header.set_accuracy(read_accuracy(root, options.accuracy, 0.0, "standard"));
  const double f = out.header.coarsening;

  // [crystal]
  {
    const SceneTable t = root.table("crystal");
    read_elastic(t, out.crystal, false);
    if (out.plasticity) {
      read_plastic(t, out.crystal);
      out.crystal.hill_form = t.choice("hill_form", {"yield_stress_ratio", "as_printed"}, "yield_stress_ratio");
    } else {
      for (const char* k : {"yield_stress", "hardening_exponent", "R12", "hill_form"})
        if (t.has(k))
          t.fail(k, "needs the effect \"plasticity\" in model.effects (without it the beam is linear elastic)");
    }
    t.finish();
  }

  // [beam]
  {
    const SceneTable t = root.table("beam");
    SolidBeam& b = out.beam;
    b.length = t.real("length", b.length, um(0.0, true, "the beam's length, root to loading point"));
    b.width = t.real("width", b.width, um(0.0, true, "the pentagon's top width"));
    b.height = t.real("height", b.height, um(0.0, true, "the pentagon's depth at the apex"));
    b.wall = t.real("wall", b.wall, um(0.0, true, "the pentagon's side-wall height, at most beam.height"));
    if (!(b.wall <= b.height))
      t.fail("wall", "= " + format_number(b.wall) + " is out of range: must be in (0, beam.height = " + um_text(b.height) +
                         "] (wall = height: a rectangular section)");
    b.support_length = t.real("support_length", b.support_length, um(0.0, false, "the support block's length; 0: the root clamped"));
    b.support_width = t.real("support_width", b.support_width, um(0.0, true, "the support block's width"));
    b.support_depth = t.real("support_depth", b.support_depth, um(0.0, true, "the support block's depth"));
    if (b.support_length > 0 && !(b.support_width > b.width))
      t.fail("support_width", "= " + format_number(b.support_width) + " is out of range: must be > beam.width = " +
                                   um_text(b.width) + " (the block holds the beam's section)");
    if (b.support_length > 0 && !(b.support_depth > b.height))
      t.fail("support_depth", "= " + format_number(b.support_depth) + " is out of range: must be > beam.height = " +
                                   um_text(b.height) + " (the block holds the beam's section)");
    b.angles = t.has("angles") ? t.reals("angles", Range{0.0, 90.0, false, false, "degrees from [001] in the (110) plane"})
                               : kPaperAngles;
    if (b.angles.empty()) t.fail("angles", "is empty; give at least one angle in [0, 90] degrees");
    b.peak_force = t.real("peak_force", Range{0.0, 1e6, true, false, "mN (the peak of the load-unload curve)"});
    t.finish();
  }

  // [mesh]: every cell size times the preset's factor
  {
    const SceneTable t = root.table("mesh");
    SolidMesh& m = out.mesh;
    m.order = static_cast<int>(t.integer("order", 2, 1, 4));
    const double h = t.real("h_root", um(1e-3, false, "the cell size at the root, at the paper's accuracy"));
    if (!(h < out.beam.height))
      t.fail("h_root", "= " + format_number(h) + " is out of range: must be < beam.height = " + um_text(out.beam.height));
    if (!(h * f < out.beam.height))
      t.fail("h_root", "= " + format_number(h) + " times the accuracy preset '" + out.header.accuracy + "' (x" +
                           format_number(f) + ") = " + um_text(h * f) + " must be < beam.height = " + um_text(out.beam.height) +
                           "; allowed: a smaller h_root or a finer preset");
    m.growth = t.real("growth", 1.2, Range{1.0, 10.0, false, false, "(cell growth toward the tip)"});
    const double hb = t.real("h_beam_max", std::max(1.0, h), um(0.0, true, "the largest cell along the beam"));
    if (!(hb >= h)) t.fail("h_beam_max", "= " + format_number(hb) + " is out of range: must be >= mesh.h_root = " + um_text(h));
    m.support_growth = t.real("support_growth", 1.5, Range{1.0, 10.0, false, false, "(cell growth into the block)"});
    const double hs = t.real("h_support_max", std::max(3.0, h), um(0.0, true, "the largest cell of the block"));
    if (!(hs >= h)) t.fail("h_support_max", "= " + format_number(hs) + " is out of range: must be >= mesh.h_root = " + um_text(h));
    m.h_root = h * f;
    m.h_beam_max = hb * f;
    m.h_support_max = hs * f;
    t.finish();
  }

  // [load]
  if (const auto t = root.optional_table("load")) {
    out.load_increments = static_cast<int>(t->integer("load_increments", 8, 1, 1000));
    out.unload_increments = static_cast<int>(t->integer("unload_increments", 4, 0, 1000));
    t->finish();
  }

  // [newton]
  if (const auto t = root.optional_table("newton")) {
    SolidNewton& n = out.newton;
    n.tolerance = t->real("tolerance", n.tolerance, Range{1e-14, 1e-2, false, false, "(|r| <= tolerance x the force scale)"});
    n.max_iterations = static_cast<int>(t->integer("max_iterations", n.max_iterations, 1, 1000));
    n.line_search = t->boolean("line_search", n.line_search);
    n.max_cuts = static_cast<int>(t->integer("max_cuts", n.max_cuts, 0, 30));
    n.solver = t->choice("solver", {"two_level_pcg", "elastic_pcg", "direct"}, n.solver);
    n.forcing = t->real("forcing", n.forcing, Range{0.0, 1.0, false, true, "(inexact Newton's forcing term; 0: exact solves)"});
    t->finish();
  }

  // [inverse]
  if (const auto t = root.optional_table("inverse")) {
    const SceneTable root_crystal = root.table("crystal");
    if (!out.plasticity)
      t->fail_table("needs the effect \"plasticity\" in model.effects: the study estimates all six parameters of "
                    "eqs. (1)-(4) (C11, C12, C44, yield_stress, hardening_exponent, R12)");
    if (out.crystal.hill_form != "yield_stress_ratio")
      root_crystal.fail("hill_form", "= \"" + out.crystal.hill_form +
                                         "\": the inverse study's estimator uses \"yield_stress_ratio\"; allowed with "
                                         "[inverse]: \"yield_stress_ratio\"");
    check_bounds(root_crystal, out.crystal, "the hidden truth of [inverse]");
    SolidInverse inv;
    const SceneTable st = t->table("start");
    read_elastic(st, inv.start, true);
    read_plastic(st, inv.start);
    inv.start.hill_form = out.crystal.hill_form;
    check_bounds(st, inv.start, "the estimator's start");
    st.finish();
    inv.noise = t->real("noise", inv.noise, Range{0.0, 10.0, true, false, "um (standard deviation of the measured deflection)"});
    inv.seed = static_cast<std::uint32_t>(t->integer("seed", 1, 0, 4294967295LL));
    const double h = out.mesh.h_root / f;
    const double he = t->real("experiment_h_root", 0.75 * h, um(1e-3, false, "the synthetic experiment's root cell size"));
    if (!(he <= h))
      t->fail("experiment_h_root", "= " + format_number(he) + " is out of range: must be <= mesh.h_root = " + um_text(h) +
                                       " (the experiment's mesh is at least as fine as the estimator's)");
    inv.experiment_h_root = he * f;
    inv.max_iterations = static_cast<int>(t->integer("max_iterations", inv.max_iterations, 1, 200));
    inv.model_accuracy = t->real("model_accuracy", out.newton.tolerance,
                                 Range{1e-14, 1e-2, false, false, "(relative accuracy of a forward run; default newton.tolerance)"});
    inv.experiment_size = solid_mesh_size(out.beam, out.mesh, inv.experiment_h_root);
    t->finish();
    out.inverse = inv;
  }
  root.finish();

  // size and cost
  out.size = solid_mesh_size(out.beam, out.mesh);
  out.cost = solid_scene_cost(out, out.beam.angles.size(), false);
  check_size(out.cost, root.table("mesh"));
  if (out.inverse) {
    out.inverse_cost = solid_scene_cost(out, out.beam.angles.size(), true);
    check_size(out.inverse_cost, root.table("inverse"));
  }
  return out;
}

std::string solid_app(const std::filesystem::path& file) {
  const auto c = Scene::load(file).root().optional_table("case");
  return c && c->choice("test", {"cook_membrane"}) == "cook_membrane" ? "cook_membrane" : "micro_cantilever";
}

CookScene load_cook_scene(const std::filesystem::path& file, const SceneOptions& options) {
  CookScene out;
  const OpenScene s = open_scene(file, "solid", solid::effect_table(), options.precision);
  out.header = s.header;
  const SceneTable& root = s.root;
  if (out.header.effects.has("plasticity"))
    s.model.fail("effects", "lists \"plasticity\": Cook's membrane here is linear elastic; allowed: effects = []");
  s.model.finish();
  out.header.set_accuracy(read_accuracy(root, options.accuracy, 0.0, "standard"));
  {
    const SceneTable t = root.table("case");
    t.choice("test", {"cook_membrane"});
    t.finish();
  }
  {
    const SceneTable t = root.table("material");
    out.young = t.real("youngs_modulus", out.young, Range{0.0, 1e12, true, false, "(Young's modulus, any consistent unit)"});
    out.poisson = t.real("poisson_ratio", out.poisson, Range{-1.0, 0.5, true, true, "(Poisson's ratio)"});
    out.plane = t.choice("plane", {"stress", "strain"}, out.plane);
    t.finish();
  }
  {
    const SceneTable t = root.table("load");
    out.traction = t.real("shear_traction", out.traction, Range{-1e12, 1e12, false, false, "(the shear traction on the edge x = 48)"});
    if (out.traction == 0.0) t.fail("shear_traction", "= 0: the membrane would not move; allowed: a non-zero traction");
    t.finish();
  }
  {
    const SceneTable t = root.table("mesh");
    out.order = static_cast<int>(t.integer("order", out.order, 1, 4));
    const int n = static_cast<int>(t.integer("cells", 32, 1, 4096));
    out.cells = std::max(1, static_cast<int>(std::lround(n / out.header.coarsening)));
    t.finish();
  }
  if (const auto t = root.optional_table("solver")) {
    out.solver = t->choice("kind", {"direct", "cg"}, out.solver);
    out.tolerance = t->real("tolerance", out.tolerance, Range{1e-14, 1e-2, false, false, "(CG's relative residual)"});
    if (out.solver == "direct" && t->has("tolerance"))
      t->fail("tolerance", "applies to kind = \"cg\"; the direct solve has none");
    t->finish();
  }
  root.finish();
  // cost: nodes (p n + 1)^2, two DoFs each; the host sparse LU of the 2D system measured 1.0 s at 33 282 DoFs of
  // order 2 and 4.0 s at order 4 (docs/figures/fe/sweep_solid_cook.csv, one thread), growing like DoFs^1.6
  const double side = static_cast<double>(out.order) * out.cells + 1.0;
  CostEstimate& c = out.cost;
  c.method = std::string("FE solid, Cook's membrane, order ") + std::to_string(out.order) + ", plane " + out.plane;
  c.item_name = "DoFs";
  c.items = 2.0 * side * side;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  c.steps = 1;
  c.step_name = out.solver == "direct" ? "direct solve" : "CG solve";
  const double q = static_cast<double>(out.order) / 2.0;
  c.bytes = 20e6 + c.items * 2e3 * q * q;
  c.seconds = 0.05 + 1.0 * std::pow(c.items / 33282.0, 1.6) * q * q * (out.solver == "cg" ? 3.0 : 1.0);
  c.rate = "1.0 s x (DoFs / 33 282)^1.6 x (order / 2)^2 (the direct solve; CG x 3), docs/figures/fe/sweep_solid_cook.csv";
  c.rate_threads = 1;
  c.size_keys = {"mesh.cells = " + std::to_string(out.cells) + " (after the preset)", "mesh.order = " + std::to_string(out.order)};
  check_size(c, root.table("mesh"));
  return out;
}

}  // namespace polymech::io
