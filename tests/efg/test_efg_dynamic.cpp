// The EFG dynamics (models/efg, seed 004 eqs. (6)-(11), (13)) on a coarse Chen plate (centre crack,
// 10 MPa step): Newmark's average-acceleration rule keeps kinetic + strain - load work at 0 (it conserves
// energy under a constant load) over many steps; the crack tip feels nothing before the dilatational
// wave from the loaded edges arrives (h / c_d); after it, J' is positive and its paths agree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "efg/efg.hpp"

namespace efg = polymech::efg;

namespace {

efg::Config coarse_chen_plate() {
  efg::Config c;
  c.crack = efg::CrackKind::centre;
  c.width = 0.02;
  c.height = 0.04;
  c.crack_length = 0.0024;
  c.h_min = 0.0004;
  c.h_max = 0.002;
  c.growth = 0.3;
  c.gauss = 4;
  c.young = 7.562e9;
  c.poisson = 0.394;
  c.density = 1191.0;
  c.stress = 1e7;
  return c;
}

}  // namespace

TEST(EfgDynamic, EnergyIsConservedAndTheTipWaitsForTheWave) {
  const auto c = coarse_chen_plate();
  efg::Efg<double> m(c);
  m.start_dynamic(0.2e-6);
  const double lam = c.young * c.poisson / ((1 + c.poisson) * (1 - 2 * c.poisson)), mu = c.young / (2 * (1 + c.poisson));
  const double arrival = 0.5 * c.height / std::sqrt((lam + 2 * mu) / c.density);  // 5.5 us
  double worst = 0, work = 0, k_before = 0, k_after = 0;
  const int steps = 1000;  // 200 us: many reflections
  for (int s = 1; s <= steps; ++s) {
    m.step();
    const double e = m.kinetic_energy() + m.strain_energy() - m.load_work();
    worst = std::max(worst, std::abs(e));
    work = std::max(work, std::abs(m.load_work()));
    if (s <= 60 && s % 5 == 0) {
      const auto j = m.dynamic_j(0.0012);
      if (m.time() < 0.5 * arrival) k_before = std::max(k_before, std::abs(j.factor));
      if (m.time() > 2 * arrival) k_after = std::max(k_after, j.factor);
    }
  }
  std::printf("%d nodes: energy balance %.3e of the load work %.3e over %d steps; K factor before the wave %.2e, after %.3f\n", m.nodes(),
              worst, work, steps, k_before, k_after);
  EXPECT_LT(worst, 1e-9 * work);
  EXPECT_LT(k_before, 1e-2);  // MLS supports and Newmark dispersion smear the front a little
  EXPECT_GT(k_after, 0.5);
  EXPECT_LT(m.strain_energy(), 10 * work);  // bounded
}

// Newmark with gamma > 1/2 (config newmark_gamma, beta = (gamma + 1/2)^2 / 4) only removes energy: the
// balance kinetic + strain - load work never rises above round-off and ends clearly below zero.
TEST(EfgDynamic, NumericalDampingOnlyRemovesEnergy) {
  auto c = coarse_chen_plate();
  c.newmark_gamma = 0.6;
  efg::Efg<double> m(c);
  m.start_dynamic(0.2e-6);
  double highest = -1e300, work = 0;
  for (int s = 1; s <= 300; ++s) {
    m.step();
    const double e = m.kinetic_energy() + m.strain_energy() - m.load_work();
    highest = std::max(highest, e);
    work = std::max(work, std::abs(m.load_work()));
  }
  const double last = m.kinetic_energy() + m.strain_energy() - m.load_work();
  std::printf("gamma 0.6: energy balance highest %.3e, last %.3e of the load work %.3e\n", highest, last, work);
  EXPECT_LT(highest, 1e-9 * work);
  EXPECT_LT(last, -1e-3 * work);
}

