// DEM step throughput (seed 002 paper 2; issue 13): sphere-steps per second of the whole Dem step
// (broad phase with skin, sphere-sphere and sphere-plane Hertz-Mindlin with friction and damping, the
// integrator) on a dense block in contact, for spheres and for the cubical clumps of 8 spheres, at
// 1e3 .. 6.4e4 particles. The block is a cubic lattice of spacing 0.99 x 2R in a box of planes that
// holds it exactly, so every particle keeps its neighbours in contact while the block rings down. CPU
// time (the machine is shared): run with OMP_NUM_THREADS=1.
#include <benchmark/benchmark.h>

#include "dem/dem.hpp"
#include "dem/pour.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

dm::Config dense_block(int n, bool clumps) {
  dm::Config c;
  c.particle = {5e7, 0.3, 2650};
  c.wall = {5e7, 0.3, 2650};
  c.restitution = 0.4;
  c.friction = 0.5;
  c.gravity = {0, 0, -9.81};
  c.max_speed = 1.0;
  const double r = 0.006, a = 0.99 * 2 * r, side = n * a;
  c.effects = pm::EffectSet::resolve(clumps ? std::vector<std::string>{"friction", "damping", "clumps"}
                                            : std::vector<std::string>{"friction", "damping"},
                                     dm::effect_table());
  if (clumps) c.clump_shapes = {dm::gravel_shapes()[2]};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::array<double, 3> p = {(i + 0.5) * a, (j + 0.5) * a, (k + 0.5) * a};
        if (clumps) {
          dm::ClumpInit cl;
          cl.scale = r;
          cl.position = p;
          c.clumps.push_back(cl);
        } else {
          dm::SphereInit s;
          s.radius = r;
          s.position = p;
          c.spheres.push_back(s);
        }
      }
  c.planes = dm::box_planes(side, side);
  return c;
}

void dem_step(benchmark::State& state, bool clumps) {
  const int n = static_cast<int>(state.range(0));
  dm::Dem<double> m(dense_block(n, clumps));
  for (int s = 0; s < 20; ++s) m.step();  // the first list and the first contacts
  for (auto _ : state) m.step();
  Kokkos::fence();
  const double spheres = double(m.sphere_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * spheres));
  state.counters["particles"] = double(n) * n * n;
  state.counters["spheres"] = spheres;
  state.counters["sphere_steps_per_s"] = benchmark::Counter(spheres, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["list_builds"] = m.sphere_list_builds();
}

void BM_DemStepSpheres(benchmark::State& state) { dem_step(state, false); }
void BM_DemStepCubeClumps(benchmark::State& state) { dem_step(state, true); }

}  // namespace

BENCHMARK(BM_DemStepSpheres)->Arg(10)->Arg(20)->Arg(40)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DemStepCubeClumps)->Arg(10)->Arg(20)->Unit(benchmark::kMicrosecond);
