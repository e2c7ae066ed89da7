// Structural dynamics of the solid layer (issue 34; models/solid/dynamics.hpp):
//   BM_ExplicitStep<T>/p/n        one central-difference step (lumped mass, one fused matrix-free elastic apply
//                                 and two vector kernels; energy tracking off) on an n^3 box of order-p hexahedra
//                                 clamped on xmin, about 3e5 DoFs: DoF/s (items/s)
//   BM_NewmarkStep/p/n/solver     one implicit Newmark step (average acceleration, dt = 20 x the explicit limit) on
//                                 an n^3 box: solver 0 = the factorized effective matrix (host sparse LU: one
//                                 elastic and one mass apply for the right-hand side, one forward/back solve),
//                                 1 = matrix-free CG with the effective diagonal; counters: setup seconds
//                                 (assembly + factorization), CG iterations per step
// Run on a shared machine with OMP_NUM_THREADS=1, CPU time, repeated:
//   OMP_NUM_THREADS=1 build/ci/bench/bench_solid_dynamics --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "solid/dynamics.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

so::Config<3> box(int order, int n) {
  so::BoxSpec b;
  b.cells = {n, n, n};
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = order;
  c.stiffness = pm::materials::isotropic_stiffness(1.0, 0.3);
  c.dirichlet.push_back({"xmin", 7u, {}});
  return c;
}

so::PointFunction bend() {
  return [](const double* x, double* u) {
    u[0] = 0.0;
    u[1] = 1e-3 * x[0] * x[0];
    u[2] = 0.0;
  };
}

template <class T>
void BM_ExplicitStep(benchmark::State& state) {
  so::DynamicsOptions o;
  o.track_energy = false;
  so::ExplicitOptions e;
  e.power_iterations = 40;  // set-up only; the step time does not depend on it
  so::CentralDifference<T, 3> m(box(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))), o, 0.0, e);
  m.set_initial(bend());
  m.step();
  Kokkos::fence();
  for (auto _ : state) {
    m.step();
    Kokkos::fence();
  }
  const double dofs = static_cast<double>(m.dof_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * dofs));
  state.counters["dofs"] = dofs;
  state.counters["dt_crit"] = m.critical_time_step();
}
// about 3e5 DoFs: 3 (p n + 1)^3
BENCHMARK_TEMPLATE(BM_ExplicitStep, double)->Args({1, 46})->Args({2, 23})->Args({3, 15})->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ExplicitStep, float)->Args({1, 46})->Args({2, 23})->Args({3, 15})->Unit(benchmark::kMillisecond);

void BM_NewmarkStep(benchmark::State& state) {
  const int p = static_cast<int>(state.range(0)), n = static_cast<int>(state.range(1));
  so::DynamicsOptions o;
  o.track_energy = false;
  const double dt = 20.0 * 0.9 * (1.0 / n) / (p * p) / std::sqrt(3.4);  // ~20 x the explicit limit h / (p^2 c_p)
  so::NewmarkOptions no;
  no.solver = state.range(2) == 0 ? so::NewmarkSolver::direct : so::NewmarkSolver::cg;
  no.cg.tolerance = 1e-10;
  so::Newmark<double, 3> m(box(p, n), o, dt, no);
  m.set_initial(bend());
  m.step();
  Kokkos::fence();
  double its = 0.0;
  for (auto _ : state) {
    m.step();
    Kokkos::fence();
    its += m.last_iterations();
  }
  const double dofs = static_cast<double>(m.dof_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * dofs));
  state.counters["dofs"] = dofs;
  state.counters["setup_s"] = m.setup_seconds();
  state.counters["cg_its"] = its / static_cast<double>(state.iterations());
}
BENCHMARK(BM_NewmarkStep)->Args({2, 6, 0})->Args({2, 6, 1})->Args({2, 10, 0})->Args({2, 10, 1})->Unit(benchmark::kMillisecond);

}  // namespace