TEST(EfgDynamic, DynamicJPathsAgreeAfterTheWave) {
  const auto c = coarse_chen_plate();
  efg::Efg<double> m(c);
  m.start_dynamic(0.2e-6);
  for (int s = 0; s < 40; ++s) m.step();  // 8 us
  double lo = 1e300, hi = -1e300, klo = 1e300, khi = -1e300;
  for (double r : {0.0008, 0.0010, 0.0012, 0.0014, 0.0016}) {
    const auto j = m.dynamic_j(r);
    std::printf("t = %.1f us, r = %.1f mm: K/(s sqrt(pi a)) = %.4f\n", m.time() * 1e6, r * 1e3, j.factor);
    lo = std::min(lo, j.j);
    hi = std::max(hi, j.j);
    klo = std::min(klo, j.factor);
    khi = std::max(khi, j.factor);
  }
  EXPECT_GT(lo, 0.0);
  // coarse nodes (546): the paths agree to 9 % in K (16 % in J'); the paper-size run: docs/VALIDATION.md
  EXPECT_LT((khi - klo) / khi, 0.10);
}

// A checkpoint taken after 30 steps and loaded into a fresh model continues bitwise like the original.
TEST(EfgDynamic, SaveAndLoadContinueTheRunBitwise) {
  const auto c = coarse_chen_plate();
  efg::Efg<double> a(c);
  a.start_dynamic(0.2e-6);
  for (int s = 0; s < 30; ++s) a.step();
  polymech::models::Archive ar;
  a.save(ar, "efg/");
  efg::Efg<double> b(c);
  b.load(ar, "efg/");
  EXPECT_EQ(b.step_index(), 30);
  EXPECT_EQ(b.time(), a.time());
  for (int s = 0; s < 10; ++s) {
    a.step();
    b.step();
  }
  EXPECT_EQ(a.strain_energy(), b.strain_energy());
  EXPECT_EQ(a.kinetic_energy(), b.kinetic_energy());
  EXPECT_EQ(a.dynamic_j(0.0012).j, b.dynamic_j(0.0012).j);
}

// A crack running at 1000 m/s (seed 004 §3.3) through a coarse plate: the tip moves, the shape functions,
// K and M are rebuilt at every step, and the run stays finite and bounded; after the growth J' is positive.
TEST(EfgDynamic, RunningCrackStaysBounded) {
  auto c = coarse_chen_plate();
  c.growth_speed = 1000.0;
  c.growth_start = 2.0e-6;
  c.final_crack_length = 0.0048;
  efg::Efg<double> m(c);
  const double dt = 0.4e-6;
  m.start_dynamic(dt);
  double cod_max = 0;
  for (int s = 0; s < 30; ++s) {
    if (m.time() >= c.growth_start - 1e-3 * dt) {
      const double a = std::min(c.final_crack_length, c.crack_length + c.growth_speed * (m.time() - c.growth_start));
      if (a > m.crack_length()) m.set_crack_length(a, a < c.final_crack_length ? c.growth_speed : 0.0);
    }
    m.step();
    const double cod = m.dynamic_opening_at(0.0);
    ASSERT_TRUE(std::isfinite(cod)) << "step " << s;
    cod_max = std::max(cod_max, std::abs(cod));
  }
  EXPECT_NEAR(m.crack_length(), c.final_crack_length, 1e-12);
  const auto j = m.dynamic_j(0.0012);
  std::printf("running crack: a = %.2f mm at t = %.1f us, K/(s sqrt(pi a0)) = %.3f, max |COD| = %.3e m\n", 1e3 * m.crack_length(),
              1e6 * m.time(), j.factor, cod_max);
  EXPECT_GT(j.j, 0.0);
  EXPECT_LT(cod_max, 1e-3);  // 1 mm: the stationary plate opens by ~30 um
}

// The prescribed growth moves the crack to where it is at the END of each step (the implicit step solves
// the balance at t_n + dt): the first step after growth_start already has a = a0 + v dt and the tip's
// speed, so the K after the onset (Freund's comparison, docs/VALIDATION.md) is that of a running crack.
// Moving it to a(t_n) instead lagged the crack by one step (a = a0 after the first step past t0).
TEST(EfgDynamic, PrescribedGrowthPutsTheCrackWhereItIsAtTheEndOfTheStep) {
  auto c = coarse_chen_plate();
  c.growth_speed = 1000.0;
  c.growth_start = 0.8e-6;
  c.final_crack_length = 0.0040;
  efg::Efg<double> m(c);
  const double dt = 0.4e-6;
  m.start_dynamic(dt);
  m.set_prescribed_growth(true);
  for (int s = 0; s < 2; ++s) m.step();  // 0.8 us = growth_start: not yet running
  EXPECT_NEAR(m.crack_length(), c.crack_length, 1e-15);
  m.step();  // 1.2 us: the crack at a0 + v (t - t0)
  EXPECT_NEAR(m.time(), 1.2e-6, 1e-15);
  EXPECT_NEAR(m.crack_length(), c.crack_length + c.growth_speed * (m.time() - c.growth_start), 1e-12);
  for (int s = 0; s < 6; ++s) m.step();  // 3.6 us: arrested at the final length
  EXPECT_NEAR(m.crack_length(), c.final_crack_length, 1e-12);
}

