// Scene files of the DEM model (seed 002 paper 2): scenes/dem/*.toml -> a validated dem::Config of a
// binary impact (the Chung & Ooi 2011 benchmark tests) plus what dem_benchmark sweeps (incidence angles,
// restitution coefficients). Every problem is a SceneError naming the file, line, key and what is
// allowed; a time step above the model's limit (Rayleigh, Hertz contact time) is refused with the limit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dem/impacts.hpp"
#include "dem/setup.hpp"
#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct DemScene {
  SceneHeader header;
  dem::Config config;               // the impact at the first angle and restitution (dt resolved)
  dem::Case impact;                 // material, radius, speed
  std::string target;               // "sphere" (two spheres head on), "plane", "mesh"
  double steps_per_contact = 400;   // dt = the Hertz contact time / this (unless [time].dt)
  double dt = 0.0;                  // [time].dt (0: from steps_per_contact)
  std::vector<double> angles;       // incidence angles [deg] (test 4); one entry otherwise
  std::vector<double> restitutions; // coefficients of restitution (test 3); one entry otherwise
  int test = 0;                     // [benchmark].test: the Chung & Ooi test number (0: none)
  dem::TimeStepLimit limit;         // of config
  CostEstimate cost;
};

// The configuration of one run of the scene: angle and restitution from the scene's lists.
dem::Config dem_impact_config(const DemScene& s, double angle_deg, double restitution);

DemScene load_dem_scene(const std::filesystem::path& file, const SceneOptions& options = {});  // options.accuracy: unused (the Chung & Ooi tests have one size)

}  // namespace polymech::io
