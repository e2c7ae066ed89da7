// The square particle lattice of the 2D MPS models: particle (i, j) at ((i + 1/2) l0, (j + 1/2) l0),
// index j * nx + i (x1 fastest), so each particle stands for one l0 x l0 cell of the rectangle; and
// the particles the excitation drives. Host code, free of Kokkos (io/ checks scenes with it).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <vector>

#include "core/index.hpp"
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

// The top-row particles the excitation drives (seed 000 eqs. (22)-(24)): the whole row for the plane
// waves; for the point source, the particles whose cells lie inside [xs - w/2, xs + w/2], so the
// driven width is the same physical width at every resolution (w a multiple of l0), or, when no cell
// fits (w = 0 or w < l0), the particle(s) nearest to xs (both, when xs is between two).
inline std::vector<Index> source_particles(const Config& c, const Lattice& lat) {
  std::vector<Index> src;
  const auto& ex = c.excitation;
  if (ex.kind == ExcitationKind::none) return src;
  const std::int64_t top = lat.ny - 1;
  if (ex.kind != ExcitationKind::point) {
    for (std::int64_t i = 0; i < lat.nx; ++i) src.push_back(lat.index(i, top));
    return src;
  }
  const double xs = ex.position < 0 ? 0.5 * c.width : ex.position;
  const double half = 0.5 * ex.width * (1.0 + 1e-9), l0 = c.spacing;
  double nearest = 1e300;
  for (std::int64_t i = 0; i < lat.nx; ++i) {
    const double d = std::abs(lat.x1(lat.index(i, top)) - xs);
    if (d + 0.5 * l0 <= half) src.push_back(lat.index(i, top));
    nearest = std::min(nearest, d);
  }
  if (src.empty())
    for (std::int64_t i = 0; i < lat.nx; ++i)
      if (std::abs(lat.x1(lat.index(i, top)) - xs) <= nearest + 1e-9 * l0) src.push_back(lat.index(i, top));
  return src;
}

// The source point of the excitation (top row, at the excitation's x1), where the wave-speed
// measurement takes distances from.
struct SourcePoint {
  double x1 = 0.0, x3 = 0.0;
};
inline SourcePoint excitation_source_point(const Config& c) {
  const Lattice lat = make_lattice(c);
  SourcePoint p;
  p.x1 = c.excitation.position < 0 ? 0.5 * c.width : c.excitation.position;
  p.x3 = (static_cast<double>(lat.ny) - 0.5) * c.spacing;  // the top row
  return p;
}

}  // namespace polymech::mps_elastic
