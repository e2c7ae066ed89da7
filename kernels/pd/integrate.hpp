// Velocity Verlet for the particles (kick - drift - force - kick):
//   v_n+1/2 = v_n + dt/2 a_n;   u_n+1 = u_n + dt v_n+1/2;   a_n+1 = a(u_n+1, v_n+1/2);   v_n+1 = v_n+1/2 + dt/2 a_n+1
// Constrained velocity components take their prescribed values after every kick. An optional
// mass-proportional damping c (quasi-static relaxation only, e.g. the tension test) is applied
// semi-implicitly in the kicks: v <- (v + h a) / (1 + h c).
#pragma once

#include "pd/fields.hpp"

namespace polymech::pd {

// Kernel "polymech::pd::kick": v += h a (with damping), then the constraints.
template <class T, int D>
void kick(const Fields<T, D>& f, T h, T damping = T(0)) {
  const bool constrained = f.constraint.extent(0) > 0;
  const T scale = T(1) / (T(1) + h * damping);
  Kokkos::parallel_for(
      "polymech::pd::kick", range(static_cast<std::int64_t>(f.v.extent(0))), KOKKOS_LAMBDA(const std::int64_t i) {
        const std::uint8_t mask = constrained ? f.constraint(i) : std::uint8_t(0);
        for (int k = 0; k < D; ++k)
          f.v(i, k) = (mask >> k) & 1 ? f.prescribed_v(i, k) : scale * (f.v(i, k) + h * f.a(i, k));
      });
}

// Kernel "polymech::pd::drift": u += dt v.
template <class T, int D>
void drift(const Fields<T, D>& f, T dt) {
  Kokkos::parallel_for(
      "polymech::pd::drift", range(static_cast<std::int64_t>(f.u.extent(0))), KOKKOS_LAMBDA(const std::int64_t i) {
        for (int k = 0; k < D; ++k) f.u(i, k) += dt * f.v(i, k);
      });
}

}  // namespace polymech::pd
