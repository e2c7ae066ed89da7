// MLS shape functions of seed 004 eqs. (2)-(5) (kernels/mls/mls.hpp): partition of unity and linear
// reproduction to round-off on jittered nodes, derivatives against central differences, the visibility
// criterion at a crack, and the moment-matrix check (flag in the kernel, an error naming the point).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "efg/efg.hpp"
#include "mls/mls.hpp"
#include "neighbors/neighbor_search.hpp"

namespace pm = polymech;

namespace {

struct Cloud {
  std::vector<double> nodes;  // x, y
  std::vector<double> dm;
};

// An n x n grid of spacing h on [0, 1]^2 jittered by up to 0.3 h; support radius factor x h.
Cloud jittered_grid(int n, double factor, unsigned seed) {
  Cloud c;
  const double h = 1.0 / (n - 1);
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-0.3 * h, 0.3 * h);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      c.nodes.push_back(i * h + u(g));
      c.nodes.push_back(j * h + u(g));
      c.dm.push_back(factor * h);
    }
  return c;
}

struct Evaluated {
  std::vector<std::vector<std::pair<int, double>>> phi, dx, dy;  // per point: (node, value)
  std::vector<int> status;
};

Evaluated evaluate(const Cloud& c, const std::vector<double>& pts, const std::vector<double>& crack, double min_ratio) {
  const auto nodes = pm::efg::detail::to_points<double>(c.nodes, 2, "nodes");
  const auto points = pm::efg::detail::to_points<double>(pts, 2, "points");
  pm::View1<double> dm("dm", c.dm.size());
  auto hd = Kokkos::create_mirror_view(dm);
  double rmax = 0;
  for (std::size_t i = 0; i < c.dm.size(); ++i) {
    hd(i) = c.dm[i];
    rmax = std::max(rmax, c.dm[i]);
  }
  Kokkos::deep_copy(dm, hd);
  pm::mls::Segments<double> seg("crack", crack.size() / 4);
  auto hs = Kokkos::create_mirror_view(seg);
  for (std::size_t s = 0; s < crack.size() / 4; ++s)
    for (int k = 0; k < 4; ++k) hs(s, k) = crack[4 * s + static_cast<std::size_t>(k)];
  Kokkos::deep_copy(seg, hs);
  pm::neighbors::NeighborSearch<double, 2> search;
  pm::neighbors::NeighborList cand;
  search.build_between(points, nodes, rmax, cand);
  pm::mls::ShapeFunctions<double> sf;
  sf.rows = pm::mls::support_rows(cand, points, nodes, dm, seg);
  pm::mls::evaluate(points, nodes, dm, min_ratio, sf);
  auto off = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sf.rows.offsets);
  auto nb = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sf.rows.neighbors);
  auto ph = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sf.phi);
  auto dp = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sf.dphi);
  auto st = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sf.status);
  Evaluated e;
  const std::size_t n = pts.size() / 2;
  e.phi.resize(n);
  e.dx.resize(n);
  e.dy.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    e.status.push_back(st(i));
    for (auto k = off(i); k < off(i + 1); ++k) {
      e.phi[i].emplace_back(nb(k), ph(k));
      e.dx[i].emplace_back(nb(k), dp(k, 0));
      e.dy[i].emplace_back(nb(k), dp(k, 1));
    }
  }
  return e;
}

std::vector<double> random_points(int n, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> p;
  for (int i = 0; i < 2 * n; ++i) p.push_back(u(g));
  return p;
}

}  // namespace

TEST(Mls, QuarticSplineMatchesEq5) {
  double w, dw;
  pm::mls::quartic_spline(0.0, w, dw);
  EXPECT_DOUBLE_EQ(w, 1.0);
  EXPECT_DOUBLE_EQ(dw, 0.0);
  pm::mls::quartic_spline(0.5, w, dw);
  EXPECT_NEAR(w, 1 - 6 * 0.25 + 8 * 0.125 - 3 * 0.0625, 1e-15);
  EXPECT_NEAR(dw, -12 * 0.5 + 24 * 0.25 - 12 * 0.125, 1e-15);
  pm::mls::quartic_spline(1.0, w, dw);
  EXPECT_EQ(w, 0.0);
  EXPECT_EQ(dw, 0.0);
}

