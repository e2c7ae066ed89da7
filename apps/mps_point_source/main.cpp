// Seed 000 §5.1: elastic waves from a point source in a steel plate (MPS, no crack).
//   mps_point_source [--scene scenes/mps/point_source.toml] [--out out/mps_point_source]
//                    [--accuracy draft|standard|paper] [--precision double|float] [--steps N]
// Writes summary.json, probes.csv, energy.csv and fields.h5 + fields.xdmf (ParaView) to --out.
#include <cmath>
#include <cstdio>

#include "apps/common/case.hpp"
#include "io/mps_elastic_scene.hpp"
#include "mps_elastic/run.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

template <class T>
int run_case(const pm::io::MpsElasticScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const me::Config& c = scene.config;
  pm::apps::Case cs({"mps_point_source", scene.header, c.steps, c.dt}, opt, ropt);
  me::MpsElastic<T> model(c);
  std::fprintf(stderr,
               "[mps_point_source] %s\n  accuracy %s (spacing %.3g m, x%g), %s precision, %d particles, %lld bonds, "
               "n0 = %.4f\n  dt = %.3g s (stability limit %.3g s), %lld steps, %s\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), c.spacing, scene.header.coarsening, scene.header.precision.c_str(),
               model.particles(), static_cast<long long>(model.bonds()), model.n0(), c.dt, scene.stable_dt,
               static_cast<long long>(c.steps), pm::apps::thread_count().c_str());

  // Field snapshots: displacement, |u| / u0 (Fig. 4), velocity, volumetric strain, particle rotation.
  const double u0 = c.excitation.amplitude > 0 ? c.excitation.amplitude : 1.0;
  cs.snapshots(pm::apps::point_mesh(2, model.host_fields().x0)).every(scene.snapshot_every, [&](std::int64_t) {
    const auto h = model.host_fields();
    std::vector<double> mag(h.e.size());
    for (std::size_t i = 0; i < mag.size(); ++i) mag[i] = std::hypot(h.u[2 * i], h.u[2 * i + 1]) / u0;
    pm::apps::CaseSnapshots::Fields fields = {
        {"displacement", 2, h.u}, {"abs_u_over_u0", 1, mag}, {"velocity", 2, h.v}, {"volumetric_strain", 1, h.e}};
    if (!h.theta.empty()) fields.push_back({"rotation_angle", 1, h.theta});
    return fields;
  }, [&](std::int64_t k) { return static_cast<double>(k) * c.dt; });
  cs.hooks.watchdog.keep_last_good = true;  // snapshotted when the run diverges
  const me::RunStats stats = cs.run([&](auto& hooks, std::int64_t n) { return me::run(model, n, hooks); });
  const std::string xdmf = cs.snapshots().finish().filename().string();
  if (stats.diverged) {  // the summary says why and where; the last snapshot is the last good state
    nlohmann::json j = cs.summary();
    j["steps"] = stats.steps;
    return cs.finish(j, stats, {"summary.json", xdmf});
  }

  // Wave speeds from arrival times (seed 000 §5.1).
  const auto src = me::excitation_source_point(c);
  me::WaveSpeeds speeds;
  std::string speed_note;
  try {
    speeds = me::measure_wave_speeds(model.probes(), c, src.x1, src.x3, scene.p_wave_probes, scene.s_wave_probes);
  } catch (const std::invalid_argument& e) {
    speed_note = e.what();  // e.g. too few steps for the waves to reach the far probes
  }

  // probes.csv: time, then <probe>_<field> for every probe and field.
  const auto& h = model.probes();
  std::vector<std::string> header = {"time"};
  std::vector<std::vector<double>> columns = {h.times};
  for (std::size_t p = 0; p < h.names.size(); ++p)
    for (int f = 0; f < pm::mps::probe_field_count; ++f) {
      header.push_back(h.names[p] + "_" + pm::mps::probe_field_name(f));
      columns.push_back(h.values[p][f]);
    }
  pm::io::write_csv(cs.out() / "probes.csv", header, columns);
  pm::io::write_csv(cs.out() / "energy.csv", {"time", "total_energy"}, pm::io::Columns{stats.energy.time, stats.energy.total});

  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  const double cp_a = model.cp_analytic(), cs_a = model.cs_analytic();
  nlohmann::json j = cs.summary();
  j["spacing"] = c.spacing;
  j["dt"] = c.dt;
  j["stable_dt"] = scene.stable_dt;
  j["n0"] = model.n0();
  j["particles"] = model.particles();
  j["bonds"] = model.bonds();
  j["steps"] = stats.steps;
  j["simulated_time"] = model.time();
  j["wall_seconds"] = stats.wall_seconds;
  j["steps_per_second"] = static_cast<double>(stats.steps) / stats.wall_seconds;
  j["cp_analytic"] = cp_a;
  j["cs_analytic"] = cs_a;
  j["cp_measured"] = num(speeds.cp);
  j["cs_measured"] = num(speeds.cs);
  j["cp_relative_error"] = num((speeds.cp - cp_a) / cp_a);
  j["cs_relative_error"] = num((speeds.cs - cs_a) / cs_a);
  if (!speed_note.empty()) j["wave_speed_note"] = speed_note;
  j["arrivals"] = {{"P", {{"t_near", num(speeds.p.t_near)}, {"t_far", num(speeds.p.t_far)},
                          {"r_near", speeds.p.r_near}, {"r_far", speeds.p.r_far}}},
                   {"S", {{"t_near", num(speeds.s.t_near)}, {"t_far", num(speeds.s.t_far)},
                          {"r_near", speeds.s.r_near}, {"r_far", speeds.s.r_far}}}};
  j["energy_after_excitation"] = stats.energy.reference;
  j["energy_final"] = stats.energy.last;
  j["energy_drift"] = stats.energy.drift();
  j["energy_spread"] = stats.energy.spread();
  cs.finish(j, stats, {"summary.json", "probes.csv", "energy.csv", "fields.h5", xdmf});

  std::printf("cp: measured %.1f m/s, analytic %.1f m/s (%+.2f %%)\n", speeds.cp, cp_a, 100 * (speeds.cp - cp_a) / cp_a);
  std::printf("cs: measured %.1f m/s, analytic %.1f m/s (%+.2f %%)\n", speeds.cs, cs_a, 100 * (speeds.cs - cs_a) / cs_a);
  if (!speed_note.empty()) std::printf("wave speeds: %s\n", speed_note.c_str());
  std::printf("energy drift after the pulse: %.2e; wall %.1f s (%.0f steps/s)\n", stats.energy.drift(),
              stats.wall_seconds, static_cast<double>(stats.steps) / stats.wall_seconds);
  std::printf("results in %s: summary.json, probes.csv, energy.csv, %s (open in ParaView)\n", cs.out().c_str(), xdmf.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"MPS elastic waves from a point source in steel (seed 000 section 5.1)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/mps/point_source.toml", "out/mps_point_source");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "mps_point_source", argc, argv)) return *rc;
  return pm::apps::guarded("mps_point_source", [&] {
    pm::apps::KokkosSession kokkos(opt);
    pm::io::MpsSceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    so.steps = opt.steps;
    const auto scene = pm::io::load_mps_elastic_scene(opt.scene, so);
    if (pm::apps::announce_cost("mps_point_source", scene.header, scene.cost, opt)) return 0;
    return pm::apps::with_precision(scene.header.precision, [&](auto t) { return run_case<decltype(t)>(scene, opt, ropt); });
  });
}
