// NOSB peridynamics kernels (seed 003): bond throughput of the two bond passes of a step (deformation
// gradient, eq. (1); bond forces) and of a whole elasto-plastic step with damage and velocity
// viscosity, and the cost of the shared neighbour search that builds the reference family (once) and
// the short-range contact list (when particles moved more than half the skin), all in bonds (pairs)
// per second. A 3D steel box on a cubic lattice with m = 3 (122 bonds per interior particle), N from
// 1e5 to 1e6 particles, double and float.
#include <benchmark/benchmark.h>

#include <cmath>

#include "nosb_pd/nosb_pd.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

np::Config box(std::int64_t particles, std::vector<std::string> effects, np::Law law = np::Law::elastic) {
  np::Config c;
  c.dimension = 3;
  c.spacing = 1e-3;
  c.horizon_ratio = 3.0;
  const double side = std::cbrt(static_cast<double>(particles)) * c.spacing;
  c.geometry.length = c.geometry.width = c.geometry.height = side;
  c.material.law = law;
  c.material.jc_a = 490e6;
  c.material.jc_b = 807e6;
  c.material.jc_n = 0.73;
  c.material.jc_c = 0.0114;
  c.material.jc_reference_rate = 5e-4;
  c.damage.critical_stretch = 0.05;
  c.stabilization.c_v = 0.3;
  c.stabilization.omega_v = 2.78e6;
  c.dt = 3e-8;
  c.effects = pm::EffectSet::resolve(effects, np::NosbPd<double, 3>::effects());
  return c;
}

// A smooth deformation so that nothing is trivially zero: u = 1e-3 (sin x, sin y, sin z) / k.
template <class T>
void deform(np::NosbPd<T, 3>& m) {
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
  auto u = Kokkos::create_mirror_view(m.fields().u);
  for (pm::Index i = 0; i < m.particles(); ++i)
    for (int k = 0; k < 3; ++k) u(i, k) = static_cast<T>(1e-6 * std::sin(300.0 * x0(i, k)));
  Kokkos::deep_copy(m.fields().u, u);
  m.compute_forces();
}

template <class T>
void BM_PdDeformationGradient(benchmark::State& state) {
  np::NosbPd<T, 3> m(box(state.range(0), {}));
  deform(m);
  pm::pd::DeformationParams<T> p;
  for (auto _ : state) {
    pm::pd::deformation_gradient(m.family(), m.fields(), p);
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * m.bonds());
  state.counters["particles"] = m.particles();
  state.counters["bonds_per_particle"] = static_cast<double>(m.bonds()) / m.particles();
}

// Strategy: the neighbour loop's (kernels/neighbors/neighbor_loop.hpp), serial over a row or a team
// per particle.
template <class T, class Strategy = pm::neighbors::SerialNeighbors>
void BM_PdBondForces(benchmark::State& state) {
  np::NosbPd<T, 3> m(box(state.range(0), {}));
  deform(m);
  pm::pd::ForceParams<T> p;
  p.density = T(7850);
  for (auto _ : state) {
    pm::pd::bond_forces(m.family(), m.fields(), p, false, false, Strategy{});
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * m.bonds());
  state.counters["particles"] = m.particles();
}

// The whole step of the penetration case: J2/Johnson-Cook, damage, velocity viscosity, weights of eq. (2).
template <class T>
void BM_PdStep(benchmark::State& state) {
  np::NosbPd<T, 3> m(box(state.range(0), {"weighted_function", "velocity_viscosity", "damage"}, np::Law::johnson_cook));
  deform(m);
  for (auto _ : state) {
    m.step();
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * m.bonds());  // bonds per second through the whole step
  state.counters["particles"] = m.particles();
}

// The shared neighbour search: the reference family (radius delta) and the short-range contact list
// (radius d_s + skin = 1.4 spacings) over the same particles; items are the pairs found.
template <class T>
void BM_PdNeighborSearch(benchmark::State& state) {
  np::NosbPd<T, 3> m(box(state.range(0), {}));
  const bool family = state.range(1) == 1;
  const T radius = static_cast<T>(family ? m.config().horizon() * (1 + 1e-6) : 1.4 * m.config().spacing);
  pm::neighbors::NeighborSearch<T, 3> search;
  pm::neighbors::NeighborList list;
  search.build(m.fields().x0, radius, pm::neighbors::ListKind::full, list);  // warm: storage allocated
  for (auto _ : state) {
    search.build(m.fields().x0, radius, pm::neighbors::ListKind::full, list);
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * list.num_pairs);
  state.counters["particles"] = m.particles();
  state.counters["pairs_per_particle"] = static_cast<double>(list.num_pairs) / m.particles();
}

}  // namespace

#define POLYMECH_PD_BENCH(fn, T, name)                                                              \
  BENCHMARK(fn<T>)->Name(name)->Arg(100000)->Arg(1000000)->UseRealTime()->Unit(benchmark::kMillisecond) \
      ->MinTime(0.5)

POLYMECH_PD_BENCH(BM_PdDeformationGradient, double, "PdDeformationGradient/double");
POLYMECH_PD_BENCH(BM_PdDeformationGradient, float, "PdDeformationGradient/float");
POLYMECH_PD_BENCH(BM_PdBondForces, double, "PdBondForces/double");
POLYMECH_PD_BENCH(BM_PdBondForces, float, "PdBondForces/float");
BENCHMARK(BM_PdBondForces<double, pm::neighbors::TeamNeighbors>)
    ->Name("PdBondForces/double/team")
    ->Arg(100000)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);
POLYMECH_PD_BENCH(BM_PdStep, double, "PdStep/double/johnson_cook_damage_viscosity");
POLYMECH_PD_BENCH(BM_PdStep, float, "PdStep/float/johnson_cook_damage_viscosity");
BENCHMARK(BM_PdNeighborSearch<double>)
    ->Name("PdNeighborSearch/double")
    ->Args({100000, 1})
    ->Args({100000, 0})
    ->Args({1000000, 1})
    ->Args({1000000, 0})
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond)
    ->MinTime(0.5);
