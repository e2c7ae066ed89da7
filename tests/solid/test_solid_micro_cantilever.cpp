// The micro-cantilever of seed 002 paper 5 on the masked structured lattice (issue 34;
// models/solid/micro_cantilever.hpp), every number the assertions rest on printed:
//  - the active-cell mask: node and face counts of an L-shaped lattice in closed form, no node inside the
//    inactive block, an all-active mask identical to no mask, the patch test exact on the L-shaped lattice;
//  - the pentagon mapping: det J > 0 in every element, the section's area and the model's volume equal their
//    closed forms, the apex and the bottom faces exact;
//  - a slender beam-only (clamped-root) isotropic cantilever against Timoshenko beam theory with the
//    pentagon's second moment of area (computed here by Green's theorem over the vertices);
//  - the crystal orientation: the compliance ratio of theta = 54.7 deg (<111>) to 0 deg (<001>) against the
//    uniaxial modulus ratio E<001> / E<111> of cubic 8YSZ.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solid/micro_cantilever.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

// The 4 x 4 x 2 unit-cell box without its quadrant x > 2, y > 2 (an L-shaped prism).
so::StructuredMesh<3> l_shaped(bool distort_z) {
  so::BoxSpec b;
  b.lengths = {4.0, 4.0, 2.0};
  b.cells = {4, 4, 2};
  so::StructuredMesh<3> m = so::make_box<3>(b);
  if (distort_z) {  // interior vertices moved along z only: the faces x = 2, y = 2 stay planes
    b.distortion = so::Distortion::random;
    b.amplitude = 0.3;
    const auto d = so::make_box<3>(b);
    for (std::size_t v = 0; v < m.vertices.size(); v += 3) m.vertices[v + 2] = d.vertices[v + 2];
  }
  m.active.assign(static_cast<std::size_t>(m.cell_count()), 1);
  for (int k = 0; k < 2; ++k)
    for (int j = 2; j < 4; ++j)
      for (int i = 2; i < 4; ++i) m.active[static_cast<std::size_t>(m.cell({i, j, k}))] = 0;
  return m;
}

// Volume of the elements whose centre lies at x > x_lo (Gauss quadrature of det J, exact for these maps).
double volume(const so::Discretization<3>& d, double x_lo) {
  const so::ElementEvaluator<3> ev(d);
  std::vector<double> xq, wq;
  pm::fem::gauss_legendre(d.n1d, xq, wq);
  const int Q = d.n1d, ND = d.nodes_per_element();
  double v = 0.0;
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    double xc = 0.0;
    for (int a = 0; a < ND; ++a) xc += d.coordinates[static_cast<std::size_t>(3 * d.element_nodes[e * ND + a])];
    if (xc / ND <= x_lo) continue;
    for (int q = 0; q < Q * Q * Q; ++q)
      v += wq[q % Q] * wq[(q / Q) % Q] * wq[q / (Q * Q)] *
           ev.at(static_cast<std::int64_t>(e), {xq[q % Q], xq[(q / Q) % Q], xq[q / (Q * Q)]}).det;
  }
  return v;
}

// The pentagon's area, centroid depth and second moment about the centroidal y axis by Green's theorem over
// its vertices (y, z), counter-clockwise: independent of the rectangle-plus-triangle split in the header.
struct Polygon {
  double area = 0.0, zc = 0.0, I = 0.0;
};
Polygon pentagon_by_vertices(double w, double h, double hs) {
  const double P[5][2] = {{-w / 2, 0.0}, {-w / 2, -hs}, {0.0, -h}, {w / 2, -hs}, {w / 2, 0.0}};
  double A = 0.0, Sz = 0.0, Izz = 0.0;
  for (int i = 0; i < 5; ++i) {
    const double y0 = P[i][0], z0 = P[i][1], y1 = P[(i + 1) % 5][0], z1 = P[(i + 1) % 5][1];
    const double c = y0 * z1 - y1 * z0;
    A += 0.5 * c;
    Sz += c * (z0 + z1) / 6.0;
    Izz += c * (z0 * z0 + z0 * z1 + z1 * z1) / 12.0;
  }
  Polygon p;
  p.area = A;
  p.zc = Sz / A;
  p.I = Izz - A * p.zc * p.zc;
  return p;
}

double compliance(const so::MicroCantileverSpec& s, const pm::materials::Stiffness6<double>& C) {
  so::LinearElastic<double, 3> m(so::micro_cantilever(s, C));
  m.solve_direct();
  return so::tip_deflection(m) / s.force;
}

}  // namespace

