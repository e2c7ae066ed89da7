// Element-free Galerkin cracked plates (seed 004, Hagihara et al.), static stage: an edge or centre crack
// in tension (a scene of scenes/efg/), solved with MLS shape functions; the J-integral on circles
// around the tip gives K_I, compared with the Tada, Paris & Irwin handbook value. A scene with
// [dynamic] runs the stationary or running crack under a step load through models::run.
//   efg [--scene scenes/efg/edge_crack_static.toml] [--out out/efg] [--accuracy draft|standard|paper]
//       [--steps N] [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]   (the last four: dynamic)
// Static: writes summary.json (nodes, gauss_points, handbook_factor, sif_static [[radius_m, K/(s sqrt(pi a))], ...],
// sif_error (mean over the paths), j_path_spread, crack_opening (at the crack centre or mouth), timings,
// shape_function_evaluations_per_second, wall_seconds), j_paths.csv and a snapshot efg.xdmf/.h5 of
// the displacement at the nodes. Dynamic: summary.json (sif_stationary or sif_running, crack_opening,
// sif_peak, energy_error, run record) and sif_history.csv; checkpoints and --restart as in
// apps/common/restart.hpp.
#include <algorithm>
#include <cstdint>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/app.hpp"
#include "apps/common/restart.hpp"
#include "efg/efg.hpp"
#include "io/efg_scene.hpp"

namespace pm = polymech;

namespace {

// The stationary or running crack under a Heaviside step (seed 004 §3.2, §3.3) through the shared run
// driver (models::run: checkpoints, --restart, watchdog): Newmark steps, J' on every path and the crack
// opening at the centre every output_every steps; energy balance of the average-acceleration rule.
template <class T>
int run_dynamic(const pm::io::EfgScene& scene, pm::efg::Efg<T>& model, pm::apps::CommonOptions opt,
                const pm::apps::RestartOptions& ropt, nlohmann::json& j) {
  const auto& c = scene.config;
  const auto steps = opt.steps > 0 ? opt.steps : static_cast<std::int64_t>(std::ceil(scene.duration / scene.dt - 1e-9));
  pm::apps::Checkpoints checkpoints(opt, ropt, pm::apps::run_key("efg", scene.header, steps));
  pm::io::make_output_dir(opt.out);
  model.assemble();
  model.start_dynamic(scene.dt);
  model.set_prescribed_growth(true);
  // the samples: time [us], mean K factor, crack opening, energy balance, load work, J' path spread,
  // then K factor on each path
  const std::size_t paths = c.j_radii.size();
  std::vector<std::vector<double>> series(6 + paths);
  double j_seconds = 0.0;
  auto sample = [&](std::int64_t) {
    const auto tj = std::chrono::steady_clock::now();
    double lo = 1e300, hi = -1e300, sum = 0.0;
    for (std::size_t p = 0; p < paths; ++p) {
      const auto r = model.dynamic_j(c.j_radii[p], scene.domain_cells);
      series[6 + p].push_back(r.factor);
      sum += r.factor;
      lo = std::min(lo, r.j);
      hi = std::max(hi, r.j);
    }
    j_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - tj).count();
    const double f = sum / static_cast<double>(paths);
    const double t_us = model.time() * 1e6;
    const double cod = model.dynamic_opening_at(0.0);
    const double spread = hi > 0 ? (hi - lo) / hi : 0.0;
    series[0].push_back(t_us);
    series[1].push_back(f);
    series[2].push_back(cod);
    series[3].push_back(model.kinetic_energy() + model.strain_energy() - model.load_work());
    series[4].push_back(model.load_work());
    series[5].push_back(spread);
    if (!opt.quiet)
      std::printf("t = %7.3f us: a = %.4g mm, K/(s sqrt(pi a0)) = %.4f (J' spread %.2f %%), COD = %.4e m\n", t_us, 1e3 * model.crack_length(), f,
                  100 * spread, cod);
  };
  pm::models::RunHooks hooks;
  hooks.sample_every = scene.output_every;
  hooks.sample_at_start = true;
  hooks.sample = sample;
  checkpoints.attach(hooks, [&](pm::models::Archive& a) {
    a.put_columns("efg/series", series);
    a.put("efg/j_seconds", j_seconds);
  }, opt.quiet);
  if (hooks.resume) {
    series = hooks.resume->get_columns<double>("efg/series");
    if (series.size() != 6 + paths) throw std::invalid_argument("checkpoint: efg/series has the wrong number of columns");
    j_seconds = hooks.resume->get<double>("efg/j_seconds");
  }
  const auto stats = pm::models::run(model, steps - checkpoints.resume_step(), hooks);
  if (stats.diverged)
    std::fprintf(stderr, "[efg] the run diverged at step %lld: %s\n", static_cast<long long>(stats.bad_step), stats.reason.c_str());

