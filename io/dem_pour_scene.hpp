// Scene files of a DEM pour (seed 002 paper 2, sec. 2 and Fig. 6: gravel particles of radii 5-7 mm
// poured into the soil bin): scenes/dem/*pour*.toml -> a validated dem::Config of the pour and what the
// app measures. Every problem is a SceneError naming the file, line, key and what is allowed; a time
// step above the model's limit (Rayleigh, Hertz contact time) is refused with the limit.
//
//   [model] kind = "dem_pour", effects = ["friction", "damping", "clumps"]
//   [particle] youngs_modulus, poisson_ratio, density     [wall] youngs_modulus, poisson_ratio
//   [contact] restitution, friction, pour_friction (mu until pour_friction_until, s; default wheel.start)
//   [gravel] count, shapes = ["cylinder", "cone", "cube"] (or ["sphere"]), radius_min, radius_max, seed
//   [bin] size = [lx, ly, lz], release_at (s; > 0: the wall x = lx opens, a heap forms)
//   [time] duration, dt (0: dt_safety x the limit), dt_safety
//   [wheel] (effects "fe_surfaces", "rigid_wheel"; seed 002 paper 2, sec. 4) radius, width, facet_size,
//           side_depth, mass, load, load_ramp = [from, to], speed, speed_ramp = [from, to], slip, start, x_start
//   [output] snapshots, sample_every    [accuracy] default = "paper" (draft: count / 4, standard: / 2)
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "dem/pour.hpp"
#include "dem/setup.hpp"
#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct DemPourScene {
  SceneHeader header;
  dem::Config config;     // the pour (dt resolved)
  dem::PourSpec pour;
  double duration = 0.0;  // simulated seconds
  std::int64_t steps = 0;  // steps of config.dt over the duration (decided here, once)
  int snapshots = 0;      // over the run (HDF5/XDMF)
  std::int64_t sample_every = 0;
  dem::TimeStepLimit limit;
  CostEstimate cost;
};

DemPourScene load_dem_pour_scene(const std::filesystem::path& file, const SceneOptions& options = {});

}  // namespace polymech::io
