// The crack of the MPS model (seed 000 §4): which bonds it cuts, the contact pairs, the closed crack at
// rest, the effects census, and the hard cases: contact stiffness k' from 0.01 to 1 for a whole
// 5-cycle pulse, a crack reaching the free surface, and a crack one spacing long.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "mps_elastic/mps_elastic.hpp"
#include "mps_elastic/run.hpp"
#include "support/kernel_census.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;
using Model = me::MpsElastic<double>;

namespace {

constexpr double l0 = 1e-4;

// 6 mm x 8 mm plate, plane P wave from the top (eq. (23)), a horizontal crack 1 mm long in the middle.
me::Config plate(const std::vector<std::string>& effects, double k_prime = 0.1) {
  me::Config c;
  c.width = 60 * l0;
  c.height = 80 * l0;
  c.spacing = l0;
  c.dt = 4e-9;  // the paper's dt / l0
  c.excitation.kind = me::ExcitationKind::plane_p;
  c.excitation.cycles = 5;
  c.crack.mode = me::CrackMode::cut;
  c.crack.x1 = 30 * l0;
  c.crack.x3 = 40 * l0;  // between rows 39 and 40
  c.crack.length = 10 * l0;
  c.crack.k_prime = k_prime;
  c.crack.normal_reaction = 1e-3;
  c.probes.push_back({"below", 30 * l0, 35 * l0});
  c.effects = pm::EffectSet::resolve(effects, Model::effects());
  return c;
}

double max_abs(const pm::VecView<double, 2>& v) {
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
  double m = 0;
  for (std::size_t i = 0; i < h.extent(0); ++i) m = std::max({m, std::abs(h(i, 0)), std::abs(h(i, 1))});
  return m;
}

}  // namespace

TEST(MpsCrack, CutsExactlyTheBondsCrossingTheCrack) {
  const auto c = plate({"rotation", "crack_contact.open_close"});
  Model cracked(c);
  me::Config intact_cfg = c;
  intact_cfg.crack.mode = me::CrackMode::none;
  intact_cfg.effects = pm::EffectSet::resolve({"rotation"}, Model::effects());
  Model intact(intact_cfg);
  const auto seg = cracked.crack().segment();
  // brute force over the intact family
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), intact.fields().x0);
  auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), intact.family().offsets);
  auto nb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), intact.family().neighbors);
  std::set<std::pair<int, int>> cut;
  for (pm::Index i = 0; i < intact.particles(); ++i)
    for (pm::Offset k = off(i); k < off(i + 1); ++k)
      if (seg.cuts(x0(i, 0), x0(i, 1), x0(nb(k), 0), x0(nb(k), 1))) cut.insert({i, nb(k)});
  EXPECT_EQ(intact.bonds() - cracked.bonds(), static_cast<pm::Offset>(cut.size()));
  EXPECT_EQ(cracked.crack().cut_bonds(), static_cast<std::int64_t>(cut.size()));
  auto coff = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cracked.family().offsets);
  auto cnb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), cracked.family().neighbors);
  for (pm::Index i = 0; i < cracked.particles(); ++i)
    for (pm::Offset k = coff(i); k < coff(i + 1); ++k) ASSERT_EQ(cut.count({i, cnb(k)}), 0u);
  // a 10-spacing horizontal crack between rows: one opposite pair per column
  EXPECT_EQ(cracked.crack().pair_count(), 10);
  // r_e = 2.1 l0, crack over columns 25..34 between rows 39 and 40. Undirected bonds crossing it:
  // (0, 1): 10; (0, 2) from rows 40 and 41: 20; (+-1, 1): 20, the ones leaving the end columns
  // outwards cross exactly at the tips (inclusive). (1, 2) is sqrt(5) l0 > r_e. 50 bonds, 100 directed.
  EXPECT_EQ(cut.size(), 100u);
}

TEST(MpsCrack, ObliqueCrackPairsLieAcrossTheLine) {
  auto c = plate({"crack_contact.open_close", "crack_contact.slip"});
  c.crack.angle = 45.0;
  Model m(c);
  ASSERT_GT(m.crack().pair_count(), 0);
  const auto seg = m.crack().segment();
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
  auto plus = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.crack().pairs().plus);
  auto minus = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.crack().pairs().minus);
  for (pm::Index k = 0; k < m.crack().pair_count(); ++k) {
    EXPECT_TRUE(seg.upper(x0(plus(k), 0), x0(plus(k), 1)));
    EXPECT_FALSE(seg.upper(x0(minus(k), 0), x0(minus(k), 1)));
    EXPECT_LE(std::hypot(x0(plus(k), 0) - x0(minus(k), 0), x0(plus(k), 1) - x0(minus(k), 1)), 1.0001 * l0);
  }
}

