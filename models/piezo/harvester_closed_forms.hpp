// The closed forms a harvester case is compared against (issue 35; seed 002 paper 1): the laminated bender of
// the static case, and the Erturk-Inman model's bimorph (models/piezo/analytic.hpp, EI09) of a symmetric series
// bimorph for the harmonic case.
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

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "piezo/analytic.hpp"
#include "piezo/harvester_beam.hpp"
#include "piezo/harvester_setup.hpp"

namespace polymech::piezo {

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

}  // namespace polymech::piezo
