// The deformable tyre 37x12.5R16.5 of seed 002 paper 2 (§4: "the rubber parts ... Mooney-Rivlin, the carcass and
// belt reinforcements ... orthotropic elastic, the rim rigid"; issue 37) as one mapped 3D lattice of the solid
// layer (models/solid/mesh.hpp), and a rigid plate pressed against it (node-to-plane penalty contact).
//
// Lattice: direction 0 round the wheel (theta, periodic), direction 1 along the cross-section contour from bead to
// bead (s in [0, 1]: ymin = the bead at y < 0, ymax = the bead at y > 0; sidewall - shoulder - tread - shoulder -
// sidewall), direction 2 through the wall (t in [0, 1]: zmin = the inner surface, where the inflation pressure
// acts; zmax = the outer surface, the contact surface). The wheel axis is y, the vertical z: a point of the section
// at radius r and axial position a is (r cos theta, a, -r sin theta), so the tyre's lowest point (theta = pi/2) is
// at z = -R and the lattice's Jacobian is positive.
//
// The section (TyreSpec): the inner contour is three tangent-continuous circular arcs per half (the tread crown
// arc of radius R_t from the centre line to the tread edge, the shoulder arc of radius R_s down to the widest
// point, where the contour is radial, and the sidewall arc of radius R_w turning in to the bead), parametrised by
// arc length so the cells along it are of equal length; R_s and (R_w, its angle) follow from the widest point and
// the bead position (bead_section). The wall is h_t thick over the tread and h_w on the sidewall (a cosine
// blend over the shoulder arc), offset along the contour's normal. Dimensions: outer radius 0.445 m and width
// 0.310 m (paper 2 §4); rim 16.5 in (radius 0.2096 m) and 8.25 in wide (the 16.5x8.25 rim of this size, so the
// beads at y = +-0.105 m); wall gauges, crown and tread width assumed (TyreSpec comments; docs/VALIDATION.md).
//
// By default one law for every element (the Config has one; TyreSpec::layered = false): a Mooney-Rivlin solid whose initial shear modulus is the
// rubber's plus the reinforcement smeared over the sidewall gauge (tyre_equivalent_law): each carcass ply is
// a unidirectional cord-rubber layer (rule of mixtures E_1 = V_f E_cord + (1 - V_f) E_rubber along the cords,
// E_2 = E_rubber / (1 - V_f) across), the plies' in-plane stiffness replaced by the quasi-isotropic laminate's
// E_qi = 3/8 E_1 + 5/8 E_2 (the classical quasi-isotropic estimate for E_1 >> E_2), and its membrane stiffness
// E_qi t_plies spread over the wall: E_eq = E_rubber + E_qi t_plies / h_w, mu_eq = E_eq / 3, split between C10
// and C01 in the rubber's ratio; the bulk modulus kappa = kappa_ratio mu_eq (the homogenised cord-rubber
// composite is compressible; a larger ratio shortens the explicit step as 1/sqrt(kappa)). Smearing over the
// gauge matches the membrane stiffness that carries the inflation; it overestimates the wall's bending
// stiffness (the cords sit at mid-surface) and underestimates the steel belt's circumferential stiffness.
// With TyreSpec::layered the wall is layered instead (tyre_layers: the same law scaled per cell, the plies in
// the middle cell through the wall), which keeps the membrane stiffness and drops the plies' bending share.
// TyreSpec::belted adds a steel belt layer over the crown (tyre_layers: the layer outside the cord layer), read as
// one isotropic modulus, or with TyreSpec::belt_rebar as rebar: the layer keeps the rubber and carries two steel-cord
// families at +-belt_angle_deg to the circumference (tyre_fibre_stiffness; Hyperelastic::set_fibres; seed 002
// paper 2 §4, the belt reinforcements).
//
// Plate (PlateContact): a rigid plane z = z_p(t) below the tyre, normal +z, frictionless; each outer-surface node
// below it gets f_z = k_i g + c_i (v_p - v_z) >= 0 (g = z_p - z_i the penetration), k_i = beta m_i omega_max^2 (a
// fraction beta of the stiffest element mode on the node's lumped mass, so the contact costs the explicit step at
// most a factor 1/sqrt(1 + beta)), c_i = 2 zeta sqrt(k_i m_i). It is a Kokkos kernel on the residual
// (HyperelasticExplicit::set_external_force), so the tyre's reaction reaches the rim's ties exactly.
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/finite_strain_explicit.hpp"
#include "solid/tyre_section.hpp"

