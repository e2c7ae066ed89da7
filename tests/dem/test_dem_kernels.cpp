// DEM kernels: the Hertz-Mindlin force law (eqs. (11)-(17)) and the sphere-facet inside-outside
// regions (eqs. (1)-(10)), every region, one force per touching feature, continuity across edges and
// nodes, and a meshed flat wall against the analytic plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/sphere_facet.hpp"
#include "dem/contact_forces.hpp"
#include "dem/surface_loads.hpp"
#include "neighbors/transpose.hpp"

namespace pm = polymech;
namespace ct = polymech::contact;
namespace dm = polymech::dem;
using V3 = pm::Vec3<double>;

namespace {

struct HostContact {
  int region;
  long a, b;
  double overlap, n[3], q[3];
};

// Contacts of spheres (centres p, radius r) with facet f, evaluated in a kernel.
std::vector<HostContact> contacts(const ct::SurfaceMesh<double>& m, pm::Index f, const std::vector<V3>& p, double r) {
  const auto n = p.size();
  pm::VecView<double, 3> pts("pts", n);
  auto hp = Kokkos::create_mirror_view(pts);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) hp(i, k) = p[i][k];
  Kokkos::deep_copy(pts, hp);
  Kokkos::View<double* [9], Kokkos::LayoutRight, pm::MemSpace> out("out", n);
  Kokkos::parallel_for(
      "test::sphere_facet", pm::range(static_cast<std::int64_t>(n)), KOKKOS_LAMBDA(const std::int64_t i) {
        const auto c = ct::sphere_facet_contact(m, f, pm::load<3>(pts, i), r);
        out(i, 0) = static_cast<double>(c.region);
        out(i, 1) = static_cast<double>(c.node_a);
        out(i, 2) = static_cast<double>(c.node_b);
        out(i, 3) = c.overlap;
        for (int k = 0; k < 3; ++k) {
          out(i, 4 + k) = c.normal[k];
        }
        out(i, 7) = c.point[0];
        out(i, 8) = c.point[1];
      });
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
  std::vector<HostContact> r_out(n);
  for (std::size_t i = 0; i < n; ++i) {
    r_out[i].region = static_cast<int>(h(i, 0));
    r_out[i].a = static_cast<long>(h(i, 1));
    r_out[i].b = static_cast<long>(h(i, 2));
    r_out[i].overlap = h(i, 3);
    for (int k = 0; k < 3; ++k) r_out[i].n[k] = h(i, 4 + k);
    r_out[i].q[0] = h(i, 7);
    r_out[i].q[1] = h(i, 8);
  }
  return r_out;
}

// A flat grid of nx x ny unit quads at z = 0 (normal +z), spacing h, from the origin.
ct::SurfaceMesh<double> grid_mesh(int nx, int ny, double h, double z = 0.0) {
  std::vector<double> nodes;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      nodes.push_back(i * h);
      nodes.push_back(j * h);
      nodes.push_back(z);
    }
  std::vector<int> sizes;
  std::vector<pm::Index> fn;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const pm::Index n0 = j * (nx + 1) + i;
      sizes.push_back(4);
      for (pm::Index n : {n0, n0 + 1, n0 + nx + 2, n0 + nx + 1}) fn.push_back(n);
    }
  return ct::make_surface_mesh<double>(nodes, sizes, fn, "test_grid");
}

dm::SphereSet<double> spheres_at(const std::vector<V3>& p, double r, double density, const std::vector<V3>& v = {}) {
  dm::SphereSet<double> s;
  dm::allocate(s, static_cast<pm::Index>(p.size()), "test::");
  auto x = Kokkos::create_mirror_view(s.x);
  auto vel = Kokkos::create_mirror_view(s.v);
  auto rad = Kokkos::create_mirror_view(s.radius);
  auto m = Kokkos::create_mirror_view(s.mass);
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      x(i, k) = p[i][k];
      vel(i, k) = v.empty() ? 0.0 : v[i][k];
    }
    rad(i) = r;
    m(i) = density * 4.0 / 3.0 * dm::kPi * r * r * r;
  }
  Kokkos::deep_copy(s.x, x);
  Kokkos::deep_copy(s.x0, x);
  Kokkos::deep_copy(s.v, vel);
  Kokkos::deep_copy(s.radius, rad);
  Kokkos::deep_copy(s.mass, m);
  return s;
}

