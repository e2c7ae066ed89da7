// What the higher-harmonic case of seed 000 §5.2 measures (Figs. 7-10; docs/VALIDATION.md), from the
// records of its two runs (harmonics.hpp: without and with the crack), used alike by apps/mps_harmonics,
// the tests and the sweeps:
//   - before a run: whether the record holds the analysis window at a probe (the burst's arrival plus
//     four periods), and the reason in words when it does not;
//   - the spectra of both runs at the harmonics probe over the first harmonic (Figs. 8, 10);
//   - every probe's u1 and u3 over time, both runs (with the spectra: the tables the case writes);
//   - the harmonic ratios A_n / A_1 at every probe, each in its own steady window (how the harmonics
//     fade with the distance from the crack).
// Host code; spectra need polymech_analysis (FFTW).
#pragma once

#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/spectrum.hpp"
#include "common/host_copy.hpp"
#include "mps_elastic/harmonics.hpp"

namespace polymech::mps_elastic {

// How the harmonic ratios are measured (run_harmonics_case, burst_ratios), in words for the summary.
inline constexpr const char* ratios_method =
    "A_n/A_1 from the Fourier coefficients at n f0 over 3 drive periods of the steady transmitted "
    "burst (window_start .. + 3 T), the same window for both runs";

// "the P burst reaches probe <probe> at <t> s and its analysis window ends 3.75 periods later"
inline std::string window_description(const Config& c, const std::string& probe) {
  char b[256];
  std::snprintf(b, sizeof b, "the %s burst reaches probe %s at %.3g s and its analysis window ends 3.75 periods later",
                c.excitation.kind == ExcitationKind::plane_s ? "S" : "P", probe.c_str(), burst_arrival(c, probe_named(c, probe)));
  return std::string(b);
}

// Why the record of c.steps steps is too short for the harmonic window at `probe` ("" when it is long
// enough; steps_for_harmonic_window). `steps_from` names what set the step count ("--steps").
inline std::string record_shortfall(const Config& c, const std::string& probe, const std::string& steps_from) {
  const std::int64_t n = steps_for_harmonic_window(c, probe);
  if (c.steps >= n) return "";
  return steps_from + " = " + std::to_string(c.steps) + " records " + models::format_g(static_cast<double>(c.steps) * c.dt) +
         " s, but " + window_description(c, probe) + ": needs at least " + std::to_string(n) + " steps (--steps " +
         std::to_string(n) + ")";
}

// Why a scene cannot run as a harmonics case ("" when it can): it needs a crack, a harmonics probe, and a
// record that holds that probe's analysis window (record_shortfall), or the run's time is spent for
// nothing (issue 33 item 3).
inline std::string harmonics_case_error(const Config& c, const std::string& probe, const std::string& steps_from) {
  if (c.crack.mode == CrackMode::none) return "mps_harmonics needs a [crack] table";
  if (probe.empty()) return "mps_harmonics needs [analysis].harmonics_probe";
  return record_shortfall(c, probe, steps_from);
}

// The other probes whose own window the record does not hold: their ratios are left out (a note each,
// "<window_description>: the ratios at probe <name> are left out (<n> steps needed)").
inline std::vector<std::string> probes_left_out(const Config& c, const std::string& harmonics_probe) {
  std::vector<std::string> notes;
  for (const auto& p : c.probes) {
    if (p.name == harmonics_probe) continue;
    const std::int64_t n = steps_for_harmonic_window(c, p.name);
    if (c.steps < n)
      notes.push_back(window_description(c, p.name) + ": the ratios at probe " + p.name + " are left out (" + std::to_string(n) +
                      " steps needed)");
  }
  return notes;
}

// The lattice's reference positions (x1, x3 per particle): the mesh of the snapshots.
inline std::vector<double> lattice_points(const Config& c) {
  const Lattice lat = make_lattice(c);
  std::vector<double> points(2 * static_cast<std::size_t>(lat.count()));
  for (Index i = 0; i < lat.count(); ++i) {
    points[2 * static_cast<std::size_t>(i)] = lat.x1(i);
    points[2 * static_cast<std::size_t>(i) + 1] = lat.x3(i);
  }
  return points;
}

// The amplitude spectra of both runs up to 6 f0, each over its own first harmonic's amplitude (0 where
// that is 0): columns frequency, crack, intact (spectrum.csv; Figs. 8, 10).
inline std::vector<std::vector<double>> relative_spectra(const HarmonicsResult& r) {
  const auto& sa = r.spectrum_intact;
  const auto& sb = r.spectrum_crack;
  const double a1_intact = analysis::harmonic_amplitudes(sa, r.f0, 1)[0];
  const double a1_crack = analysis::harmonic_amplitudes(sb, r.f0, 1)[0];
  std::vector<std::vector<double>> cols(3);
  for (std::size_t k = 0; k < sa.frequency.size() && sa.frequency[k] <= 6.0 * r.f0; ++k) {
    cols[0].push_back(sa.frequency[k]);
    cols[1].push_back(a1_crack > 0 ? sb.amplitude[k] / a1_crack : 0.0);
    cols[2].push_back(a1_intact > 0 ? sa.amplitude[k] / a1_intact : 0.0);
  }
  return cols;
}

// u1 and u3 at every probe of a run's history: the header (time, <probe>_u1, <probe>_u3, ...) and the
// columns.
struct ProbeTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;
};
inline ProbeTable probe_table(const ProbeHistory& h) {
  ProbeTable t{{"time"}, {h.times}};
  for (std::size_t p = 0; p < h.names.size(); ++p)
    for (int f : {mps::probe_u1, mps::probe_u3}) {
      t.header.push_back(h.names[p] + "_" + mps::probe_field_name(f));
      t.columns.push_back(h.values[p][f]);
    }
  return t;
}

