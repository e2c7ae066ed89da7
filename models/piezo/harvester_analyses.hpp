// The static and harmonic analyses of a harvester case (issue 35; seed 002 paper 1), each with the closed forms
// it is compared against (models/piezo/harvester_closed_forms.hpp). No I/O: the results come back as summary
// values and tables (models/piezo/harvester_beam.hpp).
//
//   static     the prescribed electrodes at their potentials, no mechanical load: the tip deflection against
//              the laminated bender's closed form (below), as a beam (uniaxial stress, T2 = 0) and as a plate
//              (cylindrical bending, S2 = 0); the charges and capacitances of the prescribed electrodes.
//   harmonic   for each load R and frequency f: the steady load voltage, power and tip amplitude for the base
//              acceleration amplitude A (beam.harmonic, one complex factorisation each); the short- and open-
//              circuit frequencies of the FE beam; per load the sweep's peak power; R_opt and P_max of the sweep;
//              for a symmetric series bimorph the Erturk-Inman distributed-parameter model (analytic.hpp, EI09)
//              on the same grid, with and without the induced-potential stiffening.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "piezo/analytic.hpp"
#include "piezo/beam_model.hpp"
#include "piezo/harvester_beam.hpp"
#include "piezo/harvester_closed_forms.hpp"
#include "piezo/harvester_setup.hpp"

