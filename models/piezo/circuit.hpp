// The external circuit of the piezoelectric harvester (issue 35; seed 002 paper 1 eqs. (9)-(10)), as an
// object: branches between electrodes (or an electrode and ground) that the coupled solvers read through
// their linear admittance. Now: resistors. A capacitor would add a term i w C (harmonic) or C dV/dt (time
// domain) to the same electrode rows; a rectifier makes the circuit nonlinear and needs the partitioned loop.
//
// Conventions. Electrode k has the potential V_k and the charge Q_k (models/piezo/assembly.hpp: minus the sum
// of its nodes' electrical rows). A branch between a and b carries the current I = (V_a - V_b) / R from a to
// b, so charge conservation (eq. (10)) reads dQ_a/dt = -I, dQ_b/dt = +I, and for all branches together
//   dQ/dt = -G V,   G = sum over branches of (1/R) (e_a - e_b)(e_a - e_b)^T     (e_ground = 0).
// Paper 1 eq. (9) writes I = (phi2 - phi1) / R with I = dQ1/dt: the same law with the current counted the
// other way round.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymech::piezo {

class Circuit {
 public:
  static constexpr int ground = -1;
  struct Resistor {
    int a = ground, b = ground;
    double R = 0.0;  // [ohm]
  };

  Circuit() = default;
  explicit Circuit(int electrodes) : electrodes_(electrodes) {}

  int electrodes() const { return electrodes_; }
  const std::vector<Resistor>& resistors() const { return resistors_; }

  // A resistor between electrodes a and b (Circuit::ground for the ground). R must be positive and finite:
  // an open circuit has no branch, a short circuit is a grounded electrode.
  Circuit& add_resistor(int a, int b, double R) {
    if (!(R > 0.0) || !std::isfinite(R))
      throw std::invalid_argument("circuit: a resistance must be positive and finite, got " + std::to_string(R) +
                                  " ohm (an open circuit has no resistor; a short circuit grounds the electrode)");
    for (const int k : {a, b})
      if (k != ground && (k < 0 || k >= electrodes_))
        throw std::invalid_argument("circuit: electrode " + std::to_string(k) + " does not exist (" +
                                    std::to_string(electrodes_) + " electrodes)");
    if (a == b) throw std::invalid_argument("circuit: a resistor needs two different terminals");
    resistors_.push_back({a, b, R});
    return *this;
  }

  // The conductance matrix G (electrodes x electrodes, row-major): dQ/dt = -G V.
  std::vector<double> conductance() const {
    const int n = electrodes_;
    std::vector<double> G(static_cast<std::size_t>(n) * n, 0.0);
    for (const auto& r : resistors_) {
      const double g = 1.0 / r.R;
      if (r.a != ground) G[static_cast<std::size_t>(r.a) * n + r.a] += g;
      if (r.b != ground) G[static_cast<std::size_t>(r.b) * n + r.b] += g;
      if (r.a != ground && r.b != ground) {
        G[static_cast<std::size_t>(r.a) * n + r.b] -= g;
        G[static_cast<std::size_t>(r.b) * n + r.a] -= g;
      }
    }
    return G;
  }

  // The power dissipated in the circuit at the electrode potentials V: V^T G V [W].
  template <class Vec>
  double power(const Vec& V) const {
    double p = 0.0;
    for (const auto& r : resistors_) {
      const double va = r.a == ground ? 0.0 : V[static_cast<std::size_t>(r.a)];
      const double vb = r.b == ground ? 0.0 : V[static_cast<std::size_t>(r.b)];
      p += (va - vb) * (va - vb) / r.R;
    }
    return p;
  }

 private:
  int electrodes_ = 0;
  std::vector<Resistor> resistors_;
};

}  // namespace polymech::piezo
