// Scene files of the NOSB peridynamics model (seed 003): scenes/pd/*.toml -> a validated
// nosb_pd::Config at the chosen accuracy, plus what the apps need around the model (run length,
// sampling and snapshot cadence, tension schedule). Every problem is a SceneError naming the file,
// line, key and what is allowed.
//
// Accuracy presets scale the resolution: the scene gives the spacing of its `paper` preset; `draft`
// multiplies it by [accuracy].draft (default 4), `standard` by [accuracy].standard (default 2),
// `paper` by [accuracy].paper (default 1). omega_v of eq. (3) is an oscillation frequency of the
// particles, which scales as 1 / spacing, so it is divided by the same factor; an explicit dt is
// multiplied by it. Simulated time is kept.
#pragma once

#include <cstdint>
#include <limits>
#include <filesystem>
#include <string>

#include "io/cost.hpp"
#include "io/scene.hpp"
#include "nosb_pd/setup.hpp"

namespace polymech::io {

struct NosbPdScene {
  SceneHeader header;      // file, title, effects, precision, accuracy (coarsening: spacing / the scene's)
  nosb_pd::Config config;  // at the chosen accuracy (config.dt resolved: never 0)
  double stable_dt = 0.0;  // stability limit of this resolution [s]
  double end_time = 0.0;   // impact: simulated time [s]
  std::int64_t steps = 0;  // impact: steps of config.dt to end_time; tension: the schedule's length (decided here, once)
  nosb_pd::TensionSchedule tension;  // tension: ramp and hold, in bar transit times
  std::int64_t sample_every = 50;    // steps between energy / projectile samples
  std::int64_t snapshots = 0;        // number of field snapshots over the run (0: none)
  bool stop_after_perforation = true;  // impact: end once the projectile is through and free
  // impact: the experiment's residual velocity at this scene's impact velocity (NaN: none given)
  double experiment_residual_velocity = std::numeric_limits<double>::quiet_NaN();
  CostEstimate cost;  // particles, bonds, steps (tension: ramp and hold), memory, time
};

struct NosbPdSceneOptions {
  std::string accuracy;       // "" -> the scene's [accuracy].default
  double coarsening = 0.0;    // > 0 overrides the preset's factor (accuracy-cost sweeps)
  std::string precision;      // "" -> the scene's [model].precision
  double horizon_ratio = 0.0;  // > 0 overrides [discretization].horizon_ratio (sweeps)
  double velocity = 0.0;       // > 0 overrides [projectile].velocity
  double c_v = -1.0;           // >= 0 overrides [stabilization].c_v
};

NosbPdScene load_nosb_pd_scene(const std::filesystem::path& file, const NosbPdSceneOptions& options = {});

}  // namespace polymech::io
