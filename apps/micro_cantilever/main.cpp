// Seed 002 paper 5 (issue 34): the single-crystal 8YSZ micro-cantilever. For every angle of the beam axis
// (from [001] in the (110) plane) the load-unload curve of the finite-element beam with its support block
// (models/solid/micro_cantilever.hpp), Hill plasticity with power-law hardening when the scene lists the
// effect "plasticity" (models/solid/micro_cantilever_case.hpp, load_unload_curve), linear elastic otherwise;
// with --inverse the synthetic inverse study of the paper's section 5 (run_inverse_study): curves of the
// scene's [crystal] (the hidden truth) on a finer mesh plus noise, and the six parameters fitted from the
// estimator's start on the scene's mesh.
//   micro_cantilever [--scene scenes/solid/micro_cantilever.toml] [--out out/micro_cantilever] [--angles 0,54.7]
//                    [--inverse]
// Writes summary.json (per angle: the closed-form uniaxial modulus along the beam axis, the compliance of the
// first load step, the peak and residual deflections, Newton iterations, wall time; with --inverse the
// estimator's result) and curves.csv (angle, step, force, deflection); with --inverse also fitted.csv
// (measured, noise-free experiment and fitted deflection per step). Plot: tools/plot_micro_cantilever_run.py.
// The scene as the model's specs, the curves and the inverse study's summary keys: apps/micro_cantilever/case.hpp.
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "apps/micro_cantilever/case.hpp"
#include "io/solid_scene.hpp"

namespace pm = polymech;
namespace mc = polymech::apps::cantilever;

namespace {

template <class T>
int run_case(const pm::io::SolidScene& scene, const pm::apps::CommonOptions& opt, const std::vector<double>& angles, bool inverse) {
  const int increments = scene.load_increments + scene.unload_increments;
  pm::apps::CaseSpec spec("micro_cantilever", scene.header, static_cast<std::int64_t>(increments * angles.size()), 0.0,
                          inverse ? "inverse" : "");
  spec.checkpoints = false;  // curves of seconds to minutes each
  spec.progress = false;     // one line per curve
  pm::apps::Case cs(spec, opt, pm::apps::RestartOptions{});
  std::fprintf(stderr, "[micro_cantilever] %s\n  accuracy %s (h_root %.3g um, order %d), %s, %s, %s, %zu angle%s\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), scene.mesh.h_root, scene.mesh.order,
               scene.header.precision.c_str(), scene.plasticity ? "Hill plasticity" : "linear elastic",
               pm::apps::thread_count().c_str(), angles.size(), angles.size() == 1 ? "" : "s");
  nlohmann::json j = cs.summary();
  j["C11"] = scene.crystal.C11;
  j["C12"] = scene.crystal.C12;
  j["C44"] = scene.crystal.C44;
  if (scene.plasticity) {
    j["yield_stress"] = scene.crystal.yield_stress;
    j["hardening_exponent"] = scene.crystal.hardening_exponent;
    j["R12"] = scene.crystal.R12;
    j["hill_form"] = scene.crystal.hill_form;
  }
  j["peak_force"] = scene.beam.peak_force;
  j["order"] = scene.mesh.order;
  j["h_root"] = scene.mesh.h_root;
  j["load_increments"] = scene.load_increments;
  j["unload_increments"] = scene.unload_increments;
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> files = {"summary.json", "curves.csv"};
  mc::CurveRows rows;
  pm::models::RunStats stats;
  if (!inverse)
    mc::run_curves<T>(scene, cs, angles, j, rows, stats);
  else
    mc::run_inverse<T>(scene, cs, angles, j, rows, stats, files);
  pm::io::write_csv(cs.out() / "curves.csv", {"angle", "step", "force", "deflection"},
                    {rows.angle, rows.step, rows.force, rows.deflection});
  j["wall_seconds"] = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  for (const auto& e : j["curves"])
    std::printf("theta %7.4g deg: E_axis %6.1f GPa, compliance %.4g um/mN, peak deflection %.4g um, residual %.4g um, "
                "%d Newton iterations, %.1f s\n",
                e["angle"].get<double>(), e["uniaxial_modulus"].get<double>(), e["compliance"].get<double>(),
                e["peak_deflection"].get<double>(), e["residual_deflection"].is_number() ? e["residual_deflection"].get<double>() : 0.0,
                e["newton_iterations"].get<int>(), e["wall_seconds"].get<double>());
  stats.steps = static_cast<std::int64_t>(j["curves"].size());
  const int rc = cs.finish(j, stats, files);
  std::printf("results in %s\n", cs.out().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The 8YSZ micro-cantilever: load-unload curves per orientation, Hill plasticity, inverse study "
               "(seed 002 paper 5)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/solid/micro_cantilever.toml", "out/micro_cantilever");
  pm::apps::refuse_option(app, "--steps", "a curve has the scene's load.load_increments + load.unload_increments steps");
  bool inverse = false;
  std::vector<double> angles;
  app.add_flag("--inverse", inverse, "run the synthetic inverse study of the scene's [inverse] table");
  app.add_option("--angles", angles, "beam angles from [001] in the (110) plane, degrees (default: the scene's beam.angles)")
      ->delimiter(',')
      ->check(CLI::Validator(
          [](std::string& v) -> std::string {
            long double x = 0;
            if (!pm::apps::cli::read_number(v, x) || x < 0 || x > 90)
              return "--angles " + pm::apps::cli::shown(v) + ": must be 0 to 90 (degrees)";
            return "";
          },
          "0..90"));
  if (const auto rc = pm::apps::parse_command_line(app, "micro_cantilever", argc, argv)) return *rc;
  return pm::apps::guarded("micro_cantilever", [&] {
    pm::apps::KokkosSession kokkos(opt);
    pm::io::SceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    const auto scene = pm::io::load_solid_scene(opt.scene, so);
    if (inverse && !scene.inverse)
      throw std::invalid_argument("--inverse: " + opt.scene.string() + " has no [inverse] table (scenes/solid/"
                                  "micro_cantilever_inverse.toml has one)");
    const std::vector<double> run_angles = angles.empty() ? scene.beam.angles : angles;
    const pm::io::CostEstimate cost = pm::io::solid_scene_cost(scene, run_angles.size(), inverse);
    if (pm::apps::announce_cost("micro_cantilever", scene.header, cost, opt)) return 0;
    return pm::apps::with_precision(scene.header.precision, [&](auto t) {
      return run_case<decltype(t)>(scene, opt, run_angles, inverse);
    });
  });
}
