// The Turek-Hron FSI2 and FSI3 cases (issue 36; Turek & Hron 2006, section 3.3, Table 13): the elastic SVK flag
// behind the cylinder at Ubar = 1 (FSI2, rho_s = 10 rho_f) and Ubar = 2 (FSI3), the inflow ramped over 2 s, the
// flag's self-excited periodic oscillation. Partitioned Dirichlet-Neumann, strongly coupled in every time step
// (models/fsi/turek_hron_fsi_transient.hpp: BDF2 ALE Taylor-Hood fluid on the pseudo-elastically moved mesh,
// Newmark SVK flag, IQN-ILS / Aitken / relaxation on the wet nodes' displacement, models/fsi/coupling.hpp).
// Writes series.csv as the run goes (t, drag, lift, ux, uy of point A, the step's coupling evaluations, |r|,
// int div u) and summary.json with the benchmark's mean and amplitude over the last period of uy(A)
// (fsi::turek_hron_fsi_period), against Table 13. The loop, its failures, progress, checkpoints and --restart are
// the harvester's too (apps/turek_hron/step_loop.hpp): the coupled model's state (TurekHronFsiTransient::save: fluid,
// mesh, solid, the coupling's IQN-ILS columns) and the rows so far; a resumed run writes series.csv and summary.json
// as one never interrupted.
// The flap (test = "flap", issue 36's weakly coupled check): CSM3's flag under gravity in the fluid at rest
// (fsi::flap_case), the same loop; summary.json's "flap" keys: the period of uy(A) against the same flag's in vacuo
// (fsi::run_flap without the fluid, run after the loop: cheap) and CSM3's reference (Table 6).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "apps/turek_hron/cases.hpp"
#include "apps/turek_hron/step_loop.hpp"
#include "fsi/turek_hron_fsi_transient.hpp"

