// The piezoelectric energy harvester (issue 35; seed 002 paper 1): a layered cantilever of piezoceramic and
// elastic layers (models/piezo/beam_model.hpp) with electrodes and a resistive circuit, run as the scene's
// [analysis] says (models/piezo/harvester_case.hpp):
//   static    -> summary.json (tip_deflection against the laminated bender's closed forms, beam and plate;
//                the prescribed electrodes' charges and capacitances), deflection.csv (x, w along the bottom);
//   harmonic  -> frf.csv (R_ohm, f_hz, V_amplitude, power, tip), power_R.csv (per load: the sweep's peak),
//                summary.json (f_sc, f_oc of the FE beam, the Erturk-Inman values with and without the induced
//                potential, R_opt and P_max of the sweep, wall time);
//   transient -> series.csv (t, base_acceleration, V, tip, power, energy terms), summary.json (the steady voltage
//                amplitude and mean power over the last periods against the harmonic solve at the same
//                frequency, energy_balance_error, solves, wall time); checkpoints and --restart.
//   piezo_harvester [--scene scenes/piezo/dutoit_harvester.toml] [--out out/piezo_harvester] [--accuracy ...]
//                   [--steps N] [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]
// Plot: tools/plot_piezo_harvester.py OUT.
#include <cstdio>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "io/piezo_scene.hpp"
#include "piezo/harvester_case.hpp"

namespace pm = polymech;
namespace pz = polymech::piezo;

namespace {

void put(nlohmann::json& j, const pz::CaseSummary& s) {
  for (const auto& [k, v] : s.numbers) j[k] = v;  // NaN is written as null
  for (const auto& [k, v] : s.texts) j[k] = v;
}
void write(const pm::apps::Case& cs, const std::string& name, const pz::CaseTable& t) {
  pm::io::write_csv(cs.out() / name, t.names, t.columns);
}

// static and harmonic: one solve or a sweep of solves, no checkpoints.
int run_solves(const pm::io::PiezoScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const auto& a = scene.config.analysis;
  pm::apps::CaseSpec spec("piezo_harvester", scene.header, 0);
  spec.checkpoints = false;
  spec.progress = false;
  pm::apps::Case cs(spec, opt, ropt);  // --restart refused: no checkpoints
  nlohmann::json j = cs.summary();
  j["analysis"] = a.kind;
  std::vector<std::string> files = {"summary.json"};
  pz::CaseSummary s;
  if (a.kind == "static") {
    pz::CaseTable deflection;
    s = pz::run_static(scene.config, deflection);
    write(cs, "deflection.csv", deflection);
    files.push_back("deflection.csv");
    std::printf("piezo_harvester: static, %g unknowns: tip deflection %.6e m (beam theory %.6e, plate theory %.6e)\n",
                s.get("unknowns"), s.get("tip_deflection"), s.get("tip_deflection_beam_theory"), s.get("tip_deflection_plate_theory"));
  } else {
    pz::CaseTable frf, per_load;
    s = pz::run_harmonic(scene.config, frf, per_load, [&](const std::string& line) {
      if (!opt.quiet) std::fprintf(stderr, "  %s\n", line.c_str());
    });
    write(cs, "frf.csv", frf);
    write(cs, "power_R.csv", per_load);
    files.insert(files.end(), {"frf.csv", "power_R.csv"});
    std::printf("piezo_harvester: harmonic, %g unknowns: f_sc %.4f Hz, f_oc %.4f Hz (EI09 with the induced potential %.4f, "
                "%.4f); R_opt %.4g ohm, P_max %.4e W at %.4f Hz\n",
                s.get("unknowns"), s.get("f_sc"), s.get("f_oc"), s.get("f_sc_ei09_induced_potential"),
                s.get("f_oc_ei09_induced_potential"), s.get("R_opt"), s.get("P_max"), s.get("f_at_P_max"));
  }
  put(j, s);
  cs.finish(j, files);
  std::printf("results in %s\n", cs.out().c_str());
  return 0;
}

int run_transient(const pm::io::PiezoScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const auto& a = scene.config.analysis;
  pz::HarvesterTransient model(scene.config);
  const std::int64_t steps = opt.steps > 0 ? opt.steps : a.steps();
  pm::apps::Case cs({"piezo_harvester", scene.header, steps, model.dt()}, opt, ropt);
  if (!opt.quiet)
    std::fprintf(stderr, "[piezo_harvester] %s\n  %lld unknowns, f_sc %.4f Hz, f_oc %.4f Hz; a_b = %g sin(2 pi %.4f t) m/s^2, "
                 "dt %.4g s, %lld steps, %s, %s\n", scene.header.title.c_str(), static_cast<long long>(model.beam().unknowns()),
                 model.omega_sc() / (2 * pz::kPi), model.omega_oc() / (2 * pz::kPi), a.base_acceleration,
                 model.omega() / (2 * pz::kPi), model.dt(), static_cast<long long>(steps), a.scheme.c_str(),
                 pm::apps::thread_count().c_str());
  pm::apps::Series series(pz::HarvesterTransient::columns());
  cs.records.keep("piezo/series", series);
  cs.hooks.sample_every = a.sample_every;
  cs.hooks.sample_at_start = true;
  cs.hooks.sample = [&](std::int64_t) { series.append(model.sample()); };
  const auto stats = cs.run([&](auto& hooks, std::int64_t n) { return pm::models::run(model, n, hooks); });
  nlohmann::json j = cs.summary();
  j["analysis"] = a.kind;
  put(j, model.summary(series["t"], series["V"], series["tip"], series["work_circuit"]));
  j["steps"] = stats.steps;
  j["wall_seconds"] = stats.wall_seconds;
  series.write_csv(cs.out() / "series.csv");
  const int rc = cs.finish(j, stats, {"summary.json", "series.csv"});
  std::printf("piezo_harvester: transient, %lld steps: steady |V| %.6g V (harmonic %.6g V), mean power %.6g W (harmonic %.6g W), "
              "energy balance %.2e, %.1f s; results in %s\n", static_cast<long long>(stats.steps),
              j.value("voltage_amplitude", 0.0), j["harmonic_voltage_amplitude"].get<double>(), j.value("mean_power", 0.0),
              j["harmonic_mean_power"].get<double>(), j["energy_balance_error"].get<double>(), stats.wall_seconds, cs.out().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The piezoelectric energy harvester: static bender, harmonic load/frequency sweep, base-excited transient "
               "(seed 002 paper 1)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/piezo/dutoit_harvester.toml", "out/piezo_harvester");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "piezo_harvester", argc, argv)) return *rc;
  return pm::apps::guarded("piezo_harvester", [&] {
    const auto scene = pm::io::load_piezo_scene(opt.scene, {opt.accuracy, opt.precision});
    const bool transient = scene.config.analysis.kind == "transient";
    if (!transient && opt.steps > 0)
      throw std::invalid_argument("--steps " + std::to_string(opt.steps) + ": does not apply: a " + scene.config.analysis.kind +
                                  " analysis has no time steps");
    if (!transient && !ropt.restart.empty())
      throw std::invalid_argument("--restart: a " + scene.config.analysis.kind + " analysis has no checkpoints; run it again");
    const auto cost = transient ? pm::apps::with_steps(scene.cost, scene.config.analysis.steps(), opt.steps) : scene.cost;
    if (pm::apps::announce_cost("piezo_harvester", scene.header, cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    return transient ? run_transient(scene, opt, ropt) : run_solves(scene, opt, ropt);
  });
}
