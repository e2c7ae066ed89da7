// Driving an MpsElastic model through a run: steps, energy bookkeeping, and hooks for progress and
// snapshots (the app decides what they print or write; models do no I/O). Also the wave-speed
// measurement of seed 000 §5.1 from the probe histories.
#pragma once

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/signals.hpp"
#include "mps_elastic/mps_elastic.hpp"

namespace polymech::mps_elastic {

struct RunHooks {
  std::function<void(std::int64_t step)> after_step;  // progress
  std::int64_t snapshot_every = 0;                    // 0: never
  std::function<void(std::int64_t step)> snapshot;    // called at step 0 and every snapshot_every steps
  std::int64_t energy_every = 100;                    // energy sampling interval (steps)
};

struct RunStats {
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  double energy_after_excitation = 0.0;  // total energy at the first sample after the pulse ended
  double energy_final = 0.0;
  double energy_min = 0.0, energy_max = 0.0;  // over the samples after the pulse
  // (E_final - E_after) / E_after; max |E - E_after| / E_after over the samples is energy_spread
  double energy_drift = 0.0;
  double energy_spread = 0.0;
  bool finite = true;
  std::vector<double> energy_time, energy_total;  // samples of the total energy
};

// Runs `steps` steps (from the model's current step). Stops early, with finite = false, as soon as a
// sampled state holds NaN or Inf.
template <class T>
RunStats run(MpsElastic<T>& m, std::int64_t steps, const RunHooks& hooks = {}) {
  RunStats s;
  const double pulse_end = m.excitation_end_time();
  const auto t0 = std::chrono::steady_clock::now();
  bool have_ref = false;
  auto sample_energy = [&] {
    const double e = m.energy().total();
    s.energy_time.push_back(m.time());
    s.energy_total.push_back(e);
    if (m.time() > pulse_end) {
      if (!have_ref) {
        have_ref = true;
        s.energy_after_excitation = e;
        s.energy_min = s.energy_max = e;
      }
      s.energy_min = std::min(s.energy_min, e);
      s.energy_max = std::max(s.energy_max, e);
    }
    s.energy_final = e;
    if (!std::isfinite(e)) s.finite = false;
  };
  if (hooks.snapshot && hooks.snapshot_every > 0 && m.step_index() == 0) hooks.snapshot(0);
  const std::int64_t end = m.step_index() + steps;
  while (m.step_index() < end && s.finite) {
    m.step();
    const std::int64_t k = m.step_index();
    if (hooks.energy_every > 0 && (k % hooks.energy_every == 0 || k == end)) sample_energy();
    if (hooks.snapshot && hooks.snapshot_every > 0 && k % hooks.snapshot_every == 0) hooks.snapshot(k);
    if (hooks.after_step) hooks.after_step(k);
  }
  Kokkos::fence();
  s.steps = m.step_index();
  s.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (s.finite) s.finite = m.finite();
  if (have_ref && s.energy_after_excitation > 0) {
    s.energy_drift = (s.energy_final - s.energy_after_excitation) / s.energy_after_excitation;
    s.energy_spread = std::max(s.energy_max - s.energy_after_excitation, s.energy_after_excitation - s.energy_min) /
                      s.energy_after_excitation;
  }
  return s;
}

struct WaveSpeeds {
  double cp = std::numeric_limits<double>::quiet_NaN();
  double cs = std::numeric_limits<double>::quiet_NaN();
  analysis::SpeedMeasurement p, s;
};

inline const Probe& probe_named(const Config& c, const std::string& name) {
  for (const auto& p : c.probes)
    if (p.name == name) return p;
  throw std::invalid_argument("no probe named '" + name + "'");
}

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
