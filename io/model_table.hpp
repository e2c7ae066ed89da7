// What every scene's [model] table holds besides `kind`: the effects the scene asks for, checked against
// the ones the model declares, and the floating-point precision, which a command-line choice overrides.
// Host-only, like the rest of io/.
#pragma once

#include <string>
#include <vector>

#include "effects.hpp"
#include "io/scene.hpp"

namespace polymech::io {

// [model].effects resolved against `declared`; an unknown effect or a missing requirement is an error at
// the key, listing what is allowed.
inline EffectSet read_effects(const SceneTable& model, const std::vector<EffectSpec>& declared) {
  const auto requested = model.strings("effects", {});
  try {
    return EffectSet::resolve(requested, declared);
  } catch (const EffectError& e) {
    model.fail("effects", std::string("is invalid: ") + e.what());
  }
}

// [model].precision ("double" unless the scene says), or `requested` when not empty.
inline std::string read_precision(const SceneTable& model, const std::string& requested) {
  const std::string scene = model.choice("precision", {"double", "float"}, "double");
  if (requested.empty()) return scene;
  if (requested != "double" && requested != "float")
    throw SceneError(model.file().string() + ": precision '" + requested + "' is unknown; allowed: double, float");
  return requested;
}

}  // namespace polymech::io
