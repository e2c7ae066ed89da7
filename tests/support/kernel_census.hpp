// Counts kernel launches (parallel_for / reduce / scan) and View allocations by name through the
// Kokkos Tools callbacks, so tests can prove which kernels an effect launches and that a disabled
// effect launches and allocates nothing.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/launch_callbacks.hpp"

namespace polymech::testing {

class KernelCensus {
 public:
  // Installs the callbacks; one census at a time.
  KernelCensus() {
    state() = {};
    kx::set_launch_callbacks(&on_begin);
    Kokkos::Tools::Experimental::set_allocate_data_callback(&on_allocate);
  }
  ~KernelCensus() {
    kx::set_launch_callbacks(nullptr);
    Kokkos::Tools::Experimental::set_allocate_data_callback(nullptr);
  }
  KernelCensus(const KernelCensus&) = delete;
  KernelCensus& operator=(const KernelCensus&) = delete;

  int launches(const std::string& name) const {
    auto it = state().launches.find(name);
    return it == state().launches.end() ? 0 : it->second;
  }
  // Kernel names and allocation labels that contain `part`.
  std::vector<std::string> kernels_containing(const std::string& part) const {
    std::vector<std::string> out;
    for (const auto& [name, n] : state().launches)
      if (name.find(part) != std::string::npos) out.push_back(name);
    return out;
  }
  std::vector<std::string> allocations_containing(const std::string& part) const {
    std::vector<std::string> out;
    for (const auto& label : state().allocations)
      if (label.find(part) != std::string::npos) out.push_back(label);
    return out;
  }

 private:
  struct State {
    std::map<std::string, int> launches;
    std::vector<std::string> allocations;
  };
  static State& state() {
    static State s;
    return s;
  }
  static void on_begin(const char* name, const std::uint32_t, std::uint64_t* id) {
    ++state().launches[name];
    *id = 0;
  }
  static void on_allocate(const Kokkos_Profiling_SpaceHandle, const char* label, const void*, const std::uint64_t) {
    state().allocations.emplace_back(label);
  }
};

}  // namespace polymech::testing
