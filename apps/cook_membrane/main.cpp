// Cook's membrane (issue 34's verification case; Cook 1974): the tapered panel (0, 0), (48, 44), (48, 60),
// (0, 44), clamped at x = 0, a uniform shear traction on the edge x = 48, linear elastic in plane stress or
// plane strain (models/solid/cases.hpp), order-p quadrilaterals on the n x n bilinear lattice, solved by the
// host sparse LU or matrix-free Jacobi CG as the scene says (io/solid_scene.hpp, load_cook_scene).
//   cook_membrane [--scene scenes/solid/cook_membrane.toml] [--out out/cook_membrane] [--accuracy draft|standard|paper]
// Writes summary.json: tip_vertical_displacement (the top-right vertex's vertical displacement), the converged
// reference of models/solid/cases.hpp (CalculiX's Richardson limit in plane stress, the published fine-mesh value
// in plane strain) and the relative error, DoFs, order, cells, the solver's iterations, set-up and solve seconds.
// The mesh and order study behind the reference: docs/VALIDATION.md and docs/figures/fe/sweep_solid_cook.csv.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "apps/common/case.hpp"
#include "io/solid_scene.hpp"
#include "solid/analysis.hpp"
#include "solid/cases.hpp"
#include "solid/linear_elastic.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

template <class T>
int run_case(const pm::io::CookScene& scene, const pm::apps::CommonOptions& opt) {
  pm::apps::CaseSpec spec("cook_membrane", scene.header, 1);
  spec.checkpoints = false;  // one linear solve
  spec.progress = false;
  pm::apps::Case cs(spec, opt, pm::apps::RestartOptions{});
  so::CookSpec c;
  c.order = scene.order;
  c.n = scene.cells;
  c.young = scene.young;
  c.poisson = scene.poisson;
  c.traction = scene.traction;
  c.plane = scene.plane == "strain" ? so::Plane::strain : so::Plane::stress;
  if (!opt.quiet)
    std::fprintf(stderr, "[cook_membrane] %s\n  accuracy %s: order %d, %d x %d cells, plane %s, %s, %s solve, %s\n",
                 scene.header.title.c_str(), scene.header.accuracy.c_str(), c.order, c.n, c.n, scene.plane.c_str(),
                 scene.header.precision.c_str(), scene.solver.c_str(), pm::apps::thread_count().c_str());
  const auto t0 = std::chrono::steady_clock::now();
  so::LinearElastic<T, 2> m(so::cook_membrane(c));
  Kokkos::fence();
  const double setup = since(t0);
  const auto t1 = std::chrono::steady_clock::now();
  nlohmann::json j = cs.summary();
  pm::models::RunStats stats;
  stats.steps = 1;
  bool ok = true;
  if (scene.solver == "direct") {
    m.solve_direct();
    j["iterations"] = 0;
  } else {
    pm::solvers::SolverOptions o;
    o.tolerance = scene.tolerance;
    o.max_iterations = 200000;
    o.stagnation_window = 50000;  // Jacobi CG on fine meshes plateaus for thousands of iterations
    const auto r = m.solve_cg(o);
    j["iterations"] = r.iterations;
    if (!r.converged()) {
      ok = false;
      j["reason"] = std::string("CG did not converge: ") + r.reason;
    }
  }
  Kokkos::fence();
  const double solve = since(t1);
  const double tip = so::displacement_at(m, {48.0, 60.0})[1];
  const double ref = so::cook_reference(c);
  if (!std::isfinite(tip)) {
    ok = false;
    j["reason"] = "the tip displacement is not finite";
  }
  j["tip_vertical_displacement"] = tip;
  j["reference_tip_vertical_displacement"] = ref;
  j["reference"] = c.plane == so::Plane::stress
                       ? "CalculiX CPS8 Richardson limit, u E / F = 25.175 (models/solid/cases.hpp)"
                       : "fine-mesh CalculiX / Code_Aster / Elmer, u E / F = 22.59 (models/solid/cases.hpp)";
  j["relative_error"] = tip / ref - 1.0;
  j["dofs"] = m.dof_count();
  j["order"] = c.order;
  j["cells"] = c.n;
  j["plane"] = scene.plane;
  j["youngs_modulus"] = c.young;
  j["poisson_ratio"] = c.poisson;
  j["shear_traction"] = c.traction;
  j["solver"] = scene.solver;
  j["setup_seconds"] = setup;
  j["solve_seconds"] = solve;
  j["converged"] = ok;
  std::printf("Cook's membrane, order %d, %d x %d cells (%d DoFs): tip vertical displacement %.8g (reference %.6g, %+.3e), "
              "%.3g s\n", c.order, c.n, c.n, static_cast<int>(m.dof_count()), tip, ref, tip / ref - 1.0, setup + solve);
  if (!ok) {
    stats.diverged = true;
    stats.bad_step = 0;
    stats.reason = j["reason"].get<std::string>();
  }
  const int rc = cs.finish(j, stats, {"summary.json"});
  std::printf("results in %s\n", cs.out().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Cook's membrane: the tapered panel in shear, linear elastic, the top-right vertical displacement "
               "against the converged reference (issue 34)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/solid/cook_membrane.toml", "out/cook_membrane");
  pm::apps::refuse_option(app, "--steps", "Cook's membrane is one linear solve");
  if (const auto rc = pm::apps::parse_command_line(app, "cook_membrane", argc, argv)) return *rc;
  return pm::apps::guarded("cook_membrane", [&] {
    pm::io::SceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    const auto scene = pm::io::load_cook_scene(opt.scene, so);
    if (pm::apps::announce_cost("cook_membrane", scene.header, scene.cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    return pm::apps::with_precision(scene.header.precision, [&](auto t) { return run_case<decltype(t)>(scene, opt); });
  });
}
