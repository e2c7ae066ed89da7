// Scene files of the element-free Galerkin model (seed 004): scenes/efg/*.toml -> a validated
// efg::Config of a cracked plate (edge or centre crack in tension) plus its cost. Every problem is a
// SceneError naming the file, line, key and what is allowed; the size (node lines, Gauss points) is
// estimated and checked before anything is built.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "efg/setup.hpp"
#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct EfgScene {
  SceneHeader header;
  efg::Config config;
  double handbook = 0.0;  // Tada, Paris & Irwin K / (stress sqrt(pi a)) of the plate
  // [dynamic] (optional): a Heaviside step load at t = 0, Newmark beta = 1/4 (seed 004 §3.2)
  bool dynamic = false;
  double dt = 0.0;           // [s]
  double duration = 0.0;     // [s]
  std::int64_t steps = 0;    // dynamic: Newmark steps of dt over the duration (decided here, once)
  int output_every = 1;      // steps between J' and crack-opening samples
  int domain_cells = 20;     // radial and angular cells of the J' domain part (4 x 4 Gauss points each)
  CostEstimate cost;
};

// `accuracy` ("" = the scene's [accuracy] default, else draft / standard / paper) scales h_min and h_max.
EfgScene load_efg_scene(const std::filesystem::path& file, const SceneOptions& options = {});

}  // namespace polymech::io
