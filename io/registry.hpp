// The registry of scene kinds: [model].kind -> its loader (which validates a scene completely, with
// errors naming file, line and key) and the apps that run it. Every loader is registered here once, so
// the scene tests, the fuzzer and the `polymech` app find a scene's loader by its kind.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "io/cost.hpp"

namespace polymech::io {

struct SceneKind {
  std::string kind;                 // [model].kind
  std::string description;
  std::vector<std::string> apps;    // the apps that run scenes of this kind
  // Loads and validates a scene of this kind at its default accuracy (SceneError on bad input).
  void (*check)(const std::filesystem::path& file) = nullptr;
  // The app that runs this scene (one of `apps`), from what the scene holds.
  std::string (*app_for)(const std::filesystem::path& file) = nullptr;
  // Loads a scene at its default accuracy and returns what running it would cost (what --dry-run prints).
  CostEstimate (*estimate)(const std::filesystem::path& file) = nullptr;
};

const std::vector<SceneKind>& scene_kinds();

// The entry of a scene file's [model].kind; a SceneError naming the file, line and the known kinds if
// the kind is missing or unknown.
const SceneKind& scene_kind_of(const std::filesystem::path& file);

}  // namespace polymech::io
