// Block-structured meshes of biquadratic (Q2, nine-node) quadrilaterals for the incompressible flow model
// (issue 36), host data free of Kokkos. A mesh is made of blocks, each the transfinite (Coons) image of the
// unit square bounded by four edge curves (straight segments or circular arcs); the Q2 nodes of every cell,
// mid-edge and centre nodes included, are images of the cell's parameter midpoints, so a node on an arc lies
// on the circle and the isoparametric Q2 map carries the curved boundary to third order. Blocks are joined by
// merging coincident nodes (shared edges must have the same cell count and parameter spacing).
//
// Node order within an element: a = i + 3 j (i along the element's first reference direction, j along the
// second; i, j = 0, 1, 2 at the Gauss-Lobatto nodes -1, 0, 1), as fem::tensor_point numbers them; the
// corners a = 0, 2, 6, 8 carry the bilinear pressure. Each element is counter-clockwise (det J > 0).
//
// Generators: a rectangle (optionally with a smooth interior distortion) and the Turek-Hron channel
// (Turek & Hron 2006: channel 2.5 x 0.41, cylinder radius 0.05 at (0.2, 0.2), a flag 0.35 x 0.02 behind it
// with its right end at x = 0.6, 0.19 <= y <= 0.21), each with refinement levels (every cell count x 2^level).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

namespace polymech::flow {

// Boundary tags, one bit each (a node may carry several: a corner of the inflow and a wall).
enum BoundaryTag : unsigned {
  kInflow = 1u,    // x = x_min: prescribed velocity
  kWall = 2u,      // the channel walls: no slip
  kObstacle = 4u,  // the cylinder and the flag: no slip; the force integral's support
  kOutflow = 8u,   // x = x_max: do nothing (natural)
};

struct QuadMesh {
  std::vector<double> x;               // node_count x 2
  std::vector<std::int64_t> elements;  // element_count x 9, a = i + 3 j
  std::vector<unsigned> tags;          // per node: BoundaryTag bits (0 inside)
  std::int64_t node_count() const { return static_cast<std::int64_t>(x.size() / 2); }
  std::int64_t element_count() const { return static_cast<std::int64_t>(elements.size() / 9); }
};

// An edge curve C(s), s in [0, 1]: a segment P0 -> P1, or an arc about `centre` of `radius` from angle a0 to a1.
struct Curve {
  bool arc = false;
  std::array<double, 2> p0{}, p1{};
  std::array<double, 2> centre{};
  double radius = 0.0, a0 = 0.0, a1 = 0.0;
  unsigned tag = 0;  // boundary tag of the nodes on it (0: interior edge)
  std::array<double, 2> at(double s) const {
    if (!arc) return {p0[0] + s * (p1[0] - p0[0]), p0[1] + s * (p1[1] - p0[1])};
    const double a = a0 + s * (a1 - a0);
    return {centre[0] + radius * std::cos(a), centre[1] + radius * std::sin(a)};
  }
};
inline Curve segment(std::array<double, 2> a, std::array<double, 2> b, unsigned tag = 0) {
  Curve c;
  c.p0 = a;
  c.p1 = b;
  c.tag = tag;
  return c;
}
inline Curve arc(std::array<double, 2> centre, double radius, double a0, double a1, unsigned tag = 0) {
  Curve c;
  c.arc = true;
  c.centre = centre;
  c.radius = radius;
  c.a0 = a0;
  c.a1 = a1;
  c.p0 = c.at(0.0);
  c.p1 = c.at(1.0);
  c.tag = tag;
  return c;
}

// A block: bottom C_b(s) and top C_t(s) run in s, left C_l(t) and right C_r(t) in t; the corners must agree
// (C_b(0) = C_l(0), C_b(1) = C_r(0), C_t(0) = C_l(1), C_t(1) = C_r(1)). s_planes, t_planes: the cell
// boundaries in parameter space (n + 1 increasing values from 0 to 1).
struct Block {
  Curve bottom, top, left, right;
  std::vector<double> s_planes, t_planes;
};

// The axis-parallel block [xa, xb] x [ya, yb]: s along x (s_planes), t along y (t_planes), its sides tagged (bottom,
// top, left, right: BoundaryTag bits, 0 inside); the rectangular blocks of the channel meshes.
inline Block rect_block(double xa, double xb, double ya, double yb, const std::vector<double>& s_planes,
                        const std::vector<double>& t_planes, unsigned bottom, unsigned top, unsigned left, unsigned right) {
  Block b;
  b.bottom = segment({xa, ya}, {xb, ya}, bottom);
  b.top = segment({xa, yb}, {xb, yb}, top);
  b.left = segment({xa, ya}, {xa, yb}, left);
  b.right = segment({xb, ya}, {xb, yb}, right);
  b.s_planes = s_planes;
  b.t_planes = t_planes;
  return b;
}

inline std::vector<double> uniform_planes(int n) {
  std::vector<double> p(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) p[static_cast<std::size_t>(k)] = static_cast<double>(k) / n;
  return p;
}
// n cells of the fixed map t -> (exp(a t) - 1) / (exp(a) - 1) of uniform planes: fine at 0, coarse at 1 (the last
// cell exp(a) times the first's size in the limit), the same map at every n (a mesh family that refines uniformly).
inline std::vector<double> graded_planes(int n, double a) {
  std::vector<double> p = uniform_planes(n);
  if (!(a > 0.0)) return p;
  for (int k = 1; k < n; ++k) p[static_cast<std::size_t>(k)] = std::expm1(a * k / n) / std::expm1(a);
  return p;
}
// n cells growing geometrically from the first (a fraction `first` of the length) to the end.
inline std::vector<double> geometric_planes(int n, double first) {
  if (!(first > 0.0) || first * n > 1.0 + 1e-12) return uniform_planes(n);
  double lo = 1.0, hi = 2.0;  // ratio r with first (r^n - 1) / (r - 1) = 1
  auto sum = [&](double r) { return r == 1.0 ? first * n : first * (std::pow(r, n) - 1.0) / (r - 1.0); };
  while (sum(hi) < 1.0) hi *= 2.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    (sum(mid) < 1.0 ? lo : hi) = mid;
  }
  const double r = 0.5 * (lo + hi);
  std::vector<double> p{0.0};
  double h = first, acc = 0.0;
  for (int k = 0; k < n; ++k) {
    acc += h;
    p.push_back(k + 1 == n ? 1.0 : acc / sum(r));
    h *= r;
  }
  return p;
}

