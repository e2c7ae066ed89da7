// Contact pairs keep their history across list rebuilds; the surface mesh's facet geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <utility>
#include <vector>

#include "contact/contact_pairs.hpp"
#include "contact/surface_mesh.hpp"

namespace pm = polymech;
namespace ct = polymech::contact;
namespace nb = polymech::neighbors;

namespace {

using PairMap = std::map<std::pair<int, int>, std::pair<double, int>>;  // (i, j) -> (value 0, state)

// The pairs of the current list with their history, on the host.
template <class Pairs>
PairMap pairs_of(const Pairs& p) {
  const auto& list = p.list();
  auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
  auto nbr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbors);
  auto val = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.history().values);
  auto st = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), p.history().state);
  PairMap m;
  for (int i = 0; i < list.num_particles; ++i)
    for (auto k = off(i); k < off(i + 1); ++k) m[{i, nbr(k)}] = {val(k, 0), st(k)};
  return m;
}

// Writes a history that names its pair: value = 1000 i + j, state = i + 1.
template <class Pairs>
void stamp(const Pairs& p) {
  const auto& list = p.list();
  auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
  auto nbr = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbors);
  auto val = Kokkos::create_mirror_view(p.history().values);
  auto st = Kokkos::create_mirror_view(p.history().state);
  for (int i = 0; i < list.num_particles; ++i)
    for (auto k = off(i); k < off(i + 1); ++k) {
      for (int c = 0; c < static_cast<int>(val.extent(1)); ++c) val(k, c) = 1000.0 * i + nbr(k) + c;
      st(k) = i + 1;
    }
  Kokkos::deep_copy(p.history().values, val);
  Kokkos::deep_copy(p.history().state, st);
}

}  // namespace

TEST(ContactPairs, HistorySurvivesRebuildsAndNewPairsStartAtZero) {
  const int n = 400;
  pm::VecView<double, 3> x("x", n);
  auto h = Kokkos::create_mirror_view(x);
  std::mt19937 g(7);
  std::uniform_real_distribution<double> u(0.0, 4.0);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) h(i, k) = u(g);
  Kokkos::deep_copy(x, h);
  ct::ContactPairs<double, 3, 3> pairs(0.5, 0.1, nb::ListKind::half);
  EXPECT_TRUE(pairs.update(x));
  stamp(pairs);
  const PairMap before = pairs_of(pairs);
  EXPECT_FALSE(pairs.update(x)) << "nothing moved: no rebuild";
  // move every particle by 0.3 in a random direction: more than skin / 2, so the list is rebuilt
  std::normal_distribution<double> nd;
  for (int i = 0; i < n; ++i) {
    double d[3] = {nd(g), nd(g), nd(g)};
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    for (int k = 0; k < 3; ++k) h(i, k) += 0.3 * d[k] / len;
  }
  Kokkos::deep_copy(x, h);
  EXPECT_TRUE(pairs.update(x));
  EXPECT_EQ(pairs.builds(), 2);
  const PairMap after = pairs_of(pairs);
  int kept = 0, fresh = 0;
  for (const auto& [ij, hist] : after) {
    const auto it = before.find(ij);
    if (it != before.end()) {
      EXPECT_EQ(hist, it->second) << "pair " << ij.first << "-" << ij.second << " lost its history";
      ++kept;
    } else {
      EXPECT_EQ(hist, std::make_pair(0.0, 0)) << "new pair " << ij.first << "-" << ij.second;
      ++fresh;
    }
  }
  EXPECT_GT(kept, 100);
  EXPECT_GT(fresh, 100);
}