TEST(SolidMask, LShapedLatticeCounts) {
  for (int p = 1; p <= 3; ++p) {
    const so::StructuredMesh<3> m = l_shaped(false);
    const auto d = so::discretize(m, p, 1);
    // lattice points of the L: the full (4p + 1)^2 per layer less the (2p)^2 strictly inside the quadrant
    const std::int64_t expected = ((4 * p + 1) * (4 * p + 1) - 4 * p * p) * (2 * p + 1);
    std::printf("L-shape p=%d: %lld nodes (closed form %lld), %zu elements\n", p, static_cast<long long>(d.nodes),
                static_cast<long long>(expected), d.element_cells.size());
    EXPECT_EQ(d.nodes, expected);
    EXPECT_EQ(static_cast<std::int64_t>(d.element_cells.size()), m.active_cell_count());
    EXPECT_EQ(m.active_cell_count(), 24);
    EXPECT_EQ(d.chunk_start.size(), 25u);  // one cell per chunk: the 8 empty chunks left out
    // no node strictly inside the inactive block; every node used by an element
    std::vector<char> used(static_cast<std::size_t>(d.nodes), 0);
    for (const auto v : d.element_nodes) used[static_cast<std::size_t>(v)] = 1;
    for (std::int64_t v = 0; v < d.nodes; ++v) {
      const double x = d.coordinates[3 * v], y = d.coordinates[3 * v + 1];
      EXPECT_FALSE(x > 2.0 + 1e-12 && y > 2.0 + 1e-12) << "node " << v << " at " << x << ", " << y;
      EXPECT_TRUE(used[static_cast<std::size_t>(v)]);
      EXPECT_EQ(d.node(d.lattice_index(v)), v);
    }
    // sides: xmax holds the faces of the 2 x 2 active cells at i = 3 and the (2p + 1)^2 nodes on them
    EXPECT_EQ(so::side_faces(d, "xmax").size(), 4u * (p + 1) * (p + 1));
    EXPECT_EQ(so::side_nodes(d, "xmax").size(), static_cast<std::size_t>((2 * p + 1) * (2 * p + 1)));
    EXPECT_EQ(so::side_faces(d, "zmax").size(), 12u * (p + 1) * (p + 1));
    EXPECT_EQ(so::side_nodes(d, "zmax").size(), static_cast<std::size_t>(expected / (2 * p + 1)));
  }
}

TEST(SolidMask, AllActiveMaskEqualsNoMask) {
  so::BoxSpec b;
  b.cells = {3, 2, 2};
  b.distortion = so::Distortion::random;
  b.amplitude = 0.2;
  so::StructuredMesh<3> m = so::make_box<3>(b);
  const auto plain = so::discretize(m, 2, 2);
  m.active.assign(static_cast<std::size_t>(m.cell_count()), 1);
  const auto masked = so::discretize(m, 2, 2);
  EXPECT_EQ(plain.nodes, masked.nodes);
  EXPECT_EQ(plain.element_nodes, masked.element_nodes);
  EXPECT_EQ(plain.element_cells, masked.element_cells);
  EXPECT_EQ(plain.chunk_start, masked.chunk_start);
  EXPECT_EQ(plain.color_offsets, masked.color_offsets);
  EXPECT_EQ(plain.coordinates, masked.coordinates);
  for (const char* s : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
    EXPECT_EQ(so::side_nodes(plain, s), so::side_nodes(masked, s));
    EXPECT_EQ(so::side_faces(plain, s), so::side_faces(masked, s));
  }
  m.active.assign(static_cast<std::size_t>(m.cell_count()), 0);
  EXPECT_THROW(so::discretize(m, 2, 2), std::invalid_argument);
  m.active.assign(3, 1);
  EXPECT_THROW(so::discretize(m, 2, 2), std::invalid_argument);
}

