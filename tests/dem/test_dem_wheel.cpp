// The rigid wheel of the `rigid_wheel` effect (seed 002 paper 2, sec. 4): its mesh faces outwards, it
// comes to rest on a bed carrying exactly its load, it is driven at the prescribed speed and slip, and a
// run restarted mid-drive continues bit for bit (the wheel is part of the checkpoint).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "dem/dem.hpp"
#include "dem/pour.hpp"
#include "dem/wheel.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

// A small wheel (R = 6 cm, 4 cm wide, 1 kg, 15 N) on one layer of 5 mm spheres on the floor of a box of
// planes, set down at 2 ms, loaded over 10-12 ms after that (the paper's ramp: the wheel bounces on the
// spheres' Hertz springs, period ~ 28 ms, like the fluctuation of Fig. 8), driven at 0.2 m/s (12-15 ms)
// with 20 % slip.
dm::Config wheel_on_a_layer(double speed, double load_to = 0.012) {
  dm::Config c;
  c.particle = {5e7, 0.3, 2650};
  c.wall = {5e7, 0.3, 2650};
  c.restitution = 0.4;
  c.friction = 0.5;
  c.gravity = {0, 0, -9.81};
  c.effects = pm::EffectSet::resolve({"friction", "damping", "fe_surfaces", "rigid_wheel"}, dm::effect_table());
  const double r = 0.005, lx = 0.2, ly = 0.08;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 20; ++i) {
      dm::SphereInit s;
      s.radius = r;
      s.position = {r + 2 * r * i, r + 2 * r * j, r};
      c.spheres.push_back(s);
    }
  c.planes = dm::box_planes(lx, ly);
  auto& w = c.wheel;
  w.radius = 0.06;
  w.width = 0.04;
  w.around = 64;
  w.across = 6;
  w.side_depth = 0.01;
  w.mass = 1.0;
  w.load = 15.0;
  w.load_from = 0.010;
  w.load_to = load_to;
  w.speed = speed;
  w.speed_from = 0.012;
  w.speed_to = 0.015;
  w.slip = 0.2;
  w.start = 0.002;
  w.x_start = 0.07;
  w.y_centre = 0.04;
  w.parked = {0.07, 0.04, 1.0};
  c.surface = dm::wheel_surface(w);
  c.max_speed = 0.5;
  return c;
}

}  // namespace

TEST(Wheel, TheMeshFacesOutwardsAndCoversTheTread) {
  dm::WheelSpec w;
  w.radius = 0.445;
  w.width = 0.31;
  w.around = 140;
  w.across = 16;
  w.side_depth = 0.1;
  const auto s = dm::wheel_surface(w);
  const auto mesh = pm::contact::make_surface_mesh<double>(s.nodes, s.facet_sizes, {s.facet_nodes.begin(), s.facet_nodes.end()}, "wheel");
  auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.centroid);
  auto n = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.normal);
  ASSERT_EQ(mesh.facet_count(), 140 * 16 + 2 * 140 * 5);  // side rings about as long as the tread's facets
  int tread = 0;
  double tread_area_proxy = 0;
  for (pm::Index f = 0; f < mesh.facet_count(); ++f) {
    const double radial = std::hypot(c(f, 0), c(f, 2));
    if (std::abs(c(f, 1)) < 0.5 * w.width - 1e-9) {  // the tread: normal radial, outwards
      ++tread;
      EXPECT_NEAR((c(f, 0) * n(f, 0) + c(f, 2) * n(f, 2)) / radial, 1.0, 1e-12) << f;
      tread_area_proxy += radial;
    } else {  // a side: normal along the side's y
      EXPECT_NEAR(n(f, 1), c(f, 1) > 0 ? 1.0 : -1.0, 1e-12) << f;
    }
  }
  EXPECT_EQ(tread, 140 * 16);
  // the facets' centroids lie on the inscribed radius R cos(pi / 140)
  EXPECT_NEAR(tread_area_proxy / tread, 0.445 * std::cos(dm::kPi / 140), 1e-12);
  EXPECT_THROW(dm::wheel_surface(dm::WheelSpec{}), std::invalid_argument);
}

