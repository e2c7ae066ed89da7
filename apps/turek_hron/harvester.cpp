// The flow-driven piezoelectric harvester (seed 002 paper 1, case 2, Figs. 3, 5, 6; issue 36): the bimorph plate
// behind the square cylinder in the air stream, its resistor harvesting the wake's forcing
// (models/fsi/flow_harvester.hpp: BDF2 ALE Taylor-Hood fluid on the pseudo-elastically moved mesh, the Newmark
// piezo-structure and circuit, IQN-ILS on the wet nodes' displacement per step; scheme "partitioned" nests the
// piezo-circuit loop of paper 1's Fig. 2 inside the FSI loop as its Fig. 3, "monolithic" solves them together).
// Run from the scene (io/flow_scene.hpp, [case] benchmark = "harvester"):
//   series.csv   as the run goes, every sample_every steps: t, tip, drag, lift, voltage, power, evaluations,
//                circuit_solves, residual (the plate's tip deflection m; the forces on cylinder and plate N/m; the
//                voltage across the resistor V; the power W per metre of span; the step's coupling evaluations,
//                piezo-circuit solves and last coupling residual);
//   summary.json at the end (written whole: io::write_json): the sizes, the cylinder's side and Re = U D / nu, the
//                plate's first short- and open-circuit frequencies, the resistor and capacitance, and over the last
//                `window` seconds the means, amplitudes ((max - min) / 2) and frequencies (upward crossings of the
//                mean) of tip, lift and drag, the voltage amplitude, the mean power, lift_frequency / f1_sc (the
//                lock-in ratio); the coupling evaluations and circuit solves per step, the CPU split. A failed run
//                (the fluid's Newton iteration or the coupling stopped) exits 1 with `reason`.
// The loop, its failures, progress, checkpoints and --restart are FSI2's (apps/turek_hron/step_loop.hpp): the
// model's state (FlowHarvester::save) and every step's row; a resumed run writes series.csv and summary.json as one
// never interrupted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "apps/common/case.hpp"
#include "apps/turek_hron/cases.hpp"
#include "apps/turek_hron/step_loop.hpp"
#include "common/host_copy.hpp"
#include "fsi/flow_harvester.hpp"

