// The single-crystal micro-cantilever of seed 002 paper 5 (issue 34): a beam of pentagonal section milled by
// FIB into a (110) 8YSZ wafer, bent by a load at its loading point, modelled as ONE masked structured lattice
// of hexahedra (models/solid/mesh.hpp) holding the beam and the block of wafer it stands out of.
//
// Geometry (lengths in um; x along the beam, z the wafer normal, the top face z = 0 is the (110) surface):
//  - the beam runs from its root x = 0 to the loading section x = L (paper 5 §3 (2): the load enters as a
//    face traction on the section through the loading point, so the model ends there and its end face is the
//    lattice side xmax). Its section is the FIB pentagon: the top face z = 0 of width w, vertical side walls
//    down to z = -h_s, and two faces meeting at the bottom apex (0, -h) on the centre line (the undercut).
//    The paper gives "a pentagon of 2.5 x 1.5 um": w = 2.5, h = 1.5; the wall height is not given (Fig. 1 is
//    an image), h_s = 0.75 (half the depth) is this model's default and a parameter.
//    The section is the image of a lattice square: every lattice column is a vertical line y = const, its
//    points equally spaced from z = 0 to the bottom z = -depth(y), depth(y) = h_s + (h - h_s)(1 - |2y / w|);
//    the column count is even so the apex lies on the middle column and the bottom is exact (straight cell
//    edges on the two bottom faces);
//  - the support (paper 5 §3 (3): the real fixation is the bottom of the specimen, far away, so the model
//    varies the size of the modelled wafer block until the beam's response stops changing): the block
//    x in [-L_b, 0], y in [-W_b / 2, W_b / 2], z in [-H_b, 0], top flush with the beam's top. Its (y, z)
//    lattice holds the beam's section as a sub-block: columns graded outward from the side walls, rows below
//    the section that start along its bent bottom and relax to the flat bottom z = -H_b. The same section
//    lattice is extruded over x in [-L_b, L]; over x > 0 only the beam's sub-block is active (the mask).
//    Clamped: the block's back (xmin), bottom (zmin) and sides (ymin, ymax); free: its top and the front face
//    around the beam. L_b = 0: no block, the beam's root section (xmin) clamped;
//  - cells: about h_root next to the root (along x on both sides of it, and across the section everywhere),
//    growing by `growth` per cell toward the tip up to h_beam_max, and by `support_growth` into the block
//    (back, down and sideways) up to h_support_max.
//
// Material (paper 5 eqs. (1)-(2)): cubic 8YSZ (materials::ysz8_constants_gpa) in the specimen axes of
// materials::cantilever_rotation(theta), theta the beam axis' angle from [001] in the (110) plane.
//
// Units: um, GPa, mN (1 mN / um^2 = 1 GPa): forces in mN, stresses in GPa, displacements in um,
// compliance in um / mN.
//
// Measures: the tip deflection as the work-conjugate mean of -u_z over the loaded face,
//   delta = f_ext . u / F = (1 / A) int_end (-u_z) dA   (uniform traction -F / A e_z on the end face),
// so F delta is twice the strain energy: it converges monotonically from below under refinement and needs no
// point search; the axial stress sigma_xx at a point (mean over the elements that hold it) and its maximum
// over the Gauss points of the beam's cells in an x range.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "materials/cubic_elastic.hpp"
#include "solid/analysis.hpp"
#include "solid/config.hpp"
#include "solid/mesh.hpp"

