// Stabilized ISPH with IGCB walls (seed 002 paper 4): runs a scene of scenes/isph/ (the case, hydrostatic
// tank or dam break, is the scene's [tank].case), writes
//   summary.json: particles, steps, wall_seconds, ppe_iterations_mean, particle_steps_per_second, and
//     hydrostatic: hydrostatic_pressure_error (relative L2 of the pressure averaged over the last
//       [time].average_last seconds against rho g (H - y)), max_speed;
//     dam break: front_positions [[T, Z], ...] with T = t sqrt(2 g / a), Z = x / a;
//     floating body: its state, forces and draft (models/isph/analysis.hpp);
//   series.csv (time, PPE iterations, residual, front or pressure error, max speed; the body's),
//   ppe_residual_history.csv (the last solve's residual after each iteration),
//   fields.h5 / fields.xdmf snapshots (position, velocity, pressure, density, free surface).
//   isph [--scene scenes/isph/dam_break.toml] [--out out/isph] [--accuracy draft|standard|paper]
//        [--steps N] [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]
// The run plumbing (checkpoints, --restart, progress, snapshots, divergence) is apps/common/case.hpp.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "io/isph_scene.hpp"
#include "isph/analysis.hpp"
#include "isph/isph.hpp"

namespace pm = polymech;
namespace ip = polymech::isph;