// Patch test on the L-shaped lattice (cells distorted along z): uniaxial stress sigma_zz = s0 is the one
// linear state whose traction vanishes on the re-entrant faces x = 2, y = 2 that no side names, so
//   u = eps x + omega x + b,  eps = diag(-nu, -nu, 1) s0 / E,
// Dirichlet on xmin, ymin, zmin, the traction s0 e_z on the (L-shaped) top zmax, the rest free: exact.
TEST(SolidMask, PatchTestOnLShape) {
  const double E = 2.0, nu = 0.3, s0 = 1e-3;
  const double e[3] = {-nu * s0 / E, -nu * s0 / E, s0 / E}, w[3] = {2e-4, -1e-4, 3e-4}, b[3] = {1e-4, 2e-4, -1e-4};
  auto exact = [=](const double* x, double* u) {
    const double rot[3] = {w[1] * x[2] - w[2] * x[1], w[2] * x[0] - w[0] * x[2], w[0] * x[1] - w[1] * x[0]};
    for (int c = 0; c < 3; ++c) u[c] = e[c] * x[c] + rot[c] + b[c];
  };
  for (int p = 1; p <= 3; ++p) {
    so::Config<3> c;
    c.mesh = l_shaped(true);
    c.order = p;
    c.affine_geometry = false;
    c.stiffness = pm::materials::isotropic_stiffness(E, nu);
    for (const char* s : {"xmin", "ymin", "zmin"}) c.dirichlet.push_back({s, 7u, exact});
    c.tractions.push_back({"zmax", {0.0, 0.0, s0}});
    so::LinearElastic<double, 3> m(c);
    m.solve_direct();
    const auto u = m.displacement_host();
    const auto& d = m.discretization();
    double err = 0.0;
    for (std::int64_t v = 0; v < d.nodes; ++v) {
      double ue[3];
      exact(&d.coordinates[3 * v], ue);
      for (int k = 0; k < 3; ++k) err = std::max(err, std::abs(u[3 * v + k] - ue[k]));
    }
    std::printf("L-shape patch p=%d: %lld DoFs, max nodal error / |eps| %.2e\n", p,
                static_cast<long long>(m.dof_count()), err / (s0 / E));
    EXPECT_LT(err / (s0 / E), 1e-10) << "p " << p;
  }
}

TEST(SolidMicroCantilever, PentagonGeometry) {
  so::MicroCantileverSpec s;
  s.h_root = 0.4;
  s.order = 2;
  const Polygon poly = pentagon_by_vertices(s.width, s.height, s.wall);
  const so::PentagonSection sec = so::pentagon_section(s);
  std::printf("pentagon %.2f x %.2f (walls %.2f): area %.6f (header %.6f), centroid depth %.6f, I %.6f um^4 (header %.6f)\n",
              s.width, s.height, s.wall, poly.area, sec.area, -poly.zc, poly.I, sec.second_moment);
  EXPECT_NEAR(sec.area, poly.area, 1e-12);
  EXPECT_NEAR(sec.centroid_depth, -poly.zc, 1e-12);
  EXPECT_NEAR(sec.second_moment, poly.I, 1e-12);
  for (const double Lb : {0.0, 3.0}) {
    s.support_length = Lb;
    s.support_width = 8.0;
    s.support_depth = 5.0;
    so::LinearElastic<double, 3> m(so::micro_cantilever(s, pm::materials::isotropic_stiffness(200.0, 0.3)));
    const auto& d = m.discretization();
    const double beam = volume(d, 0.0), all = volume(d, -1e9);
    const double block = Lb * s.support_width * s.support_depth;
    std::printf("micro-cantilever L_b=%.0f: %lld elements, %lld DoFs, min det J ratio %.3f, beam volume %.9f "
                "(L A = %.9f), total %.9f (closed form %.9f)\n",
                Lb, static_cast<long long>(m.element_count()), static_cast<long long>(m.dof_count()),
                m.jacobian().min_ratio, beam, s.length * poly.area, all, block + s.length * poly.area);
    EXPECT_GT(m.jacobian().min_ratio, 0.05);
    EXPECT_NEAR(beam / (s.length * poly.area), 1.0, 1e-12);
    EXPECT_NEAR(all / (block + s.length * poly.area), 1.0, 1e-12);
    // the apex is a node and no beam node lies below the bottom faces
    bool apex = false;
    for (std::int64_t v = 0; v < d.nodes; ++v) {
      const double x = d.coordinates[3 * v], y = d.coordinates[3 * v + 1], z = d.coordinates[3 * v + 2];
      apex = apex || (std::abs(x - s.length) < 1e-12 && std::abs(y) < 1e-12 && std::abs(z + s.height) < 1e-12);
      if (x > 1e-12) {
        EXPECT_GE(z, -so::pentagon_depth(s, y) - 1e-12);
        EXPECT_LE(std::abs(y), 0.5 * s.width + 1e-12);
      }
    }
    EXPECT_TRUE(apex);
    // the loaded face carries the total force F
    const auto f = pm::models::to_host(m.external_force());
    double fz = 0.0;
    for (std::size_t i = 2; i < f.size(); i += 3) fz += f[i];
    EXPECT_NEAR(fz / -s.force, 1.0, 1e-12);
  }
}

