// Accuracy-cost sweep of Cook's membrane (issue 34; models/solid/cases.hpp): the top-right vertical
// displacement's error (plane stress, E = 70, nu = 1/3, traction 6250) per order 1..4
// and mesh, double and float, solved matrix-free by Jacobi CG and (double) by the host sparse LU, with the
// wall time of set-up and solve. The error is against the Richardson limit of order 4 on 16, 32 and 64 cells
// per side (LU, double; the `reference` column), not the rounded published value. Writes CSV rows for
// tools/plot_accuracy_cost.py:
//   order,n,dofs,is_float,direct,iterations,converged,tip,reference,tip_error,setup_seconds,solve_seconds,wall_seconds
// (direct: 1 for the sparse LU, 0 for CG; every column numeric for the plot tool)
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_solid_cook out/sweep_solid_cook.csv
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "core/kokkos_shim.hpp"
#include "solid/analysis.hpp"
#include "solid/cases.hpp"

namespace so = polymech::solid;

namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }

template <class T>
void run(std::ofstream& out, int order, int n, bool direct, double ref) {
  so::CookSpec s;
  s.order = order;
  s.n = n;
  const auto t0 = clock_type::now();
  so::LinearElastic<T, 2> m(so::cook_membrane(s));
  Kokkos::fence();
  const double setup = since(t0);
  const auto t1 = clock_type::now();
  int iterations = 0;
  bool converged = true;
  if (direct) {
    m.solve_direct();
  } else {
    polymech::solvers::SolverOptions o;
    o.tolerance = sizeof(T) == 4 ? 1e-6 : 1e-10;  // near the attainable accuracy of each precision
    o.max_iterations = 200000;
    o.stagnation_window = 50000;  // Jacobi CG on the finest meshes plateaus for thousands of iterations
    const auto r = m.solve_cg(o);
    iterations = r.iterations;
    converged = r.converged();
  }
  Kokkos::fence();
  const double solve = since(t1);
  const double tip = so::displacement_at(m, {48.0, 60.0})[1];
  char line[320];
  std::snprintf(line, sizeof line, "%d,%d,%d,%d,%d,%d,%d,%.9g,%.9g,%.6e,%.6e,%.6e,%.6e\n", order, n, m.dof_count(),
                sizeof(T) == 4 ? 1 : 0, direct ? 1 : 0, iterations, converged ? 1 : 0, tip, ref,
                std::abs(tip / ref - 1.0), setup, solve, setup + solve);
  out << line;
  out.flush();
  std::fputs(line, stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : "sweep_solid_cook.csv";
  polymech::kx::initialize();
  {
    std::ofstream out(path + ".part");
    double v[3];
    for (int k = 0; k < 3; ++k) {
      so::CookSpec s;
      s.order = 4;
      s.n = 16 << k;
      so::LinearElastic<double, 2> m(so::cook_membrane(s));
      m.solve_direct();
      v[k] = so::displacement_at(m, {48.0, 60.0})[1];
    }
    const double ref = v[2] + (v[2] - v[1]) * (v[2] - v[1]) / ((v[1] - v[0]) - (v[2] - v[1]));
    std::printf("reference: order 4, n = 16, 32, 64: %.6f %.6f %.6f, Richardson %.6f (u E / F = %.5f)\n", v[0], v[1],
                v[2], ref, ref * 70.0 / 1e5);
    out << "order,n,dofs,is_float,direct,iterations,converged,tip,reference,tip_error,setup_seconds,solve_seconds,"
           "wall_seconds\n";
    for (int p = 1; p <= 4; ++p)
      for (int n = 2; n <= (p <= 2 ? 64 : 32); n *= 2) {
        run<double>(out, p, n, true, ref);
        run<double>(out, p, n, false, ref);
        run<float>(out, p, n, false, ref);
      }
  }
  std::rename((path + ".part").c_str(), path.c_str());
  Kokkos::finalize();
  return 0;
}
