// Scene files of the stabilized ISPH model (seed 002 paper 4): scenes/isph/*.toml -> a validated
// isph::Config (tank, water block, fluid, walls, PPE settings) plus the case the app runs (hydrostatic
// tank or dam break), its duration and snapshot interval. Every problem is a SceneError naming the file,
// line, key and what is allowed; a time step above the CFL/viscous limit is refused with the limit.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "io/cost.hpp"
#include "io/scene.hpp"
#include "isph/setup.hpp"

namespace polymech::io {

struct IsphScene {
  SceneHeader header;
  isph::Config config;          // spacing and dt scaled by the accuracy preset
  std::string case_name;        // "hydrostatic" or "dam_break"
  double end_time = 1.0;        // [s]
  double snapshot_every = 0.0;  // [s] (0: none)
  double sample_every = 0.0;    // [s] series (front, pressure error)
  double average_last = 0.0;    // [s] hydrostatic: pressure averaged over the last ... of the run
  double draft_average_last = 0.0;  // [s] floating body: draft averaged over the last ... of the run
  std::int64_t steps = 0;       // end_time / dt
  isph::TimeStepLimit limit;
  CostEstimate cost;
};

IsphScene load_isph_scene(const std::filesystem::path& file, const SceneOptions& options = {});

// The summary keys that say how a run was set up: dimension, spacing, dt and the readings that are scene
// choices (docs/METHODS.md): alpha of eq. (4), the PPE operator and preconditioner, the free-surface test,
// the pressure gradient's form and the ghost interpolation.
nlohmann::json isph_choices(const isph::Config& c);

// ISPH: particles, wall points, steps; the rate of docs/PERFORMANCE.md "ISPH".
CostEstimate isph_cost(double particles, double wall_points, int dim, double steps, bool stored = true,
                       bool two_level = false);

}  // namespace polymech::io
