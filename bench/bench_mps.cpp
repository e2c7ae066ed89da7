// MPS elastic force kernels (seed 000 eqs. (4), (5), (11), (12)): pair interactions per second for the
// volumetric-strain pass plus the acceleration pass, with and without the rotation effect, in double
// and float, and the whole time step in particles per second. Plate of the paper's material at
// l0 = 50 um; N from 1e4 to 2e6 (the paper's size). MpsWaveFront: the force kernels with the plate
// ahead of the wave still quiet, its subnormal numbers flushed or kept (issue 39).
#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mps_elastic/mps_elastic.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

me::Config plate(std::int64_t particles, bool rotation) {
  me::Config c;
  const double l0 = 5e-5;
  const auto ny = static_cast<std::int64_t>(std::sqrt(2.0 * static_cast<double>(particles)));  // 1 : 2 plate
  c.spacing = l0;
  c.height = static_cast<double>(ny) * l0;
  c.width = static_cast<double>(particles / ny) * l0;
  c.dt = 2e-9;
  c.excitation.kind = me::ExcitationKind::point;
  if (rotation) c.effects = pm::EffectSet::resolve({"rotation"}, me::MpsElastic<double>::effects());
  return c;
}

// Strategy: the neighbour loop's (kernels/neighbors/neighbor_loop.hpp), serial over a row or a team
// per particle.
template <class T, bool Rotation, class Strategy = pm::neighbors::SerialNeighbors>
void BM_MpsForce(benchmark::State& state) {
  me::MpsElastic<T> m(plate(state.range(0), Rotation));
  for (int s = 0; s < 300; ++s) m.step();  // a wave in the plate, so nothing is trivially zero
  for (auto _ : state) {
    pm::mps::volumetric_strain<T, Rotation>(m.family(), m.fields(), m.params(), Strategy{});
    pm::mps::elastic_acceleration<T, Rotation>(m.family(), m.fields(), m.params(), Strategy{});
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * m.bonds());  // pair interactions (full list)
  state.counters["particles"] = m.particles();
  state.counters["pairs_per_particle"] = static_cast<double>(m.bonds()) / m.particles();
}

template <class T, bool Rotation>
void BM_MpsStep(benchmark::State& state) {
  me::MpsElastic<T> m(plate(state.range(0), Rotation));
  for (int s = 0; s < 300; ++s) m.step();
  for (auto _ : state) {
    m.step();
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * m.particles());  // particle updates
  state.counters["particles"] = m.particles();
}

// The force kernels while a wave front enters a quiet plate: after 300 steps of the point source the
// front has crossed a few millimetres, and ahead of it the displacements and velocities decay through
// the subnormal range (the discrete stencil carries a tail one neighbour radius per step) down to zero.
// range(1): 0 runs the whole case with subnormals flushed to zero (the default), 1 keeps them, which on
// Intel cores sends every operation on them through microcode (issue 39: 3.6x slower on a Xeon).
// Counter subnormal_share: the share of displacement and velocity components in the subnormal range.
template <class T>
void BM_MpsWaveFront(benchmark::State& state) {
  const pm::kx::Subnormals before = pm::kx::thread_subnormals();
  pm::kx::set_host_subnormals(state.range(1) == 1 ? pm::kx::Subnormals::keep : pm::kx::Subnormals::flush);
  {
    me::MpsElastic<T> m(plate(state.range(0), true));
    for (int s = 0; s < 300; ++s) m.step();
    for (auto _ : state) {
      pm::mps::volumetric_strain<T, true>(m.family(), m.fields(), m.params(), pm::neighbors::SerialNeighbors{});
      pm::mps::elastic_acceleration<T, true>(m.family(), m.fields(), m.params(), pm::neighbors::SerialNeighbors{});
      Kokkos::fence();
    }
    const auto h = m.host_fields();
    std::int64_t sub = 0;
    for (const std::vector<double>* f : {&h.u, &h.v})
      for (double x : *f) sub += (x != 0.0 && std::abs(x) < static_cast<double>(std::numeric_limits<T>::min())) ? 1 : 0;
    state.SetItemsProcessed(state.iterations() * m.bonds());
    state.counters["particles"] = m.particles();
    state.counters["subnormal_share"] = static_cast<double>(sub) / static_cast<double>(h.u.size() + h.v.size());
  }
  pm::kx::set_host_subnormals(before);
}

}  // namespace

#define POLYMECH_MPS_BENCH(fn, T, R, name)                                                         \
  BENCHMARK(fn<T, R>)->Name(name)->Arg(10000)->Arg(100000)->Arg(1000000)->Arg(2000000)->UseRealTime() \
      ->Unit(benchmark::kMillisecond)

POLYMECH_MPS_BENCH(BM_MpsForce, double, true, "MpsForce/double/rotation");
POLYMECH_MPS_BENCH(BM_MpsForce, double, false, "MpsForce/double/no_rotation");
POLYMECH_MPS_BENCH(BM_MpsForce, float, true, "MpsForce/float/rotation");
BENCHMARK(BM_MpsForce<double, true, pm::neighbors::TeamNeighbors>)
    ->Name("MpsForce/double/rotation/team")
    ->Arg(100000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
POLYMECH_MPS_BENCH(BM_MpsStep, double, true, "MpsStep/double/rotation");
POLYMECH_MPS_BENCH(BM_MpsStep, float, true, "MpsStep/float/rotation");
// 0 = subnormals flushed (default), 1 = kept
BENCHMARK(BM_MpsWaveFront<double>)
    ->Name("MpsWaveFront/double")
    ->ArgNames({"particles", "keep_subnormals"})
    ->ArgsProduct({{10000, 100000, 1000000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MpsWaveFront<float>)
    ->Name("MpsWaveFront/float")
    ->ArgNames({"particles", "keep_subnormals"})
    ->ArgsProduct({{100000}, {0, 1}})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
