// The Turek-Hron CFD tests of apps/turek_hron (issue 36; seed 002 paper 1 eqs. (1)-(3) on a fixed mesh): the
// channel with the cylinder and the rigid flag, Taylor-Hood Q2/Q1 (models/flow), steady (CFD1, CFD2: Newton)
// or periodic (CFD3: BDF2 from rest with the inflow ramped, checkpoints and --restart: apps/turek_hron/loop_checkpoints.hpp);
// what they write: apps/turek_hron/main.cpp.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "apps/turek_hron/cases.hpp"
#include "apps/turek_hron/loop_checkpoints.hpp"
#include "common/host_copy.hpp"
#include "flow/analysis.hpp"
#include "flow/time_state_archive.hpp"
#include "flow/turek_hron.hpp"
#include "io/flow_scene.hpp"

namespace pm = polymech;
namespace fl = polymech::flow;

namespace {

double cpu_seconds(std::clock_t c0) { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; }

fl::TurekHronCase case_of(const pm::io::FlowSetup& s) {
  fl::TurekHronCase c;
  c.mean_velocity = s.mean_velocity;
  c.ramp_time = s.transient ? s.ramp_time : 0.0;
  c.rho = s.density;
  c.nu = s.viscosity;
  c.level = s.level;
  c.kick_omega = s.kick_omega;
  c.kick_start = s.kick_start;
  c.kick_duration = s.kick_duration;
  return c;
}

// The flow model's configuration from the scene (the solver's settings on the case's geometry and fluid; the
// chord iteration for time steps only).
fl::FlowConfig flow_config(const pm::io::FlowSetup& s) {
  fl::FlowConfig cfg = fl::turek_hron_config(case_of(s));
  cfg.picard_steps = s.picard_steps;
  cfg.newton_max = s.max_iterations + s.picard_steps;
  cfg.newton_tol = s.tolerance;
  cfg.chord = s.transient && s.chord;
  return cfg;
}

// The channel's geometry: the benchmark's, with the ring graded towards the circle where the scene asks.
fl::TurekHronGeometry geometry_of(const pm::io::FlowSetup& s) {
  fl::TurekHronGeometry g;
  g.ring_grading = s.ring_grading;
  return g;
}

void put_reference(nlohmann::json& j, int test, bool benchmark_values) {
  const auto r = fl::turek_hron_reference(test);
  j["reference"] = {{"source", "Turek & Hron 2006, Tables 12-13"}, {"drag_mean", r.drag}, {"lift_mean", r.lift},
                    {"drag_amplitude", r.drag_amplitude}, {"lift_amplitude", r.lift_amplitude}};
  if (test == 3) j["reference"]["frequency"] = r.frequency;
  if (!benchmark_values) j["reference"]["note"] = "the scene changes the benchmark's inflow, density or viscosity";
}

}  // namespace

int pm::apps::run_turek_hron_steady(const pm::io::FlowScene& scene, const pm::apps::CommonOptions& opt) {
  const auto& s = scene.config;
  pm::apps::CaseSpec spec("turek_hron", scene.header, 0);
  spec.checkpoints = false;
  spec.progress = false;
  pm::apps::Case cs(spec, opt, {});
  const std::clock_t c0 = std::clock();
  const auto w0 = std::chrono::steady_clock::now();
  const fl::FlowConfig cfg = flow_config(s);
  fl::NavierStokes2D ns(fl::make_turek_hron_channel(s.level, geometry_of(s)), cfg);
  if (!opt.quiet)
    std::fprintf(stderr, "[turek_hron] %s\n  CFD%d, level %d: %lld cells, %lld unknowns, %s\n", scene.header.title.c_str(), s.test,
                 s.level, static_cast<long long>(ns.mesh().element_count()), static_cast<long long>(ns.unknowns()),
                 pm::apps::thread_count().c_str());
  const auto r = ns.solve_steady();
  const double cpu = cpu_seconds(c0);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  const auto& f = ns.forces();
  const auto ref = fl::turek_hron_reference(s.test);
  nlohmann::json j = cs.summary();
  j["test"] = "cfd" + std::to_string(s.test);
  j["analysis"] = "steady";
  j["level"] = s.level;
  j["ring_grading"] = s.ring_grading;
  j["cells"] = ns.mesh().element_count();
  j["unknowns"] = ns.unknowns();
  j["newton_iterations"] = r.iterations;
  j["converged"] = r.converged;
  j["residual"] = r.residual;
  pm::apps::put_steady_force(j, "drag", f.drag, ref.drag);
  pm::apps::put_steady_force(j, "lift", f.lift, ref.lift);
  j["divergence_l2"] = ns.divergence_l2();
  if (!r.converged)
    j["reason"] = "Newton did not converge in " + std::to_string(r.iterations) + " iterations (residual " +
                  pm::models::format_g(r.residual) + ")";
  j["cpu_seconds"] = cpu;
  j["wall_seconds"] = wall;
  j["cpu_split"] = pm::apps::flow_cpu_split(ns.timings());
  put_reference(j, s.test, s.mean_velocity == std::vector<double>{0.0, 0.2, 1.0, 2.0}[static_cast<std::size_t>(s.test)] &&
                               s.density == 1000.0 && s.viscosity == 1e-3);
  cs.finish(j, {"summary.json"});
  std::printf("turek_hron: CFD%d level %d, %lld unknowns: drag %.5f (%+.3f %%), lift %.5f (%+.3f %%); %d iterations%s, "
              "CPU %.2f s; results in %s\n", s.test, s.level, static_cast<long long>(ns.unknowns()), f.drag,
              100 * (f.drag / ref.drag - 1), f.lift, 100 * (f.lift / ref.lift - 1), r.iterations,
              r.converged ? "" : " (NOT converged)", cpu, cs.out().c_str());
  if (!r.converged) {
    std::fprintf(stderr, "turek_hron: Newton did not converge in %d iterations (residual %.3e)\n", r.iterations, r.residual);
    return 1;
  }
  return 0;
}

