// Structured meshes of the solid model (issue 34): a logically Cartesian lattice of (n_0 + 1) x ... vertices
// in D = 2 or 3 dimensions, each cell a quadrilateral or hexahedron whose map is the multilinear
// interpolation of its 2^D vertices (so the isoparametric element of any order represents it exactly and the
// patch test holds with Q = N Gauss points: the integrand det J dN/dx of a multilinear map is a polynomial the
// rule integrates exactly). The sides are named xmin, xmax, ymin, ymax (zmin, zmax) after the lattice
// directions. Generators: a box or rectangle, with an optional random or smooth interior distortion; Cook's
// membrane; a slender cantilever (a box).
//
// Active-cell mask: a lattice may leave cells out (`active`, one flag per cell; empty = every cell active), so
// one lattice holds a non-convex body such as a beam standing out of its support block
// (models/solid/micro_cantilever.hpp). The discretization makes elements of active cells only and keeps the
// nodes they touch (models/solid/discretization.hpp); the lattice's sides stay the named boundaries, each the
// faces of active cells that lie on it. Graded lattice planes (`graded_planes`) put fine cells where the
// stresses concentrate.
//
// Closed and curved bodies (issue 37's tyre): a lattice direction may be periodic (`periodic[d]`: its last
// vertex plane is the first one again, the lattice closes on itself and that direction has no sides; at least
// three cells), and an optional `map` sends the multilinear position to the body (the vertices are then in the
// parameter space: an annulus is the rectangle [0, 2 pi] x [r_in, r_out] mapped by polar coordinates). Every node,
// the GLL nodes inside the cells included, is placed by the map, so an order-p element represents the curved
// boundary to O(h^(p+1)) (isoparametric) and not as a polygon.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/hash.hpp"

namespace polymech::solid {

// The map of a mapped lattice: parameter point xi (D values) -> body point x (D values).
using MeshMap = std::function<void(const double* xi, double* x)>;

template <int D>
struct StructuredMesh {
  std::array<int, D> cells{};      // cells per lattice direction
  std::vector<double> vertices;    // vertex_count x D, lattice order (direction 0 fastest); parameter space if map
  std::vector<char> active;        // cell_count flags in lattice order (non-zero: active); empty: every cell
  std::array<bool, D> periodic{};  // closed directions: the last vertex plane is the first one again
  MeshMap map;                     // empty: the vertices are the body's points

  std::int64_t vertex_count() const {
    std::int64_t n = 1;
    for (int d = 0; d < D; ++d) n *= cells[d] + 1;
    return n;
  }
  std::int64_t cell_count() const {
    std::int64_t n = 1;
    for (int d = 0; d < D; ++d) n *= cells[d];
    return n;
  }
  std::int64_t vertex(const std::array<int, D>& i) const {
    std::int64_t v = 0;
    for (int d = D - 1; d >= 0; --d) v = v * (cells[d] + 1) + i[d];
    return v;
  }
  std::int64_t cell(const std::array<int, D>& c) const {
    std::int64_t v = 0;
    for (int d = D - 1; d >= 0; --d) v = v * cells[d] + c[d];
    return v;
  }
  bool masked() const { return !active.empty(); }
  bool is_active(std::int64_t c) const { return active.empty() || active[static_cast<std::size_t>(c)] != 0; }
  std::int64_t active_cell_count() const {
    if (active.empty()) return cell_count();
    std::int64_t n = 0;
    for (const char a : active) n += a != 0;
    return n;
  }
};

// Lattice planes from a to b (either order) whose cells start at `first` next to a and grow by `ratio` per
// cell up to `largest`: the fewest cells that reach b, every size then scaled by one factor <= 1 so that the
// last plane is b exactly (so the first cell is at most `first`). Returns the n + 1 plane positions, a first.
inline std::vector<double> graded_planes(double a, double b, double first, double ratio, double largest) {
  const double length = std::abs(b - a);
  if (!(length > 0) || !(first > 0) || !(ratio >= 1.0) || !(largest >= first))
    throw std::invalid_argument("graded planes: need a != b, first > 0, ratio >= 1, largest >= first");
  std::vector<double> sizes;
  double sum = 0.0, h = first;
  while (sum < length * (1.0 - 1e-12)) {
    sizes.push_back(h);
    sum += h;
    h = std::min(h * ratio, largest);
  }
  const double scale = length / sum, sign = b > a ? 1.0 : -1.0;
  std::vector<double> x{a};
  double acc = 0.0;
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    acc += sizes[k] * scale;
    x.push_back(k + 1 == sizes.size() ? b : a + sign * acc);
  }
  return x;
}

// The tensor-product lattice of the given plane positions per direction (every cell a box).
template <int D>
StructuredMesh<D> make_tensor_box(const std::array<std::vector<double>, D>& planes) {
  StructuredMesh<D> m;
  for (int d = 0; d < D; ++d) {
    if (planes[d].size() < 2) throw std::invalid_argument("solid tensor box: at least two planes per direction");
    m.cells[d] = static_cast<int>(planes[d].size()) - 1;
  }
  m.vertices.resize(static_cast<std::size_t>(m.vertex_count()) * D);
  for (std::int64_t v = 0; v < m.vertex_count(); ++v) {
    std::int64_t r = v;
    for (int d = 0; d < D; ++d) {
      m.vertices[static_cast<std::size_t>(D * v + d)] = planes[d][static_cast<std::size_t>(r % (m.cells[d] + 1))];
      r /= m.cells[d] + 1;
    }
  }
  return m;
}

