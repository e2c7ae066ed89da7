// Gravel poured into a bin (seed 002 paper 2, sec. 2 and Fig. 6: multi-sphere gravel particles of
// radii 5-7 mm fill the soil bin before the tyre runs on it): the particles drop from a lattice, settle,
// and the bed's packing fraction is measured.
//   dem_pour [--scene scenes/dem/gravel_pour.toml] [--out out/dem_pour] [--accuracy draft|standard|paper]
//            [--steps N] [--restart OUT] [--checkpoint-every S] [--lammps-data FILE]
// Writes summary.json (packing_fraction, bed_height, particles, spheres, clumps, steps, wall_seconds,
// sphere_steps_per_second, final kinetic energy, run record), energy.csv (time, kinetic energy, mean
// and top particle height) and fields.h5 + fields.xdmf (ParaView: displacement from the start,
// velocity, radius, clump). --lammps-data writes the initial particles as a LAMMPS/LIGGGHTS data file
// (atom_style sphere; spheres only) for the side-by-side run of bench/peers/liggghts.
// With a [wheel] (scenes/dem/wheel_gravel*.toml; seed 002 paper 2, sec. 4) the rigid wheel is set on the
// bed at wheel.start and driven: wheel.csv (its histories, Figs. 8-10: vertical force, tractive force,
// rim sinkage, driving torque), track_profile.csv (the bed's surface across the track, Fig. 7) and the
// summary's sinkage_mm, vertical_force, tractive_force (means over the steady stage).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "apps/common/case.hpp"
#include "dem/analysis.hpp"
#include "io/dem_pour_scene.hpp"
#include "io/lammps_data.hpp"
#include "solid/tyre_section.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

