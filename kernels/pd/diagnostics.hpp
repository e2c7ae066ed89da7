// Zero-energy-mode diagnostics: how much of the bond deformation the deformation gradient does not
// see. Eq. (1) fits one affine map F_i to a whole family; a displacement field with Y = F_i xi on
// every bond is all the correspondence model can resist, and the rest, z_i<xi> = Y - F_i xi, is
// invisible to it (the zero-energy modes of seed 003 §3(2)). The measure is
//   Z = sqrt( sum_i sum_j W_ij |Y - F_i xi|^2 / sum_i sum_j W_ij |Y - xi|^2 ),
// 0 for every affine field, and growing when a spurious oscillation develops. Particles with fewer
// than `min_bonds` bonds (the surface layer, where the affine fit of a smooth field is not exact)
// can be left out.
#pragma once

#include "pd/fields.hpp"
#include "pd/reduce.hpp"

namespace polymech::pd {

struct NonAffineMeasure {
  double nonaffine = 0.0;  // sum W |Y - F xi|^2
  double total = 0.0;      // sum W |Y - xi|^2
  double ratio() const { return total > 0 ? std::sqrt(nonaffine / total) : 0.0; }
};

// Kernel "polymech::pd::nonaffine_deviation" (intact bonds; F from the last deformation pass).
template <class T, int D>
NonAffineMeasure nonaffine_deviation(const neighbors::BondFamily& family, const Fields<T, D>& f, Index min_bonds = 0) {
  const bool damage = f.bond_intact.extent(0) > 0;
  const auto s = ordered_sum<2>(
      "polymech::pd::nonaffine_deviation", family.num_particles, KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        if (family.count(static_cast<Index>(i)) < min_bonds) return;
        const Vec<T, D> xi0 = load<D>(f.x0, i), ui = load<D>(f.u, i);
        const Mat<T, D> Fi = load_mat<D>(f.F, i);
        for (Offset k = family.begin(static_cast<Index>(i)); k < family.end(static_cast<Index>(i)); ++k) {
          if (damage && !f.bond_intact(k)) continue;
          const Index j = family.neighbor(k);
          const Vec<T, D> xi = load<D>(f.x0, j) - xi0, eta = load<D>(f.u, j) - ui;
          const T w = f.bond_weight(k);
          // Y - F xi = eta - (F - I) xi
          const Vec<T, D> z = eta - (Fi * xi - xi);
          acc[0] += double(w * norm2(z));
          acc[1] += double(w * norm2(eta));
        }
      });
  return {s[0], s[1]};
}

}  // namespace polymech::pd
