// DEM step throughput (seed 002 paper 2; issue 13): sphere-steps and contacts per second of the whole Dem
// step (broad phase with skin, sphere-sphere and sphere-plane Hertz-Mindlin with friction and damping, the
// integrator) on a dense block in contact, for spheres (1e3 .. 1e6) and for the cubical clumps of 8
// spheres (8e3 .. 8.3e5 spheres). The block is a cubic lattice of spacing 0.99 x 2R in a box of planes
// that holds it exactly, so every particle keeps its neighbours in contact while the block rings down.
// Counters: `contacts` (sphere blocks: lattice neighbours and planes in contact after the timed steps,
// counted on the host), `contacts_per_s`, and where the step's time goes, from the kernels' times
// (bench/support/kernel_times.hpp) over 10 further steps: `share_broad_phase` (the neighbour search's
// kernels and the carried springs, the planes' Verlet mask), `share_contact_forces`, `share_integrator`;
// `build_us_per_sphere`: one list build (the first step's broad-phase kernels) per sphere. CPU time (the
// machine is shared): run with OMP_NUM_THREADS=1.
// BM_DemPour/STEPS: the pour of scenes/dem/sphere_pour.toml (2 000 spheres, R = 5-7 mm, a 12 cm bin of five
// planes; the case bench/peers/liggghts/run_pour.sh runs next to LIGGGHTS) for STEPS steps from its start,
// one iteration: sphere-steps/s of the loop and each kernel group's share of the kernels' time over the
// whole run (`share_*`; the timing callbacks cost about 1 % of the step).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "support/kernel_times.hpp"
#include "dem/dem.hpp"
#include "dem/layer_cases.hpp"
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

// Kernel names by what they do in a step.
const std::vector<std::string> kBroadPhase = {"polymech::neighbors::", "polymech::contact::carry_history",
                                              "polymech::dem::near_planes"};
const std::vector<std::string> kContactForces = {"polymech::dem::sphere_sphere", "polymech::dem::sphere_plane"};
const std::vector<std::string> kIntegrator = {"polymech::dem::kick", "polymech::dem::start_forces",
                                              "polymech::dem::clump_"};

// Contacts of a block of free spheres (lattice order i + n (j + n k)): face neighbours that overlap, and
// spheres that overlap one of the box's planes (the floor z = 0, the walls x, y = 0 and = side).
double block_contacts(const dm::Dem<double>& m, int n, double side) {
  const auto& s = m.spheres();
  auto x = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.x);
  auto r = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), s.radius);
  auto id = [n](int i, int j, int k) { return i + n * (j + n * k); };
  double contacts = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = id(i, j, k);
        const int next[3] = {i + 1 < n ? id(i + 1, j, k) : -1, j + 1 < n ? id(i, j + 1, k) : -1,
                             k + 1 < n ? id(i, j, k + 1) : -1};
        for (const int b : next) {
          if (b < 0) continue;
          const double dx = x(a, 0) - x(b, 0), dy = x(a, 1) - x(b, 1), dz = x(a, 2) - x(b, 2);
          if (std::sqrt(dx * dx + dy * dy + dz * dz) < r(a) + r(b)) ++contacts;
        }
        const double gaps[5] = {x(a, 2), x(a, 0), side - x(a, 0), x(a, 1), side - x(a, 1)};
        for (const double g : gaps)
          if (g < r(a)) ++contacts;
      }
  return contacts;
}

void dem_step(benchmark::State& state, bool clumps) {
  const int n = static_cast<int>(state.range(0));
  const auto config = dense_block(n, clumps);
  dm::Dem<double> m(config);
  double build_seconds = 0.0;
  {
    pm::bench::KernelTimes first;  // the first step holds the first list build
    m.step();
    build_seconds = first.seconds(kBroadPhase);
  }
  for (int s = 0; s < 19; ++s) m.step();  // the first contacts
  for (auto _ : state) m.step();
  Kokkos::fence();
  pm::bench::KernelTimes times;
  for (int s = 0; s < 10; ++s) m.step();
  Kokkos::fence();
  const double all = times.total();
  const double spheres = double(m.sphere_count());
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * spheres));
  state.counters["particles"] = double(n) * n * n;
  state.counters["spheres"] = spheres;
  state.counters["sphere_steps_per_s"] = benchmark::Counter(spheres, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["list_builds"] = m.sphere_list_builds();
  state.counters["share_broad_phase"] = times.seconds(kBroadPhase) / all;
  state.counters["share_contact_forces"] = times.seconds(kContactForces) / all;
  state.counters["share_integrator"] = times.seconds(kIntegrator) / all;
  state.counters["build_us_per_sphere"] = 1e6 * build_seconds / spheres;
  if (!clumps) {
    const double contacts = block_contacts(m, n, config.planes[2].point[0]);
    state.counters["contacts"] = contacts;
    state.counters["contacts_per_s"] = benchmark::Counter(contacts, benchmark::Counter::kIsIterationInvariantRate);
  }
}