int run_case(const pm::io::DemPourScene& scene, const pm::apps::CommonOptions& opt, const pm::apps::RestartOptions& ropt,
             const std::string& lammps_data) {
  const dm::Config& c = scene.config;
  dm::Dem<double> model(c);  // (with a tyre and no time.dt: the smaller of the spheres' and the tyre's step)
  const auto steps = opt.steps > 0 ? opt.steps : c.dt > 0 ? scene.steps : static_cast<std::int64_t>(std::ceil(scene.duration / model.dt()));
  pm::apps::Case cs({"dem_pour", scene.header, steps, model.dt()}, opt, ropt);
  if (!lammps_data.empty()) pm::io::write_lammps_data(lammps_data, c, scene.pour);
  const auto spheres = model.sphere_count();
  std::fprintf(stderr,
               "[dem_pour] %s\n  accuracy %s: %d particles (%zu clumps, %lld spheres), radii %.3g-%.3g m, bin %.3g x %.3g x %.3g m\n"
               "  dt = %.3g s (limit %s), %lld steps to %.3g s, %s\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), scene.pour.count, model.clump_count(),
               static_cast<long long>(spheres), scene.pour.radius_min, scene.pour.radius_max, scene.pour.bin[0], scene.pour.bin[1],
               scene.pour.bin[2], model.dt(), model.limit().describe().c_str(), static_cast<long long>(steps), steps * model.dt(),
               pm::apps::thread_count().c_str());
  if (c.effects.has("fe_tyre"))  // the tyre's own step: it sets the common step or is subcycled under the spheres'
    std::fprintf(stderr, "  tyre: %lld DoFs, its step %.4g s (critical %.4g s), %d per DEM step\n",
                 static_cast<long long>(model.tyre().solid().dof_count()), model.tyre().solid().time_step(),
                 model.tyre().solid().critical_time_step(), model.tyre().substeps());

  // snapshots: displacement from the start, velocity, radius and the clump each sphere belongs to
  auto layout = dm::sphere_layout(model, c);
  cs.snapshots(pm::apps::point_mesh(3, std::move(layout.points)))
      .every(scene.snapshots > 0 ? std::max<std::int64_t>(1, steps / scene.snapshots) : 0, [&](std::int64_t) {
        auto m = dm::sphere_motion(model);
        return pm::apps::CaseSnapshots::Fields{{"displacement", 3, std::move(m.u)}, {"velocity", 3, std::move(m.v)},
                                               {"radius", 1, layout.radius}, {"clump", 1, layout.clump}};
      }, [&](std::int64_t) { return model.time(); });
  pm::apps::Series series(dm::pour_columns()), wheel_series(dm::wheel_columns());
  const bool wheel = c.wheel.enabled();
  cs.records.keep("dem_pour/series", series);
  if (wheel) cs.records.keep("dem_pour/wheel", wheel_series);
  // the bed as the wheel meets it (the summary's packing_fraction is the run's end, after the wheel has passed)
  pm::apps::Series set_down({"time", "packing_fraction", "bed_height"});
  if (wheel) cs.records.keep("dem_pour/bed_at_set_down", set_down);
  cs.hooks.sample_every = scene.sample_every;
  cs.hooks.sample_at_start = true;
  cs.hooks.sample = [&](std::int64_t) {
    if (wheel && model.wheel().placed) wheel_series.append(dm::wheel_row(model.time(), model.wheel()));
    series.append(dm::pour_row(model));
  };
  // the heap: the wall x = lx opens at release_at (moved far behind the spheres; planes are state, so a
  // restart after the release keeps it open)
  const auto release_step = scene.pour.release_at > 0 ? static_cast<std::int64_t>(std::llround(scene.pour.release_at / model.dt())) : -1;
  cs.after_step = [&](std::int64_t k) {
    if (k == release_step) model.move_plane(dm::kReleaseWall, {1e3, 0.0, 0.0});
    if (wheel && set_down.empty() && model.time() >= c.wheel.start - 0.5 * model.dt()) {
      const auto b = dm::settled_bed(dm::sphere_rows(model), scene.pour);
      set_down.append({model.time(), b.measured ? b.packing_fraction : NAN, b.hi[2] + scene.pour.radius_max});
    }
  };
  cs.hooks.watchdog.keep_last_good = true;
  const auto stats = cs.run([&](auto& hooks, std::int64_t n) { return pm::models::run(model, n, hooks); });

  const auto rows = dm::sphere_rows(model);
  const auto bed = dm::settled_bed(rows, scene.pour);  // none thinner than 2 radius_max (draft accuracy on a wide bin)
  const auto &lo = bed.lo, &hi = bed.hi;
  series.write_csv(cs.out() / "energy.csv");
  std::vector<std::string> files = {"summary.json", "energy.csv", "fields.h5", cs.snapshots().finish().filename().string()};

  nlohmann::json j = cs.summary();
  if (scene.pour.release_at > 0) {  // a heap: its angle, not a bed
    const auto heap = dm::heap(rows, scene.pour);
    pm::io::write_csv(cs.out() / "heap_profile.csv", {"x", "surface_height"}, heap.profile);
    files.push_back("heap_profile.csv");
    j["repose_angle_deg"] = std::isfinite(heap.angle) ? nlohmann::json(heap.angle) : nlohmann::json(nullptr);
    j["release_at"] = scene.pour.release_at;
    std::printf("heap released at %.3g s: angle of repose %.2f degrees (heap_profile.csv)\n", scene.pour.release_at, heap.angle);
  }
  if (wheel) {  // seed 002 paper 2, Figs. 7-10
    wheel_series.write_csv(cs.out() / "wheel.csv");
    const auto w = model.wheel();
    const auto means = dm::steady_means(wheel_series.all(), c.wheel.speed_to);
    pm::io::write_csv(cs.out() / "track_profile.csv", {"y", "surface_height"}, dm::track_profile(rows, scene.pour, c.wheel, w));
    auto mean = [&](double x) { return means.samples > 0 ? nlohmann::json(x) : nlohmann::json(nullptr); };
    j["sinkage_mm"] = mean(means.sinkage);
    j["tread_sinkage_mm"] = mean(means.tread_sinkage);
    j["vertical_force"] = mean(means.vertical);
    j["tractive_force"] = mean(means.tractive);
    j["driving_torque"] = mean(means.torque);
    j["steady_stage_from"] = means.from;
    j["paper_sinkage_mm"] = 53.6;
    if (!set_down.empty())  // the settled bed before the wheel (packing_fraction below: the run's end)
      j["bed_at_set_down"] = {{"time", set_down["time"][0]},
                              {"packing_fraction", std::isfinite(set_down["packing_fraction"][0]) ? nlohmann::json(set_down["packing_fraction"][0]) : nlohmann::json(nullptr)},
                              {"bed_height", set_down["bed_height"][0]}};
    j["wheel"] = {{"radius", c.wheel.radius}, {"width", c.wheel.width}, {"mass", c.wheel.mass}, {"load", c.wheel.load}, {"damping", c.wheel.damping},
                  {"speed", c.wheel.speed}, {"slip", c.wheel.slip}, {"start", c.wheel.start}, {"facets_around", c.wheel.around},
                  {"facets_across", c.wheel.across}, {"bed_level", w.bed_level}, {"travel", w.centre[0] - c.wheel.x_start},
                  {"time_driven", w.time}};
    if (c.effects.has("fe_tyre"))  // the deformable tyre (issue 37): its lattice and inflation; the wheel's facets are its surface's
      j["tyre"] = {{"cells", {c.tyre.around, c.tyre.across, c.tyre.through}}, {"order", c.tyre.order}, {"pressure", c.tyre.pressure},
                   {"wall", c.tyre.belt_rebar ? "belted_rebar" : c.tyre.layered ? "layered" : "smeared"},
                   {"crown_radius", c.tyre.crown_radius > 0 ? c.tyre.crown_radius : polymech::solid::TyreSpec{}.crown_radius},
                   {"deflate", {c.tyre.deflate[0], c.tyre.deflate[1]}}, {"substeps", model.tyre().substeps()},
                   {"time_step", model.tyre().solid().time_step()},
                   {"dofs", model.tyre().solid().dof_count()}, {"critical_step", model.tyre().solid().critical_time_step()},
                   {"surface_facets", model.surface().facet_count()}, {"damping", c.tyre.damping}};
    files.insert(files.end(), {"wheel.csv", "track_profile.csv"});
    std::printf("wheel: %.3g s after it was set down, travelled %.3g m; steady stage (t >= %.3g s): rim sinkage %.2f mm (paper, deformable "
                "tyre: 53.6), vertical force %.4g N (load %.4g), tractive force %.4g N, driving torque %.4g N m (wheel.csv)\n",
                w.time, w.centre[0] - c.wheel.x_start, means.from, means.sinkage, means.vertical, c.wheel.load, means.tractive, means.torque);
  }
  j["friction"] = c.friction;
  if (c.pour_friction >= 0)  // a denser bed: the pour's lower friction (docs/METHODS.md)
    j["pour_friction"] = {{"mu", c.pour_friction}, {"until", c.pour_friction_until}};
  j["packing_fraction"] = bed.measured ? nlohmann::json(bed.packing_fraction) : nlohmann::json(nullptr);
  if (!bed.measured) j["packing_fraction_note"] = "the bed is thinner than 2 radius_max: nothing to measure (pour more particles)";
  j["bed_box"] = {{"lo", lo}, {"hi", hi}};
  j["bed_height"] = hi[2] + scene.pour.radius_max;
  j["particles"] = scene.pour.count;
  j["clumps"] = model.clump_count();
  j["spheres"] = spheres;
  j["shapes"] = scene.pour.shapes;
  j["dt"] = model.dt();
  j["time_step_limit"] = model.limit().limit;
  j["steps"] = stats.steps;
  j["simulated_time"] = model.time();
  j["final_kinetic_energy"] = model.kinetic_energy();
  j["wall_seconds"] = stats.wall_seconds;
  const double rate = stats.wall_seconds > 0 ? double(spheres) * double(stats.steps - cs.resume_step()) / stats.wall_seconds : 0.0;
  j["sphere_steps_per_second"] = rate;
  j["sphere_list_builds"] = model.sphere_list_builds();
  const int rc = cs.finish(j, stats, files);
  std::printf("%d particles (%lld spheres) poured in %.3f s simulated: packing fraction %.4f in [%.3g, %.3g] x [%.3g, %.3g] x "
              "[%.3g, %.3g] m, kinetic energy %.3g J; wall %.1f s (%.3g sphere-steps/s)\n",
              scene.pour.count, static_cast<long long>(spheres), model.time(), bed.packing_fraction, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2],
              model.kinetic_energy(), stats.wall_seconds, rate);
  std::printf("results in %s: summary.json, energy.csv, %s (open in ParaView)\n", cs.out().c_str(), files[3].c_str());
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Gravel poured into a bin: multi-sphere DEM (seed 002 paper 2)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/dem/gravel_pour.toml", "out/dem_pour");
  pm::apps::RestartOptions ropt;
  pm::apps::add_restart_options(app, ropt);
  std::string lammps_data;
  app.add_option("--lammps-data", lammps_data, "also write the initial spheres as a LAMMPS/LIGGGHTS data file");
  if (const auto rc = pm::apps::parse_command_line(app, "dem_pour", argc, argv)) return *rc;
  return pm::apps::guarded("dem_pour", [&] {
    pm::apps::KokkosSession kokkos(opt);
    const auto scene = pm::io::load_dem_pour_scene(opt.scene, {opt.accuracy, opt.precision});
    if (pm::apps::announce_cost("dem_pour", scene.header, scene.cost, opt)) return 0;
    return run_case(scene, opt, ropt, lammps_data);
  });
}
