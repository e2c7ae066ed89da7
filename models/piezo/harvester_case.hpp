// A harvester case (issue 35; seed 002 paper 1) from its description (models/piezo/harvester_setup.hpp): the
// finite-element beam, its circuit and damping, and the three analyses apps/piezo_harvester runs, with the
// closed forms each is compared against. No I/O: the results come back as summary values and tables.
//
//   static     the prescribed electrodes at their potentials, no mechanical load: the tip deflection against
//              the laminated bender's closed form (below), as a beam (uniaxial stress, T2 = 0) and as a plate
//              (cylindrical bending, S2 = 0); the charges and capacitances of the prescribed electrodes.
//   harmonic   for each load R and frequency f: the steady load voltage, power and tip amplitude for the base
//              acceleration amplitude A (beam.harmonic, one complex factorisation each); the short- and open-
//              circuit frequencies of the FE beam; per load the sweep's peak power; R_opt and P_max of the sweep;
//              for a symmetric series bimorph the Erturk-Inman distributed-parameter model (analytic.hpp, EI09)
//              on the same grid, with and without the induced-potential stiffening.
//   transient  a_b(t) = A sin(w t) from rest (HarvesterTransient, a model of the run driver models/common/run.hpp:
//              step, save/load for checkpoints); afterwards the steady amplitude and mean power over the last
//              periods against the harmonic solve at the same frequency (transient_summary).
//
// The laminated bender (the closed form of the static case; the classical lamination theory of a beam). Layer k
// occupies z_k < z < z_k+1 with the stiffness Q_k and the free (piezoelectric) strain Lambda_k, uniform through
// it; with eps = eps0 + kappa z the force and moment vanish:
//   sum Q_k [(eps0 - Lambda_k) h_k + kappa S_k] = 0,   sum Q_k [(eps0 - Lambda_k) S_k + kappa I_k] = 0,
//   h_k = z_k+1 - z_k, S_k = (z_k+1^2 - z_k^2)/2, I_k = (z_k+1^3 - z_k^3)/3;   tip deflection w(L) = -kappa L^2 / 2.
// Beam (T2 = T3 = 0): Q = 1/s11^E, Lambda = d31 E3. Plate (S2 = 0, T3 = 0): Q = 1/(s11 - s12^2/s11),
// Lambda = d31 (1 - s12/s11) E3 (isotropic: (1 + nu) d31 E3). The field: a run of piezoelectric layers between
// two surfaces of known potential (a prescribed or grounded electrode, the grounded host) carries one D, so
// E_k = -(V_b - V_a) / (eps_k sum_j t_j / eps_j) (floating electrodes inside the run are charge-free: ignored);
// the strain's own contribution to the field (the induced potential) is left out, as in the textbook bender.
// For two equal layers poled oppositely this is delta = 3 d31 V L^2 / (2 t^2) (series_bimorph_tip_deflection).
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/archive.hpp"
#include "common/run.hpp"
#include "common/state.hpp"
#include "piezo/analytic.hpp"
#include "piezo/beam_model.hpp"
#include "piezo/fe_law.hpp"
#include "piezo/harvester_setup.hpp"
#include "piezo/transient.hpp"

namespace polymech::piezo {

// The piezoelectric law of a material name of harvester_setup.hpp.
inline PiezoCeramic piezo_material(const std::string& name) {
  if (name == "pzt5a") return pzt5a();
  if (name == "pvdf") {
    const Pvdf p{};
    return isotropic_piezo(p.E, p.nu, p.d31, p.eps_r, p.rho);
  }
  throw std::invalid_argument("piezo harvester: no piezoelectric material '" + name + "' (allowed: pzt5a, pvdf)");
}

inline BeamSpec beam_spec(const HarvesterSetup& s) {
  BeamSpec b;
  b.dim = s.dim;
  b.plane = s.plane == "strain" ? Plane::strain : Plane::stress;
  b.order = s.order;
  b.length = s.length;
  b.width = s.width;
  b.cells_length = s.cells_length;
  b.cells_width = s.cells_width;
  for (const auto& l : s.layers) b.layers.push_back({l.name, l.thickness, l.piezoelectric(), l.poling, l.cells});
  const std::string m = s.piezo_material();
  if (!m.empty()) b.piezo = piezo_material(m);
  b.host = brass();
  b.conducting_host = s.conducting_host;
  b.support = s.support == "free" ? Support::free : Support::clamped_root;
  for (const auto& e : s.electrodes) {
    const ElectrodeKind k = e.kind == "grounded" ? ElectrodeKind::grounded
                            : e.kind == "prescribed" ? ElectrodeKind::prescribed
                                                     : ElectrodeKind::floating;
    b.electrodes.push_back({e.name, e.surface, k, e.potential});
  }
  return b;
}

// A circuit terminal: an electrode's index in the beam, or Circuit::ground.
inline int terminal(const PiezoBeam& b, const std::string& name) { return name == "ground" ? Circuit::ground : b.electrode(name); }

// The scene's circuit; load > 0 replaces the first resistor's resistance (the load).
inline Circuit make_circuit(const PiezoBeam& b, const HarvesterSetup& s, double load = 0.0) {
  Circuit c(b.electrodes());
  for (std::size_t k = 0; k < s.resistors.size(); ++k)
    c.add_resistor(terminal(b, s.resistors[k].from), terminal(b, s.resistors[k].to), k == 0 && load > 0 ? load : s.resistors[k].ohm);
  return c;
}

inline Rayleigh damping_of(const HarvesterSetup& s, double w_sc) {
  return s.zeta > 0.0 ? Rayleigh::stiffness_proportional(s.zeta, w_sc) : Rayleigh{s.alpha, s.beta};
}

// Ordered summary values (the app writes them to summary.json in this order) and tables (CSV).
struct CaseSummary {
  std::vector<std::pair<std::string, double>> numbers;
  std::vector<std::pair<std::string, std::string>> texts;
  void put(const std::string& k, double v) { numbers.emplace_back(k, v); }
  void note(const std::string& k, const std::string& v) { texts.emplace_back(k, v); }
  double get(const std::string& k) const {
    for (const auto& [key, v] : numbers)
      if (key == k) return v;
    return std::numeric_limits<double>::quiet_NaN();
  }
};
struct CaseTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  explicit CaseTable(std::vector<std::string> n = {}) : names(std::move(n)), columns(names.size()) {}
  void append(const std::vector<double>& row) {
    for (std::size_t k = 0; k < row.size() && k < columns.size(); ++k) columns[k].push_back(row[k]);
  }
};

