// Quasi-static elasto-plastic solids (issue 34; kernels/solid/plastic_law.hpp, models/solid/elastoplastic.hpp):
//   BM_PlasticResidual/p/n       r = f_int(u) - f_ext with Hill's return mapping at every point (from a copy of
//                                the converged history; trial history and tangent stored) on an n^3 box of
//                                order-p hexahedra (about 1e5 DoFs) in a bending state with about half of the
//                                points plastic: DoF/s, counter plastic_fraction
//   BM_PlasticTangentApply/p/n   y = K_t x with the stored per-point tangent (PointStiffness): DoF/s
//   BM_LoadUnload/solver/p       a 3D cantilever (Hill, rotated cubic crystal) loaded to 1.6 times first yield
//                                and unloaded, 8 + 4 steps, to the load-unload curve: wall time per curve,
//                                counters newton_per_step, linear_per_step (CG iterations or LU solves);
//                                solver 0 = assembled tangent + host sparse LU every iteration,
//                                1 = matrix-free CG on the tangent preconditioned by the elastic LU (default)
//   BM_CoarseSolve/kind/h10      the coarse level of the two-level preconditioner (models/solid/two_level.hpp):
//                                the order-1 elastic stiffness of the micro-cantilever (beam + block, theta 0)
//                                with h_root = h10 / 10 um, one solve with its sparse LU factors (COLAMD);
//                                kind 0 = double, 1 = float factors: time per solve, counters dofs,
//                                factor_seconds
// Run on a shared machine with OMP_NUM_THREADS=1:
//   OMP_NUM_THREADS=1 OMP_PROC_BIND=false build/ci/bench/bench_solid_plastic
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "solid/elastoplastic.hpp"
#include "solid/micro_cantilever.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace pm = polymech;
namespace so = polymech::solid;
namespace mt = polymech::materials;

