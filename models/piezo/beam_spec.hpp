// The description of a finite-element piezoelectric beam (issue 35; seed 002 paper 1 eqs. (4)-(10)): its layers,
// electrodes, support and laws (BeamSpec), the Rayleigh damping of its solves and the record of a harmonic
// response. The beam itself is models/piezo/piezo_beam.hpp (include models/piezo/beam_model.hpp).
//
// Electrodes (eq. (8)) are named surfaces between layers: "bottom", "top", or "interface K" (between layer K
// and K + 1, counted from 1 at the bottom). The paper's equations name them inconsistently (the text joins
// AE and DH through the resistor, eq. (8) puts the second potential on BF, a face of the grounded host); this
// model takes the reading that agrees with eqs. (7), (9) and (10): the host and both inner faces at 0 V, the
// outer faces AE (top) and DH (bottom) each one floating unknown, the resistor between them. docs/METHODS.md
// draws it.
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "piezo/fe_law.hpp"

namespace polymech::piezo {

struct LayerSpec {
  std::string name;
  double thickness = 0.0;   // [m]
  bool piezoelectric = false;
  int poling = 1;           // +1: along +thickness, -1: along -thickness
  int cells = 1;            // cells through the layer's thickness
};

enum class ElectrodeKind { floating, grounded, prescribed };

struct ElectrodeSpec {
  std::string name;
  std::string surface;  // "bottom", "top" or "interface K"
  ElectrodeKind kind = ElectrodeKind::floating;
  double potential = 0.0;  // prescribed: [V] (static solves)
};

enum class Support {
  clamped_root,  // every displacement component at x = 0 fixed (the cantilever)
  free,          // the rigid-body motions removed by point constraints (a free layer)
};

struct BeamSpec {
  int dim = 2;
  Plane plane = Plane::stress;  // 2D only
  int order = 2;
  double length = 0.0, width = 0.0;  // [m]; in 2D the width multiplies every integral
  int cells_length = 40, cells_width = 2;  // cells_width: 3D only
  std::vector<LayerSpec> layers;     // bottom to top
  PiezoCeramic piezo{};              // the law of every piezoelectric layer
  IsotropicElastic host{};           // the law of every elastic layer
  bool conducting_host = true;       // an elastic layer is a grounded conductor (eq. (7))
  Support support = Support::clamped_root;
  std::vector<ElectrodeSpec> electrodes;
};

// Rayleigh damping C = alpha M + beta Kuu on the displacement unknowns.
struct Rayleigh {
  double alpha = 0.0, beta = 0.0;
  // Stiffness-proportional damping ratio zeta at the angular frequency w: beta = 2 zeta / w.
  static Rayleigh stiffness_proportional(double zeta, double w) { return {0.0, 2.0 * zeta / w}; }
};

// The steady response at one frequency to a unit base acceleration amplitude (1 m/s^2 along the thickness).
struct HarmonicResponse {
  double omega = 0.0;
  std::vector<std::complex<double>> V;  // electrode potentials [V]
  std::complex<double> tip;             // tip deflection relative to the base (mean over the tip face) [m]
  double power = 0.0;                   // mean power in the circuit, (1/2) V^H G V [W]
  double power_in = 0.0;                // mean power the base puts in [W]
  double power_damping = 0.0;           // mean power of the damping [W]
};

}  // namespace polymech::piezo
