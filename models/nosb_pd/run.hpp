// Driving a NosbPd model through a run: steps, time series of energies and of the projectile, and
// hooks for progress and snapshots (the app decides what they print or write; models do no I/O).
#pragma once

#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

struct RunHooks {
  std::function<void(std::int64_t step)> after_step;  // progress
  std::int64_t snapshot_every = 0;                    // 0: never
  std::function<void(std::int64_t step)> snapshot;    // called at step 0 and every snapshot_every steps
  std::int64_t sample_every = 50;                     // energies and projectile (steps)
  // Called after each sample; returning true ends the run (e.g. the projectile is through the plate).
  std::function<bool()> stop;
  // > 0: end the run as diverged once the accounted energy exceeds this multiple of the initial one.
  double energy_limit = 0.0;
};

// One row of the time series.
struct Sample {
  double time = 0;
  Energies energy;
  ProjectileState projectile;
  std::int64_t broken_bonds = 0;
};

struct RunStats {
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  bool finite = true;
  bool diverged = false;  // the energy passed RunHooks::energy_limit (or became NaN / Inf)
  double initial_energy = 0.0;
  std::vector<Sample> samples;
  // max |E_total - E_0| / E_0 over the samples
  double energy_error() const {
    double e = 0;
    for (const auto& s : samples) e = std::max(e, std::abs(s.energy.total() - initial_energy));
    return initial_energy > 0 ? e / initial_energy : 0.0;
  }
};

template <class T, int D>
Sample take_sample(const NosbPd<T, D>& m) {
  Sample s;
  s.time = m.time();
  s.energy = m.energy();
  s.projectile = m.projectile();
  s.broken_bonds = m.broken_bonds();
  return s;
}

// Runs `steps` steps from the model's current step; stops early when a sampled state is not finite
// or hooks.stop() says so.
template <class T, int D>
RunStats run(NosbPd<T, D>& m, std::int64_t steps, const RunHooks& hooks = {}) {
  RunStats s;
  const auto t0 = std::chrono::steady_clock::now();
  s.samples.push_back(take_sample(m));
  s.initial_energy = s.samples.back().energy.total();
  if (hooks.snapshot && hooks.snapshot_every > 0 && m.step_index() == 0) hooks.snapshot(0);
  const std::int64_t end = m.step_index() + steps;
  bool stop = false;
  while (m.step_index() < end && s.finite && !stop) {
    m.step();
    const std::int64_t k = m.step_index();
    if (hooks.sample_every > 0 && (k % hooks.sample_every == 0 || k == end)) {
      s.samples.push_back(take_sample(m));
      const double e = s.samples.back().energy.total();
      if (!std::isfinite(e)) s.finite = false;
      if (!s.finite || (hooks.energy_limit > 0 && e > hooks.energy_limit * s.initial_energy)) s.diverged = true;
      stop = s.diverged;
      if (!stop && hooks.stop) stop = hooks.stop();
    }
    if (hooks.snapshot && hooks.snapshot_every > 0 && (k % hooks.snapshot_every == 0 || stop)) hooks.snapshot(k);
    if (hooks.after_step) hooks.after_step(k);
  }
  Kokkos::fence();
  s.steps = m.step_index();
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (s.finite) s.finite = m.finite();
  return s;
}

}  // namespace polymech::nosb_pd
