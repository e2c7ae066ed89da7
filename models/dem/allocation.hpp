// The construction of dem::Dem (models/dem/dem.hpp, which includes this file): the device arrays of the
// spheres (the free ones, then the clumps' members with their clump's mass), of the clumps (rigid bodies,
// their members as CSR and the members' offsets in the body frame) and of the analytic planes, filled on
// the host from the configuration and copied once.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "dem/dem.hpp"

namespace polymech::dem {

template <class T>
inline void Dem<T>::allocate_spheres() {
  const std::size_t free = cfg_.spheres.size();
  const Index n = static_cast<Index>(free + clump_init_.members.size());
  allocate(s_, n, "polymech::dem::");
  auto x0 = Kokkos::create_mirror_view(s_.x0);
  auto v = Kokkos::create_mirror_view(s_.v);
  auto w = Kokkos::create_mirror_view(s_.omega);
  auto r = Kokkos::create_mirror_view(s_.radius);
  auto m = Kokkos::create_mirror_view(s_.mass);
  for (Index i = 0; i < n; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const auto& sp = u < free ? cfg_.spheres[u] : clump_init_.members[u - free];
    for (int k = 0; k < 3; ++k) {
      x0(i, k) = T(sp.position[k]);
      v(i, k) = T(sp.velocity[k]);
      w(i, k) = T(sp.omega[k]);
    }
    r(i) = T(sp.radius);
    // a member carries its clump's mass (kernels/dem/clumps.hpp)
    m(i) = T(u < free ? cfg_.particle.density * 4.0 / 3.0 * kPi * sp.radius * sp.radius * sp.radius
                      : clump_init_.bodies[static_cast<std::size_t>(clump_init_.member_body[u - free])].mass);
  }
  Kokkos::deep_copy(s_.x0, x0);
  Kokkos::deep_copy(s_.v, v);
  Kokkos::deep_copy(s_.omega, w);
  Kokkos::deep_copy(s_.radius, r);
  Kokkos::deep_copy(s_.mass, m);
  Kokkos::deep_copy(s_.x, s_.x0);
}

template <class T>
inline void Dem<T>::allocate_clumps() {
  const auto& k = clump_init_;
  const std::size_t free = cfg_.spheres.size(), nb = k.bodies.size(), nm = k.members.size();
  clumps_set_.bodies = decltype(clumps_set_.bodies)("polymech::dem::clump_bodies", nb);
  clumps_set_.first_member = Kokkos::View<Offset*, MemSpace>("polymech::dem::clump_first_member", nb + 1);
  clumps_set_.members = Kokkos::View<Index*, MemSpace>("polymech::dem::clump_members", nm);
  clumps_set_.offset = VecView<T, 3>("polymech::dem::clump_offset", free + nm);
  s_.body = View1<int>("polymech::dem::body", free + nm);
  auto bodies = Kokkos::create_mirror_view(clumps_set_.bodies);
  auto first = Kokkos::create_mirror_view(clumps_set_.first_member);
  auto members = Kokkos::create_mirror_view(clumps_set_.members);
  auto offset = Kokkos::create_mirror_view(clumps_set_.offset);
  auto body = Kokkos::create_mirror_view(s_.body);
  for (std::size_t b = 0; b < nb; ++b) {
    const auto& in = k.bodies[b];
    rigid::RigidBody<3> rb;
    rb.mass = in.mass;
    for (int a = 0; a < 3; ++a) {
      rb.inertia[a] = in.inertia[a];
      rb.position[a] = in.position[a];
      rb.velocity[a] = in.velocity[a];
      rb.spin[a] = in.angular_momentum[a];
    }
    for (int a = 0; a < 4; ++a) rb.orientation[a] = in.orientation[a];
    bodies(b) = rb;
  }
  for (std::size_t i = 0; i < free; ++i) body(i) = -1;
  // members are stored clump after clump (expand_clumps), so the CSR is their running count
  for (std::size_t j = 0; j < nm; ++j) {
    const auto b = static_cast<std::size_t>(k.member_body[j]);
    body(free + j) = static_cast<int>(b);
    members(j) = static_cast<Index>(free + j);
    first(b + 1) = static_cast<Offset>(j + 1);
    for (int a = 0; a < 3; ++a) offset(free + j, a) = T(k.member_offset[j][a]);
  }
  for (std::size_t b = 0; b < nb; ++b) first(b + 1) = std::max(first(b + 1), first(b));
  Kokkos::deep_copy(clumps_set_.bodies, bodies);
  Kokkos::deep_copy(clumps_set_.first_member, first);
  Kokkos::deep_copy(clumps_set_.members, members);
  Kokkos::deep_copy(clumps_set_.offset, offset);
  Kokkos::deep_copy(s_.body, body);
}

template <class T>
inline void Dem<T>::allocate_planes() {
  if (cfg_.planes.empty()) return;
  if (cfg_.planes.size() > static_cast<std::size_t>(max_planes))
    throw std::invalid_argument("dem: " + std::to_string(cfg_.planes.size()) + " planes; at most " + std::to_string(max_planes) +
                                " (a larger boundary is an FE surface: effect fe_surfaces)");
  near_planes_ = PlaneMask("polymech::dem::near_planes", static_cast<std::size_t>(s_.size()));
  planes_ = PlaneView<T>("polymech::dem::planes", cfg_.planes.size());
  auto h = Kokkos::create_mirror_view(planes_);
  for (std::size_t q = 0; q < cfg_.planes.size(); ++q) {
    const auto& pl = cfg_.planes[q];
    const double len = std::sqrt(pl.normal[0] * pl.normal[0] + pl.normal[1] * pl.normal[1] + pl.normal[2] * pl.normal[2]);
    if (!(len > 0)) throw std::invalid_argument("dem: a plane normal must not be zero");
    for (int k = 0; k < 3; ++k) {
      h(q, k) = T(pl.point[k]);
      h(q, 3 + k) = T(pl.normal[k] / len);
    }
  }
  Kokkos::deep_copy(planes_, h);
  if (friction_) plane_history_ = SpringView<T>("polymech::dem::plane_history", static_cast<std::size_t>(s_.size()) * cfg_.planes.size());
}

}  // namespace polymech::dem
