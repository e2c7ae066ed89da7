// Element-free Galerkin cracked plates (seed 004, Hagihara et al.), static stage: an edge or centre crack
// in tension (a scene of scenes/efg/), solved with MLS shape functions; the J-integral on circles
// around the tip gives K_I, compared with the Tada, Paris & Irwin handbook value. A scene with
// [dynamic] runs the stationary or running crack under a step load through models::run.
//   efg [--scene scenes/efg/edge_crack_static.toml] [--out out/efg] [--accuracy draft|standard|paper]
//       [--steps N] [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]   (the last four: dynamic)
// Static: writes summary.json (nodes, gauss_points, handbook_factor, sif_static [[radius_m, K/(s sqrt(pi a))], ...],
// sif_error (mean over the paths), j_path_spread, crack_opening (at the crack centre or mouth), timings,
// shape_function_evaluations_per_second, wall_seconds), j_paths.csv and a snapshot fields.xdmf/.h5 of
// the displacement at the nodes. Dynamic: summary.json (sif_stationary or sif_running, crack_opening,
// sif_peak, energy_error, run record) and sif_history.csv; checkpoints and --restart as in
// apps/common/restart.hpp. The dynamic case: apps/efg/dynamic.hpp.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "apps/efg/dynamic.hpp"
#include "efg/analysis.hpp"
#include "io/efg_scene.hpp"

namespace pm = polymech;

namespace {

// A scene's run in precision T: the MLS shape functions, their derivatives and the stiffness and mass
// kernels in T (the sparse matrices, their factorisation and the Newmark vectors stay double).
template <class T>
int run_case(const pm::io::EfgScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const auto t0 = std::chrono::steady_clock::now();
  pm::efg::Efg<T> model(scene.config);
  const auto& c = scene.config;
  nlohmann::json j = pm::apps::summary_header("efg", scene.header);
  j["state"] = c.plane_strain ? "plane_strain" : "plane_stress";
  j["j_band"] = c.j_band;  // J' on each path: the mean over r +- j_band h(r) / 2 (0: single circles)
  if (scene.dynamic) return pm::apps::efg_case::run_dynamic(scene, model, opt, ropt, j);
  pm::apps::CaseSpec spec("efg", scene.header, 0);
  spec.checkpoints = false;  // one solve
  pm::apps::Case cs(spec, opt, ropt);
  model.solve_static();
  const auto sif = pm::efg::static_sif(model, scene.handbook);
  for (std::size_t p = 0; p < sif.radii.size() && !opt.quiet; ++p)
    std::printf("r = %.4g m: J = %.6g N/m, K_I = %.6g Pa m^0.5, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%)\n", sif.radii[p], sif.j[p],
                sif.k[p], sif.factor[p], scene.handbook, 100 * sif.error[p]);
  const auto nodal = pm::efg::nodal_fields(model);
  cs.snapshots(pm::apps::point_mesh(2, model.layout().nodes), "fields", true)
      .add(0, 0.0, pm::io::Fields{{"displacement", 2, nodal.displacement}, {"stress", 3, nodal.stress}});
  cs.snapshots().finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& t = model.timings();
  j["nodes"] = model.nodes();
  j["gauss_points"] = model.layout().quad_count();
  j["crack"] = c.crack == pm::efg::CrackKind::edge ? "edge" : "centre";
  j["a_over_w"] = pm::efg::a_over_w(c);
  j["handbook_factor"] = scene.handbook;
  j["sif_static"] = pm::apps::json_pairs(sif.paths());
  j["sif_mean"] = sif.mean;
  j["sif_error"] = sif.mean_error;
  j["sif_max_abs_error"] = sif.max_abs_error();
  j["j_path_spread"] = sif.spread;
  j["crack_opening"] = model.opening_at(0.0);  // at the crack's centre (centre crack) or mouth (edge crack)
  j["shape_seconds"] = t.shape_seconds;
  j["assembly_seconds"] = t.assembly_seconds;
  j["solve_seconds"] = t.solve_seconds;
  j["shape_function_points"] = t.evaluations;
  j["shape_function_values"] = t.entries;
  j["shape_function_evaluations_per_second"] = t.evaluations / t.shape_seconds;
  j["wall_seconds"] = wall;
  pm::io::write_csv(cs.out() / "j_paths.csv", pm::efg::StaticSif::header(), sif.columns());
  cs.finish(j, {"summary.json", "j_paths.csv", "fields.h5", "fields.xdmf"});
  std::printf("efg: %d nodes, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%), J path spread %.2f %%, %.2f s; results in %s\n",
              model.nodes(), sif.mean, scene.handbook, 100 * sif.mean_error, 100 * sif.spread, wall, cs.out().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Element-free Galerkin cracked plate: static K_I from the J-integral against the handbook (seed 004)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/efg/edge_crack_static.toml", "out/efg");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "efg", argc, argv)) return *rc;
  return pm::apps::guarded("efg", [&] {
    const auto scene = pm::io::load_efg_scene(opt.scene, {opt.accuracy, opt.precision});
    if (!scene.dynamic && opt.steps > 0)
      throw std::invalid_argument("--steps " + std::to_string(opt.steps) + ": does not apply: " + opt.scene.string() +
                                  " is a static scene (one solve); --steps sets the length of the dynamic scenes");
    if (!scene.dynamic && !ropt.restart.empty())
      throw std::invalid_argument("--restart: " + opt.scene.string() + " is a static scene (one solve: nothing to resume)");
    if (pm::apps::announce_cost("efg", scene.header, scene.cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    return pm::apps::with_precision(scene.header.precision, [&](auto t) { return run_case<decltype(t)>(scene, opt, ropt); });
  });
}
