// Driving an MpsElastic model through a run (the shared driver of models/common/run.hpp with the
// model's energy bookkeeping), and the wave-speed measurement of seed 000 §5.1 from the probe
// histories.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/signals.hpp"
#include "common/run.hpp"
#include "mps_elastic/burst.hpp"
#include "mps_elastic/mps_elastic.hpp"

namespace polymech::mps_elastic {

using models::RunHooks;

// The shared driver's statistics and the energy record: samples of the total energy, its drift and
// spread over the samples after the excitation has ended.
struct RunStats : models::RunStats {
  bool finite = true;  // no NaN / Inf found by the watchdog
  models::EnergyLog energy;
};

// Runs `steps` steps (from the model's current step) through the shared run driver
// (models/common/run.hpp), sampling the total energy every hooks.sample_every steps (default 100)
// before the hook's own sample. The watchdog checks every sample: the run stops early, with finite =
// false, when the state holds a NaN or Inf or when the energy exceeds 100 x its first sampled value
// (far above what an excitation adds after its first 100 steps; a lattice past its stability limit
// flies apart with a finite energy many orders larger).
template <class T>
RunStats run(MpsElastic<T>& m, std::int64_t steps, RunHooks hooks = {}) {
  RunStats s;
  s.energy.reference_time = m.excitation_end_time();
  if (hooks.resume) s.energy = models::load_energy_log(*hooks.resume, "run/energy/");
  hooks.checkpoint.add.push_back([&s](models::Archive& a) { models::save_energy_log(s.energy, a, "run/energy/"); });
  if (hooks.sample_every <= 0) hooks.sample_every = 100;
  hooks.sample = [&s, &m, user = hooks.sample](std::int64_t k) {
    s.energy.add(m.time(), m.energy().total());
    if (user) user(k);
  };
  hooks.watchdog.check_every = hooks.sample_every;
  if (!(hooks.watchdog.energy_limit > 0)) hooks.watchdog.energy_limit = 100.0;
  hooks.watchdog.energy = [&s] { return s.energy.total.empty() ? 0.0 : s.energy.total.back(); };
  static_cast<models::RunStats&>(s) = models::run(m, steps, hooks);
  s.finite = !s.diverged;
  return s;
}

struct WaveSpeeds {
  double cp = std::numeric_limits<double>::quiet_NaN();
  double cs = std::numeric_limits<double>::quiet_NaN();
  analysis::SpeedMeasurement p, s;
};

// P- and S-wave speeds from arrival-time differences (seed 000 §5.1: cp = sqrt((C13 + 2 C55)/rho),
// cs = sqrt(C55/rho)): the P front in the divergence field at two probes on one ray from the source,
// the S front in the rotation field (1/2 curl u) at two others. Neither field sees the other wave
// in the continuum, so each arrival is that wave's own.
inline WaveSpeeds measure_wave_speeds(const ProbeHistory& h, const Config& c, double source_x1, double source_x3,
                                      const std::vector<std::string>& p_probes,
                                      const std::vector<std::string>& s_probes) {
  WaveSpeeds w;
  auto index_of = [&](const std::string& name) {
    for (std::size_t k = 0; k < h.names.size(); ++k)
      if (h.names[k] == name) return k;
    throw std::invalid_argument("no probe history named '" + name + "'");
  };
  auto distance = [&](const std::string& name) {
    const Probe& p = probe_named(c, name);
    return std::hypot(p.x1 - source_x1, p.x3 - source_x3);
  };
  auto measure = [&](const std::vector<std::string>& names, int field) {
    const auto a = index_of(names.at(0)), b = index_of(names.at(1));
    return analysis::wave_speed(h.times, h.values[a][field], h.values[b][field], distance(names[0]),
                                distance(names[1]));
  };
  if (p_probes.size() == 2) {
    w.p = measure(p_probes, mps::probe_divergence);
    w.cp = w.p.speed;
  }
  if (s_probes.size() == 2) {
    w.s = measure(s_probes, mps::probe_rotation);
    w.cs = w.s.speed;
  }
  return w;
}

}  // namespace polymech::mps_elastic