std::vector<V3> accelerations(const dm::SphereSet<double>& s) {
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.a);
  std::vector<V3> out(s.size());
  for (pm::Index i = 0; i < s.size(); ++i) out[i] = V3{{a(i, 0), a(i, 1), a(i, 2)}};
  return out;
}

// A two-set list with every facet for every sphere (n spheres, nf facets).
pm::neighbors::NeighborList every_facet(pm::Index n, pm::Index nf) {
  pm::neighbors::NeighborList all;
  all.offsets = Kokkos::View<pm::Offset*, pm::MemSpace>("off", n + 1);
  all.neighbors = Kokkos::View<pm::Index*, pm::MemSpace>("nbr", std::size_t(n * nf));
  auto ho = Kokkos::create_mirror_view(all.offsets);
  auto hn = Kokkos::create_mirror_view(all.neighbors);
  for (pm::Index i = 0; i <= n; ++i) ho(i) = i * nf;
  for (pm::Index i = 0; i < n; ++i)
    for (pm::Index f = 0; f < nf; ++f) hn(i * nf + f) = f;
  Kokkos::deep_copy(all.offsets, ho);
  Kokkos::deep_copy(all.neighbors, hn);
  all.num_particles = n;
  all.num_pairs = n * nf;
  return all;
}

// The accelerations from the surface (all facets listed for every sphere) and from the plane z = 0.
std::pair<std::vector<V3>, std::vector<V3>> mesh_and_plane(const ct::SurfaceMesh<double>& mesh, const std::vector<V3>& p,
                                                           double r, const std::vector<V3>& v = {}) {
  const double density = 2500;
  dm::HertzMindlin<double> law{5e10, 2e10, dm::damping_ratio(0.8), 0.3};
  auto s = spheres_at(p, r, density, v);
  const pm::Index nf = mesh.facet_count(), n = s.size();
  const auto all = every_facet(n, nf);
  dm::SpringView<double> hist("hist", std::size_t(n * nf));
  dm::body_forces(s, V3::zero());
  dm::sphere_facet_forces(s, mesh, all, hist, law, true, 1e-6);
  const auto from_mesh = accelerations(s);
  dm::PlaneView<double> plane("plane", 1);
  auto hpl = Kokkos::create_mirror_view(plane);
  for (int k = 0; k < 6; ++k) hpl(0, k) = k == 5 ? 1.0 : 0.0;
  Kokkos::deep_copy(plane, hpl);
  dm::SpringView<double> phist("phist", std::size_t(n));
  dm::body_forces(s, V3::zero());
  dm::sphere_plane_forces(s, plane, phist, law, true, 1e-6);
  return {from_mesh, accelerations(s)};
}

}  // namespace

TEST(HertzMindlin, StaticNormalForceIsHertz) {
  dm::HertzMindlin<double> law{4e10, 1.5e10, 0.0, 0.5};
  V3 xi = V3::zero();
  const double r = 0.01, m = 0.01, delta = 1e-5;
  const auto c = dm::hertz_mindlin_force(law, r, m, delta, V3{{0, 0, 1}}, V3::zero(), true, 1e-7, xi);
  const double expected = 4.0 / 3.0 * 4e10 * std::sqrt(r) * std::pow(delta, 1.5);
  EXPECT_NEAR(c.normal, expected, 1e-12 * expected);
  EXPECT_NEAR(c.force[2], expected, 1e-12 * expected);
  EXPECT_EQ(c.force[0], 0.0);
}

TEST(HertzMindlin, TangentialSpringIsMindlinAndCoulombLimited) {
  dm::HertzMindlin<double> law{4e10, 1.5e10, 0.0, 0.3};
  const double r = 0.01, m = 0.01, delta = 1e-5, dt = 1e-7;
  // a small tangential displacement: F_t = -8 G* sqrt(R delta) xi
  V3 xi = V3::zero();
  const auto c = dm::hertz_mindlin_force(law, r, m, delta, V3{{0, 0, 1}}, V3{{1e-3, 0, 0}}, true, dt, xi);
  EXPECT_NEAR(xi[0], 1e-10, 1e-22);
  EXPECT_NEAR(c.force[0], -8 * 1.5e10 * std::sqrt(r * delta) * 1e-10, 1e-9);
  // a large one: |F_t| = mu F_n, the spring shortened to match
  xi = V3{{1e-3, 0, 0}};
  const auto s = dm::hertz_mindlin_force(law, r, m, delta, V3{{0, 0, 1}}, V3::zero(), true, dt, xi);
  EXPECT_NEAR(std::abs(s.force[0]), 0.3 * s.normal, 1e-9 * s.normal);
  EXPECT_NEAR(8 * 1.5e10 * std::sqrt(r * delta) * xi[0], 0.3 * s.normal, 1e-9 * s.normal);
  // the spring is rotated into the tangent plane, its length kept
  xi = V3{{3e-9, 0, 4e-9}};
  (void)dm::hertz_mindlin_force(law, r, m, delta, V3{{0, 0, 1}}, V3::zero(), true, dt, xi);
  EXPECT_NEAR(xi[0], 5e-9, 1e-20);
  EXPECT_EQ(xi[2], 0.0);
}

