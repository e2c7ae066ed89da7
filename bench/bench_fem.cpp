// Matrix-free Helmholtz operator of seed 002 paper 3 eq. (16) (order-p hexahedra, sum factorization)
// against the assembled CSR matrix, and one COCG iteration:
//   BM_MatrixFreeApply<T>/p/n   y = K x on an n^3 cube (about 1e6 DoFs for every p): DoF/s, and the
//                               bytes per apply of a minimal traffic model (geometric factors + element
//                               map read once, x read, y zeroed, y read and written) as bytes/s, to
//                               compare with bench_stream's STREAM triad
//   BM_AssembledApply/p/n       the same product with the assembled matrix (CSR, complex double)
//   BM_MatrixFreeSameMesh/p/n   the matrix-free product on the assembled benchmark's mesh
//   BM_CocgIteration<T>/p/n     20 COCG iterations with Jacobi (apply + vector kernels): DoF-iterations/s
// Counters: dofs, elements, operator_MiB (what the operator stores), bytes_per_dof (traffic model).
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "helmholtz/assembled.hpp"
#include "helmholtz/helmholtz.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

namespace {

// The unit cube of seed 002 paper 3 §3(2) (Dirichlet data from eq. (27), 500 Hz).
hz::Config cube(int order, int n) {
  hz::Config c;
  c.order = order;
  hz::BoxSpec box;
  box.elements = {n, n, n};
  c.mesh = hz::make_box_mesh(box);
  for (const char* f : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) c.boundaries.push_back({f, hz::BoundaryKind::dirichlet});
  c.analytic.kind = hz::AnalyticKind::plane_cosines;
  c.effects = pm::EffectSet::resolve({"dirichlet"}, hz::Helmholtz<double>::effects());
  return c;
}

template <class T>
pm::View1<Kokkos::complex<T>> ramp(pm::Index n) {
  pm::View1<Kokkos::complex<T>> v("x", n);
  auto h = Kokkos::create_mirror_view(v);
  for (pm::Index i = 0; i < n; ++i) h(i) = Kokkos::complex<T>(T(std::sin(0.01 * i)), T(std::cos(0.017 * i)));
  Kokkos::deep_copy(v, h);
  return v;
}

// Minimal DRAM traffic of one apply [bytes]: operator storage read once, x read, y zeroed, y read + written.
template <class T>
double traffic(const hz::Helmholtz<T>& m) {
  return static_cast<double>(m.op().bytes()) + 4.0 * sizeof(Kokkos::complex<T>) * m.dof_count();
}

template <class T>
void set_counters(benchmark::State& state, const hz::Helmholtz<T>& m, double bytes_per_apply, double applies) {
  state.SetItemsProcessed(static_cast<std::int64_t>(applies * m.dof_count()));
  state.SetBytesProcessed(static_cast<std::int64_t>(applies * bytes_per_apply));
  state.counters["dofs"] = m.dof_count();
  state.counters["elements"] = m.element_count();
  state.counters["operator_MiB"] = static_cast<double>(m.op().bytes()) / (1 << 20);
  state.counters["bytes_per_dof"] = bytes_per_apply / m.dof_count();
}

template <class T>
void BM_MatrixFreeApply(benchmark::State& state) {
  hz::Helmholtz<T> m(cube(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
  const auto x = ramp<T>(m.dof_count());
  pm::View1<Kokkos::complex<T>> y("y", m.dof_count());
  m.op().apply(x, y);
  Kokkos::fence();
  for (auto _ : state) {
    m.op().apply(x, y);
    Kokkos::fence();
  }
  set_counters(state, m, traffic(m), static_cast<double>(state.iterations()));
}

// About 1e6 DoFs for each order: (p n + 1)^3.
BENCHMARK_TEMPLATE(BM_MatrixFreeApply, double)
    ->Args({1, 100})->Args({2, 50})->Args({3, 33})->Args({4, 25})
    ->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_MatrixFreeApply, float)
    ->Args({1, 100})->Args({2, 50})->Args({3, 33})->Args({4, 25})
    ->Unit(benchmark::kMillisecond)->UseRealTime();

// Steps of the batched volume kernel (double, about 1e6 DoFs, p = 2..4), to see what each one gains:
//   BM_ApplyStep<E, EvenOdd, Affine, Prefetch, Stage>/p/n: y = 0, then the volume kernel y += (A + m M) x
//   with E elements per batch (1: one element at a time, as before batching), the even-odd 1D kernels
//   or the full matrices, one Jacobian per affine element or factors at every point, the software
//   prefetch of the next batch's DoFs, and the stage (0 gather + scatter, 1 + B / B^T, 2 + Dq / Dq^T,
//   3 the whole kernel). <2, 1, 1, 1, 3> is the production kernel (fem::volume_batch<double>() = 2 on AVX2).
template <int E, bool EvenOdd, bool Affine, bool Prefetch, int Stage, bool Kronecker>
void BM_ApplyStep(benchmark::State& state) {
  hz::Config c = cube(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  c.batch_elements = E;
  c.affine_geometry = Affine;
  if (state.range(2) > 0) c.chunk_elements = static_cast<int>(state.range(2));
  hz::Helmholtz<double> m(c);
  const auto x = ramp<double>(m.dof_count());
  pm::View1<Kokkos::complex<double>> y("y", m.dof_count());
  const auto& el = m.op().elements();
  state.counters["colors"] = el.colors();
  auto apply = [&] {
    Kokkos::deep_copy(y, Kokkos::complex<double>(0));
    auto run = [&](auto n) {
      pm::fem::detail::apply_volume<Kokkos::complex<double>, double, decltype(n)::value, E, true, EvenOdd,
                                    static_cast<pm::fem::detail::VolumeStage>(Stage), Prefetch, Kronecker>(
          "bench::apply_step", el, m.op().mass_coefficient(), x, y);
    };
    switch (c.order) {
      case 2: run(std::integral_constant<int, 3>{}); break;
      case 3: run(std::integral_constant<int, 4>{}); break;
      case 4: run(std::integral_constant<int, 5>{}); break;
      default: state.SkipWithError("orders 2..4 only");
    }
    Kokkos::fence();
  };
  apply();
  for (auto _ : state) apply();
  set_counters(state, m, traffic(m), static_cast<double>(state.iterations()));
}
#define POLYMECH_STEP_SIZES ->Args({2, 50, 0})->Args({3, 33, 0})->Args({4, 25, 0})->Args({3, 33, 1 << 30})->Unit(benchmark::kMillisecond)->UseRealTime()
BENCHMARK_TEMPLATE(BM_ApplyStep, 1, false, false, false, 3, false) POLYMECH_STEP_SIZES;  // one element at a time
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, false, false, false, 3, false) POLYMECH_STEP_SIZES;  // + batches of 2 (one AVX2 register)
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, false, false, 3, false) POLYMECH_STEP_SIZES;   // + even-odd 1D kernels
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, false, 3, false) POLYMECH_STEP_SIZES;    // + one Jacobian per affine element
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, true, 3, false) POLYMECH_STEP_SIZES;     // + prefetch of the next batch
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, true, 3, true) POLYMECH_STEP_SIZES;      // + Kronecker form: production
BENCHMARK_TEMPLATE(BM_ApplyStep, 4, true, true, true, 3, true) POLYMECH_STEP_SIZES;      // batches of 4 (two registers)
BENCHMARK_TEMPLATE(BM_ApplyStep, 1, true, true, true, 3, true) POLYMECH_STEP_SIZES;      // batches of 1 (complex in one register)
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, true, 0, true) POLYMECH_STEP_SIZES;      // stages of the quadrature path
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, true, 1, true) POLYMECH_STEP_SIZES;
BENCHMARK_TEMPLATE(BM_ApplyStep, 2, true, true, true, 2, true) POLYMECH_STEP_SIZES;

