// Accuracy-cost sweep of the MPS point-source case (seed 000 §5.1): the same scene at several
// resolutions and in double and float; for each run the wave-speed errors against the analytic
// speeds, the probe-waveform difference against the finest double run, and the wall time.
//
//   sweep_mps_point_source [--scene scenes/mps/point_source.toml] [--out out/accuracy_cost]
//                          [--coarsening 8,4,2,1] [--precision double,float] [--duration 8e-6]
//
// Writes <out>/mps_point_source.csv (rewritten after every run, so a long sweep can be watched);
// tools/plot_accuracy_cost.py draws it. Powers of two keep the scene's 0.4 mm source exactly
// 1, 2, 4, 8 cells wide, so the runs differ only in resolution.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "apps/common/app.hpp"
#include "bench/support/sweep_common.hpp"
#include "io/mps_elastic_scene.hpp"
#include "mps_elastic/run.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

struct Run {
  std::string precision;
  double coarsening = 0, spacing = 0;
  std::int64_t particles = 0, steps = 0;
  double wall = 0, cpu = 0, cp = NAN, cs = NAN, cp_err = NAN, cs_err = NAN, wave_diff = NAN;
  me::ProbeHistory history;
};

// One run of the scene for `duration` seconds; its cost is the CPU time of this process (all threads):
// on a shared machine, the single-thread CPU time of a run is a far steadier measure than wall time.
template <class T>
Run run_one(const pm::io::MpsElasticScene& scene, double duration) {
  me::Config c = scene.config;
  c.steps = static_cast<std::int64_t>(std::llround(duration / c.dt));
  me::MpsElastic<T> m(c);
  const double cpu0 = pm::sweeps::cpu_seconds();
  const auto stats = me::run(m, c.steps);
  const double cpu = pm::sweeps::cpu_seconds() - cpu0;
  if (!stats.finite) throw std::runtime_error("run at coarsening " + std::to_string(scene.header.coarsening) + " went unstable");
  Run r;
  r.precision = scene.header.precision;
  r.coarsening = scene.header.coarsening;
  r.spacing = c.spacing;
  r.particles = m.particles();
  r.steps = c.steps;
  r.wall = stats.wall_seconds;
  r.cpu = cpu;
  const auto src = me::excitation_source_point(c);
  r.history = m.probes();
  const auto w = me::measure_wave_speeds(r.history, c, src.x1, src.x3, scene.p_wave_probes, scene.s_wave_probes);
  r.cp = w.cp;
  r.cs = w.cs;
  r.cp_err = std::abs(w.cp - m.cp_analytic()) / m.cp_analytic();
  r.cs_err = std::abs(w.cs - m.cs_analytic()) / m.cs_analytic();
  return r;
}

// Relative L2 difference of the displacement histories (u1 and u3 of every probe) from the reference.
double waveform_difference(const me::ProbeHistory& h, const me::ProbeHistory& ref) {
  double num = 0, den = 0;
  for (std::size_t p = 0; p < ref.names.size(); ++p)
    for (int f : {pm::mps::probe_u1, pm::mps::probe_u3}) {
      const double d = pm::analysis::relative_l2_difference(h.times, h.values[p][f], ref.times, ref.values[p][f]);
      double n2 = 0;
      for (double v : ref.values[p][f]) n2 += v * v;
      num += d * d * n2;
      den += n2;
    }
  return den > 0 ? std::sqrt(num / den) : 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Accuracy-cost sweep of the MPS point-source case (seed 000 section 5.1)"};
  std::string scene_file = "scenes/mps/point_source.toml", out = "out/accuracy_cost", coarsening = "8,4,2,1",
              precisions = "double,float";
  double duration = 8e-6;
  int threads = -1;
  app.add_option("--scene", scene_file, "scene file")->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--coarsening", coarsening, "spacing factors relative to the scene's (finest first or last)")
      ->capture_default_str();
  app.add_option("--precision", precisions, "precisions to run: double,float")->capture_default_str();
  app.add_option("--duration", duration, "simulated time per run [s]")->capture_default_str()->check(CLI::PositiveNumber);
  app.add_option("--threads", threads, "OpenMP threads");
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("sweep_mps_point_source", [&] {
    pm::apps::KokkosSession kokkos(threads);
    auto factors = pm::sweeps::parse_numbers("--coarsening", coarsening);
    std::sort(factors.begin(), factors.end());  // finest first: it is the reference
    std::vector<std::string> precs;
    for (const char* p : {"double", "float"})
      if (precisions.find(p) != std::string::npos) precs.push_back(p);
    if (precs.empty() || precs[0] != "double") precs.insert(precs.begin(), "double");  // the reference is double
    pm::io::make_output_dir(out);
    std::vector<Run> runs;
    const Run* ref = nullptr;
    auto write = [&] {
      std::vector<std::vector<double>> cols(12);
      std::vector<std::string> header = {"is_float", "coarsening", "spacing", "particles", "steps", "wall_seconds",
                                         "cpu_seconds", "threads", "cp_rel_error", "cs_rel_error",
                                         "waveform_difference", "particle_steps"};
      const double nthreads = pm::kx::concurrency<pm::ExecSpace>();
      for (const auto& r : runs) {
        const double v[] = {r.precision == "float" ? 1.0 : 0.0, r.coarsening, r.spacing, double(r.particles),
                            double(r.steps), r.wall, r.cpu, nthreads, r.cp_err, r.cs_err, r.wave_diff,
                            double(r.particles) * double(r.steps)};
        for (int k = 0; k < 12; ++k) cols[k].push_back(v[k]);
      }
      pm::io::write_csv(std::filesystem::path(out) / "mps_point_source.csv", header, cols);
    };
    for (const auto& prec : precs)
      for (double f : factors) {
        pm::io::MpsSceneOptions o;
        o.coarsening = f;
        o.precision = prec;
        const auto scene = pm::io::load_mps_elastic_scene(scene_file, o);
        std::fprintf(stderr, "[sweep] %s, coarsening %g (spacing %.3g m) ...\n", prec.c_str(), f, scene.config.spacing);
        runs.push_back(prec == "float" ? run_one<float>(scene, duration) : run_one<double>(scene, duration));
        ref = &runs.front();  // the finest double run (re-taken: the vector may have moved)
        runs.back().wave_diff = waveform_difference(runs.back().history, ref->history);
        const auto& r = runs.back();
        std::fprintf(stderr, "[sweep]   %lld particles, %lld steps, %.1f s wall, %.1f s CPU: cp error %.3f %%, cs error %.3f %%, waveform %.3g\n",
                     static_cast<long long>(r.particles), static_cast<long long>(r.steps), r.wall, r.cpu, 100 * r.cp_err,
                     100 * r.cs_err, r.wave_diff);
        write();
      }
    std::printf("accuracy-cost table: %s/mps_point_source.csv\n", out.c_str());
    return 0;
  });
}
