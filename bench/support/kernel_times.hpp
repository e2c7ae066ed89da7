// Time per kernel name through the Kokkos Tools begin/end callbacks, for benchmarks that report where a
// step's time goes (e.g. the DEM broad phase against the contact forces). On a host backend a launch
// returns when the kernel is done, so begin-to-end is the kernel's time; on a device backend it is the
// launch's time only (fence inside the timed region to measure there). One instance at a time.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/launch_callbacks.hpp"

namespace polymech::bench {

class KernelTimes {
 public:
  KernelTimes() {
    state() = {};
    kx::set_launch_callbacks(&on_begin, &on_end);
  }
  ~KernelTimes() { kx::set_launch_callbacks(nullptr); }
  KernelTimes(const KernelTimes&) = delete;
  KernelTimes& operator=(const KernelTimes&) = delete;

  // Seconds spent in the kernels whose names contain any of `parts` (all kernels: {""}).
  double seconds(const std::vector<std::string>& parts) const {
    double s = 0.0;
    for (const auto& [name, t] : state().seconds)
      for (const auto& p : parts)
        if (name.find(p) != std::string::npos) {
          s += t;
          break;
        }
    return s;
  }
  double total() const { return seconds({""}); }
  const std::map<std::string, double>& by_name() const { return state().seconds; }

 private:
  using Clock = std::chrono::steady_clock;
  struct Open {
    std::string name;
    Clock::time_point start;
  };
  struct State {
    std::map<std::string, double> seconds;
    std::vector<Open> open;  // indexed by the launch id handed to Kokkos
  };
  static State& state() {
    static State s;
    return s;
  }
  static void on_begin(const char* name, const std::uint32_t, std::uint64_t* id) {
    auto& s = state();
    *id = s.open.size();
    s.open.push_back({name, Clock::now()});
  }
  static void on_end(const std::uint64_t id) {
    auto& s = state();
    const auto now = Clock::now();
    if (id >= s.open.size()) return;
    const Open& o = s.open[id];
    s.seconds[o.name] += std::chrono::duration<double>(now - o.start).count();
    if (id + 1 == s.open.size()) s.open.pop_back();  // launches do not nest: the list stays short
  }
};

}  // namespace polymech::bench