TEST(HertzMindlin, EffectiveModuliAndRigidWall) {
  EXPECT_NEAR(dm::effective_modulus(4.8e10, 0.2, 4.8e10, 0.2), 2.5e10, 1.0);
  EXPECT_NEAR(dm::effective_modulus(7e10, 0.33, 0.0, 0.0), 7e10 / (1 - 0.33 * 0.33), 1.0);
  const double g = 7e10 / 2.66;
  EXPECT_NEAR(dm::effective_shear_modulus(7e10, 0.33, 0.0, 0.0), g / 1.67, 1.0);
  EXPECT_NEAR(dm::damping_ratio(1.0), 0.0, 1e-15);
  EXPECT_LT(dm::damping_ratio(0.5), 0.0);
}

TEST(SphereFacet, EveryRegionOfAQuad) {
  const auto m = grid_mesh(1, 1, 1.0);  // nodes 0 (0,0) 1 (1,0) 2 (0,1) 3 (1,1); facet 0-1-3-2
  const double r = 0.1;
  const auto c = contacts(m, 0,
                          {V3{{0.5, 0.4, 0.05}}, V3{{1.03, 0.5, 0.05}}, V3{{1.03, 1.04, 0.05}}, V3{{-0.02, 0.5, 0.0}},
                           V3{{0.5, 0.5, 0.2}}, V3{{0.5, 0.5, -0.12}}, V3{{0.5, 0.5, -0.05}}, V3{{1.2, 0.5, 0.0}},
                           V3{{0.5, -0.05, -0.05}}},
                          r);
  // PTF: overlap r - d along +z
  EXPECT_EQ(c[0].region, int(ct::FacetRegion::facet));
  EXPECT_NEAR(c[0].overlap, 0.05, 1e-14);
  EXPECT_NEAR(c[0].n[2], 1.0, 1e-14);
  EXPECT_NEAR(c[0].q[0], 0.5, 1e-14);
  // PTE: edge 1-3 (x = 1), Q = (1, 0.5, 0)
  EXPECT_EQ(c[1].region, int(ct::FacetRegion::edge));
  EXPECT_EQ(c[1].a, 1);
  EXPECT_EQ(c[1].b, 3);
  EXPECT_NEAR(c[1].overlap, r - std::hypot(0.03, 0.05), 1e-14);
  EXPECT_NEAR(c[1].q[1], 0.5, 1e-14);
  EXPECT_NEAR(c[1].n[0], 0.03 / std::hypot(0.03, 0.05), 1e-14);
  // PTN: node 3 at (1, 1)
  EXPECT_EQ(c[2].region, int(ct::FacetRegion::node));
  EXPECT_EQ(c[2].a, 3);
  EXPECT_NEAR(c[2].overlap, r - std::sqrt(0.03 * 0.03 + 0.04 * 0.04 + 0.05 * 0.05), 1e-14);
  // PTE in the plane of the facet: edge 2-0 (x = 0), normal -x
  EXPECT_EQ(c[3].region, int(ct::FacetRegion::edge));
  EXPECT_EQ(c[3].a, 0);
  EXPECT_EQ(c[3].b, 2);
  EXPECT_NEAR(c[3].n[0], -1.0, 1e-14);
  // too far above, more than r behind, farther than r from every edge: none
  EXPECT_EQ(c[4].region, int(ct::FacetRegion::none));
  EXPECT_EQ(c[5].region, int(ct::FacetRegion::none));
  EXPECT_EQ(c[7].region, int(ct::FacetRegion::none));
  // a centre behind the facet plane (less than r) is still pushed out along +z: overlap r + |d|
  EXPECT_EQ(c[6].region, int(ct::FacetRegion::facet));
  EXPECT_NEAR(c[6].overlap, 0.15, 1e-14);
  // below the plane and outside an edge: the other side's business
  EXPECT_EQ(c[8].region, int(ct::FacetRegion::none));
}

