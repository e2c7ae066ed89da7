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
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "io/solid_scene.hpp"
#include "solid/micro_cantilever_case.hpp"

namespace pm = polymech;
namespace so = polymech::solid;
namespace mt = polymech::materials;
namespace est = polymech::estimation;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kPaperRunsPerSpecimen = 30;  // the paper's response surface: 30 forward runs per specimen (section 5)

mt::CubicHillParameters<double> parameters(const pm::io::SolidCrystal& c) {
  mt::CubicHillParameters<double> p;
  p.elastic.C11 = c.C11;
  p.elastic.C12 = c.C12;
  p.elastic.C44 = c.C44;
  p.yield_stress = c.yield_stress;
  p.hardening_exponent = c.hardening_exponent;
  p.R12 = c.R12;
  p.form = c.hill_form == "as_printed" ? mt::HillForm::as_printed : mt::HillForm::yield_stress_ratio;
  return p;
}

so::CurveSpec curve_spec(const pm::io::SolidScene& s, double h_root) {
  so::CurveSpec c;
  so::MicroCantileverSpec& b = c.beam;
  b.length = s.beam.length;
  b.width = s.beam.width;
  b.height = s.beam.height;
  b.wall = s.beam.wall;
  b.support_length = s.beam.support_length;
  b.support_width = s.beam.support_width;
  b.support_depth = s.beam.support_depth;
  b.order = s.mesh.order;
  b.h_root = h_root;
  b.growth = s.mesh.growth;
  b.h_beam_max = std::max(s.mesh.h_beam_max, h_root);
  b.support_growth = s.mesh.support_growth;
  b.h_support_max = std::max(s.mesh.h_support_max, h_root);
  b.force = s.beam.peak_force;
  c.load_increments = s.load_increments;
  c.unload_increments = s.unload_increments;
  c.newton.tolerance = s.newton.tolerance;
  c.newton.max_iterations = s.newton.max_iterations;
  c.newton.line_search = s.newton.line_search;
  c.newton.max_cuts = s.newton.max_cuts;
  c.newton.solver = s.newton.solver == "direct"        ? so::TangentSolver::direct
                    : s.newton.solver == "elastic_pcg" ? so::TangentSolver::elastic_pcg
                                                       : so::TangentSolver::two_level_pcg;
  c.newton.forcing = s.newton.solver == "direct" ? 0.0 : s.newton.forcing;
  return c;
}