// The tables a harmonics case writes, in the order of its summary's list of files: time_history.csv
// (`component` at the harmonics probe, both runs), probes_crack.csv and probes_intact.csv (probe_table),
// spectrum.csv (relative_spectra; not when the analysis failed) and contact_states.csv (the crack's pairs
// in each state over time; when the cracked run recorded them).
struct NamedTable {
  std::string file;
  ProbeTable table;
};
inline std::vector<NamedTable> harmonics_tables(const HarmonicsResult& r, const std::string& component) {
  const auto& a = r.intact;
  const auto& b = r.crack;
  std::vector<NamedTable> out;
  out.push_back({"time_history.csv", {{"time", component + "_crack", component + "_intact"}, {b.times, b.signal, a.signal}}});
  out.push_back({"probes_crack.csv", probe_table(b.history)});
  out.push_back({"probes_intact.csv", probe_table(a.history)});
  if (r.analysis_error.empty()) out.push_back({"spectrum.csv", {{"frequency", "crack", "intact"}, relative_spectra(r)}});
  if (!b.contact.times.empty())
    out.push_back({"contact_states.csv",
                   {{"time", "separation", "stick", "slip"}, {b.contact.times, b.contact.separation, b.contact.stick, b.contact.slip}}});
  return out;
}

// The harmonic ratios of `field` at every probe, both runs, in the probe's own steady window (found in
// the intact run's record, analysis::burst_steady_start); `note` says why a probe has none.
struct ProbeRatios {
  std::string name;
  bool measured = false;
  std::vector<double> crack, intact;
  double window_start = 0.0;
  std::string note;
};
inline std::vector<ProbeRatios> probe_ratios(const HarmonicsResult& r, int field) {
  const auto& a = r.intact.history;
  const auto& b = r.crack.history;
  std::vector<ProbeRatios> out;
  for (std::size_t p = 0; p < b.names.size(); ++p) {
    ProbeRatios q;
    q.name = b.names[p];
    try {
      q.window_start = analysis::burst_steady_start(a.times, a.values[p][field], r.f0);
      q.crack = burst_ratios(b.times, b.values[p][field], q.window_start, r.f0);
      q.intact = burst_ratios(a.times, a.values[p][field], q.window_start, r.f0);
      q.measured = true;
    } catch (const std::invalid_argument& e) {
      q.note = e.what();
    }
    out.push_back(q);
  }
  return out;
}

}  // namespace polymech::mps_elastic