namespace {

mt::HillPlasticity<double> crystal() {
  mt::CubicHillParameters<double> p;
  p.elastic = {170.0, 124.0, 75.0};
  p.yield_stress = 0.1;
  p.hardening_exponent = 0.15;
  p.R12 = 0.8;
  const double s = std::sqrt(0.5);
  pm::Mat3<double> Q;
  Q.a[0][0] = s;  Q.a[0][1] = s;  Q.a[0][2] = 0.0;
  Q.a[1][0] = -s; Q.a[1][1] = s;  Q.a[1][2] = 0.0;
  Q.a[2][0] = 0.0; Q.a[2][1] = 0.0; Q.a[2][2] = 1.0;
  return mt::make_cubic_hill(p, Q);
}

so::Config<3> beam(int order, std::array<int, 3> cells, std::array<double, 3> lengths, double traction) {
  const auto law = crystal();
  so::BoxSpec b;
  b.lengths = lengths;
  b.cells = cells;
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = order;
  c.stiffness = law.C;
  c.plasticity = law;
  c.dirichlet.push_back({"xmin", 7u, {}});
  c.tractions.push_back({"xmax", {0.0, traction, 0.0}});
  return c;
}

// The unit cube in n^3 cells and the bending field u_y = k x^2 / 2, u_x = -k x (y - 1/2): eps_xx = -k (y - 1/2),
// the outer half of the section beyond the yield strain (about 0.1 / 129 along [110]).
struct Bent {
  so::ElastoPlastic<double, 3> model;
  pm::View1<double> u, r;
  Bent(int order, int n) : model(beam(order, {n, n, n}, {1.0, 1.0, 1.0}, 0.0)) {
    const pm::Index nd = model.dof_count();
    u = pm::View1<double>("u", nd);
    r = pm::View1<double>("r", nd);
    const double k = 4.0 * 0.1 / 129.0 / 0.5;
    auto uh = Kokkos::create_mirror_view(u);
    const auto& x = model.discretization().coordinates;
    for (pm::Index v = 0; v < nd / 3; ++v) {
      const double X = x[3 * v], Y = x[3 * v + 1];
      uh(3 * v) = -k * X * (Y - 0.5);
      uh(3 * v + 1) = 0.5 * k * X * X;
    }
    Kokkos::deep_copy(u, uh);
  }
};

void BM_PlasticResidual(benchmark::State& state) {
  Bent b(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  b.model.residual(b.u, 0.0, b.r);
  Kokkos::fence();
  for (auto _ : state) {
    b.model.residual(b.u, 0.0, b.r);
    Kokkos::fence();
  }
  const double dofs = static_cast<double>(b.model.dof_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * dofs));
  state.counters["dofs"] = dofs;
  state.counters["plastic_fraction"] =
      static_cast<double>(b.model.law().counts().plastic) /
      (static_cast<double>(b.model.element_count()) * b.model.points_per_element());
}

void BM_PlasticTangentApply(benchmark::State& state) {
  Bent b(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  b.model.residual(b.u, 0.0, b.r);  // stores the tangent
  pm::View1<double> y("y", b.model.dof_count());
  b.model.tangent_apply(b.u, y);
  Kokkos::fence();
  for (auto _ : state) {
    b.model.tangent_apply(b.u, y);
    Kokkos::fence();
  }
  const double dofs = static_cast<double>(b.model.dof_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * dofs));
  state.counters["dofs"] = dofs;
}

// Cantilever [0, 8] x [0, 1] x [0, 1], 16 x 2 x 2 cells: elastic clamp stress 36 P... here 6 P L / (b h^2) = 48 P,
// first yield along [110] at 0.8386 sigma0; loaded to 1.6 times that, then unloaded.
void BM_LoadUnload(benchmark::State& state) {
  const int order = static_cast<int>(state.range(1));
  const double P = 1.6 * 0.838628 * 0.1 / 48.0;
  so::NewtonOptions o;
  o.solver = state.range(0) == 0 ? so::TangentSolver::direct : so::TangentSolver::elastic_pcg;
  double newton = 0.0, linear = 0.0, steps = 0.0, dofs = 0.0;
  for (auto _ : state) {
    so::ElastoPlastic<double, 3> m(beam(order, {16, 2, 2}, {8.0, 1.0, 1.0}, P), o);
    so::LoadPath path;
    path.points = {0.0, 1.0, 0.0};
    path.increments = {8, 4};
    const auto r = m.run(path);
    for (const auto& s : r) {
      newton += s.newton_iterations;
      linear += s.linear_iterations;
    }
    steps += static_cast<double>(r.size());
    dofs = static_cast<double>(m.dof_count());
  }
  state.counters["newton_per_step"] = newton / steps;
  state.counters["linear_per_step"] = linear / steps;
  state.counters["dofs"] = dofs;
}

void BM_CoarseSolve(benchmark::State& state) {
  so::MicroCantileverSpec spec;
  spec.order = 1;
  spec.h_root = 0.1 * static_cast<double>(state.range(1));
  const so::LinearElastic<double, 3> coarse(so::micro_cantilever(spec));
  const so::Triplets a = coarse.assemble();
  polymech::solvers::HostSparseLU lu;
  const auto t0 = std::chrono::steady_clock::now();
  lu.factor(a.n, a.rows, a.cols, a.values, state.range(0) == 1);
  const double factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::vector<double> b(static_cast<std::size_t>(a.n));
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::sin(0.37 * static_cast<double>(i));
  for (auto _ : state) {
    lu.solve(b.data());
    benchmark::DoNotOptimize(b.data());
  }
  state.counters["dofs"] = static_cast<double>(a.n);
  state.counters["factor_seconds"] = factor_seconds;
}

}  // namespace

BENCHMARK(BM_CoarseSolve)->Args({0, 4})->Args({1, 4})->Args({0, 2})->Args({1, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlasticResidual)->Args({1, 32})->Args({2, 16})->Args({3, 11})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlasticTangentApply)->Args({1, 32})->Args({2, 16})->Args({3, 11})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LoadUnload)->Args({0, 1})->Args({1, 1})->Args({0, 2})->Args({1, 2})->Iterations(1)->Unit(benchmark::kMillisecond);