TEST(SphereFacet, TriangleAndWarpedQuad) {
  // a triangle (0,0,0) (1,0,0) (0,1,0) and a quad with one node lifted (warped): normal of the diagonals
  std::vector<double> nodes = {0, 0, 0, 1, 0, 0, 0, 1, 0, 3, 0, 0, 4, 0, 0.1, 4, 1, 0, 3, 1, 0.1};
  const auto m = ct::make_surface_mesh<double>(nodes, {3, 4}, {0, 1, 2, 3, 4, 5, 6}, "tri_quad");
  const auto t = contacts(m, 0, {V3{{0.2, 0.2, 0.05}}, V3{{0.55, 0.55, 0.0}}}, 0.1);
  EXPECT_EQ(t[0].region, int(ct::FacetRegion::facet));
  EXPECT_NEAR(t[0].overlap, 0.05, 1e-14);
  EXPECT_EQ(t[1].region, int(ct::FacetRegion::edge));  // the hypotenuse 1-2
  EXPECT_EQ(t[1].a, 1);
  EXPECT_EQ(t[1].b, 2);
  EXPECT_NEAR(t[1].overlap, 0.1 - std::sqrt(2 * 0.05 * 0.05), 1e-14);
  const auto q = contacts(m, 1, {V3{{3.5, 0.5, 0.1}}}, 0.1);
  EXPECT_EQ(q[0].region, int(ct::FacetRegion::facet));
  // the mean plane passes through the centroid (3.5, 0.5, 0.05) with normal (x2-x0) x (x3-x1) = (0, 0, 1)-ish
  EXPECT_NEAR(q[0].n[2], 1.0, 1e-12);
  EXPECT_NEAR(q[0].overlap, 0.05, 1e-12);
}

TEST(SphereFacet, OneForceAtSharedEdgesAndNodesAndMeshEqualsPlane) {
  const auto mesh = grid_mesh(2, 2, 0.5);  // four quads, a shared node at (0.5, 0.5)
  const double r = 0.05;
  std::vector<V3> p;
  // across the shared edge x = 0.5, on it, and over the shared node, sliding along x and diagonally
  for (int k = 0; k <= 40; ++k) p.push_back(V3{{0.45 + 0.0025 * k, 0.3, 0.048}});
  for (int k = 0; k <= 40; ++k) p.push_back(V3{{0.45 + 0.0025 * k, 0.45 + 0.0025 * k, 0.046}});
  p.push_back(V3{{0.5, 0.5, 0.04}});
  std::vector<V3> v(p.size(), V3{{0.3, -0.2, -0.5}});
  const auto [from_mesh, from_plane] = mesh_and_plane(mesh, p, r, v);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(from_mesh[i][k], from_plane[i][k], 1e-9 * std::abs(from_plane[i][2])) << "sphere " << i << " comp " << k;
  EXPECT_GT(from_plane.back()[2], 0.0);
}

TEST(SphereFacet, ConvexRidgeGivesOneContinuousForce) {
  // two facets meeting at a ridge along y at x = 1 (the second tilted down by 30 degrees)
  const double c = std::cos(M_PI / 6), s = std::sin(M_PI / 6);
  std::vector<double> nodes = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 1 + c, 0, -s, 1 + c, 1, -s};
  const auto mesh = ct::make_surface_mesh<double>(nodes, {4, 4}, {0, 1, 2, 3, 1, 4, 5, 2}, "ridge");
  const double r = 0.1;
  const double d = r - 0.002;
  // a sphere rolling over the ridge at distance d from the surface: on the first facet, round the
  // ridge (the normal turning from +z to the second facet's), on the second facet
  std::vector<V3> p = {V3{{0.8, 0.5, d}}};
  for (int k = 0; k <= 40; ++k) {
    const double ang = (M_PI / 6) * k / 40.0;
    p.push_back(V3{{1 + d * std::sin(ang), 0.5, d * std::cos(ang)}});
  }
  p.push_back(V3{{1 + 0.3 * c + d * s, 0.5, -0.3 * s + d * c}});
  const auto all = mesh_and_plane(mesh, p, r).first;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double f = std::sqrt(all[i][0] * all[i][0] + all[i][1] * all[i][1] + all[i][2] * all[i][2]);
    // one contact of overlap 0.002 (Hertz force of the same magnitude all the way round)
    EXPECT_NEAR(f, std::sqrt(all[0][0] * all[0][0] + all[0][2] * all[0][2]), 1e-9 * f) << i;
  }
}

