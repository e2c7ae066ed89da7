#include "io/helmholtz_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "fem/orders.hpp"
#include "helmholtz/effect_table.hpp"
#include "helmholtz/mesh_import.hpp"
#include "io/gmsh_msh.hpp"
#include "io/model_table.hpp"
#include "io/ranges.hpp"

namespace polymech::io {

namespace hz = polymech::helmholtz;
namespace pl = polymech::io::plausible;

namespace {

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s.empty() ? "(none)" : s;
}

// Three numbers in a range.
std::array<double, 3> triple(const SceneTable& t, const std::string& key, Range range) {
  const auto v = t.reals(key, range);
  if (v.size() != 3) t.fail(key, "must have 3 entries (x, y, z), got " + std::to_string(v.size()));
  return {v[0], v[1], v[2]};
}

// The mesh's bounding box, lo and hi per direction.
std::array<std::array<double, 3>, 2> bounding_box(const hz::HexMesh& m) {
  std::array<std::array<double, 3>, 2> b{};
  b[0].fill(1e300);
  b[1].fill(-1e300);
  for (std::int64_t v = 0; v < m.vertex_count(); ++v)
    for (int d = 0; d < 3; ++d) {
      b[0][d] = std::min(b[0][d], m.vertices[3 * v + d]);
      b[1][d] = std::max(b[1][d], m.vertices[3 * v + d]);
    }
  return b;
}

std::string point_text(const std::array<double, 3>& p) {
  return "(" + format_number(p[0]) + ", " + format_number(p[1]) + ", " + format_number(p[2]) + ")";
}

// A profile end point inside the mesh's bounding box (to a relative 1e-9 of its size).
void check_inside(const SceneTable& t, const std::string& key, const std::array<double, 3>& p,
                  const std::array<std::array<double, 3>, 2>& box) {
  for (int d = 0; d < 3; ++d) {
    const double tol = 1e-9 * std::max(1.0, box[1][d] - box[0][d]);
    if (!(p[d] >= box[0][d] - tol && p[d] <= box[1][d] + tol))
      t.fail(key, "= " + point_text(p) + " is outside the mesh; allowed: a point in its bounding box " +
                      point_text(box[0]) + " .. " + point_text(box[1]));
  }
}

hz::BoundaryKind kind_of(const std::string& s) {
  if (s == "dirichlet") return hz::BoundaryKind::dirichlet;
  if (s == "impedance") return hz::BoundaryKind::impedance;
  if (s == "vibrating") return hz::BoundaryKind::vibrating;
  return hz::BoundaryKind::rigid;
}

}  // namespace

