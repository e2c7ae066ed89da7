// Sums over the family of an interior particle of a regular lattice (host, exact enumeration of the
// lattice offsets within the horizon). They fix the constants that must not depend on where a
// particle sits: beta of the weighted-function method (seed 003 eq. (2)) and the bond-based
// micromodulus that scales the hourglass and short-range forces.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace polymech::nosb_pd {

struct LatticeFamily {
  std::int64_t bonds = 0;
  double plain_volume = 0.0;     // sum_j V (V = h^D)
  double weighted_volume = 0.0;  // sum_j V (1 - |xi|^2 / delta^2)
  double length_weighted = 0.0;  // sum_j W_ij |xi| with the chosen weights (beta included)
};

// Interior family on a lattice of spacing h with horizon m h (bonds with |xi| <= m h, the same
// inclusive rule and tolerance as the model's family search).
inline LatticeFamily lattice_family(int dim, double h, double m, bool weighted, double beta) {
  LatticeFamily s;
  const auto n = static_cast<std::int64_t>(std::floor(m)) + 1;
  const double delta = m * h, r_max = delta * (1.0 + 1e-6);
  const double V = dim == 3 ? h * h * h : h * h;
  const std::int64_t nz = dim == 3 ? n : 0;
  for (std::int64_t c = -nz; c <= nz; ++c)
    for (std::int64_t b = -n; b <= n; ++b)
      for (std::int64_t a = -n; a <= n; ++a) {
        if (a == 0 && b == 0 && c == 0) continue;
        const double r = h * std::sqrt(static_cast<double>(a * a + b * b + c * c));
        if (r > r_max) continue;
        const double shape = std::max(0.0, 1.0 - r * r / (delta * delta));
        ++s.bonds;
        s.plain_volume += V;
        s.weighted_volume += V * shape;
        s.length_weighted += r * (weighted ? beta * V * shape : V);
      }
  return s;
}

// beta of eq. (2): the weighted family of an interior lattice particle has the volume of the plain
// one, sum_j W'_ij = sum_j V_ij ("beta was chosen to reproduce the result of eq. (1) on a simple
// problem", seed 003 §3(1)). In eq. (1) and in the force state a constant beta cancels; it keeps W'
// a volume, so that sums of W' (horizon volume, micromodulus) mean what they mean with V.
inline double weighted_function_beta(int dim, double m) {
  const LatticeFamily s = lattice_family(dim, 1.0, m, false, 1.0);
  return s.weighted_volume > 0 ? s.plain_volume / s.weighted_volume : 1.0;
}

}  // namespace polymech::nosb_pd
