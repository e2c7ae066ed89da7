// The first bond pass of a NOSB step: shape tensor K_i, deformation gradient F_i (seed 003 eq. (1)),
// its rate, bond breakage and the damage field, and the neighbour-mean velocity of eq. (3), all from
// one gather over i's reference family (full list, fixed neighbour order: the result does not depend
// on the thread count).
//
//   K_i = sum_j omega W_ij xi (x) xi,    F_i = I + [sum_j omega W_ij (u_j - u_i) (x) xi] K_i^-1
//
// which is eq. (1), F = [sum omega (Y (x) xi) V_ij][sum omega (xi (x) xi) V_ij]^-1, with Y = xi + u_j - u_i
// split so that F - I is formed from displacement differences (no cancellation in float). omega is
// 1 for an intact bond and 0 for a broken one (seed 003 §3(1)); W_ij is V_ij or, with the
// weighted_function effect, W'_ij of eq. (2) (pd::BondWeight, stored per bond in Fields::bond_weight).
#pragma once

#include "pd/fields.hpp"

namespace polymech::pd {

template <class T>
struct DeformationParams {
  bool damage = false;          // damage effect: break bonds whose stretch exceeds critical_stretch
  T critical_stretch = T(0);
  bool rate = false;            // also dF/dt (rate-dependent laws)
  bool mean_velocity = false;   // velocity_viscosity effect: weighted mean velocity and V_H
  // A particle whose intact family cannot determine F (fewer than D + 1 intact bonds, or a shape
  // tensor with det K / (tr K / D)^D below this) is marked failed and carries no stress.
  T min_shape_quality = T(1e-4);
};

namespace detail {

// K scaled to unit mean eigenvalue, Ks = K / (tr K / D): K ~ V |xi|^2 x (bonds) is ~1e-13 m^5 at a
// 1 mm spacing, so det K (~1e-39) underflows single precision; quality and inverse come from Ks.
template <class T, int D>
KOKKOS_INLINE_FUNCTION T shape_quality_of_scaled(const Mat<T, D>& Ks) {
  return det(Ks);  // det K / (tr K / D)^D
}

}  // namespace detail

// The optional parts (bond tests, rate, mean velocity) are template flags so that the bond loop the
// compiler sees has no branches but the bond test itself.
template <class T, int D, bool Damage, bool Rate, bool Mean>
struct DeformationGradient {
  neighbors::BondFamily family;  // the rebuild pass of finish() walks the row again
  Fields<T, D> f;
  T sc, min_quality;
  struct Accumulator {
    Vec<T, D> xi0, ui, vi;
    bool broke;
    Mat<T, D> N;     // sum W (u_j - u_i) (x) xi
    Mat<T, D> Ndot;  // sum W (v_j - v_i) (x) xi
    Vec<T, D> vsum;
    T w_intact, w_all;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const {
    Accumulator acc{load<D>(f.x0, i), load<D>(f.u, i), Vec<T, D>::zero(), false, Mat<T, D>::zero(), Mat<T, D>::zero(),
                    Vec<T, D>::zero(), T(0), T(0)};
    if (Rate || Mean) acc.vi = load<D>(f.v, i);
    return acc;
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    const Vec<T, D> xi = load<D>(f.x0, j) - acc.xi0;
    const T w = f.bond_weight(k);
    if (Damage) {
      acc.w_all += w;
      if (!f.bond_intact(k)) return;
    }
    const Vec<T, D> eta = load<D>(f.u, j) - acc.ui;
    // stretch (|Y| - |xi|) / |xi| > sc  <=>  |Y|^2 > (1 + sc)^2 |xi|^2 (no square root); the
    // same test from j's side gives the same answer, so both halves of a bond break together
    if (Damage && norm2(xi + eta) > (T(1) + sc) * (T(1) + sc) * norm2(xi)) {
      f.bond_intact(k) = 0;
      acc.broke = true;
      return;
    }
    const Vec<T, D> wxi = w * xi;
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) acc.N.a[r][c] += eta[r] * wxi[c];
    if (Rate) {
      const Vec<T, D> dv = load<D>(f.v, j) - acc.vi;
      for (int r = 0; r < D; ++r)
        for (int c = 0; c < D; ++c) acc.Ndot.a[r][c] += dv[r] * wxi[c];
    }
    if (Mean) acc.vsum += w * load<D>(f.v, j);
    if (Damage || Mean) acc.w_intact += w;
  }
  // K_i changes only when one of i's bonds breaks: it is kept (as K^-1) between passes and rebuilt
  // from the intact bonds (a second pass over the row) when it is not known yet or a bond broke.
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const bool known = f.status(i) & status_shape_known;
    Mat<T, D> kinv;
    if (known && !acc.broke) {
      kinv = load_mat<D>(f.kinv, i);
    } else {
      auto K = Mat<T, D>::zero();
      int intact = 0;
      for (Offset k = family.begin(i); k < family.end(i); ++k) {
        if (Damage && !f.bond_intact(k)) continue;
        const Vec<T, D> xi = load<D>(f.x0, family.neighbor(k)) - acc.xi0;
        const T w = f.bond_weight(k);
        for (int r = 0; r < D; ++r)
          for (int c = 0; c < D; ++c) K.a[r][c] += w * xi[r] * xi[c];
        ++intact;
      }
      const T scale = trace(K) / T(D);
      const Mat<T, D> Ks = (scale > T(0) ? T(1) / scale : T(0)) * K;
      const bool ok = intact > D && scale > T(0) && detail::shape_quality_of_scaled(Ks) > min_quality;
      const bool crushed = f.status(i) & status_crushed;  // sticky (pd/stress.hpp)
      f.status(i) = std::uint8_t(status_shape_known | (ok && !crushed ? 0 : status_failed) | (crushed ? status_crushed : 0));
      kinv = ok ? (T(1) / scale) * inverse(Ks) : Mat<T, D>::zero();
      store_mat<D>(f.kinv, i, kinv);
    }
    store_mat<D>(f.F, i, Mat<T, D>::identity() + acc.N * kinv);
    if (Rate) store_mat<D>(f.Fdot, i, acc.Ndot * kinv);
    if (Damage) f.damage(i) = acc.w_all > T(0) ? T(1) - acc.w_intact / acc.w_all : T(0);
    if (Mean) {
      // seed 003 eq. (3): int_H omega v' dV' / int_H omega dV' (zero-weight families: own velocity)
      store<D>(f.vbar, i, acc.w_intact > T(0) ? (T(1) / acc.w_intact) * acc.vsum : acc.vi);
      f.horizon_weight(i) = acc.w_intact;
    }
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) {
    into.broke = into.broke || from.broke;
    into.N += from.N;
    into.Ndot += from.Ndot;
    into.vsum += from.vsum;
    into.w_intact += from.w_intact;
    into.w_all += from.w_all;
  }
};

