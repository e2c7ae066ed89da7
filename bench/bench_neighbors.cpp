// Neighbour-list build rate (particles/s) and pair visits/s for 1e4 .. 1e6 particles in 2D and 3D.
// Particles sit on a jittered lattice of unit spacing; radius 2.1 spacings (the MPS influence radius
// of seed 000). items_per_second staying flat as N grows shows the build is O(N).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "neighbors/neighbor_search.hpp"

namespace pm = polymech;
namespace nb = polymech::neighbors;

namespace {

template <int D>
pm::VecView<double, D> jittered_lattice(std::int64_t n) {
  const auto side = static_cast<std::int64_t>(std::ceil(std::pow(static_cast<double>(n), 1.0 / D)));
  pm::VecView<double, D> x("x", n);
  auto h = Kokkos::create_mirror_view(x);
  std::mt19937 gen(42);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (std::int64_t i = 0; i < n; ++i) {
    std::int64_t r = i;
    for (int k = 0; k < D; ++k) {
      h(i, k) = static_cast<double>(r % side) + jitter(gen);
      r /= side;
    }
  }
  Kokkos::deep_copy(x, h);
  return x;
}

// One pass over the list touching both ends of every pair: the access pattern of a pair kernel.
template <int D>
double visit_pairs(const nb::NeighborList& list, const pm::VecView<double, D>& x) {
  double sum = 0.0;
  Kokkos::parallel_reduce(
      "polymech::bench::pair_visit", pm::range(list.num_particles),
      KOKKOS_LAMBDA(const pm::Index i, double& s) {
        for (auto k = list.begin(i); k < list.end(i); ++k) {
          const pm::Index j = list.neighbor(k);
          double r2 = 0.0;
          for (int d = 0; d < D; ++d) {
            const double dx = x(j, d) - x(i, d);
            r2 += dx * dx;
          }
          s += r2;
        }
      },
      sum);
  return sum;
}

template <int D>
void BM_NeighborBuild(benchmark::State& state) {
  const auto n = state.range(0);
  auto x = jittered_lattice<D>(n);
  nb::NeighborSearch<double, D> search;
  nb::NeighborList list;
  search.build(x, 2.1, nb::ListKind::full, list);  // warm the workspace
  for (auto _ : state) {
    search.build(x, 2.1, nb::ListKind::full, list);
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * n);
  state.counters["pairs_per_particle"] = static_cast<double>(list.num_pairs) / static_cast<double>(n);
  state.counters["seconds_per_particle"] = benchmark::Counter(
      static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

template <int D>
void BM_PairVisit(benchmark::State& state) {
  const auto n = state.range(0);
  auto x = jittered_lattice<D>(n);
  nb::NeighborSearch<double, D> search;
  nb::NeighborList list;
  search.build(x, 2.1, nb::ListKind::full, list);
  for (auto _ : state) benchmark::DoNotOptimize(visit_pairs<D>(list, x));
  state.SetItemsProcessed(state.iterations() * list.num_pairs);  // pair visits
}

}  // namespace

BENCHMARK(BM_NeighborBuild<2>)->Name("NeighborBuild/2D")->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_NeighborBuild<3>)->Name("NeighborBuild/3D")->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PairVisit<2>)->Name("PairVisit/2D")->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PairVisit<3>)->Name("PairVisit/3D")->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond)->UseRealTime();