// Nodes on the crack path (Config::path_nodes, the paper's Model 4 layout): each node on the line ahead
// of the tip is split in two (one per face) when the tip passes it, so no node is left on the open crack
// tying its faces together; the node count grows by exactly the nodes passed, the run is bounded, the
// faces open by about what they open on the layout without path nodes, and a checkpoint taken after
// some splits restarts bitwise. (Without the split, the passed nodes tie the faces: the opening half-way
// along the grown part is 3.5e-8 m against 1.7e-7 m, and the test fails.)
// Also with the gradual release (Config::path_release_gradual: the tie's force fades over a spacing),
// whose checkpoint carries the ties' states and forces.
class PathNodes : public ::testing::TestWithParam<bool> {};
INSTANTIATE_TEST_SUITE_P(EfgDynamic, PathNodes, ::testing::Values(false, true),
                         [](const ::testing::TestParamInfo<bool>& i) { return i.param ? "Gradual" : "Sudden"; });
TEST_P(PathNodes, SplitWhenTheTipPassesThem) {
  auto c = coarse_chen_plate();
  c.growth_speed = 1000.0;
  c.growth_start = 0.8e-6;
  c.final_crack_length = 0.0048;
  const double dt = 0.4e-6;
  auto off = c;
  c.path_nodes = true;
  c.path_release_gradual = GetParam();
  efg::Efg<double> m(c), o(off);
  const double eps = m.layout().face_offset;
  std::vector<double> path;  // |x| of the path nodes
  for (std::size_t i = 0; i < m.layout().node_count(); ++i)
    if (m.layout().nodes[2 * i + 1] == 0.0 && std::abs(m.layout().nodes[2 * i]) >= c.crack_length &&
        std::abs(m.layout().nodes[2 * i]) < c.final_crack_length - 1e-9 * c.h_min)
      path.push_back(m.layout().nodes[2 * i]);
  const auto n0 = m.nodes();
  ASSERT_EQ(static_cast<std::size_t>(n0 - o.nodes()), path.size());
  ASSERT_GE(path.size(), 4u);
  m.start_dynamic(dt);
  o.start_dynamic(dt);
  m.set_prescribed_growth(true);
  o.set_prescribed_growth(true);
  polymech::models::Archive ar;
  for (int s = 0; s < 12; ++s) {
    m.step();
    o.step();
    if (s == 4) m.save(ar, "efg/");
    const double a = m.crack_length();
    const auto passed = std::count_if(path.begin(), path.end(), [&](double x) { return std::abs(x) < a - 1e-9 * c.h_min; });
    ASSERT_EQ(m.nodes(), n0 + static_cast<polymech::Index>(passed)) << "step " << s << ", a = " << a;
    ASSERT_EQ(m.split_nodes(), static_cast<polymech::Index>(passed));
    const auto& X = m.layout().nodes;
    for (std::size_t i = 0; i < m.layout().node_count(); ++i)
      ASSERT_FALSE(X[2 * i + 1] == 0.0 && std::abs(X[2 * i]) < a - 1e-9 * c.h_min) << "a node on the open crack at x = " << X[2 * i];
    for (const double x : path) {
      if (!(std::abs(x) < a - 1e-9 * c.h_min)) continue;
      int up = 0, down = 0;
      for (std::size_t i = 0; i < m.layout().node_count(); ++i)
        if (X[2 * i] == x) {
          up += X[2 * i + 1] == eps;
          down += X[2 * i + 1] == -eps;
        }
      ASSERT_EQ(up, 1) << x;
      ASSERT_EQ(down, 1) << x;
    }
  }
  EXPECT_NEAR(m.crack_length(), c.final_crack_length, 1e-12);
  const double x1 = *std::max_element(path.begin(), path.end());  // the path node farthest out
  double xin = 1e300;  // the passed path node nearest the initial tip (x > 0)
  for (const double x : path)
    if (x > c.crack_length + 1e-9 * c.h_min) xin = std::min(xin, x);
  for (const double x : {xin, 0.5 * (xin + x1)}) {
    const double cm = m.dynamic_opening_at(x), co = o.dynamic_opening_at(x);
    std::printf("path nodes: opening at x = %.2f mm %.3e m (layout without path nodes %.3e m)\n", 1e3 * x, cm, co);
    EXPECT_GT(cm, 0.0);
    EXPECT_NEAR(cm, co, 0.25 * std::abs(co));
  }
  const auto j = m.dynamic_j(0.0012);
  EXPECT_GT(j.j, 0.0);
  // restart from the checkpoint taken after step 5 (some nodes already split)
  efg::Efg<double> b(c);
  b.set_prescribed_growth(true);
  b.load(ar, "efg/");
  EXPECT_EQ(b.nodes(), static_cast<polymech::Index>(n0 + b.split_nodes()));
  for (int s = 5; s < 12; ++s) b.step();
  EXPECT_EQ(b.nodes(), m.nodes());
  EXPECT_EQ(b.strain_energy(), m.strain_energy());
  EXPECT_EQ(b.kinetic_energy(), m.kinetic_energy());
}