namespace polymech::solid {

struct MicroCantileverSpec {
  // beam (um): root x = 0 to the loading section x = length; the pentagon (width, height, wall = h_s)
  double length = 12.0, width = 2.5, height = 1.5, wall = 0.75;
  // support block (um): x in [-support_length, 0], |y| <= support_width / 2, z in [-support_depth, 0];
  // support_length = 0: no block, the root section clamped
  double support_length = 6.0, support_width = 20.0, support_depth = 12.0;
  // mesh: element order, the cell size at the root and its growth toward the tip and into the block
  int order = 2;
  double h_root = 0.2, growth = 1.2, h_beam_max = 1.0, support_growth = 1.5, h_support_max = 3.0;
  // crystal and load: the beam axis' angle from [001] in degrees; the total force (mN) along -z
  double theta_degrees = 0.0, force = 0.05;
};

// The pentagon in closed form: area, the depth of the centroid below the top face, the second moment of
// area about the centroidal axis parallel to y (a rectangle w x h_s plus a triangle of base w, height h - h_s).
struct PentagonSection {
  double area = 0.0, centroid_depth = 0.0, second_moment = 0.0;
};
inline PentagonSection pentagon_section(const MicroCantileverSpec& s) {
  const double w = s.width, a = s.wall, t = s.height - s.wall;
  const double A1 = w * a, A2 = 0.5 * w * t, z1 = 0.5 * a, z2 = a + t / 3.0;
  PentagonSection p;
  p.area = A1 + A2;
  p.centroid_depth = (A1 * z1 + A2 * z2) / p.area;
  p.second_moment = w * a * a * a / 12.0 + A1 * (z1 - p.centroid_depth) * (z1 - p.centroid_depth) +
                    w * t * t * t / 36.0 + A2 * (z2 - p.centroid_depth) * (z2 - p.centroid_depth);
  return p;
}

// The section lattice: (ny + 1) x (nz + 1) points (y fastest, z index 0 at the bottom), the beam's cells
// [beam_y0, beam_y1) x [beam_z0, nz).
struct SectionLattice {
  int ny = 0, nz = 0, beam_y0 = 0, beam_y1 = 0, beam_z0 = 0;
  std::vector<double> yz;
  double y(int j, int k) const { return yz[static_cast<std::size_t>(2 * (k * (ny + 1) + j))]; }
  double z(int j, int k) const { return yz[static_cast<std::size_t>(2 * (k * (ny + 1) + j) + 1)]; }
};

inline void check_spec(const MicroCantileverSpec& s) {
  if (!(s.length > 0 && s.width > 0 && s.height > 0 && s.wall > 0 && s.wall <= s.height))
    throw std::invalid_argument("micro-cantilever: need length, width, height > 0 and 0 < wall <= height");
  if (!(s.h_root > 0 && s.growth >= 1 && s.support_growth >= 1 && s.h_beam_max >= s.h_root &&
        s.h_support_max >= s.h_root))
    throw std::invalid_argument("micro-cantilever: need h_root > 0, growth >= 1, h_*_max >= h_root");
  if (s.support_length < 0) throw std::invalid_argument("micro-cantilever: support_length must be >= 0");
  if (s.support_length > 0 && !(s.support_width > s.width && s.support_depth > s.height))
    throw std::invalid_argument("micro-cantilever: the support must be wider and deeper than the beam");
}

// Depth of the pentagon's bottom below the top face at y (the wall height outside the beam).
inline double pentagon_depth(const MicroCantileverSpec& s, double y) {
  const double r = std::min(1.0, std::abs(2.0 * y / s.width));
  return s.wall + (s.height - s.wall) * (1.0 - r);
}

inline SectionLattice micro_cantilever_section(const MicroCantileverSpec& s) {
  check_spec(s);
  SectionLattice L;
  const int nyb = 2 * std::max(1, static_cast<int>(std::ceil(s.width / (2.0 * s.h_root) - 1e-9)));
  const int nzb = std::max(2, static_cast<int>(std::ceil(s.height / s.h_root - 1e-9)));
  std::vector<double> ys;  // column positions
  std::vector<double> below{0.0};  // fractions g of the way from the section's bottom to z = -H_b
  std::vector<double> outer;       // graded from w / 2 outward
  if (s.support_length > 0) {
    outer = graded_planes(0.5 * s.width, 0.5 * s.support_width, s.width / nyb, s.support_growth, s.h_support_max);
    const auto z = graded_planes(s.height, s.support_depth, s.height / nzb, s.support_growth, s.h_support_max);
    below.clear();
    for (const double d : z) below.push_back((d - s.height) / (s.support_depth - s.height));
  }
  const int nout = outer.empty() ? 0 : static_cast<int>(outer.size()) - 1;
  for (int k = nout; k >= 1; --k) ys.push_back(-outer[static_cast<std::size_t>(k)]);
  for (int j = 0; j <= nyb; ++j) ys.push_back(s.width * (static_cast<double>(j) / nyb - 0.5));
  for (int k = 1; k <= nout; ++k) ys.push_back(outer[static_cast<std::size_t>(k)]);
  const int nbelow = static_cast<int>(below.size()) - 1;
  L.ny = nyb + 2 * nout;
  L.nz = nzb + nbelow;
  L.beam_y0 = nout;
  L.beam_y1 = nout + nyb;
  L.beam_z0 = nbelow;
  L.yz.resize(static_cast<std::size_t>(2 * (L.ny + 1) * (L.nz + 1)));
  for (int k = 0; k <= L.nz; ++k)
    for (int j = 0; j <= L.ny; ++j) {
      const double y = ys[static_cast<std::size_t>(j)], d = pentagon_depth(s, y);
      double z;
      if (k >= nbelow) {
        z = -d * static_cast<double>(L.nz - k) / nzb;  // inside the section's rows: 0 at the top
      } else {
        const double g = below[static_cast<std::size_t>(nbelow - k)];
        z = -(d + g * (s.support_depth - d));  // relaxes from the bent bottom to the flat z = -H_b
      }
      if (k == 0 && nbelow > 0) z = -s.support_depth;  // the flat bottom exactly
      L.yz[static_cast<std::size_t>(2 * (k * (L.ny + 1) + j))] = y;
      L.yz[static_cast<std::size_t>(2 * (k * (L.ny + 1) + j) + 1)] = z;
    }
  return L;
}

// The x planes: the block's, graded from the root backward, then the beam's, graded from the root to the tip.
inline std::vector<double> micro_cantilever_planes(const MicroCantileverSpec& s, int* support_cells = nullptr) {
  std::vector<double> x;
  if (s.support_length > 0) {
    const auto b = graded_planes(0.0, -s.support_length, s.h_root, s.support_growth, s.h_support_max);
    x.assign(b.rbegin(), b.rend());
    x.pop_back();  // the root plane comes with the beam's planes
  }
  if (support_cells) *support_cells = static_cast<int>(x.size());
  const auto f = graded_planes(0.0, s.length, s.h_root, s.growth, s.h_beam_max);
  x.insert(x.end(), f.begin(), f.end());
  return x;
}

// The masked lattice of the beam and its support block (no mask without a block).
inline StructuredMesh<3> make_micro_cantilever_mesh(const MicroCantileverSpec& s) {
  const SectionLattice L = micro_cantilever_section(s);
  int nxs = 0;
  const std::vector<double> x = micro_cantilever_planes(s, &nxs);
  StructuredMesh<3> m;
  m.cells = {static_cast<int>(x.size()) - 1, L.ny, L.nz};
  m.vertices.resize(static_cast<std::size_t>(3 * m.vertex_count()));
  for (int k = 0; k <= L.nz; ++k)
    for (int j = 0; j <= L.ny; ++j)
      for (int i = 0; i <= m.cells[0]; ++i) {
        const std::size_t v = static_cast<std::size_t>(m.vertex({i, j, k}));
        m.vertices[3 * v] = x[static_cast<std::size_t>(i)];
        m.vertices[3 * v + 1] = L.y(j, k);
        m.vertices[3 * v + 2] = L.z(j, k);
      }
  if (s.support_length > 0) {
    m.active.assign(static_cast<std::size_t>(m.cell_count()), 0);
    for (int k = 0; k < L.nz; ++k)
      for (int j = 0; j < L.ny; ++j)
        for (int i = 0; i < m.cells[0]; ++i) {
          const bool beam = j >= L.beam_y0 && j < L.beam_y1 && k >= L.beam_z0;
          m.active[static_cast<std::size_t>(m.cell({i, j, k}))] = (i < nxs || beam) ? 1 : 0;
        }
  }
  return m;
}

// Cubic 8YSZ in the specimen axes of a beam at theta degrees from [001] in the (110) plane (GPa).
inline materials::Stiffness6<double> ysz8_cantilever_stiffness(double theta_degrees) {
  const double theta = theta_degrees * 3.14159265358979323846 / 180.0;
  return materials::rotated_cubic_stiffness(materials::ysz8_constants_gpa<double>(),
                                            materials::cantilever_rotation(theta));
}

// The configuration with a given stiffness: the clamps and the end-face traction -F / A e_z.
inline Config<3> micro_cantilever(const MicroCantileverSpec& s, const materials::Stiffness6<double>& C) {
  Config<3> c;
  c.mesh = make_micro_cantilever_mesh(s);
  c.order = s.order;
  c.stiffness = C;
  if (s.support_length > 0) {
    for (const char* side : {"xmin", "zmin", "ymin", "ymax"}) c.dirichlet.push_back({side, 7u, {}});
  } else {
    c.dirichlet.push_back({"xmin", 7u, {}});
  }
  c.tractions.push_back({"xmax", {0.0, 0.0, -s.force / pentagon_section(s).area}});
  return c;
}

// The paper's case: cubic 8YSZ rotated by theta_degrees.
inline Config<3> micro_cantilever(const MicroCantileverSpec& s) {
  return micro_cantilever(s, ysz8_cantilever_stiffness(s.theta_degrees));
}

// Tip deflection: f_ext . u / F with F = -sum_z f_ext, the area mean of -u_z over the loaded face.
template <class T>
double tip_deflection(const LinearElastic<T, 3>& m) {
  const std::vector<double> f = models::to_host(m.external_force());
  const std::vector<double> u = m.displacement_host();
  double work = 0.0, force = 0.0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    work += f[i] * u[i];
    if (i % 3 == 2) force -= f[i];
  }
  return work / force;
}