// Transfinite interpolation of the block at (s, t).
inline std::array<double, 2> block_point(const Block& b, double s, double t) {
  const auto B = b.bottom.at(s), T = b.top.at(s), L = b.left.at(t), R = b.right.at(t);
  const auto P00 = b.bottom.at(0.0), P10 = b.bottom.at(1.0), P01 = b.top.at(0.0), P11 = b.top.at(1.0);
  std::array<double, 2> x{};
  for (int d = 0; d < 2; ++d)
    x[d] = (1 - t) * B[d] + t * T[d] + (1 - s) * L[d] + s * R[d] -
           ((1 - s) * (1 - t) * P00[d] + s * (1 - t) * P10[d] + (1 - s) * t * P01[d] + s * t * P11[d]);
  return x;
}

// Joins blocks into one mesh: nodes closer than `merge_tol` (relative to the mesh's extent) are one node.
class MeshBuilder {
 public:
  explicit MeshBuilder(double length_scale) : quantum_(1e-9 * length_scale) {}

  void add(const Block& b) {
    const int ns = static_cast<int>(b.s_planes.size()) - 1, nt = static_cast<int>(b.t_planes.size()) - 1;
    if (ns < 1 || nt < 1) throw std::invalid_argument("flow mesh: a block needs at least one cell per direction");
    auto corner_mismatch = [&](std::array<double, 2> a, std::array<double, 2> c) {
      return std::hypot(a[0] - c[0], a[1] - c[1]) > 1e3 * quantum_;
    };
    if (corner_mismatch(b.bottom.at(0), b.left.at(0)) || corner_mismatch(b.bottom.at(1), b.right.at(0)) ||
        corner_mismatch(b.top.at(0), b.left.at(1)) || corner_mismatch(b.top.at(1), b.right.at(1)))
      throw std::invalid_argument("flow mesh: a block's edge curves do not meet at its corners");
    // the Q2 lattice of the block: parameter values of cell boundaries and midpoints
    auto lattice = [](const std::vector<double>& p) {
      std::vector<double> q;
      for (std::size_t k = 0; k + 1 < p.size(); ++k) {
        q.push_back(p[k]);
        q.push_back(0.5 * (p[k] + p[k + 1]));
      }
      q.push_back(p.back());
      return q;
    };
    const std::vector<double> S = lattice(b.s_planes), T = lattice(b.t_planes);
    const int ms = 2 * ns + 1, mt = 2 * nt + 1;
    std::vector<std::int64_t> id(static_cast<std::size_t>(ms) * mt);
    for (int j = 0; j < mt; ++j)
      for (int i = 0; i < ms; ++i) {
        std::array<double, 2> x;
        unsigned tag = 0;
        // nodes on an edge are evaluated on the edge's curve itself (exactly on an arc)
        if (j == 0) {
          x = b.bottom.at(S[i]);
          tag |= b.bottom.tag;
        } else if (j == mt - 1) {
          x = b.top.at(S[i]);
          tag |= b.top.tag;
        } else if (i == 0) {
          x = b.left.at(T[j]);
        } else if (i == ms - 1) {
          x = b.right.at(T[j]);
        } else {
          x = block_point(b, S[i], T[j]);
        }
        if (i == 0) tag |= b.left.tag;
        if (i == ms - 1) tag |= b.right.tag;
        id[static_cast<std::size_t>(j) * ms + i] = node(x, tag);
      }
    for (int cj = 0; cj < nt; ++cj)
      for (int ci = 0; ci < ns; ++ci) {
        std::array<std::int64_t, 9> en;
        for (int j = 0; j < 3; ++j)
          for (int i = 0; i < 3; ++i) en[static_cast<std::size_t>(i + 3 * j)] = id[static_cast<std::size_t>(2 * cj + j) * ms + 2 * ci + i];
        // orientation: counter-clockwise corners 0 -> 2 -> 8 -> 6; mirror in i otherwise
        const double* a = &mesh_.x[2 * static_cast<std::size_t>(en[0])];
        const double* c = &mesh_.x[2 * static_cast<std::size_t>(en[2])];
        const double* d = &mesh_.x[2 * static_cast<std::size_t>(en[6])];
        const double cross = (c[0] - a[0]) * (d[1] - a[1]) - (c[1] - a[1]) * (d[0] - a[0]);
        if (cross < 0)
          for (int j = 0; j < 3; ++j) std::swap(en[static_cast<std::size_t>(3 * j)], en[static_cast<std::size_t>(3 * j + 2)]);
        mesh_.elements.insert(mesh_.elements.end(), en.begin(), en.end());
      }
  }
  QuadMesh take() { return std::move(mesh_); }

