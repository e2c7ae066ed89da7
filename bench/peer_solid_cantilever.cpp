// Our side of the CalculiX comparison on a 3D anisotropic cantilever (issue 34; the peer script is
// bench/peers/calculix/cantilever_aniso.py, which runs this executable and ccx alternately on the same meshes).
//
// The case: a box beam [0, 12] x [-1.25, 1.25] x [-1.5, 0] (um: length, width, height, the micro-cantilever's
// outer dimensions without the pentagon's undercut), cubic 8YSZ (C11, C12, C44 = 401, 96, 56 GPa;
// kernels/materials/cubic_elastic.hpp) rotated to the beam axis at theta from [001] in the (110) top face
// (cantilever_rotation), clamped at x = 0, a uniform traction of total force F = 0.1 mN along -z on x = 12
// (units GPa = mN/um^2, um, mN). The output is the vertical displacement at the end face's centre
// (12, 0, -0.75), which is a lattice node for even cell counts in y and z, so both codes report a nodal value.
//
//   peer_solid_cantilever ORDER NX NY NZ THETA_DEG SOLVER(lu|cg|mg)
// (lu: the assembled matrix's sparse LU with COLAMD, kernels/solvers/host_sparse_lu.hpp; cg: matrix-free
// Jacobi CG to 1e-9; mg: CG to 1e-9 with the two-level p-multigrid of models/solid/two_level.hpp. In 3D
// Jacobi CG is 5x faster than the LU already at 1.6e4 DoFs and the LU's fill explodes beyond; an Eigen
// simplicial LDL^T with AMD measured slower still than the LU, docs/PERFORMANCE.md)
// prints one line: order,nx,ny,nz,theta,dofs,solver,iterations,tip_uz,setup_seconds,solve_seconds
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "core/kokkos_shim.hpp"
#include "materials/cubic_elastic.hpp"
#include "solid/analysis.hpp"
#include "solid/two_level.hpp"

namespace so = polymech::solid;
namespace ma = polymech::materials;

namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }

constexpr double length = 12.0, width = 2.5, height = 1.5, force = 0.1;

so::Config<3> box_cantilever(int order, int nx, int ny, int nz, double theta_deg) {
  so::BoxSpec b;
  b.origin = {0.0, -0.5 * width, -height};
  b.lengths = {length, width, height};
  b.cells = {nx, ny, nz};
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = order;
  const double theta = theta_deg * 3.14159265358979323846 / 180.0;
  c.stiffness = ma::rotated_cubic_stiffness(ma::ysz8_constants_gpa<double>(), ma::cantilever_rotation(theta));
  c.dirichlet.push_back({"xmin", 7u, {}});
  c.tractions.push_back({"xmax", {0.0, 0.0, -force / (width * height)}});
  return c;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::fprintf(stderr, "usage: %s ORDER NX NY NZ THETA_DEG lu|cg|mg\n", argv[0]);
    return 2;
  }
  const int order = std::atoi(argv[1]), nx = std::atoi(argv[2]), ny = std::atoi(argv[3]), nz = std::atoi(argv[4]);
  const double theta = std::atof(argv[5]);
  const std::string solver = argv[6];
  if (order < 1 || order > 4 || nx < 1 || ny < 2 || nz < 2 || ny % 2 || nz % 2 || (solver != "lu" && solver != "cg" && solver != "mg")) {
    std::fprintf(stderr, "%s: order 1..4, NX >= 1, NY and NZ even and >= 2, solver lu, cg or mg\n", argv[0]);
    return 2;
  }
  polymech::kx::initialize();
  int status = 0;
  {
    const auto t0 = clock_type::now();
    so::LinearElastic<double, 3> m(box_cantilever(order, nx, ny, nz, theta));
    Kokkos::fence();
    const double setup = since(t0);
    const auto t1 = clock_type::now();
    int iterations = 0;
    if (solver == "lu") {
      m.solve_direct();
    } else if (solver == "mg") {
      const auto tp = clock_type::now();
      const auto inv = m.op().inverse_diagonal();
      const so::TwoLevel<double, 3, so::ElasticOperator<double, 3>> mg(&m.op(), inv, m.config(), m.discretization(),
                                                                       m.constrained_mask());
      std::fprintf(stderr, "two-level set-up %.3f s, %s\n", since(tp), mg.describe().c_str());
      polymech::solvers::SolverOptions o;
      o.tolerance = 1e-9;
      o.max_iterations = 20000;
      Kokkos::deep_copy(m.displacement(), 0.0);
      const auto r = polymech::solvers::cg_preconditioned(m.op(), mg, m.rhs(), m.displacement(), o);
      iterations = r.iterations;
      if (!r.converged()) {
        std::fprintf(stderr, "two-level CG: %s (%s), relative residual %.3e\n", polymech::solvers::to_string(r.status),
                     r.reason.c_str(), r.true_relative_residual);
        status = 1;
      }
    } else {
      polymech::solvers::SolverOptions o;
      o.tolerance = 1e-9;
      o.max_iterations = 200000;
      o.stagnation_window = 50000;
      const auto r = m.solve_cg(o);
      iterations = r.iterations;
      if (!r.converged()) status = 1;
    }
    Kokkos::fence();
    const double solve = since(t1);
    const double tip = so::displacement_at(m, {length, 0.0, -0.5 * height})[2];
    std::printf("%d,%d,%d,%d,%g,%d,%s,%d,%.10g,%.6e,%.6e\n", order, nx, ny, nz, theta, static_cast<int>(m.dof_count()),
                solver.c_str(), iterations, tip, setup, solve);
  }
  Kokkos::finalize();
  return status;
}
