// Scene files of the Helmholtz model (seed 002 paper 3): scenes/helmholtz/*.toml -> a validated
// helmholtz::Config at the chosen accuracy, order and precision, plus what the app writes. Every
// problem is a SceneError naming the file, line, key and what is allowed (a Gmsh mesh's own errors
// name the .msh file and line as well).
//
// Accuracy presets scale box meshes: the scene gives the element counts at accuracy `paper`; `draft`
// divides them by [accuracy].draft (default 4), `standard` by [accuracy].standard (default 2); without
// an [accuracy] table the counts are used as written. A
// Gmsh mesh is used as it is (presets do not apply; --accuracy is refused for it).
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "helmholtz/config.hpp"
#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct HelmholtzScene {
  SceneHeader header;           // accuracy: the preset name ("mesh file" for Gmsh meshes); coarsening: box
                                // element counts divided by this
  helmholtz::Config config;     // at the chosen accuracy / order / frequency
  std::string mesh_source;      // "box 20 x 4 x 2" or the .msh path
  std::array<int, 3> box_elements{0, 0, 0};  // box meshes: element counts used
  // output
  bool write_field = true;
  bool has_profile = false;
  std::array<double, 3> profile_from{0, 0, 0}, profile_to{0, 0, 0};
  CostEstimate cost;  // DoFs, estimated COCG iterations, memory, time
};

struct HelmholtzSceneOptions {
  std::string accuracy;      // "" -> the scene's [accuracy].default
  std::string precision;     // "" -> the scene's [model].precision
  int order = 0;             // > 0 overrides [discretization].order
  double coarsening = 0.0;   // > 0 overrides the preset's factor (box meshes)
  double frequency = 0.0;    // > 0 overrides [acoustics].frequency
  std::array<int, 3> elements{0, 0, 0};  // > 0 overrides the box's element counts (sweeps)
};

HelmholtzScene load_helmholtz_scene(const std::filesystem::path& file, const HelmholtzSceneOptions& options = {});

}  // namespace polymech::io
