// Small Helmholtz configurations shared by the FEM tests.
#pragma once

#include <algorithm>
#include <array>
#include <random>
#include <string>
#include <vector>

#include "helmholtz/helmholtz.hpp"

namespace polymech::testing {

namespace hz = polymech::helmholtz;

// A box with the given boundary kinds (names xmin..zmax) and the effects they need.
inline hz::Config box_config(int order, std::array<int, 3> elements, std::array<double, 3> lengths,
                             const std::vector<hz::BoundaryCondition>& bcs, double vertex_perturbation = 0.0,
                             double node_perturbation = 0.0) {
  hz::Config c;
  c.order = order;
  hz::BoxSpec box;
  box.elements = elements;
  box.lengths = lengths;
  box.perturbation = vertex_perturbation;
  c.mesh = hz::make_box_mesh(box);
  c.node_perturbation = node_perturbation;
  c.boundaries = bcs;
  std::vector<std::string> effects;
  for (const auto& b : bcs) {
    const std::string k = hz::to_string(b.kind);
    if (k != "rigid" && std::find(effects.begin(), effects.end(), k) == effects.end()) effects.push_back(k);
  }
  c.effects = EffectSet::resolve(effects, hz::Helmholtz<double>::effects());
  return c;
}

// The unit cube of seed 002 paper 3 §3(2): Dirichlet data from eq. (27) on every face (Table 1).
inline hz::Config cube_case(int order, int n, double frequency = 500.0) {
  std::vector<hz::BoundaryCondition> bcs;
  for (const char* f : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) bcs.push_back({f, hz::BoundaryKind::dirichlet});
  hz::Config c = box_config(order, {n, n, n}, {1.0, 1.0, 1.0}, bcs);
  c.frequency = frequency;
  c.analytic.kind = hz::AnalyticKind::plane_cosines;
  return c;
}

// The duct of §3(3): 1 x 0.2 x 0.1 m, vibrating left end (v0 = 0.014 m/s), impedance 445.9 at the
// right end, rigid elsewhere (Table 2); n elements along the length, the others scaled to keep cubes.
inline hz::Config duct_case(int order, int n, double frequency = 500.0) {
  std::vector<hz::BoundaryCondition> bcs = {{"xmin", hz::BoundaryKind::vibrating, 0.0, 0.014},
                                            {"xmax", hz::BoundaryKind::impedance, 445.9, 0.0}};
  const int ny = std::max(1, n / 5), nz = std::max(1, n / 10);
  hz::Config c = box_config(order, {n, ny, nz}, {1.0, 0.2, 0.1}, bcs);
  c.frequency = frequency;
  c.analytic.kind = hz::AnalyticKind::duct;
  c.analytic.length = 1.0;
  c.analytic.velocity = 0.014;
  c.analytic.impedance = 445.9;
  return c;
}

template <class T>
View1<Kokkos::complex<T>> random_complex(Index n, unsigned seed) {
  View1<Kokkos::complex<T>> v("random", n);
  auto h = Kokkos::create_mirror_view(v);
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Index i = 0; i < n; ++i) h(i) = Kokkos::complex<T>(static_cast<T>(u(gen)), static_cast<T>(u(gen)));
  Kokkos::deep_copy(v, h);
  return v;
}

}  // namespace polymech::testing
