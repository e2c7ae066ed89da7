// Seed 003 §3(3)-§4 (Figs. 3-7): a rigid blunt cylindrical projectile perforating an elasto-plastic
// steel plate, NOSB peridynamics with velocity viscosity, bond damage and contact.
//   pd_penetration [--scene scenes/pd/penetration_303.toml] [--out out/pd_penetration]
//                  [--accuracy draft|standard|paper] [--precision double|float] [--velocity V] [--cv C]
// Writes summary.json (residual_velocity, initial_velocity, particles, bonds, wall_seconds, ...),
// energy.csv, projectile.csv and fields.h5 + fields.xdmf (ParaView: damage, velocity, plastic strain).
#include <cmath>
#include <cstdio>

#include "apps/common/case.hpp"
#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/impact.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

template <class T, int D>
int run_case(const pm::io::NosbPdScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const np::Config& c = scene.config;
  const auto steps = opt.steps > 0 ? opt.steps : scene.steps;
  char extra[96];
  std::snprintf(extra, sizeof extra, "velocity=%.17g; c_v=%.17g", c.projectile.velocity, c.stabilization.c_v);
  pm::apps::Case cs({"pd_penetration", scene.header, steps, c.dt, extra}, opt, ropt);
  np::Impact<T, D> model(c);
  const np::NosbPd<T, D>& plate = model.plate();
  std::fprintf(stderr,
               "[pd_penetration] %s\n  accuracy %s (spacing %.3g m, m = %g), %s precision, %d particles, %lld bonds\n"
               "  v0 = %.1f m/s, c_v = %g, omega_v = %.3g rad/s, dt = %.3g s (limit %.3g s), up to %lld steps, %s\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), c.spacing, c.horizon_ratio, scene.header.precision.c_str(),
               plate.particles(), static_cast<long long>(plate.bonds()), c.projectile.velocity, c.stabilization.c_v,
               c.stabilization.omega_v, c.dt, scene.stable_dt, static_cast<long long>(steps), pm::apps::thread_count().c_str());

  cs.snapshots(pm::apps::point_mesh(D, plate.host_fields().x0))
      .every(scene.snapshots > 0 ? std::max<std::int64_t>(1, steps / scene.snapshots) : 0, [&](std::int64_t) {
        const auto h = plate.host_fields();
        pm::apps::CaseSnapshots::Fields fields = {{"displacement", D, h.u}, {"velocity", D, h.v}};
        if (!h.damage.empty()) fields.push_back({"damage", 1, h.damage});
        if (!h.eps_p.empty()) fields.push_back({"plastic_strain", 1, h.eps_p});
        return fields;
      }, [&](std::int64_t) { return model.time(); });
  cs.hooks.sample_every = scene.sample_every;
  cs.hooks.watchdog.keep_last_good = true;  // snapshotted when the run diverges
  const np::RunStats stats = cs.run([&](auto& hooks, std::int64_t n) {
    return np::run_impact(model, n, hooks, scene.stop_after_perforation);
  });
  const np::ImpactState impact = np::analyse_impact(model);

  // energy.csv and projectile.csv: the time series
  std::vector<std::vector<double>> e(12), p(4);
  for (const auto& s : stats.samples) {
    const double row[] = {s.time, s.energy.kinetic, s.energy.strain, s.energy.plastic, -s.energy.viscous, s.energy.hourglass,
                          s.energy.contact, s.energy.short_range, s.energy.projectile_kinetic, s.energy.total(),
                          s.energy.total() - stats.initial_energy, double(s.broken_bonds)};
    for (int k = 0; k < 12; ++k) e[k].push_back(row[k]);
    p[0].push_back(s.time);
    p[1].push_back(s.projectile.position[D - 1]);
    p[2].push_back(s.projectile.velocity[D - 1]);
    p[3].push_back(s.projectile.reaction[D - 1]);
  }
  pm::io::write_csv(cs.out() / "energy.csv",
                    {"time", "kinetic", "strain", "plastic", "viscous_dissipated", "hourglass_work", "contact", "short_range",
                     "projectile_kinetic", "total", "total_minus_initial", "broken_bonds"},
                    e);
  pm::io::write_csv(cs.out() / "projectile.csv", {"time", "nose_position", "velocity", "reaction"}, p);
  const auto xdmf = cs.snapshots().finish();

  const double v0 = c.projectile.velocity, vexp = scene.experiment_residual_velocity;
  auto num = [](double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); };
  nlohmann::json j = cs.summary();
  j["initial_velocity"] = v0;
  j["residual_velocity"] = num(stats.diverged ? NAN : impact.residual_velocity);
  j["perforated"] = impact.perforated;  // through and free of contact
  j["through"] = impact.through;        // nose more than a horizon below the plate (a plug may ride on it)
  j["experiment_residual_velocity"] = num(vexp);
  j["residual_velocity_error"] = num(stats.diverged ? NAN : impact.residual_velocity - vexp);
  j["particles"] = plate.particles();
  j["bonds"] = plate.bonds();
  j["broken_bonds"] = model.broken_bonds();
  j["wall_seconds"] = stats.wall_seconds;
  j["short_range_list_builds"] = plate.verlet_builds();  // neighbour searches of the contact list (skin)
  j["spacing"] = c.spacing;
  j["horizon_ratio"] = c.horizon_ratio;
  j["dt"] = c.dt;
  j["stable_dt"] = scene.stable_dt;
  j["steps"] = stats.steps;
  j["simulated_time"] = model.time();
  j["c_v"] = c.stabilization.c_v;
  j["omega_v"] = c.stabilization.omega_v;
  j["critical_stretch"] = plate.critical_stretch_value();
  j["plate"] = {{"core_damage", impact.core_damage}, {"rim_damage", impact.rim_damage}, {"max_damage", impact.max_damage},
                {"plug_mass", impact.plug_mass}, {"plug_mass_nominal", impact.plug_mass_nominal}};
  const auto& last = stats.samples.back().energy;
  j["energy"] = {{"initial", stats.initial_energy},
                 {"final_total", last.total()},
                 {"max_relative_error", stats.energy_error()},
                 {"kinetic", last.kinetic},
                 {"strain", last.strain},
                 {"plastic", last.plastic},
                 {"viscous_dissipated", -last.viscous},
                 {"hourglass_work", last.hourglass},
                 {"contact", last.contact},
                 {"short_range", last.short_range},
                 {"projectile_kinetic", last.projectile_kinetic}};
  const int rc = cs.finish(j, stats, {"summary.json", "energy.csv", "projectile.csv", "fields.h5", xdmf.filename().string()});

  std::printf("v0 = %.1f m/s -> residual %.1f m/s (%s)%s\n", v0, impact.residual_velocity,
              impact.perforated ? "perforated" : (impact.through ? "through, plug on the nose" : "not through at the end of the run"),
              std::isfinite(vexp) ? (", experiment " + std::to_string(vexp).substr(0, 5) + " m/s").c_str() : "");
  std::printf("plate: core damage %.2f, rim damage %.2f, plug %.1f g (nominal %.1f g); energy error %.2e; wall %.1f s\n",
              impact.core_damage, impact.rim_damage, 1e3 * impact.plug_mass, 1e3 * impact.plug_mass_nominal, stats.energy_error(),
              stats.wall_seconds);
  std::printf("results in %s: summary.json, energy.csv, projectile.csv, %s (open in ParaView)\n", cs.out().c_str(),
              xdmf.filename().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Rigid blunt projectile perforating a steel plate, NOSB peridynamics (seed 003 Figs. 3-7)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/pd/penetration_303.toml", "out/pd_penetration");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  double velocity = 0, cv = -1;
  pm::apps::positive<double>(app.add_option("--velocity", velocity, "impact velocity [m/s] (default: the scene's)"));
  pm::apps::non_negative<double>(app.add_option("--cv", cv, "velocity viscosity coefficient c_v (default: the scene's)"));
  if (const auto rc = pm::apps::parse_command_line(app, "pd_penetration", argc, argv)) return *rc;
  return pm::apps::guarded("pd_penetration", [&] {
    pm::apps::KokkosSession kokkos(opt);
    pm::io::NosbPdSceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    so.velocity = velocity;
    so.c_v = cv;
    const auto scene = pm::io::load_nosb_pd_scene(opt.scene, so);
    if (pm::apps::announce_cost("pd_penetration", scene.header, pm::apps::with_steps(scene.cost, scene.steps, opt.steps), opt)) return 0;
    return pm::apps::with_precision_and_dimension(scene.header.precision, scene.config.dimension, [&](auto t, auto d) {
      return run_case<decltype(t), decltype(d)::value>(scene, opt, ropt);
    });
  });
}