namespace polymech::apps {

int run_flow_harvester(const io::FlowScene& scene, const CommonOptions& opt, const RestartOptions& ropt) {
  const auto& s = scene.config;
  const std::int64_t steps = opt.steps > 0 ? opt.steps : s.steps();
  CaseSpec spec("turek_hron", scene.header, steps, s.dt);
  spec.progress = false;  // the loop below keeps its own io::Progress
  Case cs(spec, opt, ropt);
  // every step's row (the window's statistics need them all, series.csv every sample_every-th), the coupling
  // evaluations and circuit solves, into every checkpoint
  long circuit_solves = 0;
  CoupledStepLoop<fsi::FlowHarvesterStep> loop(cs, "harvester", steps, s, 1.0, [&circuit_solves](Records& r) {
    r.keep("harvester/circuit_solves", circuit_solves);
  });

  fsi::FlowHarvesterCase c;
  c.level = s.level;
  c.inflow = s.mean_velocity;
  c.rho_f = s.density;
  c.nu_f = s.viscosity;
  c.side = s.side;
  c.plate_length = s.plate_length;
  c.piezo_thickness = s.piezo_thickness;
  c.host_thickness = s.host_thickness;
  c.ramp_time = s.ramp_time;
  c.gust = s.gust;
  c.resistance = s.resistance;
  c.zeta = s.zeta;
  c.scheme = s.scheme == "partitioned" ? piezo::Scheme::partitioned : piezo::Scheme::monolithic;
  c.dt = s.dt;
  c.smagorinsky = s.smagorinsky;
  // per step |r| <= tol max(|x~|, 1 mm), as fsi2's (the model's default scale)
  c.coupling.method = fsi::coupling_method(s.coupling_method);
  c.coupling.omega = s.coupling_omega;
  c.coupling.tolerance = s.coupling_tolerance;
  c.coupling.scale = 1e-3;
  c.coupling.max_iterations = s.coupling_max_iterations;
  c.coupling.reuse = s.coupling_reuse;
  if (c.side == 0.0) {
    // the lock-in side (the scene checked an explicit one against the plate's thickness): the mesh needs t < D / 2
    const double d = fsi::lock_in_side(c), t = 2.0 * c.piezo_thickness + c.host_thickness;
    if (!(t < 0.5 * d))
      throw std::invalid_argument(scene.header.file.string() + ": key 'case.side' = 0 takes the lock-in side St U / f_1 = " +
                                  models::format_g(d) + " m, and the plate (2 piezo_thickness + host_thickness = " + models::format_g(t) +
                                  " m) must be thinner than half of it; allowed: side > " + models::format_g(2.0 * t) +
                                  " m, or thinner layers");
  }
  fsi::FlowHarvester model(c);
  const double two_pi = 2.0 * 3.14159265358979323846, f1_sc = model.omega_sc() / two_pi, f1_oc = model.omega_oc() / two_pi;
  const double side = model.config().side, reynolds = s.mean_velocity * side / s.viscosity;
  if (!opt.quiet)
    std::fprintf(stderr, "[turek_hron] %s\n  harvester, level %d: %lld fluid cells, %lld fluid unknowns, %zu wet nodes; D %.4g m (Re %.0f), "
                 "plate %g m, f1 %.4g Hz (short circuit), %.4g Hz (open), R %.4g ohm m; dt %g s (%g at accuracy paper), %lld steps to "
                 "t = %g s; %s coupling to %g per step, %s piezo-circuit; %s\n", scene.header.title.c_str(), s.level,
                 static_cast<long long>(model.fluid().mesh().element_count()), static_cast<long long>(model.fluid_unknowns()),
                 model.interface_nodes(), side, reynolds, s.plate_length, f1_sc, f1_oc, model.resistance(), s.dt, s.scene_dt,
                 static_cast<long long>(steps), static_cast<double>(steps) * s.dt, s.coupling_method.c_str(), s.coupling_tolerance,
                 s.scheme.c_str(), thread_count().c_str());
  loop.run(
      model, opt.quiet, "t,tip,drag,lift,voltage,power,evaluations,circuit_solves,residual\n",
      [](FILE* fp, const fsi::FlowHarvesterStep& r) {
        std::fprintf(fp, "%.9g,%.12e,%.12e,%.12e,%.12e,%.12e,%d,%d,%.3e\n", r.t, r.tip, r.drag, r.lift, r.voltage, r.power, r.evaluations,
                     r.circuit_iterations, r.residual);
      },
      [](const fsi::FlowHarvesterStep& r) -> const char* {
        const bool finite = std::isfinite(r.tip) && std::isfinite(r.drag) && std::isfinite(r.lift) && std::isfinite(r.voltage);
        return finite ? nullptr : "a non-finite force, deflection or voltage";
      },
      [&circuit_solves](const fsi::FlowHarvesterStep& r) { circuit_solves += r.circuit_iterations; },
      [](const fsi::FlowHarvesterStep& r) {
        std::fprintf(stderr, "  t = %.2f s: tip %.4e m, drag %.4e, lift %.4e N/m, V %.4e V, P %.3e W/m", r.t, r.tip, r.drag, r.lift,
                     r.voltage, r.power);
      });
  const auto& rows = loop.rows;
  const auto done = loop.done();
  const double cpu = loop.cpu_seconds();  // the interrupted processes' included
  const double per_step = loop.evaluations_per_step();
  const auto& t = model.timings();
  const double end = loop.end_time();
  // the statistics' window: the last `window` seconds of the run (all of it when shorter: --steps)
  const double t0 = end - s.window;
  nlohmann::json j = cs.summary();
  j["test"] = "harvester";
  loop.put_summary(j, model);
  j["level"] = s.level;
  j["cells"] = model.fluid().mesh().element_count();
  j["unknowns"] = model.fluid_unknowns();
  j["interface_nodes"] = model.interface_nodes();
  j["plate_unknowns"] = model.beam().unknowns();
  j["inflow"] = s.mean_velocity;
  j["side"] = side;
  j["side_lock_in"] = s.side == 0.0;
  j["reynolds"] = reynolds;
  j["plate_length"] = s.plate_length;
  j["scheme"] = s.scheme;
  j["smagorinsky"] = s.smagorinsky;
  j["f1_sc_Hz"] = f1_sc;
  j["f1_oc_Hz"] = f1_oc;
  j["resistance"] = model.resistance();
  j["capacitance"] = model.capacitance();
  j["window"] = {std::max(t0, rows.empty() ? 0.0 : rows.front().t), end};
  if (t0 < (rows.empty() ? 0.0 : rows.front().t))
    j["note"] = "the run is shorter than time.window: the statistics are over the whole run (the ramp included)";
  const WindowStats tip = window_stats(rows, &fsi::FlowHarvesterStep::tip, t0);
  const WindowStats lift = window_stats(rows, &fsi::FlowHarvesterStep::lift, t0);
  const WindowStats drag = window_stats(rows, &fsi::FlowHarvesterStep::drag, t0);
  const WindowStats volt = window_stats(rows, &fsi::FlowHarvesterStep::voltage, t0);
  put_window(j, "tip", tip, true);
  put_window(j, "lift", lift, true);
  put_window(j, "drag", drag, false);
  j["voltage_amplitude"] = volt.amplitude;
  double power = 0.0;
  long in_window = 0;
  for (const auto& r : rows)
    if (r.t >= t0) power += r.power, ++in_window;
  j["power_mean"] = in_window > 0 ? power / static_cast<double>(in_window) : 0.0;
  j["lift_frequency_ratio"] = lift.frequency / f1_sc;  // the shedding against the plate's first mode: 1 at lock-in
  j["tip_frequency_ratio"] = tip.frequency / f1_sc;
  j["circuit_solves"] = circuit_solves;
  j["circuit_solves_per_step"] = done > 0 ? static_cast<double>(circuit_solves) / static_cast<double>(done) : 0.0;
  j["cpu_split"] = {{"setup", t.setup}, {"mesh", t.mesh}, {"fluid", t.fluid}, {"structure", t.structure}};
  const int rc = cs.finish(j, {"summary.json", "series.csv"});
  std::printf("turek_hron: harvester level %d dt %g to t = %g s (D %.4g m, Re %.0f, f1 %.4g Hz): over the last %g s tip %.4e +- %.4e m at "
              "%.4g Hz, lift %.4e +- %.4e N/m at %.4g Hz (x %.3f of f1), V +- %.4e V, P %.4e W/m; %.2f evaluations per step; CPU %.1f s%s; "
              "results in %s\n", s.level, s.dt, end, side, reynolds, f1_sc, end - j["window"][0].get<double>(), tip.mean, tip.amplitude,
              tip.frequency, lift.mean, lift.amplitude, lift.frequency, lift.frequency / f1_sc, volt.amplitude,
              j["power_mean"].get<double>(), per_step, cpu, loop.failed ? " (STOPPED)" : "", cs.out().c_str());
  return loop.exit_code(rc);
}

}  // namespace polymech::apps