// A moving surface (a wheel's tread): the relative velocity of the contact is the sphere's less the
// facet's material point's, so spheres at rest on a sliding, turning surface are dragged along its
// motion at each contact point; the reaction rows the kernel writes are minus the spheres' forces and
// their moments about the motion's centre, to round-off (what the wheel feels is what the gravel gets).
TEST(SphereFacet, AMovingSurfaceDragsSpheresAndFeelsTheirReaction) {
  const auto mesh = grid_mesh(4, 4, 0.01);
  const double r = 0.004, delta = 2e-6, density = 2500, dt = 1e-6;
  std::vector<V3> p;
  for (double x : {0.006, 0.017, 0.031})
    for (double y : {0.008, 0.024, 0.035}) p.push_back(V3{{x, y, r - delta}});
  auto s = spheres_at(p, r, density);
  const pm::Index n = s.size(), nf = mesh.facet_count();
  const auto all = every_facet(n, nf);
  dm::SpringView<double> hist("hist", std::size_t(n * nf));
  dm::WrenchView<double> reaction("reaction", std::size_t(n));
  dm::SurfaceMotion<double> motion;
  motion.centre = V3{{0.02, 0.02, 0.0}};
  motion.velocity = V3{{0.3, -0.1, 0.0}};
  motion.omega = V3{{0.0, 0.0, 20.0}};
  const dm::HertzMindlin<double> law{5e10, 2e10, dm::damping_ratio(0.5), 0.4};
  dm::body_forces(s, V3::zero());
  dm::sphere_facet_forces(s, mesh, all, hist, law, true, dt, motion, reaction);
  const auto a = accelerations(s);
  auto hr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), reaction);
  const double m = density * 4.0 / 3.0 * dm::kPi * r * r * r;
  V3 force_sum = V3::zero(), moment_sum = V3::zero(), reaction_force = V3::zero(), reaction_moment = V3::zero();
  for (pm::Index i = 0; i < n; ++i) {
    const V3 f = m * a[i], q{{p[i][0], p[i][1], 0.0}};
    const V3 u = motion.at(q);  // the surface under sphere i
    const V3 ft{{f[0], f[1], 0.0}};
    EXPECT_NEAR(f[2], 4.0 / 3.0 * 5e10 * std::sqrt(r) * std::pow(delta, 1.5), 1e-9 * f[2]) << "sphere " << i;
    // dragged along: the tangential force is parallel to the surface's velocity there
    EXPECT_GT(dot(ft, u), 0.999 * norm(ft) * norm(u)) << "sphere " << i;
    force_sum += f;
    moment_sum += cross(q - motion.centre, f);
    for (int k = 0; k < 3; ++k) {
      reaction_force[k] += hr(i, k);
      reaction_moment[k] += hr(i, 3 + k);
    }
  }
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(reaction_force[k], -force_sum[k], 1e-12 * norm(force_sum)) << k;
    EXPECT_NEAR(reaction_moment[k], -moment_sum[k], 1e-12 * norm(force_sum) * 0.03) << k;
  }
  EXPECT_GT(norm(moment_sum), 0.0);
}

