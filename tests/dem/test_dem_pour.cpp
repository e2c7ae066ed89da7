// The pour of gravel into a bin (issue 13): the packing-fraction measure against a lattice whose
// fraction is known, and a small pour of the paper's three clump shapes that settles inside the bin
// into a bed of plausible packing.
#include <gtest/gtest.h>

#include <cmath>

#include "dem/dem.hpp"
#include "dem/pour.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

TEST(DemPour, PackingFractionOfASimpleCubicLatticeIsPiOverSix) {
  std::vector<std::array<double, 4>> spheres;
  const double r = 0.5;
  for (int i = -1; i <= 11; ++i)
    for (int j = -1; j <= 11; ++j)
      for (int k = -1; k <= 11; ++k) spheres.push_back({double(i), double(j), double(k), r});
  // 97 samples per axis: a grid not commensurate with the lattice
  const double phi = dm::packing_fraction(spheres, {0, 0, 0}, {10, 10, 10}, 97);
  EXPECT_NEAR(phi, std::acos(-1.0) / 6, 3e-3);
  EXPECT_EQ(dm::packing_fraction({}, {0, 0, 0}, {1, 1, 1}, 10), 0.0);
}

TEST(DemPour, ThreeShapesSettleIntoABedInsideTheBin) {
  dm::Config base;
  base.particle = {5e6, 0.3, 2650};  // softer than the scene's: a test of seconds
  base.wall = {5e6, 0.3, 2650};
  base.restitution = 0.4;
  base.friction = 0.5;
  base.gravity = {0, 0, -9.81};
  base.effects = pm::EffectSet::resolve({"friction", "damping", "clumps"}, dm::effect_table());
  dm::PourSpec spec;
  spec.bin = {0.04, 0.04, 0.04};
  spec.count = 72;
  spec.shapes = {"cylinder", "cone", "cube"};
  spec.radius_min = 0.005;
  spec.radius_max = 0.007;
  dm::Config c = dm::pour_config(base, spec);
  ASSERT_EQ(c.clumps.size(), 72u);
  dm::Dem<double> m(c);
  const double top = dm::pour_top(spec);
  pm::models::run(m, static_cast<std::int64_t>(0.5 / m.dt()));
  double z_max = 0;
  for (std::size_t b = 0; b < m.clump_count(); ++b) {
    const auto body = m.clump(b);
    EXPECT_GT(body.position[0], 0.0);
    EXPECT_LT(body.position[0], spec.bin[0]);
    EXPECT_GT(body.position[1], 0.0);
    EXPECT_LT(body.position[1], spec.bin[1]);
    EXPECT_GT(body.position[2], 0.0);
    z_max = std::max(z_max, body.position[2]);
  }
  EXPECT_LT(z_max, 0.6 * top);  // it has fallen and packed
  const double potential_drop = 72 * m.clump(0).mass * 9.81 * 0.01;
  EXPECT_LT(m.kinetic_energy(), 1e-3 * potential_drop);  // and nearly come to rest
  auto radius = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), m.spheres().radius);
  std::vector<std::array<double, 4>> rows;
  for (pm::Index i = 0; i < m.sphere_count(); ++i) {
    const auto s = m.sphere(i);
    rows.push_back({s.x[0], s.x[1], s.x[2], radius(i)});
  }
  std::array<double, 3> lo{}, hi{};
  dm::bed_box(rows, spec, lo, hi);
  ASSERT_GT(hi[2], lo[2] + 0.003);
  const double phi = dm::packing_fraction(rows, lo, hi, 50);
  EXPECT_GT(phi, 0.4);
  EXPECT_LT(phi, 0.75);
  std::printf("72 clumps: top centre %.4f m (dropped from up to %.4f m), packing fraction %.3f in z [%.4f, %.4f] m\n", z_max, top,
              phi, lo[2], hi[2]);
}

// The angle-of-repose measure on a synthetic heap: spheres filling the region under a 30-degree slope
// against the wall x = 0.
TEST(DemPour, ReposeAngleOfASyntheticThirtyDegreeHeap) {
  dm::PourSpec spec;
  spec.bin = {0.1, 0.1, 0.1};
  spec.radius_min = spec.radius_max = 0.002;
  const double r = 0.002, tan30 = std::tan(std::acos(-1.0) / 6), h0 = 0.06;
  std::vector<std::array<double, 4>> spheres;
  for (double x = r; x < 0.2; x += 2 * r)
    for (double y = r; y < 0.1; y += 2 * r)
      for (double z = r; z < h0 - x * tan30; z += 2 * r) spheres.push_back({x, y, z, r});
  std::vector<std::array<double, 2>> profile;
  const double angle = dm::repose_angle(spheres, spec, &profile);
  EXPECT_NEAR(angle, 30.0, 1.5);
  EXPECT_GT(profile.size(), 10u);
  // grains run out beyond the toe: a layer 14 mm high (23 % of the heap) on the floor from x = 0.11 m
  // to 0.2 m; the slope's angle is unchanged (a fit over every bin between 20 % and 80 % of the top took
  // this layer in: 18 degrees for a heap of 30 in the gravel_heap run)
  auto with_debris = spheres;
  for (double x = 0.11 + r; x < 0.2; x += 2 * r)
    for (double y = r; y < 0.1; y += 2 * r)
      for (double z = r; z < 0.014; z += 2 * r) with_debris.push_back({x, y, z, r});
  EXPECT_NEAR(dm::repose_angle(with_debris, spec), 30.0, 1.5);
  EXPECT_TRUE(std::isnan(dm::repose_angle({{0.01, 0.05, 0.01, r}}, spec)));
}
