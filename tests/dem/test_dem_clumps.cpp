// Multi-sphere clumps (issue 13, seed 002 paper 2 sec. 2): mass properties of a union of spheres
// computed numerically against closed forms, a one-sphere clump against a free sphere, torque-free
// rotation of an asymmetric clump (angular momentum exact, energy bounded, members rigid), momentum
// exchange between two clumps, and a clump dropped on a floor with friction comes to rest (it does not
// roll away as a sphere does).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "dem/dem.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

constexpr double kPi = 3.14159265358979323846;

double sphere_volume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

// Union of two spheres of radius r at distance d < 2 r: two spheres minus the lens.
double two_sphere_union(double r, double d) { return 2 * sphere_volume(r) - kPi * (4 * r + d) * (2 * r - d) * (2 * r - d) / 12; }

dm::Config quiet(const std::vector<std::string>& effects) {
  dm::Config c;
  c.particle = {1e8, 0.3, 2500};
  c.wall = {1e8, 0.3, 2500};
  c.restitution = 0.5;
  c.friction = 0.5;
  c.max_speed = 2.0;
  c.effects = pm::EffectSet::resolve(effects, dm::effect_table());
  return c;
}

double distance(const dm::Dem<double>& m, pm::Index i, pm::Index j) {
  const auto a = m.sphere(i), b = m.sphere(j);
  return std::sqrt((a.x[0] - b.x[0]) * (a.x[0] - b.x[0]) + (a.x[1] - b.x[1]) * (a.x[1] - b.x[1]) + (a.x[2] - b.x[2]) * (a.x[2] - b.x[2]));
}

}  // namespace

TEST(ClumpMass, OneSphereAndTwoOverlappingSpheresMatchClosedForms) {
  const dm::ClumpShape one{"one", {{0.1, -0.2, 0.3, 1.0}}};
  const auto p = dm::union_mass_properties(one, 200);
  EXPECT_NEAR(p.volume / sphere_volume(1.0), 1.0, 1e-4);
  EXPECT_NEAR(p.centre[0], 0.1, 1e-6);
  EXPECT_NEAR(p.centre[2], 0.3, 1e-6);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.principal[k] / (0.4 * sphere_volume(1.0)), 1.0, 1e-3);

  // two spheres 1.2 r apart: the overlap is counted once (adding sphere masses would be 9 % heavier)
  const dm::ClumpShape two{"two", {{0, 0, 0, 1.0}, {0, 0, 1.2, 1.0}}};
  const auto q = dm::union_mass_properties(two, 200);
  EXPECT_NEAR(q.volume / two_sphere_union(1.0, 1.2), 1.0, 1e-4);
  EXPECT_NEAR(q.centre[2], 0.6, 1e-6);
  // the long axis (z) has the smallest moment; the eigenvectors rebuild the tensor
  EXPECT_NEAR(std::abs(q.axes[2][0]), 1.0, 1e-9);
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      double t = 0;
      for (int k = 0; k < 3; ++k) t += q.axes[a][k] * q.principal[k] * q.axes[b][k];
      EXPECT_NEAR(t, q.inertia[a][b], 1e-12 * q.principal[2]);
    }
}

TEST(ClumpMass, ConvergesWithTheColumnCount) {
  const dm::ClumpShape two{"two", {{0, 0, 0, 1.0}, {0.3, 0.2, 1.2, 0.8}}};
  const double d = std::sqrt(0.3 * 0.3 + 0.2 * 0.2 + 1.2 * 1.2);
  // union of radii 1 and 0.8 at distance d: lens volume of two spheres (closed form)
  const double R1 = 1.0, R2 = 0.8;
  const double lens = kPi * (R1 + R2 - d) * (R1 + R2 - d) *
                      (d * d + 2 * d * R2 - 3 * R2 * R2 + 2 * d * R1 + 6 * R1 * R2 - 3 * R1 * R1) / (12 * d);
  const double exact = sphere_volume(R1) + sphere_volume(R2) - lens;
  // the midpoint rule across the silhouette converges irregularly (~ n^-1.5 on average)
  const double e25 = std::abs(dm::union_mass_properties(two, 25).volume / exact - 1.0);
  for (int n : {100, 200, 400}) {
    const double error = std::abs(dm::union_mass_properties(two, n).volume / exact - 1.0);
    EXPECT_LT(error, e25 / 10) << n << " columns";
    if (n >= 200) {
      EXPECT_LT(error, 2e-5) << n << " columns";
    }
  }
}