namespace polymech::solid {

// The tyre's mapped lattice: n_theta x n_section x n_wall cells (see the header).
inline StructuredMesh<3> make_tyre(const TyreSpec& s, int n_theta, int n_section, int n_wall) {
  if (n_theta < 3 || n_section < 2 || n_wall < 1) throw std::invalid_argument("solid::make_tyre: need n_theta >= 3, n_section >= 2, n_wall >= 1");
  const double two_pi = 6.28318530717958647692;
  std::vector<double> th(static_cast<std::size_t>(n_theta) + 1), sv(static_cast<std::size_t>(n_section) + 1),
      tv(static_cast<std::size_t>(n_wall) + 1);
  for (int i = 0; i <= n_theta; ++i) th[static_cast<std::size_t>(i)] = two_pi * i / n_theta;
  for (int i = 0; i <= n_section; ++i) sv[static_cast<std::size_t>(i)] = static_cast<double>(i) / n_section;
  for (int i = 0; i <= n_wall; ++i) tv[static_cast<std::size_t>(i)] = static_cast<double>(i) / n_wall;
  StructuredMesh<3> m = make_tensor_box<3>({th, sv, tv});
  m.periodic = {true, false, false};
  const TyreSection c = tyre_section(s);
  m.map = [c](const double* xi, double* x) {
    const double sigma = (2.0 * xi[1] - 1.0) * c.half_length;
    double p[2], n[2], h = 0.0;
    c.at(std::fabs(sigma), p, n, h);
    const double sg = sigma < 0.0 ? -1.0 : 1.0;
    const double a = sg * (p[0] + xi[2] * h * n[0]), r = p[1] + xi[2] * h * n[1];
    x[0] = r * std::cos(xi[0]);
    x[1] = a;
    x[2] = -r * std::sin(xi[0]);
  };
  return m;
}

// Volume of the tyre (revolved section, midpoint rule on a fine (sigma, t) grid).
inline double tyre_volume(const TyreSpec& s) {
  const TyreSection c = tyre_section(s);
  const int ns = 4000, nt = 8;
  double v = 0.0;
  const double ds = c.half_length / ns;
  for (int i = 0; i < ns; ++i) {
    double p[2], n[2], h = 0.0, p2[2], n2[2], h2 = 0.0;
    const double sg = (i + 0.5) * ds;
    c.at(sg - 0.5 * ds, p, n, h);
    c.at(sg + 0.5 * ds, p2, n2, h2);
    for (int j = 0; j < nt; ++j) {
      const double t = (j + 0.5) / nt;
      // the cell's corners in (a, r): a thin quadrilateral; its area by the cross product of its diagonals
      const double A0[2] = {p[0] + t * h * n[0], p[1] + t * h * n[1]}, A1[2] = {p2[0] + t * h2 * n2[0], p2[1] + t * h2 * n2[1]};
      const double ta[2] = {A1[0] - A0[0], A1[1] - A0[1]};
      const double nm[2] = {0.5 * (n[0] + n2[0]), 0.5 * (n[1] + n2[1])};
      const double hm = 0.5 * (h + h2) / nt;
      const double area = std::fabs(ta[0] * nm[1] - ta[1] * nm[0]) * hm;
      v += 2.0 * 6.28318530717958647692 * (0.5 * (A0[1] + A1[1])) * area;  // both halves: 2 x 2 pi r dA
    }
  }
  return v;
}

// The one law of every element: Mooney-Rivlin with the rubber plus the smeared carcass plies (see the header).
struct TyreLaw {
  materials::MooneyRivlin<double> law;
  double E_ply_along = 0.0, E_ply_across = 0.0, E_quasi_isotropic = 0.0, E_equivalent = 0.0, mu = 0.0, density = 0.0;
};

inline TyreLaw tyre_equivalent_law(const TyreSpec& s) {
  TyreLaw o;
  const double Er = 6.0 * (s.C10 + s.C01);
  o.E_ply_along = s.cord_fraction * s.cord_modulus + (1.0 - s.cord_fraction) * Er;
  o.E_ply_across = Er / (1.0 - s.cord_fraction);
  o.E_quasi_isotropic = 0.375 * o.E_ply_along + 0.625 * o.E_ply_across;
  o.E_equivalent = Er + o.E_quasi_isotropic * s.plies * s.ply_thickness / s.wall_gauge;
  o.mu = o.E_equivalent / 3.0;
  const double share = s.C10 / (s.C10 + s.C01);
  o.law.C10 = 0.5 * o.mu * share;
  o.law.C01 = 0.5 * o.mu * (1.0 - share);
  o.law.kappa = s.kappa_ratio * o.mu;
  o.density = s.mass / tyre_volume(s);
  return o;
}

// The layered wall (issue 37: "reinforcement as orthotropic layers"): per cell of the make_tyre lattice a scale of
// the smeared law (HyperelasticExplicit's cell_scale; the Mooney-Rivlin stress is linear in C10, C01 and kappa, so
// s times the law is the same law with its moduli times s). With n_wall (odd, >= 3) cells through the wall, the
// middle cell is the cord layer (the carcass plies at the wall's mid-surface) and the others rubber:
//   rubber:      E = E_rubber = 6 (C10 + C01)                       (s = E_rubber / E_eq)
//   cord layer:  E = E_rubber + E_qi t_plies / h_c,  h_c = h / n_wall (s = E / E_eq)
// h the local gauge at the cell's centre along the contour (the tread's 20 mm, the sidewall's 12 mm, blended over
// the shoulder), so the wall's membrane stiffness is E_rubber h + E_qi t_plies everywhere, that of the smeared law
// on the sidewall, while the plies' share of the bending stiffness drops from E_qi t_plies h^2 / 12 (smeared
// over h) to E_qi t_plies h^2 / (12 n_wall^2) (a layer h / n_wall thick at the mid-surface): the crown and the
// walls bend as rubber with a stiff membrane, as a cord-rubber laminate does. The plies stay quasi-isotropic
// in the plane (E_qi) and isotropic through it (the Mooney-Rivlin law), as in the smeared law.
//
// The belt (TyreSpec::belted): each +-theta steel-cord ply is a unidirectional cord-rubber layer (E_1, E_2 as for the
// carcass plies, G_12 = G_rubber / (1 - V_f), nu_12 = V_f 0.3 + (1 - V_f) 0.5), rotated by classical lamination
// theory; the balanced laminate's membrane stiffness A = t_belt Qbar (the +theta and -theta plies' shear couplings
// cancel). Its one isotropic modulus E_belt is A11 / t_belt (the circumferential modulus with the lateral strain
// held) or, belt_laterally_free, (A11 - A12^2 / A22) / t_belt. In the crown cells, the layer k = n_wall / 2 + 1 gets
//   belt layer:  E = E_rubber + f E_belt t_belt / h_c,  h_c = h / n_wall
// f the share of the cell's contour length inside the belt's half width (1 in the crown, a fraction at the belt's
// edge: the belt's width is kept on coarse meshes), so the crown's circumferential membrane stiffness is
// E_rubber h + E_qi t_plies + E_belt t_belt. The layer's modulus (14 GPa) shortens the explicit step ~ 5 x (24 x 8 x 3).
// With belt_rebar the layer's scale stays the rubber's and fibre_stiffness holds each cord family's smeared modulus
// k = f E_cord V_f (t_belt / 2) / h_c in the same cells (seed 002 paper 2 §4, the belt reinforcements; the fibre law
// of kernels/solid/finite_strain.hpp): the layer's small-strain cord stiffness is 2 k cos^4 beta round the wheel
// (14.0 GPa, the A11 reading's), 2 k sin^4 beta across (0.25 GPa) and 2 k cos^2 beta sin^2 beta in shear, and the
// cords act along the cell's plane only, so they leave the explicit step at the layered wall's (the cord layer's
// through-thickness mode stays the highest; the power iteration runs with the cords).
struct TyreLayers {
  std::vector<double> cell_scale;     // [n_theta n_section n_wall], cell id i0 + n_theta (i1 + n_section i2)
  double E_rubber = 0.0, E_cord_min = 0.0, E_cord_max = 0.0, scale_max = 0.0, scale_min = 0.0;
  // the belt (belted only): the laminate's A11 / t, A22 / t, free E_x, the modulus used, the layer's largest E,
  // the layer index through the wall and the contour cells it covers (f > 0)
  double E_belt_held = 0.0, E_belt_across = 0.0, E_belt_free = 0.0, E_belt = 0.0, E_belt_layer_max = 0.0;
  int belt_layer = -1, belt_cells = 0;
  // the rebar belt (belt_rebar only; else empty): per cell (the cell_scale's order) the smeared modulus k of each of
  // the two cord families (0 outside the belt), and its largest value
  std::vector<double> fibre_stiffness;
  double fibre_k_max = 0.0;
};

// The belt laminate's moduli (see TyreLayers): {A11 / t, A22 / t, (A11 - A12^2 / A22) / t}.
inline std::array<double, 3> tyre_belt_moduli(const TyreSpec& s) {
  const double Er = 6.0 * (s.C10 + s.C01), Vf = s.belt_fraction;
  const double E1 = Vf * s.belt_modulus + (1.0 - Vf) * Er, E2 = Er / (1.0 - Vf), G12 = Er / 3.0 / (1.0 - Vf);
  const double nu12 = Vf * 0.3 + (1.0 - Vf) * 0.5, nu21 = nu12 * E2 / E1, den = 1.0 - nu12 * nu21;
  const double Q11 = E1 / den, Q22 = E2 / den, Q12 = nu12 * E2 / den, Q66 = G12;
  const double th = s.belt_angle_deg * 3.14159265358979323846 / 180.0, c = std::cos(th), sn = std::sin(th);
  const double c2 = c * c, s2 = sn * sn;
  const double A11 = Q11 * c2 * c2 + 2.0 * (Q12 + 2.0 * Q66) * s2 * c2 + Q22 * s2 * s2;
  const double A22 = Q11 * s2 * s2 + 2.0 * (Q12 + 2.0 * Q66) * s2 * c2 + Q22 * c2 * c2;
  const double A12 = (Q11 + Q22 - 4.0 * Q66) * s2 * c2 + Q12 * (s2 * s2 + c2 * c2);
  return {A11, A22, A11 - A12 * A12 / A22};
}

inline TyreLayers tyre_layers(const TyreSpec& s, int n_theta, int n_section, int n_wall) {
  if (n_wall < 3 || n_wall % 2 == 0)
    throw std::invalid_argument("solid::tyre_layers: the layered wall needs an odd number of cells through the wall >= 3 (got " +
                                std::to_string(n_wall) + ")");
  const TyreLaw eq = tyre_equivalent_law(s);
  const TyreSection c = tyre_section(s);
  TyreLayers o;
  o.E_rubber = 6.0 * (s.C10 + s.C01);
  o.E_cord_min = 1e300;
  o.cell_scale.assign(static_cast<std::size_t>(n_theta) * static_cast<std::size_t>(n_section) * static_cast<std::size_t>(n_wall), 0.0);
  const double t_plies = s.plies * s.ply_thickness;
  for (int j = 0; j < n_section; ++j) {
    const double sigma = (2.0 * (j + 0.5) / n_section - 1.0) * c.half_length;  // the cell's centre along the contour
    double p[2], n[2], h = 0.0;
    c.at(std::fabs(sigma), p, n, h);
    const double E_cord = o.E_rubber + eq.E_quasi_isotropic * t_plies / (h / n_wall);
    o.E_cord_min = std::fmin(o.E_cord_min, E_cord);
    o.E_cord_max = std::fmax(o.E_cord_max, E_cord);
    for (int k = 0; k < n_wall; ++k) {
      const double sc = (k == n_wall / 2 ? E_cord : o.E_rubber) / eq.E_equivalent;
      for (int i = 0; i < n_theta; ++i)
        o.cell_scale[static_cast<std::size_t>(i + n_theta * (j + n_section * k))] = sc;
    }
  }
  o.scale_min = o.E_rubber / eq.E_equivalent;
  o.scale_max = o.E_cord_max / eq.E_equivalent;
  if (s.belted) {
    if (!(s.belt_modulus > 0.0) || !(s.belt_fraction > 0.0 && s.belt_fraction < 1.0) || !(s.belt_ply_thickness > 0.0) ||
        s.belt_plies < 1 || !(s.belt_half_width > 0.0) || !(s.belt_angle_deg >= 0.0 && s.belt_angle_deg < 90.0))
      throw std::invalid_argument("solid::tyre_layers: the belt needs modulus > 0, 0 < fraction < 1, ply thickness > 0, plies >= 1, "
                                  "half width > 0 and 0 <= angle < 90 deg");
    const std::array<double, 3> A = tyre_belt_moduli(s);
    o.E_belt_held = A[0];
    o.E_belt_across = A[1];
    o.E_belt_free = A[2];
    o.E_belt = s.belt_laterally_free ? A[2] : A[0];
    o.belt_layer = n_wall / 2 + 1;
    const double t_belt = s.belt_plies * s.belt_ply_thickness, ds = 2.0 * c.half_length / n_section;
    if (s.belt_rebar) o.fibre_stiffness.assign(o.cell_scale.size(), 0.0);
    for (int j = 0; j < n_section; ++j) {
      const double lo = (2.0 * j / n_section - 1.0) * c.half_length, hi = lo + ds;
      const double f = std::fmax(0.0, std::fmin(hi, s.belt_half_width) - std::fmax(lo, -s.belt_half_width)) / ds;
      if (!(f > 0.0)) continue;
      const double sigma = 0.5 * (lo + hi);
      double p[2], n[2], h = 0.0;
      c.at(std::fabs(sigma), p, n, h);
      ++o.belt_cells;
      if (s.belt_rebar) {
        // Rebar (seed 002 paper 2 §4, the belt reinforcements): the plies split evenly over the +-beta families; a
        // family's cords, V_f of t_belt / 2, smeared over the cell layer h_c = h / n_wall: k = f E_cord V_f
        // (t_belt / 2) / h_c (the cords' share only: the rubber between them is the layer's own Mooney-Rivlin law,
        // kept; f the covered share of the cell's contour length, as for the isotropic layer). 9.0 GPa per family in
        // a crown cell of 24 x 8 x 3: round the wheel 2 k cos^4(20 deg) = 14.0 GPa, as the A11 reading's layer.
        const double k = f * s.belt_modulus * s.belt_fraction * (0.5 * t_belt) / (h / n_wall);
        o.fibre_k_max = std::fmax(o.fibre_k_max, k);
        for (int i = 0; i < n_theta; ++i) o.fibre_stiffness[static_cast<std::size_t>(i + n_theta * (j + n_section * o.belt_layer))] = k;
        continue;
      }
      const double E_layer = o.E_rubber + f * o.E_belt * t_belt / (h / n_wall);
      o.E_belt_layer_max = std::fmax(o.E_belt_layer_max, E_layer);
      for (int i = 0; i < n_theta; ++i)
        o.cell_scale[static_cast<std::size_t>(i + n_theta * (j + n_section * o.belt_layer))] = E_layer / eq.E_equivalent;
    }
    o.scale_max = std::fmax(o.scale_max, o.E_belt_layer_max / eq.E_equivalent);
  }
  return o;
}

// The cell scales of the spec's wall: empty with the smeared law (the one-law path), tyre_layers' with layered.
inline std::vector<double> tyre_cell_scale(const TyreSpec& s, int n_theta, int n_section, int n_wall) {
  if (s.belted && !s.layered) throw std::invalid_argument("solid::tyre_cell_scale: the belt (TyreSpec::belted) needs the layered wall");
  return s.layered ? tyre_layers(s, n_theta, n_section, n_wall).cell_scale : std::vector<double>{};
}

// The rebar belt's per-cell cord stiffness (TyreSpec::belt_rebar; ExplicitFiniteStrainOptions::fibre_stiffness,
// with fibre_angle_deg = belt_angle_deg): empty without it. make_tyre's element direction 0 is round the wheel and
// direction 1 along the contour, so the kernel's t_0, t_1 are the circumferential and lateral tangents.
inline std::vector<double> tyre_fibre_stiffness(const TyreSpec& s, int n_theta, int n_section, int n_wall) {
  if (!s.belt_rebar) return {};
  if (!s.belted || !s.layered) throw std::invalid_argument("solid::tyre_fibre_stiffness: the rebar belt (TyreSpec::belt_rebar) needs belted and layered");
  return tyre_layers(s, n_theta, n_section, n_wall).fibre_stiffness;
}

// The widest point of the (deformed) inner surface on the y > 0 side, on the meridian theta = 0: (y, r) at the
// vertex of the parabola through the node of largest y and its two neighbours along the contour (the membrane
// closed form of the bead force needs the radius where the inner contour is axial-most, between nodes on a
// coarse mesh).
inline std::array<double, 2> widest_inner_point(const Discretization<3>& d, const std::vector<double>& u) {
  const int n1 = d.lattice[1];
  std::vector<double> y(static_cast<std::size_t>(n1)), r(static_cast<std::size_t>(n1));
  for (int j = 0; j < n1; ++j) {
    const std::size_t i = static_cast<std::size_t>(3 * d.node({0, j, 0}));
    const double x = d.coordinates[i] + u[i], z = d.coordinates[i + 2] + u[i + 2];
    y[static_cast<std::size_t>(j)] = d.coordinates[i + 1] + u[i + 1];
    r[static_cast<std::size_t>(j)] = std::sqrt(x * x + z * z);
  }
  int k = 1;
  for (int j = 1; j + 1 < n1; ++j)
    if (y[static_cast<std::size_t>(j)] > y[static_cast<std::size_t>(k)]) k = j;
  const double ym = y[static_cast<std::size_t>(k - 1)], y0 = y[static_cast<std::size_t>(k)], yp = y[static_cast<std::size_t>(k + 1)];
  const double den = ym - 2.0 * y0 + yp;
  const double q = den < 0.0 ? std::fmax(-1.0, std::fmin(1.0, 0.5 * (ym - yp) / den)) : 0.0;  // vertex offset in nodes
  const double rm = r[static_cast<std::size_t>(k - 1)], r0 = r[static_cast<std::size_t>(k)], rp = r[static_cast<std::size_t>(k + 1)];
  return {y0 - 0.25 * (ym - yp) * q, r0 + 0.5 * q * (rp - rm) + 0.5 * q * q * (rp - 2.0 * r0 + rm)};
}

// The rigid plate z = z_p(t) (normal +z, frictionless) against the outer-surface nodes (see the header).
template <class T>
class PlateContact {
 public:
  PlateContact(const Discretization<3>& d, const View1<T>& lumped_mass, double omega_max, double beta, double zeta,
               std::function<double(double)> height, std::function<double(double)> speed)
      : height_(std::move(height)), speed_(std::move(speed)) {
    if (!(beta > 0.0) || !(zeta >= 0.0)) throw std::invalid_argument("solid::PlateContact: need beta > 0, zeta >= 0");
    const std::vector<std::int64_t> nodes = side_nodes(d, "zmax");
    const std::vector<double> m = models::to_host(lumped_mass);
    std::vector<Index> id(nodes.size());
    std::vector<double> z0(nodes.size()), k(nodes.size()), c(nodes.size());
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      id[j] = static_cast<Index>(nodes[j]);
      z0[j] = d.coordinates[static_cast<std::size_t>(3 * nodes[j] + 2)];
      const double mi = m[static_cast<std::size_t>(3 * nodes[j] + 2)];
      k[j] = beta * mi * omega_max * omega_max;
      c[j] = 2.0 * zeta * std::sqrt(k[j] * mi);
    }
    nodes_ = models::to_device<Index>("polymech::solid::plate_nodes", id);
    z0_ = models::to_device<double>("polymech::solid::plate_z0", z0);
    k_ = models::to_device<double>("polymech::solid::plate_k", k);
    c_ = models::to_device<double>("polymech::solid::plate_c", c);
    host_nodes_ = nodes;
  }

