// The higher-harmonic experiment of seed 000 §5.2: the same scene without and with the crack, the
// transmitted wave at one probe, and its spectrum at the harmonics of the drive frequency. The run
// without the crack monitors the crack line; with a normal-reaction ratio, the slip model's fixed
// normal reaction is that ratio times the largest shear force through the line (§5.2.2: 0.75).
// Host code over MpsElastic; spectra need polymech_analysis (FFTW).
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "analysis/spectrum.hpp"
#include "mps_elastic/run.hpp"

namespace polymech::mps_elastic {

struct HarmonicsRun {
  std::vector<double> times, signal;  // the probe field over time
  ProbeHistory history;               // every probe
  ContactHistory contact;
  RunStats stats;
  double max_shear_force = 0.0;  // monitor of the run without the crack [N/m]
  Index particles = 0;
  Offset bonds = 0;
  Index pairs = 0;
};

struct HarmonicsResult {
  HarmonicsRun intact, crack;
  double normal_reaction = 0.0;  // the slip model's fixed |f'_n| used in the cracked run
  double f0 = 0.0;               // drive frequency 1/T
  // Harmonic ratios A_n / A_1 (n = 1..5) of the steady part of the transmitted burst, over 3 drive
  // periods starting one period after its arrival; the same window for both runs.
  double window_start = 0.0;
  std::vector<double> ratios_intact, ratios_crack;
  // Spectra of the whole records (Figs. 8, 10) and the ratios read off them (peak within +-10 % of n f0).
  analysis::Spectrum spectrum_intact, spectrum_crack;
  std::vector<double> spectrum_ratios_intact, spectrum_ratios_crack;
  // Why the analysis of the finished runs failed ("" when it did not): the records are kept and written
  // all the same (issue 33 item 3); the ratios above are then empty.
  std::string analysis_error;
};

// A_n / A_1 of a probe signal over the steady window starting at t_start.
inline std::vector<double> burst_ratios(const std::vector<double>& t, const std::vector<double>& x, double t_start,
                                        double f0) {
  auto a = analysis::burst_harmonic_amplitudes(t, x, t_start, f0);
  const double a1 = a[0];
  for (auto& v : a) v = a1 > 0 ? v / a1 : 0.0;
  return a;
}

// make_hooks(label, model) gives each run's hooks (progress, snapshots, checkpoints); label is "intact"
// or "crack".
template <class T>
using HarmonicsHooks = std::function<RunHooks(const std::string& label, MpsElastic<T>& model)>;

// Checkpoints of the pair of runs: each holds "harmonics/run" (the label of the run it was taken in),
// and those of the cracked run also the finished intact run's record ("harmonics/intact/..."), so a
// restart continues inside whichever run was going.
inline std::string harmonics_phase(const models::Archive* a) { return a ? a->get_string("harmonics/run") : std::string(); }

inline void save_harmonics_run(const HarmonicsRun& r, models::Archive& a, const std::string& prefix) {
  a.put_vector(prefix + "times", r.times);
  a.put_vector(prefix + "signal", r.signal);
  const auto& h = r.history;
  a.put(prefix + "probes", static_cast<std::int64_t>(h.names.size()));
  a.put(prefix + "probe_fields", static_cast<std::int64_t>(h.fields.size()));
  for (std::size_t p = 0; p < h.names.size(); ++p) {
    a.put_string(prefix + "probe_name/" + std::to_string(p), h.names[p]);
    a.put_columns(prefix + "probe_values/" + std::to_string(p), h.values[p]);
  }
  for (std::size_t f = 0; f < h.fields.size(); ++f) a.put_string(prefix + "probe_field/" + std::to_string(f), h.fields[f]);
  a.put_vector(prefix + "probe_times", h.times);
  a.put_columns(prefix + "contact", std::vector<std::vector<double>>{r.contact.times, r.contact.separation, r.contact.stick, r.contact.slip});
  a.put(prefix + "max_shear_force", r.max_shear_force);
  a.put(prefix + "particles", static_cast<std::int64_t>(r.particles));
  a.put(prefix + "bonds", static_cast<std::int64_t>(r.bonds));
  a.put(prefix + "pairs", static_cast<std::int64_t>(r.pairs));
  a.put(prefix + "steps", r.stats.steps);
  a.put(prefix + "wall_seconds", r.stats.wall_seconds);
  a.put(prefix + "restarts", r.stats.restarts);
  models::save_energy_log(r.stats.energy, a, prefix + "energy/");
}
inline HarmonicsRun load_harmonics_run(const models::Archive& a, const std::string& prefix) {
  HarmonicsRun r;
  r.times = a.get_vector<double>(prefix + "times");
  r.signal = a.get_vector<double>(prefix + "signal");
  auto& h = r.history;
  const auto probes = a.get<std::int64_t>(prefix + "probes"), fields = a.get<std::int64_t>(prefix + "probe_fields");
  for (std::int64_t p = 0; p < probes; ++p) {
    h.names.push_back(a.get_string(prefix + "probe_name/" + std::to_string(p)));
    h.values.push_back(a.get_columns<double>(prefix + "probe_values/" + std::to_string(p)));
  }
  for (std::int64_t f = 0; f < fields; ++f) h.fields.push_back(a.get_string(prefix + "probe_field/" + std::to_string(f)));
  h.times = a.get_vector<double>(prefix + "probe_times");
  const auto c = a.get_columns<double>(prefix + "contact");
  if (c.size() != 4) throw std::runtime_error("checkpoint: " + prefix + "contact needs 4 columns");
  r.contact = {c[0], c[1], c[2], c[3]};
  r.max_shear_force = a.get<double>(prefix + "max_shear_force");
  r.particles = static_cast<Index>(a.get<std::int64_t>(prefix + "particles"));
  r.bonds = static_cast<Offset>(a.get<std::int64_t>(prefix + "bonds"));
  r.pairs = static_cast<Index>(a.get<std::int64_t>(prefix + "pairs"));
  r.stats.steps = a.get<std::int64_t>(prefix + "steps");
  r.stats.wall_seconds = a.get<double>(prefix + "wall_seconds");
  r.stats.restarts = a.get<std::int64_t>(prefix + "restarts");
  r.stats.energy = models::load_energy_log(a, prefix + "energy/");
  return r;
}

// One of the two runs. The hooks' resume is used only when that checkpoint was taken in this run
// (otherwise this run starts from its beginning); `carry` (the intact run's record, in the cracked
// run) goes into every checkpoint.
template <class T>
HarmonicsRun run_harmonics_once(const Config& c, const std::string& probe, int field, const std::string& label,
                                const HarmonicsHooks<T>& make_hooks, const HarmonicsRun* carry = nullptr) {
  MpsElastic<T> model(c);
  RunHooks hooks = make_hooks ? make_hooks(label, model) : RunHooks{};
  if (hooks.resume && harmonics_phase(hooks.resume) != label) hooks.resume = nullptr;
  hooks.checkpoint.add.push_back([label, carry](models::Archive& a) {
    a.put_string("harmonics/run", label);
    if (carry) save_harmonics_run(*carry, a, "harmonics/intact/");
  });
  HarmonicsRun r;
  r.stats = run(model, c.steps - (hooks.resume ? hooks.resume->get<std::int64_t>("driver/step") : 0), hooks);
  if (!r.stats.finite)
    throw std::runtime_error("the " + label + " run became unstable (NaN/Inf) before step " + std::to_string(r.stats.steps));
  const auto& h = model.probes();
  for (std::size_t p = 0; p < h.names.size(); ++p)
    if (h.names[p] == probe) r.signal = h.values[p][field];
  if (r.signal.empty()) throw std::invalid_argument("no probe named '" + probe + "'");
  r.times = h.times;
  r.history = h;
  r.contact = model.contact_history();
  r.max_shear_force = model.crack().max_shear_force();
  r.particles = model.particles();
  r.bonds = model.bonds();
  r.pairs = model.crack().pair_count();
  return r;
}

// c: the cracked scene (CrackMode::cut and its contact effects); field: mps::probe_u1 or probe_u3.
// resume: the checkpoint the hooks resume from (nullptr: none); one taken in the cracked run skips the
// intact run (its record is in the checkpoint).
template <class T>
HarmonicsResult run_harmonics_case(const Config& c, const std::string& probe, int field, double normal_reaction_ratio,
                                   const HarmonicsHooks<T>& make_hooks = {}, const models::Archive* resume = nullptr) {
  HarmonicsResult out;
  Config intact = c;
  intact.crack.mode = CrackMode::monitor;
  intact.effects = EffectSet::resolve(c.effects.has("rotation") ? std::vector<std::string>{"rotation"}
                                                                : std::vector<std::string>{},
                                      MpsElastic<T>::effects());
  if (harmonics_phase(resume) == "crack")
    out.intact = load_harmonics_run(*resume, "harmonics/intact/");
  else
    out.intact = run_harmonics_once<T>(intact, probe, field, "intact", make_hooks);
  Config cracked = c;
  if (normal_reaction_ratio > 0) cracked.crack.normal_reaction = normal_reaction_ratio * out.intact.max_shear_force;
  out.normal_reaction = cracked.crack.normal_reaction;
  out.crack = run_harmonics_once<T>(cracked, probe, field, "crack", make_hooks, &out.intact);

  out.f0 = 1.0 / c.excitation.period;
  const double dt = c.dt * static_cast<double>(c.probe_every);
  try {
    out.window_start = analysis::burst_steady_start(out.intact.times, out.intact.signal, out.f0);
    out.ratios_intact = burst_ratios(out.intact.times, out.intact.signal, out.window_start, out.f0);
    out.ratios_crack = burst_ratios(out.crack.times, out.crack.signal, out.window_start, out.f0);
    out.spectrum_intact = analysis::amplitude_spectrum(out.intact.signal, dt);
    out.spectrum_crack = analysis::amplitude_spectrum(out.crack.signal, dt);
    out.spectrum_ratios_intact = analysis::harmonic_ratios(out.spectrum_intact, out.f0, 5, 0.1);
    out.spectrum_ratios_crack = analysis::harmonic_ratios(out.spectrum_crack, out.f0, 5, 0.1);
  } catch (const std::invalid_argument& e) {
    out.analysis_error = "the harmonic analysis at probe " + probe + ": " + e.what();
    out.ratios_intact.clear();
    out.ratios_crack.clear();
  }
  return out;
}

}  // namespace polymech::mps_elastic
