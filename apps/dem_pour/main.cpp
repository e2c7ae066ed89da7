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
#include <fstream>

#include "apps/common/app.hpp"
#include "apps/common/restart.hpp"
#include "dem/dem.hpp"
#include "io/dem_pour_scene.hpp"
#include "io/progress.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

std::vector<std::array<double, 4>> sphere_rows(const dm::Dem<double>& m) {
  const auto& s = m.spheres();
  auto x0 = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.x0);
  auto u = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.u);
  auto r = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.radius);
  std::vector<std::array<double, 4>> rows(static_cast<std::size_t>(s.size()));
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = {x0(i, 0) + u(i, 0), x0(i, 1) + u(i, 1), x0(i, 2) + u(i, 2), r(i)};
  return rows;
}

void write_lammps_data(const std::filesystem::path& file, const dm::Config& c, const dm::PourSpec& p) {
  if (!c.clumps.empty()) throw std::invalid_argument("--lammps-data: the scene has clumps; the peer run takes spheres only");
  std::ofstream out(file);
  if (!out) throw std::runtime_error("cannot write " + file.string());
  out.precision(17);
  out << "polymech dem_pour initial particles (atom_style sphere: id type diameter density x y z)\n\n"
      << c.spheres.size() << " atoms\n1 atom types\n\n0 " << p.bin[0] << " xlo xhi\n0 " << p.bin[1] << " ylo yhi\n0 "
      << std::max(p.bin[2], dm::pour_top(p) + 2 * p.radius_max) << " zlo zhi\n\nAtoms\n\n";
  for (std::size_t i = 0; i < c.spheres.size(); ++i) {
    const auto& s = c.spheres[i];
    out << i + 1 << " 1 " << 2 * s.radius << " " << c.particle.density << " " << s.position[0] << " " << s.position[1] << " "
        << s.position[2] << "\n";
  }
}

// Means of the wheel's histories over its steady stage: the last half of the time after the speed ramp
// (the whole drive's last quarter when that is shorter than a quarter of it).
struct WheelMeans {
  double from = 0.0, sinkage = 0.0, vertical = 0.0, tractive = 0.0, torque = 0.0;
  int samples = 0;
};
WheelMeans steady_means(const std::vector<std::vector<double>>& w, double speed_to) {
  WheelMeans m;
  if (w[0].empty()) return m;
  const double end = w[1].back();
  m.from = std::max(speed_to + 0.5 * (end - speed_to), 0.75 * end);
  for (std::size_t k = 0; k < w[0].size(); ++k) {
    if (w[1][k] < m.from) continue;
    m.sinkage += w[4][k];
    m.vertical += w[5][k];
    m.tractive += w[6][k];
    m.torque += w[7][k];
    ++m.samples;
  }
  if (m.samples > 0) {
    m.sinkage /= m.samples;
    m.vertical /= m.samples;
    m.tractive /= m.samples;
    m.torque /= m.samples;
  }
  return m;
}

// The bed's surface across the track (Fig. 7): the highest sphere top in columns of 2 r_max in y over
// the x range the wheel has run over, averaged over x; with the bed's level under the wheel at start.
std::vector<std::vector<double>> track_profile(const std::vector<std::array<double, 4>>& rows, const dm::PourSpec& p, double x0, double x1) {
  const double cell = 2 * p.radius_max;
  const int ny = std::max(1, static_cast<int>(p.bin[1] / cell)), nx = std::max(1, static_cast<int>((x1 - x0) / cell));
  std::vector<double> top(static_cast<std::size_t>(nx * ny), 0.0);
  for (const auto& r : rows) {
    if (r[0] < x0 || r[0] >= x0 + nx * cell || r[1] < 0 || r[1] >= ny * cell) continue;
    const auto k = static_cast<std::size_t>(static_cast<int>((r[0] - x0) / cell) * ny + static_cast<int>(r[1] / cell));
    top[k] = std::max(top[k], r[2] + r[3]);
  }
  std::vector<std::vector<double>> cols(2);
  for (int j = 0; j < ny; ++j) {
    double h = 0;
    for (int i = 0; i < nx; ++i) h += top[static_cast<std::size_t>(i * ny + j)];
    cols[0].push_back((j + 0.5) * cell);
    cols[1].push_back(h / nx);
  }
  return cols;
}

