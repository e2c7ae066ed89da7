// Progress of long runs on stderr: step, simulated time, steps/s and ETA, and once at the end. Lines
// come every `interval` seconds at first, then every 1/30 of the elapsed time (at most every minute),
// so an hour-long run prints a readable log rather than thousands of lines, e.g.
//   [mps_point_source] step 1200/10000 (12%)  t = 2.400e-06 s  845 steps/s  ETA 0:10
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace polymech::io {

class Progress {
 public:
  Progress(std::string label, std::int64_t total_steps, double dt, bool enabled = true, double interval_s = 2.0)
      : label_(std::move(label)), total_(total_steps), dt_(dt), enabled_(enabled), interval_(interval_s),
        start_(clock::now()), last_(start_) {}

  // Call after each step; cheap when nothing is printed.
  void update(std::int64_t step) {
    if (!enabled_ || (step & 15) != 0) return;
    const auto now = clock::now();
    const double since = std::chrono::duration<double>(now - last_).count();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (since < std::min(60.0, std::max(interval_, elapsed / 30.0))) return;
    last_ = now;
    print(step, now, false);
  }
  void done(std::int64_t step) {
    if (enabled_) print(step, clock::now(), true);
  }
  double elapsed() const { return std::chrono::duration<double>(clock::now() - start_).count(); }
  // A run restarted from a checkpoint at `step`: rates and ETA count the steps from there.
  void resume_at(std::int64_t step) { first_ = step; }

 private:
  using clock = std::chrono::steady_clock;
  void print(std::int64_t step, clock::time_point now, bool final) const {
    const double secs = std::chrono::duration<double>(now - start_).count();
    const double rate = secs > 0 ? static_cast<double>(step - first_) / secs : 0.0;
    const double eta = rate > 0 ? static_cast<double>(total_ - step) / rate : 0.0;
    const auto e = static_cast<long long>(eta + 0.5);
    std::fprintf(stderr, "[%s] step %lld/%lld (%.0f%%)  t = %.3e s  %.0f steps/s  %s %lld:%02lld\n", label_.c_str(),
                 static_cast<long long>(step), static_cast<long long>(total_),
                 total_ > 0 ? 100.0 * static_cast<double>(step) / static_cast<double>(total_) : 100.0,
                 static_cast<double>(step) * dt_, rate, final ? "wall" : "ETA",
                 final ? static_cast<long long>(secs) / 60 : e / 60,
                 final ? static_cast<long long>(secs) % 60 : e % 60);
  }

  std::string label_;
  std::int64_t total_;
  std::int64_t first_ = 0;
  double dt_;
  bool enabled_;
  double interval_;
  clock::time_point start_, last_;
};

}  // namespace polymech::io
