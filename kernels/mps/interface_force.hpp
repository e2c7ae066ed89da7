// Force transmitted through a line inside an intact MPS body (seed 000 §5.2.2): for each particle on
// the upper side of the line, the sum of the elastic pair forces (the terms of eq. (11), times the
// particle mass) from its bonds that cross the line, projected on the line's tangent. The S-wave crack
// case sets the crack's fixed normal reaction from the largest such shear force of the intact run.
#pragma once

#include "mps/elastic.hpp"

namespace polymech::mps {

// Bonds crossing the line, per upper-side particle (CSR over `particles`).
struct LineCrossings {
  View1<Index> particles;
  Kokkos::View<Offset*, MemSpace> offsets;
  View1<Index> neighbors;  // the lower-side end of each crossing bond
  View1<Offset> bonds;     // its index in the family (for 1/|r0|)
};

// running_max(q) = max(running_max(q), |F_q . t|) for the crossing particles q.
template <class T, bool Rotation>
void interface_shear_force_max(const LineCrossings& lc, const ElasticFields<T>& f, const ElasticParams<T>& p,
                               T t1, T t3, const View1<T>& running_max) {
  const T re = p.re;
  const T c_vol = p.mass * p.c13 * T(2) / (p.n0 * p.rho);
  const T c_lap = p.mass * T(2) * p.c55 * T(4) / (p.n0 * p.rho);
  Kokkos::parallel_for(
      "polymech::mps::interface_shear_force", range(static_cast<std::int64_t>(lc.particles.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t q) {
        const Index i = lc.particles(q);
        const ParticleState<T, Rotation> pi(f, i);
        Vec2<T> force = Vec2<T>::zero();
        for (Offset m = lc.offsets(q); m < lc.offsets(q + 1); ++m) {
          const Index j = lc.neighbors(m);
          const ElasticPair<T, Rotation> b(pi, ParticleState<T, Rotation>(f, j), f.inv_r0(lc.bonds(m)), re);
          force += ((f.e(i) + f.e(j)) * c_vol * b.w * b.inv_r0 * b.inv_r) * b.r;
          force += (c_lap * b.w * b.inv_r0 * b.inv_r0) * b.uij;
        }
        const T shear = kx::fabs(force[0] * t1 + force[1] * t3);
        if (shear > running_max(q)) running_max(q) = shear;
      });
}

}  // namespace polymech::mps
