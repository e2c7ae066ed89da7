// Small kernels of the NosbPd model (power iteration for the stable time step, tension-test
// measurements). Free functions: under CUDA a KOKKOS_LAMBDA may not sit in a private member function.
#pragma once

#include <cmath>
#include <cstdint>

#include "pd/fields.hpp"
#include "pd/reduce.hpp"

namespace polymech::nosb_pd::detail {

// Deterministic pseudo-random field of amplitude eps in u (start of the power iteration).
template <class T, int D>
void random_displacement(const pd::Fields<T, D>& f, T eps) {
  Kokkos::parallel_for(
      "polymech::nosb_pd::power_iteration_start", range(static_cast<std::int64_t>(f.u.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        for (int k = 0; k < D; ++k) {
          std::uint32_t x = static_cast<std::uint32_t>(D * i + k) * 2654435761u + 12345u;
          x ^= x >> 16;
          x *= 0x7feb352dU;
          x ^= x >> 15;
          x *= 0x846ca68bU;
          x ^= x >> 16;
          f.u(i, k) = eps * (T(x) / T(4294967295.0) - T(0.5));
        }
      });
}

// Rayleigh quotient <u, -a>_M / <u, u>_M of the linearised operator a = -M^-1 K u.
template <class T, int D>
double rayleigh_quotient(const pd::Fields<T, D>& f) {
  const auto s = pd::ordered_sum<2>(
      "polymech::nosb_pd::power_iteration_rq", static_cast<std::int64_t>(f.u.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        const double m = double(f.volume(i));
        for (int k = 0; k < D; ++k) {
          acc[0] -= m * double(f.u(i, k)) * double(f.a(i, k));
          acc[1] += m * double(f.u(i, k)) * double(f.u(i, k));
        }
      });
  return s[1] > 0 ? s[0] / s[1] : 0.0;
}

// u <- a / |a|_M * eps |1|_M: the next power-iteration vector.
template <class T, int D>
void acceleration_as_displacement(const pd::Fields<T, D>& f, T eps) {
  const auto s = pd::ordered_sum<2>(
      "polymech::nosb_pd::power_iteration_norm", static_cast<std::int64_t>(f.u.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        const double m = double(f.volume(i));
        for (int k = 0; k < D; ++k) acc[0] += m * double(f.a(i, k)) * double(f.a(i, k));
        acc[1] += m;
      });
  const T scale = s[0] > 0 ? static_cast<T>(double(eps) * std::sqrt(s[1] / s[0])) : T(0);
  Kokkos::parallel_for(
      "polymech::nosb_pd::power_iteration_step", range(static_cast<std::int64_t>(f.u.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        for (int k = 0; k < D; ++k) f.u(i, k) = scale * f.a(i, k);
      });
}

// Tension test: internal force on the pulled grip (group 2) along x, and the least-squares slope of
// u_x over x for the particles with x0 in [x_lo, x_hi] (the strain of the gauge section).
struct TensionMeasure {
  double grip_force = 0.0;
  double gauge_strain = 0.0;
};

template <class T, int D>
TensionMeasure tension_measure(const pd::Fields<T, D>& f, const Kokkos::View<std::uint8_t*, MemSpace>& group, T density,
                               T x_lo, T x_hi) {
  const auto s = pd::ordered_sum<6>(
      "polymech::nosb_pd::tension_measure", static_cast<std::int64_t>(f.u.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        if (group(i) == 2) acc[0] -= double(density * f.volume(i) * f.a(i, 0));
        const T x = f.x0(i, 0);
        if (x >= x_lo && x <= x_hi) {
          const double xd = double(x), ud = double(f.u(i, 0));
          acc[1] += 1.0;
          acc[2] += xd;
          acc[3] += ud;
          acc[4] += xd * xd;
          acc[5] += xd * ud;
        }
      });
  TensionMeasure m;
  m.grip_force = s[0];
  const double n = s[1], sxx = s[4] - s[2] * s[2] / n, sxu = s[5] - s[2] * s[3] / n;
  m.gauge_strain = n > 1 && sxx > 0 ? sxu / sxx : 0.0;
  return m;
}

// sum_i v_i (a thread-count independent sum of a vector field), e.g. the projectile's reaction.
template <class T, int D>
Kokkos::Array<double, D> vector_sum(const char* label, const VecView<T, D>& v) {
  return pd::ordered_sum<D>(label, static_cast<std::int64_t>(v.extent(0)), KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
    for (int k = 0; k < D; ++k) acc[k] += double(v(i, k));
  });
}

// sum_i e_i (thread-count independent).
template <class T>
double scalar_sum(const char* label, const View1<T>& e) {
  return pd::ordered_sum<1>(label, static_cast<std::int64_t>(e.extent(0)),
                            KOKKOS_LAMBDA(const std::int64_t i, double* acc) { acc[0] += double(e(i)); })[0];
}

// sum_i |f_i|^2 / (2 k): energy stored in the penalty springs of the contact forces f_i.
template <class T, int D>
double penalty_energy(const VecView<T, D>& force, double stiffness) {
  const double inv2k = 0.5 / stiffness;
  const auto s = pd::ordered_sum<1>(
      "polymech::nosb_pd::contact_energy", static_cast<std::int64_t>(force.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        double f2 = 0;
        for (int k = 0; k < D; ++k) f2 += double(force(i, k)) * double(force(i, k));
        acc[0] += f2 * inv2k;
      });
  return s[0];
}

}  // namespace polymech::nosb_pd::detail