HelmholtzScene load_helmholtz_scene(const std::filesystem::path& file, const HelmholtzSceneOptions& options) {
  HelmholtzScene out;
  const OpenScene opened = open_scene(file, "helmholtz", hz::effect_table(), options.precision, out);
  const SceneTable& root = opened.root;
  const SceneTable& model = opened.model;
  hz::Config& c = out.config;

  // [discretization]
  const SceneTable disc = root.table("discretization");
  c.order = static_cast<int>(disc.integer("order", fem::min_order, fem::max_order));
  disc.finish();
  if (options.order != 0) {
    if (options.order < fem::min_order || options.order > fem::max_order)
      throw SceneError(file.string() + ": order " + std::to_string(options.order) +
                       " is not supported; allowed: 1..4");
    c.order = options.order;
  }

  // [mesh]
  const SceneTable mesh = root.table("mesh");
  const std::string mesh_kind = mesh.choice("kind", {"box", "gmsh"});
  if (mesh_kind == "gmsh") {
    if (const auto acc = root.optional_table("accuracy"))
      acc->fail_table("accuracy presets scale box meshes; a Gmsh mesh is used as it is");
  } else {
    // without [accuracy]: the element counts as written
    out.header.set_accuracy(read_accuracy(root, options.accuracy, options.coarsening, "paper"));
  }
  const bool single = out.header.precision == "float";
  // the size of the run: refused before the mesh is built (box) or used (Gmsh) if it cannot fit
  double dofs = 0.0, elements = 0.0;
  std::vector<std::string> size_keys;
  const auto check_run_size = [&] {
    CostEstimate e = helmholtz_cost(dofs, elements, c.order, single, 10000);
    e.size_keys = size_keys;
    check_size(e, mesh);
  };
  if (mesh_kind == "box") {
    hz::BoxSpec box;
    box.lengths = triple(mesh, "lengths", pl::length());
    if (mesh.has("origin")) box.origin = triple(mesh, "origin", pl::coordinate());
    const auto n = triple(mesh, "elements", at_least(1.0));
    for (int d = 0; d < 3; ++d) {
      if (n[d] != std::floor(n[d]) || n[d] > 1e5)
        mesh.fail("elements", "must be whole numbers in [1, 100000], got " + format_number(n[d]));
      box.elements[d] = options.elements[d] > 0 ? options.elements[d]
                                                : std::max(1, static_cast<int>(std::lround(n[d] / out.header.coarsening)));
      out.box_elements[d] = box.elements[d];
    }
    elements = dofs = 1.0;
    for (int d = 0; d < 3; ++d) {
      elements *= box.elements[d];
      dofs *= static_cast<double>(c.order) * box.elements[d] + 1.0;
    }
    size_keys = {"mesh.elements = [" + std::to_string(box.elements[0]) + ", " + std::to_string(box.elements[1]) + ", " +
                     std::to_string(box.elements[2]) + "] (at accuracy '" + out.header.accuracy + "')",
                 "discretization.order = " + std::to_string(c.order)};
    check_run_size();
    box.perturbation = mesh.real("perturbation", 0.0, between(0.0, 1.0));
    box.seed = static_cast<std::uint32_t>(mesh.integer("seed", 1, 0, 1 << 30));
    c.mesh = hz::make_box_mesh(box);
    for (std::int64_t e = 0; e < c.mesh.element_count(); ++e) {
      const double r = hz::min_corner_jacobian_ratio(c.mesh, e);
      if (!(r > 0))
        mesh.fail("perturbation", "= " + format_number(box.perturbation) + " inverts element " + std::to_string(e) +
                                      " (det J at a corner / mean = " + format_number(r) +
                                      "); allowed: a perturbation that keeps every element valid (about < 0.4)");
    }
    out.mesh_source = "box " + std::to_string(box.elements[0]) + " x " + std::to_string(box.elements[1]) + " x " +
                      std::to_string(box.elements[2]);
  } else {
    if (!options.accuracy.empty())
      throw SceneError(file.string() + ": accuracy '" + options.accuracy +
                       "' cannot be applied: presets scale box meshes and this scene reads a Gmsh mesh");
    if (options.coarsening > 0 || options.elements[0] > 0)
      throw SceneError(file.string() + ": a Gmsh mesh cannot be coarsened or refined here");
    out.header.accuracy = "mesh file";
    const std::string name = mesh.string("file");
    std::filesystem::path path = name;
    if (path.is_relative()) path = file.parent_path() / path;
    if (!std::filesystem::exists(path))
      mesh.fail("file", "= \"" + name + "\": no such file (looked for " + path.string() + ")");
    try {
      c.mesh = hz::hex_mesh_from(read_gmsh_mesh(path));
    } catch (const MeshError& e) {
      mesh.fail("file", "= \"" + name + "\" cannot be used: " + e.what());
    } catch (const std::invalid_argument& e) {
      mesh.fail("file", "= \"" + name + "\" cannot be used: " + e.what());
    }
    out.mesh_source = path.string();
    elements = static_cast<double>(c.mesh.element_count());
    dofs = std::max(static_cast<double>(c.mesh.vertex_count()), elements * c.order * c.order * c.order);
    size_keys = {"mesh.file = \"" + name + "\" (" + std::to_string(c.mesh.element_count()) + " hexahedra)",
                 "discretization.order = " + std::to_string(c.order)};
    check_run_size();
  }
  mesh.finish();

  // [acoustics]
  const SceneTable ac = root.table("acoustics");
  c.sound_speed = ac.real("sound_speed", pl::wave_speed());
  c.frequency = ac.real("frequency", pl::frequency());
  c.density = ac.real("density", pl::density());
  ac.finish();
  if (options.frequency > 0) c.frequency = options.frequency;

  // [[boundary]]
  std::vector<std::string> used_names;
  std::vector<std::string> kinds_used;
  for (const auto& b : root.tables("boundary")) {
    const auto names = b.strings("names", {});
    if (names.empty()) b.fail("names", "is missing or empty; it is required (mesh boundaries: " + join(c.mesh.boundary_names) + ")");
    const std::string kind = b.choice("kind", {"rigid", "dirichlet", "impedance", "vibrating"});
    hz::BoundaryCondition bc;
    bc.kind = kind_of(kind);
    if (bc.kind == hz::BoundaryKind::impedance) bc.impedance = b.real("impedance", pl::impedance());
    if (bc.kind == hz::BoundaryKind::vibrating) bc.velocity = b.real("velocity", pl::signed_velocity());
    const bool has_value = bc.kind == hz::BoundaryKind::dirichlet && b.has("value");
    if (has_value) bc.value = b.real("value", Range{-1e12, 1e12, false, false, "(a plausible potential)"});
    if (bc.kind != hz::BoundaryKind::rigid && !c.effects.has(kind))
      b.fail("kind", "= \"" + kind + "\" needs effect '" + kind + "' in model.effects (listed: " +
                         join(std::vector<std::string>(c.effects.names().begin(), c.effects.names().end())) + ")");
    for (const auto& n : names) {
      if (c.mesh.boundary_index(n) < 0)
        b.fail("names", "names boundary '" + n + "', which the mesh does not have; mesh boundaries: " +
                            join(c.mesh.boundary_names));
      if (std::find(used_names.begin(), used_names.end(), n) != used_names.end())
        b.fail("names", "names boundary '" + n + "' a second time; each boundary takes one condition");
      used_names.push_back(n);
      bc.name = n;
      c.boundaries.push_back(bc);
    }
    kinds_used.push_back(kind);
    b.finish();
    if (bc.kind == hz::BoundaryKind::dirichlet && !has_value && !root.has("analytic"))
      b.fail("kind", "= \"dirichlet\" needs 'value' (there is no [analytic] field to take the values from)");
  }
  for (const auto& e : c.effects.names())
    if (std::find(kinds_used.begin(), kinds_used.end(), e) == kinds_used.end())
      model.fail("effects", "lists effect '" + e + "' but no [[boundary]] has kind = \"" + e +
                                "\"; a scene lists only the effects its boundaries need");
  model.finish();

  // [analytic]
  if (auto an = root.optional_table("analytic")) {
    const std::string kind = an->choice("kind", {"none", "plane_cosines", "duct"});
    c.analytic.kind = kind == "plane_cosines" ? hz::AnalyticKind::plane_cosines
                      : kind == "duct"        ? hz::AnalyticKind::duct
                                              : hz::AnalyticKind::none;
    if (c.analytic.kind == hz::AnalyticKind::duct) {
      const auto bb = bounding_box(c.mesh);
      const double lo = bb[0][0], hi = bb[1][0];
      double v0 = 0.0, zn = 0.0;
      for (const auto& b : c.boundaries) {
        if (b.kind == hz::BoundaryKind::vibrating) v0 = b.velocity;
        if (b.kind == hz::BoundaryKind::impedance) zn = b.impedance;
      }
      c.analytic.x0 = an->real("x0", lo, pl::coordinate());
      c.analytic.length = an->real("length", hi - lo, pl::length());
      c.analytic.velocity = an->real("velocity", v0, pl::signed_velocity());
      c.analytic.impedance = an->real("impedance", zn > 0 ? zn : 1.0, pl::impedance());
    }
    an->finish();
  }

  // [solver]
  if (auto s = root.optional_table("solver")) {
    s->choice("method", {"cocg"}, "cocg");
    const std::string pc = s->choice("preconditioner", {"jacobi", "none", "chebyshev", "pmg"}, "jacobi");
    c.preconditioner = pc == "none"        ? hz::Preconditioner::none
                       : pc == "chebyshev" ? hz::Preconditioner::chebyshev
                       : pc == "pmg"       ? hz::Preconditioner::pmg
                                           : hz::Preconditioner::jacobi;
    // shifted Laplacian S = A + shift k^2 M of the chebyshev / pmg preconditioners
    c.shifted.shift = s->real("shift", c.shifted.shift, Range{0.0, 100.0, true, true});
    c.shifted.smoothing_degree = static_cast<int>(s->integer("smoothing_degree", c.shifted.smoothing_degree, 1, 50));
    c.shifted.polynomial_degree = static_cast<int>(s->integer("polynomial_degree", c.shifted.polynomial_degree, 0, 1000));
    c.solver.tolerance = s->real("tolerance", 1e-10, Range{1e-15, 1.0, false, true, "(a relative residual the solver can reach)"});
    c.solver.max_iterations = static_cast<int>(s->integer("max_iterations", 10000, 1, 10000000));
    c.solver.stagnation_window = static_cast<int>(s->integer("stagnation_window", 1000, 1, 10000000));
    c.solver.max_restarts = static_cast<int>(s->integer("max_restarts", 3, 0, 100));
    s->finish();
  }

  // [output]
  if (auto o = root.optional_table("output")) {
    out.write_field = o->boolean("field", true);
    if (o->has("profile_from") || o->has("profile_to")) {
      out.profile_from = triple(*o, "profile_from", pl::coordinate());
      out.profile_to = triple(*o, "profile_to", pl::coordinate());
      out.has_profile = true;
      const auto bb = bounding_box(c.mesh);
      check_inside(*o, "profile_from", out.profile_from, bb);
      check_inside(*o, "profile_to", out.profile_to, bb);
      double length = 0.0, size = 0.0;
      for (int d = 0; d < 3; ++d) {
        length += (out.profile_to[d] - out.profile_from[d]) * (out.profile_to[d] - out.profile_from[d]);
        size += (bb[1][d] - bb[0][d]) * (bb[1][d] - bb[0][d]);
      }
      if (!(std::sqrt(length) > 1e-9 * std::sqrt(size)))
        o->fail("profile_to", "= " + point_text(out.profile_to) + " is the same point as profile_from; allowed: a line of "
                              "length > 0 inside the mesh");
    }
    o->finish();
  }
  root.finish();
  out.cost = helmholtz_cost(dofs, elements, c.order, single, c.solver.max_iterations);
  out.cost.size_keys = size_keys;
  return out;
}

}  // namespace polymech::io
