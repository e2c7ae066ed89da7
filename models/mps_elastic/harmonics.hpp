// The higher-harmonic experiment of seed 000 §5.2: the same scene without and with the crack, the
// transmitted wave at one probe, and its spectrum at the harmonics of the drive frequency. The run
// without the crack monitors the crack line; with a normal-reaction ratio, the slip model's fixed
// normal reaction is that ratio times the largest shear force through the line (§5.2.2: 0.75).
// Host code over MpsElastic; spectra need polymech_analysis (FFTW).
#pragma once

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
  analysis::Spectrum spectrum_intact, spectrum_crack;
  std::vector<double> ratios_intact, ratios_crack;  // A_n / A_1, n = 1..5
};

// make_hooks(label, model) gives each run's hooks (progress, snapshots); label is "intact" or "crack".
template <class T>
using HarmonicsHooks = std::function<RunHooks(const std::string& label, MpsElastic<T>& model)>;

template <class T>
HarmonicsRun run_harmonics_once(const Config& c, const std::string& probe, int field, const std::string& label,
                                const HarmonicsHooks<T>& make_hooks) {
  MpsElastic<T> model(c);
  const RunHooks hooks = make_hooks ? make_hooks(label, model) : RunHooks{};
  HarmonicsRun r;
  r.stats = run(model, c.steps, hooks);
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
template <class T>
HarmonicsResult run_harmonics_case(const Config& c, const std::string& probe, int field, double normal_reaction_ratio,
                                   const HarmonicsHooks<T>& make_hooks = {}) {
  HarmonicsResult out;
  Config intact = c;
  intact.crack.mode = CrackMode::monitor;
  intact.effects = EffectSet::resolve(c.effects.has("rotation") ? std::vector<std::string>{"rotation"}
                                                                : std::vector<std::string>{},
                                      MpsElastic<T>::effects());
  out.intact = run_harmonics_once<T>(intact, probe, field, "intact", make_hooks);
  Config cracked = c;
  if (normal_reaction_ratio > 0) cracked.crack.normal_reaction = normal_reaction_ratio * out.intact.max_shear_force;
  out.normal_reaction = cracked.crack.normal_reaction;
  out.crack = run_harmonics_once<T>(cracked, probe, field, "crack", make_hooks);

  out.f0 = 1.0 / c.excitation.period;
  const double dt = c.dt * static_cast<double>(c.probe_every);
  out.spectrum_intact = analysis::amplitude_spectrum(out.intact.signal, dt);
  out.spectrum_crack = analysis::amplitude_spectrum(out.crack.signal, dt);
  out.ratios_intact = analysis::harmonic_ratios(out.spectrum_intact, out.f0);
  out.ratios_crack = analysis::harmonic_ratios(out.spectrum_crack, out.f0);
  return out;
}

}  // namespace polymech::mps_elastic
