// The transient analysis of a harvester case (issue 35; seed 002 paper 1) as a model of the run driver
// (models/common/run.hpp). No I/O.
//
//   transient  a_b(t) = A sin(w t) from rest (HarvesterTransient, a model of the run driver models/common/run.hpp:
//              step, save/load for checkpoints); afterwards the steady amplitude and mean power over the last
//              periods against the harmonic solve at the same frequency (transient_summary).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "common/run.hpp"
#include "common/state.hpp"
#include "piezo/beam_model.hpp"
#include "piezo/harvester_analyses.hpp"
#include "piezo/harvester_beam.hpp"
#include "piezo/harvester_setup.hpp"
#include "piezo/transient.hpp"

namespace polymech::piezo {

// ---- transient ----

// The time-domain harvester as a model of the run driver (models/common/run.hpp): a_b(t) = A sin(w t) from rest,
// one PiezoTransient step per step; its complete state (TransientState and the solve count) goes into every
// checkpoint, so a resumed run continues bitwise (the monolithic scheme; the partitioned scheme forms its
// Broyden Jacobian again after a restart: the same answer to the loop's tolerance, not bitwise).
class HarvesterTransient {
 public:
  static constexpr int dimension = 2;  // for the run driver's messages only

  explicit HarvesterTransient(const HarvesterSetup& s)
      : s_(s), beam_(beam_spec(s)), wsc_(beam_.natural_frequency(true)), woc_(beam_.natural_frequency(false)),
        w_(s.analysis.frequency > 0 ? 2.0 * kPi * s.analysis.frequency : wsc_),
        dt_(2.0 * kPi / w_ / s.analysis.steps_per_period), damping_(damping_of(s, wsc_)), circuit_(make_circuit(beam_, s)),
        transient_(beam_, circuit_, options()), la_(terminal(beam_, s.resistors.front().from)),
        lb_(terminal(beam_, s.resistors.front().to)) {
    transient_.start(0.0);
  }
  HarvesterTransient(const HarvesterTransient&) = delete;
  HarvesterTransient& operator=(const HarvesterTransient&) = delete;

  const PiezoBeam& beam() const { return beam_; }
  double omega_sc() const { return wsc_; }
  double omega_oc() const { return woc_; }
  double omega() const { return w_; }
  double dt() const { return dt_; }
  const Rayleigh& damping() const { return damping_; }
  const Circuit& circuit() const { return circuit_; }
  const PiezoTransient& transient() const { return transient_; }
  std::int64_t solves() const { return solves_; }
  double base_acceleration(std::int64_t k) const { return s_.analysis.base_acceleration * std::sin(w_ * dt_ * static_cast<double>(k)); }

  // the run driver's model interface
  void prepare() {}
  void step() {
    solves_ += transient_.step(base_acceleration(step_ + 1));
    ++step_;
  }
  std::int64_t step_index() const { return step_; }
  void set_step_index(std::int64_t k) { step_ = k; }
  double time() const { return dt_ * static_cast<double>(step_); }
  const models::StateRegistry& state() const { return no_views_; }  // host vectors: checkpoints use save/load
  models::Health health() const {
    models::Health h;
    const auto& x = transient_.state().x;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (!std::isfinite(x[i])) {
        h.finite = false;
        h.first_bad = static_cast<std::int64_t>(i);
        h.what = "unknown";
        break;
      }
    return h;
  }
  void save(models::Archive& a, const std::string& p) const {
    const TransientState& t = transient_.state();
    a.put(p + "step", step_);
    a.put(p + "solves", solves_);
    a.put(p + "transient_step", t.step);
    a.put_vector(p + "scalars", std::vector<double>{t.time, t.base_acceleration, t.work_in, t.work_damping, t.work_circuit, t.energy0});
    a.put_vector(p + "x", t.x);
    a.put_vector(p + "v", t.v);
    a.put_vector(p + "a", t.a);
    a.put_vector(p + "Q", t.Q);
    a.put_vector(p + "jacobian", t.jacobian);  // partitioned: the Broyden Jacobian (restart bitwise)
  }
  void load(const models::Archive& a, const std::string& p) {
    TransientState t;
    step_ = a.get<std::int64_t>(p + "step");
    solves_ = a.get<std::int64_t>(p + "solves");
    t.step = a.get<std::int64_t>(p + "transient_step");
    const auto sc = a.get_vector<double>(p + "scalars");
    if (sc.size() != 6) throw std::runtime_error("checkpoint: " + p + "scalars has " + std::to_string(sc.size()) + " values");
    t.time = sc[0];
    t.base_acceleration = sc[1];
    t.work_in = sc[2];
    t.work_damping = sc[3];
    t.work_circuit = sc[4];
    t.energy0 = sc[5];
    t.x = a.get_vector<double>(p + "x");
    t.v = a.get_vector<double>(p + "v");
    t.a = a.get_vector<double>(p + "a");
    t.Q = a.get_vector<double>(p + "Q");
    t.jacobian = a.get_vector<double>(p + "jacobian");
    transient_.restore(t);  // refuses a state of another size
  }

