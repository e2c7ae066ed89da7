// Kernels of MpsElastic's power iteration (the stability limit, MpsElastic::max_eigenvalue). Free
// functions rather than private members: under CUDA an extended __host__ __device__ lambda
// (KOKKOS_LAMBDA) may not be defined in a private or protected member function.
#pragma once

#include <cstdint>

#include "mps/elastic.hpp"

namespace polymech::mps_elastic {

namespace detail {

// Deterministic pseudo-random start vector of amplitude eps (theta scaled by 1 / l0).
template <class T>
void power_iteration_start(const mps::ElasticFields<T>& f, Index n, bool rot, T eps, T l0) {
  Kokkos::parallel_for(
      "polymech::mps_elastic::power_iteration_start", range(n), KOKKOS_LAMBDA(const Index i) {
        auto hash = [](std::uint32_t x) {
          x ^= x >> 16;
          x *= 0x7feb352dU;
          x ^= x >> 15;
          x *= 0x846ca68bU;
          x ^= x >> 16;
          return T(x) / T(4294967295.0) - T(0.5);
        };
        f.u(i, 0) = eps * hash(3u * static_cast<std::uint32_t>(i) + 1u);
        f.u(i, 1) = eps * hash(3u * static_cast<std::uint32_t>(i) + 2u);
        if (rot) f.theta(i) = eps / l0 * hash(3u * static_cast<std::uint32_t>(i) + 3u);
      });
}

// <q, A q>_M / <q, q>_M with A q = -(a, alpha), particle mass m and moment of inertia `inertia`.
template <class T>
double power_iteration_rayleigh_quotient(const mps::ElasticFields<T>& f, Index n, bool rot, T m, T inertia) {
  T num = T(0), den = T(0);
  Kokkos::parallel_reduce(
      "polymech::mps_elastic::power_iteration_rq", range(n),
      KOKKOS_LAMBDA(const Index i, T& nn, T& dd) {
        nn -= m * (f.u(i, 0) * f.a(i, 0) + f.u(i, 1) * f.a(i, 1));
        dd += m * (f.u(i, 0) * f.u(i, 0) + f.u(i, 1) * f.u(i, 1));
        if (rot) {
          nn -= inertia * f.theta(i) * f.alpha(i);
          dd += inertia * f.theta(i) * f.theta(i);
        }
      },
      num, den);
  return static_cast<double>(num) / static_cast<double>(den);
}

// q <- A q (u <- a, theta <- alpha), renormalised to M-norm amplitude eps per particle.
template <class T>
void power_iteration_step(const mps::ElasticFields<T>& f, Index n, bool rot, T m, T inertia, T eps) {
  T norm = T(0);
  Kokkos::parallel_reduce(
      "polymech::mps_elastic::power_iteration_norm", range(n),
      KOKKOS_LAMBDA(const Index i, T& s) {
        s += m * (f.a(i, 0) * f.a(i, 0) + f.a(i, 1) * f.a(i, 1));
        if (rot) s += inertia * f.alpha(i) * f.alpha(i);
      },
      norm);
  const T scale = eps * kx::sqrt(m * static_cast<T>(n) / norm);
  Kokkos::parallel_for(
      "polymech::mps_elastic::power_iteration_step", range(n), KOKKOS_LAMBDA(const Index i) {
        f.u(i, 0) = scale * f.a(i, 0);
        f.u(i, 1) = scale * f.a(i, 1);
        if (rot) f.theta(i) = scale * f.alpha(i);
      });
}

}  // namespace detail

}  // namespace polymech::mps_elastic
