// The shifted-Laplacian preconditioners of COCG (models/helmholtz/preconditioners.hpp) on the paper's
// cases (seed 002 paper 3 §3(2), §3(3), reduced sizes): the same solution as with Jacobi (L2 error of
// eq. (28) to 1e-6 relative: both solve to the tolerance 1e-10), in fewer iterations, and the
// p-multigrid's iterations nearly independent of the mesh.
#include <gtest/gtest.h>

#include <cstdio>

#include "helmholtz_fixtures.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

namespace {

struct Outcome {
  int iterations = 0;
  double error = 0.0;
};

Outcome solve(hz::Config cfg, hz::Preconditioner pc) {
  cfg.preconditioner = pc;
  hz::Helmholtz<double> m(cfg);
  const auto r = m.solve();
  EXPECT_TRUE(r.converged()) << hz::to_string(pc) << ": " << r.reason;
  EXPECT_LE(r.true_relative_residual, 1e-10);
  if (pc != hz::Preconditioner::jacobi && pc != hz::Preconditioner::none)
    std::printf("  %s: %s\n", hz::to_string(pc), m.preconditioner_description().c_str());
  return {r.iterations, m.l2_error().relative()};
}

void compare(const char* name, const hz::Config& cfg, double min_gain) {
  const Outcome j = solve(cfg, hz::Preconditioner::jacobi);
  const Outcome c = solve(cfg, hz::Preconditioner::chebyshev);
  const Outcome g = solve(cfg, hz::Preconditioner::pmg);
  std::printf("%s p = %d: iterations jacobi %d, chebyshev %d, pmg %d; L2 error %.6e / %.6e / %.6e\n", name, cfg.order,
              j.iterations, c.iterations, g.iterations, j.error, c.error, g.error);
  EXPECT_NEAR(c.error, j.error, 1e-6 * j.error) << name;
  EXPECT_NEAR(g.error, j.error, 1e-6 * j.error) << name;
  EXPECT_LT(g.iterations * min_gain, j.iterations) << name;
  EXPECT_LT(c.iterations * min_gain, j.iterations) << name;
}

}  // namespace

TEST(HelmholtzPreconditioners, CubeSameSolutionFewerIterations) {
  compare("cube", pm::testing::cube_case(2, 8), 2.0);
  compare("cube", pm::testing::cube_case(3, 6), 3.0);
  compare("cube", pm::testing::cube_case(4, 4), 3.0);
}

TEST(HelmholtzPreconditioners, DuctWithImpedanceSameSolutionFewerIterations) {
  compare("duct", pm::testing::duct_case(3, 20), 3.0);
  compare("duct 2 kHz", pm::testing::duct_case(4, 10, 2000.0), 1.5);  // more of it is indefinite
}

// Jacobi's iterations grow with the DoFs per direction; the p-multigrid's stay nearly flat.
TEST(HelmholtzPreconditioners, MultigridIterationsHardlyGrowWithTheMesh) {
  const Outcome coarse = solve(pm::testing::cube_case(3, 4), hz::Preconditioner::pmg);
  const Outcome fine = solve(pm::testing::cube_case(3, 8), hz::Preconditioner::pmg);
  const Outcome jc = solve(pm::testing::cube_case(3, 4), hz::Preconditioner::jacobi);
  const Outcome jf = solve(pm::testing::cube_case(3, 8), hz::Preconditioner::jacobi);
  std::printf("p = 3, n = 4 -> 8: jacobi %d -> %d, pmg %d -> %d\n", jc.iterations, jf.iterations, coarse.iterations,
              fine.iterations);
  EXPECT_GT(jf.iterations, 1.7 * jc.iterations);
  EXPECT_LT(fine.iterations, 1.3 * coarse.iterations + 2);
}