namespace polymech::apps {

int run_turek_hron_fsi_transient(const io::FlowScene& scene, const CommonOptions& opt, const RestartOptions& ropt) {
  const auto& s = scene.config;
  const std::string test = s.name();
  const std::int64_t steps = opt.steps > 0 ? opt.steps : s.steps();
  CaseSpec spec("turek_hron", scene.header, steps, s.dt);
  spec.progress = false;  // the loop below keeps its own io::Progress
  Case cs(spec, opt, ropt);
  // the run so far (every step's row, the coupling evaluations, the largest |int div u|), into every checkpoint
  double max_div = 0.0;
  CoupledStepLoop<fsi::TurekHronFsiStep> loop(cs, "turek_hron", steps, s, 0.5,
                                              [&max_div](Records& r) { r.keep("turek_hron/max_div", max_div); });
  // flap: CSM3's flag under gravity in the fluid at rest (fsi::flap_case; the scene's inflow, density, viscosity below)
  fsi::TurekHronFsiCase c = s.flap ? fsi::flap_case(s.level, s.density, s.viscosity) : fsi::turek_hron_fsi_case(test, s.level);
  c.mean_velocity = s.mean_velocity;
  c.rho_f = s.density;
  c.nu_f = s.viscosity;
  c.ramp_time = s.ramp_time;
  c.fluid_chord = true;
  // the per-step coupling of bench/sweep_turek_hron_fsi's runs (docs/VALIDATION.md): |r| <= tol max(|x~|, 1 mm)
  c.coupling.method = fsi::coupling_method(s.coupling_method);
  c.coupling.omega = s.coupling_omega;
  c.coupling.tolerance = s.coupling_tolerance;
  c.coupling.scale = 1e-3;
  c.coupling.max_iterations = s.coupling_max_iterations;
  c.coupling.reuse = s.coupling_reuse;
  fsi::TurekHronFsiTransient model(c, s.dt);
  const auto ref = s.flap ? fsi::TurekHronFsiPeriodicReference{} : fsi::turek_hron_fsi_periodic_reference(test);
  const char* name = test == "fsi2" ? "FSI2" : test == "fsi3" ? "FSI3" : "flap";
  if (!opt.quiet)
    std::fprintf(stderr, "[turek_hron] %s\n  %s, level %d: %lld fluid unknowns, %lld mesh-motion unknowns, %lld solid DoFs, %zu wet nodes; "
                 "dt %g s (%g at accuracy paper), %lld steps to t = %g s; %s coupling to %g per step; %s\n", scene.header.title.c_str(),
                 name, s.level, static_cast<long long>(model.fluid_unknowns()),
                 static_cast<long long>(model.mesh_unknowns()), static_cast<long long>(model.solid_unknowns()), model.interface_nodes(), s.dt,
                 s.scene_dt, static_cast<long long>(steps), static_cast<double>(steps) * s.dt, s.coupling_method.c_str(), s.coupling_tolerance,
                 thread_count().c_str());
  loop.run(
      model, opt.quiet, "t,drag,lift,ux,uy,evaluations,residual,int_div_u\n",
      [](FILE* fp, const fsi::TurekHronFsiStep& r) {
        std::fprintf(fp, "%.9g,%.12e,%.12e,%.12e,%.12e,%d,%.3e,%.3e\n", r.t, r.drag, r.lift, r.ux, r.uy, r.evaluations, r.residual,
                     r.net_flux);
      },
      [](const fsi::TurekHronFsiStep& r) -> const char* {
        const bool finite = std::isfinite(r.drag) && std::isfinite(r.lift) && std::isfinite(r.ux) && std::isfinite(r.uy);
        return finite ? nullptr : "a non-finite force or displacement";
      },
      [&max_div](const fsi::TurekHronFsiStep& r) { max_div = std::max(max_div, std::abs(r.net_flux)); },
      [](const fsi::TurekHronFsiStep& r) {
        std::fprintf(stderr, "  t = %.2f s: ux(A) %.4e, uy(A) %.4e m, drag %.3f, lift %.3f N/m", r.t, r.ux, r.uy, r.drag, r.lift);
      });
  const auto& rows = loop.rows;
  const double cpu = loop.cpu_seconds();  // the interrupted processes' included
  const double per_step = loop.evaluations_per_step();
  const auto& t = model.timings();
  nlohmann::json j = cs.summary();
  j["test"] = test;
  put_fsi_sizes(j, model, s.level);
  loop.put_summary(j, model);
  j["solid_newton_iterations"] = t.solid_newton;
  j["max_abs_int_div_u"] = max_div;
  j["cpu_split"] = {{"setup", t.setup}, {"mesh_motion", t.mesh}, {"fluid", t.fluid}, {"solid", t.solid}};
  if (s.flap) {
    // the weakly coupled check: the period of uy(A) against the same flag's in vacuo (same mesh, Newmark, dt;
    // fsi::run_flap, the fluid left out), and CSM3's (Turek & Hron 2006, Table 6: 1.0995 Hz, uy(A) down to
    // -63.607e-3 - 65.160e-3 m)
    const double end = rows.empty() ? s.dt : rows.back().t;
    fsi::FlapSwing w, v;
    const bool ok = fsi::flap_swing(rows, w);
    const bool ok_vacuo = fsi::flap_swing(fsi::run_flap(c, s.dt, std::max(end, s.dt), true), v);
    j["flap"] = {{"turning_points", w.turning_points}, {"period", ok ? w.period : 0.0}, {"first_min_uy", ok ? w.first_min : 0.0},
                 {"next_max_uy", ok ? w.first_max : 0.0}, {"period_in_vacuo", ok_vacuo ? v.period : 0.0},
                 {"first_min_uy_in_vacuo", ok_vacuo ? v.first_min : 0.0},
                 {"period_ratio", ok && ok_vacuo ? w.period / v.period : 0.0},
                 {"note", "period: twice the mean half period between the turning points of uy(A) (fsi::flap_swing); 0 until uy(A) has a minimum"}};
    j["reference"] = {{"source", "Turek & Hron 2006, Table 6 (CSM3, the flag in vacuo)"}, {"frequency", 1.0995}, {"uy_min", -128.767e-3}};
    if (ok && ok_vacuo)
      std::printf("turek_hron: flap (rho_f %g) level %d dt %g: period %.5f s, in vacuo %.5f s (x %.4f; CSM3 %.5f s); first min uy(A) %.4e m "
                  "(in vacuo %.4e)\n", s.density, s.level, s.dt, w.period, v.period, w.period / v.period, 1.0 / 1.0995, w.first_min, v.first_min);
  } else {
    j["reference"] = {{"source", "Turek & Hron 2006, Table 13"},
                      {"ux_mean", ref.ux_mean}, {"ux_amplitude", ref.ux_amplitude}, {"uy_mean", ref.uy_mean},
                      {"uy_amplitude", ref.uy_amplitude}, {"drag_mean", ref.drag_mean}, {"drag_amplitude", ref.drag_amplitude},
                      {"lift_mean", ref.lift_mean}, {"lift_amplitude", ref.lift_amplitude}, {"frequency", ref.frequency}};
    const double ubar = test == "fsi2" ? 1.0 : 2.0;
    if (!(s.mean_velocity == ubar && s.density == 1000.0 && s.viscosity == 1e-3 && s.ramp_time == 2.0))
      j["reference"]["note"] = "the scene changes the benchmark's inflow, ramp, density or viscosity";
  }
  fsi::TurekHronFsiPeriod p;
  // a period of uy(A) whose swing is above round-off (1 um: the references' amplitudes are 2.5-80 mm)
  const bool periodic = fsi::turek_hron_fsi_period(rows, 0, p) && p.uy.amplitude > 1e-6;
  j["periodic"] = periodic;
  if (periodic) {
    put_window(j, "ux", p.ux);
    put_window(j, "uy", p.uy);
    put_window(j, "drag", p.drag);
    put_window(j, "lift", p.lift);
    j["frequency"] = p.uy.frequency;
    j["period_window"] = {p.uy.t_begin, p.uy.t_end};
    if (!s.flap)  // the flap's reference is CSM3's in vacuo: its "flap" keys above
      j["errors"] = {{"ux_mean", p.ux.mean / ref.ux_mean - 1.0}, {"ux_amplitude", p.ux.amplitude / ref.ux_amplitude - 1.0},
                   {"uy_mean", p.uy.mean / ref.uy_mean - 1.0}, {"uy_amplitude", p.uy.amplitude / ref.uy_amplitude - 1.0},
                   {"drag_mean", p.drag.mean / ref.drag_mean - 1.0}, {"drag_amplitude", p.drag.amplitude / ref.drag_amplitude - 1.0},
                   {"lift_mean", p.lift.mean / ref.lift_mean - 1.0}, {"lift_amplitude", p.lift.amplitude / ref.lift_amplitude - 1.0},
                   {"frequency", p.uy.frequency / ref.frequency - 1.0}};
    fsi::TurekHronFsiPeriod q;
    if (fsi::turek_hron_fsi_period(rows, 1, q))
      j["previous_period"] = {{"ux_mean", q.ux.mean}, {"ux_amplitude", q.ux.amplitude}, {"uy_mean", q.uy.mean},
                              {"uy_amplitude", q.uy.amplitude}, {"drag_mean", q.drag.mean}, {"drag_amplitude", q.drag.amplitude},
                              {"lift_mean", q.lift.mean}, {"lift_amplitude", q.lift.amplitude}, {"frequency", q.uy.frequency},
                              {"window", {q.uy.t_begin, q.uy.t_end}}};
  } else {
    // no full period of uy(A) yet: the same keys over the whole run (the ramp included), frequency 0
    const double all = -std::numeric_limits<double>::infinity();
    put_window(j, "ux", window_stats(rows, &fsi::TurekHronFsiStep::ux, all));
    put_window(j, "uy", window_stats(rows, &fsi::TurekHronFsiStep::uy, all));
    put_window(j, "drag", window_stats(rows, &fsi::TurekHronFsiStep::drag, all));
    put_window(j, "lift", window_stats(rows, &fsi::TurekHronFsiStep::lift, all));
    j["frequency"] = 0.0;
    j["period_window"] = {rows.empty() ? 0.0 : rows.front().t, rows.empty() ? 0.0 : rows.back().t};
    j["note"] = "no full period of uy(A) yet: the means and amplitudes are over the whole run";
  }
  const int rc = cs.finish(j, {"summary.json", "series.csv"});
  if (periodic && s.flap)
    std::printf("turek_hron: flap level %d dt %g to t = %g s: ux(A) %.4e +- %.4e, uy(A) %.4e +- %.4e m over the last period of uy(A), "
                "%.4f Hz; %.2f evaluations per step; CPU %.1f s; results in %s\n", s.level, s.dt, j["end_time"].get<double>(), p.ux.mean,
                p.ux.amplitude, p.uy.mean, p.uy.amplitude, p.uy.frequency, per_step, cpu, cs.out().c_str());
  else if (periodic)
    std::printf("turek_hron: %s level %d dt %g to t = %g s: ux(A) %.4e +- %.4e, uy(A) %.4e +- %.4e m, drag %.3f +- %.3f, lift %.3f +- %.3f "
                "N/m, %.4f Hz (reference %.4e +- %.4e, %.4e +- %.4e, %.2f +- %.2f, %.2f +- %.2f, %.1f Hz); %.2f evaluations per step; "
                "CPU %.1f s; results in %s\n", name, s.level, s.dt, j["end_time"].get<double>(), p.ux.mean, p.ux.amplitude, p.uy.mean,
                p.uy.amplitude, p.drag.mean, p.drag.amplitude, p.lift.mean, p.lift.amplitude, p.uy.frequency, ref.ux_mean, ref.ux_amplitude,
                ref.uy_mean, ref.uy_amplitude, ref.drag_mean, ref.drag_amplitude, ref.lift_mean, ref.lift_amplitude, ref.frequency, per_step,
                cpu, cs.out().c_str());
  else
    std::printf("turek_hron: %s level %d dt %g to t = %g s: no full period of uy(A) yet (uy %.4e m, drag %.3f, lift %.3f at the end); %.2f "
                "evaluations per step; CPU %.1f s%s; results in %s\n", name, s.level, s.dt, j["end_time"].get<double>(),
                rows.empty() ? 0.0 : rows.back().uy, rows.empty() ? 0.0 : rows.back().drag, rows.empty() ? 0.0 : rows.back().lift, per_step,
                cpu, loop.failed ? " (STOPPED)" : "", cs.out().c_str());
  return loop.exit_code(rc);
}

}  // namespace polymech::apps