  nlohmann::json sif = nlohmann::json::array(), opening = nlohmann::json::array();
  double worst_energy = 0.0, max_work = 0.0, peak = -1.0, peak_spread = 0.0, peak_t = 0.0;
  for (std::size_t i = 0; i < series[0].size(); ++i) {
    const double t_us = series[0][i], f = series[1][i];
    sif.push_back({t_us, f});
    opening.push_back({t_us, series[2][i]});
    worst_energy = std::max(worst_energy, std::abs(series[3][i]));
    max_work = std::max(max_work, std::abs(series[4][i]));
    if (f > peak) {
      peak = f;
      peak_t = t_us;
      peak_spread = series[5][i];
    }
  }
  const double wall = stats.wall_seconds;
  const auto& t = model.timings();
  j["mode"] = "dynamic";
  pm::apps::put_run_record(j, stats);
  j["nodes"] = model.nodes() - model.split_nodes();  // the layout's (a split path node counts once)
  j["gauss_points"] = model.layout().quad_count();
  if (c.growth_speed > 0) {
    j["path_nodes"] = c.path_nodes;
    j["split_nodes"] = model.split_nodes();  // path nodes the tip passed, each now one per face
  }
  j["state"] = c.plane_strain ? "plane_strain" : "plane_stress";
  j["dt"] = scene.dt;
  j["steps"] = stats.steps;
  j[c.growth_speed > 0 ? "sif_running" : "sif_stationary"] = sif;
  if (c.growth_speed > 0) {
    j["growth_speed"] = c.growth_speed;
    j["growth_start_us"] = c.growth_start * 1e6;
    j["final_crack_length"] = c.final_crack_length;
  }
  j["crack_opening"] = opening;
  j["sif_peak"] = peak;
  j["sif_peak_time_us"] = peak_t;
  j["j_path_spread"] = peak_spread;
  j["j_radii"] = c.j_radii;
  j["j_band"] = c.j_band;  // J' on each path: the mean over r +- j_band h(r) / 2 (0: single circles)
  j["energy_error"] = max_work > 0 ? worst_energy / max_work : 0.0;
  // timings of this process (a resumed run: since its restart)
  j["assembly_seconds"] = t.assembly_seconds;
  j["shape_seconds"] = t.shape_seconds;
  j["factor_seconds"] = t.factor_seconds;
  const auto done = stats.steps - checkpoints.resume_step();
  j["step_seconds_per_step"] = done > 0 ? t.step_seconds / static_cast<double>(done) : 0.0;
  j["j_seconds"] = j_seconds;
  j["wall_seconds"] = wall;
  pm::io::write_json(opt.out / "summary.json", j);
  std::vector<std::string> header{"t_us", "K_factor_mean", "crack_opening_m", "energy_balance_J"};
  pm::io::Columns cols{series[0], series[1], series[2], series[3]};
  for (std::size_t p = 0; p < paths; ++p) {
    char name[64];
    std::snprintf(name, sizeof name, "K_factor_r%.3gmm", c.j_radii[p] * 1e3);
    header.push_back(name);
    cols.push_back(series[6 + p]);
  }
  pm::io::write_csv(opt.out / "sif_history.csv", header, cols);
  checkpoints.finished();
  std::printf("efg: %d nodes (%d path nodes split), %lld steps, peak K/(s sqrt(pi a)) = %.4f at %.2f us (J' path spread %.2f %%), energy error %.2e, %.2f s; results in %s\n",
              model.nodes() - model.split_nodes(), model.split_nodes(), static_cast<long long>(stats.steps), peak, peak_t, 100 * peak_spread, max_work > 0 ? worst_energy / max_work : 0.0, wall,
              opt.out.c_str());
  return stats.diverged ? 1 : 0;
}

