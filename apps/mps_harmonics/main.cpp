// Seed 000 §5.2: higher harmonics from a closed crack in steel. Runs the scene twice, without and with
// the crack, and compares the spectra of the transmitted wave at the harmonics probe (Figs. 7-10).
//   mps_harmonics --scene scenes/mps/crack_p_wave.toml [--out out/crack_p_wave] [--accuracy draft|standard|paper]
//                 [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]
// The run without the crack also records the largest shear force through the crack line; a scene with
// [crack].normal_reaction_ratio sets the slip model's fixed normal reaction from it (§5.2.2: 0.75 x).
// Writes time_history.csv, spectrum.csv, contact_states.csv, summary.json, fields.h5/.xdmf (cracked run).
// Checkpoints and --restart as in apps/common/restart.hpp: a restart continues inside whichever of the
// two runs was going (the cracked run's checkpoints carry the intact run's record). The summary keys:
// apps/mps_harmonics/summary.hpp.
#include <cstdio>
#include <memory>
#include <utility>

#include "apps/common/case.hpp"
#include "apps/mps_harmonics/summary.hpp"
#include "io/mps_elastic_scene.hpp"
#include "io/progress.hpp"
#include "mps_elastic/analysis.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

// Before the run (also for --dry-run): the scene must be a harmonics case whose record holds the
// analysis window, and the probes whose own window does not fit are named (models/mps_elastic/analysis.hpp).
void check_scene(const pm::io::MpsElasticScene& scene, const pm::apps::CommonOptions& opt) {
  const auto why = me::harmonics_case_error(scene.config, scene.harmonics_probe, opt.steps > 0 ? "--steps" : "[time].steps at this accuracy");
  if (!why.empty()) throw pm::io::SceneError(opt.scene.string() + ": " + why);
  for (const auto& note : me::probes_left_out(scene.config, scene.harmonics_probe))
    if (!opt.quiet) std::fprintf(stderr, "mps_harmonics: note: %s\n", note.c_str());
}

