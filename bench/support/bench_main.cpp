// Google Benchmark main bracketed by Kokkos::initialize / finalize; prints the Kokkos build so the
// numbers in docs/PERFORMANCE.md can be matched to a configuration.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <stdexcept>

#include "core/kokkos_shim.hpp"

int main(int argc, char** argv) {
  try {
    polymech::kx::initialize();  // subnormals flushed unless POLYMECH_SUBNORMALS=keep
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], e.what());
    return 2;
  }
  benchmark::AddCustomContext("kokkos_version", std::to_string(KOKKOS_VERSION));
  benchmark::AddCustomContext("execution_space", Kokkos::DefaultExecutionSpace::name());
  benchmark::AddCustomContext("concurrency",
                              std::to_string(polymech::kx::concurrency<Kokkos::DefaultExecutionSpace>()));
  // flush (the default) or keep (POLYMECH_SUBNORMALS=keep): core/float_env.hpp
  benchmark::AddCustomContext("subnormals", polymech::kx::to_string(polymech::kx::thread_subnormals()));
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  Kokkos::finalize();
  return 0;
}
