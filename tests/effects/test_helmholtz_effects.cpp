// Effects of the Helmholtz model: a case runs exactly the boundary kernels its boundaries need. The
// cube (Dirichlet only) launches and allocates nothing for impedance or vibrating faces; the duct
// (impedance + vibrating) nothing for Dirichlet DoFs. Counted through Kokkos Tools.
#include <gtest/gtest.h>

#include "../fem/helmholtz_fixtures.hpp"
#include "support/kernel_census.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;
using Model = hz::Helmholtz<double>;

namespace {

struct Measured {
  int iterations = 0;
  int colors = 0;  // element colours: one launch each per operator application
};

Measured solve_and_measure(const hz::Config& cfg) {
  Model m(cfg);
  const auto r = m.solve();
  EXPECT_TRUE(r.converged()) << r.reason;
  if (cfg.analytic.kind != hz::AnalyticKind::none) (void)m.l2_error();
  return {r.iterations, m.colors()};
}

}  // namespace

TEST(HelmholtzEffects, CubeRunsNoFaceKernels) {
  pm::testing::KernelCensus census;
  const auto [it, colors] = solve_and_measure(pm::testing::cube_case(2, 3));
  for (const char* part : {"impedance", "boundary_load", "face_geometry"})
    EXPECT_TRUE(census.kernels_containing(part).empty()) << part;
  for (const char* part : {"impedance", "vibrating", "face_"})
    EXPECT_TRUE(census.allocations_containing(part).empty()) << part;
  // Dirichlet rows once per operator application: initial and final true residual + one per iteration
  EXPECT_EQ(census.launches("polymech::fem::dirichlet_rows"), it + 2);
  EXPECT_EQ(census.launches("polymech::fem::dirichlet_lift"), colors);  // one lifting
  EXPECT_EQ(census.launches("polymech::fem::helmholtz_apply"), colors * (it + 2));
}

TEST(HelmholtzEffects, DuctRunsNoDirichletKernels) {
  pm::testing::KernelCensus census;
  const int it = solve_and_measure(pm::testing::duct_case(2, 10)).iterations;
  EXPECT_TRUE(census.kernels_containing("dirichlet").empty());
  EXPECT_TRUE(census.allocations_containing("dirichlet").empty());
  EXPECT_EQ(census.launches("polymech::fem::face_geometry"), 2);  // impedance and vibrating faces
  EXPECT_EQ(census.launches("polymech::fem::boundary_load"), 2);  // 2 colours of 2 x 1 vibrating faces
  EXPECT_EQ(census.launches("polymech::fem::impedance_apply"), 2 * (it + 2));
}

TEST(HelmholtzEffects, EveryDeclaredKernelOfAnEnabledEffectRuns) {
  std::vector<hz::BoundaryCondition> all = {{"xmin", hz::BoundaryKind::vibrating, 0.0, 0.01},
                                            {"xmax", hz::BoundaryKind::impedance, 445.9, 0.0},
                                            {"ymin", hz::BoundaryKind::dirichlet, 0.0, 0.0, 0.5}};
  pm::testing::KernelCensus census;
  solve_and_measure(pm::testing::box_config(2, {3, 2, 2}, {1.0, 0.5, 0.5}, all));
  for (const auto& spec : Model::effects())
    for (const auto& kernel : spec.kernels) EXPECT_GE(census.launches(kernel), 1) << spec.name << ": " << kernel;
}

TEST(HelmholtzEffects, BoundaryKindsAndEffectsMustAgree) {
  auto refused = [](const hz::Config& cfg) -> std::string {
    try {
      Model m(cfg);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  auto cfg = pm::testing::duct_case(1, 10);
  cfg.effects = pm::EffectSet::resolve({"vibrating"}, Model::effects());  // impedance boundary, no effect
  EXPECT_NE(refused(cfg).find("boundary 'xmax' is of kind impedance but effect 'impedance' is not enabled"),
            std::string::npos)
      << refused(cfg);
  cfg.effects = pm::EffectSet::resolve({"vibrating", "impedance", "dirichlet"}, Model::effects());
  EXPECT_NE(refused(cfg).find("effect 'dirichlet' is enabled but no boundary is of kind dirichlet"), std::string::npos)
      << refused(cfg);
}
