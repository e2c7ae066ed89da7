// The effects of the EFG model (seed 004), as plain data for io/: none yet (the static solve and the
// J-integral are always on).
#pragma once

#include <vector>

#include "effects.hpp"

namespace polymech::efg {

inline const std::vector<EffectSpec>& effect_table() {
  static const std::vector<EffectSpec> specs = {};
  return specs;
}

}  // namespace polymech::efg