// The curve of a linear elastic beam (no effect "plasticity": Config::plasticity left empty, no history): the
// same load path and tip measure as solid::load_unload_curve, one Newton iteration per step.
template <class T>
so::LoadUnloadCurve elastic_curve(const so::CurveSpec& s, const mt::CubicHillParameters<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const so::Config<3> c = so::micro_cantilever(s.beam, so::cantilever_law(p, s.beam.theta_degrees).C);
  so::ElastoPlastic<T, 3> m(c, s.newton);
  const std::vector<double> f = pm::models::to_host(m.external_force());
  double F = 0.0;
  for (std::size_t i = 2; i < f.size(); i += 3) F -= f[i];
  so::Monitor mon;
  mon.displacement = [&f, F](const std::vector<double>& u) {
    double w = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) w += f[i] * u[i];
    return w / F;
  };
  so::LoadPath path;
  path.points = {0.0, 1.0};
  path.increments = {s.load_increments};
  if (s.unload_increments > 0) {
    path.points.push_back(0.0);
    path.increments.push_back(s.unload_increments);
  }
  so::LoadUnloadCurve out;
  out.dofs = m.dof_count();
  out.points = m.element_count() * m.points_per_element();
  for (const so::StepResult& r : m.run(path, mon)) {  // an elastic step never cuts: every step is a planned one
    out.newton_iterations += r.newton_iterations;
    out.linear_iterations += r.linear_iterations;
    out.force.push_back(r.load_factor * s.beam.force);
    out.deflection.push_back(r.displacement);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

double peak(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

// One angle's summary entry.
nlohmann::json curve_json(const pm::io::SolidScene& s, double theta, const so::LoadUnloadCurve& c) {
  const mt::CubicConstants<double> k{s.crystal.C11, s.crystal.C12, s.crystal.C44};
  const double E = mt::cubic_uniaxial_modulus(k, mt::cantilever_axis(theta * kPi / 180.0));
  so::MicroCantileverSpec b;
  b.length = s.beam.length;
  b.width = s.beam.width;
  b.height = s.beam.height;
  b.wall = s.beam.wall;
  const double I = so::pentagon_section(b).second_moment;
  nlohmann::json j;
  j["angle"] = theta;
  j["uniaxial_modulus"] = E;
  j["beam_theory_compliance"] = std::pow(s.beam.length, 3) / (3.0 * E * I);  // Euler-Bernoulli, clamped root
  j["compliance"] = c.force.empty() ? 0.0 : c.deflection.front() / c.force.front();
  j["peak_force"] = peak(c.force);
  j["peak_deflection"] = peak(c.deflection);
  j["residual_deflection"] = s.unload_increments > 0 ? c.residual_deflection() : std::numeric_limits<double>::quiet_NaN();
  j["max_plastic_points"] = c.max_plastic_points;
  j["quadrature_points"] = c.points;
  j["newton_iterations"] = c.newton_iterations;
  j["linear_iterations"] = c.linear_iterations;
  j["step_cuts"] = c.cuts;
  j["wall_seconds"] = c.seconds;
  return j;
}

void progress_line(const pm::apps::Case& cs, double theta, const so::LoadUnloadCurve& c, std::size_t k, std::size_t n) {
  if (cs.quiet()) return;
  std::fprintf(stderr, "  [%zu/%zu] theta = %.4g deg: peak deflection %.4g um, residual %.4g um, %lld plastic points, "
               "%d Newton iterations (%d cuts), %.1f s\n",
               k + 1, n, theta, peak(c.deflection), c.residual_deflection(), static_cast<long long>(c.max_plastic_points),
               c.newton_iterations, c.cuts, c.seconds);
}

template <class T>
int run_case(const pm::io::SolidScene& scene, const pm::apps::CommonOptions& opt, const std::vector<double>& angles, bool inverse) {
  const int increments = scene.load_increments + scene.unload_increments;
  pm::apps::CaseSpec spec("micro_cantilever", scene.header, static_cast<std::int64_t>(increments * angles.size()), 0.0,
                          inverse ? "inverse" : "");
  spec.checkpoints = false;  // curves of seconds to minutes each
  spec.progress = false;     // one line per curve
  pm::apps::Case cs(spec, opt, pm::apps::RestartOptions{});
  const auto p = parameters(scene.crystal);
  const so::CurveSpec base = curve_spec(scene, scene.mesh.h_root);
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
  std::vector<double> ca, cs_, cf, cd;  // curves.csv columns
  auto add_rows = [&](double theta, const so::LoadUnloadCurve& c) {
    for (std::size_t i = 0; i < c.force.size(); ++i) {
      ca.push_back(theta);
      cs_.push_back(static_cast<double>(i + 1));
      cf.push_back(c.force[i]);
      cd.push_back(c.deflection[i]);
    }
  };
  // A curve whose Newton iteration fails (the step cut max_cuts times: std::runtime_error naming the load
  // factor reached) ends the run as "diverged" in summary.json, with the reason and the angle; the curves
  // finished before it are kept in summary.json and curves.csv; exit code 1.
  pm::models::RunStats stats;
  if (!inverse) {
    nlohmann::json per = nlohmann::json::array();
    for (std::size_t k = 0; k < angles.size(); ++k) {
      so::CurveSpec c = base;
      c.beam.theta_degrees = angles[k];
      so::LoadUnloadCurve curve;
      try {
        curve = scene.plasticity ? so::load_unload_curve<T>(c, p) : elastic_curve<T>(c, p);
      } catch (const std::runtime_error& e) {
        stats.diverged = true;
        stats.bad_step = static_cast<std::int64_t>(k);
        stats.last_good_step = static_cast<std::int64_t>(k) - 1;
        stats.reason = "the curve at theta = " + pm::io::format_number(angles[k]) + " deg failed: " + e.what();
        j["failed_angle"] = angles[k];
        break;
      }
      progress_line(cs, angles[k], curve, k, angles.size());
      if (k == 0) j["dofs"] = curve.dofs;
      per.push_back(curve_json(scene, angles[k], curve));
      add_rows(angles[k], curve);
    }
    j["curves"] = per;
  } else {
    so::InverseStudySpec st;
    st.truth = p;
    st.start = parameters(scene.inverse->start);
    st.experiment = curve_spec(scene, scene.inverse->experiment_h_root);
    st.estimator = base;
    st.angles = angles;
    st.noise = scene.inverse->noise;
    st.seed = scene.inverse->seed;
    st.options.max_iterations = scene.inverse->max_iterations;
    st.options.model_accuracy = scene.inverse->model_accuracy;
    std::fprintf(stderr, "  inverse study: experiment h_root %.3g um, estimator h_root %.3g um, noise %.3g um, seed %u\n",
                 scene.inverse->experiment_h_root, scene.mesh.h_root, st.noise, st.seed);
    const so::InverseStudy r = so::run_inverse_study<T>(st, [&](const std::string& line) {
      if (!cs.quiet()) std::fprintf(stderr, "  %s\n", line.c_str());
    });
    if (!cs.quiet()) std::fprintf(stderr, "  fit: %d forward runs, %.1f s\n", r.result.forward_runs, r.result.wall_seconds);
    std::printf("%s", est::describe(r.result).c_str());
    nlohmann::json per = nlohmann::json::array();
    std::vector<double> fa, fs, ff, fm, fe, fv;
    for (std::size_t k = 0; k < angles.size(); ++k) {
      nlohmann::json e = curve_json(scene, angles[k], r.experiments[k]);
      e["fitted_peak_deflection"] = peak(r.fitted[k].deflection);
      e["fitted_residual_deflection"] = r.fitted[k].residual_deflection();
      per.push_back(e);
      add_rows(angles[k], r.experiments[k]);
      for (std::size_t i = 0; i < r.fitted[k].force.size(); ++i) {
        fa.push_back(angles[k]);
        fs.push_back(static_cast<double>(i + 1));
        ff.push_back(r.fitted[k].force[i]);
        fm.push_back(r.measured[k][i]);
        fe.push_back(r.experiments[k].deflection[i]);
        fv.push_back(r.fitted[k].deflection[i]);
      }
    }
    j["dofs"] = r.fitted.empty() ? 0 : r.fitted.front().dofs;
    j["experiment_dofs"] = r.experiments.empty() ? 0 : r.experiments.front().dofs;
    j["experiment_h_root"] = scene.inverse->experiment_h_root;
    j["curves"] = per;  // the experiment's (noise-free) curves of the hidden truth
    j["noise"] = st.noise;
    j["seed"] = st.seed;
    j["truth"] = so::to_vector(st.truth);
    j["start"] = so::to_vector(st.start);
    j["parameter_names"] = so::hill_parameter_names();
    j["inverse"] = nlohmann::json::parse(est::to_json(r.result));
    j["experiment_seconds"] = r.experiment_seconds;
    j["fit_seconds"] = r.result.wall_seconds;
    j["forward_runs"] = r.result.forward_runs;
    j["forward_runs_per_specimen"] = static_cast<double>(r.result.forward_runs) / static_cast<double>(angles.size());
    j["paper_forward_runs_per_specimen"] = kPaperRunsPerSpecimen;
    pm::io::write_csv(cs.out() / "fitted.csv", {"angle", "step", "force", "measured", "experiment", "fitted"},
                      {fa, fs, ff, fm, fe, fv});
    files.push_back("fitted.csv");
    std::printf("cost: %d forward runs (%.1f per orientation; the paper's response surface: %d per specimen), fit %.1f s, "
                "experiment %.1f s\n",
                r.result.forward_runs, static_cast<double>(r.result.forward_runs) / angles.size(), kPaperRunsPerSpecimen,
                r.result.wall_seconds, r.experiment_seconds);
    if (r.result.reason == est::StopReason::ModelFailure) {
      stats.diverged = true;
      stats.reason = "the fit stopped: the forward model failed (" + r.result.message + ")";
    }
  }
  pm::io::write_csv(cs.out() / "curves.csv", {"angle", "step", "force", "deflection"}, {ca, cs_, cf, cd});
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
