// Neighbour search against brute force: random and lattice clouds, particles exactly at the cut-off,
// empty cells, all particles in one cell, one particle, particles on the bounding-box boundary,
// half lists, and the skin-distance rebuild rule.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <vector>

#include "neighbors/neighbor_search.hpp"
#include "neighbors/verlet_list.hpp"

namespace pm = polymech;
namespace nb = polymech::neighbors;

namespace {

template <int D>
using Points = std::vector<std::array<double, D>>;

template <int D>
pm::VecView<double, D> to_device(const Points<D>& p) {
  pm::VecView<double, D> x("x", p.size());
  auto h = Kokkos::create_mirror_view(x);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < D; ++k) h(i, k) = p[i][k];
  Kokkos::deep_copy(x, h);
  return x;
}

template <int D>
std::vector<std::vector<int>> brute_force(const Points<D>& p, double radius, bool half) {
  std::vector<std::vector<int>> out(p.size());
  const double r2 = radius * radius;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = 0; j < p.size(); ++j) {
      if (i == j || (half && j < i)) continue;
      double d2 = 0;
      for (int k = 0; k < D; ++k) d2 += (p[j][k] - p[i][k]) * (p[j][k] - p[i][k]);
      if (d2 <= r2) out[i].push_back(static_cast<int>(j));
    }
  return out;
}

std::vector<std::vector<int>> to_rows(const nb::NeighborList& list) {
  auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
  auto nbr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbors);
  std::vector<std::vector<int>> rows(list.num_particles);
  for (int i = 0; i < list.num_particles; ++i)
    for (auto k = off(i); k < off(i + 1); ++k) rows[i].push_back(nbr(k));
  return rows;
}

template <int D>
void expect_matches_brute_force(const Points<D>& p, double radius) {
  auto x = to_device<D>(p);
  nb::NeighborSearch<double, D> search;
  for (auto kind : {nb::ListKind::full, nb::ListKind::half}) {
    nb::NeighborList list;
    search.build(x, radius, kind, list);
    auto rows = to_rows(list);
    auto ref = brute_force<D>(p, radius, kind == nb::ListKind::half);
    ASSERT_EQ(rows.size(), ref.size());
    std::size_t pairs = 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
      auto r = rows[i];
      std::sort(r.begin(), r.end());
      EXPECT_EQ(std::set<int>(r.begin(), r.end()).size(), r.size()) << "duplicate neighbour of " << i;
      ASSERT_EQ(r, ref[i]) << "particle " << i << " (" << (kind == nb::ListKind::half ? "half" : "full") << ")";
      pairs += r.size();
    }
    EXPECT_EQ(static_cast<std::size_t>(list.num_pairs), pairs);
  }
}

template <int D>
Points<D> random_cloud(int n, double box, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, box);
  Points<D> p(n);
  for (auto& q : p)
    for (int k = 0; k < D; ++k) q[k] = u(gen);
  return p;
}

template <int D>
Points<D> lattice(int per_side, double spacing) {
  Points<D> p;
  if constexpr (D == 2) {
    for (int b = 0; b < per_side; ++b)
      for (int a = 0; a < per_side; ++a) p.push_back({a * spacing, b * spacing});
  } else {
    for (int c = 0; c < per_side; ++c)
      for (int b = 0; b < per_side; ++b)
        for (int a = 0; a < per_side; ++a) p.push_back({a * spacing, b * spacing, c * spacing});
  }
  return p;
}

}  // namespace

TEST(NeighborSearch, RandomCloud2DMatchesBruteForce) {
  for (double radius : {0.01, 0.05, 0.13}) expect_matches_brute_force<2>(random_cloud<2>(1500, 1.0, 3), radius);
}

TEST(NeighborSearch, RandomCloud3DMatchesBruteForce) {
  for (double radius : {0.03, 0.1, 0.27}) expect_matches_brute_force<3>(random_cloud<3>(1500, 1.0, 5), radius);
}

TEST(NeighborSearch, LatticeIncludesParticlesExactlyAtTheCutOff) {
  // spacing 1 and radius 2: distances 1, sqrt2, 2 are in, sqrt5 is out; 2.0 is exact in binary.
  auto p2 = lattice<2>(12, 1.0);
  expect_matches_brute_force<2>(p2, 2.0);
  auto x = to_device<2>(p2);
  nb::NeighborList list;
  nb::NeighborSearch<double, 2> search;
  search.build(x, 2.0, nb::ListKind::full, list);
  auto rows = to_rows(list);
  const int interior = 5 * 12 + 5;  // (5, 5)
  EXPECT_EQ(rows[interior].size(), 12u);  // 4 at 1, 4 at sqrt2, 4 at exactly 2
  auto p3 = lattice<3>(7, 0.5);
  expect_matches_brute_force<3>(p3, 1.0);
}