TEST(ClumpMass, GravelShapesHaveUnitReachAndCentredMass) {
  ASSERT_EQ(dm::gravel_shapes().size(), 3u);
  for (const auto& s : dm::gravel_shapes()) {
    const auto p = dm::union_mass_properties(s, 200);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.centre[k], 0.0, 2e-3) << s.name;
    double reach = 0;
    for (const auto& sp : s.spheres) reach = std::max(reach, std::sqrt(sp[0] * sp[0] + sp[1] * sp[1] + sp[2] * sp[2]) + sp[3]);
    EXPECT_NEAR(reach, 1.0, 1e-12) << s.name;
    EXPECT_GT(p.volume, 0.3) << s.name;
    EXPECT_LT(p.volume, sphere_volume(1.0)) << s.name;
  }
}

// A clump of one sphere bounces on a floor with friction and damping exactly as the free sphere does.
TEST(Clumps, AOneSphereClumpMovesAsAFreeSphere) {
  dm::Config free = quiet({"friction", "damping"});
  free.gravity = {0, 0, -9.81};
  dm::SphereInit s;
  s.radius = 0.005;
  s.position = {0, 0, 0.006};
  s.velocity = {0.3, 0, -0.5};
  s.omega = {0, 20, 0};
  free.spheres = {s};
  dm::PlaneInit floor;
  floor.normal = {0, 0, 1};
  free.planes = {floor};
  free.dt = 2e-7;

  dm::Config clumped = free;
  clumped.spheres.clear();
  clumped.effects = pm::EffectSet::resolve({"friction", "damping", "clumps"}, dm::effect_table());
  clumped.clump_shapes = {{"one", {{0, 0, 0, 1.0}}}};
  dm::ClumpInit k;
  k.scale = s.radius;
  k.position = s.position;
  k.velocity = s.velocity;
  k.omega = s.omega;
  clumped.clumps = {k};
  clumped.mass_columns = 800;  // the numerical mass and inertia within ~1e-5 of the sphere's

  dm::Dem<double> a(free), b(clumped);
  pm::models::run(a, 20000);
  pm::models::run(b, 20000);
  const auto sa = a.sphere(0), sb = b.sphere(0);
  EXPECT_GT(sa.v[2], 0.1);  // it has bounced
  for (int k2 = 0; k2 < 3; ++k2) {
    EXPECT_NEAR(sb.x[k2], sa.x[k2], 1e-8) << k2;
    EXPECT_NEAR(sb.v[k2], sa.v[k2], 2e-4 * 0.5) << k2;
    EXPECT_NEAR(sb.omega[k2], sa.omega[k2], 2e-4 * 20) << k2;
  }
}

// No contact, no gravity: the angular momentum stays to round-off, the kinetic energy of the tumbling
// asymmetric clump within 1e-6, and the members keep their distances.
TEST(Clumps, TorqueFreeTumblingKeepsAngularMomentumAndShape) {
  dm::Config c = quiet({"clumps"});
  c.clump_shapes = dm::gravel_shapes();
  dm::ClumpInit k;
  k.shape = 1;  // the cone: three different principal moments? two equal; tumble about a skew axis
  k.scale = 0.006;
  k.orientation = {0.9, 0.1, 0.3, -0.2};
  k.omega = {30, -50, 80};
  c.clumps = {k};
  c.dt = 1e-6;
  dm::Dem<double> m(c);
  const auto b0 = m.clump(0);
  const double e0 = b0.kinetic_energy();
  const double d01 = distance(m, 0, 1), d03 = distance(m, 0, 3);
  pm::models::run(m, 20000);
  const auto b1 = m.clump(0);
  for (int a = 0; a < 3; ++a) EXPECT_EQ(b1.spin[a], b0.spin[a]);
  // the drift turns by the angular velocity at its start: energy drifts O(dt), 7e-6 here (2 rad of tumbling)
  EXPECT_NEAR(b1.kinetic_energy() / e0, 1.0, 2e-5);
  EXPECT_NEAR(distance(m, 0, 1), d01, 1e-12);
  EXPECT_NEAR(distance(m, 0, 3), d03, 1e-12);
  double w[3];
  b1.angular_velocity(w);
  EXPECT_GT(std::abs(w[0] - 30) + std::abs(w[1] + 50) + std::abs(w[2] - 80), 1.0);  // it does tumble
}

