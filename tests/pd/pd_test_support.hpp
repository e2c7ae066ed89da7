// Helpers shared by the peridynamics tests: small configurations and host-side state access.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::testing {

namespace np = polymech::nosb_pd;

// A box of cells^D particles (spacing h), elastic steel, the given effects.
inline np::Config box_config(int dim, int cells, double m, std::vector<std::string> effects,
                             np::Layout layout = np::Layout::lattice, double h = 1e-3) {
  np::Config c;
  c.dimension = dim;
  c.spacing = h;
  c.horizon_ratio = m;
  c.geometry.shape = np::Shape::box;
  c.geometry.length = c.geometry.width = c.geometry.height = cells * h;
  c.geometry.layout = layout;
  c.material.youngs_modulus = 200e9;
  c.material.poisson_ratio = 0.3;
  c.material.density = 7850;
  c.damage.critical_stretch = 0.01;
  c.stabilization.omega_v = 1e5;
  c.dt = 1e-8;
  c.effects = EffectSet::resolve(effects, np::NosbPd<double, 3>::effects());
  return c;
}

// Sets u(i) = fn(x0_i) for every particle (host).
template <class Model, int D>
void set_displacement(Model& m, const std::function<std::array<double, D>(const std::array<double, D>&, int)>& fn) {
  const auto& f = m.fields();
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.x0);
  auto u = Kokkos::create_mirror_view(f.u);
  for (Index i = 0; i < m.particles(); ++i) {
    std::array<double, D> x;
    for (int k = 0; k < D; ++k) x[k] = x0(i, k);
    const auto d = fn(x, i);
    for (int k = 0; k < D; ++k) u(i, k) = d[k];
  }
  Kokkos::deep_copy(f.u, u);
}

template <class Model, int D>
void set_velocity(Model& m, const std::function<std::array<double, D>(const std::array<double, D>&, int)>& fn) {
  const auto& f = m.fields();
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.x0);
  auto v = Kokkos::create_mirror_view(f.v);
  for (Index i = 0; i < m.particles(); ++i) {
    std::array<double, D> x;
    for (int k = 0; k < D; ++k) x[k] = x0(i, k);
    const auto d = fn(x, i);
    for (int k = 0; k < D; ++k) v(i, k) = d[k];
  }
  Kokkos::deep_copy(f.v, v);
}

// Deterministic pseudo-random number in [-1, 1).
inline double noise(std::uint64_t k) { return np::detail::hash_uniform(k * 7919 + 17); }

}  // namespace polymech::testing