// The assembled matrix of the same operator (Dirichlet rows included), in CSR on the device.
struct Assembled {
  std::unique_ptr<hz::Helmholtz<double>> model;
  pm::fem::CsrMatrix<Kokkos::complex<double>> csr;
};
// The cache holds Kokkos views: it is emptied by a finalize hook, before Kokkos::finalize frees the
// memory spaces (a static map's destructor would run after it and abort the benchmark at exit).
Assembled& assembled(int p, int n) {
  static std::map<std::pair<int, int>, Assembled> cache;
  static const bool hooked = [] {
    Kokkos::push_finalize_hook([] { cache.clear(); });
    return true;
  }();
  (void)hooked;
  auto& a = cache[{p, n}];
  if (!a.model) {
    a.model = std::make_unique<hz::Helmholtz<double>>(cube(p, n));
    a.csr = hz::to_csr<double>(hz::assemble_reference(*a.model));
  }
  return a;
}

void BM_AssembledApply(benchmark::State& state) {
  auto& a = assembled(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const pm::Index n = a.model->dof_count();
  const auto x = ramp<double>(n);
  pm::View1<Kokkos::complex<double>> y("y", n);
  a.csr.apply(x, y);
  Kokkos::fence();
  for (auto _ : state) {
    a.csr.apply(x, y);
    Kokkos::fence();
  }
  // CSR traffic: matrix once, x gathered (counted once), y written
  const double bytes = static_cast<double>(a.csr.bytes()) + 2.0 * sizeof(Kokkos::complex<double>) * n;
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * n);
  state.SetBytesProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * bytes));
  state.counters["dofs"] = n;
  state.counters["nonzeros"] = static_cast<double>(a.csr.nonzeros());
  state.counters["operator_MiB"] = static_cast<double>(a.csr.bytes()) / (1 << 20);
  state.counters["bytes_per_dof"] = bytes / n;
}

