// The finite-element harvester's two reference cases (issue 35), shared by the tests, the benchmarks and the
// sweeps (the app builds the same from its scenes, scenes/piezo/):
//   the PVDF bimorph bender of Hwang & Park (1993): L = 100 mm, width 5 mm, two 0.5 mm layers poled
//   oppositely, the bottom face grounded and the top at 100 V, clamped at x = 0;
//   the duToit & Wardle (2007) harvester of seed 002 paper 1: brass 0.14 mm between two PZT-5A layers 0.27 mm
//   poled oppositely (series), 55 mm long, width 6.4 mm (not in the paper: the choice of models/piezo/analytic.hpp,
//   docs/METHODS.md), the host grounded (eq. (7)) and the outer faces floating electrodes "top" and "bottom".
#pragma once

#include "piezo/beam_model.hpp"
#include "piezo/fe_law.hpp"

namespace polymech::piezo {

inline BeamSpec pvdf_bender_spec(int dim, Plane plane, int order, int cells_length, double volts = 100.0) {
  const Pvdf pv{};
  BeamSpec s;
  s.dim = dim;
  s.plane = plane;
  s.order = order;
  s.length = 0.1;
  s.width = 5e-3;
  s.cells_length = cells_length;
  s.cells_width = 2;
  s.layers = {{"lower", 5e-4, true, 1, 1}, {"upper", 5e-4, true, -1, 1}};
  s.piezo = isotropic_piezo(pv.E, pv.nu, pv.d31, pv.eps_r, pv.rho);
  s.electrodes = {{"ground", "bottom", ElectrodeKind::grounded, 0.0}, {"top", "top", ElectrodeKind::prescribed, volts}};
  return s;
}

inline BeamSpec dutoit_harvester_spec(int order, int cells_length, int cells_per_piezo_layer, int dim = 2,
                                      int cells_width = 1) {
  BeamSpec s;
  s.dim = dim;
  s.plane = Plane::stress;
  s.order = order;
  s.length = 55e-3;
  s.width = 6.4e-3;
  s.cells_length = cells_length;
  s.cells_width = cells_width;
  s.layers = {{"pzt lower", 0.27e-3, true, 1, cells_per_piezo_layer},
              {"brass", 0.14e-3, false, 1, 1},
              {"pzt upper", 0.27e-3, true, -1, cells_per_piezo_layer}};
  s.piezo = pzt5a();
  s.host = brass();
  s.electrodes = {{"bottom", "bottom", ElectrodeKind::floating, 0.0}, {"top", "top", ElectrodeKind::floating, 0.0}};
  return s;
}

// The load resistor between the two outer electrodes of the harvester.
inline Circuit harvester_load(const PiezoBeam& b, double R) {
  Circuit c(b.electrodes());
  c.add_resistor(b.electrode("top"), b.electrode("bottom"), R);
  return c;
}

}  // namespace polymech::piezo
