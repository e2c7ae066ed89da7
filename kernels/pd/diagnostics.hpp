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
#include "particles/reductions.hpp"

namespace polymech::pd {

struct NonAffineMeasure {
  double nonaffine = 0.0;  // sum W |Y - F xi|^2
  double total = 0.0;      // sum W |Y - xi|^2
  double ratio() const { return total > 0 ? std::sqrt(nonaffine / total) : 0.0; }
};

// sum_j W |Y - F_i xi|^2 and sum_j W |Y - xi|^2 over the intact bonds of i (in double).
template <class T, int D>
struct NonAffineRow {
  Fields<T, D> f;
  bool damage;
  struct Accumulator {
    Vec<T, D> xi0, ui;
    Mat<T, D> Fi;
    double nonaffine, total;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const {
    return {load<D>(f.x0, i), load<D>(f.u, i), load_mat<D>(f.F, i), 0.0, 0.0};
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    if (damage && !f.bond_intact(k)) return;
    const Vec<T, D> xi = load<D>(f.x0, j) - acc.xi0, eta = load<D>(f.u, j) - acc.ui;
    const T w = f.bond_weight(k);
    // Y - F xi = eta - (F - I) xi
    const Vec<T, D> z = eta - (acc.Fi * xi - xi);
    acc.nonaffine += double(w * norm2(z));
    acc.total += double(w * norm2(eta));
  }
};

// Kernel "polymech::pd::nonaffine_deviation" (intact bonds; F from the last deformation pass).
template <class T, int D>
NonAffineMeasure nonaffine_deviation(const neighbors::BondFamily& family, const Fields<T, D>& f, Index min_bonds = 0) {
  const NonAffineRow<T, D> row{f, f.bond_intact.extent(0) > 0};
  const auto s = particles::ordered_sum<2>(
      "polymech::pd::nonaffine_deviation", family.num_particles, KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        const auto p = static_cast<Index>(i);
        if (family.count(p) < min_bonds) return;
        auto sums = row.start(p);
        sums.nonaffine = acc[0];
        sums.total = acc[1];
        neighbors::gather_row(family, p, row, sums);
        acc[0] = sums.nonaffine;
        acc[1] = sums.total;
      });
  return {s[0], s[1]};
}

}  // namespace polymech::pd