// Slender clamped-root beam (L = 24, L / h = 16), isotropic E = 200, nu = 0 (the clamp adds no Poisson
// restraint): the work-conjugate tip deflection against P L^3 / (3 E I) + P L / (kappa G A) with the
// pentagon's I by Green's theorem and kappa = 5/6 (the shear term is 1.6e-3 of the total; kappa of the
// pentagon is not known in closed form, so +-0.1 in kappa moves the reference by 1.9e-4).
TEST(SolidMicroCantilever, SlenderBeamAgainstTimoshenko) {
  so::MicroCantileverSpec s;
  s.support_length = 0.0;
  s.length = 24.0;
  s.h_root = 0.75;  // 4 x 2 cells across
  s.growth = 1.0;
  s.h_beam_max = 0.75;
  const double E = 200.0, G = E / 2.0;
  const Polygon poly = pentagon_by_vertices(s.width, s.height, s.wall);
  const double bending = s.force * std::pow(s.length, 3) / (3.0 * E * poly.I);
  const double beam = bending + s.force * s.length / (5.0 / 6.0 * G * poly.area);
  {  // order 2 (order 3 measured 1.50e-4: the 1.3e-4 is the reference's kappa, not the mesh; its LU takes 20 s)
    const int p = 2;
    s.order = p;
    so::LinearElastic<double, 3> m(so::micro_cantilever(s, pm::materials::isotropic_stiffness(E, 0.0)));
    m.solve_direct();
    const double tip = so::tip_deflection(m);
    const double centroid = -so::displacement_at(m, {s.length, 0.0, poly.zc})[2];
    std::printf("slender pentagon p=%d (%lld DoFs): tip %.6f um, Timoshenko %.6f, Euler-Bernoulli %.6f, relative "
                "%.2e (centroid %.6f)\n",
                p, static_cast<long long>(m.dof_count()), tip, beam, bending, tip / beam - 1.0, centroid);
    // measured +1.26e-4 (3.193760 against 3.193358); Euler-Bernoulli alone is 1.6e-3 below, the rectangle
    // 2.5 x 1.5 (I = 0.703) a factor 1.95 off
    EXPECT_NEAR(tip / beam, 1.0, 5e-4);
  }
}

// The crystal orientation on a slender clamped-root beam of 8YSZ (L = 24): the compliance ratio of the <111>
// beam to the <001> beam against E<001> / E<111> = 2.37. Not exact: beam bending follows 1 / S'_11 (the
// axial compliance in the beam's axes) only for the bending part; the shear part follows the transverse
// shear compliance S'_55, which does not scale with S'_11 (shear / bending differs between the two
// orientations), and the clamped root restrains the crystal's Poisson and shear-extension couplings
// (S'_12, S'_13, S'_15) over about one depth, by an amount that differs with theta. Both effects are O(h / L)
// or O((h / L)^2), here a few per cent.
TEST(SolidMicroCantilever, OrientationEffect) {
  so::MicroCantileverSpec s;
  s.support_length = 0.0;
  s.length = 24.0;
  s.h_root = 0.75;
  s.growth = 1.0;
  s.h_beam_max = 0.75;
  const double t111 = std::atan(std::sqrt(2.0)) * 180.0 / 3.14159265358979323846;  // 54.7356 deg
  const auto k = pm::materials::ysz8_constants_gpa<double>();
  const double E001 = pm::materials::cubic_uniaxial_modulus(k, pm::materials::cantilever_axis(0.0));
  const double E111 = pm::materials::cubic_uniaxial_modulus(k, pm::materials::cantilever_axis(t111 * 3.14159265358979323846 / 180.0));
  const double c0 = compliance(s, so::ysz8_cantilever_stiffness(0.0));
  const double c1 = compliance(s, so::ysz8_cantilever_stiffness(t111));
  const Polygon poly = pentagon_by_vertices(s.width, s.height, s.wall);
  const double eb0 = std::pow(s.length, 3) / (3.0 * E001 * poly.I), eb1 = std::pow(s.length, 3) / (3.0 * E111 * poly.I);
  std::printf("orientation: E<001> %.1f GPa, E<111> %.1f GPa, ratio %.4f; compliance 0 deg %.5f um/mN (EB %.5f, "
              "%+.2f %%), 54.7 deg %.5f (EB %.5f, %+.2f %%), ratio %.4f (%+.2f %% from the modulus ratio)\n",
              E001, E111, E001 / E111, c0, eb0, 100 * (c0 / eb0 - 1), c1, eb1, 100 * (c1 / eb1 - 1), c1 / c0,
              100 * ((c1 / c0) / (E001 / E111) - 1));
  // measured: 35.1706 (+0.36 % from Euler-Bernoulli with E<001>), 81.8688 (-1.46 % with E<111>), ratio 2.3278,
  // 1.8 % below the modulus ratio 2.3707; a 3 % band (an isotropic E-scaled model would give 0 %, a wrong
  // rotation, e.g. <110> at 90 deg, E = 233 GPa, a ratio of 1.5)
  EXPECT_NEAR(E001 / E111, 2.37, 0.01);
  EXPECT_NEAR((c1 / c0) / (E001 / E111), 1.0, 0.03);
  EXPECT_NEAR(c0 / eb0, 1.0, 0.03);
  EXPECT_NEAR(c1 / eb1, 1.0, 0.03);
}
