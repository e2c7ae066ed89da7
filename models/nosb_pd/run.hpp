// Driving a NosbPd model, or an impact (impact.hpp), through the shared run driver
// (models/common/run.hpp): time series of energies and of the projectile, the energy watchdog, and
// hooks for progress and snapshots (the app decides what they print or write; models do no I/O).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "common/run.hpp"
#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

using models::RunHooks;

// The projectile in a sample (zeros without one). reaction: the force on it [N].
struct ProjectileState {
  double position[3] = {0, 0, 0}, velocity[3] = {0, 0, 0}, acceleration[3] = {0, 0, 0};
  double reaction[3] = {0, 0, 0};
  double mass = 0.0;
};

// One row of the time series.
struct Sample {
  double time = 0;
  Energies energy;
  ProjectileState projectile;
  std::int64_t broken_bonds = 0;
};

struct RunStats : models::RunStats {
  bool finite = true;      // no NaN / Inf in the state or the energy
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
ProjectileState projectile_state(const NosbPd<T, D>&) {
  return {};
}

template <class Model>
Sample take_sample(const Model& m) {
  Sample s;
  s.time = m.time();
  s.energy = m.energy();
  s.projectile = projectile_state(m);
  s.broken_bonds = m.broken_bonds();
  return s;
}

// Runs `steps` steps from the model's current step, sampling every hooks.sample_every steps (default
// 50) and the initial state. The run ends early when the watchdog finds a NaN / Inf, when the
// accounted energy exceeds energy_limit x the initial one (> 0: the uncontrolled zero-energy modes),
// or when hooks.stop() says so.
template <class Model>
RunStats run(Model& m, std::int64_t steps, RunHooks hooks = {}, double energy_limit = 0.0) {
  RunStats s;
  if (hooks.resume) {  // the samples so far (the model itself is loaded by the driver)
    s.samples = hooks.resume->get_vector<Sample>("run/samples");
    s.initial_energy = hooks.resume->get<double>("run/initial_energy");
  }
  hooks.checkpoint.add.push_back([&s](models::Archive& a) {
    a.put_vector("run/samples", s.samples);
    a.put("run/initial_energy", s.initial_energy);
  });
  if (!hooks.resume) m.prepare();
  if (hooks.sample_every <= 0) hooks.sample_every = 50;
  hooks.sample_at_start = true;
  hooks.sample = [&s, &m, user = hooks.sample](std::int64_t k) {
    s.samples.push_back(take_sample(m));
    if (s.samples.size() == 1) s.initial_energy = s.samples.front().energy.total();
    if (user) user(k);
  };
  hooks.watchdog.check_every = hooks.sample_every;
  hooks.watchdog.energy_limit = energy_limit;
  hooks.watchdog.energy = [&s] { return s.samples.back().energy.total(); };
  static_cast<models::RunStats&>(s) = models::run(m, steps, hooks);
  s.finite = s.health.finite && (s.samples.empty() || std::isfinite(s.samples.back().energy.total()));
  return s;
}

}  // namespace polymech::nosb_pd
