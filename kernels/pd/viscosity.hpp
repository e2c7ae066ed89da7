// Velocity viscosity (seed 003 eq. (3)), the report's control of zero-energy modes:
//
//   T^ZE[x]<xi> = c_v (2 omega_v rho / (D V)) ( s(x) int_H omega v' dV' / int_H omega dV'  -  v )
//
// Reading of the symbols (the report defines c_v and omega_v only):
//  - "D V" is taken as the weighted horizon volume V_H,i = sum_j omega W_ij, so that the force
//    density on a particle whose neighbours are at rest is 2 c_v omega_v rho (vbar_i - v_i): c_v is
//    the damping ratio of a particle oscillating at omega_v against its neighbourhood;
//  - s(x) (the report's varsigma) is 1 while x keeps intact bonds; with none the term vanishes (a
//    free fragment is not braked: the bracket is Galilean invariant only when s = 1).
// The force state is the same for every bond of i; pd/forces.hpp sums W_ij (t_i - t_j).
#pragma once

#include "pd/fields.hpp"

namespace polymech::pd {

template <class T>
struct ViscosityParams {
  T c_v = T(6);          // velocity viscosity coefficient (the report: about 6.0)
  T omega_v = T(0);      // particle's lowest oscillation frequency [rad/s]
  T density = T(1);
};

// Kernel "polymech::pd::velocity_viscosity_state": t_i from vbar_i and V_H,i (deformation pass).
template <class T, int D>
void velocity_viscosity_state(const Fields<T, D>& f, const ViscosityParams<T>& p) {
  const T c = p.c_v * T(2) * p.omega_v * p.density;
  Kokkos::parallel_for(
      "polymech::pd::velocity_viscosity_state", range(static_cast<std::int64_t>(f.x0.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        const T vh = f.horizon_weight(i);
        const T s = vh > T(0) ? c / vh : T(0);  // s(x) = 0 without intact bonds
        store<D>(f.vv_state, i, s * (load<D>(f.vbar, i) - load<D>(f.v, i)));
      });
}

}  // namespace polymech::pd