 private:
  std::int64_t node(std::array<double, 2> x, unsigned tag) {
    const long long qx = std::llround(x[0] / quantum_ / 16.0), qy = std::llround(x[1] / quantum_ / 16.0);
    for (long long dx = -1; dx <= 1; ++dx)  // neighbouring buckets: a node near a bucket boundary
      for (long long dy = -1; dy <= 1; ++dy) {
        const auto it = index_.find({qx + dx, qy + dy});
        if (it == index_.end()) continue;
        for (const std::int64_t k : it->second) {
          const double* y = &mesh_.x[2 * static_cast<std::size_t>(k)];
          if (std::hypot(y[0] - x[0], y[1] - x[1]) < 16.0 * quantum_) {
            mesh_.tags[static_cast<std::size_t>(k)] |= tag;
            return k;
          }
        }
      }
    const std::int64_t k = mesh_.node_count();
    mesh_.x.push_back(x[0]);
    mesh_.x.push_back(x[1]);
    mesh_.tags.push_back(tag);
    index_[{qx, qy}].push_back(k);
    return k;
  }
  double quantum_;
  QuadMesh mesh_;
  std::map<std::pair<long long, long long>, std::vector<std::int64_t>> index_;
};

// The rectangle [x0, x0 + lx] x [y0, y0 + ly] with nx x ny cells; tags: xmin kInflow, ymin/ymax kWall,
// xmax kOutflow (callers re-tag as they need). distortion > 0 moves interior lattice nodes smoothly by up to
// that fraction of a cell (a curvilinear mesh; the isoparametric map is then not affine).
inline QuadMesh make_rectangle(double x0, double y0, double lx, double ly, int nx, int ny, double distortion = 0.0) {
  if (nx < 1 || ny < 1 || !(lx > 0) || !(ly > 0)) throw std::invalid_argument("flow rectangle: need nx, ny >= 1 and positive sides");
  MeshBuilder mb(std::max(lx, ly));
  mb.add(rect_block(x0, x0 + lx, y0, y0 + ly, uniform_planes(nx), uniform_planes(ny), kWall, kWall, kInflow, kOutflow));
  QuadMesh m = mb.take();
  if (distortion > 0.0) {
    const double pi = 3.14159265358979323846, hx = lx / nx, hy = ly / ny;
    for (std::int64_t k = 0; k < m.node_count(); ++k) {
      double& x = m.x[2 * static_cast<std::size_t>(k)];
      double& y = m.x[2 * static_cast<std::size_t>(k) + 1];
      const double s = (x - x0) / lx, t = (y - y0) / ly, bump = std::sin(pi * s) * std::sin(pi * t);
      const double dx = distortion * hx * bump * std::cos(pi * t), dy = distortion * hy * bump * std::cos(pi * s);
      x += dx;  // a smooth map of the whole rectangle onto itself: cells stay valid for distortion < ~0.3
      y += dy;
    }
  }
  return m;
}