// The paper's node set for Chen's plate (h_min = 0.15 mm, h_max = 0.8 mm, 2 292 nodes; 4 x 4 background
// points here for the time): at the peak of K (15.2 us) the single circles of eq. (13) at r = 0.8 ... 1.6 mm
// disagree by 6.6 % in J' (their error oscillates with r at the period of the node lines, as in a static
// solution on the same nodes: docs/VALIDATION.md), the band of one local spacing (Config::j_band = 1)
// brings them within 2 %. And the banded J' is the mean of eq. (13) over the 4 radial Gauss points.
TEST(EfgDynamic, BandedDynamicJIsPathIndependentAtThePeak) {
  auto c = coarse_chen_plate();
  c.h_min = 0.00015;
  c.h_max = 0.0008;
  c.growth = 0.25;
  c.support_factor = 1.5;
  efg::Efg<double> m(c);
  m.start_dynamic(0.2e-6);
  for (int s = 0; s < 76; ++s) m.step();  // 15.2 us
  auto spread = [&](double band, double& kmean) {
    m.set_j_band(band);
    double lo = 1e300, hi = -1e300;
    kmean = 0;
    for (double r : {0.0008, 0.0010, 0.0012, 0.0014, 0.0016}) {
      const auto j = m.dynamic_j(r);
      std::printf("band %.1f, r = %.1f mm: K/(s sqrt(pi a)) = %.4f\n", band, r * 1e3, j.factor);
      lo = std::min(lo, j.j);
      hi = std::max(hi, j.j);
      kmean += 0.2 * j.factor;
    }
    return (hi - lo) / hi;
  };
  double k0 = 0, k1 = 0;
  const double single = spread(0.0, k0), banded = spread(1.0, k1);
  std::printf("%d nodes, t = %.1f us: J' path spread %.2f %% (single circles), %.2f %% (band 1); mean K factor %.4f, %.4f\n", m.nodes(),
              m.time() * 1e6, 100 * single, 100 * banded, k0, k1);
  EXPECT_GT(single, 0.04);
  EXPECT_LT(banded, 0.02);
  EXPECT_NEAR(k1, k0, 0.01 * k0);  // the band moves the mean K by well under 1 %
  EXPECT_GT(k1, 2.5);              // near the peak of the history (2.92 with 10 x 10 points)
  // the band's J' = sum of w_g / 2 x J'(r + d/2 x_g), d = 1 x (h_min + growth r)
  const double r = 0.0012, d = efg::j_band_width(m.config(), r);
  EXPECT_NEAR(d, 0.00015 + 0.25 * r, 1e-15);
  std::vector<double> gx, gw;
  efg::Efg<double>::gauss_rule(4, gx, gw);
  double mean = 0;
  for (std::size_t g = 0; g < gx.size(); ++g) mean += 0.5 * gw[g] * m.dynamic_j_at(r + 0.5 * d * gx[g]).j;
  EXPECT_NEAR(m.dynamic_j(r).j, mean, 1e-12 * std::abs(mean));
}
