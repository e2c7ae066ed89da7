// Many spheres at once: a small pour into a box of planes under gravity, with friction and damping.
// Every sphere stays inside the box, none overlaps another or a wall by more than a few percent of its
// radius, and the kinetic energy decays to a small fraction of the potential energy released.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <vector>

#include "pile.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

TEST(DemPile, PourIntoABoxSettlesInsideTheBox) {
  const auto c = pour_into_a_box();
  const double r = 0.005, box = kBox;
  dm::Dem<double> m(c);
  const int steps = static_cast<int>(0.45 / m.dt());
  double e_peak = 0;
  pm::models::RunHooks hooks;  // the shared run driver, its watchdog keeping the last good state
  hooks.sample_every = 200;
  hooks.sample = [&](std::int64_t) { e_peak = std::max(e_peak, m.kinetic_energy()); };
  hooks.watchdog.check_every = 500;
  hooks.watchdog.keep_last_good = true;
  const auto stats = pm::models::run(m, steps, hooks);
  EXPECT_FALSE(stats.diverged) << stats.reason;
  EXPECT_EQ(stats.steps, steps);
  EXPECT_TRUE(m.health().finite);
  const double e_end = m.kinetic_energy();
  std::printf("pile: %zu spheres, %d steps of %.3g s, %d list builds, kinetic energy peak %.3g J, end %.3g J\n",
              c.spheres.size(), steps, m.dt(), m.sphere_list_builds(), e_peak, e_end);
  EXPECT_LT(e_end, 1e-3 * e_peak);
  double max_wall_overlap = 0, max_pair_overlap = 0;
  std::vector<dm::SphereState> st;
  for (std::size_t i = 0; i < c.spheres.size(); ++i) st.push_back(m.sphere(static_cast<pm::Index>(i)));
  for (std::size_t i = 0; i < st.size(); ++i) {
    const double ri = c.spheres[i].radius;
    for (int k = 0; k < 2; ++k) {
      max_wall_overlap = std::max({max_wall_overlap, ri - st[i].x[k], st[i].x[k] + ri - box});
    }
    max_wall_overlap = std::max(max_wall_overlap, ri - st[i].x[2]);
    for (std::size_t j = i + 1; j < st.size(); ++j) {
      double d2 = 0;
      for (int k = 0; k < 3; ++k) d2 += (st[i].x[k] - st[j].x[k]) * (st[i].x[k] - st[j].x[k]);
      max_pair_overlap = std::max(max_pair_overlap, ri + c.spheres[j].radius - std::sqrt(d2));
    }
  }
  EXPECT_LT(max_wall_overlap, 0.05 * r);
  EXPECT_LT(max_pair_overlap, 0.05 * r);
}

// The watchdog's speed bound (issue 33 item 2): a sphere that moves more than the neighbour lists' skin in
// one step could pass through another unseen; one just below it is healthy.
TEST(DemPile, WatchdogFlagsASphereFasterThanTheSkinPerStep) {
  auto c = pour_into_a_box();
  c.skin = 0.001;
  dm::Dem<double> m(c);
  const double limit = c.skin / m.dt();
  const auto set_speed = [&](double s) {
    auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.spheres().v);
    for (int k = 0; k < 3; ++k) v(5, k) = k == 0 ? s : 0.0;
    Kokkos::deep_copy(m.spheres().v, v);
  };
  set_speed(0.99 * limit);
  EXPECT_TRUE(m.health().finite);
  set_speed(1.01 * limit);
  const pm::models::Health h = m.health();
  EXPECT_FALSE(h.finite);
  EXPECT_EQ(h.first_bad, 5);
  EXPECT_NE(h.problem.find("neighbour skin per step"), std::string::npos) << h.problem;
}