// Straightens every cell: the mid-edge and centre nodes are put at the averages of their corners, so each cell
// is the bilinear image of the square (the isoparametric space then holds every polynomial of degree 2 in x, y).
inline void make_bilinear(QuadMesh& m) {
  for (std::int64_t e = 0; e < m.element_count(); ++e) {
    const std::int64_t* en = &m.elements[static_cast<std::size_t>(e) * 9];
    for (int d = 0; d < 2; ++d) {
      auto X = [&](int a) -> double& { return m.x[2 * static_cast<std::size_t>(en[a]) + d]; };
      X(1) = 0.5 * (X(0) + X(2));
      X(7) = 0.5 * (X(6) + X(8));
      X(3) = 0.5 * (X(0) + X(6));
      X(5) = 0.5 * (X(2) + X(8));
      X(4) = 0.25 * (X(0) + X(2) + X(6) + X(8));
    }
  }
}

// The Turek-Hron geometry (Turek & Hron 2006, Fig. 1 and Table 1).
struct TurekHronGeometry {
  double length = 2.5, height = 0.41;
  double cx = 0.2, cy = 0.2, radius = 0.05;
  double flag_end = 0.6, flag_low = 0.19, flag_high = 0.21;  // the flag: x from the circle to flag_end
  bool flag = true;                                           // false: the cylinder alone (DFG 2D-1/2/3)
  // grading of the ring around the circle (0: uniform, the benchmark's meshes): its radial planes are
  // graded_planes(n, ring_grading), the same map at every level, so refining halves every cell
  double ring_grading = 0.0;
};