TEST(NeighborSearch, ClusteredCloudWithEmptyCells) {
  // two tight clusters far apart: most cells are empty
  auto a = random_cloud<3>(300, 0.1, 9);
  auto b = random_cloud<3>(300, 0.1, 10);
  for (auto& q : b)
    for (auto& c : q) c += 5.0;
  a.insert(a.end(), b.begin(), b.end());
  expect_matches_brute_force<3>(a, 0.04);
  // a far outlier makes a huge bounding box: the grid coarsens instead of allocating 1e12 cells
  a.push_back({1e6, -1e6, 3e5});
  expect_matches_brute_force<3>(a, 0.04);
}

TEST(NeighborSearch, AllParticlesInOneCell) {
  expect_matches_brute_force<2>(random_cloud<2>(200, 0.1, 13), 10.0);
  expect_matches_brute_force<3>(random_cloud<3>(200, 0.1, 14), 10.0);
}

TEST(NeighborSearch, OneParticleAndNoParticles) {
  expect_matches_brute_force<2>(Points<2>{{0.3, 0.7}}, 1.0);
  expect_matches_brute_force<3>(Points<3>{{0.3, 0.7, 0.1}}, 1.0);
  pm::VecView<double, 2> empty("empty", 0);
  nb::NeighborList list;
  nb::NeighborSearch<double, 2> search;
  search.build(empty, 1.0, nb::ListKind::full, list);
  EXPECT_EQ(list.num_pairs, 0);
  EXPECT_EQ(list.num_particles, 0);
}

TEST(NeighborSearch, ParticlesOnTheBoundingBoxBoundary) {
  // points exactly on the faces and corners of [0,1]^D, including the max corner, with radius equal
  // to the distance to the neighbouring boundary point
  Points<2> p2;
  for (int a = 0; a <= 4; ++a) {
    p2.push_back({a * 0.25, 0.0});
    p2.push_back({a * 0.25, 1.0});
    p2.push_back({0.0, a * 0.25});
    p2.push_back({1.0, a * 0.25});
  }
  expect_matches_brute_force<2>(p2, 0.25);
  Points<3> p3;
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b)
      for (int c = 0; c < 2; ++c) p3.push_back({1.0 * a, 1.0 * b, 1.0 * c});
  expect_matches_brute_force<3>(p3, 1.0);
}

// Points of different sizes (the DEM's sphere radii): a pair is listed within s_i + s_j + margin only;
// with a row scratch (one search pass for short rows, longer rows searched again) the same list.
TEST(NeighborSearch, SizedPairsAndRowScratchMatchBruteForce) {
  const auto p = random_cloud<3>(400, 0.5, 11);  // about 7 neighbours a row: capacities 1 and 4 overflow, 64 holds
  std::mt19937 gen(5);
  std::uniform_real_distribution<double> u(0.02, 0.05);
  std::vector<double> size(p.size());
  for (auto& v : size) v = u(gen);
  const double margin = 0.01, radius = 2 * 0.05 + margin;
  pm::View1<double> sizes("sizes", p.size());
  auto hs = Kokkos::create_mirror_view(sizes);
  for (std::size_t i = 0; i < p.size(); ++i) hs(i) = size[i];
  Kokkos::deep_copy(sizes, hs);
  auto x = to_device<3>(p);
  for (const int capacity : {0, 1, 4, 64})
    for (auto kind : {nb::ListKind::full, nb::ListKind::half}) {
      const bool half = kind == nb::ListKind::half;
      nb::NeighborSearch<double, 3> search;
      search.set_row_capacity(capacity);
      nb::NeighborList list;
      search.build(x, radius, kind, list, sizes, margin);
      const auto rows = to_rows(list);
      std::size_t pairs = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        std::vector<int> ref;
        for (std::size_t j = 0; j < p.size(); ++j) {
          if (i == j || (half && j < i)) continue;
          double d2 = 0;
          for (int k = 0; k < 3; ++k) d2 += (p[j][k] - p[i][k]) * (p[j][k] - p[i][k]);
          const double c = size[i] + size[j] + margin;
          if (d2 <= c * c) ref.push_back(static_cast<int>(j));
        }
        auto r = rows[i];
        std::sort(r.begin(), r.end());
        ASSERT_EQ(r, ref) << "particle " << i << ", capacity " << capacity << (half ? " (half)" : " (full)");
        pairs += r.size();
      }
      EXPECT_EQ(static_cast<std::size_t>(list.num_pairs), pairs);
      EXPECT_GT(pairs, 2 * p.size() / (half ? 2 : 1));  // rows of several pairs
    }
}