// The pour of scenes/dem/sphere_pour.toml (io/dem_pour_scene.cpp's defaults: dt = 0.5 x the limit).
dm::Config sphere_pour() {
  dm::Config base;
  base.particle = {5e7, 0.3, 2650};
  base.wall = {5e7, 0.3, 2650};
  base.restitution = 0.4;
  base.friction = 0.5;
  base.gravity = {0, 0, -9.81};
  base.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
  dm::PourSpec p;
  p.bin = {0.12, 0.12, 0.12};
  p.count = 2000;
  p.shapes = {"sphere"};
  p.radius_min = 0.005;
  p.radius_max = 0.007;
  p.seed = 1;
  return dm::pour_config(base, p);
}

void BM_DemPour(benchmark::State& state) {
  const auto steps = state.range(0);
  auto config = sphere_pour();
  if (const char* skin = std::getenv("POLYMECH_BENCH_SKIN")) config.skin = std::atof(skin);  // default 0.2 r_min = 1 mm
  std::map<std::string, double> seconds;
  double spheres = 0, builds = 0;
  for (auto _ : state) {
    state.PauseTiming();
    dm::Dem<double> m(config);
    spheres = double(m.sphere_count());
    state.ResumeTiming();
    pm::bench::KernelTimes times;
    for (std::int64_t s = 0; s < steps; ++s) m.step();
    Kokkos::fence();
    for (const auto& [name, t] : times.by_name()) seconds[name] += t;
    builds = m.sphere_list_builds();
  }
  double all = 0;
  for (const auto& [name, t] : seconds) all += t;
  if (std::getenv("POLYMECH_BENCH_KERNELS"))  // every kernel's share, to stderr
    for (const auto& [name, t] : seconds) std::fprintf(stderr, "%6.2f %%  %.3f s  %s\n", 100 * t / all, t, name.c_str());
  auto share = [&](const std::vector<std::string>& parts) {
    double t = 0;
    for (const auto& [name, sec] : seconds)
      for (const auto& q : parts)
        if (name.find(q) != std::string::npos) {
          t += sec;
          break;
        }
    return t / all;
  };
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * spheres * double(steps)));
  state.counters["spheres"] = spheres;
  state.counters["list_builds"] = builds;
  state.counters["share_sphere_sphere"] = share({"polymech::dem::sphere_sphere"});
  state.counters["share_sphere_plane"] = share({"polymech::dem::sphere_plane"});
  state.counters["share_list_build"] = share({"polymech::neighbors::", "polymech::contact::carry_history", "polymech::dem::near_planes"}) -
                                       share({"polymech::neighbors::max_displacement"});
  state.counters["share_displacement_check"] = share({"polymech::neighbors::max_displacement"});
  state.counters["share_integrator"] = share(kIntegrator);
}

// The FE tyre standing on a layer of spheres at the full load (dm::cases::tyre_on_a_layer, 16 x 6 cells of
// order 1 round and across): wall range(0) = 0 smeared (1 cell through), 1 layered (3 cells: rubber / cord /
// rubber, its stable step about a quarter); range(1) = the tyre's substeps per DEM step (1: one common step,
// the smaller of the two; 0: subcycled, the DEM's step and as many tyre steps as its own needs). Timed: 5 ms of
// simulated time after 15 ms of inflation and loading. Counter simulated_ms_per_s: simulated time per second.
void BM_TyreOnALayer(benchmark::State& state) {
  dm::Config c = dm::cases::tyre_on_a_layer(0.0, 0.010);
  c.tyre.layered = state.range(0) == 1;
  c.tyre.through = c.tyre.layered ? 3 : 1;
  c.tyre.substeps = static_cast<int>(state.range(1));
  dm::Dem<double> m(c);
  const auto steps = [&](double t) { return static_cast<std::int64_t>(std::llround(t / m.dt())); };
  pm::models::run(m, steps(0.015));
  const std::int64_t n = steps(0.005);
  for (auto _ : state) {
    pm::models::run(m, n);
    Kokkos::fence();
  }
  state.SetItemsProcessed(state.iterations() * n);  // DEM steps
  state.counters["simulated_ms_per_s"] = benchmark::Counter(5.0 * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["dem_dt"] = m.dt();
  state.counters["tyre_dt"] = m.tyre().solid().time_step();
  state.counters["substeps"] = m.tyre().substeps();
  state.counters["tyre_dofs"] = double(m.tyre().solid().dof_count());
}

void BM_DemStepSpheres(benchmark::State& state) { dem_step(state, false); }
void BM_DemStepCubeClumps(benchmark::State& state) { dem_step(state, true); }

}  // namespace

BENCHMARK(BM_DemStepSpheres)->Arg(10)->Arg(22)->Arg(40)->Arg(47)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_DemPour)->Arg(30000)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TyreOnALayer)->Args({0, 1})->Args({1, 1})->Args({1, 0})->Args({0, 0})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DemStepCubeClumps)->Arg(10)->Arg(20)->Arg(47)->Unit(benchmark::kMicrosecond);
