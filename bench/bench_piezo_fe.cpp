// The finite-element piezoelectric harvester (issue 35; models/piezo/beam_model.hpp, transient.hpp) on the
// duToit & Wardle bimorph of seed 002 paper 1 (2D plane stress, models/piezo/cases.hpp):
//   BM_PiezoAssemble/p/nl        assembling the coupled (u, phi) matrices and the mass: unknowns/s (items/s)
//   BM_PiezoHarmonic/p/nl        one harmonic solve at the resonance with 2000 ohm (a complex sparse LU of the
//                                bordered matrix, the electrodes eliminated by their Schur complement, one
//                                solve): frequencies/s = items/s; the counter `sweep200_s` is 200 of them
//   BM_PiezoStep/p/nl/scheme     one Newmark step with 2000 ohm (0 monolithic: one sparse solve; 1 partitioned:
//                                paper 1's loop, two solves): unknowns/s; counter solves_per_step
//   BM_AnalyticResponse          one frequency of the single-mode distributed-parameter model (EI09), for scale
// Run on a shared machine with one thread, CPU time, repeated:
//   OMP_NUM_THREADS=1 build/ci/bench/bench_piezo_fe --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "piezo/analytic.hpp"
#include "piezo/cases.hpp"
#include "piezo/transient.hpp"

namespace pz = polymech::piezo;

namespace {

void BM_PiezoAssemble(benchmark::State& state) {
  const auto spec = pz::dutoit_harvester_spec(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 1);
  double n = 0.0;
  for (auto _ : state) {
    pz::PiezoBeam b(spec);
    n = static_cast<double>(b.unknowns());
    benchmark::DoNotOptimize(b.K().val.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * n));
  state.counters["unknowns"] = n;
}

void BM_PiezoHarmonic(benchmark::State& state) {
  const pz::PiezoBeam b(pz::dutoit_harvester_spec(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 1));
  const double w = b.natural_frequency(true);
  const auto damping = pz::Rayleigh::stiffness_proportional(0.01, w);
  const pz::Circuit c = pz::harvester_load(b, 2000.0);
  for (auto _ : state) {
    const auto h = b.harmonic(w, c, damping);
    benchmark::DoNotOptimize(h.power);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["unknowns"] = static_cast<double>(b.unknowns());
  // seconds of 200 solves: (iterations / 200) per second, inverted
  state.counters["sweep200_s"] = benchmark::Counter(static_cast<double>(state.iterations()) / 200.0,
                                                    benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_PiezoStep(benchmark::State& state) {
  const pz::PiezoBeam b(pz::dutoit_harvester_spec(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), 1));
  const double w = b.natural_frequency(true);
  pz::TransientOptions o;
  o.dt = 2.0 * pz::kPi / w / 40.0;
  o.damping = pz::Rayleigh::stiffness_proportional(0.01, w);
  o.scheme = state.range(2) == 0 ? pz::Scheme::monolithic : pz::Scheme::partitioned;
  pz::PiezoTransient t(b, pz::harvester_load(b, 2000.0), o);
  t.start(0.0);
  std::int64_t k = 0;
  for (int i = 0; i < 40; ++i) t.step(std::sin(w * static_cast<double>(++k) * o.dt));  // past the first step's set-up
  const std::int64_t solves0 = t.total_solves();
  for (auto _ : state) t.step(std::sin(w * static_cast<double>(++k) * o.dt));
  const double n = static_cast<double>(b.unknowns());
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * n));
  state.counters["unknowns"] = n;
  state.counters["solves_per_step"] =
      static_cast<double>(t.total_solves() - solves0) / static_cast<double>(std::max<std::int64_t>(1, state.iterations()));
}

void BM_AnalyticResponse(benchmark::State& state) {
  const pz::BimorphHarvester h(pz::dutoit_wardle_2007_case());
  double w = h.omega(0);
  for (auto _ : state) {
    const auto r = h.response(w, 2000.0);
    benchmark::DoNotOptimize(r.power);
    w *= 1.0 + 1e-12;
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

BENCHMARK(BM_PiezoAssemble)->Args({2, 40})->Args({3, 40})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_PiezoHarmonic)->Args({2, 40})->Args({3, 40})->Args({3, 80})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PiezoStep)->Args({2, 40, 0})->Args({2, 40, 1})->Args({3, 80, 0})->Args({3, 80, 1})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AnalyticResponse);
