// Sweeps of the plate-perforation case (seed 003 Figs. 6-7): every combination of the listed
// resolutions (spacing factors relative to the scene's paper spacing), precisions, horizon ratios,
// velocity-viscosity coefficients c_v and impact velocities; for each run the residual velocity, its
// error against the experiment (the scene's [experiment], e.g. 200.6 m/s at 303.5 m/s, Borvik et al.), the plate's damage, the
// energy error and the wall time. A diverged run (no zero-energy control) has NaN residual velocity.
//
//   sweep_pd_penetration [--scene scenes/pd/penetration_303.toml] [--out out/pd_sweeps] [--name NAME]
//                        [--coarsening 4,2] [--precision double,float] [--horizon-ratio 3]
//                        [--cv 0,0.1,0.3,1] [--velocity 303.5,224.5]
//
// Writes <out>/<name>.csv, rewritten after every run so a long sweep can be watched;
// tools/plot_accuracy_cost.py (accuracy against cost) and tools/plot_pd_sweeps.py (Figs. 6-7) draw it.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "apps/common/app.hpp"
#include "bench/support/sweep_common.hpp"
#include "io/nosb_pd_scene.hpp"
#include "nosb_pd/impact.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

// is_float, coarsening, spacing, horizon_ratio, c_v, velocity, particles, bonds, steps, wall_seconds,
// residual_velocity, perforated, residual_velocity_error, core_damage, rim_damage, energy_error_fraction
using Row = std::vector<double>;

template <class T>
Row run_one(const pm::io::NosbPdScene& scene) {
  const np::Config& c = scene.config;
  np::Impact<T, 3> m(c);
  np::RunHooks hooks;
  hooks.sample_every = scene.sample_every;
  const auto stats = np::run_impact(m, static_cast<std::int64_t>(std::ceil(scene.end_time / c.dt)), hooks);
  const auto s = np::analyse_impact(m);
  const double exp = scene.experiment_residual_velocity;
  return {scene.header.precision == "float" ? 1.0 : 0.0, scene.header.coarsening, c.spacing, c.horizon_ratio, c.stabilization.c_v,
          c.projectile.velocity, double(m.plate().particles()), double(m.plate().bonds()), double(stats.steps), stats.wall_seconds,
          stats.diverged ? NAN : s.residual_velocity, s.perforated ? 1.0 : 0.0,
          stats.diverged ? NAN : std::abs(s.residual_velocity - exp), s.core_damage, s.rim_damage,
          stats.diverged ? NAN : stats.energy_error()};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Sweeps of the plate-perforation case (seed 003 Figs. 6-7)"};
  std::string scene_file = "scenes/pd/penetration_303.toml", out = "out/pd_sweeps", name = "pd_penetration",
              coarsening = "4,2", precisions = "double", m_list = "", cv_list = "", v_list = "";
  int threads = -1;
  app.add_option("--scene", scene_file, "scene file")->capture_default_str();
  app.add_option("--out", out, "output folder")->capture_default_str();
  app.add_option("--name", name, "CSV file name (without .csv)")->capture_default_str();
  app.add_option("--coarsening", coarsening, "spacing factors relative to the scene's paper spacing")->capture_default_str();
  app.add_option("--precision", precisions, "double,float")->capture_default_str();
  app.add_option("--horizon-ratio", m_list, "horizon ratios m (default: the scene's)");
  app.add_option("--cv", cv_list, "velocity viscosity coefficients c_v (default: the scene's)");
  app.add_option("--velocity", v_list, "impact velocities [m/s] (default: the scene's)");
  app.add_option("--threads", threads, "OpenMP threads");
  CLI11_PARSE(app, argc, argv);
  return pm::apps::guarded("sweep_pd_penetration", [&] {
    pm::apps::KokkosSession kokkos(threads);
    pm::io::make_output_dir(out);
    std::vector<std::string> precs;
    for (const char* p : {"double", "float"})
      if (precisions.find(p) != std::string::npos) precs.push_back(p);
    const auto ms = m_list.empty() ? std::vector<double>{0.0} : pm::sweeps::parse_numbers("--horizon-ratio", m_list);
    const auto cvs = cv_list.empty() ? std::vector<double>{-1.0} : pm::sweeps::parse_numbers("--cv", cv_list);
    const auto vs = v_list.empty() ? std::vector<double>{0.0} : pm::sweeps::parse_numbers("--velocity", v_list);
    std::vector<Row> rows;
    const std::vector<std::string> header = {"is_float", "coarsening", "spacing", "horizon_ratio", "c_v", "velocity", "particles",
                                             "bonds", "steps", "wall_seconds", "residual_velocity", "perforated",
                                             "residual_velocity_error", "core_damage", "rim_damage", "energy_error_fraction"};
    for (const auto& prec : precs)
      for (double f : pm::sweeps::parse_numbers("--coarsening", coarsening))
        for (double m : ms)
          for (double cv : cvs)
            for (double v : vs) {
              pm::io::NosbPdSceneOptions o;
              o.coarsening = f;
              o.precision = prec;
              o.horizon_ratio = m;
              o.c_v = cv;
              o.velocity = v;
              const auto scene = pm::io::load_nosb_pd_scene(scene_file, o);
              const auto& c = scene.config;
              std::fprintf(stderr, "[sweep] %s, spacing %.3g m, m = %g, c_v = %g, v0 = %g m/s ...\n", prec.c_str(), c.spacing,
                           c.horizon_ratio, c.stabilization.c_v, c.projectile.velocity);
              rows.push_back(prec == "float" ? run_one<float>(scene) : run_one<double>(scene));
              const Row& r = rows.back();
              std::fprintf(stderr, "[sweep]   %.0f particles, %.0f steps, %.1f s: residual %.1f m/s (%s), core %.2f rim %.2f\n",
                           r[6], r[8], r[9], r[10], r[11] > 0 ? "through" : "not through", r[13], r[14]);
              std::vector<std::vector<double>> cols(header.size());
              for (const auto& row : rows)
                for (std::size_t k = 0; k < header.size(); ++k) cols[k].push_back(row[k]);
              pm::io::write_csv(std::filesystem::path(out) / (name + ".csv"), header, cols);
            }
    std::printf("%s/%s.csv\n", out.c_str(), name.c_str());
    return 0;
  });
}
