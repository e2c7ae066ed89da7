// The square particle lattice of the 2D MPS models: particle (i, j) at ((i + 1/2) l0, (j + 1/2) l0),
// index j * nx + i (x1 fastest), so each particle stands for one l0 x l0 cell of the rectangle.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "core/types.hpp"
#include "mps_elastic/config.hpp"

namespace polymech::mps_elastic {

struct Lattice {
  std::int64_t nx = 0, ny = 0;
  double spacing = 0.0;

  Index count() const { return static_cast<Index>(nx * ny); }
  Index index(std::int64_t i, std::int64_t j) const { return static_cast<Index>(j * nx + i); }
  double x1(Index id) const { return (static_cast<double>(id % nx) + 0.5) * spacing; }
  double x3(Index id) const { return (static_cast<double>(id / nx) + 0.5) * spacing; }
};

// Cells per direction: width / l0 rounded to the nearest integer (at least 1).
inline Lattice make_lattice(const Config& c) {
  Lattice l;
  l.spacing = c.spacing;
  l.nx = std::max<std::int64_t>(1, std::llround(c.width / c.spacing));
  l.ny = std::max<std::int64_t>(1, std::llround(c.height / c.spacing));
  return l;
}

// Mean over all particles of the number density (seed 000 eq. (2)) on the lattice, from the pair
// counts per lattice offset: offset (a, b) occurs (nx - |a|)(ny - |b|) times.
inline double lattice_mean_number_density(const Lattice& l, double re) {
  const auto m = static_cast<std::int64_t>(re / l.spacing) + 1;
  double sum = 0.0;
  for (std::int64_t b = -m; b <= m; ++b)
    for (std::int64_t a = -m; a <= m; ++a) {
      if ((a == 0 && b == 0) || std::llabs(a) >= l.nx || std::llabs(b) >= l.ny) continue;
      const double r = l.spacing * std::sqrt(static_cast<double>(a * a + b * b));
      if (r > re) continue;
      sum += (re / r - 1.0) * static_cast<double>((l.nx - std::llabs(a)) * (l.ny - std::llabs(b)));
    }
  return sum / static_cast<double>(l.nx * l.ny);
}

}  // namespace polymech::mps_elastic