// A deforming surface (the FE tyre's, issue 37) whose nodes move with a rigid motion: the material velocity
// interpolated from the nodes at the contact point (contact/facet_weights.hpp) is the rigid one (bilinear
// interpolation reproduces a linear field on a flat grid), so the spheres get the rigid surface's forces; the
// node loads gathered over the list's transpose by facet add up to minus the spheres' forces, and their moment
// to minus the spheres' moment (the weights reproduce the contact point): the momentum exchange is exact.
// Three of the spheres touch a facet's face, one an edge and one a node (regions of eqs. (3)-(10)).
TEST(SphereFacet, ADeformingSurfaceReturnsTheForcesToItsNodes) {
  const auto rigid = grid_mesh(4, 4, 0.01), deforming = grid_mesh(4, 4, 0.01);
  const double r = 0.004, delta = 2e-6, density = 2500, dt = 1e-6;
  std::vector<V3> p;
  for (double x : {0.006, 0.017, 0.031}) p.push_back(V3{{x, 0.013, r - delta}});
  p.push_back(V3{{0.02, 0.025, r - delta}});  // over the edge y ... x = 0.02
  p.push_back(V3{{0.03, 0.03, r - delta}});   // over a node
  const pm::Index n = static_cast<pm::Index>(p.size()), nf = rigid.facet_count();
  const auto all = every_facet(n, nf);
  dm::SurfaceMotion<double> motion;
  motion.centre = V3{{0.02, 0.02, 0.0}};
  motion.velocity = V3{{0.3, -0.1, 0.0}};
  motion.omega = V3{{0.0, 0.0, 20.0}};
  const dm::HertzMindlin<double> law{5e10, 2e10, dm::damping_ratio(0.5), 0.4};
  auto s1 = spheres_at(p, r, density), s2 = spheres_at(p, r, density);
  dm::SpringView<double> h1("h1", std::size_t(n * nf)), h2("h2", std::size_t(n * nf));
  dm::body_forces(s1, V3::zero());
  dm::body_forces(s2, V3::zero());
  dm::sphere_facet_forces(s1, rigid, all, h1, law, true, dt, motion);
  // the nodes' velocities: the rigid motion at each node
  const pm::Index nn = deforming.node_count();
  pm::VecView<double, 3> node_v("node_v", std::size_t(nn)), node_f("node_f", std::size_t(nn));
  auto hx = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), deforming.nodes);
  auto hv = Kokkos::create_mirror_view(node_v);
  for (pm::Index k = 0; k < nn; ++k) {
    const V3 u = motion.at(V3{{hx(k, 0), hx(k, 1), hx(k, 2)}});
    for (int q = 0; q < 3; ++q) hv(k, q) = u[q];
  }
  Kokkos::deep_copy(node_v, hv);
  dm::EntryLoadView<double> entry("entry", std::size_t(n * nf));
  dm::sphere_deforming_facet_forces(s2, deforming, all, h2, law, true, dt, node_v, entry);
  pm::neighbors::ListTranspose by_facet;
  pm::neighbors::transpose(all, by_facet, nf);
  std::vector<int> sizes(static_cast<std::size_t>(nf), 4);
  auto hfac = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), deforming.facets);
  std::vector<pm::Index> fn;
  for (pm::Index f = 0; f < nf; ++f)
    for (int a = 0; a < 4; ++a) fn.push_back(hfac(f, a));
  dm::surface_node_loads(dm::surface_adjacency(nn, sizes, fn), by_facet, entry, node_f);
  const auto a1 = accelerations(s1), a2 = accelerations(s2);
  const double m = density * 4.0 / 3.0 * dm::kPi * r * r * r;
  V3 force_sum = V3::zero(), moment_sum = V3::zero(), node_force = V3::zero(), node_moment = V3::zero();
  for (pm::Index i = 0; i < n; ++i) {
    const V3 f = m * a2[i];
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a2[i][k], a1[i][k], 1e-12 * norm(a1[i])) << "sphere " << i << " component " << k;
    force_sum += f;
    moment_sum += cross(V3{{p[i][0], p[i][1], 0.0}}, f);  // every contact point is under its sphere's centre
  }
  auto hf = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), node_f);
  int loaded = 0;
  for (pm::Index k = 0; k < nn; ++k) {
    const V3 f{{hf(k, 0), hf(k, 1), hf(k, 2)}};
    loaded += norm(f) > 0 ? 1 : 0;
    node_force += f;
    node_moment += cross(V3{{hx(k, 0), hx(k, 1), hx(k, 2)}}, f);
  }
  // face contacts share 4 nodes, the edge's 2, the node's 1: (3 x 4 - 0 shared) + 2 + 1 distinct nodes at most
  EXPECT_GE(loaded, 7);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(node_force[k], -force_sum[k], 1e-12 * norm(force_sum)) << k;
    EXPECT_NEAR(node_moment[k], -moment_sum[k], 1e-12 * norm(force_sum) * 0.03) << k;
  }
  EXPECT_GT(norm(force_sum), 0.0);
}

