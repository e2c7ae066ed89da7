// The Chung & Ooi (2011) DEM benchmark impacts (seed 002 paper 2's contact law): runs a scene of
// scenes/dem/ (or, with --all, every chung_ooi_test*.toml next to it) and compares with Hertz theory.
//   dem_benchmark [--scene scenes/dem/chung_ooi_test1.toml] [--all] [--out out/dem_benchmark]
// Writes summary.json: test1_max_force, test1_contact_time, test1_max_overlap (and the Hertz values and
// relative errors), the same for test2 (and test2_mesh_* for the meshed wall), test3_restitution
// [[input, measured], ...], test4_rebound_angles [[incidence_deg, rebound_deg], ...] (the contact point's),
// test4_centre_rebound_angles (the centre of mass's); and test4.csv (both angles, velocity and spin after).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/app.hpp"
#include "dem/benchmark.hpp"
#include "io/dem_scene.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

std::int64_t total_steps = 0;  // over every run, for the rate in summary.json
bool wrote_test4 = false;      // test4.csv, for the summary's file list

// One impact of the scene in the scene's precision (the kernels' type; the measures are double).
dm::ImpactMeasure impact(const pm::io::DemScene& s, double angle_deg, double restitution) {
  const auto c = pm::io::dem_impact_config(s, angle_deg, restitution);
  return s.header.precision == "float" ? dm::run_impact<float>(c) : dm::run_impact<double>(c);
}

void run_scene(const pm::io::DemScene& s, const std::filesystem::path& out_dir, nlohmann::json& j, bool quiet) {
  const std::string prefix = "test" + std::to_string(s.test) + (s.target == "mesh" ? "_mesh_" : "_");
  if (s.test == 1 || s.test == 2) {
    const auto got = impact(s, 0.0, s.restitutions[0]);
    total_steps += got.steps;
    const auto h = dm::hertz_impact(s.impact, s.target == "sphere");  // models/dem/benchmark.hpp
    const auto e = dm::hertz_errors(got, h);
    j[prefix + "max_force"] = got.max_force;
    j[prefix + "contact_time"] = got.contact_time;
    j[prefix + "max_overlap"] = got.max_overlap;
    j[prefix + "restitution"] = got.normal_restitution;
    j[prefix + "hertz_max_force"] = h.max_force;
    j[prefix + "hertz_contact_time"] = h.contact_time;
    j[prefix + "hertz_max_overlap"] = h.max_overlap;
    j[prefix + "max_force_error"] = e.max_force;
    j[prefix + "contact_time_error"] = e.contact_time;
    j[prefix + "max_overlap_error"] = e.max_overlap;
    j[prefix + "dt"] = pm::io::dem_impact_config(s, 0.0, s.restitutions[0]).dt;
    if (!quiet)
      std::printf("%s: F_max %.6g N (Hertz %.6g, %+.3f %%), delta_max %.6g m (%+.3f %%), t_c %.6g s (Hertz %.6g, %+.3f %%)\n",
                  s.header.file.filename().c_str(), got.max_force, h.max_force, 100 * e.max_force, got.max_overlap,
                  100 * e.max_overlap, got.contact_time, h.contact_time, 100 * e.contact_time);
  } else if (s.test == 3) {
    nlohmann::json rows = nlohmann::json::array();
    for (double e : s.restitutions) {
      const auto got = impact(s, 0.0, e);
      total_steps += got.steps;
      rows.push_back({e, got.normal_restitution});
      if (!quiet) std::printf("test 3: restitution %.2f -> measured %.4f\n", e, got.normal_restitution);
    }
    j["test3_restitution"] = rows;
  } else if (s.test == 4) {
    dm::ReboundTable table;  // models/dem/benchmark.hpp
    for (double angle : s.angles) {
      const auto got = impact(s, angle, s.restitutions[0]);
      total_steps += got.steps;
      table.add(angle, got, s.impact.radius);
      if (!quiet)
        std::printf("test 4: incidence %4.1f deg -> rebound %7.3f deg (contact point), %7.3f deg (centre)\n", angle,
                    table.contact_point.back(), table.centre.back());
    }
    j["test4_rebound_angles"] = pm::apps::json_pairs(table.incidence, table.contact_point);
    j["test4_centre_rebound_angles"] = pm::apps::json_pairs(table.incidence, table.centre);
    pm::io::write_csv(out_dir / "test4.csv", dm::ReboundTable::header(), table.columns());
    wrote_test4 = true;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Chung & Ooi (2011) DEM benchmark impacts against Hertz theory (seed 002 paper 2)"};
  pm::apps::CommonOptions opt;
  pm::apps::add_common_options(app, opt, "scenes/dem/chung_ooi_test1.toml", "out/dem_benchmark");
  pm::apps::refuse_option(app, "--steps", "each Chung-Ooi test runs its impacts to their end (the scene's [time])");
  pm::apps::refuse_option(app, "--accuracy", "the Chung-Ooi tests are single spheres and pairs: there is nothing to refine");
  bool all = false;
  app.add_flag("--all", all, "run every chung_ooi_test*.toml in the scene's folder");
  if (const auto rc = pm::apps::parse_command_line(app, "dem_benchmark", argc, argv)) return *rc;
  return pm::apps::guarded("dem_benchmark", [&] {
    pm::apps::KokkosSession kokkos(opt);
    std::vector<std::filesystem::path> files = {opt.scene};
    if (all) {
      files.clear();
      for (const auto& e : std::filesystem::directory_iterator(opt.scene.parent_path()))
        if (e.path().filename().string().rfind("chung_ooi_test", 0) == 0 && e.path().extension() == ".toml")
          files.push_back(e.path());
      std::sort(files.begin(), files.end());
    }
    std::vector<pm::io::DemScene> scenes;
    for (const auto& f : files) scenes.push_back(pm::io::load_dem_scene(f, {"", opt.precision}));
    bool stop = false;
    for (const auto& s : scenes) stop = pm::apps::announce_cost("dem_benchmark", s.header, s.cost, opt) || stop;
    if (stop) return 0;
    pm::io::make_output_dir(opt.out);
    nlohmann::json j = pm::apps::summary_header("dem_benchmark", scenes.front().header);
    j["scenes"] = nlohmann::json::array();
    const auto t0 = std::chrono::steady_clock::now();
    for (const auto& s : scenes) {
      j["scenes"].push_back(s.header.file.string());
      run_scene(s, opt.out, j, opt.quiet);
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    j["wall_seconds"] = wall;
    j["steps"] = total_steps;
    j["steps_per_second"] = static_cast<double>(total_steps) / wall;
    // the files it wrote, like every app's summary (issue 33 item 10)
    nlohmann::json written = {"summary.json"};
    if (wrote_test4) written.push_back("test4.csv");
    j["files"] = written;
    pm::io::write_json(opt.out / "summary.json", j);
    std::printf("results in %s\n", opt.out.c_str());
    return 0;
  });
}