namespace detail {
// sigma_xx at reference point xi of storage element e (host, from the element's stiffness).
template <class T>
double axial_stress(const LinearElastic<T, 3>& m, const ElementEvaluator<3>& ev, const std::vector<double>& u,
                    const std::vector<double>& C, std::int64_t e, const std::array<double, 3>& xi) {
  const auto& d = m.discretization();
  const int ND = d.nodes_per_element();
  const PointBasis<3> p = ev.at(e, xi);
  const std::int64_t* en = &d.element_nodes[static_cast<std::size_t>(e) * ND];
  double H[3][3] = {};
  for (int a = 0; a < ND; ++a)
    for (int c = 0; c < 3; ++c)
      for (int j = 0; j < 3; ++j)
        H[c][j] += u[static_cast<std::size_t>(3 * en[a] + c)] * p.dN[static_cast<std::size_t>(a) * 3 + j];
  const double eps[6] = {H[0][0], H[1][1], H[2][2], H[1][2] + H[2][1], H[0][2] + H[2][0], H[0][1] + H[1][0]};
  double s = 0.0;
  for (int j = 0; j < 6; ++j) s += C[static_cast<std::size_t>(36 * e + j)] * eps[j];  // row 11 of C
  return s;
}
template <class T>
std::vector<double> host_materials(const LinearElastic<T, 3>& m) {
  const auto mat = Kokkos::create_mirror_view_and_copy(HostSpace(), m.elements().material);
  std::vector<double> C(mat.extent(0) * 36);
  for (std::size_t e = 0; e < mat.extent(0); ++e)
    for (int k = 0; k < 36; ++k) C[e * 36 + k] = static_cast<double>(mat(e, k));
  return C;
}
}  // namespace detail

