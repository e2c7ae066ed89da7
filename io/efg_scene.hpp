// Scene files of the element-free Galerkin model (seed 004): scenes/efg/*.toml -> a validated
// efg::Config of a cracked plate (edge or centre crack in tension) plus its cost. Every problem is a
// SceneError naming the file, line, key and what is allowed; the size (node lines, Gauss points) is
// estimated and checked before anything is built.
#pragma once

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
  CostEstimate cost;
};

// `accuracy` ("" = the scene's [accuracy] default, else draft / standard / paper) scales h_min and h_max.
EfgScene load_efg_scene(const std::filesystem::path& file, const std::string& precision = "", const std::string& accuracy = "");

}  // namespace polymech::io
