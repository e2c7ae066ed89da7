// The watchdog's check of a particle set (models/common/run.hpp): the first particle whose
// displacement or velocity is not finite or, with max_u > 0, has moved farther than the model allows.
#pragma once

#include <cmath>
#include <string>

#include "common/host_copy.hpp"
#include "common/run.hpp"
#include "particles/reductions.hpp"
#include "particles/speed_limit.hpp"

namespace polymech::models {

template <class T, int D>
Health particle_health(const particles::ParticleSet<T, D>& p, T max_u = T(0), const std::string& range = "") {
  Health h;
  const Index bad = particles::first_bad_particle(p, max_u);
  if (bad < 0) return h;
  h.finite = false;
  h.first_bad = bad;
  auto x = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.x0, bad, Kokkos::ALL()));
  auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.u, bad, Kokkos::ALL()));
  auto v = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.v, bad, Kokkos::ALL()));
  bool finite = true;
  double u2 = 0;
  for (int k = 0; k < D; ++k) {
    h.position[k] = static_cast<double>(x(k));
    finite = finite && std::isfinite(static_cast<double>(u(k))) && std::isfinite(static_cast<double>(v(k)));
    u2 += static_cast<double>(u(k)) * static_cast<double>(u(k));
  }
  if (finite)
    h.problem = "moved " + format_g(std::sqrt(u2)) + " m, more than " + format_g(static_cast<double>(max_u)) + " m" +
                (range.empty() ? "" : " (" + range + ")");
  return h;
}

// The first particle faster than `max_speed` as an unhealthy Health (`bound` says where the bound comes
// from), or a healthy one. A state that blew up can stay finite for many steps (issue 33 item 2: an ISPH
// tank at 3e28 m/s, every value finite): the speed a discretization cannot represent catches it first.
template <class T, int D>
Health speed_health(const particles::ParticleSet<T, D>& p, double max_speed, const std::string& bound) {
  Health h;
  const Index fast = particles::first_faster_than(p.v, static_cast<T>(max_speed));
  if (fast < 0) return h;
  auto x = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.x0, fast, Kokkos::ALL()));
  auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.u, fast, Kokkos::ALL()));
  auto v = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(p.v, fast, Kokkos::ALL()));
  double s2 = 0;
  for (int k = 0; k < D; ++k) {
    h.position[k] = static_cast<double>(x(k)) + static_cast<double>(u(k));
    s2 += static_cast<double>(v(k)) * static_cast<double>(v(k));
  }
  h.finite = false;
  h.first_bad = fast;
  h.problem = "moves at " + format_g(std::sqrt(s2)) + " m/s, more than " + bound + " = " + format_g(max_speed) + " m/s";
  return h;
}

}  // namespace polymech::models
