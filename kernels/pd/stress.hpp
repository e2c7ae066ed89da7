// Per-particle constitutive update of a NOSB step: from F_i (and dF/dt) to the first Piola-Kirchhoff
// stress P_i and the matrix A_i = P_i K_i^-1 that gives the force state T_i<xi> = omega A_i xi
// (correspondence: the force state whose work equals P : dF for every bond family). One overload of
// pd::update_stress per law of kernels/materials, chosen by the law's type.
#pragma once

#include "materials/johnson_cook.hpp"
#include "pd/fields.hpp"

namespace polymech::pd {

// A particle whose volume ratio J = det F leaves [j_min, 1 / j_min] is crushed: in a metal, whose
// plastic flow keeps the volume, such a J only comes from a family torn apart or collapsed onto itself
// (zero-energy modes, a few intact bonds after damage). There the hypoelastic pressure grows without
// bound and P = J sigma F^-T changes sign when F inverts, which creates energy; the particle is failed
// for good (no stress, its stored energy released) and is kept apart by the short-range contact.
template <class T>
struct CrushLimits {
  T j_min = T(0);  // 0: never
};

// Kernel "polymech::pd::stress_elastic": St. Venant-Kirchhoff (dt and crush limits unused: a
// hyperelastic law has no history).
template <class T, int D>
void update_stress(const Fields<T, D>& f, const materials::StVenantKirchhoff<T>& law, T /*dt*/ = T(0),
                   CrushLimits<T> /*crush*/ = {}) {
  Kokkos::parallel_for(
      "polymech::pd::stress_elastic", range(static_cast<std::int64_t>(f.x0.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        if (f.status(i) & status_failed) {
          store_mat<D>(f.A, i, Mat<T, D>::zero());
          return;
        }
        const Mat3<T> P = law.first_piola_kirchhoff(embed3<T, D>(load_mat<D>(f.F, i)));
        store_mat<D>(f.A, i, block<T, D>(P) * load_mat<D>(f.kinv, i));
      });
}

// Kernel "polymech::pd::stress_johnson_cook": J2 with Johnson-Cook hardening over a step dt. The
// velocity gradient is L = dF/dt F_mid^-1 with F_mid = F - dt/2 dF/dt, the midpoint of the step
// (F is linear in the displacements, so F_n+1 - F_n = dt dF/dt(v_n+1/2) exactly on a fixed family).
template <class T, int D>
void update_stress(const Fields<T, D>& f, const materials::J2JohnsonCook<T>& law, T dt, CrushLimits<T> crush = {}) {
  const T j_min = crush.j_min, j_max = crush.j_min > T(0) ? T(1) / crush.j_min : T(0);
  Kokkos::parallel_for(
      "polymech::pd::stress_johnson_cook", range(static_cast<std::int64_t>(f.x0.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        if (f.status(i) & status_failed) {
          store_mat<D>(f.A, i, Mat<T, D>::zero());
          return;
        }
        const Mat3<T> F = embed3<T, D>(load_mat<D>(f.F, i));
        if (j_min > T(0)) {
          const T J = det(F);
          if (!(J > j_min && J < j_max)) {
            f.status(i) |= std::uint8_t(status_failed | status_crushed);
            store_sym(f.sigma, i, Mat3<T>::zero());
            store_mat<D>(f.A, i, Mat<T, D>::zero());
            return;
          }
        }
        Mat3<T> Fdot = embed3<T, D>(load_mat<D>(f.Fdot, i));
        if constexpr (D == 2) Fdot.a[2][2] = T(0);  // plane strain: F33 = 1 at all times
        const Mat3<T> L = Fdot * inverse(F - (T(0.5) * dt) * Fdot);
        const T eps = f.eps_p(i), temp = f.temperature(i);
        const materials::J2Step<T> s = law.update(load_sym(f.sigma, i), L, dt, eps, temp);
        store_sym(f.sigma, i, s.sigma);
        if (s.d_eps_p > T(0)) {
          f.eps_p(i) = eps + s.d_eps_p;
          const T work = s.flow_stress * s.d_eps_p;
          f.plastic_work(i) += work;
          if (law.hardening.thermal()) f.temperature(i) = temp + law.hardening.chi * work / law.hardening.rho_cp;
        }
        // P = J sigma F^-T
        const Mat3<T> Finv = inverse(F);
        const Mat3<T> P = det(F) * (s.sigma * transpose(Finv));
        store_mat<D>(f.A, i, block<T, D>(P) * load_mat<D>(f.kinv, i));
      });
}

// The stored elastic energy density of particle i under each law.
template <class T, int D>
KOKKOS_INLINE_FUNCTION T stored_energy_density(const materials::StVenantKirchhoff<T>& law, const Fields<T, D>& f,
                                               std::int64_t i) {
  return law.energy_density(embed3<T, D>(load_mat<D>(f.F, i)));
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION T stored_energy_density(const materials::J2JohnsonCook<T>& law, const Fields<T, D>& f,
                                               std::int64_t i) {
  return law.stored_energy(load_sym(f.sigma, i));
}

}  // namespace polymech::pd
