// Energy and momentum of the particles (host values, thread-count independent sums,
// particles/reductions.hpp).
#pragma once

#include "particles/reductions.hpp"
#include "pd/stress.hpp"

namespace polymech::pd {

struct ParticleEnergies {
  double kinetic = 0.0;        // sum 1/2 rho V |v|^2
  double strain = 0.0;         // stored elastic energy sum V W
  double plastic = 0.0;        // plastic work dissipated so far
  double viscous = 0.0;        // work done by velocity-viscosity forces so far (<= 0: dissipated)
  double hourglass = 0.0;      // work done by hourglass forces so far
  double momentum[3] = {0, 0, 0};
};

// Kernel "polymech::pd::energies": the stored energy of the law (St. Venant-Kirchhoff: W(F); J2: the
// elastic energy of the Cauchy stress) and, for rate laws, the plastic work.
template <class T, int D, class Law>
ParticleEnergies particle_energies(const Fields<T, D>& f, const Law& law, T density) {
  const bool vv = f.viscous_work.extent(0) > 0, hg = f.hourglass_work.extent(0) > 0;
  constexpr bool plastic_law = Law::rate_form;
  const auto s = particles::ordered_sum<5 + D>(
      "polymech::pd::energies", static_cast<std::int64_t>(f.x0.extent(0)), KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        const T V = f.volume(i);
        const Vec<T, D> v = load<D>(f.v, i);
        acc[0] += double(T(0.5) * density * V * norm2(v));
        if (!(f.status(i) & status_failed)) acc[1] += double(V * stored_energy_density(law, f, i));
        if (plastic_law) acc[2] += double(V * f.plastic_work(i));
        if (vv) acc[3] += double(f.viscous_work(i));
        if (hg) acc[4] += double(f.hourglass_work(i));
        for (int k = 0; k < D; ++k) acc[5 + k] += double(density * V * v[k]);
      });
  ParticleEnergies e;
  e.kinetic = s[0];
  e.strain = s[1];
  e.plastic = s[2];
  e.viscous = s[3];
  e.hourglass = s[4];
  for (int k = 0; k < D; ++k) e.momentum[k] = s[5 + k];
  return e;
}

}  // namespace polymech::pd
