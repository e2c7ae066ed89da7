// STREAM triad a(i) = b(i) + s * c(i) through Kokkos: the machine's sustainable memory bandwidth,
// the roofline reference for the kernel benchmarks (bytes_per_second counts 3 x 8 bytes per item;
// write-allocate traffic is not counted, as in McCalpin's STREAM).
#include <benchmark/benchmark.h>

#include "core/types.hpp"

namespace pm = polymech;

static void triad(pm::View1<double> a, pm::View1<double> b, pm::View1<double> c, double s) {
  Kokkos::parallel_for(
      "polymech::bench::stream_triad", pm::range(a.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i) { a(i) = b(i) + s * c(i); });
}

static void BM_StreamTriad(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  pm::View1<double> a("a", n), b("b", n), c("c", n);
  Kokkos::deep_copy(b, 1.0);
  Kokkos::deep_copy(c, 2.0);
  triad(a, b, c, 3.0);  // first touch
  Kokkos::fence();
  for (auto _ : state) {
    triad(a, b, c, 3.0);
    Kokkos::fence();
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * n));
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * n * 3 * sizeof(double)));
}
// 8 Mi doubles = 64 MiB per array, far beyond any last-level cache.
BENCHMARK(BM_StreamTriad)->Arg(1 << 23)->Arg(1 << 25)->Unit(benchmark::kMillisecond)->UseRealTime();