TEST(Wheel, StandingOnTheBedItCarriesItsLoad) {
  // loaded slowly (10-200 ms, 7 periods of its bounce: the contacts' damping is set by the spheres'
  // mass, a few % of critical for the wheel's), then 200 ms at the full load
  dm::Dem<double> m(wheel_on_a_layer(0.0, 0.200));
  pm::models::run(m, static_cast<std::int64_t>(0.001 / m.dt()));
  EXPECT_FALSE(m.wheel().placed);
  pm::models::run(m, static_cast<std::int64_t>(0.299 / m.dt()));
  auto w = m.wheel();
  ASSERT_TRUE(w.placed);
  // set down touching the two spheres under it (x = 0.065, 0.075): lowest point R - sqrt((R + r)^2 - dx^2) above their centres
  EXPECT_NEAR(w.bed_highest, 0.005 + std::sqrt(0.065 * 0.065 - 0.005 * 0.005) - 0.06, 1e-5);
  EXPECT_NEAR(w.bed_level, 0.01, 1e-4);  // the layer's top
  // 0.3-0.4 s: the gravel carries the 15 N load (the wheel has no weight of its own); the mean over
  // the window differs from it by m (v_z(end) - v_z(start)) / T, the bounce that is left
  double fz = 0, sink = 0;
  const int n = 200;
  const auto every = std::max<std::int64_t>(1, static_cast<std::int64_t>(0.1 / m.dt() / n));
  for (int k = 0; k < n; ++k) {
    pm::models::run(m, every);
    fz += m.wheel().vertical_force / n;
    sink += m.wheel().sinkage / n;
  }
  EXPECT_NEAR(fz, 15.0, 0.15);
  EXPECT_GT(sink, 0.0);     // the spheres are pressed into the floor: about 0.2 mm under 4 spheres
  EXPECT_LT(sink, 1e-3);
  EXPECT_EQ(m.wheel().centre[0], 0.07);  // no speed: it stays
}

TEST(Wheel, DrivenAtTheScheduleWithSlipAndRestartedBitForBit) {
  const dm::Config c = wheel_on_a_layer(0.2);
  dm::Dem<double> whole(c);
  const auto first = static_cast<std::int64_t>(0.03 / whole.dt()), second = static_cast<std::int64_t>(0.02 / whole.dt());
  pm::models::run(whole, first);
  pm::models::Archive a;
  whole.save(a, "dem/");
  dm::Dem<double> restarted(c);
  restarted.load(a, "dem/");
  pm::models::run(whole, second);
  pm::models::run(restarted, second);
  const auto w = whole.wheel(), v = restarted.wheel();
  EXPECT_EQ(std::memcmp(w.centre, v.centre, sizeof w.centre), 0);
  EXPECT_EQ(w.vertical_force, v.vertical_force);
  EXPECT_EQ(w.tractive_force, v.tractive_force);
  for (pm::Index i = 0; i < whole.sphere_count(); ++i) {
    const auto p = whole.sphere(i), q = restarted.sphere(i);
    ASSERT_EQ(std::memcmp(&p, &q, sizeof p), 0) << "sphere " << i;
  }
  // the prescribed travel: 0.2 m/s ramped over 12-15 ms (mid-step speeds: exact for a ramp)
  const double t = w.time;
  EXPECT_NEAR(w.centre[0], 0.07 + 0.2 * (t - 0.0135), 1e-9);
  EXPECT_NEAR(w.spin, 0.2 / (0.8 * 0.06), 1e-12);
  // (the sign of the traction is not asserted here: one layer of free spheres rolls under the tread;
  // the kernel test SphereFacet.AMovingSurfaceDragsSpheresAndFeelsTheirReaction checks the drag)
}