namespace {

// The floating body's summary keys (docs/VALIDATION.md, ISPH floating body).
template <class Model>
void put_body(nlohmann::json& j, const Model& model, const ip::Config& c) {
  const auto& b = model.body();
  const auto& p = model.body_properties();
  j["body_centre"] = {b.centre[0], b.centre[1]};
  j["body_velocity"] = {b.v[0], b.v[1]};
  j["body_angle"] = b.theta;
  j["body_density_ratio"] = c.body.density_ratio;
  j["body_fluid_rings"] = c.body.fluid_rings;
  j["body_fluid_clearance"] = c.body.fluid_clearance;
  j["body_area_by_quadrature"] = p.area;
  j["body_force"] = {b.force[0], b.force[1], b.moment};  // the fluid's, last step [N/m, N/m, N]
  j["body_mass"] = p.mass;
  j["body_contact_force"] = {b.contact_force[0], b.contact_force[1], b.contact_moment};  // the tank's
  j["body_drift_over_diameter"] = std::hypot(b.centre[0] - c.body.centre[0], b.centre[1] - c.body.centre[1]) / c.body.diameter;
  j["body_speed"] = std::hypot(b.v[0], b.v[1]);
  j["body_gap_to_bottom"] = b.centre[1] - 0.5 * c.body.diameter;  // < 0: overlapping the bottom
  j["body_weight"] = p.mass * c.gravity;
  j["body_buoyancy_immersed"] = c.density * c.gravity * p.area;
  j["archimedes_draft_over_diameter"] = ip::archimedes_draft_over_diameter(c.body.density_ratio);
}

template <class T, int D>
int run_case(const pm::io::IsphScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt) {
  const auto& c = scene.config;
  const std::int64_t steps = opt.steps > 0 ? opt.steps : scene.steps;
  pm::apps::Case cs({"isph", scene.header, steps, c.dt}, opt, ropt);
  ip::Isph<T, D> model(c);
  if (!opt.quiet)
    std::fprintf(stderr, "[isph] %s\n  case %s, %dD, %d particles, %d wall points, l0 = %.4g m, dt = %.3g s, %lld steps\n",
                 scene.header.title.c_str(), scene.case_name.c_str(), D, int(model.particles()), int(model.wall_points()),
                 c.spacing, c.dt, static_cast<long long>(steps));
  const std::int64_t snapshot_every = scene.snapshot_every > 0 ? std::max<std::int64_t>(1, std::llround(scene.snapshot_every / c.dt)) : 0;
  cs.snapshots(pm::apps::point_mesh(D, model.host_positions()), "fields").every(snapshot_every, [&](std::int64_t) {
      const auto s = model.host_surface();
      return pm::apps::CaseSnapshots::Fields{{"position", D, model.host_positions()}, {"velocity", D, model.host_velocities()},
                                             {"pressure", 1, model.host_pressure()}, {"density", 1, model.host_density()},
                                             {"free_surface", 1, std::vector<double>(s.begin(), s.end())}};
    }, [&](std::int64_t k) { return static_cast<double>(k) * c.dt; });

  // the samples and the averages under way (models/isph/analysis.hpp), in every checkpoint
  const bool dam = scene.case_name == "dam_break", body = model.has_body();
  ip::CaseRecord<ip::Isph<T, D>> rec(model, dam, steps, scene.average_last, scene.draft_average_last, scene.end_time);
  pm::apps::Series series(rec.columns(dam));
  cs.records.keep("isph/series", series);
  rec.keep([&](const std::string& key, auto& value) { cs.records.keep(key, value); });
  cs.after_step = [&](std::int64_t k) { rec.after_step(k); };
  cs.hooks.sample_every = scene.sample_every > 0 ? std::max<std::int64_t>(1, std::llround(scene.sample_every / c.dt)) : 1;
  cs.hooks.sample = [&](std::int64_t k) { series.append(rec.sample(static_cast<double>(k) * c.dt)); };
  cs.hooks.watchdog.keep_last_good = true;
  const auto stats = cs.run([&](auto& hooks, std::int64_t n) { return pm::models::run(model, n, hooks); });

  nlohmann::json j = cs.summary();
  j["case"] = scene.case_name;
  j.update(pm::io::isph_choices(c));  // dimension, spacing, dt and the readings that are scene choices
  j["particles"] = model.particles();
  j["wall_points"] = model.wall_points();
  j["steps"] = stats.steps;
  j["wall_seconds"] = stats.wall_seconds;  // with the time before the checkpoints it resumed from
  j["particle_steps_per_second"] = double(model.particles()) * double(stats.steps) / stats.wall_seconds;
  j["ppe_iterations_mean"] = model.ppe_solves() > 0 ? double(model.ppe_iterations_total()) / double(model.ppe_solves()) : 0.0;
  j["ppe_share_of_step"] = model.ppe_seconds() / stats.wall_seconds;
  j["ppe_last_residual"] = model.last_solve().residual;
  j["particles_put_back_inside"] = model.escaped();
  j["max_speed"] = ip::max_speed(model);
  j["interior_density_over_rho0"] = ip::interior_density_ratio(model);
  if (stats.diverged) j["reason"] = stats.reason;
  if (dam) {
    j["front_positions"] = nlohmann::json::array();
    for (std::size_t k = 0; k < rec.fronts_T.size(); ++k) j["front_positions"].push_back({rec.fronts_T[k], series["front_Z"][k]});
  } else {
    j["hydrostatic_pressure_error"] = ip::pressure_error(model, rec.averaged_pressure());
    j["hydrostatic_pressure_error_instantaneous"] = ip::pressure_error(model, model.host_pressure());
    j["pressure_averaged_over_seconds"] = rec.pcount * c.dt;
  }
  if (body) {
    put_body(j, model, c);
    j["body_lowest_gap_to_bottom"] = rec.lowest_gap;
    j["draft_over_diameter"] = rec.draft_mean(rec.draft_sum, series["draft_over_diameter"]);
    j["draft_over_diameter_surface_particles"] = rec.draft_mean(rec.draft_s_sum, series["draft_over_diameter_surface_particles"]);
    j["draft_averaged_over_samples"] = rec.draft_count;
    // against Archimedes (the relative error `polymech plan` reads; bench/sweep_isph_float.py's error_volume)
    j["draft_relative_error"] = j["draft_over_diameter"].get<double>() / ip::archimedes_draft_over_diameter(c.body.density_ratio) - 1.0;
  }
  std::vector<std::string> csv(series.names().begin(), series.names().begin() + rec.written_columns());
  series.write_csv(cs.out() / "series.csv", csv);
  const auto& history = model.last_solve().history;
  std::vector<double> iteration(history.size());
  for (std::size_t k = 0; k < history.size(); ++k) iteration[k] = double(k);
  pm::io::write_csv(cs.out() / "ppe_residual_history.csv", {"iteration", "relative_residual"}, pm::io::Columns{iteration, history});
  const int rc = cs.finish(j, stats, {"summary.json", "series.csv", "ppe_residual_history.csv", "fields.h5", cs.snapshots().finish().filename().string()});
  if (!opt.quiet)
    std::printf("isph: %s, %lld steps in %.1f s; results in %s\n", scene.case_name.c_str(), static_cast<long long>(stats.steps),
                stats.wall_seconds, cs.out().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Stabilized ISPH with IGCB walls: hydrostatic tank and dam break (seed 002 paper 4)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/isph/dam_break.toml", "out/isph");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "isph", argc, argv)) return *rc;
  return pm::apps::guarded("isph", [&] {
    const auto scene = pm::io::load_isph_scene(opt.scene, {opt.accuracy, opt.precision});
    if (pm::apps::announce_cost("isph", scene.header, pm::apps::with_steps(scene.cost, scene.steps, opt.steps), opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    return pm::apps::with_precision_and_dimension(scene.header.precision, scene.config.dim, [&](auto t, auto d) {
      return run_case<decltype(t), decltype(d)::value>(scene, opt, ropt);
    });
  });
}