// The channel around the cylinder and flag as 20 blocks: a ring of five blocks between the circle and the
// square [0.1, 0.3]^2 (split by the flag), the columns x in [0, 0.1], [0.1, 0.3], [0.3, flag_end] and
// [flag_end, 2.5] split at y = 0.1, 0.19, 0.21, 0.3 (the flag's own rows left out), the last column graded
// geometrically in x from the cell size of the one before it. Level 0 has 260 cells; each level doubles every
// count. Tags: x = 0 kInflow, y = 0 and y = 0.41 kWall, x = 2.5 kOutflow, circle and flag kObstacle.
inline QuadMesh make_turek_hron_channel(int level, const TurekHronGeometry& g = {}) {
  if (level < 0 || level > 6) throw std::invalid_argument("turek-hron mesh: level " + std::to_string(level) + " outside 0..6");
  if (!g.flag) throw std::invalid_argument("turek-hron mesh: only the geometry with the flag is generated");
  const int f = 1 << level;
  const int nx0 = 2 * f, nx1 = 4 * f, nx2 = 6 * f, nx3 = 16 * f;
  const int ny0 = 2 * f, ny1 = 2 * f, ny2 = 1 * f, ny3 = 2 * f, nleft = 2 * ny1 + ny2, nr = 2 * f;
  const double pi = 3.14159265358979323846;
  const double b0 = g.cx - 0.1, b1 = g.cx + 0.1, c0 = g.cy - 0.1, c1 = g.cy + 0.1;  // the square around the circle
  const double H = g.height, L = g.length, fe = g.flag_end, fl = g.flag_low, fh = g.flag_high;
  const double af = std::asin((fh - g.cy) / g.radius), afl = std::asin((fl - g.cy) / g.radius);
  const std::array<double, 2> C{g.cx, g.cy};
  auto circ = [&](double a) { return std::array<double, 2>{g.cx + g.radius * std::cos(a), g.cy + g.radius * std::sin(a)}; };
  const double r = g.radius;
  MeshBuilder mb(L);
  auto box = [&](double xa, double xb, double ya, double yb, const std::vector<double>& sp, int nt, unsigned tb, unsigned tt,
                 unsigned tl, unsigned tr) { mb.add(rect_block(xa, xb, ya, yb, sp, uniform_planes(nt), tb, tt, tl, tr)); };
  const std::vector<double> u0 = uniform_planes(nx0), u1 = uniform_planes(nx1), u2 = uniform_planes(nx2);
  const std::vector<double> g3 = geometric_planes(nx3, ((fe - b1) / nx2) / (L - fe));
  // column x in [0, 0.1]
  box(0, b0, 0, c0, u0, ny0, kWall, 0, kInflow, 0);
  box(0, b0, c0, c1, u0, nleft, 0, 0, kInflow, 0);
  box(0, b0, c1, H, u0, ny3, 0, kWall, kInflow, 0);
  // column x in [0.1, 0.3], below and above the square
  box(b0, b1, 0, c0, u1, ny0, kWall, 0, 0, 0);
  box(b0, b1, c1, H, u1, ny3, 0, kWall, 0, 0);
  // the ring: s runs along the circle (counter-clockwise), t from the circle outwards
  auto ring = [&](double a0, double a1, std::array<double, 2> o0, std::array<double, 2> o1, int ns, unsigned t_start,
                  unsigned t_end) {
    Block b;
    b.bottom = arc(C, r, a0, a1, kObstacle);
    b.top = segment(o0, o1);
    b.left = segment(circ(a0), o0, t_start);
    b.right = segment(circ(a1), o1, t_end);
    b.s_planes = uniform_planes(ns);
    b.t_planes = g.ring_grading > 0.0 ? graded_planes(nr, g.ring_grading) : uniform_planes(nr);
    mb.add(b);
  };
  ring(af, pi / 4, {b1, fh}, {b1, c1}, ny1, kObstacle, 0);             // right, above the flag
  ring(pi / 4, 3 * pi / 4, {b1, c1}, {b0, c1}, nx1, 0, 0);             // top
  ring(3 * pi / 4, 5 * pi / 4, {b0, c1}, {b0, c0}, nleft, 0, 0);       // left
  ring(5 * pi / 4, 7 * pi / 4, {b0, c0}, {b1, c0}, nx1, 0, 0);         // bottom
  ring(-pi / 4, afl, {b1, c0}, {b1, fl}, ny1, 0, kObstacle);           // right, below the flag
  // column x in [0.3, flag_end]: the flag's rows left out
  box(b1, fe, 0, c0, u2, ny0, kWall, 0, 0, 0);
  box(b1, fe, c0, fl, u2, ny1, 0, kObstacle, 0, 0);
  box(b1, fe, fh, c1, u2, ny1, kObstacle, 0, 0, 0);
  box(b1, fe, c1, H, u2, ny3, 0, kWall, 0, 0);
  // column x in [flag_end, 2.5], graded
  box(fe, L, 0, c0, g3, ny0, kWall, 0, 0, kOutflow);
  box(fe, L, c0, fl, g3, ny1, 0, 0, 0, kOutflow);
  box(fe, L, fl, fh, g3, ny2, 0, 0, kObstacle, kOutflow);
  box(fe, L, fh, c1, g3, ny1, 0, 0, 0, kOutflow);
  box(fe, L, c1, H, g3, ny3, 0, kWall, 0, kOutflow);
  QuadMesh m = mb.take();
  // the flag's tip corners and the nodes where the flag meets a wall-free column carry kObstacle from their
  // edges; a node on both the channel wall and the inflow or outflow keeps both bits (the wall wins in the model)
  return m;
}

}  // namespace polymech::flow
