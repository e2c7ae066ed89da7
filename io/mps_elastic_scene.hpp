// Scene files of the MPS elastic-wave model (seed 000): scenes/mps/*.toml -> a validated
// mps_elastic::Config at the chosen accuracy, plus what the app needs around the model (analysis
// probes, output cadence). Every problem is a SceneError naming the file, line, key and what is allowed.
//
// Accuracy presets scale the resolution: the scene gives the paper's spacing l0 and dt; preset
// `draft` multiplies both by [accuracy].draft (default 4), `standard` by [accuracy].standard
// (default 2), `paper` by [accuracy].paper (default 1), and divides the step count by the same
// factor, so every preset simulates the same physical time.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/cost.hpp"
#include "io/scene.hpp"
#include "mps_elastic/setup.hpp"

namespace polymech::io {

struct MpsElasticScene {
  SceneHeader header;          // file, title, effects, precision, accuracy (coarsening: spacing / the scene's)
  mps_elastic::Config config;  // at the chosen accuracy
  double stable_dt = 0.0;      // stability limit of this resolution [s]
  // Wave-speed measurement (optional): two probes on one ray from the source each.
  std::vector<std::string> p_wave_probes;  // arrival of the divergence (P) field
  std::vector<std::string> s_wave_probes;  // arrival of the rotation (S) field
  std::int64_t snapshot_every = 0;         // steps between field snapshots (0: none)
  // Crack cases (seed 000 §5.2): the fixed normal reaction as a ratio of the largest shear force through
  // the crack line in the same run without the crack (0.75 in the paper's S-wave case; 0: not used).
  double normal_reaction_ratio = 0.0;
  // Harmonic analysis: spectrum of this probe's field, harmonics of the drive frequency.
  std::string harmonics_probe;      // "" = none
  std::string harmonics_component;  // "u1" or "u3"
  CostEstimate cost;                // particles, bonds, steps (both runs of a crack case), memory, time
};

struct MpsSceneOptions {
  std::string accuracy;        // "" -> the scene's [accuracy].default
  std::int64_t steps = -1;     // > 0 overrides the (scaled) step count
  double coarsening = 0.0;     // > 0 overrides the preset's factor (accuracy-cost sweeps)
  std::string precision;       // "" -> the scene's [model].precision
};

MpsElasticScene load_mps_elastic_scene(const std::filesystem::path& file, const MpsSceneOptions& options = {});

}  // namespace polymech::io
