// Strong Dirichlet conditions (seed 002 paper 3 §3(2): the analytic values of eq. (27) imposed on the
// whole boundary). The constrained operator acts as the identity on constrained DoFs and as the
// operator on the free ones (columns of constrained DoFs removed), so it stays complex symmetric;
// the data enter the right-hand side as q - K g (the lifting) and as g on the constrained rows.
#pragma once

#include "core/types.hpp"

namespace polymech::fem {

// y(d) = x(d) for every constrained DoF d (the identity rows of the constrained operator).
template <class V>
void copy_constrained_rows(const View1<Index>& constrained, const View1<V>& x, const View1<V>& y) {
  Kokkos::parallel_for(
      "polymech::fem::dirichlet_rows", range(static_cast<Index>(constrained.extent(0))),
      KOKKOS_LAMBDA(const Index k) { y(constrained(k)) = x(constrained(k)); });
}

// x(d) = g(k) for the k-th constrained DoF d.
template <class V>
void set_constrained_values(const View1<Index>& constrained, const View1<V>& g, const View1<V>& x) {
  Kokkos::parallel_for(
      "polymech::fem::dirichlet_values", range(static_cast<Index>(constrained.extent(0))),
      KOKKOS_LAMBDA(const Index k) { x(constrained(k)) = g(k); });
}

// x(d) = value for every constrained DoF d (unit rows of the operator diagonal).
template <class V>
void fill_constrained(const View1<Index>& constrained, V value, const View1<V>& x) {
  Kokkos::parallel_for(
      "polymech::fem::dirichlet_fill", range(static_cast<Index>(constrained.extent(0))),
      KOKKOS_LAMBDA(const Index k) { x(constrained(k)) = value; });
}

}  // namespace polymech::fem
