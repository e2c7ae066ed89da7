// One explicit run driver for every model: steps, progress, field snapshots, samples (energies, a
// projectile, ...), stop conditions, and a watchdog that stops a run that went bad with the step, the
// first bad particle and where it is, and hands the last good state to the snapshot writer. Models do
// no I/O: what a hook prints or writes is the app's business.
//
// The model needs step(), step_index(), time(), and for the watchdog health() -> Health (all finite?
// the first bad particle and its position) and, to keep the last good state, state() -> const
// StateRegistry& and set_step_index(). Checkpoints (hooks.checkpoint) and restarts (hooks.resume)
// need save(Archive&, prefix) and load(const Archive&, prefix): the model's complete state.
//
// A checkpoint holds the model, the driver's own record ("driver/..."), what the layers above add
// (a run wrapper's time series: Checkpointing::add) and what the app adds when it stores it
// (Checkpointing::write: its snapshot writer). A run resumed from it continues exactly where the
// checkpoint was taken: no start sample, the watchdog's reference energy and the wall time carried.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "common/state.hpp"

namespace polymech::models {

// What the watchdog learns from a model: the first particle (or DoF) whose state is not finite or has
// left the range the model holds for it (an MPS particle moved more than half a spacing).
struct Health {
  bool finite = true;                      // false: the state is bad
  std::int64_t first_bad = -1;             // index of the first bad particle / DoF (-1: none)
  std::string what = "particle";           // what first_bad counts
  std::string problem = "is not finite";   // what is wrong with it
  double position[3] = {0, 0, 0};          // where it is (reference position)
};

struct Watchdog {
  std::int64_t check_every = 50;   // steps between checks (0: never), after that step's sample
  // the run has diverged once the energy the `energy` hook reports is not finite or (energy_limit > 0)
  // exceeds energy_limit x the first positive value it reported (an explicit scheme above its
  // stability limit does not always reach NaN: an MPS lattice that flies apart loses its interactions
  // and keeps a finite, absurd energy: the model's health check catches that first)
  double energy_limit = 0.0;
  std::function<double()> energy;  // total accounted energy (may return the last sample's)
  // keep a copy of the state at the last good check, and snapshot it when the run goes bad
  bool keep_last_good = false;
};

struct Checkpointing {
  double every_seconds = 0.0;     // wall time between checkpoints (0: not by time)
  std::int64_t every_steps = 0;   // also every n steps (0: not by steps; tests use it)
  // records of the layers between the driver and the app (run wrappers), added to every checkpoint
  std::vector<std::function<void(Archive&)>> add;
  // stores the checkpoint of `step` (the app adds its own records first); none when empty
  std::function<void(std::int64_t step, Archive&)> write;
};

struct RunHooks {
  std::function<void(std::int64_t step)> after_step;  // progress
  std::int64_t snapshot_every = 0;                    // 0: never
  // called at step 0, every snapshot_every steps, when a stop condition ends the run, and with the
  // last good state when the watchdog ends it
  std::function<void(std::int64_t step)> snapshot;
  std::int64_t sample_every = 0;                      // 0: never
  bool sample_at_start = false;                       // also sample the initial state
  std::function<void(std::int64_t step)> sample;      // every sample_every steps and at the end
  std::function<bool()> stop;                         // asked after each sample: true ends the run
  Watchdog watchdog;
  Checkpointing checkpoint;
  // continue from this checkpoint: the driver loads the model from it (run wrappers load their own
  // records); nullptr: start from the model's current state
  const Archive* resume = nullptr;
  // every n steps (and at the end) count the subnormal values of the model's state (StateRegistry::
  // subnormal_census; a diagnostic that copies the state to the host, issue 39); 0: never
  std::int64_t census_every = 0;
};

// The largest share of subnormal values each View of the state held at a census, and the step.
struct SubnormalPeak {
  std::string name;
  double share = 0.0;
  std::int64_t step = -1;
};

struct RunStats {
  std::int64_t steps = 0;          // the model's step index at the end
  double wall_seconds = 0.0;
  bool stopped = false;            // a stop condition ended the run
  bool diverged = false;           // the watchdog ended it
  std::string reason;              // why it diverged, in words
  std::int64_t bad_step = -1;      // the step at which the watchdog found it
  Health health;                   // the first bad particle
  std::int64_t last_good_step = -1;  // the step of the last good state (snapshotted when kept)
  std::int64_t checkpoints = 0;      // written during this run
  std::int64_t restarts = 0;         // times the run was resumed from a checkpoint
  std::vector<SubnormalPeak> subnormals;  // per View of the state, with hooks.census_every > 0
};

namespace detail {
inline std::string number(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}
inline std::string describe(const Health& h, int dim) {
  std::string s = h.what + " " + std::to_string(h.first_bad);
  if (h.what == "particle") {
    s += " at (";
    for (int k = 0; k < dim; ++k) s += (k ? ", " : "") + number(h.position[k]);
    s += ")";
  }
  return s + " " + h.problem;
}
}  // namespace detail

// Runs `steps` steps from the model's current step.
template <class Model>
RunStats run(Model& m, std::int64_t steps, const RunHooks& hooks = {}) {
  RunStats s;
  const auto t0 = std::chrono::steady_clock::now();
  const Watchdog& wd = hooks.watchdog;
  StateRegistry::Backup last_good;
  double initial_energy = 0.0;  // the first positive energy the hook reports
  double earlier_wall = 0.0;    // wall seconds of the run before the checkpoint it resumed from
  if (hooks.resume) {
    m.load(*hooks.resume, "model/");
    initial_energy = hooks.resume->get<double>("driver/initial_energy");
    earlier_wall = hooks.resume->get<double>("driver/wall_seconds");
    s.restarts = hooks.resume->get<std::int64_t>("driver/restarts") + 1;
  }
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  const Checkpointing& ck = hooks.checkpoint;
  double last_checkpoint = 0.0;
  auto checkpoint_due = [&](std::int64_t k) {
    if (!ck.write) return false;
    if (ck.every_steps > 0 && k % ck.every_steps == 0) return true;
    return ck.every_seconds > 0 && elapsed() - last_checkpoint >= ck.every_seconds;
  };
  auto write_checkpoint = [&](std::int64_t k) {
    Kokkos::fence();
    Archive a;
    a.put("driver/initial_energy", initial_energy);
    a.put("driver/wall_seconds", earlier_wall + elapsed());
    a.put("driver/restarts", s.restarts);
    a.put("driver/step", k);
    m.save(a, "model/");
    for (const auto& add : ck.add) add(a);
    ck.write(k, a);
    last_checkpoint = elapsed();
    ++s.checkpoints;
  };
  auto check_energy = [&]() {
    if (!wd.energy) return true;
    const double e = wd.energy();
    if (!(initial_energy > 0) && e > 0) initial_energy = e;
    if (!std::isfinite(e)) {
      s.reason = "the accounted energy is not finite";
      return false;
    }
    if (!(wd.energy_limit > 0) || !(initial_energy > 0) || !(e > wd.energy_limit * initial_energy)) return true;
    s.reason = "the accounted energy " + detail::number(e) + " J exceeds " + detail::number(wd.energy_limit) +
               " x the initial " + detail::number(initial_energy) + " J";
    return false;
  };
  auto healthy = [&]() {
    const Health h = m.health();
    if (h.finite) return true;
    s.health = h;
    s.reason = "the first bad " + detail::describe(h, Model::dimension);
    return false;
  };
  auto census = [&](std::int64_t k) {
    const auto c = m.state().subnormal_census();
    if (s.subnormals.size() != c.size()) s.subnormals.assign(c.size(), SubnormalPeak{});
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double share = c[i].values > 0 ? double(c[i].subnormal) / double(c[i].values) : 0.0;
      s.subnormals[i].name = c[i].name;
      if (share > s.subnormals[i].share || s.subnormals[i].step < 0) s.subnormals[i] = {c[i].name, share, k};
    }
  };
  auto keep = [&]() {
    if (!wd.keep_last_good) return;
    m.state().save(last_good);
    s.last_good_step = m.step_index();
  };