// Two cube clumps collide off-centre with friction: linear and angular momentum are exchanged exactly.
TEST(Clumps, TwoClumpsExchangeMomentumExactly) {
  dm::Config c = quiet({"friction", "damping", "clumps"});
  c.clump_shapes = dm::gravel_shapes();
  dm::ClumpInit a, b;
  a.shape = b.shape = 2;
  a.scale = 0.006;
  b.scale = 0.005;
  a.position = {-0.0065, 0.002, 0};
  b.position = {0.0065, -0.001, 0.001};
  a.velocity = {1.0, 0, 0};
  b.velocity = {-0.5, 0.2, 0};
  b.orientation = {0.8, 0.3, -0.2, 0.1};
  a.omega = {0, 0, 40};
  c.clumps = {a, b};
  dm::Dem<double> m(c);
  auto momenta = [&](double (&p)[3], double (&l)[3]) {
    for (int k = 0; k < 3; ++k) p[k] = l[k] = 0;
    for (std::size_t n = 0; n < 2; ++n) {
      const auto r = m.clump(n);
      for (int k = 0; k < 3; ++k) p[k] += r.mass * r.velocity[k];
      l[0] += r.spin[0] + r.mass * (r.position[1] * r.velocity[2] - r.position[2] * r.velocity[1]);
      l[1] += r.spin[1] + r.mass * (r.position[2] * r.velocity[0] - r.position[0] * r.velocity[2]);
      l[2] += r.spin[2] + r.mass * (r.position[0] * r.velocity[1] - r.position[1] * r.velocity[0]);
    }
  };
  double p0[3], l0[3], p1[3], l1[3];
  momenta(p0, l0);
  const auto a0 = m.clump(0);
  pm::models::run(m, 40000);
  momenta(p1, l1);
  const auto a1 = m.clump(0);
  EXPECT_LT(a1.velocity[0], 0.5 * a0.velocity[0]);  // they did collide
  const double p_scale = a0.mass * 1.0, l_scale = p_scale * 0.006;
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p1[k], p0[k], 1e-12 * p_scale) << k;
    EXPECT_NEAR(l1[k], l0[k], 1e-9 * l_scale) << k;
  }
}

// A cube clump thrown spinning onto a floor with friction stops: a sphere would roll on for ever
// (no rolling resistance); the flat-faced clump tips onto a face and rests.
TEST(Clumps, AClumpOnAFloorComesToRest) {
  dm::Config c = quiet({"friction", "damping", "clumps"});
  c.gravity = {0, 0, -9.81};
  c.clump_shapes = dm::gravel_shapes();
  dm::ClumpInit k;
  k.shape = 2;
  k.scale = 0.006;
  k.position = {0, 0, 0.008};
  k.velocity = {0.2, 0, 0};
  k.omega = {0, 30, 0};
  k.orientation = {0.95, 0.2, 0.1, 0.0};
  c.clumps = {k};
  dm::PlaneInit floor;
  floor.normal = {0, 0, 1};
  c.planes = {floor};
  dm::Dem<double> m(c);
  const double e0 = m.kinetic_energy() + m.clump(0).mass * 9.81 * 0.008;
  pm::models::run(m, static_cast<std::int64_t>(0.7 / m.dt()));
  const auto b = m.clump(0);
  EXPECT_LT(m.kinetic_energy(), 1e-20 * e0);
  // on a face: the corner spheres' centres (0.5 / reach) plus their radius (0.6 / reach), reach = sqrt(0.75) + 0.6
  const double reach = std::sqrt(0.75) + 0.6;
  EXPECT_NEAR(b.position[2], 0.006 * 1.1 / reach, 2e-5);
  pm::models::run(m, 20000);  // and stays there: no creep
  const auto c1 = m.clump(0);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(c1.position[a], b.position[a], 1e-12);
}