  // One row of series.csv.
  static std::vector<std::string> columns() {
    return {"t", "base_acceleration", "V", "tip", "power", "stored_energy", "work_in", "work_damping", "work_circuit",
            "energy_balance_error"};
  }
  std::vector<double> sample() const {
    const TransientState& t = transient_.state();
    return {time(), t.base_acceleration, transient_.voltage(la_, lb_), transient_.tip(), transient_.power(), transient_.energy(),
            t.work_in, t.work_damping, t.work_circuit, transient_.energy_balance_error()};
  }

  // The summary after the run, from the series (its columns as sampled, restart-safe): the steady amplitude
  // sqrt(2 mean V^2) and the peak |V| over the last average_periods periods, the mean harvested power over them
  // (the circuit's work difference over the time between), and the harmonic solve at w for comparison.
  CaseSummary summary(const std::vector<double>& t, const std::vector<double>& V, const std::vector<double>& tip,
                      const std::vector<double>& work_circuit) const {
    CaseSummary o;
    const auto& a = s_.analysis;
    const double A = a.base_acceleration, tau = 2.0 * kPi;
    o.put("unknowns", static_cast<double>(beam_.unknowns()));
    o.put("f_sc", wsc_ / tau);
    o.put("f_oc", woc_ / tau);
    o.put("frequency", w_ / tau);
    o.put("dt", dt_);
    o.put("steps_per_period", a.steps_per_period);
    o.put("periods_run", time() * w_ / tau);
    o.put("base_acceleration", A);
    o.put("load_ohm", circuit_.resistors().front().R);
    const double window = a.average_periods * tau / w_;
    const std::size_t n = t.size();
    std::size_t first = n;
    while (first > 0 && t[first - 1] >= time() - window - 0.25 * dt_) --first;
    if (n > 0 && first + 1 < n) {
      double v2 = 0.0, peak = 0.0, tip_peak = 0.0;
      for (std::size_t i = first + 1; i < n; ++i) {  // whole periods: the samples after the window's start
        v2 += V[i] * V[i];
        peak = std::max(peak, std::fabs(V[i]));
        tip_peak = std::max(tip_peak, std::fabs(tip[i]));
      }
      o.put("average_over_periods", (t[n - 1] - t[first]) * w_ / tau);
      o.put("voltage_amplitude", std::sqrt(2.0 * v2 / static_cast<double>(n - 1 - first)));
      o.put("voltage_peak", peak);
      o.put("tip_peak", tip_peak);
      o.put("mean_power", (work_circuit[n - 1] - work_circuit[first]) / (t[n - 1] - t[first]));
    }
    const HarmonicResponse h = beam_.harmonic(w_, circuit_, damping_);
    const auto at = [&](int k) { return k == Circuit::ground ? std::complex<double>(0.0) : h.V[static_cast<std::size_t>(k)]; };
    o.put("harmonic_voltage_amplitude", A * std::abs(at(la_) - at(lb_)));
    o.put("harmonic_mean_power", A * A * h.power);
    o.put("harmonic_tip_amplitude", A * std::abs(h.tip));
    if (const auto spec = bimorph_of(s_, s_.zeta > 0 ? s_.zeta : 0.5 * (s_.alpha / wsc_ + s_.beta * wsc_))) {
      BimorphSpec st = *spec;
      st.induced_potential = true;
      const BimorphHarvester ei(st);
      o.put("ei09_induced_potential_voltage_amplitude_at_its_f_sc", A * std::abs(ei.response(ei.omega(0), circuit_.resistors().front().R).V));
    }
    o.put("energy_balance_error", transient_.energy_balance_error());
    o.put("solves", static_cast<double>(solves_));
    o.note("scheme", to_string(transient_.options().scheme));
    return o;
  }

 private:
  TransientOptions options() const {
    TransientOptions o;
    o.dt = dt_;
    o.damping = damping_;
    o.scheme = s_.analysis.scheme == "partitioned" ? Scheme::partitioned : Scheme::monolithic;
    return o;
  }

  HarvesterSetup s_;
  PiezoBeam beam_;
  double wsc_, woc_, w_, dt_;
  Rayleigh damping_;
  Circuit circuit_;
  PiezoTransient transient_;
  int la_, lb_;
  std::int64_t step_ = 0, solves_ = 0;
  models::StateRegistry no_views_;
};

}  // namespace polymech::piezo