int run_case(const pm::io::DemPourScene& scene, pm::apps::CommonOptions opt, const pm::apps::RestartOptions& ropt,
             const std::string& lammps_data, const std::string& argv0) {
  const dm::Config& c = scene.config;
  const auto steps = opt.steps > 0 ? opt.steps : static_cast<std::int64_t>(std::ceil(scene.duration / c.dt));
  pm::apps::Checkpoints checkpoints(opt, ropt, pm::apps::run_key("dem_pour", scene.header, steps, ""));
  pm::io::make_output_dir(opt.out);
  if (!lammps_data.empty()) write_lammps_data(lammps_data, c, scene.pour);
  dm::Dem<double> model(c);
  const auto spheres = model.sphere_count();
  std::fprintf(stderr,
               "[dem_pour] %s\n  accuracy %s: %d particles (%zu clumps, %lld spheres), radii %.3g-%.3g m, bin %.3g x %.3g x %.3g m\n"
               "  dt = %.3g s (limit %s), %lld steps to %.3g s, %d threads\n",
               scene.header.title.c_str(), scene.header.accuracy.c_str(), scene.pour.count, model.clump_count(),
               static_cast<long long>(spheres), scene.pour.radius_min, scene.pour.radius_max, scene.pour.bin[0], scene.pour.bin[1],
               scene.pour.bin[2], c.dt, model.limit().describe().c_str(), static_cast<long long>(steps), steps * c.dt,
               pm::kx::concurrency<pm::ExecSpace>());

  pm::io::SnapshotMesh mesh;
  mesh.dim = 3;
  std::vector<double> radius, clump;
  for (const auto& row : sphere_rows(model)) {
    mesh.points.insert(mesh.points.end(), row.begin(), row.begin() + 3);
    radius.push_back(row[3]);
  }
  clump.assign(static_cast<std::size_t>(spheres), -1.0);
  for (std::size_t i = c.spheres.size(), b = 0, k = 0; i < clump.size(); ++i) {  // members, clump after clump
    clump[i] = double(b);
    if (++k == c.clump_shapes[static_cast<std::size_t>(c.clumps[b].shape)].spheres.size()) {
      k = 0;
      ++b;
    }
  }
  pm::io::SnapshotWriter snapshots(opt.out, "fields", std::move(mesh));
  auto snapshot = [&](std::int64_t step) {
    const auto& s = model.spheres();
    auto u = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.u);
    auto v = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.v);
    std::vector<double> hu(u.data(), u.data() + u.size()), hv(v.data(), v.data() + v.size());
    snapshots.add(step, model.time(), {{"displacement", 3, hu}, {"velocity", 3, hv}, {"radius", 1, radius}, {"clump", 1, clump}});
  };
  std::vector<std::vector<double>> series(4);  // time, kinetic, mean height, top height
  const bool wheel = c.wheel.enabled();
  std::vector<std::vector<double>> wheel_series(10);  // see the header of wheel.csv below
  auto sample = [&](std::int64_t) {
    if (wheel && model.wheel().placed) {
      const auto w = model.wheel();
      const double row[10] = {model.time(), w.time, w.centre[0], w.centre[2], 1e3 * w.sinkage, w.vertical_force, w.tractive_force,
                              w.driving_torque, w.load, w.speed};
      for (std::size_t k = 0; k < 10; ++k) wheel_series[k].push_back(row[k]);
    }
    const auto rows = sphere_rows(model);
    double mean = 0, top = 0;
    for (const auto& r : rows) {
      mean += r[2];
      top = std::max(top, r[2] + r[3]);
    }
    series[0].push_back(model.time());
    series[1].push_back(model.kinetic_energy());
    series[2].push_back(mean / double(rows.size()));
    series[3].push_back(top);
  };

  pm::io::Progress progress("dem_pour", steps, c.dt, !opt.quiet);
  pm::models::RunHooks hooks;
  // the heap: the wall x = lx opens at release_at (moved far behind the spheres; planes are state, so a
  // restart after the release keeps it open)
  const auto release_step = scene.pour.release_at > 0 ? static_cast<std::int64_t>(std::llround(scene.pour.release_at / c.dt)) : -1;
  hooks.after_step = [&](std::int64_t k) {
    progress.update(k);
    if (k == release_step) model.move_plane(dm::kReleaseWall, {1e3, 0.0, 0.0});
  };
  hooks.sample_every = scene.sample_every;
  hooks.sample_at_start = true;
  hooks.sample = sample;
  hooks.snapshot_every = scene.snapshots > 0 ? std::max<std::int64_t>(1, steps / scene.snapshots) : 0;
  hooks.snapshot = snapshot;
  hooks.watchdog.keep_last_good = true;
  checkpoints.attach(hooks, [&](pm::models::Archive& a) {
    snapshots.save(a);
    a.put_columns("dem_pour/series", series);
    if (wheel) a.put_columns("dem_pour/wheel", wheel_series);
  }, opt.quiet);
  if (hooks.resume) {
    snapshots.resume(*hooks.resume);
    series = hooks.resume->get_columns<double>("dem_pour/series");
    if (wheel) wheel_series = hooks.resume->get_columns<double>("dem_pour/wheel");
    hooks.sample_at_start = false;
    progress.resume_at(checkpoints.resume_step());
  }
  const auto stats = pm::models::run(model, steps - checkpoints.resume_step(), hooks);
  progress.done(stats.steps);
  if (stats.diverged)
    std::fprintf(stderr, "[dem_pour] the run diverged at step %lld: %s; the last good state (step %lld) is the last snapshot\n",
                 static_cast<long long>(stats.bad_step), stats.reason.c_str(), static_cast<long long>(stats.last_good_step));

  const auto rows = sphere_rows(model);
  std::array<double, 3> lo{}, hi{};
  dm::bed_box(rows, scene.pour, lo, hi);
  const bool bed = hi[2] > lo[2];  // a bed thicker than 2 radius_max (not at draft accuracy on a wide bin)
  const double phi = bed ? dm::packing_fraction(rows, lo, hi, 80) : NAN;
  pm::io::write_csv(opt.out / "energy.csv", {"time", "kinetic_energy", "mean_height", "top_height"}, series);
  const auto xdmf = snapshots.finish();

  nlohmann::json j = pm::apps::summary_header("dem_pour", scene.header);
  j["command"] = argv0;
  pm::apps::put_run_record(j, stats);
  if (scene.pour.release_at > 0) {  // a heap: its angle, not a bed
    std::vector<std::array<double, 2>> profile;
    const double angle = dm::repose_angle(rows, scene.pour, &profile);
    std::vector<std::vector<double>> cols(2);
    for (const auto& p : profile) {
      cols[0].push_back(p[0]);
      cols[1].push_back(p[1]);
    }
    pm::io::write_csv(opt.out / "heap_profile.csv", {"x", "surface_height"}, cols);
    j["repose_angle_deg"] = std::isfinite(angle) ? nlohmann::json(angle) : nlohmann::json(nullptr);
    j["release_at"] = scene.pour.release_at;
    std::printf("heap released at %.3g s: angle of repose %.2f degrees (heap_profile.csv)\n", scene.pour.release_at, angle);
  }
  if (wheel) {  // seed 002 paper 2, Figs. 7-10
    pm::io::write_csv(opt.out / "wheel.csv",
                      {"time", "time_from_start", "x", "z", "sinkage_mm", "vertical_force", "tractive_force", "driving_torque", "load", "speed"},
                      wheel_series);
    const auto w = model.wheel();
    const auto means = steady_means(wheel_series, c.wheel.speed_to);
    pm::io::write_csv(opt.out / "track_profile.csv", {"y", "surface_height"},
                      track_profile(rows, scene.pour, c.wheel.x_start, std::max(c.wheel.x_start + 2 * scene.pour.radius_max, w.centre[0])));
    j["sinkage_mm"] = means.samples > 0 ? nlohmann::json(means.sinkage) : nlohmann::json(nullptr);
    j["vertical_force"] = means.samples > 0 ? nlohmann::json(means.vertical) : nlohmann::json(nullptr);
    j["tractive_force"] = means.samples > 0 ? nlohmann::json(means.tractive) : nlohmann::json(nullptr);
    j["driving_torque"] = means.samples > 0 ? nlohmann::json(means.torque) : nlohmann::json(nullptr);
    j["steady_stage_from"] = means.from;
    j["paper_sinkage_mm"] = 53.6;
    j["wheel"] = {{"radius", c.wheel.radius}, {"width", c.wheel.width}, {"mass", c.wheel.mass}, {"load", c.wheel.load},
                  {"speed", c.wheel.speed}, {"slip", c.wheel.slip}, {"start", c.wheel.start}, {"facets_around", c.wheel.around},
                  {"facets_across", c.wheel.across}, {"bed_level", w.bed_level}, {"travel", w.centre[0] - c.wheel.x_start},
                  {"time_driven", w.time}};
    std::printf("wheel: %.3g s after it was set down, travelled %.3g m; steady stage (t >= %.3g s): rim sinkage %.2f mm (paper, deformable "
                "tyre: 53.6), vertical force %.4g N (load %.4g), tractive force %.4g N, driving torque %.4g N m (wheel.csv)\n",
                w.time, w.centre[0] - c.wheel.x_start, means.from, means.sinkage, means.vertical, c.wheel.load, means.tractive, means.torque);
  }
  j["packing_fraction"] = bed ? nlohmann::json(phi) : nlohmann::json(nullptr);
  if (!bed) j["packing_fraction_note"] = "the bed is thinner than 2 radius_max: nothing to measure (pour more particles)";
  j["bed_box"] = {{"lo", lo}, {"hi", hi}};
  j["bed_height"] = hi[2] + scene.pour.radius_max;
  j["particles"] = scene.pour.count;
  j["clumps"] = model.clump_count();
  j["spheres"] = spheres;
  j["shapes"] = scene.pour.shapes;
  j["dt"] = c.dt;
  j["time_step_limit"] = model.limit().limit;
  j["steps"] = stats.steps;
  j["simulated_time"] = model.time();
  j["final_kinetic_energy"] = model.kinetic_energy();
  j["wall_seconds"] = stats.wall_seconds;
  j["sphere_steps_per_second"] = stats.wall_seconds > 0 ? double(spheres) * double(stats.steps - checkpoints.resume_step()) / stats.wall_seconds : 0.0;
  j["threads"] = pm::kx::concurrency<pm::ExecSpace>();
  j["sphere_list_builds"] = model.sphere_list_builds();
  j["files"] = {"summary.json", "energy.csv", "fields.h5", xdmf.filename().string()};
  if (wheel) {
    j["files"].push_back("wheel.csv");
    j["files"].push_back("track_profile.csv");
  }
  pm::io::write_json(opt.out / "summary.json", j);
  checkpoints.finished();
  std::printf("%d particles (%lld spheres) poured in %.3f s simulated: packing fraction %.4f in [%.3g, %.3g] x [%.3g, %.3g] x "
              "[%.3g, %.3g] m, kinetic energy %.3g J; wall %.1f s (%.3g sphere-steps/s)\n",
              scene.pour.count, static_cast<long long>(spheres), model.time(), phi, lo[0], hi[0], lo[1], hi[1], lo[2], hi[2],
              model.kinetic_energy(), stats.wall_seconds, double(j["sphere_steps_per_second"]));
  std::printf("results in %s: summary.json, energy.csv, %s (open in ParaView)\n", opt.out.c_str(), xdmf.filename().c_str());
  return stats.diverged ? 1 : 0;
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
  std::string command;
  for (int k = 0; k < argc; ++k) command += (k ? " " : "") + std::string(argv[k]);
  return pm::apps::guarded("dem_pour", [&] {
    pm::apps::KokkosSession kokkos(opt);
    const auto scene = pm::io::load_dem_pour_scene(opt.scene, opt.accuracy, opt.precision);
    if (pm::apps::announce_cost("dem_pour", scene.header, scene.cost, opt)) return 0;
    return run_case(scene, opt, ropt, lammps_data, command);
  });
}