// ---- the laminated bender (header comment) ----

struct BenderClosedForm {
  double beam = std::numeric_limits<double>::quiet_NaN();   // uniaxial stress (a narrow beam)
  double plate = std::numeric_limits<double>::quiet_NaN();  // cylindrical bending (a wide plate)
  std::string not_applicable;                              // why there is none ("" when there is)
};

inline BenderClosedForm laminated_bender(const HarvesterSetup& s) {
  BenderClosedForm out;
  const std::size_t nl = s.layers.size();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> V(nl + 1, nan);  // the known surface potentials
  for (const auto& e : s.electrodes) {
    std::size_t k = e.surface == "bottom" ? 0 : e.surface == "top" ? nl : static_cast<std::size_t>(std::stoi(e.surface.substr(10)));
    if (e.kind != "floating") V[k] = e.kind == "prescribed" ? e.potential : 0.0;
  }
  if (s.conducting_host)
    for (std::size_t k = 0; k < nl; ++k)
      if (!s.layers[k].piezoelectric()) V[k] = V[k + 1] = 0.0;
  const PiezoCeramic pz = s.piezo_material().empty() ? pzt5a() : piezo_material(s.piezo_material());
  const IsotropicElastic host = brass();
  std::vector<double> E3(nl, 0.0);  // the field along +z in each piezoelectric layer
  for (std::size_t a = 0; a < nl;) {
    if (!s.layers[a].piezoelectric()) {
      ++a;
      continue;
    }
    std::size_t b = a + 1;  // the run a..b-1 of piezoelectric layers up to the next known potential
    while (b < nl && s.layers[b].piezoelectric() && std::isnan(V[b])) ++b;
    if (std::isnan(V[a]) || std::isnan(V[b])) {
      out.not_applicable = "the faces of layer '" + s.layers[a].name + "' (and the piezoelectric layers joined to it) are not "
                           "both at known potentials (a prescribed or grounded electrode, the grounded host)";
      return out;
    }
    double t = 0.0;
    for (std::size_t k = a; k < b; ++k) t += s.layers[k].thickness;
    for (std::size_t k = a; k < b; ++k) E3[k] = -(V[b] - V[a]) / t;  // one material: equal permittivities
    a = b;
  }
  auto tip = [&](bool plate) {
    double A = 0, B = 0, D = 0, N = 0, M = 0, z = 0;
    for (std::size_t k = 0; k < nl; ++k) {
      const auto& l = s.layers[k];
      const double z1 = z + l.thickness, h = l.thickness, S = 0.5 * (z1 * z1 - z * z), I = (z1 * z1 * z1 - z * z * z) / 3.0;
      double Q, Lam = 0.0;
      if (l.piezoelectric()) {
        Q = plate ? 1.0 / (pz.s11E - pz.s12E * pz.s12E / pz.s11E) : 1.0 / pz.s11E;
        Lam = pz.d31 * (plate ? 1.0 - pz.s12E / pz.s11E : 1.0) * l.poling * E3[k];
      } else {
        Q = plate ? host.E / (1.0 - host.nu * host.nu) : host.E;
      }
      A += Q * h;
      B += Q * S;
      D += Q * I;
      N += Q * Lam * h;
      M += Q * Lam * S;
      z = z1;
    }
    const double kappa = (A * M - B * N) / (A * D - B * B);
    return -0.5 * kappa * s.length * s.length;
  };
  out.beam = tip(false);
  out.plate = tip(true);
  return out;
}

// ---- the Erturk-Inman model of a symmetric series bimorph ----

// The BimorphSpec of the scene's beam when it is a symmetric series bimorph (two equal piezoelectric layers poled
// oppositely, with or without a host between them, the outer faces the electrodes), else none.
inline std::optional<BimorphSpec> bimorph_of(const HarvesterSetup& s, double zeta) {
  const auto& L = s.layers;
  const bool three = L.size() == 3 && L[0].piezoelectric() && !L[1].piezoelectric() && L[2].piezoelectric();
  const bool two = L.size() == 2 && L[0].piezoelectric() && L[1].piezoelectric();
  if (!(three || two) || L.front().thickness != L.back().thickness || L.front().poling != -L.back().poling) return std::nullopt;
  if (s.resistors.empty()) return std::nullopt;
  BimorphSpec b;
  b.L = s.length;
  b.b = s.width;
  b.hp = L.front().thickness;
  b.hs = three ? L[1].thickness : 0.0;
  b.host = brass();
  b.piezo = reduce(piezo_material(s.piezo_material()));
  b.connection = Connection::series;
  b.zeta = {zeta};
  b.modes = 1;
  return b;
}

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
