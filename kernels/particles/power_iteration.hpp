// Kernels of the power iteration for the largest eigenvalue of M^-1 K, the linearised operator of an
// explicit particle model; its square root bounds the stable time step (models/common/stability.hpp).
//
// The degrees of freedom are described by a functor, so one iteration serves every model:
//
//   static constexpr int slots;                                   // state components per particle
//   KOKKOS_INLINE_FUNCTION T& state(Index i, int s) const;          // q (a displacement, a rotation)
//   KOKKOS_INLINE_FUNCTION T response(Index i, int s) const;        // -(M^-1 K q): the acceleration
//   KOKKOS_INLINE_FUNCTION double weight(Index i, int s) const;     // the mass (or inertia) of the DoF
//   KOKKOS_INLINE_FUNCTION T start_divisor(int s) const;            // start amplitude eps / divisor
//
// Sums are particles::ordered_sum in double: the estimate does not depend on the thread count.
#pragma once

#include <cmath>
#include <cstdint>

#include "core/hash.hpp"
#include "particles/reductions.hpp"

namespace polymech::particles {

// The deterministic pseudo-random start vector: slot s of particle i gets
// eps / divisor(s) * (hash(uint32(stride * i + s) * multiplier + offset) - 1/2). Each model keeps the
// seed it was validated with, so its stability limits stay exactly what they were.
struct StartVector {
  std::uint32_t stride = 3;
  std::uint32_t multiplier = 1;
  std::uint32_t offset = 1;
};

// Uniform in [-1/2, 1/2] from a 32-bit key (an integer hash with good avalanche).
template <class T>
KOKKOS_INLINE_FUNCTION T hash_centered(std::uint32_t x) {
  return T(mix32(x)) / T(4294967295.0) - T(0.5);
}

// Kernel "polymech::particles::power_iteration_start".
template <class T, class Dofs>
void power_iteration_start(const Dofs& dofs, Index n, T eps, StartVector start) {
  Kokkos::parallel_for(
      "polymech::particles::power_iteration_start", range(n), KOKKOS_LAMBDA(const Index i) {
        for (int s = 0; s < Dofs::slots; ++s) {
          const auto key = static_cast<std::uint32_t>(static_cast<std::int64_t>(start.stride) * i + s);
          dofs.state(i, s) = eps / dofs.start_divisor(s) * hash_centered<T>(key * start.multiplier + start.offset);
        }
      });
}

// <q, A q>_M / <q, q>_M with A q = -response: the Rayleigh quotient of M^-1 K at the current state.
template <class Dofs>
double power_iteration_rayleigh_quotient(const Dofs& dofs, Index n) {
  const auto s = ordered_sum<2>("polymech::particles::power_iteration_rq", n, KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
    for (int k = 0; k < Dofs::slots; ++k) {
      const double m = dofs.weight(static_cast<Index>(i), k);
      const double q = double(dofs.state(static_cast<Index>(i), k));
      acc[0] -= m * q * double(dofs.response(static_cast<Index>(i), k));
      acc[1] += m * q * q;
    }
  });
  return s[1] > 0 ? s[0] / s[1] : 0.0;
}

// q <- response / |response|_M * eps |1|_M: the next vector (|1|_M from the first slot's weights).
template <class T, class Dofs>
void power_iteration_step(const Dofs& dofs, Index n, T eps) {
  const auto s = ordered_sum<2>("polymech::particles::power_iteration_norm", n, KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
    for (int k = 0; k < Dofs::slots; ++k) {
      const double r = double(dofs.response(static_cast<Index>(i), k));
      acc[0] += dofs.weight(static_cast<Index>(i), k) * r * r;
    }
    acc[1] += dofs.weight(static_cast<Index>(i), 0);
  });
  const T scale = s[0] > 0 ? static_cast<T>(double(eps) * std::sqrt(s[1] / s[0])) : T(0);
  Kokkos::parallel_for(
      "polymech::particles::power_iteration_step", range(n), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < Dofs::slots; ++k) dofs.state(i, k) = scale * dofs.response(i, k);
      });
}

}  // namespace polymech::particles
