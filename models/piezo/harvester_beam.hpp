// A harvester case's finite-element parts from its description (issue 35; seed 002 paper 1;
// models/piezo/harvester_setup.hpp): the piezoelectric law of a material name, the beam's spec, the circuit
// (its terminals by electrode name) and the Rayleigh damping; and the ordered summary values and tables the
// case's analyses return (the app writes them to summary.json and CSV). No I/O.
#pragma once

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "piezo/analytic.hpp"
#include "piezo/beam_model.hpp"
#include "piezo/fe_law.hpp"
#include "piezo/harvester_setup.hpp"

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

}  // namespace polymech::piezo
