// The description of a piezoelectric harvester case (issue 35; seed 002 paper 1), as plain values: what a scene
// of scenes/piezo/ holds once io/piezo_scene.cpp has validated it, and what models/piezo/harvester_case.hpp turns
// into the finite-element beam (models/piezo/beam_model.hpp), its circuit and the analysis to run. Plain C++17,
// no Kokkos, so io/ can fill it.
//
//   layers     bottom to top; material "pzt5a" (materials.hpp, Berlincourt), "pvdf" (the Hwang & Park PVDF,
//              Pvdf{} through isotropic_piezo with rho 1780 kg/m^3) or "brass" (the host, elastic); the beam has
//              one piezoelectric law, so every piezoelectric layer is of one material
//   electrodes on "bottom", "top" or "interface K"; floating, grounded or prescribed (a potential, static only)
//   resistors  between two floating electrodes or one and "ground"; the first is the load (the harmonic sweep
//              varies it, the transient reports its voltage)
//   damping    Rayleigh C = alpha M + beta Kuu, or zeta: stiffness-proportional at the short-circuit frequency
//   analysis   static (the prescribed electrodes' potentials, no mechanical load), harmonic (loads x
//              frequencies, unit base acceleration scaled to base_acceleration), transient (a_b = A sin(w t)
//              from rest, Newmark; the monolithic or the partitioned scheme of models/piezo/transient.hpp)
#pragma once

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace polymech::piezo {

struct HarvesterLayer {
  std::string name;
  double thickness = 0.0;  // [m]
  std::string material;    // "pzt5a" | "pvdf" | "brass"
  int poling = 1;          // +1 along +thickness, -1 against (piezoelectric layers)
  int cells = 1;           // cells through the thickness, at the paper's accuracy times the preset
  bool piezoelectric() const { return material != "brass"; }
};

struct HarvesterElectrode {
  std::string name;
  std::string surface;            // "bottom" | "top" | "interface K"
  std::string kind = "floating";  // "floating" | "grounded" | "prescribed"
  double potential = 0.0;         // [V], prescribed only
};

struct HarvesterResistor {
  std::string from, to;  // electrode names or "ground"
  double ohm = 0.0;
};

struct HarvesterAnalysis {
  std::string kind = "static";  // "static" | "harmonic" | "transient"
  double base_acceleration = 9.81;  // [m/s^2], amplitude (harmonic: the responses are scaled to it)
  // harmonic
  std::vector<double> loads;  // [ohm]; empty: the scene's circuit as it is
  int points = 200;           // frequencies, evenly spaced on [fmin, fmax]
  double fmin = 0.0, fmax = 0.0;  // [Hz]; 0: 0.9 f_sc and 1.1 f_oc of the FE model
  // transient
  double frequency = 0.0;     // [Hz]; 0: "resonance", the FE short-circuit frequency
  double periods = 0.0;
  int steps_per_period = 80;
  std::string scheme = "monolithic";  // | "partitioned"
  int average_periods = 2;    // the steady amplitude and the mean power over the last periods
  int sample_every = 1;       // steps between the rows of series.csv
  std::int64_t steps() const { return static_cast<std::int64_t>(periods * steps_per_period + 0.5); }
};

struct HarvesterSetup {
  int dim = 2;
  std::string plane = "stress";  // 2D: "stress" | "strain"
  double length = 0.0, width = 0.0;  // [m]
  std::vector<HarvesterLayer> layers;
  bool conducting_host = true;
  std::string support = "clamped";  // "clamped" (the root) | "free"
  std::vector<HarvesterElectrode> electrodes;
  int order = 2, cells_length = 40, cells_width = 2;  // after the accuracy preset
  std::vector<HarvesterResistor> resistors;
  double zeta = 0.0;                // > 0: stiffness-proportional at the short-circuit frequency
  double alpha = 0.0, beta = 0.0;   // used when zeta = 0
  HarvesterAnalysis analysis;

  // The piezoelectric material of the beam ("" when there is no piezoelectric layer).
  std::string piezo_material() const {
    for (const auto& l : layers)
      if (l.piezoelectric()) return l.material;
    return "";
  }
};

// The unknowns of the finite-element beam in closed form, as beam_model.hpp numbers them (for the cost
// estimate, before anything is allocated): D displacement components per node less the supports', a potential
// per node that touches a piezoelectric element, is not in or on the grounded host and not on an electrode, and
// one per floating or prescribed electrode.
inline double harvester_unknowns(const HarvesterSetup& s) {
  const int p = s.order, nl = static_cast<int>(s.layers.size());
  std::vector<int> start(1, 0);  // the node plane of each layer boundary
  for (const auto& l : s.layers) start.push_back(start.back() + p * l.cells);
  const double per_plane = (p * static_cast<double>(s.cells_length) + 1) * (s.dim == 3 ? p * static_cast<double>(s.cells_width) + 1 : 1.0);
  const double nt = start.back() + 1.0;
  const double root = per_plane / (p * static_cast<double>(s.cells_length) + 1);  // nodes at x = 0
  double n = s.support == "free" ? s.dim * (per_plane * nt) - (s.dim == 3 ? 6.0 : 3.0) : s.dim * (per_plane - root) * nt;
  for (int j = 0; j < start.back() + 1; ++j) {
    bool piezo = false, host = false, electrode = false;
    for (int k = 0; k < nl; ++k)
      if (j >= start[static_cast<std::size_t>(k)] && j <= start[static_cast<std::size_t>(k) + 1])
        (s.layers[static_cast<std::size_t>(k)].piezoelectric() ? piezo : host) = true;
    for (const auto& e : s.electrodes) {
      const int k = e.surface == "bottom" ? 0 : e.surface == "top" ? nl : std::atoi(e.surface.c_str() + 10);
      electrode = electrode || (k >= 0 && k <= nl && start[static_cast<std::size_t>(k)] == j);
    }
    if (piezo && !(s.conducting_host && host) && !electrode) n += per_plane;
  }
  for (const auto& e : s.electrodes) n += e.kind != "grounded";
  return n;
}

}  // namespace polymech::piezo
