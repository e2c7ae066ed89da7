// Seed 003 §4(1): uniaxial tension of a bar, NOSB peridynamics. Measures Young's modulus (quasi-static,
// by dynamic relaxation) on the scene's layout, or, with --identify-omega-v, the oscillation frequency
// omega_v of eq. (3) from the same pull without damping or control (as the report identified it).
//   pd_tension [--scene scenes/pd/tension_conforming.toml] [--out out/pd_tension] [--identify-omega-v]
//              [--restart OUT] [--checkpoint-every S] [--checkpoint-steps N]
// Writes summary.json (modulus, reference, relative_error or omega_v, particles, bonds, wall_seconds,
// run record) and fields.h5 + fields.xdmf (displacement at the end). The modulus run goes through the
// shared run driver: checkpoints and --restart as in apps/common/restart.hpp (not --identify-omega-v).
#include <cmath>
#include <cstdio>

#include "apps/common/case.hpp"
#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/tension.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

template <class T, int D>
int run_case(pm::io::NosbPdScene scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt, bool identify,
             double horizon_ratio) {
  np::Config& c = scene.config;
  if (identify && !ropt.restart.empty())
    throw std::invalid_argument("--restart: the --identify-omega-v run has no checkpoints (it takes seconds); run it again");
  char extra[64];
  std::snprintf(extra, sizeof extra, "horizon_ratio=%.17g", horizon_ratio);
  pm::apps::CaseSpec spec("pd_tension", scene.header, opt.steps, c.dt, extra);
  spec.checkpoints = !identify;
  spec.progress = false;  // run_tension prints its own (dynamic relaxation has no fixed length)
  pm::apps::Case cs(spec, opt, ropt);
  if (identify) {
    c = np::omega_v_identification(c);
    scene.header.effects = c.effects;  // what ran
  }
  np::NosbPd<T, D> model(c);
  std::fprintf(stderr, "[pd_tension] %s\n  accuracy %s (spacing %.3g m, m = %g), %s, %d particles, %lld bonds, dt %.3g s\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), c.spacing, c.horizon_ratio, scene.header.precision.c_str(), model.particles(),
               static_cast<long long>(model.bonds()), c.dt);
  nlohmann::json j = pm::apps::summary_header("pd_tension", scene.header);
  j["spacing"] = c.spacing;
  j["horizon_ratio"] = c.horizon_ratio;
  j["particles"] = model.particles();
  j["bonds"] = model.bonds();
  j["dt"] = c.dt;
  auto& snapshots = cs.snapshots(pm::apps::point_mesh(D, model.host_fields().x0));
  auto write_fields = [&] {  // the displacement at the end
    const auto h = model.host_fields();
    snapshots.add(model.step_index(), model.time(), pm::io::Fields{{"displacement", D, h.u}, {"velocity", D, h.v}});
    return std::vector<std::string>{"summary.json", "fields.h5", snapshots.finish().filename().string()};
  };
  if (identify) {
    const auto r = np::identify_omega_v(model, scene.tension);
    j["omega_v"] = r.omega;
    j["zero_crossings"] = r.crossings;
    j["duration"] = r.duration;
    j["omega_v_times_spacing_over_cp"] = r.omega * c.spacing / c.material.p_wave_speed();
    std::printf("omega_v = %.4g rad/s (%lld zero crossings of v - vbar over %.3g s; omega_v h / c_p = %.3f)\n", r.omega,
                static_cast<long long>(r.crossings), r.duration, r.omega * c.spacing / c.material.p_wave_speed());
    cs.finish(j, write_fields());
    std::printf("results in %s\n", cs.out().c_str());
    return 0;
  }
  np::TensionResult r;
  cs.run([&](auto& hooks, std::int64_t) {
    r = np::run_tension(model, scene.tension, hooks);
    return r.run;
  });
  j["modulus"] = r.modulus;
  j["reference"] = r.reference;
  j["relative_error"] = r.relative_error;
  j["gauge_strain"] = r.gauge_strain;
  j["stress"] = r.stress;
  j["steps"] = r.steps;
  j["wall_seconds"] = r.wall_seconds;
  std::printf("E = %.4g Pa (reference %.4g Pa, %+.2f %%), gauge strain %.4g, %lld steps, %.1f s\n", r.modulus, r.reference,
              100 * r.relative_error, r.gauge_strain, static_cast<long long>(r.steps), r.wall_seconds);
  const int rc = cs.finish(j, r.run, write_fields());
  std::printf("results in %s\n", cs.out().c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Uniaxial tension of a bar, NOSB peridynamics (seed 003 section 4(1))"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/pd/tension_conforming.toml", "out/pd_tension");
  pm::apps::refuse_option(app, "--steps", "the pull lasts loading.ramp + loading.hold wave transits of the bar (the scene's [loading])");
  bool identify = false;
  double m = 0;
  app.add_flag("--identify-omega-v", identify, "measure omega_v of eq. (3) from the undamped pull without control");
  pm::apps::within(app.add_option("--horizon-ratio", m, "m = delta / spacing (default: the scene's)"), 1.0, 10.0);
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  if (const auto rc = pm::apps::parse_command_line(app, "pd_tension", argc, argv)) return *rc;
  return pm::apps::guarded("pd_tension", [&] {
    pm::apps::KokkosSession kokkos(opt);
    pm::io::NosbPdSceneOptions so;
    so.accuracy = opt.accuracy;
    so.precision = opt.precision;
    so.horizon_ratio = m;
    const auto scene = pm::io::load_nosb_pd_scene(opt.scene, so);
    if (scene.config.loading != np::Loading::tension)
      throw pm::io::SceneError(opt.scene.string() + ": loading.kind must be \"tension\" for pd_tension");
    if (pm::apps::announce_cost("pd_tension", scene.header, scene.cost, opt)) return 0;
    return pm::apps::with_precision_and_dimension(scene.header.precision, scene.config.dimension, [&](auto t, auto d) {
      return run_case<decltype(t), decltype(d)::value>(scene, opt, ropt, identify, m);
    });
  });
}
