// Matrix-free small-strain solid operator (issue 34; kernels/solid/elastic_operator.hpp) per order, next to
// the scalar Helmholtz apply of bench_fem at the same order:
//   BM_ElasticApply<T>/p/n/distorted   y = K x on an n^3 box of order-p hexahedra (about 1e6 DoFs, three per
//                                     node), affine cells (one Jacobian per element) or randomly distorted
//                                     ones (J^-1 and w det J stored at every point): DoF/s
//   BM_HelmholtzApply/p/n              the scalar (complex) Helmholtz apply of bench_fem on the same lattice
//                                     (about 1e6 / 3 nodes): DoF/s with one complex DoF per node
//   BM_AssembledElasticApply/p/n       the assembled CSR matrix (solid/assembly.hpp) times x, about 1e5 DoFs,
//   BM_ElasticApplySameMesh/p/n        and the matrix-free apply on that mesh
// Issue 34's goal: the elastic apply at order 2 and 3 at no less than a third of the Helmholtz apply's DoF/s.
// Run on a shared machine with OMP_NUM_THREADS=1 and CPU time, repeated:
//   OMP_NUM_THREADS=1 build/ci/bench/bench_solid --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include "helmholtz/helmholtz.hpp"
#include "solid/linear_elastic.hpp"

namespace pm = polymech;
namespace so = polymech::solid;
namespace hz = polymech::helmholtz;

namespace {

// The box [0, 1]^3 in n^3 cells, clamped on xmin.
so::Config<3> box(int order, int n, bool distorted) {
  so::BoxSpec b;
  b.cells = {n, n, n};
  b.distortion = distorted ? so::Distortion::random : so::Distortion::none;
  b.amplitude = 0.2;
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = order;
  c.stiffness = pm::materials::isotropic_stiffness(1.0, 0.3);
  c.dirichlet.push_back({"xmin", 7u, {}});
  return c;
}

template <class T>
pm::View1<T> ramp(pm::Index n) {
  pm::View1<T> v("x", n);
  auto h = Kokkos::create_mirror_view(v);
  for (pm::Index i = 0; i < n; ++i) h(i) = T(std::sin(0.01 * i));
  Kokkos::deep_copy(v, h);
  return v;
}

template <class Op, class V>
void run_applies(benchmark::State& state, const Op& op, const V& x, const V& y, double dofs) {
  op.apply(x, y);
  Kokkos::fence();
  for (auto _ : state) {
    op.apply(x, y);
    Kokkos::fence();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * dofs));
  state.counters["dofs"] = dofs;
}

template <class T>
void BM_ElasticApply(benchmark::State& state) {
  so::LinearElastic<T, 3> m(box(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), state.range(2) != 0));
  const auto x = ramp<T>(m.dof_count());
  pm::View1<T> y("y", m.dof_count());
  state.counters["general_batches"] = m.elements().general_batches;
  run_applies(state, m.op(), x, y, m.dof_count());
}

// About 1e6 DoFs for every order: 3 (p n + 1)^3.
#define POLYMECH_SOLID_SIZES(d) \
  ->Args({1, 69, d})->Args({2, 35, d})->Args({3, 23, d})->Args({4, 17, d})->Unit(benchmark::kMillisecond)
BENCHMARK_TEMPLATE(BM_ElasticApply, double) POLYMECH_SOLID_SIZES(0);
BENCHMARK_TEMPLATE(BM_ElasticApply, double) POLYMECH_SOLID_SIZES(1);
BENCHMARK_TEMPLATE(BM_ElasticApply, float) POLYMECH_SOLID_SIZES(0);

// bench_fem's cube (Dirichlet faces, 500 Hz), complex double, on the elastic benchmark's lattice.
void BM_HelmholtzApply(benchmark::State& state) {
  hz::Config c;
  c.order = static_cast<int>(state.range(0));
  hz::BoxSpec b;
  b.elements = {static_cast<int>(state.range(1)), static_cast<int>(state.range(1)), static_cast<int>(state.range(1))};
  c.mesh = hz::make_box_mesh(b);
  for (const char* f : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    c.boundaries.push_back({f, hz::BoundaryKind::dirichlet});
  c.analytic.kind = hz::AnalyticKind::plane_cosines;
  c.effects = pm::EffectSet::resolve({"dirichlet"}, hz::Helmholtz<double>::effects());
  hz::Helmholtz<double> m(c);
  pm::View1<Kokkos::complex<double>> x("x", m.dof_count()), y("y", m.dof_count());
  Kokkos::deep_copy(x, Kokkos::complex<double>(1.0, 0.5));
  run_applies(state, m.op(), x, y, static_cast<double>(m.dof_count()));
}
BENCHMARK(BM_HelmholtzApply)->Args({1, 69})->Args({2, 35})->Args({3, 23})->Args({4, 17})->Unit(benchmark::kMillisecond);

// The assembled matrix (double, CSR) and the matrix-free apply on the same ~1e5-DoF mesh (the host assembly,
// seconds, is repeated with each benchmark run).
void BM_AssembledElasticApply(benchmark::State& state) {
  so::LinearElastic<double, 3> m(box(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), false));
  const auto csr = so::to_csr<double>(m.assemble());
  const auto x = ramp<double>(m.dof_count());
  pm::View1<double> y("y", m.dof_count());
  state.counters["matrix_MiB"] = static_cast<double>(csr.bytes()) / (1 << 20);
  run_applies(state, csr, x, y, m.dof_count());
}
void BM_ElasticApplySameMesh(benchmark::State& state) {
  so::LinearElastic<double, 3> m(box(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), false));
  const auto x = ramp<double>(m.dof_count());
  pm::View1<double> y("y", m.dof_count());
  run_applies(state, m.op(), x, y, m.dof_count());
}
#define POLYMECH_ASSEMBLED_SOLID ->Args({1, 32})->Args({2, 16})->Unit(benchmark::kMillisecond)
BENCHMARK(BM_AssembledElasticApply) POLYMECH_ASSEMBLED_SOLID;
BENCHMARK(BM_ElasticApplySameMesh) POLYMECH_ASSEMBLED_SOLID;

}  // namespace
