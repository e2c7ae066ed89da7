// The bonds a straight crack cuts on the MPS lattice (seed 000 §4, Fig. 1), found once from the lattice
// around the crack: the scene loader checks them (a crack must cut bonds, contact needs pairs) and the
// model builds its cut family, contact pairs and crack-line monitor from them. Host code, free of
// Kokkos.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "contact/crack_geometry.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/lattice.hpp"

namespace polymech::mps_elastic {

// One bond across the crack, from its S+ end to its S- end; (dx, dy) = x_lower - x_upper.
struct CrackCrossing {
  Index upper = 0, lower = 0;
  double dx = 0.0, dy = 0.0;
};

inline contact::CrackSegment crack_segment(const CrackConfig& k) {
  return contact::CrackSegment::make(k.x1, k.x3, k.length, k.angle);
}

// Every lattice bond within r_e (the family's radius) that the crack cuts, once each, ordered by the
// upper particle's index, then the lower's. Coordinates are rounded to T as the model stores them, so
// the model and the loader cut the same bonds in either precision.
template <class T>
std::vector<CrackCrossing> crack_crossings(const Config& c) {
  std::vector<CrackCrossing> out;
  if (c.crack.mode == CrackMode::none) return out;
  const Lattice lat = make_lattice(c);
  const auto seg = crack_segment(c.crack);
  const double re = c.re(), l0 = c.spacing, reach = seg.half_length + re, r_max = re * (1 + 1e-6);
  const auto m = static_cast<std::int64_t>(re / l0) + 1;
  auto cell = [&](double x, std::int64_t n) { return std::clamp<std::int64_t>(static_cast<std::int64_t>(x / l0), 0, n - 1); };
  auto coord = [](double x) { return static_cast<double>(static_cast<T>(x)); };
  for (std::int64_t j = cell(c.crack.x3 - reach, lat.ny); j <= cell(c.crack.x3 + reach, lat.ny); ++j)
    for (std::int64_t i = cell(c.crack.x1 - reach, lat.nx); i <= cell(c.crack.x1 + reach, lat.nx); ++i) {
      const Index a = lat.index(i, j);
      const double xa = coord(lat.x1(a)), ya = coord(lat.x3(a));
      if (!seg.upper(xa, ya)) continue;
      for (std::int64_t bj = -m; bj <= m; ++bj)
        for (std::int64_t bi = -m; bi <= m; ++bi) {
          if (i + bi < 0 || i + bi >= lat.nx || j + bj < 0 || j + bj >= lat.ny) continue;
          const double r = l0 * std::hypot(static_cast<double>(bi), static_cast<double>(bj));
          if (r == 0.0 || r > r_max) continue;
          const Index b = lat.index(i + bi, j + bj);
          const double xb = coord(lat.x1(b)), yb = coord(lat.x3(b));
          if (seg.cuts(xa, ya, xb, yb)) out.push_back({a, b, xb - xa, yb - ya});
        }
    }
  std::sort(out.begin(), out.end(), [](const CrackCrossing& p, const CrackCrossing& q) {
    return p.upper != q.upper ? p.upper < q.upper : p.lower < q.lower;
  });
  return out;
}

// The crossings short enough to be contact pairs (cut bonds up to contact_radius spacings long).
inline bool is_contact_pair(const CrackCrossing& x, const Config& c) {
  return x.dx * x.dx + x.dy * x.dy <= c.crack.contact_radius * c.spacing * c.crack.contact_radius * c.spacing;
}

}  // namespace polymech::mps_elastic
