// MPI domain decomposition of the Helmholtz model (seed 002 paper 3 §4, Fig. 9: the solution does not
// change with the number of parts). Run by ctest with 2 and 3 ranks (mpirun --oversubscribe); every
// rank also solves the whole problem on its own, and the distributed solution gathered on rank 0, the
// L2 error of eq. (28) and the iteration count must match it to the solver tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "helmholtz/mpi_communicator.hpp"
#include "helmholtz_fixtures.hpp"
#include "io/helmholtz_scene.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

namespace {

std::shared_ptr<const hz::Communicator> world;

struct Run {
  int iterations = 0;
  double error = 0.0;
  std::vector<std::complex<double>> solution;  // rank 0 (distributed) or every rank (serial)
  pm::Index ghosts = 0;
};

Run solve(hz::Config cfg, bool distributed, hz::Preconditioner pc = hz::Preconditioner::jacobi) {
  cfg.communicator = distributed ? world : nullptr;
  cfg.preconditioner = pc;
  hz::Helmholtz<double> m(cfg);
  const auto r = m.solve();
  EXPECT_TRUE(r.converged()) << r.reason;
  Run out;
  out.iterations = r.iterations;
  out.error = m.l2_error().relative();
  out.solution = m.host_solution();
  out.ghosts = static_cast<pm::Index>(m.part().global_of_local.size()) - m.part().owned;
  return out;
}

void compare(const char* name, const hz::Config& cfg, hz::Preconditioner pc = hz::Preconditioner::jacobi) {
  const Run serial = solve(cfg, false, pc), parts = solve(cfg, true, pc);
  if (world->rank() == 0) {
    double diff = 0, ref = 0;
    for (std::size_t i = 0; i < serial.solution.size(); ++i) {
      diff = std::max(diff, std::abs(parts.solution[i] - serial.solution[i]));
      ref = std::max(ref, std::abs(serial.solution[i]));
    }
    std::printf("%s, %d ranks, %s: iterations %d (one part %d), L2 error %.10e (one part %.10e), max |difference| / max "
                "|Phi| = %.2e\n",
                name, world->size(), hz::to_string(pc), parts.iterations, serial.iterations, parts.error, serial.error,
                diff / ref);
    ASSERT_EQ(parts.solution.size(), serial.solution.size());
    EXPECT_LT(diff / ref, 1e-7) << name;
  }
  EXPECT_NEAR(parts.error, serial.error, 1e-7 * serial.error) << name;
  EXPECT_LE(std::abs(parts.iterations - serial.iterations), 3) << name << ": summation order only";
  EXPECT_GT(parts.ghosts, 0) << name << ": every part has neighbours";
}

}  // namespace

TEST(HelmholtzMpi, CubeSolutionIndependentOfTheParts) {
  compare("cube p = 1, 10^3 elements (1331 nodes, Table 3)", pm::testing::cube_case(1, 10));
  compare("cube p = 3, 5^3 elements", pm::testing::cube_case(3, 5));
}

TEST(HelmholtzMpi, DuctWithImpedanceAndVibratingFaces) {
  compare("duct p = 2, 20 x 4 x 2 elements", pm::testing::duct_case(2, 20));
}

TEST(HelmholtzMpi, ChebyshevPreconditionerAcrossParts) {
  compare("cube p = 2, 6^3 elements", pm::testing::cube_case(2, 6), hz::Preconditioner::chebyshev);
}

TEST(HelmholtzMpi, GmshMeshSplitByMetis) {
  const auto dir = std::filesystem::path(std::getenv("POLYMECH_SOURCE_DIR") ? std::getenv("POLYMECH_SOURCE_DIR") : ".");
  pm::io::HelmholtzSceneOptions o;
  o.order = 2;
  auto scene = pm::io::load_helmholtz_scene(dir / "scenes/helmholtz/duct_gmsh.toml", o);
  scene.config.partition = hz::metis_available() ? hz::PartitionMethod::metis : hz::PartitionMethod::structured;
  compare("Gmsh duct p = 2", scene.config);
}

TEST(HelmholtzMpi, MultigridIsRefusedWithSeveralParts) {
  hz::Config cfg = pm::testing::cube_case(2, 4);
  cfg.communicator = world;
  cfg.preconditioner = hz::Preconditioner::pmg;
  hz::Helmholtz<double> m(cfg);
  try {
    m.solve();
    FAIL() << "pmg accepted with " << world->size() << " ranks";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("allowed with"), std::string::npos) << e.what();
  }
}

int main(int argc, char** argv) {
  hz::MpiSession mpi(argc, argv);
  world = mpi.world();
  ::testing::InitGoogleTest(&argc, argv);
  pm::kx::initialize();
  int rc = RUN_ALL_TESTS();
  Kokkos::finalize();
  world.reset();
  return rc;
}
