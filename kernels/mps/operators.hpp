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

// One functor for the four operators: the pair term of each, summed over the row, scaled by c.
enum class Operator { gradient, divergence, divergence_of_isotropic, laplacian };

template <class T, int D, Operator Op>
struct OperatorRow {
  VecView<T, D> x, x0;
  View1<T> phi;      // scalar input (gradient, divergence_of_isotropic, laplacian)
  VecView<T, D> psi;  // vector input (divergence)
  View1<T> out_scalar;
  VecView<T, D> out_vector;
  T re, c;
  static constexpr bool vector_result = Op == Operator::gradient || Op == Operator::divergence_of_isotropic;
  struct Accumulator {
    Vec<T, D> g;
    T s;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {Vec<T, D>::zero(), T(0)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    const auto pg = pair_geometry<T, D>(x, x0, i, j, re);
    if constexpr (Op == Operator::laplacian) {
      acc.s += (phi(j) - phi(i)) * pg.w / (pg.r0_len * pg.r0_len);
    } else {
      if (pg.w == T(0)) return;
      if constexpr (Op == Operator::gradient) acc.g += ((phi(j) - phi(i)) * pg.w / (pg.r0_len * pg.r_len)) * pg.r;
      if constexpr (Op == Operator::divergence_of_isotropic)
        acc.g += ((phi(j) + phi(i)) * pg.w / (pg.r0_len * pg.r_len)) * pg.r;
      if constexpr (Op == Operator::divergence)
        acc.s += dot(load<D>(psi, j) - load<D>(psi, i), pg.r) * pg.w / (pg.r0_len * pg.r_len);
    }
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    if constexpr (vector_result)
      store<D>(out_vector, i, c * acc.g);
    else
      out_scalar(i) = c * acc.s;
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) {
    into.g += from.g;
    into.s += from.s;
  }
};

// seed 000 eq. (3): <grad phi>_i = d/n0 sum (phi_j - phi_i) r_ij / (|r0_ij| |r_ij|) w.
template <class T, int D>
void gradient(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
              const View1<T>& phi, OperatorParams p, const VecView<T, D>& grad) {
  neighbors::for_each_row("polymech::mps::gradient", family,
                          OperatorRow<T, D, Operator::gradient>{x, x0, phi, {}, {}, grad, static_cast<T>(p.re),
                                                                static_cast<T>(D / p.n0)});
}

// seed 000 eq. (4) with the difference (psi_j - psi_i): the divergence of a vector field such as a
// displacement, exact for linear fields at particles with a full neighbourhood.
template <class T, int D>
void divergence(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
                const VecView<T, D>& psi, OperatorParams p, const View1<T>& div) {
  neighbors::for_each_row("polymech::mps::divergence", family,
                          OperatorRow<T, D, Operator::divergence>{x, x0, {}, psi, div, {}, static_cast<T>(p.re),
                                                                  static_cast<T>(D / p.n0)});
}

// seed 000 eq. (4) as printed, with the sum (psi_j + psi_i), applied to psi = phi I:
// <div(phi I)>_i = d/n0 sum (phi_j + phi_i) r_ij / (|r0_ij| |r_ij|) w. Pair contributions are
// antisymmetric, so the force it gives conserves linear momentum (the form eq. (11) uses).
template <class T, int D>
void divergence_of_isotropic(const neighbors::NeighborList& family, const VecView<T, D>& x,
                             const VecView<T, D>& x0, const View1<T>& phi, OperatorParams p,
                             const VecView<T, D>& out) {
  neighbors::for_each_row("polymech::mps::divergence_of_isotropic", family,
                          OperatorRow<T, D, Operator::divergence_of_isotropic>{x, x0, phi, {}, {}, out,
                                                                               static_cast<T>(p.re),
                                                                               static_cast<T>(D / p.n0)});
}

// seed 000 eq. (5): <lap phi>_i = 2d/n0 sum (phi_j - phi_i) / |r0_ij|^2 w.
template <class T, int D>
void laplacian(const neighbors::NeighborList& family, const VecView<T, D>& x, const VecView<T, D>& x0,
               const View1<T>& phi, OperatorParams p, const View1<T>& lap) {
  neighbors::for_each_row("polymech::mps::laplacian", family,
                          OperatorRow<T, D, Operator::laplacian>{x, x0, phi, {}, lap, {}, static_cast<T>(p.re),
                                                                 static_cast<T>(2 * D / p.n0)});
}

}  // namespace polymech::mps