TEST(Mls, PartitionOfUnityAndLinearReproductionOnJitteredNodes) {
  const Cloud c = jittered_grid(9, 2.2, 7);
  const auto pts = random_points(400, 3);
  const auto e = evaluate(c, pts, {}, 1e-8);
  for (std::size_t i = 0; i < e.phi.size(); ++i) {
    ASSERT_EQ(e.status[i], 0) << "point " << i;
    double s = 0, sx = 0, sy = 0, d0 = 0, d1 = 0, dxx = 0, dxy = 0, dyx = 0, dyy = 0;
    for (std::size_t k = 0; k < e.phi[i].size(); ++k) {
      const auto n = static_cast<std::size_t>(e.phi[i][k].first);
      const double xn = c.nodes[2 * n], yn = c.nodes[2 * n + 1];
      s += e.phi[i][k].second;
      sx += e.phi[i][k].second * xn;
      sy += e.phi[i][k].second * yn;
      d0 += e.dx[i][k].second;
      d1 += e.dy[i][k].second;
      dxx += e.dx[i][k].second * xn;
      dxy += e.dy[i][k].second * xn;
      dyx += e.dx[i][k].second * yn;
      dyy += e.dy[i][k].second * yn;
    }
    EXPECT_NEAR(s, 1.0, 1e-12);
    EXPECT_NEAR(sx, pts[2 * i], 1e-12);
    EXPECT_NEAR(sy, pts[2 * i + 1], 1e-12);
    EXPECT_NEAR(d0, 0.0, 1e-10);
    EXPECT_NEAR(d1, 0.0, 1e-10);
    EXPECT_NEAR(dxx, 1.0, 1e-10);
    EXPECT_NEAR(dyy, 1.0, 1e-10);
    EXPECT_NEAR(dxy, 0.0, 1e-10);
    EXPECT_NEAR(dyx, 0.0, 1e-10);
  }
}

TEST(Mls, DerivativesMatchCentralDifferences) {
  const Cloud c = jittered_grid(7, 2.5, 11);
  const double h = 1e-6;
  const auto base = random_points(20, 5);
  std::vector<double> pts;
  for (std::size_t i = 0; i < base.size() / 2; ++i) {
    const double x = 0.15 + 0.7 * base[2 * i], y = 0.15 + 0.7 * base[2 * i + 1];
    pts.insert(pts.end(), {x, y, x + h, y, x - h, y, x, y + h, x, y - h});
  }
  const auto e = evaluate(c, pts, {}, 1e-8);
  double worst = 0;
  for (std::size_t i = 0; i < pts.size() / 10; ++i) {
    std::map<int, double> v[5];
    for (int s = 0; s < 5; ++s)
      for (const auto& [n, p] : e.phi[5 * i + static_cast<std::size_t>(s)]) v[s][n] = p;
    for (std::size_t k = 0; k < e.dx[5 * i].size(); ++k) {
      const int n = e.dx[5 * i][k].first;
      const double fdx = (v[1][n] - v[2][n]) / (2 * h), fdy = (v[3][n] - v[4][n]) / (2 * h);
      worst = std::max({worst, std::abs(fdx - e.dx[5 * i][k].second), std::abs(fdy - e.dy[5 * i][k].second)});
    }
  }
  EXPECT_LT(worst, 1e-6);  // derivatives are O(10): a relative 1e-7
}

TEST(Mls, CrackHidesNodesOnTheOtherSide) {
  const Cloud c = jittered_grid(9, 2.2, 13);
  // crack from (0, 0.5) to (0.5, 0.5); a point just below it at x = 0.25 sees no node above, away from the tip
  const auto e = evaluate(c, {0.25, 0.49}, {0.0, 0.5, 0.5, 0.5}, 1e-8);
  ASSERT_EQ(e.status[0], 0);
  double s = 0;
  for (const auto& [n, p] : e.phi[0]) {
    const auto k = static_cast<std::size_t>(n);
    const double xn = c.nodes[2 * k], yn = c.nodes[2 * k + 1];
    const bool crosses = yn > 0.5 && (0.25 + (xn - 0.25) * (0.5 - 0.49) / (yn - 0.49)) < 0.5;
    EXPECT_FALSE(crosses) << "node " << n << " at (" << xn << ", " << yn << ") is behind the crack";
    s += p;
  }
  EXPECT_NEAR(s, 1.0, 1e-12);
}

TEST(Mls, CollinearNodesAreFlaggedNotNaN) {
  // every node on the line y = 0.5: the moment matrix is singular everywhere
  Cloud c;
  for (int i = 0; i < 11; ++i) {
    c.nodes.insert(c.nodes.end(), {0.1 * i, 0.5});
    c.dm.push_back(0.35);
  }
  const auto e = evaluate(c, {0.3, 0.52, 0.55, 0.45}, {}, 1e-8);
  for (int s : e.status) EXPECT_EQ(s, 1);
  for (const auto& row : e.phi)
    for (const auto& [n, p] : row) EXPECT_EQ(p, 0.0) << "node " << n;
}

TEST(Mls, TooSmallSupportsAreAnErrorNamingThePoint) {
  pm::efg::Config c;
  c.crack = pm::efg::CrackKind::none;
  c.width = 1.0;
  c.height = 1.0;
  c.h_max = c.h_min = 0.25;
  c.support_factor = 0.6;  // a point at a cell centre sees no node
  c.gauss = 2;
  pm::efg::Efg<double> model(c);
  try {
    model.shape_functions(std::vector<double>{0.125, 0.125}, 2, "probe");
    FAIL() << "no error for a point without nodes";
  } catch (const std::runtime_error& err) {
    const std::string m = err.what();
    EXPECT_NE(m.find("nearly singular"), std::string::npos) << m;
    EXPECT_NE(m.find("probe point 0"), std::string::npos) << m;
    EXPECT_NE(m.find("x = 0.125"), std::string::npos) << m;
  }
}