// sigma_xx at the physical point x: the mean over the elements that hold it (the stress of a C0 field jumps
// between elements; on a face or an edge every neighbour counts once).
template <class T>
double axial_stress_at(const LinearElastic<T, 3>& m, const std::array<double, 3>& x) {
  const auto& d = m.discretization();
  const ElementEvaluator<3> ev(d);
  const std::vector<double> u = m.displacement_host(), C = detail::host_materials(m);
  const int ND = d.nodes_per_element();
  double sum = 0.0;
  int count = 0;
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    const std::int64_t* en = &d.element_nodes[e * ND];
    bool inside = true;
    for (int c = 0; c < 3 && inside; ++c) {
      double lo = 1e300, hi = -1e300;
      for (int a = 0; a < ND; ++a) {
        lo = std::min(lo, d.coordinates[static_cast<std::size_t>(3 * en[a] + c)]);
        hi = std::max(hi, d.coordinates[static_cast<std::size_t>(3 * en[a] + c)]);
      }
      const double margin = 1e-9 * (hi - lo);
      inside = x[c] >= lo - margin && x[c] <= hi + margin;
    }
    std::array<double, 3> xi;
    if (!inside || !ev.locate(static_cast<std::int64_t>(e), x, xi)) continue;
    sum += detail::axial_stress(m, ev, u, C, static_cast<std::int64_t>(e), xi);
    ++count;
  }
  if (count == 0) throw std::invalid_argument("micro-cantilever: the stress point lies outside the mesh");
  return sum / count;
}

// The largest sigma_xx over the Gauss points (N per direction) of the cells whose centre lies in
// x_lo <= x <= x_hi.
template <class T>
double max_axial_stress(const LinearElastic<T, 3>& m, double x_lo, double x_hi) {
  const auto& d = m.discretization();
  const ElementEvaluator<3> ev(d);
  const std::vector<double> u = m.displacement_host(), C = detail::host_materials(m);
  const int ND = d.nodes_per_element(), Q = d.n1d;
  std::vector<double> xq, wq;
  fem::gauss_legendre(Q, xq, wq);
  double best = -1e300;
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    const std::int64_t* en = &d.element_nodes[e * ND];
    double xc = 0.0;
    for (int a = 0; a < ND; ++a) xc += d.coordinates[static_cast<std::size_t>(3 * en[a])];
    xc /= ND;
    if (xc < x_lo || xc > x_hi) continue;
    for (int q = 0; q < Q * Q * Q; ++q) {
      const std::array<double, 3> xi{xq[q % Q], xq[(q / Q) % Q], xq[q / (Q * Q)]};
      best = std::max(best, detail::axial_stress(m, ev, u, C, static_cast<std::int64_t>(e), xi));
    }
  }
  return best;
}

}  // namespace polymech::solid
