// Effects: the optional physics a model can run. A model declares its effects (name, what each
// requires, which kernels it launches, what it allocates); a scene lists the ones it needs; the model
// runs exactly those. A disabled effect allocates nothing and launches nothing (tests/effects checks
// this by counting kernel launches and allocations through Kokkos Tools callbacks).
#pragma once

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymech {

struct EffectSpec {
  std::string name;                   // e.g. "rotation", "crack_contact.slip"
  std::string description;            // one line, shown in error messages and --help
  std::vector<std::string> requires;  // effects that must also be enabled
  std::vector<std::string> kernels;   // kernel names it launches (polymech::...)
  std::string memory;                 // what it allocates, e.g. "3 reals per particle"
};

// A model's request for effects was unknown or inconsistent; io adds the scene file and line.
class EffectError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class EffectSet {
 public:
  EffectSet() = default;
  bool has(const std::string& name) const { return enabled_.count(name) > 0; }
  const std::set<std::string>& names() const { return enabled_; }
  bool empty() const { return enabled_.empty(); }

  // Validates `requested` against the model's declared effects: unknown names, duplicates and
  // missing requirements are errors that list the valid choices.
  static EffectSet resolve(const std::vector<std::string>& requested, const std::vector<EffectSpec>& declared) {
    EffectSet set;
    auto allowed = [&] {
      std::string s;
      for (const auto& e : declared) s += (s.empty() ? "" : ", ") + e.name;
      return s.empty() ? std::string("(none: this model has no optional effects)") : s;
    };
    for (const auto& name : requested) {
      auto it = std::find_if(declared.begin(), declared.end(), [&](const EffectSpec& e) { return e.name == name; });
      if (it == declared.end()) throw EffectError("unknown effect '" + name + "'; allowed: " + allowed());
      if (!set.enabled_.insert(name).second) throw EffectError("effect '" + name + "' is listed twice");
    }
    for (const auto& e : declared) {
      if (!set.has(e.name)) continue;
      for (const auto& r : e.requires)
        if (!set.has(r)) throw EffectError("effect '" + e.name + "' requires effect '" + r + "', which is not listed");
    }
    return set;
  }

 private:
  std::set<std::string> enabled_;
};

}  // namespace polymech
