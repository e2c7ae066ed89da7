// Accuracy-cost sweep of the higher-harmonic cases (seed 000 §5.2): a crack scene at several
// resolutions, in double and float; for each run the harmonic ratios A_n/A_1 (crack and no crack) at
// probe A, their difference from the finest double run, and the cost (wall and CPU time).
//
//   sweep_mps_harmonics --scene scenes/mps/crack_p_wave.toml [--coarsening 4,2,1] [--precision double,float]
//                       [--out out/accuracy_cost] [--width 0.04 --depth 0.010 --below 0.012]
//
// --width/--depth/--below crop the plate around the crack (crack centred, `depth` below the top
// surface, `below` of plate under it; probes keep their offsets from the crack) and the run lasts
// until the burst has passed probe A: the paper-size plate at three resolutions in two precisions
// would be days of CPU here. The default crop (40 mm wide, the crack 10 mm deep, 12 mm of plate under
// it) keeps the waves diffracted at the top corners and the P burst reflected at the bottom out of the
// analysis window at A. Writes <out>/<scene stem>.csv for tools/plot_accuracy_cost.py and, per run,
// <stem>_series_<precision>_c<factor>.csv (probe A with and without the crack, the window start).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "apps/common/app.hpp"
#include "bench/support/sweep_common.hpp"
#include "io/mps_elastic_scene.hpp"
#include "mps_elastic/harmonics.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Accuracy-cost sweep of the MPS higher-harmonic cases (seed 000 section 5.2)"};
  std::string scene_file = "scenes/mps/crack_p_wave.toml", out = "out/accuracy_cost", coarsening = "4,2,1",
              precisions = "double,float";
  double width = 0.04, depth = 0.010, below = 0.012;
  int threads = -1;
  app.add_option("--scene", scene_file, "crack scene")->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--coarsening", coarsening, "spacing factors relative to the scene's")->capture_default_str();
  app.add_option("--precision", precisions, "precisions: double,float")->capture_default_str();
  app.add_option("--width", width, "cropped plate width [m]")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--depth", depth, "crack depth below the top surface [m]")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--below", below, "plate below the crack [m]")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "OpenMP threads");
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("sweep_mps_harmonics", [&] {
    pm::apps::KokkosSession kokkos(threads);
    auto factors = pm::sweeps::parse_numbers("--coarsening", coarsening);
    std::sort(factors.begin(), factors.end());
    std::vector<std::string> precs = {"double"};
    if (precisions.find("float") != std::string::npos) precs.push_back("float");
    pm::io::make_output_dir(out);
    struct Row {
      bool is_float;
      double coarsening, spacing;
      std::int64_t particles, steps;
      double wall, cpu;
      std::vector<double> rc, ri;
    };
    std::vector<Row> rows;
    const std::string stem = std::filesystem::path(scene_file).stem().string();
    auto write = [&] {
      std::vector<std::string> header = {"is_float", "coarsening", "spacing", "particles", "steps", "wall_seconds",
                                         "cpu_seconds", "threads"};
      for (int n = 2; n <= 5; ++n) header.push_back("crack_r" + std::to_string(n));
      for (int n = 2; n <= 5; ++n) header.push_back("intact_r" + std::to_string(n));
      header.push_back("harmonics_difference");
      std::vector<std::vector<double>> cols(header.size());
      const auto& ref = rows.front().rc;
      for (const auto& r : rows) {
        double num = 0, den = 0;
        for (int n = 1; n < 5; ++n) {
          num += (r.rc[n] - ref[n]) * (r.rc[n] - ref[n]);
          den += ref[n] * ref[n];
        }
        std::vector<double> v = {r.is_float ? 1.0 : 0.0, r.coarsening, r.spacing, double(r.particles), double(r.steps),
                                 r.wall, r.cpu, double(pm::kx::concurrency<pm::ExecSpace>())};
        for (int n = 1; n < 5; ++n) v.push_back(r.rc[n]);
        for (int n = 1; n < 5; ++n) v.push_back(r.ri[n]);
        v.push_back(den > 0 ? std::sqrt(num / den) : 0.0);
        for (std::size_t k = 0; k < v.size(); ++k) cols[k].push_back(v[k]);
      }
      pm::io::write_csv(std::filesystem::path(out) / (stem + ".csv"), header, cols);
    };
    for (const auto& prec : precs)
      for (double f : factors) {
        pm::io::MpsSceneOptions o;
        o.coarsening = f;
        o.precision = prec;
        auto scene = pm::io::load_mps_elastic_scene(scene_file, o);
        me::Config& c = scene.config;
        me::crop_around_crack(c, width, depth, below);
        c.steps = me::steps_until_burst_passes(c, scene.harmonics_probe);
        std::fprintf(stderr, "[sweep] %s, coarsening %g (spacing %.3g m), %lld steps ...\n", prec.c_str(), f,
                     c.spacing, static_cast<long long>(c.steps));
        const double cpu0 = pm::sweeps::cpu_seconds();
        const int field = scene.harmonics_component == "u1" ? pm::mps::probe_u1 : pm::mps::probe_u3;
        const auto res = prec == "float"
                             ? me::run_harmonics_case<float>(c, scene.harmonics_probe, field, scene.normal_reaction_ratio)
                             : me::run_harmonics_case<double>(c, scene.harmonics_probe, field, scene.normal_reaction_ratio);
        Row r{prec == "float", f, c.spacing, res.crack.particles, c.steps,
              res.intact.stats.wall_seconds + res.crack.stats.wall_seconds, pm::sweeps::cpu_seconds() - cpu0,
              res.ratios_crack, res.ratios_intact};
        rows.push_back(r);
        // the probe records of both runs, to see what the ratios are made of
        char name[96];
        std::snprintf(name, sizeof name, "%s_series_%s_c%g.csv", stem.c_str(), prec.c_str(), f);
        pm::io::write_csv(std::filesystem::path(out) / name, {"time", "intact", "crack", "window_start"},
                          {res.intact.times, res.intact.signal, res.crack.signal,
                           std::vector<double>(res.intact.times.size(), res.window_start)});
        std::fprintf(stderr, "[sweep]   %.1f s CPU: crack %.3g %.3g %.3g %.3g | intact %.3g %.3g %.3g %.3g\n", r.cpu,
                     r.rc[1], r.rc[2], r.rc[3], r.rc[4], r.ri[1], r.ri[2], r.ri[3], r.ri[4]);
        write();
      }
    std::printf("accuracy-cost table: %s/%s.csv\n", out.c_str(), stem.c_str());
    return 0;
  });
}