  m.prepare();
  if (hooks.sample && hooks.sample_at_start && !hooks.resume) hooks.sample(m.step_index());
  if (!check_energy()) s.diverged = true;
  keep();
  if (hooks.snapshot && hooks.snapshot_every > 0 && m.step_index() == 0) hooks.snapshot(0);
  const std::int64_t end = m.step_index() + steps;
  while (m.step_index() < end && !s.diverged && !s.stopped) {
    m.step();
    const std::int64_t k = m.step_index();
    const bool sample_due = hooks.sample_every > 0 && (k % hooks.sample_every == 0 || k == end);
    if (sample_due && hooks.sample) hooks.sample(k);
    if (wd.check_every > 0 && (k % wd.check_every == 0 || k == end)) {
      if (healthy() && check_energy())
        keep();
      else
        s.diverged = true;
    }
    if (s.diverged) {
      s.bad_step = k;
      break;
    }
    if (sample_due && hooks.stop) s.stopped = hooks.stop();
    if (hooks.snapshot && hooks.snapshot_every > 0 && (k % hooks.snapshot_every == 0 || s.stopped)) hooks.snapshot(k);
    if (hooks.census_every > 0 && (k % hooks.census_every == 0 || k == end)) census(k);
    if (hooks.after_step) hooks.after_step(k);
    if (k < end && !s.stopped && checkpoint_due(k)) write_checkpoint(k);
  }
  Kokkos::fence();
  if (!s.diverged && wd.check_every > 0 && !healthy()) {
    s.diverged = true;
    s.bad_step = m.step_index();
  }
  if (s.diverged && !last_good.empty()) {
    m.state().restore(last_good);
    m.set_step_index(s.last_good_step);
    if (hooks.snapshot) hooks.snapshot(s.last_good_step);
  }
  s.steps = m.step_index();
  s.wall_seconds = earlier_wall + elapsed();
  return s;
}

