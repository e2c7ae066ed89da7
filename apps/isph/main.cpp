// Stabilized ISPH with IGCB walls (seed 002 paper 4): runs a scene of scenes/isph/ (the case, hydrostatic
// tank or dam break, is the scene's [tank].case), writes
//   summary.json: particles, steps, wall_seconds, ppe_iterations_mean, particle_steps_per_second, and
//     hydrostatic: hydrostatic_pressure_error (relative L2 of the pressure averaged over the last
//       [time].average_last seconds against rho g (H - y)), max_speed;
//     dam break: front_positions [[T, Z], ...] with T = t sqrt(2 g / a), Z = x / a;
//   series.csv (time, PPE iterations, residual, front or pressure error, max speed),
//   ppe_residual_history.csv (the last solve's residual after each iteration),
//   particles.h5 / particles.xdmf snapshots (position, velocity, pressure, density, free surface).
//   isph [--scene scenes/isph/dam_break.toml] [--out out/isph] [--accuracy draft|standard|paper]
//        [--steps N] [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]
// Checkpoint/restart (issue 16, apps/common/restart.hpp): a checkpoint holds the model (u, v, pressure,
// step, the rigid body, the solver's counts), the series, the averages under way and the snapshot
// writer; `--restart OUT` continues the run into OUT and its results are those of a run never
// interrupted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "apps/common/app.hpp"
#include "apps/common/restart.hpp"
#include "common/run.hpp"
#include "io/isph_scene.hpp"
#include "io/progress.hpp"
#include "isph/isph.hpp"

namespace pm = polymech;
namespace me = polymech::models;

namespace {

template <class Model>
double front_position(const Model& m) {
  constexpr int D = Model::dimension;
  const auto x = m.host_positions();
  const double l0 = m.config().spacing;
  double front = 0.0;
  for (std::size_t i = 0; i < x.size() / D; ++i)
    if (x[i * D + 1] < 2 * l0) front = std::max(front, x[i * D]);
  return front + 0.5 * l0;
}

template <class Model>
double pressure_error(const Model& m, const std::vector<double>& p) {
  constexpr int D = Model::dimension;
  const auto x = m.host_positions();
  const auto s = m.host_surface();
  const double rg = m.config().density * m.config().gravity, H = m.config().fluid[1];
  double e = 0, n = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (s[i]) continue;
    const double a = rg * (H - x[i * D + 1]);
    e += (p[i] - a) * (p[i] - a);
    n += a * a;
  }
  return n > 0 ? std::sqrt(e / n) : 0.0;
}

template <class Model>
double max_speed(const Model& m) {
  constexpr int D = Model::dimension;
  const auto v = m.host_velocities();
  double s = 0;
  for (std::size_t i = 0; i < v.size() / D; ++i) {
    double a = 0;
    for (int d = 0; d < D; ++d) a += v[i * D + d] * v[i * D + d];
    s = std::max(s, std::sqrt(a));
  }
  return s;
}