namespace polymech::piezo {

// ---- static ----

inline CaseSummary run_static(const HarvesterSetup& s, CaseTable& deflection) {
  const auto t0 = std::chrono::steady_clock::now();
  const PiezoBeam beam(beam_spec(s));
  const std::vector<double> x = beam.solve_static();
  const double tip = beam.tip(x);
  CaseSummary o;
  o.put("unknowns", static_cast<double>(beam.unknowns()));
  o.put("tip_deflection", tip);
  const BenderClosedForm cf = laminated_bender(s);
  if (cf.not_applicable.empty()) {
    o.put("tip_deflection_beam_theory", cf.beam);
    o.put("tip_deflection_plate_theory", cf.plate);
    const bool plate = s.dim == 2 && s.plane == "strain";
    o.put(plate ? "tip_deflection_error_plate" : "tip_deflection_error_beam", tip / (plate ? cf.plate : cf.beam) - 1.0);
  } else {
    o.note("closed_form", "none: " + cf.not_applicable);
  }
  const std::vector<double> Q = beam.charges(x), V = beam.electrode_potentials(x);
  for (const auto& e : s.electrodes) {
    if (e.kind == "grounded") continue;
    const auto k = static_cast<std::size_t>(beam.electrode(e.name));
    o.put("potential_" + e.name, V[k]);
    if (e.kind != "prescribed") continue;
    o.put("charge_" + e.name, Q[k]);
    if (e.potential != 0.0) o.put("capacitance_" + e.name, Q[k] / e.potential);
  }
  // the deflection along the bottom line (y = 0 in 3D)
  deflection = CaseTable({"x", "deflection"});
  const int D = beam.dim();
  const auto& c = beam.coordinates();
  for (std::int64_t v = 0; v < beam.nodes(); ++v) {
    const auto i = static_cast<std::size_t>(D * v);
    if (c[i + static_cast<std::size_t>(D - 1)] != 0.0 || (D == 3 && c[i + 1] != 0.0)) continue;
    const std::int64_t d = beam.dof_u(v, D - 1);
    deflection.append({c[i], d >= 0 ? x[static_cast<std::size_t>(d)] : 0.0});
  }
  o.put("wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return o;
}

// ---- harmonic ----

inline CaseSummary run_harmonic(const HarvesterSetup& s, CaseTable& frf, CaseTable& per_load,
                                const std::function<void(const std::string&)>& log) {
  const auto t0 = std::chrono::steady_clock::now();
  const PiezoBeam beam(beam_spec(s));
  const double wsc = beam.natural_frequency(true), woc = beam.natural_frequency(false), tau = 2.0 * kPi;
  const Rayleigh damping = damping_of(s, wsc);
  const auto& a = s.analysis;
  const double A = a.base_acceleration;
  const double fmin = a.fmin > 0 ? a.fmin : 0.9 * wsc / tau, fmax = a.fmax > 0 ? a.fmax : 1.1 * woc / tau;
  std::vector<double> f(static_cast<std::size_t>(a.points));
  for (int i = 0; i < a.points; ++i) f[static_cast<std::size_t>(i)] = a.points == 1 ? fmin : fmin + (fmax - fmin) * i / (a.points - 1);
  const std::vector<double> loads = a.loads.empty() ? std::vector<double>{s.resistors.front().ohm} : a.loads;
  const int la = terminal(beam, s.resistors.front().from), lb = terminal(beam, s.resistors.front().to);
  const double zeta = s.zeta > 0 ? s.zeta : 0.5 * (s.alpha / wsc + s.beta * wsc);
  std::optional<BimorphHarvester> ei09, ei09_induced;
  if (const auto spec = bimorph_of(s, zeta)) {
    ei09.emplace(*spec);
    BimorphSpec st = *spec;
    st.induced_potential = true;
    ei09_induced.emplace(st);
  }
  frf = CaseTable({"R_ohm", "f_hz", "V_amplitude", "power", "tip"});
  per_load = CaseTable({"R_ohm", "f_peak_hz", "P_max", "V_at_peak", "tip_at_peak", "P_max_ei09", "P_max_ei09_induced"});
  double best_P = -1.0, best_R = 0.0, best_f = 0.0, best_V = 0.0;
  double best_ei = -1.0, best_ei_R = 0.0, best_eis = -1.0, best_eis_R = 0.0;
  // one factorisation per frequency for every load (PiezoBeam::harmonic over circuits)
  std::vector<Circuit> circuits;
  for (const double R : loads) circuits.push_back(make_circuit(beam, s, R));
  std::vector<std::vector<HarmonicResponse>> by_frequency;
  by_frequency.reserve(f.size());
  for (const double fi : f) by_frequency.push_back(beam.harmonic(tau * fi, circuits, damping));
  for (std::size_t ri = 0; ri < loads.size(); ++ri) {
    const double R = loads[ri];
    double P = -1.0, fp = 0.0, Vp = 0.0, tp = 0.0, Pei = 0.0, Peis = 0.0;
    for (std::size_t fk = 0; fk < f.size(); ++fk) {
      const double fi = f[fk];
      const HarmonicResponse& h = by_frequency[fk][ri];
      const std::complex<double> va = la == Circuit::ground ? 0.0 : h.V[static_cast<std::size_t>(la)];
      const std::complex<double> vb = lb == Circuit::ground ? 0.0 : h.V[static_cast<std::size_t>(lb)];
      const double V = A * std::abs(va - vb), p = A * A * h.power, tip = A * std::abs(h.tip);
      frf.append({R, fi, V, p, tip});
      if (p > P) {
        P = p;
        fp = fi;
        Vp = V;
        tp = tip;
      }
      if (ei09) {
        Pei = std::max(Pei, A * A * ei09->response(tau * fi, R).power);
        Peis = std::max(Peis, A * A * ei09_induced->response(tau * fi, R).power);
      }
    }
    per_load.append({R, fp, P, Vp, tp, ei09 ? Pei : std::nan(""), ei09 ? Peis : std::nan("")});
    if (P > best_P) {
      best_P = P;
      best_R = R;
      best_f = fp;
      best_V = Vp;
    }
    if (ei09 && Pei > best_ei) {
      best_ei = Pei;
      best_ei_R = R;
    }
    if (ei09 && Peis > best_eis) {
      best_eis = Peis;
      best_eis_R = R;
    }
    if (log) {
      char line[200];
      std::snprintf(line, sizeof line, "R = %.4g ohm: P_max %.4e W at %.3f Hz, |V| %.4g V", R, P, fp, Vp);
      log(line);
    }
  }
  CaseSummary o;
  o.put("unknowns", static_cast<double>(beam.unknowns()));
  o.put("f_sc", wsc / tau);
  o.put("f_oc", woc / tau);
  o.put("zeta", zeta);
  o.put("base_acceleration", A);
  o.put("fmin", fmin);
  o.put("fmax", fmax);
  o.put("points", a.points);
  o.put("loads", static_cast<double>(loads.size()));
  o.put("R_opt", best_R);
  o.put("P_max", best_P);
  o.put("f_at_P_max", best_f);
  o.put("V_at_P_max", best_V);
  // With k^2 > 2 zeta the power against R has two maxima of about equal height, one near f_sc (small R) and one
  // near f_oc (large R): R_opt above is the higher on this grid, and these are the two (the local maxima of the
  // per-load peak power, the lowest and the highest R).
  {
    const auto& P = per_load.columns[2];
    std::vector<std::size_t> peaks;
    for (std::size_t i = 0; i < P.size(); ++i)
      if ((i == 0 || P[i] >= P[i - 1]) && (i + 1 == P.size() || P[i] >= P[i + 1])) peaks.push_back(i);
    o.put("power_maxima_over_R", static_cast<double>(peaks.size()));
    if (!peaks.empty()) {
      o.put("R_opt_low", per_load.columns[0][peaks.front()]);
      o.put("P_max_low", P[peaks.front()]);
      o.put("f_at_P_max_low", per_load.columns[1][peaks.front()]);
      o.put("R_opt_high", per_load.columns[0][peaks.back()]);
      o.put("P_max_high", P[peaks.back()]);
      o.put("f_at_P_max_high", per_load.columns[1][peaks.back()]);
    }
  }
  if (ei09) {
    o.put("f_sc_ei09", ei09->omega(0) / tau);
    o.put("f_oc_ei09", ei09->open_circuit_frequency_exact(0) / tau);
    o.put("f_oc_ei09_single_mode", ei09->open_circuit_frequency_single_mode(0) / tau);
    o.put("f_sc_ei09_induced_potential", ei09_induced->omega(0) / tau);
    o.put("f_oc_ei09_induced_potential", ei09_induced->open_circuit_frequency_exact(0) / tau);
    o.put("R_opt_ei09", best_ei_R);
    o.put("P_max_ei09", best_ei);
    o.put("R_opt_ei09_induced_potential", best_eis_R);
    o.put("P_max_ei09_induced_potential", best_eis);
    o.put("R_opt_ei09_closed_form_at_f_sc", ei09_induced->optimal_load(ei09_induced->omega(0)));
  } else {
    o.note("ei09", "none: the beam is not a symmetric series bimorph with a load resistor");
  }
  o.put("wall_seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  return o;
}

}  // namespace polymech::piezo