// The sphere-sphere rows (on a host: blocks of 16 spheres, the law vectorised over each block's touching pairs,
// dem/pair_batch.cpp) and the gather against a plain pair-by-pair sum of contact::hertz_mindlin_force: a random
// cloud dense enough that a block holds more touching pairs than one batch (64), springs of every size (some
// pairs slip, some are new, some listed pairs apart), spheres of two clumps. Forces, torques (both members) and
// the updated springs agree to round-off; every listed pair apart has its spring dropped.
TEST(SphereSphere, RowsAndGatherAreThePairByPairSums) {
  const pm::Index n = 320;
  const double side = 0.1, skin = 0.004, dt = 1e-6;
  const dm::HertzMindlin<double> law{3e7, 1.2e7, dm::damping_ratio(0.5), 0.5};
  unsigned state = 12345u;
  auto uniform = [&state](double lo, double hi) {
    state = state * 1664525u + 1013904223u;
    return lo + (hi - lo) * ((state >> 8) & 0xffffffu) / double(0x1000000);
  };
  dm::SphereSet<double> s;
  dm::allocate(s, n, "s_");
  s.body = pm::View1<int>("body", std::size_t(n));
  auto hx = Kokkos::create_mirror_view(s.x);
  auto hv = Kokkos::create_mirror_view(s.v);
  auto hw = Kokkos::create_mirror_view(s.omega);
  auto hr = Kokkos::create_mirror_view(s.radius);
  auto hm = Kokkos::create_mirror_view(s.mass);
  auto hb = Kokkos::create_mirror_view(s.body);
  for (pm::Index i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      hx(i, k) = uniform(0.0, side);
      hv(i, k) = uniform(-1.0, 1.0);
      hw(i, k) = uniform(-50.0, 50.0);
    }
    hr(i) = uniform(0.009, 0.011);
    hm(i) = 2650.0 * 4.0 / 3.0 * ct::kPi * hr(i) * hr(i) * hr(i);
    hb(i) = i < 40 ? int(i / 20) : -1;  // two clumps of 20 (their pairs never touch)
  }
  Kokkos::deep_copy(s.x, hx);
  Kokkos::deep_copy(s.v, hv);
  Kokkos::deep_copy(s.omega, hw);
  Kokkos::deep_copy(s.radius, hr);
  Kokkos::deep_copy(s.mass, hm);
  Kokkos::deep_copy(s.body, hb);
  // the half list within r_i + r_j + skin (brute force) and a spring per pair
  std::vector<pm::Offset> offsets{0};
  std::vector<pm::Index> neighbors;
  auto dist2 = [&](pm::Index i, pm::Index j) {
    double d2 = 0;
    for (int k = 0; k < 3; ++k) d2 += (hx(i, k) - hx(j, k)) * (hx(i, k) - hx(j, k));
    return d2;
  };
  for (pm::Index i = 0; i < n; ++i) {
    for (pm::Index j = i + 1; j < n; ++j)
      if (dist2(i, j) < (hr(i) + hr(j) + skin) * (hr(i) + hr(j) + skin)) neighbors.push_back(j);
    offsets.push_back(static_cast<pm::Offset>(neighbors.size()));
  }
  const auto pairs = static_cast<pm::Offset>(neighbors.size());
  pm::neighbors::NeighborList list;
  list.offsets = Kokkos::View<pm::Offset*, pm::MemSpace>("offsets", offsets.size());
  list.neighbors = Kokkos::View<pm::Index*, pm::MemSpace>("neighbors", neighbors.size());
  Kokkos::deep_copy(list.offsets, Kokkos::View<pm::Offset*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>>(offsets.data(), offsets.size()));
  Kokkos::deep_copy(list.neighbors, Kokkos::View<pm::Index*, Kokkos::HostSpace, Kokkos::MemoryTraits<Kokkos::Unmanaged>>(neighbors.data(), neighbors.size()));
  list.num_particles = n;
  list.num_pairs = pairs;
  list.kind = pm::neighbors::ListKind::half;
  dm::SpringView<double> hist("hist", std::size_t(pairs));
  auto hh = Kokkos::create_mirror_view(hist);
  for (pm::Offset k = 0; k < pairs; ++k) {
    const double size = k % 5 == 0 ? 0.0 : k % 5 == 1 ? 1e-3 : 1e-6;  // new, slipping, sticking
    for (int q = 0; q < 3; ++q) hh(k, q) = size * uniform(-1.0, 1.0);
  }
  Kokkos::deep_copy(hist, hh);
  // the reference: each listed pair in order, the law on the host
  std::vector<V3> f_ref(n, V3::zero()), t_ref(n, V3::zero());
  std::vector<V3> xi_ref(static_cast<std::size_t>(pairs), V3::zero());
  int touching = 0, most_in_a_block = 0, in_block = 0, slipping = 0;
  for (pm::Index i = 0; i < n; ++i) {
    if (i % 16 == 0) in_block = 0;
    for (pm::Offset k = offsets[i]; k < offsets[i + 1]; ++k) {
      const pm::Index j = neighbors[std::size_t(k)];
      const double reach = hr(i) + hr(j), d2 = dist2(i, j);
      if (!(d2 < reach * reach) || (hb(i) >= 0 && hb(i) == hb(j))) continue;
      ++touching;
      most_in_a_block = std::max(most_in_a_block, ++in_block);
      const double dist = std::sqrt(d2), delta = reach - dist;
      V3 n_ji, vi, wi, vj, wj, xi;
      for (int q = 0; q < 3; ++q) {
        n_ji[q] = (hx(i, q) - hx(j, q)) / dist;
        vi[q] = hv(i, q), wi[q] = hw(i, q), vj[q] = hv(j, q), wj[q] = hw(j, q), xi[q] = hh(k, q);
      }
      const double li = hr(i) - 0.5 * delta, lj = hr(j) - 0.5 * delta;
      const V3 v_rel = vi + cross(wi, (-li) * n_ji) - vj - cross(wj, lj * n_ji);
      const auto c = dm::hertz_mindlin_force(law, hr(i) * hr(j) / reach, hm(i) * hm(j) / (hm(i) + hm(j)), delta, n_ji, v_rel, true, dt, xi);
      xi_ref[std::size_t(k)] = xi;
      const V3 f_t = c.force - dot(c.force, n_ji) * n_ji;
      if (c.normal > 0 && norm(f_t) > (1.0 - 1e-9) * law.mu * c.normal) ++slipping;
      const V3 nxf = cross(n_ji, c.force);
      f_ref[std::size_t(i)] += c.force;
      f_ref[std::size_t(j)] -= c.force;
      t_ref[std::size_t(i)] -= li * nxf;
      t_ref[std::size_t(j)] -= lj * nxf;
    }
  }
  ASSERT_GT(most_in_a_block, 64) << "the cloud must fill a batch";
  dm::body_forces(s, V3::zero());
  dm::PairLoadView<double> pair_load("pair_load", std::size_t(pairs));
  pm::neighbors::ListTranspose transposed;
  pm::neighbors::transpose(list, transposed, n);
  dm::sphere_sphere_rows(s, list, hist, pair_load, law, true, dt);
  dm::sphere_sphere_gather(s, transposed, pair_load);
  auto ha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.a);
  auto hal = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.alpha);
  Kokkos::deep_copy(hh, hist);
  double f_max = 0.0, t_max = 0.0;
  for (pm::Index i = 0; i < n; ++i) {
    f_max = std::max(f_max, norm(f_ref[std::size_t(i)]));
    t_max = std::max(t_max, norm(t_ref[std::size_t(i)]));
  }
  for (pm::Index i = 0; i < n; ++i) {
    const double inertia = 0.4 * hm(i) * hr(i) * hr(i);
    for (int q = 0; q < 3; ++q) {
      EXPECT_NEAR(ha(i, q) * hm(i), f_ref[std::size_t(i)][q], 1e-12 * f_max) << i;
      EXPECT_NEAR(hal(i, q) * inertia, t_ref[std::size_t(i)][q], 1e-12 * t_max) << i;
    }
  }
  for (pm::Offset k = 0; k < pairs; ++k) {
    const V3& want = xi_ref[std::size_t(k)];
    for (int q = 0; q < 3; ++q) EXPECT_NEAR(hh(k, q), want[q], 1e-12 * (norm(want) + 1e-9)) << k;
  }
  std::printf("%lld listed pairs, %d touching, at most %d in a block of 16 spheres, %d at the Coulomb limit\n",
              static_cast<long long>(pairs), touching, most_in_a_block, slipping);
  EXPECT_GT(slipping, 0);
  EXPECT_LT(touching, static_cast<int>(pairs));
}