int pm::apps::run_turek_hron_transient(const pm::io::FlowScene& scene, const pm::apps::CommonOptions& opt,
                                       const pm::apps::RestartOptions& ropt) {
  const auto& s = scene.config;
  const std::int64_t steps = opt.steps > 0 ? opt.steps : s.steps();
  pm::apps::CaseSpec spec("turek_hron", scene.header, steps, s.dt);
  spec.progress = false;  // the loop below keeps its own io::Progress
  pm::apps::Case cs(spec, opt, ropt);
  // the run so far (per step: t, drag, lift, Newton iterations), into every checkpoint
  std::vector<double> ts, drag, lift, iterations;
  ts.reserve(static_cast<std::size_t>(steps));
  drag.reserve(static_cast<std::size_t>(steps));
  lift.reserve(static_cast<std::size_t>(steps));
  iterations.reserve(static_cast<std::size_t>(steps));
  long newton = 0;
  double next_report = 1.0;
  cs.records.keep("turek_hron/t", ts);
  cs.records.keep("turek_hron/drag", drag);
  cs.records.keep("turek_hron/lift", lift);
  cs.records.keep("turek_hron/newton_iterations", iterations);
  cs.records.keep("turek_hron/newton", newton);
  cs.records.keep("turek_hron/next_report", next_report);
  pm::apps::LoopCheckpoints ck(cs);  // with --restart: the records above are the checkpoint's
  const fl::FlowConfig cfg = flow_config(s);
  fl::NavierStokes2D ns(fl::make_turek_hron_channel(s.level, geometry_of(s)), cfg);
  // CFL of the inflow's peak speed 1.5 Ubar on the smallest node spacing (half the smallest cell edge of the Q2 mesh)
  const auto& m = ns.mesh();
  const double hmin = fl::shortest_cell_edge(m);
  const double cfl = 1.5 * s.mean_velocity * s.dt / (0.5 * hmin);
  if (!opt.quiet)
    std::fprintf(stderr, "[turek_hron] %s\n  CFD%d, level %d: %lld cells, %lld unknowns; BDF2 dt %g s (CFL %.2f at 1.5 Ubar on the "
                 "smallest node spacing %.2e m), %lld steps to t = %g s%s; %s\n", scene.header.title.c_str(), s.test, s.level,
                 static_cast<long long>(m.element_count()), static_cast<long long>(ns.unknowns()), s.dt, cfl, 0.5 * hmin,
                 static_cast<long long>(steps), static_cast<double>(steps) * s.dt,
                 s.kick_omega != 0.0 ? (", kick " + pm::io::format_number(s.kick_omega) + " rad/s at t = " +
                                        pm::io::format_number(s.kick_start) + " s").c_str() : "",
                 pm::apps::thread_count().c_str());
  if (ck.resume()) ns.set_time_state(fl::load_time_state(*ck.resume(), "model/fluid/"));
  // forces.csv: written as the run goes; a restarted run writes the rows of the steps before it again
  FILE* fp = std::fopen((cs.out() / "forces.csv").c_str(), "w");
  if (!fp) throw std::runtime_error("cannot write " + (cs.out() / "forces.csv").string());
  std::fprintf(fp, "t,drag,lift,newton_iterations\n");
  auto write_row = [&](std::int64_t k) {
    const std::size_t i = static_cast<std::size_t>(k - 1);
    if (k % s.sample_every == 0)
      std::fprintf(fp, "%.9g,%.12e,%.12e,%d\n", ts[i], drag[i], lift[i], static_cast<int>(iterations[i]));
  };
  for (std::int64_t k = 1; k <= static_cast<std::int64_t>(ts.size()); ++k) write_row(k);
  pm::io::Progress progress("turek_hron", steps, s.dt, !opt.quiet, 10.0);
  progress.resume_at(ck.first_step());
  bool failed = false;
  std::string reason;
  std::int64_t done = ck.first_step();
  for (std::int64_t k = ck.first_step() + 1; k <= steps; ++k) {
    const auto r = ns.step(s.dt);
    newton += r.iterations;
    if (!r.converged) {
      std::fprintf(stderr, "turek_hron: step %lld (t = %g s): Newton did not converge in %d iterations (residual %.3e)\n",
                   static_cast<long long>(k), ns.time(), r.iterations, r.residual);
      failed = true;
      reason = "step " + std::to_string(k) + " (t = " + pm::models::format_g(ns.time()) + " s): Newton did not converge in " +
               std::to_string(r.iterations) + " iterations (residual " + pm::models::format_g(r.residual) + ")";
      break;
    }
    done = k;
    const auto& f = ns.forces();
    ts.push_back(ns.time());
    drag.push_back(f.drag);
    lift.push_back(f.lift);
    iterations.push_back(r.iterations);
    write_row(k);
    if (k % 50 == 0) std::fflush(fp);
    progress.update(k);
    if (!opt.quiet && ns.time() >= next_report - 1e-9) {
      std::fprintf(stderr, "  t = %.2f s: drag %.3f, lift %.3f, CPU %.0f s\n", ns.time(), f.drag, f.lift, ck.cpu_seconds());
      next_report += 1.0;
    }
    ck.after_step(k, steps, [&](pm::models::Archive& a) { fl::save_time_state(a, "model/fluid/", ns.time_state()); });
  }
  std::fclose(fp);
  progress.done(done);
  const double cpu = ck.cpu_seconds();  // the interrupted processes' included
  const double wall = ck.wall_seconds();
  nlohmann::json j = cs.summary();
  j["test"] = "cfd" + std::to_string(s.test);
  j["analysis"] = "transient";
  j["level"] = s.level;
  j["ring_grading"] = s.ring_grading;
  j["cells"] = m.element_count();
  j["unknowns"] = ns.unknowns();
  j["dt"] = s.dt;
  j["cfl_inflow_smallest_cell"] = cfl;  // 1.5 Ubar on the smallest node spacing (an upper bound)
  j["cfl"] = fl::flow_cfl(ns, s.dt);          // the flow's at the end: max |u| dt / node spacing over the cells
  j["steps"] = done;
  if (failed) j["reason"] = reason;
  j["end_time"] = ns.time();
  j["newton_iterations"] = newton;
  j["kick"] = {{"omega", s.kick_omega}, {"start", s.kick_start}, {"duration", s.kick_duration}};
  j["cpu_seconds"] = cpu;
  j["cpu_seconds_per_step"] = done > 0 ? cpu / static_cast<double>(done) : 0.0;
  j["wall_seconds"] = wall;
  j["cpu_split"] = pm::apps::flow_cpu_split(ns.timings());  // this process's (a restarted run: since the restart)
  j["restarts"] = ck.restarts();
  put_reference(j, s.test, s.mean_velocity == 2.0 && s.density == 1000.0 && s.viscosity == 1e-3);
  fl::PeriodicStats d, l;
  bool periodic = !failed && fl::period_stats(ts, drag, lift, 0, d, l);
  if (periodic) periodic = l.amplitude > 1e-3 * (std::abs(l.mean) + std::abs(d.mean));  // round-off wiggles are no shedding
  j["periodic"] = periodic;
  if (periodic) {
    j["drag_mean"] = d.mean;
    j["drag_amplitude"] = d.amplitude;
    j["lift_mean"] = l.mean;
    j["lift_amplitude"] = l.amplitude;
    j["frequency"] = l.frequency;
    j["period_window"] = {l.t_begin, l.t_end};
    fl::PeriodicStats dp, lp;
    if (fl::period_stats(ts, drag, lift, 1, dp, lp))
      j["previous_period"] = {{"drag_mean", dp.mean}, {"drag_amplitude", dp.amplitude}, {"lift_mean", lp.mean},
                              {"lift_amplitude", lp.amplitude}, {"frequency", lp.frequency}, {"window", {lp.t_begin, lp.t_end}}};
  } else if (!ts.empty()) {
    j["drag_last"] = drag.back();
    j["lift_last"] = lift.back();
  }
  const int rc = cs.finish(j, {"summary.json", "forces.csv"});
  if (periodic)
    std::printf("turek_hron: CFD3 level %d dt %g to t = %g s: drag %.3f +- %.4f, lift %.3f +- %.3f, %.4f Hz (reference 439.45 +- "
                "5.6183, -11.893 +- 437.81, 4.3956 Hz); CPU %.1f s; results in %s\n", s.level, s.dt, ns.time(), d.mean, d.amplitude,
                l.mean, l.amplitude, l.frequency, cpu, cs.out().c_str());
  else if (!failed)
    std::printf("turek_hron: CFD3 level %d dt %g to t = %g s: no periodic shedding yet (drag %.3f, lift %.3f at the end); CPU %.1f s; "
                "results in %s\n", s.level, s.dt, ns.time(), drag.empty() ? 0.0 : drag.back(), lift.empty() ? 0.0 : lift.back(),
                cpu, cs.out().c_str());
  return failed ? 1 : rc;
}
