// Hard cases of seed 002 paper 3's Helmholtz problem: they converge, or stop with a stated reason.
//  - distorted elements: an inverted or folded element is a clear error naming it;
//  - the cube at 2 kHz: strongly indefinite and within 1.5e-5 of a Dirichlet resonance of the cube;
//    COCG still converges (many more iterations than at 500 Hz);
//  - the duct at 2 kHz: the pollution effect; at equal DoFs order 4 is far more accurate than order 1;
//  - float: COCG stops at the precision's attainable accuracy, saying so, with the same L2 error as
//    double where the discretization error dominates.
#include <gtest/gtest.h>

#include "helmholtz_fixtures.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

TEST(HelmholtzHardCases, InvertedElementsAreRefusedByName) {
  auto cfg = pm::testing::cube_case(2, 4);
  cfg.mesh = hz::make_box_mesh({{0, 0, 0}, {1, 1, 1}, {4, 4, 4}, 0.9, 3});
  try {
    hz::Helmholtz<double> m(cfg);
    FAIL() << "a mesh with inverted elements was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("is inverted or too distorted"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("allowed: > 0 everywhere"), std::string::npos) << e.what();
  }
  // curved elements folded by moving the high-order nodes too far (the linear mesh is fine)
  auto curved = pm::testing::cube_case(4, 2);
  curved.node_perturbation = 1.5;
  EXPECT_THROW(hz::Helmholtz<double> m(curved), std::invalid_argument);
  // and moderately distorted ones are fine
  auto mild = pm::testing::cube_case(2, 4);
  mild.mesh = hz::make_box_mesh({{0, 0, 0}, {1, 1, 1}, {4, 4, 4}, 0.25, 3});
  hz::Helmholtz<double> ok(mild);
  EXPECT_GT(ok.min_jacobian_ratio(), 0.0);
  EXPECT_LT(ok.min_jacobian_ratio(), 0.9);
}

TEST(HelmholtzHardCases, NearlyResonantCubeAt2kHzConverges) {
  hz::Helmholtz<double> lo(pm::testing::cube_case(2, 8, 500.0));
  const auto r500 = lo.solve();
  hz::Helmholtz<double> hi(pm::testing::cube_case(2, 8, 2000.0));
  const auto r2k = hi.solve();
  EXPECT_EQ(r2k.status, pm::solvers::SolveStatus::converged) << r2k.reason;
  EXPECT_LE(r2k.true_relative_residual, 1e-10);
  EXPECT_GT(r2k.iterations, 3 * r500.iterations);  // 324 vs 52 at this size
  // the error is O(1): 12 nodes per wavelength next to a resonance amplify the discretization error
  const double e = hi.l2_error().relative();
  EXPECT_TRUE(std::isfinite(e));
  EXPECT_GT(e, 0.1);
}

TEST(HelmholtzHardCases, PollutionAt2kHzFavoursHighOrder) {
  // 1845 DoFs each: order 1 on 40 x 8 x 4 elements, order 4 on 10 x 2 x 1
  hz::Helmholtz<double> p1(pm::testing::duct_case(1, 40, 2000.0)), p4(pm::testing::duct_case(4, 10, 2000.0));
  ASSERT_EQ(p1.dof_count(), p4.dof_count());
  EXPECT_TRUE(p1.solve().converged());
  EXPECT_TRUE(p4.solve().converged());
  const double e1 = p1.l2_error().relative(), e4 = p4.l2_error().relative();
  EXPECT_GT(e1, 0.3);       // 0.66: linear elements at 7 nodes per wavelength are polluted
  EXPECT_LT(e4, 0.05 * e1);  // 0.013
}

TEST(HelmholtzHardCases, FloatStopsAtItsAttainableAccuracy) {
  hz::Helmholtz<double> d(pm::testing::cube_case(2, 4));
  hz::Helmholtz<float> f(pm::testing::cube_case(2, 4));
  const auto rd = d.solve();
  const auto rf = f.solve();
  EXPECT_TRUE(rd.converged()) << rd.reason;
  EXPECT_EQ(rf.status, pm::solvers::SolveStatus::stagnated) << rf.reason;
  EXPECT_NE(rf.reason.find("attainable accuracy in float"), std::string::npos) << rf.reason;
  EXPECT_LT(rf.true_relative_residual, 1e-5);
  const double ed = d.l2_error().relative(), ef = f.l2_error().relative();
  EXPECT_NEAR(ef, ed, 1e-3 * ed);  // 8.1e-2: the discretization error dominates the float floor
}