template <class T>
int run_case(const pm::io::MpsElasticScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const me::Config& c = scene.config;
  char extra[64];
  std::snprintf(extra, sizeof extra, "k_prime=%.17g", c.crack.k_prime);
  pm::apps::CaseSpec spec("mps_harmonics", scene.header, c.steps, c.dt, extra);
  pm::apps::Case cs(spec, opt, ropt);
  const std::string phase = me::harmonics_phase(cs.resume());

  auto& snapshots = cs.snapshots(pm::apps::point_mesh(2, me::lattice_points(c))).writer();  // the lattice at rest
  std::unique_ptr<pm::io::Progress> progress;
  auto make_hooks = [&](const std::string& label, me::MpsElastic<T>& model) {
    const bool crack = label == "crack";
    std::fprintf(stderr, "[mps_harmonics] %s: %d particles, %lld bonds, %d crack pairs, %lld steps\n", label.c_str(),
                 model.particles(), static_cast<long long>(model.bonds()), model.crack().pair_count(), static_cast<long long>(c.steps));
    if (progress) progress->done(c.steps);
    progress = std::make_unique<pm::io::Progress>("mps_harmonics " + label, c.steps, c.dt, !opt.quiet);
    me::RunHooks hooks;
    hooks.after_step = [p = progress.get()](std::int64_t k) { p->update(k); };
    // the snapshot writer holds the cracked run's fields: its record goes into that run's checkpoints
    cs.attach(hooks, [&snapshots, crack](pm::models::Archive& a) {
      if (crack) snapshots.save(a);
    });
    // the store keeps (and resumes) the highest-numbered checkpoints: the cracked run's are numbered
    // after the intact run's steps
    if (crack)
      hooks.checkpoint.write = [write = hooks.checkpoint.write, n = c.steps](std::int64_t k, pm::models::Archive& a) { write(n + k, a); };
    if (label == phase) progress->resume_at(cs.resume_step() - (crack ? c.steps : 0));
    if (label == phase && crack) snapshots.resume(*cs.resume());
    if (crack && scene.snapshot_every > 0) {
      hooks.snapshot_every = scene.snapshot_every;
      hooks.snapshot = [&model, &snapshots, dt = c.dt](std::int64_t step) {
        const auto h = model.host_fields();
        // a named Fields: nvcc 11.8 cannot parse the nested braces in the call inside this init-capture lambda
        const pm::io::Fields fields{{"displacement", 2, h.u}, {"velocity", 2, h.v}, {"volumetric_strain", 1, h.e}};
        snapshots.add(step, static_cast<double>(step) * dt, fields);
      };
    }
    return hooks;
  };
  const int field = scene.harmonics_component == "u1" ? pm::mps::probe_u1 : pm::mps::probe_u3;
  const auto res = me::run_harmonics_case<T>(c, scene.harmonics_probe, field, scene.normal_reaction_ratio, make_hooks,
                                            cs.resume());
  if (progress) progress->done(c.steps);
  const auto& a = res.intact;
  const auto& b = res.crack;
  // a failed analysis (issue 33 item 3) leaves the ratios and spectra empty; the records are written all the same
  const bool analysed = res.analysis_error.empty();

  const std::string comp = scene.harmonics_component;
  std::vector<std::string> files = {"summary.json"};
  for (const auto& t : me::harmonics_tables(res, comp)) {  // models/mps_elastic/analysis.hpp
    pm::io::write_csv(cs.out() / t.file, t.table.header, t.table.columns);
    files.push_back(t.file);
  }
  const auto xdmf = scene.snapshot_every > 0 ? cs.snapshots().finish().filename().string() : std::string();
  if (!xdmf.empty()) files.insert(files.end(), {"fields.h5", xdmf});

  nlohmann::json j = cs.summary();
  pm::apps::put_harmonics_summary(j, scene, res, field);
  cs.finish(j, files);

  if (!analysed) {
    std::fprintf(stderr, "mps_harmonics: the analysis failed: %s; the records of both runs are in %s\n",
                 res.analysis_error.c_str(), cs.out().c_str());
    return 1;
  }
  std::printf("harmonics of %s at probe %s (A_n / A_1, n = 1..5):\n", comp.c_str(), scene.harmonics_probe.c_str());
  for (const auto& [name, r] : {std::pair{"crack ", &res.ratios_crack}, std::pair{"intact", &res.ratios_intact}})
    std::printf("  %s: %.3g %.3g %.3g %.3g %.3g\n", name, (*r)[0], (*r)[1], (*r)[2], (*r)[3], (*r)[4]);
  if (scene.normal_reaction_ratio > 0)
    std::printf("normal reaction %.4g N/m = %.2f x the intact run's largest shear force %.4g N/m\n",
                res.normal_reaction, scene.normal_reaction_ratio, a.max_shear_force);
  std::printf("wall %.1f s (intact) + %.1f s (crack); results in %s\n", a.stats.wall_seconds, b.stats.wall_seconds,
              cs.out().c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"MPS higher-harmonic generation at a closed crack in steel (seed 000 section 5.2)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/mps/crack_p_wave.toml", "out/mps_harmonics");
  double k_prime = 0.0;
  pm::apps::within(app.add_option("--k-prime", k_prime, "override the contact stiffness factor k' of eq. (19)"), 1e-6, 1.999);
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "mps_harmonics", argc, argv)) return *rc;
  return pm::apps::guarded("mps_harmonics", [&] {
    pm::apps::KokkosSession kokkos(opt);
    pm::io::MpsSceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    so.steps = opt.steps;
    auto scene = pm::io::load_mps_elastic_scene(opt.scene, so);
    if (k_prime > 0) scene.config.crack.k_prime = k_prime;
    check_scene(scene, opt);
    if (pm::apps::announce_cost("mps_harmonics", scene.header, scene.cost, opt)) return 0;
    return pm::apps::with_precision(scene.header.precision, [&](auto t) { return run_case<decltype(t)>(scene, opt, ropt); });
  });
}