TEST(NeighborSearch, RebuildReusesStorageAndGivesSameList) {
  auto p = random_cloud<2>(800, 1.0, 17);
  auto x = to_device<2>(p);
  nb::NeighborSearch<double, 2> search;
  nb::NeighborList list;
  search.build(x, 0.06, nb::ListKind::full, list);
  auto first = to_rows(list);
  const auto* storage = list.neighbors.data();
  search.build(x, 0.06, nb::ListKind::full, list);
  EXPECT_EQ(list.neighbors.data(), storage);  // no reallocation
  EXPECT_EQ(to_rows(list), first);            // rows in the same order, not just the same sets
}

TEST(BondFamily, ReferenceConfigurationFamily) {
  auto p = lattice<2>(10, 1.0);
  auto family = nb::build_bond_family<double, 2>(to_device<2>(p), 2.1);
  auto rows = to_rows(family);
  EXPECT_EQ(rows[4 * 10 + 4].size(), 12u);  // interior: 4 + 4 + 4 within 2.1 spacings (seed 000)
  EXPECT_EQ(rows[0].size(), 5u);            // corner: (1,0) (0,1) (1,1) (2,0) (0,2)
}

namespace {
void shift_particle(pm::VecView<double, 2> x, int i, double dx) {
  Kokkos::parallel_for(
      "test::shift", pm::range(1), KOKKOS_LAMBDA(int) { x(i, 0) += dx; });
}
}  // namespace

TEST(VerletList, RebuildsOnlyWhenAParticleMovesMoreThanHalfTheSkin) {
  auto p = random_cloud<2>(500, 1.0, 21);
  auto x = to_device<2>(p);
  const double radius = 0.05, skin = 0.02;
  nb::VerletList<double, 2> verlet(radius, skin, nb::ListKind::full);
  EXPECT_TRUE(verlet.update(x));
  EXPECT_EQ(verlet.builds(), 1);
  shift_particle(x, 7, 0.009);  // < skin / 2
  EXPECT_FALSE(verlet.update(x));
  // the list still holds every true pair within the radius (it is a superset)
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), x);
  Points<2> moved(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) moved[i] = {h(i, 0), h(i, 1)};
  auto ref = brute_force<2>(moved, radius, false);
  auto rows = to_rows(verlet.list());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int j : ref[i]) EXPECT_NE(std::find(rows[i].begin(), rows[i].end(), j), rows[i].end());
  shift_particle(x, 7, 0.002);  // now 0.011 > skin / 2
  EXPECT_TRUE(verlet.update(x));
  EXPECT_EQ(verlet.builds(), 2);
}

// The two-set search: for every query point, the points within the radius, against brute force; query
// points outside the points' bounding box (clamped to its boundary cells) find what is near them.
template <int D>
void expect_two_set_matches_brute_force(const Points<D>& queries, const Points<D>& points, double radius) {
  nb::NeighborSearch<double, D> search;
  nb::NeighborList list;
  search.build_between(to_device<D>(queries), to_device<D>(points), radius, list);
  auto rows = to_rows(list);
  ASSERT_EQ(rows.size(), queries.size());
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    std::vector<int> ref;
    for (std::size_t j = 0; j < points.size(); ++j) {
      double d2 = 0;
      for (int k = 0; k < D; ++k) d2 += (points[j][k] - queries[i][k]) * (points[j][k] - queries[i][k]);
      if (d2 <= radius * radius) ref.push_back(static_cast<int>(j));
    }
    auto r = rows[i];
    std::sort(r.begin(), r.end());
    ASSERT_EQ(r, ref) << "query " << i;
    pairs += r.size();
  }
  EXPECT_EQ(static_cast<std::size_t>(list.num_pairs), pairs);
  EXPECT_GT(pairs, 0u);
}

TEST(NeighborSearch, TwoSetsMatchBruteForce) {
  // queries spill over the points' box by 0.3 on every side
  auto shift = [](Points<3> p, double by) {
    for (auto& q : p)
      for (auto& c : q) c += by;
    return p;
  };
  const auto points = random_cloud<3>(1200, 1.0, 17);
  const auto queries = shift(random_cloud<3>(500, 1.6, 19), -0.3);
  for (double radius : {0.05, 0.12, 0.3}) expect_two_set_matches_brute_force<3>(queries, points, radius);
  expect_two_set_matches_brute_force<2>(random_cloud<2>(300, 1.0, 23), random_cloud<2>(900, 1.0, 29), 0.07);
}
