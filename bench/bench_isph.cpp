// ISPH throughput (seed 002 paper 4; issue 12) on a square hydrostatic tank of n x n particles at
// l0 = 5 mm (Table 1's spacing, the walls' IGCB cells as in scenes/isph/hydrostatic.toml):
//   BM_IsphPpeApply: one application of the pressure Poisson operator (two per BiCGSTAB iteration; the
//     PPE is 84-96 % of the step), with its pair coefficients stored once per step (`stored` 1, the
//     default `ppe_operator`) or recomputed in every apply (0, matrix-free), at 1e4 .. 1e6 particles, in
//     double and float;
//   BM_IsphStep: the whole step (three neighbour lists, density, free surface, ghosts, the PPE solve
//     warm-started from the last pressure, projection) after a few settling steps: matrix-free or stored
//     operator with Jacobi scaling at 1e3 and 1e4 particles (a step at 1e5 takes seconds to minutes: the
//     Jacobi-scaled BiCGSTAB needs ~1.75 sqrt(N) iterations), the two-level preconditioner
//     (models/isph/ppe_two_level.hpp) at 1e3 to 1e6.
// CPU time (the machine is shared): run with OMP_NUM_THREADS=1.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "isph/isph.hpp"

namespace pm = polymech;
namespace ip = polymech::isph;

namespace {

ip::Config square_tank(int n, int max_iterations) {
  ip::Config c;
  c.dim = 2;
  c.spacing = 5e-3;
  c.tank[0] = c.fluid[0] = n * c.spacing;
  c.fluid[1] = n * c.spacing;
  c.tank[1] = (n + 4) * c.spacing;
  c.dt = 5e-4;
  c.viscosity = 1e-3;  // Table 1
  c.max_iterations = max_iterations;
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization"}, ip::effect_table());
  return c;
}

template <class T>
void BM_IsphPpeApply(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool stored = state.range(1) != 0;
  // one step builds the lists, densities, surface flags and ghost weights the operator reads; its solve is
  // cut at one iteration (the state, not the pressure, is what the apply needs)
  ip::Isph<T, 2> m(square_tank(n, 1));
  m.step();
  const auto size = static_cast<std::size_t>(m.particles());
  pm::View1<T> x("bench_isph::x", size), y("bench_isph::y", size);
  Kokkos::deep_copy(x, T(1));
  m.apply_ppe(x, y, stored);  // stores the coefficients outside the timing
  for (auto _ : state) {
    m.apply_ppe(x, y, stored);
    Kokkos::fence();
  }
  const double particles = double(m.particles());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * particles));
  state.counters["particles"] = particles;
  state.counters["particle_applies_per_s"] = benchmark::Counter(particles, benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_IsphPpeApply<double>)
    ->ArgNames({"n", "stored"})
    ->ArgsProduct({{100, 316, 1000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IsphPpeApply<float>)
    ->ArgNames({"n", "stored"})
    ->ArgsProduct({{100, 316, 1000}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

// mode 0: matrix-free operator, Jacobi; 1: stored operator, Jacobi; 2: stored operator, two-level
void BM_IsphStep(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  ip::Config c = square_tank(n, 5000);
  c.ppe_stored = state.range(1) != 0;
  if (state.range(1) == 2) c.ppe_preconditioner = ip::Config::Preconditioner::two_level;
  ip::Isph<double, 2> m(c);
  for (int k = 0; k < 5; ++k) m.step();  // past the cold first solve
  const long long it0 = m.ppe_iterations_total(), s0 = m.ppe_solves();
  const double ppe0 = m.ppe_seconds();
  double wall = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    m.step();
    Kokkos::fence();
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  const double particles = double(m.particles());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * particles));
  state.counters["particles"] = particles;
  state.counters["particle_steps_per_s"] = benchmark::Counter(particles, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ppe_iterations_per_step"] =
      double(m.ppe_iterations_total() - it0) / double(std::max<long long>(1, m.ppe_solves() - s0));
  state.counters["ppe_share"] = wall > 0.0 ? (m.ppe_seconds() - ppe0) / wall : 0.0;
}
BENCHMARK(BM_IsphStep)
    ->ArgNames({"n", "mode"})
    ->ArgsProduct({{32, 100}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);
// the two-level preconditioner at 1e5 and 1e6 particles (Jacobi needs 550 and 1750 iterations a step there)
BENCHMARK(BM_IsphStep)->ArgNames({"n", "mode"})->Args({316, 2})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IsphStep)->ArgNames({"n", "mode"})->Args({1000, 2})->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