// Side name -> (lattice direction, 0 for the low side or 1 for the high one); -1 if unknown.
template <int D>
inline std::array<int, 2> side_of(const std::string& name) {
  static const char* names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (int s = 0; s < 2 * D; ++s)
    if (name == names[s]) return {s / 2, s % 2};
  return {-1, -1};
}

enum class Distortion {
  none,    // the affine lattice
  random,  // every interior vertex moved by up to `amplitude` cell sizes per direction (reproducible)
  smooth,  // interior vertices moved by amplitude h sin(pi s_0) ... (a smooth curvilinear lattice)
};

struct BoxSpec {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> lengths{1.0, 1.0, 1.0};
  std::array<int, 3> cells{4, 4, 4};
  Distortion distortion = Distortion::none;
  double amplitude = 0.0;  // in cell sizes; < 0.5 keeps random cells valid, the model checks det J
  std::uint32_t seed = 1;
};

namespace detail {
inline double lattice_hash(std::uint32_t x) { return hash_symmetric(x); }  // in [-1, 1] (kernels/core/hash.hpp)
}  // namespace detail

// The box [origin, origin + lengths] in D dimensions (the first D entries of the spec).
template <int D>
StructuredMesh<D> make_box(const BoxSpec& s) {
  StructuredMesh<D> m;
  for (int d = 0; d < D; ++d) {
    if (s.cells[d] < 1) throw std::invalid_argument("solid box: cell counts must be >= 1");
    if (!(s.lengths[d] > 0)) throw std::invalid_argument("solid box: lengths must be > 0");
    m.cells[d] = s.cells[d];
  }
  m.vertices.resize(static_cast<std::size_t>(m.vertex_count()) * D);
  const double pi = 3.14159265358979323846;
  for (std::int64_t v = 0; v < m.vertex_count(); ++v) {
    std::array<int, D> i;
    std::int64_t r = v;
    for (int d = 0; d < D; ++d) {
      i[d] = static_cast<int>(r % (m.cells[d] + 1));
      r /= m.cells[d] + 1;
    }
    bool interior = true;
    double bump = 1.0;  // prod_d sin(pi s_d): zero on the boundary
    for (int d = 0; d < D; ++d) {
      interior = interior && i[d] > 0 && i[d] < m.cells[d];
      bump *= std::sin(pi * i[d] / m.cells[d]);
    }
    for (int d = 0; d < D; ++d) {
      const double h = s.lengths[d] / m.cells[d];
      double x = s.origin[d] + h * i[d];
      if (interior && s.distortion == Distortion::random)
        x += s.amplitude * h * detail::lattice_hash(static_cast<std::uint32_t>(D * v + d) * 2654435761u + s.seed);
      if (s.distortion == Distortion::smooth)  // each direction displaced along another's sine
        x += s.amplitude * h * bump * std::cos(pi * i[(d + 1) % D] / m.cells[(d + 1) % D]);
      m.vertices[static_cast<std::size_t>(D * v + d)] = x;
    }
  }
  return m;
}

// Cook's membrane (Cook 1974): the quadrilateral (0, 0), (48, 44), (48, 60), (0, 44) as the bilinear image
// of the unit square, n x n cells; xmin is the clamped edge, xmax the loaded one.
inline StructuredMesh<2> make_cook_membrane(int n) {
  if (n < 1) throw std::invalid_argument("cook membrane: n must be >= 1");
  StructuredMesh<2> m;
  m.cells = {n, n};
  m.vertices.resize(static_cast<std::size_t>(m.vertex_count()) * 2);
  const double P[4][2] = {{0, 0}, {48, 44}, {48, 60}, {0, 44}};
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double s = static_cast<double>(i) / n, t = static_cast<double>(j) / n;
      const double w[4] = {(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t};
      for (int d = 0; d < 2; ++d)
        m.vertices[static_cast<std::size_t>(2 * m.vertex({i, j}) + d)] =
            w[0] * P[0][d] + w[1] * P[1][d] + w[2] * P[2][d] + w[3] * P[3][d];
    }
  return m;
}

// A ring (2D) r_in <= r <= r_out: n_theta cells round (direction 0, periodic: no xmin / xmax) and n_r through
// the wall (direction 1: ymin is the inner surface, ymax the outer one), centred at the origin; the lattice in
// (theta, r) with the polar map, so every node lies on its circle. theta runs clockwise (x = r cos theta,
// y = -r sin theta): with r as the second direction that keeps det J > 0.
inline StructuredMesh<2> make_ring(double r_in, double r_out, int n_theta, int n_r) {
  if (!(r_in > 0.0) || !(r_out > r_in)) throw std::invalid_argument("solid ring: need 0 < r_in < r_out");
  if (n_theta < 3 || n_r < 1) throw std::invalid_argument("solid ring: need n_theta >= 3 and n_r >= 1");
  const double two_pi = 6.28318530717958647692;
  std::vector<double> theta(static_cast<std::size_t>(n_theta) + 1), r(static_cast<std::size_t>(n_r) + 1);
  for (int i = 0; i <= n_theta; ++i) theta[static_cast<std::size_t>(i)] = two_pi * i / n_theta;
  for (int j = 0; j <= n_r; ++j) r[static_cast<std::size_t>(j)] = r_in + (r_out - r_in) * j / n_r;
  StructuredMesh<2> m = make_tensor_box<2>({theta, r});
  m.periodic = {true, false};
  m.map = [](const double* xi, double* x) {
    x[0] = xi[1] * std::cos(xi[0]);
    x[1] = -xi[1] * std::sin(xi[0]);
  };
  return m;
}

}  // namespace polymech::solid