template <class T, int D>
int run_case(const pm::io::IsphScene& scene, pm::apps::CommonOptions opt, const pm::apps::RestartOptions& ropt) {
  const auto& c = scene.config;
  const std::int64_t steps = opt.steps > 0 ? opt.steps : scene.steps;
  pm::apps::Checkpoints checkpoints(opt, ropt, pm::apps::run_key("isph", scene.header, steps));
  pm::io::make_output_dir(opt.out);
  pm::isph::Isph<T, D> model(c);
  if (!opt.quiet)
    std::fprintf(stderr, "[isph] %s\n  case %s, %dD, %d particles, %d wall points, l0 = %.4g m, dt = %.3g s, %lld steps\n",
                 scene.header.title.c_str(), scene.case_name.c_str(), D, int(model.particles()), int(model.wall_points()),
                 c.spacing, c.dt, static_cast<long long>(steps));

  pm::io::SnapshotMesh mesh;
  mesh.dim = D;
  mesh.points = model.host_positions();
  pm::io::SnapshotWriter snapshots(opt.out, "particles", std::move(mesh));
  std::int64_t last_snapshot = -1;
  auto snapshot = [&](std::int64_t step) {
    // the watchdog hands back the last good state, which may be the step just written
    if (step == last_snapshot) return;
    last_snapshot = step;
    const auto x = model.host_positions();
    const auto s = model.host_surface();
    std::vector<double> surface(s.begin(), s.end());
    std::vector<pm::io::SnapshotField> fields = {{"position", D, x},
                                                 {"velocity", D, model.host_velocities()},
                                                 {"pressure", 1, model.host_pressure()},
                                                 {"density", 1, model.host_density()},
                                                 {"free_surface", 1, surface}};
    snapshots.add(step, static_cast<double>(step) * c.dt, fields);
  };

  const bool dam = scene.case_name == "dam_break";
  const double a = c.fluid[0], tscale = std::sqrt(2 * c.gravity / a);
  std::vector<double> t_col, it_col, res_col, q_col, v_col, by_col, draft_col, draft_s_col, fy_col;
  const bool body = model.has_body();
  double draft_sum = 0.0, draft_s_sum = 0.0;
  double lowest_gap = 1e300;  // the smallest distance between the body and the tank's bottom over the samples
  int draft_count = 0;
  // The draft, two readings (docs/VALIDATION.md, ISPH floating body), both the water level minus the
  // body's lowest point, with the level
  //  - from the volume (`draft_over_diameter`): the height L of a flat free surface over the tank's width W
  //    holding the water (N l0^2) and the part of the body below L: W L = N l0^2 + A_seg(L - y_low), the
  //    undisturbed level of Archimedes' principle;
  //  - from the particles (`draft_over_diameter_surface_particles`): the mean height of the surface
  //    particles more than one diameter from the body, plus l0/2 (where the eye puts it; the surface layer
  //    settles 0.2-0.5 l0 below the water's level, see the hydrostatic tank).
  struct Draft {
    double volume = 0.0, surface = 0.0;
  };
  auto draft_now = [&]() {
    const auto x = model.host_positions();
    const auto srf = model.host_surface();
    const auto& b = model.body();
    const double D_ = c.body.diameter, R = 0.5 * D_, W = model.tank_size(0);
    const double bottom = b.centre[1] - R;
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < srf.size(); ++i)
      if (srf[i] && std::fabs(x[i * D] - b.centre[0]) > D_) {
        sum += x[i * D + 1];
        ++n;
      }
    const double water = double(model.particles()) * c.spacing * c.spacing;
    double lo = 0.0, hi = c.tank[1] + 2 * R;  // W L - A_seg(L - bottom) rises with L (W > 2R): bisection
    for (int k = 0; k < 100; ++k) {
      const double mid = 0.5 * (lo + hi);
      (W * mid - pm::isph::segment_area(R, mid - bottom) < water ? lo : hi) = mid;
    }
    Draft d;
    d.volume = 0.5 * (lo + hi) - bottom;
    d.surface = (n > 0 ? sum / n + 0.5 * c.spacing : c.fluid[1]) - bottom;
    return d;
  };
  nlohmann::json fronts = nlohmann::json::array();
  std::vector<double> psum;
  int pcount = 0;
  const std::int64_t average_from = steps - static_cast<std::int64_t>(std::llround(scene.average_last / c.dt));
  std::int64_t sample_every = scene.sample_every > 0 ? std::max<std::int64_t>(1, std::llround(scene.sample_every / c.dt)) : 1;

  pm::io::Progress progress("isph", steps, c.dt, !opt.quiet);
  me::RunHooks hooks;
  hooks.after_step = [&](std::int64_t k) {
    progress.update(k);
    if (!dam && k > average_from && scene.average_last > 0) {
      const auto p = model.host_pressure();
      if (psum.empty()) psum.assign(p.size(), 0.0);
      for (std::size_t i = 0; i < p.size(); ++i) psum[i] += p[i];
      ++pcount;
    }
  };
  if (scene.snapshot_every > 0) {
    hooks.snapshot_every = std::max<std::int64_t>(1, std::llround(scene.snapshot_every / c.dt));
    hooks.snapshot = snapshot;
  }
  hooks.sample_every = sample_every;
  hooks.sample = [&](std::int64_t k) {
    const double t = static_cast<double>(k) * c.dt;
    t_col.push_back(t);
    it_col.push_back(model.last_solve().iterations);
    res_col.push_back(model.last_solve().residual);
    v_col.push_back(max_speed(model));
    if (body) {
      by_col.push_back(model.body().centre[1]);
      lowest_gap = std::min(lowest_gap, model.body().centre[1] - 0.5 * c.body.diameter);
      const Draft d = draft_now();
      draft_col.push_back(d.volume / c.body.diameter);
      draft_s_col.push_back(d.surface / c.body.diameter);
      fy_col.push_back(model.body().force[1]);
      if (scene.draft_average_last > 0 && t >= scene.end_time - scene.draft_average_last) {
        draft_sum += d.volume / c.body.diameter;
        draft_s_sum += d.surface / c.body.diameter;
        ++draft_count;
      }
    }
    if (dam) {
      const double Z = front_position(model) / a;
      q_col.push_back(Z);
      fronts.push_back({t * tscale, Z});
    } else {
      q_col.push_back(pressure_error(model, model.host_pressure()));
    }
  };
  hooks.watchdog.keep_last_good = true;
  // the app's records in a checkpoint: the snapshot writer, the series, the dam-break fronts, the
  // hydrostatic pressure sum and the draft average under way
  checkpoints.attach(hooks, [&](me::Archive& ar) {
    snapshots.save(ar);
    ar.put_columns("isph/series", std::vector<std::vector<double>>{t_col, it_col, res_col, q_col, v_col, by_col, draft_col,
                                                                    draft_s_col, fy_col});
    std::vector<double> fronts_t, fronts_z;
    for (const auto& f : fronts) {
      fronts_t.push_back(f[0].get<double>());
      fronts_z.push_back(f[1].get<double>());
    }
    ar.put_vector("isph/fronts_T", fronts_t);
    ar.put_vector("isph/fronts_Z", fronts_z);
    ar.put_vector("isph/psum", psum);
    ar.put("isph/pcount", pcount);
    ar.put("isph/draft_sum", draft_sum);
    ar.put("isph/draft_surface_sum", draft_s_sum);
    ar.put("isph/draft_count", draft_count);
    ar.put("isph/lowest_gap", lowest_gap);
  }, opt.quiet);
  if (hooks.resume) {
    const me::Archive& ar = *hooks.resume;
    snapshots.resume(ar);
    const auto cols = ar.get_columns<double>("isph/series");
    if (cols.size() != 9) throw std::runtime_error("checkpoint: isph/series has " + std::to_string(cols.size()) + " columns");
    t_col = cols[0];
    it_col = cols[1];
    res_col = cols[2];
    q_col = cols[3];
    v_col = cols[4];
    by_col = cols[5];
    draft_col = cols[6];
    draft_s_col = cols[7];
    fy_col = cols[8];
    const auto fronts_t = ar.get_vector<double>("isph/fronts_T"), fronts_z = ar.get_vector<double>("isph/fronts_Z");
    for (std::size_t k = 0; k < fronts_t.size() && k < fronts_z.size(); ++k) fronts.push_back({fronts_t[k], fronts_z[k]});
    psum = ar.get_vector<double>("isph/psum");
    pcount = ar.get<int>("isph/pcount");
    draft_sum = ar.get<double>("isph/draft_sum");
    draft_s_sum = ar.get<double>("isph/draft_surface_sum");
    draft_count = ar.get<int>("isph/draft_count");
    lowest_gap = ar.get<double>("isph/lowest_gap");
    progress.resume_at(checkpoints.resume_step());
  }
  const me::RunStats stats = me::run(model, steps - checkpoints.resume_step(), hooks);
  const double wall = stats.wall_seconds;  // with the time before the checkpoints it resumed from
  progress.done(stats.steps);
  const auto xdmf = snapshots.finish();

  nlohmann::json j = pm::apps::summary_header("isph", scene.header);
  j["case"] = scene.case_name;
  j["dimension"] = D;
  j["particles"] = model.particles();
  j["wall_points"] = model.wall_points();
  j["spacing"] = c.spacing;
  j["dt"] = c.dt;
  // the readings that are scene choices (docs/METHODS.md): alpha of eq. (4), the free-surface test, the
  // pressure gradient's form and the ghost interpolation
  j["alpha"] = c.alpha;
  j["ppe_operator"] = c.ppe_stored ? "stored" : "matrix_free";
  j["ppe_preconditioner"] = c.ppe_preconditioner == pm::isph::Config::Preconditioner::two_level ? "two_level" : "jacobi";
  j["surface_detection"] = c.surface_detection == pm::isph::SurfaceDetection::divergence              ? "divergence"
                           : c.surface_detection == pm::isph::SurfaceDetection::divergence_or_density ? "divergence_or_density"
                                                                                                      : "density";
  j["pressure_gradient"] = c.pressure_gradient == pm::isph::PressureGradient::difference ? "difference" : "symmetric";
  j["ghost_interpolation"] = c.ghost_interpolation == pm::isph::GhostInterpolation::linear ? "linear" : "shepard";
  j["steps"] = stats.steps;
  j["wall_seconds"] = wall;
  j["particle_steps_per_second"] = double(model.particles()) * double(stats.steps) / wall;
  j["ppe_iterations_mean"] = model.ppe_solves() > 0 ? double(model.ppe_iterations_total()) / double(model.ppe_solves()) : 0.0;
  j["ppe_share_of_step"] = model.ppe_seconds() / wall;
  j["ppe_last_residual"] = model.last_solve().residual;
  j["particles_put_back_inside"] = model.escaped();
  j["max_speed"] = max_speed(model);
  {  // density drift: mean summation density of the particles off the free surface, over rho0
    const auto rho = model.host_density();
    const auto srf = model.host_surface();
    double sum = 0;
    int n = 0;
    for (std::size_t i = 0; i < rho.size(); ++i)
      if (!srf[i]) {
        sum += rho[i];
        ++n;
      }
    j["interior_density_over_rho0"] = n > 0 ? sum / n / c.density : 0.0;
  }
  pm::apps::put_run_record(j, stats);
  if (stats.diverged) j["reason"] = stats.reason;
  if (dam) {
    j["front_positions"] = fronts;
  } else {
    std::vector<double> p = model.host_pressure();
    if (pcount > 0)
      for (std::size_t i = 0; i < p.size(); ++i) p[i] = psum[i] / pcount;
    j["hydrostatic_pressure_error"] = pressure_error(model, p);
    j["hydrostatic_pressure_error_instantaneous"] = pressure_error(model, model.host_pressure());
    j["pressure_averaged_over_seconds"] = pcount * c.dt;
  }
  if (body) {
    const auto& b = model.body();
    j["body_centre"] = {b.centre[0], b.centre[1]};
    j["body_velocity"] = {b.v[0], b.v[1]};
    j["body_angle"] = b.theta;
    j["body_density_ratio"] = c.body.density_ratio;
    j["body_fluid_rings"] = c.body.fluid_rings;
    j["body_fluid_clearance"] = c.body.fluid_clearance;
    j["body_area_by_quadrature"] = model.body_properties().area;
    j["body_force"] = {b.force[0], b.force[1], b.moment};  // the fluid's, last step [N/m, N/m, N]
    j["body_mass"] = model.body_properties().mass;
    j["body_contact_force"] = {b.contact_force[0], b.contact_force[1], b.contact_moment};  // the tank's
    j["body_drift_over_diameter"] =
        std::hypot(b.centre[0] - c.body.centre[0], b.centre[1] - c.body.centre[1]) / c.body.diameter;
    j["body_speed"] = std::hypot(b.v[0], b.v[1]);
    j["body_gap_to_bottom"] = b.centre[1] - 0.5 * c.body.diameter;  // < 0: overlapping the bottom
    j["body_lowest_gap_to_bottom"] = lowest_gap;
    j["body_weight"] = model.body_properties().mass * c.gravity;
    j["body_buoyancy_immersed"] = c.density * c.gravity * model.body_properties().area;
    j["draft_over_diameter"] = draft_count > 0 ? draft_sum / draft_count : (draft_col.empty() ? 0.0 : draft_col.back());
    j["draft_over_diameter_surface_particles"] =
        draft_count > 0 ? draft_s_sum / draft_count : (draft_s_col.empty() ? 0.0 : draft_s_col.back());
    j["draft_averaged_over_samples"] = draft_count;
    j["archimedes_draft_over_diameter"] = pm::isph::archimedes_draft_over_diameter(c.body.density_ratio);
  }
  j["files"] = {"summary.json", "series.csv", "ppe_residual_history.csv", xdmf.filename().string()};
  pm::io::Columns cols = {t_col, it_col, res_col, q_col, v_col};
  std::vector<std::string> head = {"time", "ppe_iterations", "ppe_residual", dam ? "front_Z" : "pressure_error", "max_speed"};
  if (body) {
    cols.push_back(by_col);
    cols.push_back(draft_col);
    cols.push_back(draft_s_col);
    cols.push_back(fy_col);
    head.push_back("body_y");
    head.push_back("draft_over_diameter");
    head.push_back("draft_over_diameter_surface_particles");
    head.push_back("body_force_y");
  }
  pm::io::write_csv(opt.out / "series.csv", head, cols);
  std::vector<double> k_col, h_col;
  for (std::size_t k = 0; k < model.last_solve().history.size(); ++k) {
    k_col.push_back(double(k));
    h_col.push_back(model.last_solve().history[k]);
  }
  pm::io::Columns hist = {k_col, h_col};
  pm::io::write_csv(opt.out / "ppe_residual_history.csv", {"iteration", "relative_residual"}, hist);
  pm::io::write_json(opt.out / "summary.json", j);
  checkpoints.finished();
  if (!opt.quiet) std::printf("%s\n", j.dump(2).c_str());
  if (stats.diverged) {
    std::fprintf(stderr, "isph: the run diverged at step %lld: %s\n", static_cast<long long>(stats.bad_step),
                 stats.reason.c_str());
    return 1;
  }
  return 0;
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
    const auto scene = pm::io::load_isph_scene(opt.scene, opt.precision, opt.accuracy);
    if (pm::apps::announce_cost("isph", scene.header, scene.cost, opt)) return 0;
    pm::apps::KokkosSession kokkos(opt);
    const bool single = scene.header.precision == "float";
    if (scene.config.dim == 3) return single ? run_case<float, 3>(scene, opt, ropt) : run_case<double, 3>(scene, opt, ropt);
    return single ? run_case<float, 2>(scene, opt, ropt) : run_case<double, 2>(scene, opt, ropt);
  });
}