void BM_MatrixFreeSameMesh(benchmark::State& state) {
  auto& a = assembled(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const auto& m = *a.model;
  const auto x = ramp<double>(m.dof_count());
  pm::View1<Kokkos::complex<double>> y("y", m.dof_count());
  for (auto _ : state) {
    m.op().apply(x, y);
    Kokkos::fence();
  }
  set_counters(state, m, traffic(m), static_cast<double>(state.iterations()));
}

// 25^3 DoFs for every order (and 49^3 for p <= 3): assembly is the expensive part of these runs.
#define POLYMECH_ASSEMBLED_SIZES ->Args({1, 24})->Args({2, 12})->Args({3, 8})->Args({4, 6})->Args({1, 48})->Args({2, 24})->Args({3, 16})
BENCHMARK(BM_AssembledApply) POLYMECH_ASSEMBLED_SIZES->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MatrixFreeSameMesh) POLYMECH_ASSEMBLED_SIZES->Unit(benchmark::kMillisecond)->UseRealTime();

template <class T>
void BM_CocgIteration(benchmark::State& state) {
  hz::Helmholtz<T> m(cube(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))));
  const pm::Index n = m.dof_count();
  pm::View1<Kokkos::complex<T>> rhs("rhs", n), x("x", n), d("d", n), inv("inv", n);
  m.right_hand_side(rhs, x);
  m.op().diagonal(d);
  pm::solvers::jacobi_inverse(n, n, d, inv);
  pm::solvers::SolverOptions o;
  o.tolerance = 1e-30;
  o.max_iterations = 20;
  int iterations = 0;
  for (auto _ : state) {
    Kokkos::deep_copy(x, Kokkos::complex<T>(0));
    iterations += pm::solvers::cocg(m.op(), inv, rhs, x, o).iterations;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(iterations) * n);
  state.counters["dofs"] = n;
  state.counters["iterations"] = iterations / static_cast<double>(state.iterations());
}
BENCHMARK_TEMPLATE(BM_CocgIteration, double)->Args({1, 100})->Args({4, 25})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_CocgIteration, float)->Args({1, 100})->Args({4, 25})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