  // r -= f on the contact nodes' z rows; records the total force and the number of nodes in contact.
  void apply(double t, const View1<T>& u, const View1<T>& v, const View1<T>& r) {
    const double zp = height_(t), vp = speed_ ? speed_(t) : 0.0;
    const auto nodes = nodes_;
    const auto z0 = z0_, k = k_, c = c_;
    double F = 0.0, count = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::plate_contact", Kokkos::RangePolicy<ExecSpace>(0, static_cast<Index>(host_nodes_.size())),
        KOKKOS_LAMBDA(const Index j, double& f_sum, double& n_sum) {
          const Index i = nodes(j);
          const double g = zp - (z0(j) + double(u(3 * i + 2)));
          if (g <= 0.0) return;
          double f = k(j) * g + c(j) * (vp - double(v(3 * i + 2)));
          f = f > 0.0 ? f : 0.0;
          r(3 * i + 2) -= static_cast<T>(f);
          f_sum += f;
          n_sum += 1.0;
        },
        F, count);
    force_ = F;
    in_contact_ = static_cast<int>(count);
  }

  double force() const { return force_; }
  int nodes_in_contact() const { return in_contact_; }
  const std::vector<std::int64_t>& nodes() const { return host_nodes_; }
  double height(double t) const { return height_(t); }

  // The contact patch: the x and y extents of the nodes at or below the plate (host; at output times).
  std::array<double, 2> patch(const Discretization<3>& d, const View1<T>& u, double t) const {
    const std::vector<double> uh = models::to_host(u);
    const double zp = height_(t);
    double xl = 1e300, xh = -1e300, yl = 1e300, yh = -1e300;
    for (const std::int64_t n : host_nodes_) {
      const std::size_t i = static_cast<std::size_t>(3 * n);
      if (d.coordinates[i + 2] + uh[i + 2] > zp) continue;
      const double x = d.coordinates[i] + uh[i], y = d.coordinates[i + 1] + uh[i + 1];
      xl = std::fmin(xl, x);
      xh = std::fmax(xh, x);
      yl = std::fmin(yl, y);
      yh = std::fmax(yh, y);
    }
    if (xh < xl) return {0.0, 0.0};
    return {xh - xl, yh - yl};
  }

 private:
  std::function<double(double)> height_, speed_;
  Kokkos::View<Index*, MemSpace> nodes_;
  View1<double> z0_, k_, c_;
  std::vector<std::int64_t> host_nodes_;
  double force_ = 0.0;
  int in_contact_ = 0;
};

}  // namespace polymech::solid
