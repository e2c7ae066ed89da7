// A settled pile stays at rest (issue 13's hard case): after the pour of pile.hpp has settled (0.45 s),
// 1e5 more steps (2 s): the kinetic energy falls and is never pumped up, and the spheres held by three or
// more contacts slow down (no steady creep). Spheres alone on the floor may roll on: Hertz-Mindlin has
// no rolling resistance (the clumps of later stages do not roll).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "pile.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {
std::vector<double> positions(const dm::Dem<double>& m, std::size_t n) {
  std::vector<double> x;
  for (std::size_t i = 0; i < n; ++i) {
    const auto s = m.sphere(static_cast<pm::Index>(i));
    x.insert(x.end(), s.x, s.x + 3);
  }
  return x;
}
}  // namespace

TEST(DemRest, ASettledPileStaysAtRestForAHundredThousandSteps) {
  const auto c = pour_into_a_box();
  dm::Dem<double> m(c);
  const auto settle = static_cast<std::int64_t>(0.45 / m.dt());
  pm::models::run(m, settle);
  const auto x0 = positions(m, c.spheres.size());
  const double e0 = m.kinetic_energy();
  double e_max = e0;
  pm::models::RunHooks hooks;
  hooks.sample_every = 5000;
  hooks.sample = [&](std::int64_t) { e_max = std::max(e_max, m.kinetic_energy()); };
  hooks.watchdog.check_every = 10000;
  auto stats = pm::models::run(m, 50000, hooks);
  EXPECT_FALSE(stats.diverged) << stats.reason;
  const auto xh = positions(m, c.spheres.size());
  stats = pm::models::run(m, 50000, hooks);
  EXPECT_FALSE(stats.diverged) << stats.reason;
  const auto x1 = positions(m, c.spheres.size());
  // contacts of each sphere at the end (spheres and the five planes of the box)
  const std::size_t n = c.spheres.size();
  std::vector<int> contacts(n, 0);
  for (std::size_t a = 0; a < n; ++a) {
    const double ra = c.spheres[a].radius;
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const double d = std::sqrt(std::pow(x1[3 * a] - x1[3 * b], 2) + std::pow(x1[3 * a + 1] - x1[3 * b + 1], 2) +
                                 std::pow(x1[3 * a + 2] - x1[3 * b + 2], 2));
      if (d < ra + c.spheres[b].radius) ++contacts[a];
    }
    for (int k = 0; k < 2; ++k) contacts[a] += (x1[3 * a + k] < ra) + (x1[3 * a + k] > kBox - ra);
    contacts[a] += x1[3 * a + 2] < ra;
  }
  // a sphere held by three or more contacts must not creep; one rolling alone on the floor may roll on
  // (Hertz-Mindlin has no rolling resistance)
  double creep = 0, rolling = 0, creep_first = 0;
  int held = 0;
  for (std::size_t a = 0; a < n; ++a) {
    if (contacts[a] >= 3)
      creep_first = std::max(creep_first, std::sqrt(std::pow(xh[3 * a] - x0[3 * a], 2) + std::pow(xh[3 * a + 1] - x0[3 * a + 1], 2) +
                                                    std::pow(xh[3 * a + 2] - x0[3 * a + 2], 2)));
    const double d = std::sqrt(std::pow(x1[3 * a] - xh[3 * a], 2) + std::pow(x1[3 * a + 1] - xh[3 * a + 1], 2) +
                               std::pow(x1[3 * a + 2] - xh[3 * a + 2], 2));
    if (contacts[a] >= 3) {
      creep = std::max(creep, d);
      ++held;
    } else {
      rolling = std::max(rolling, d);
    }
  }
  const double e1 = m.kinetic_energy();
  std::printf("at rest: kinetic energy %.3g J after settling, at most %.3g J, %.3g J after 1e5 steps; over the last "
              "5e4 steps (1 s) the %d spheres held by >= 3 contacts moved at most %.3g m (%.2g r), the %zu others %.3g m\n",
              e0, e_max, e1, held, creep, creep / 0.005, n - static_cast<std::size_t>(held), rolling);
  std::printf("held spheres: largest displacement %.3g m in the first 5e4 steps, %.3g m in the last\n", creep_first, creep);
  EXPECT_GT(held, 60);
  EXPECT_LT(e1, 0.1 * e0);                // kinetic energy decays
  EXPECT_LT(e_max, 1.01 * e0);            // and is never pumped up
  EXPECT_LT(creep, 0.25 * creep_first);   // what still moves slows down: no steady creep
  EXPECT_LT(creep, 0.05 * 0.005);         // less than r / 20 in the last second
}