// The energy record of a run: samples of the total, and its drift and spread over the samples taken
// after a reference time (the end of an excitation; by default every sample counts, the first is the
// reference).
struct EnergyLog {
  double reference_time = -std::numeric_limits<double>::infinity();
  std::vector<double> time, total;
  double reference = 0.0, minimum = 0.0, maximum = 0.0, last = 0.0;
  bool have_reference = false;

  void add(double t, double e) {
    time.push_back(t);
    total.push_back(e);
    last = e;
    if (!(t > reference_time)) return;
    if (!have_reference) {
      have_reference = true;
      reference = minimum = maximum = e;
    }
    minimum = std::min(minimum, e);
    maximum = std::max(maximum, e);
  }
  // (E_last - E_ref) / E_ref
  double drift() const { return have_reference && reference > 0 ? (last - reference) / reference : 0.0; }
  // max |E - E_ref| / E_ref over the samples after the reference
  double spread() const {
    return have_reference && reference > 0 ? std::max(maximum - reference, reference - minimum) / reference : 0.0;
  }
};

inline void save_energy_log(const EnergyLog& e, Archive& a, const std::string& prefix) {
  a.put_vector(prefix + "time", e.time);
  a.put_vector(prefix + "total", e.total);
  const double v[] = {e.reference_time, e.reference, e.minimum, e.maximum, e.last, e.have_reference ? 1.0 : 0.0};
  a.put_bytes(prefix + "scalars", v, sizeof v);
}
inline EnergyLog load_energy_log(const Archive& a, const std::string& prefix) {
  EnergyLog e;
  e.time = a.get_vector<double>(prefix + "time");
  e.total = a.get_vector<double>(prefix + "total");
  const auto v = a.get_vector<double>(prefix + "scalars");
  if (v.size() != 6) throw std::runtime_error("checkpoint: " + prefix + "scalars has " + std::to_string(v.size()) + " values");
  e.reference_time = v[0];
  e.reference = v[1];
  e.minimum = v[2];
  e.maximum = v[3];
  e.last = v[4];
  e.have_reference = v[5] != 0.0;
  return e;
}

}  // namespace polymech::models
