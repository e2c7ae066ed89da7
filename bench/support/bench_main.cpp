// Google Benchmark main bracketed by Kokkos::initialize / finalize; prints the Kokkos build so the
// numbers in docs/PERFORMANCE.md can be matched to a configuration.
#include <benchmark/benchmark.h>

#include "core/kokkos_shim.hpp"

int main(int argc, char** argv) {
  polymech::kx::initialize();
  benchmark::AddCustomContext("kokkos_version", std::to_string(KOKKOS_VERSION));
  benchmark::AddCustomContext("execution_space", Kokkos::DefaultExecutionSpace::name());
  benchmark::AddCustomContext("concurrency",
                              std::to_string(polymech::kx::concurrency<Kokkos::DefaultExecutionSpace>()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  Kokkos::finalize();
  return 0;
}