TEST(ContactPairs, TwoSetsRebuildWhenEitherSetMoves) {
  pm::VecView<double, 3> spheres("spheres", 1), points("points", 2);
  auto hs = Kokkos::create_mirror_view(spheres);
  auto hp = Kokkos::create_mirror_view(points);
  hs(0, 0) = hs(0, 1) = hs(0, 2) = 0.0;
  hp(0, 0) = 0.4, hp(0, 1) = hp(0, 2) = 0.0;  // near
  hp(1, 0) = 3.0, hp(1, 1) = hp(1, 2) = 0.0;  // far
  Kokkos::deep_copy(spheres, hs);
  Kokkos::deep_copy(points, hp);
  ct::ContactPairs<double, 3, 1> pairs(0.5, 0.2, nb::ListKind::full);
  EXPECT_TRUE(pairs.update(spheres, points));
  EXPECT_EQ(pairs.list().num_pairs, 1);
  stamp(pairs);
  hp(1, 0) = 0.45;  // the far point (a facet node, say) comes close: only the points moved
  Kokkos::deep_copy(points, hp);
  EXPECT_TRUE(pairs.update(spheres, points));
  const PairMap m = pairs_of(pairs);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.at({0, 0}).second, 1) << "the old pair keeps its state";
  EXPECT_EQ(m.at({0, 1}).second, 0) << "the new pair starts fresh";
}

// A unit cube of six quadrilaterals (outward node order) and one triangle: outward unit normals,
// centroids at the face centres, bounding radius sqrt(2)/2; moving the nodes moves the geometry.
TEST(SurfaceMesh, FacetGeometryOfACubeFollowsItsNodes) {
  std::vector<double> nodes;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) nodes.insert(nodes.end(), {double(i), double(j), double(k)});
  auto id = [](int i, int j, int k) { return static_cast<pm::Index>(i + 2 * j + 4 * k); };
  const std::vector<pm::Index> quads = {id(0, 0, 0), id(0, 1, 0), id(1, 1, 0), id(1, 0, 0),   // z = 0, -z
                                        id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1),   // z = 1, +z
                                        id(0, 0, 0), id(1, 0, 0), id(1, 0, 1), id(0, 0, 1),   // y = 0, -y
                                        id(0, 1, 0), id(0, 1, 1), id(1, 1, 1), id(1, 1, 0),   // y = 1, +y
                                        id(0, 0, 0), id(0, 0, 1), id(0, 1, 1), id(0, 1, 0),   // x = 0, -x
                                        id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1),   // x = 1, +x
                                        id(0, 0, 1), id(1, 0, 1), id(1, 1, 1)};               // a triangle on top
  const std::vector<int> sizes = {4, 4, 4, 4, 4, 4, 3};
  auto m = ct::make_surface_mesh<double>(nodes, sizes, quads, "cube");
  const double expected[6][3] = {{0, 0, -1}, {0, 0, 1}, {0, -1, 0}, {0, 1, 0}, {-1, 0, 0}, {1, 0, 0}};
  auto n = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.normal);
  auto c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.centroid);
  auto r = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.radius);
  for (int f = 0; f < 6; ++f) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(n(f, k), expected[f][k], 1e-15) << "facet " << f;
      EXPECT_NEAR(c(f, k), 0.5 + 0.5 * expected[f][k], 1e-15) << "facet " << f;
    }
    EXPECT_NEAR(r(f), std::sqrt(0.5), 1e-15);
  }
  EXPECT_NEAR(n(6, 2), 1.0, 1e-15);
  EXPECT_NEAR(c(6, 0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(ct::max_facet_radius(m), std::sqrt(5.0) / 3.0, 1e-15);  // the triangle: (0, 0, 1) from (2/3, 1/3, 1)
  // lift the whole cube by 2: centroids follow, normals stay
  auto hn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.nodes);
  for (int i = 0; i < 8; ++i) hn(i, 2) += 2.0;
  Kokkos::deep_copy(m.nodes, hn);
  ct::update_geometry(m);
  c = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.centroid);
  EXPECT_NEAR(c(1, 2), 3.0, 1e-15);
  // a facet of five nodes and a node index outside the mesh are clear errors
  EXPECT_THROW(ct::make_surface_mesh<double>(nodes, {5}, {0, 1, 2, 3, 4}, "bad"), std::invalid_argument);
  EXPECT_THROW(ct::make_surface_mesh<double>(nodes, {3}, {0, 1, 8}, "bad"), std::invalid_argument);
}