template <class T, int D, bool Damage, bool Rate, bool Mean>
void deformation_gradient_pass(const neighbors::BondFamily& family, const Fields<T, D>& f, const DeformationParams<T>& p) {
  neighbors::for_each_row(Damage ? "polymech::pd::deformation_gradient_with_damage" : "polymech::pd::deformation_gradient",
                          family, DeformationGradient<T, D, Damage, Rate, Mean>{family, f, p.critical_stretch,
                                                                               p.min_shape_quality});
}

// Kernel "polymech::pd::deformation_gradient" (or "..._with_damage" when bonds are tested).
template <class T, int D>
void deformation_gradient(const neighbors::BondFamily& family, const Fields<T, D>& f, const DeformationParams<T>& p) {
  const int flags = (p.damage ? 4 : 0) | (p.rate ? 2 : 0) | (p.mean_velocity ? 1 : 0);
  switch (flags) {
    case 0: deformation_gradient_pass<T, D, false, false, false>(family, f, p); break;
    case 1: deformation_gradient_pass<T, D, false, false, true>(family, f, p); break;
    case 2: deformation_gradient_pass<T, D, false, true, false>(family, f, p); break;
    case 3: deformation_gradient_pass<T, D, false, true, true>(family, f, p); break;
    case 4: deformation_gradient_pass<T, D, true, false, false>(family, f, p); break;
    case 5: deformation_gradient_pass<T, D, true, false, true>(family, f, p); break;
    case 6: deformation_gradient_pass<T, D, true, true, false>(family, f, p); break;
    default: deformation_gradient_pass<T, D, true, true, true>(family, f, p); break;
  }
}

}  // namespace polymech::pd
