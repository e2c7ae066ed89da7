// MPS particle-interaction models (seed 000 eqs. (3)-(5)): gradient, divergence and Laplacian of
// particle fields over a reference neighbour family, with the initial distances |r0_ij| in the
// denominators and the weight at the current distance, as the paper writes them.
//
// These general operators serve tests and diagnostics; the elastic model fuses the same formulas
// into its force kernel (kernels/mps/elastic.hpp) so one pass over the pairs does all the work.
#pragma once

#include "mps/weight.hpp"

namespace polymech::mps {

// Geometry of one pair in the current (x) and reference (x0) configurations.
template <class T, int D>
struct PairGeometry {
  Vec<T, D> r;   // r_ij = x_j - x_i
  T r_len;       // |r_ij|
  T r0_len;      // |r0_ij|
  T w;           // w(|r_ij|), eq. (1)
};

template <class T, int D, class XView>
KOKKOS_INLINE_FUNCTION PairGeometry<T, D> pair_geometry(const XView& x, const XView& x0, Index i, Index j, T re) {
  PairGeometry<T, D> g;
  g.r = load<D>(x, j) - load<D>(x, i);
  g.r_len = norm(g.r);
  g.r0_len = norm(load<D>(x0, j) - load<D>(x0, i));
  g.w = weight(g.r_len, re);
  return g;
}

struct OperatorParams {
  double re = 0.0;  // influence radius
  double n0 = 0.0;  // reference number density
};

// seed 000 eq. (3): <grad phi>_i = d/n0 sum (phi_j - phi_i) r_ij / (|r0_ij| |r_ij|) w.
template <class T, int D>
void gradient(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
              const View1<T>& phi, OperatorParams p, const VecView<T, D>& grad) {
  const T re = static_cast<T>(p.re), c = static_cast<T>(D / p.n0);
  Kokkos::parallel_for(
      "polymech::mps::gradient", range(family.num_particles), KOKKOS_LAMBDA(const Index i) {
        auto g = Vec<T, D>::zero();
        for (Offset k = family.begin(i); k < family.end(i); ++k) {
          const Index j = family.neighbor(k);
          const auto pg = pair_geometry<T, D>(x, x0, i, j, re);
          if (pg.w == T(0)) continue;
          g += ((phi(j) - phi(i)) * pg.w / (pg.r0_len * pg.r_len)) * pg.r;
        }
        store<D>(grad, i, c * g);
      });
}

// seed 000 eq. (4) with the difference (psi_j - psi_i): the divergence of a vector field such as a
// displacement, exact for linear fields at particles with a full neighbourhood.
template <class T, int D>
void divergence(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
                const VecView<T, D>& psi, OperatorParams p, const View1<T>& div) {
  const T re = static_cast<T>(p.re), c = static_cast<T>(D / p.n0);
  Kokkos::parallel_for(
      "polymech::mps::divergence", range(family.num_particles), KOKKOS_LAMBDA(const Index i) {
        T s = T(0);
        for (Offset k = family.begin(i); k < family.end(i); ++k) {
          const Index j = family.neighbor(k);
          const auto pg = pair_geometry<T, D>(x, x0, i, j, re);
          if (pg.w == T(0)) continue;
          s += dot(load<D>(psi, j) - load<D>(psi, i), pg.r) * pg.w / (pg.r0_len * pg.r_len);
        }
        div(i) = c * s;
      });
}

// seed 000 eq. (4) as printed, with the sum (psi_j + psi_i), applied to psi = phi I:
// <div(phi I)>_i = d/n0 sum (phi_j + phi_i) r_ij / (|r0_ij| |r_ij|) w. Pair contributions are
// antisymmetric, so the force it gives conserves linear momentum (the form eq. (11) uses).
template <class T, int D>
void divergence_of_isotropic(const neighbors::NeighborList& family, const VecView<T, D>& x,
                             const VecView<T, D>& x0, const View1<T>& phi, OperatorParams p,
                             const VecView<T, D>& out) {
  const T re = static_cast<T>(p.re), c = static_cast<T>(D / p.n0);
  Kokkos::parallel_for(
      "polymech::mps::divergence_of_isotropic", range(family.num_particles), KOKKOS_LAMBDA(const Index i) {
        auto g = Vec<T, D>::zero();
        for (Offset k = family.begin(i); k < family.end(i); ++k) {
          const Index j = family.neighbor(k);
          const auto pg = pair_geometry<T, D>(x, x0, i, j, re);
          if (pg.w == T(0)) continue;
          g += ((phi(j) + phi(i)) * pg.w / (pg.r0_len * pg.r_len)) * pg.r;
        }
        store<D>(out, i, c * g);
      });
}

// seed 000 eq. (5): <lap phi>_i = 2d/n0 sum (phi_j - phi_i) / |r0_ij|^2 w.
template <class T, int D>
void laplacian(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
               const View1<T>& phi, OperatorParams p, const View1<T>& lap) {
  const T re = static_cast<T>(p.re), c = static_cast<T>(2 * D / p.n0);
  Kokkos::parallel_for(
      "polymech::mps::laplacian", range(family.num_particles), KOKKOS_LAMBDA(const Index i) {
        T s = T(0);
        for (Offset k = family.begin(i); k < family.end(i); ++k) {
          const Index j = family.neighbor(k);
          const auto pg = pair_geometry<T, D>(x, x0, i, j, re);
          s += (phi(j) - phi(i)) * pg.w / (pg.r0_len * pg.r0_len);
        }
        lap(i) = c * s;
      });
}

}  // namespace polymech::mps