TEST(MpsCrack, ClosedCrackAtRestIsForceFree) {
  auto c = plate({"rotation", "crack_contact.open_close", "crack_contact.slip"});
  c.excitation.kind = me::ExcitationKind::none;
  Model m(c);
  m.step();
  EXPECT_EQ(max_abs(m.fields().a), 0.0);
  EXPECT_EQ(max_abs(m.fields().u), 0.0);
}

TEST(MpsCrack, DisabledContactEffectsLaunchAndAllocateNothing) {
  {
    pm::testing::KernelCensus census;
    Model m(plate({"rotation"}));  // a free crack: cut, no contact
    for (int s = 0; s < 5; ++s) m.step();
    EXPECT_TRUE(census.kernels_containing("polymech::contact::").empty());
    EXPECT_TRUE(census.allocations_containing("polymech::contact::").empty());
  }
  {
    pm::testing::KernelCensus census;
    Model m(plate({"rotation", "crack_contact.open_close"}));
    for (int s = 0; s < 5; ++s) m.step();
    EXPECT_EQ(census.launches("polymech::contact::crack_open_close"), 5);
    EXPECT_EQ(census.launches("polymech::contact::crack_apply_forces"), 5);
    EXPECT_EQ(census.launches("polymech::contact::crack_slip"), 0);
    EXPECT_TRUE(census.allocations_containing("crack_slip").empty());
  }
  {
    pm::testing::KernelCensus census;
    Model m(plate({"rotation", "crack_contact.slip"}));
    for (int s = 0; s < 5; ++s) m.step();
    EXPECT_EQ(census.launches("polymech::contact::crack_slip"), 5);
    EXPECT_EQ(census.launches("polymech::contact::crack_open_close"), 0);
    EXPECT_TRUE(census.allocations_containing("crack_slip_normal_force").empty());  // only with open_close
    EXPECT_FALSE(census.allocations_containing("crack_slip_anchor").empty());
  }
}

TEST(MpsCrack, InconsistentCrackSettingsAreClearErrors) {
  auto c = plate({"rotation", "crack_contact.slip"});
  c.crack.normal_reaction = 0.0;  // slip alone with nothing pressing the faces together
  EXPECT_THROW(Model{c}, std::invalid_argument);
  c = plate({"rotation", "crack_contact.open_close"});
  c.crack.x1 = 1.0;  // far outside the plate: cuts nothing
  EXPECT_THROW(Model{c}, std::invalid_argument);
  c = plate({"rotation", "crack_contact.open_close"});
  c.crack.mode = me::CrackMode::none;
  EXPECT_THROW(Model{c}, std::invalid_argument);
  c = plate({"rotation", "crack_contact.open_close"}, 2.5);
  EXPECT_THROW(Model{c}, std::invalid_argument);
}

// k' = 0.01 .. 1 (eq. (19)): the whole 5-cycle pulse and its reflections stay bounded.
TEST(MpsCrack, ContactStiffnessFromHundredthToOneStaysBounded) {
  for (double kp : {0.01, 0.1, 1.0}) {
    auto c = plate({"rotation", "crack_contact.open_close", "crack_contact.slip"}, kp);
    Model m(c);
    const auto steps = static_cast<std::int64_t>(1.5 * 5 * c.excitation.period / c.dt);
    const auto stats = me::run(m, steps);
    EXPECT_TRUE(stats.finite) << "k' = " << kp;
    EXPECT_LT(max_abs(m.fields().u), 4 * c.excitation.amplitude) << "k' = " << kp;
    const auto n = m.crack().counts();
    EXPECT_EQ(n.separation + n.stick + n.slip, m.crack().pair_count());
  }
}

TEST(MpsCrack, CrackThroughTheFreeSurfaceAndOneSpacingLongRun) {
  auto edge = plate({"rotation", "crack_contact.open_close", "crack_contact.slip"});
  edge.crack.x1 = 2 * l0;  // from inside the plate through its left edge
  edge.crack.length = 10 * l0;
  Model a(edge);
  EXPECT_GT(a.crack().pair_count(), 0);
  EXPECT_LT(a.crack().pair_count(), 10);  // only the part inside the plate
  EXPECT_TRUE(me::run(a, 700).finite);
  EXPECT_LT(max_abs(a.fields().u), 4 * edge.excitation.amplitude);

  auto tiny = plate({"rotation", "crack_contact.open_close"});
  tiny.crack.x1 = 30.5 * l0;  // centred on a particle column
  tiny.crack.length = l0;
  Model b(tiny);
  EXPECT_EQ(b.crack().pair_count(), 1);
  EXPECT_TRUE(me::run(b, 700).finite);
  EXPECT_LT(max_abs(b.fields().u), 4 * tiny.excitation.amplitude);
}
