// Particle layouts of the NOSB model (host, once per run): positions and volumes on a regular
// lattice, a jittered lattice, or rings conforming to a cylinder (seed 003 Fig. 2: a curved surface
// is staircase-shaped on a lattice and smooth on the unstructured layout). Particles are put in
// Morton (Z-curve) order of their positions so that a family's neighbours are close in memory.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "nosb_pd/config.hpp"

namespace polymech::nosb_pd {

struct Particles {
  int dim = 3;
  std::vector<double> x;       // n x dim
  std::vector<double> volume;  // n
  std::size_t size() const { return volume.size(); }
  double coord(std::size_t i, int k) const { return x[i * static_cast<std::size_t>(dim) + static_cast<std::size_t>(k)]; }
};

namespace detail {

inline constexpr double kPi = 3.14159265358979323846;

inline double hash_uniform(std::uint64_t key) {  // splitmix64 -> [-1, 1)
  key += 0x9e3779b97f4a7c15ULL;
  key = (key ^ (key >> 30)) * 0xbf58476d1ce4e5b9ULL;
  key = (key ^ (key >> 27)) * 0x94d049bb133111ebULL;
  key ^= key >> 31;
  return static_cast<double>(key >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

inline std::int64_t cells(double extent, double h) { return std::max<std::int64_t>(1, std::llround(extent / h)); }

// Points of a disc of radius R in a plane (2 coordinates), lattice or rings, with their areas.
struct PlanarPoint {
  double a, b, area;
};
inline std::vector<PlanarPoint> disc_points(double R, double h, Layout layout) {
  std::vector<PlanarPoint> p;
  if (layout == Layout::cylindrical) {
    const std::int64_t rings = cells(R, h);
    const double hr = R / static_cast<double>(rings);
    for (std::int64_t k = 0; k < rings; ++k) {
      const double r = (static_cast<double>(k) + 0.5) * hr;
      const auto n = std::max<std::int64_t>(3, std::llround(2.0 * kPi * r / h));
      const double area = kPi * ((r + 0.5 * hr) * (r + 0.5 * hr) - (r - 0.5 * hr) * (r - 0.5 * hr)) / static_cast<double>(n);
      const double shift = (k % 2) ? 0.5 : 0.0;  // stagger neighbouring rings
      for (std::int64_t q = 0; q < n; ++q) {
        const double t = 2.0 * kPi * (static_cast<double>(q) + shift) / static_cast<double>(n);
        p.push_back({r * std::cos(t), r * std::sin(t), area});
      }
    }
    return p;
  }
  const std::int64_t n = cells(R, h);
  for (std::int64_t j = -n; j < n; ++j)
    for (std::int64_t i = -n; i < n; ++i) {
      const double a = (static_cast<double>(i) + 0.5) * h, b = (static_cast<double>(j) + 0.5) * h;
      if (a * a + b * b <= R * R) p.push_back({a, b, h * h});
    }
  return p;
}

inline std::uint64_t spread_bits(std::uint64_t v, int dim) {
  std::uint64_t r = 0;
  const int bits = dim == 3 ? 21 : 32;
  for (int b = 0; b < bits; ++b) r |= ((v >> b) & 1ULL) << (b * dim);
  return r;
}

}  // namespace detail

// Sorts the particles along a Morton curve over cells of one spacing.
inline void morton_order(Particles& p, double h) {
  const std::size_t n = p.size();
  if (n == 0) return;
  std::vector<double> lo(static_cast<std::size_t>(p.dim), 1e300);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < p.dim; ++k) lo[static_cast<std::size_t>(k)] = std::min(lo[static_cast<std::size_t>(k)], p.coord(i, k));
  std::vector<std::uint64_t> code(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t c = 0;
    for (int k = 0; k < p.dim; ++k) {
      const auto q = static_cast<std::uint64_t>(std::max(0.0, std::floor((p.coord(i, k) - lo[static_cast<std::size_t>(k)]) / h)));
      c |= detail::spread_bits(q, p.dim) << k;
    }
    code[i] = c;
  }
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return code[a] < code[b]; });
  Particles s;
  s.dim = p.dim;
  s.x.reserve(p.x.size());
  s.volume.reserve(n);
  for (std::size_t i : order) {
    for (int k = 0; k < p.dim; ++k) s.x.push_back(p.coord(i, k));
    s.volume.push_back(p.volume[i]);
  }
  p = std::move(s);
}

// The particles of a configuration (validated by the model: shape and layout must fit the dimension).
inline Particles generate_particles(const Config& c) {
  const Geometry& g = c.geometry;
  const double h = c.spacing;
  const int D = c.dimension;
  Particles p;
  p.dim = D;
  auto add = [&](std::initializer_list<double> xs, double vol) {
    for (double v : xs) p.x.push_back(v);
    p.volume.push_back(vol);
  };
  switch (g.shape) {
    case Shape::box: {
      const auto nx = detail::cells(g.length, h), ny = detail::cells(D == 3 ? g.width : g.height, h),
                 nz = D == 3 ? detail::cells(g.height, h) : 1;
      for (std::int64_t k = 0; k < nz; ++k)
        for (std::int64_t j = 0; j < ny; ++j)
          for (std::int64_t i = 0; i < nx; ++i) {
            const double a = (i + 0.5) * h, b = (j + 0.5) * h, cc = (k + 0.5) * h;
            if (D == 3) add({a, b, cc}, h * h * h);
            else add({a, b}, h * h);
          }
      break;
    }
    case Shape::disc: {
      const auto nz = detail::cells(g.thickness, h);
      const double hz = g.thickness / static_cast<double>(nz);
      if (D == 2) {
        const auto nx = detail::cells(2.0 * g.radius, h);
        const double hx = 2.0 * g.radius / static_cast<double>(nx);
        for (std::int64_t k = 0; k < nz; ++k)
          for (std::int64_t i = 0; i < nx; ++i) add({-g.radius + (i + 0.5) * hx, -g.thickness + (k + 0.5) * hz}, hx * hz);
        break;
      }
      const auto plane = detail::disc_points(g.radius, h, g.layout);
      for (std::int64_t k = 0; k < nz; ++k)
        for (const auto& q : plane) add({q.a, q.b, -g.thickness + (k + 0.5) * hz}, q.area * hz);
      break;
    }
    case Shape::round_bar: {
      const auto nx = detail::cells(g.length, h);
      const double hx = g.length / static_cast<double>(nx);
      const auto section = detail::disc_points(g.radius, h, g.layout);
      for (std::int64_t i = 0; i < nx; ++i)
        for (const auto& q : section) add({(i + 0.5) * hx, q.a, q.b}, q.area * hx);
      break;
    }
  }
  if (g.layout == Layout::jittered) {
    const double amp = g.jitter * h;
    for (std::size_t i = 0; i < p.x.size(); ++i) p.x[i] += amp * detail::hash_uniform(g.seed * 0x100000001b3ULL + i);
  }
  morton_order(p, h);
  return p;
}

}  // namespace polymech::nosb_pd