// A scene's run in precision T: the MLS shape functions, their derivatives and the stiffness and mass
// kernels in T (the sparse matrices, their factorisation and the Newmark vectors stay double).
template <class T>
int run_case(const pm::io::EfgScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const auto t0 = std::chrono::steady_clock::now();
  pm::efg::Efg<T> model(scene.config);
  const auto& c = scene.config;
  nlohmann::json j = pm::apps::summary_header("efg", scene.header);
  if (scene.dynamic) return run_dynamic(scene, model, opt, ropt, j);
  pm::io::make_output_dir(opt.out);
  model.solve_static();
  std::vector<double> radii, js, ks, fs, errs;
  nlohmann::json sif = nlohmann::json::array();
  double lo = 1e300, hi = -1e300;
  for (double r : c.j_radii) {
    const auto res = model.j_integral(r);
    radii.push_back(r);
    js.push_back(res.j);
    ks.push_back(res.k);
    fs.push_back(res.factor);
    errs.push_back(res.factor / scene.handbook - 1);
    sif.push_back({r, res.factor});
    lo = std::min(lo, res.j);
    hi = std::max(hi, res.j);
    if (!opt.quiet)
      std::printf("r = %.4g m: J = %.6g N/m, K_I = %.6g Pa m^0.5, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%)\n", r, res.j,
                  res.k, res.factor, scene.handbook, 100 * errs.back());
  }
  double mean = 0;
  for (double f : fs) mean += f;
  mean /= static_cast<double>(fs.size());
  const double cod = model.opening_at(c.crack == pm::efg::CrackKind::centre ? 0.0 : 0.0);
  // displacement at the nodes (MLS values: the nodal coefficients are not the displacements)
  const auto& nodes = model.layout().nodes;
  const auto v = model.fields_at(nodes, "node");
  pm::io::SnapshotMesh mesh;
  mesh.dim = 2;
  mesh.points = nodes;
  pm::io::SnapshotWriter snap(opt.out, "efg", mesh, true);
  pm::io::SnapshotField disp{"displacement", 2, {}};
  pm::io::SnapshotField sig{"stress", 3, {}};
  const auto& cf = model.config();
  const double nu = cf.poisson, mu = cf.young / (2 * (1 + nu));
  double lam = cf.young * nu / ((1 + nu) * (1 - 2 * nu));
  if (!cf.plane_strain) lam = 2 * lam * mu / (lam + 2 * mu);
  for (std::size_t i = 0; i < v.size() / 6; ++i) {
    const double* g = &v[6 * i];
    disp.values.insert(disp.values.end(), {g[0], g[1]});
    sig.values.insert(sig.values.end(), {(lam + 2 * mu) * g[2] + lam * g[5], lam * g[2] + (lam + 2 * mu) * g[5], mu * (g[3] + g[4])});
  }
  snap.add(0, 0.0, pm::io::Fields{disp, sig});
  snap.finish();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const auto& t = model.timings();
  j["nodes"] = model.nodes();
  j["gauss_points"] = model.layout().quad_count();
  j["crack"] = c.crack == pm::efg::CrackKind::edge ? "edge" : "centre";
  j["a_over_w"] = c.crack == pm::efg::CrackKind::edge ? c.crack_length / c.width : c.crack_length / (0.5 * c.width);
  j["state"] = c.plane_strain ? "plane_strain" : "plane_stress";
  j["handbook_factor"] = scene.handbook;
  j["sif_static"] = sif;
  j["sif_mean"] = mean;
  j["sif_error"] = mean / scene.handbook - 1;
  j["sif_max_abs_error"] = std::abs(*std::max_element(errs.begin(), errs.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }));
  j["j_path_spread"] = (hi - lo) / hi;
  j["j_band"] = c.j_band;
  j["crack_opening"] = cod;
  j["shape_seconds"] = t.shape_seconds;
  j["assembly_seconds"] = t.assembly_seconds;
  j["solve_seconds"] = t.solve_seconds;
  j["shape_function_points"] = t.evaluations;
  j["shape_function_values"] = t.entries;
  j["shape_function_evaluations_per_second"] = t.evaluations / t.shape_seconds;
  j["wall_seconds"] = wall;
  pm::io::write_json(opt.out / "summary.json", j);
  pm::io::write_csv(opt.out / "j_paths.csv", {"radius_m", "J_N_per_m", "K_Pa_sqrt_m", "K_factor", "handbook_factor_error"},
                    pm::io::Columns{radii, js, ks, fs, errs});
  std::printf("efg: %d nodes, K/(s sqrt(pi a)) = %.5f (handbook %.5f, %+.2f %%), J path spread %.2f %%, %.2f s; results in %s\n",
              model.nodes(), mean, scene.handbook, 100 * (mean / scene.handbook - 1), 100 * (hi - lo) / hi, wall, opt.out.c_str());
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
    const auto scene = pm::io::load_efg_scene(opt.scene, opt.precision, opt.accuracy);
    if (pm::apps::announce_cost("efg", scene.header, scene.cost, opt)) return 0;
    if (!scene.dynamic && !ropt.restart.empty())
      throw std::invalid_argument("--restart: " + opt.scene.string() + " is a static scene (one solve: nothing to resume)");
    pm::apps::KokkosSession kokkos(opt);
    return scene.header.precision == "float" ? run_case<float>(scene, opt, ropt) : run_case<double>(scene, opt, ropt);
  });
}
