// Explicit integrators of a particle set, on the displacement u (positions are x0 + u):
//
//  - symplectic Euler (seed 000 eqs. (13)-(14)):  v_n+1 = v_n + dt a_n;  u_n+1 = u_n + dt v_n+1
//  - velocity Verlet as kick - drift - force - kick (seed 003):
//      v_n+1/2 = v_n + dt/2 a_n;  u_n+1 = u_n + dt v_n+1/2;  a_n+1 = a(u_n+1, v_n+1/2);  v_n+1 = v_n+1/2 + dt/2 a_n+1
//
// Constrained velocity components (ParticleSet::constraint) take their prescribed values instead of
// being integrated. An optional mass-proportional damping c (quasi-static relaxation only, e.g. a
// tension test) is applied semi-implicitly in the kick: v <- (v + h a) / (1 + h c).
#pragma once

#include "particles/particle_set.hpp"

namespace polymech::particles {

// Kernel "polymech::particles::symplectic_euler".
template <class T, int D>
void symplectic_euler(const ParticleSet<T, D>& p, T dt) {
  const bool constrained = p.constrained();
  const auto u = p.u, v = p.v, a = p.a, prescribed = p.prescribed_v;
  const auto constraint = p.constraint;
  Kokkos::parallel_for(
      "polymech::particles::symplectic_euler", range(static_cast<std::int64_t>(u.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        const std::uint8_t mask = constrained ? constraint(i) : std::uint8_t(0);
        for (int k = 0; k < D; ++k) {
          v(i, k) = (mask >> k) & 1 ? prescribed(i, k) : v(i, k) + dt * a(i, k);
          u(i, k) += dt * v(i, k);
        }
      });
}

// Kernel "polymech::particles::kick": v += h a (with damping), then the constraints.
template <class T, int D>
void kick(const ParticleSet<T, D>& p, T h, T damping = T(0)) {
  const bool constrained = p.constrained();
  const T scale = T(1) / (T(1) + h * damping);
  const auto v = p.v, a = p.a, prescribed = p.prescribed_v;
  const auto constraint = p.constraint;
  Kokkos::parallel_for(
      "polymech::particles::kick", range(static_cast<std::int64_t>(v.extent(0))), KOKKOS_LAMBDA(const std::int64_t i) {
        const std::uint8_t mask = constrained ? constraint(i) : std::uint8_t(0);
        for (int k = 0; k < D; ++k) v(i, k) = (mask >> k) & 1 ? prescribed(i, k) : scale * (v(i, k) + h * a(i, k));
      });
}

// Kernel "polymech::particles::drift": u += dt v.
template <class T, int D>
void drift(const ParticleSet<T, D>& p, T dt) {
  const auto u = p.u, v = p.v;
  Kokkos::parallel_for(
      "polymech::particles::drift", range(static_cast<std::int64_t>(u.extent(0))), KOKKOS_LAMBDA(const std::int64_t i) {
        for (int k = 0; k < D; ++k) u(i, k) += dt * v(i, k);
      });
}

}  // namespace polymech::particles
