// Accuracy-cost sweep of the uniaxial tension test (seed 003 §4(1)): Young's modulus error against
// particle count (resolution), horizon ratio m and precision, with the wall time and the process CPU time of
// the run (cpu_seconds: the cost measure on a shared machine, where wall time is not; the same span as
// wall_seconds, the pull and the measurement, not the model's construction), for one tension scene.
//
//   sweep_pd_tension [--scene scenes/pd/tension_conforming.toml] [--out out/pd_sweeps] [--name NAME]
//                    [--coarsening 4,2,1] [--horizon-ratio 2,3,4] [--precision double,float]
//
// Writes <out>/<name>.csv (rewritten after every run); tools/plot_accuracy_cost.py draws it.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "apps/common/app.hpp"
#include "bench/support/sweep_common.hpp"
#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/tension.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

template <class T, int D>
std::vector<double> run_one(const pm::io::NosbPdScene& scene) {
  np::NosbPd<T, D> m(scene.config);
  const double cpu0 = pm::sweeps::cpu_seconds();
  const auto r = np::run_tension(m, scene.tension);
  const double cpu = pm::sweeps::cpu_seconds() - cpu0;
  return {scene.header.precision == "float" ? 1.0 : 0.0, scene.header.coarsening, scene.config.spacing, scene.config.horizon_ratio,
          double(m.particles()), double(m.bonds()), double(r.steps), r.wall_seconds, cpu, r.modulus, std::abs(r.relative_error)};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Accuracy-cost sweep of the uniaxial tension test (seed 003 section 4(1))"};
  std::string scene_file = "scenes/pd/tension_conforming.toml", out = "out/pd_sweeps", name = "pd_tension", coarsening = "4,2,1",
              m_list = "3", precisions = "double,float";
  int threads = -1;
  app.add_option("--scene", scene_file, "scene file")->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--name", name, "CSV file name (without .csv)")->capture_default_str();
  app.add_option("--coarsening", coarsening, "spacing factors relative to the scene's paper spacing")->capture_default_str();
  app.add_option("--horizon-ratio", m_list, "horizon ratios m")->capture_default_str();
  app.add_option("--precision", precisions, "double,float")->capture_default_str();
  app.add_option("--threads", threads, "OpenMP threads");
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("sweep_pd_tension", [&] {
    pm::apps::KokkosSession kokkos(threads);
    pm::io::make_output_dir(out);
    const std::vector<std::string> header = {"is_float", "coarsening", "spacing", "horizon_ratio", "particles", "bonds",
                                             "steps", "wall_seconds", "cpu_seconds", "modulus",
                                             "modulus_relative_error"};
    std::vector<std::vector<double>> rows;
    for (const char* prec : {"double", "float"}) {
      if (precisions.find(prec) == std::string::npos) continue;
      for (double m : pm::sweeps::parse_numbers("--horizon-ratio", m_list))
        for (double f : pm::sweeps::parse_numbers("--coarsening", coarsening)) {
          pm::io::NosbPdSceneOptions o;
          o.coarsening = f;
          o.precision = prec;
          o.horizon_ratio = m;
          const auto scene = pm::io::load_nosb_pd_scene(scene_file, o);
          const bool fl = scene.header.precision == "float";
          rows.push_back(scene.config.dimension == 2 ? (fl ? run_one<float, 2>(scene) : run_one<double, 2>(scene))
                                                     : (fl ? run_one<float, 3>(scene) : run_one<double, 3>(scene)));
          const auto& r = rows.back();
          std::fprintf(stderr, "[sweep] %s m = %g spacing %.3g m: %.0f particles, E error %.3f %%, %.3g s (CPU %.3g s)\n", prec, m,
                       r[2], r[4], 100 * r[10], r[7], r[8]);
          std::vector<std::vector<double>> cols(header.size());
          for (const auto& row : rows)
            for (std::size_t k = 0; k < header.size(); ++k) cols[k].push_back(row[k]);
          pm::io::write_csv(std::filesystem::path(out) / (name + ".csv"), header, cols);
        }
    }
    std::printf("%s/%s.csv\n", out.c_str(), name.c_str());
    return 0;
  });
}
