// The dynamic cases of apps/efg (seed 004 §3.2, §3.3): the stationary or running crack under a step load, run
// through the case runner; what they measure is models/efg/analysis.hpp, what they write summary.json and
// sif_history.csv (apps/efg/main.cpp).
#pragma once

#include <cstdint>
#include <cstdio>

#include "apps/common/case.hpp"
#include "efg/analysis.hpp"
#include "io/efg_scene.hpp"

namespace polymech::apps::efg_case {

// The stationary or running crack under a Heaviside step (seed 004 §3.2, §3.3) through the case runner
// (apps/common/case.hpp: checkpoints, --restart, watchdog): Newmark steps, J' on every path and the crack
// opening at the centre every output_every steps; energy balance of the average-acceleration rule.
template <class T>
int run_dynamic(const io::EfgScene& scene, efg::Efg<T>& model, const apps::CommonOptions& opt,
                const apps::RestartOptions& ropt, nlohmann::json& j) {
  const auto& c = scene.config;
  const auto steps = opt.steps > 0 ? opt.steps : scene.steps;
  apps::CaseSpec spec("efg", scene.header, steps, scene.dt);
  spec.progress = false;  // a line per sample instead
  apps::Case cs(spec, opt, ropt);
  model.assemble();
  model.start_dynamic(scene.dt);
  model.set_prescribed_growth(true);
  apps::Series series(efg::history_columns(c.j_radii));  // models/efg/analysis.hpp
  efg::DynamicRecord<efg::Efg<T>> rec(model, scene.domain_cells);
  cs.records.keep("efg/series", series);
  cs.records.keep("efg/j_seconds", rec.j_seconds);
  cs.hooks.sample_every = scene.output_every;
  cs.hooks.sample_at_start = true;
  cs.hooks.sample = [&](std::int64_t) {
    efg::DynamicSample s;
    series.append(rec.sample(s));
    if (!opt.quiet)
      std::printf("t = %7.3f us: a = %.4g mm, K/(s sqrt(pi a0)) = %.4f (J' spread %.2f %%), COD = %.4e m\n", model.time() * 1e6,
                  1e3 * model.crack_length(), s.mean, 100 * s.spread, s.opening);
  };
  const auto stats = cs.run([&](auto& hooks, std::int64_t n) { return models::run(model, n, hooks); });

  const auto h = efg::dynamic_history(series.all());
  const auto& t = model.timings();
  j["mode"] = "dynamic";
  j["nodes"] = model.nodes() - model.split_nodes();  // the layout's (a split path node counts once)
  j["gauss_points"] = model.layout().quad_count();
  if (c.growth_speed > 0) {
    j["path_nodes"] = c.path_nodes;
    j["split_nodes"] = model.split_nodes();  // path nodes the tip passed, each now one per face
    j["growth_speed"] = c.growth_speed;
    j["growth_start_us"] = c.growth_start * 1e6;
    j["final_crack_length"] = c.final_crack_length;
  }
  j["dt"] = scene.dt;
  j["steps"] = stats.steps;
  j[c.growth_speed > 0 ? "sif_running" : "sif_stationary"] = apps::json_pairs(h.sif);
  j["crack_opening"] = apps::json_pairs(h.opening);
  j["sif_peak"] = h.peak;
  j["sif_peak_time_us"] = h.peak_time_us;
  j["j_path_spread"] = h.peak_spread;
  j["j_radii"] = c.j_radii;
  j["energy_error"] = h.energy_error;
  // timings of this process (a resumed run: since its restart)
  j["assembly_seconds"] = t.assembly_seconds;
  j["shape_seconds"] = t.shape_seconds;
  j["factor_seconds"] = t.factor_seconds;
  const auto done = stats.steps - cs.resume_step();
  j["step_seconds_per_step"] = done > 0 ? t.step_seconds / static_cast<double>(done) : 0.0;
  j["j_seconds"] = rec.j_seconds;
  j["wall_seconds"] = stats.wall_seconds;
  series.write_csv(cs.out() / "sif_history.csv", efg::history_csv_columns(series.names()));
  const int rc = cs.finish(j, stats, {"summary.json", "sif_history.csv"});
  std::printf("efg: %d nodes (%d path nodes split), %lld steps, peak K/(s sqrt(pi a)) = %.4f at %.2f us (J' path spread %.2f %%), energy error %.2e, %.2f s; results in %s\n",
              model.nodes() - model.split_nodes(), model.split_nodes(), static_cast<long long>(stats.steps), h.peak, h.peak_time_us, 100 * h.peak_spread,
              h.energy_error, stats.wall_seconds, cs.out().c_str());
  return rc;
}

}  // namespace polymech::apps::efg_case
