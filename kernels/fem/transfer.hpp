// Transfer between two discretizations of one mesh: y (+)= P x with a sparse real matrix P in CSR
// form, applied to real or complex vectors. The p-multigrid of models/helmholtz/pmg.hpp uses it for
// the prolongation from order q to a higher order (the coarse interpolant at the fine nodes) and for
// its transpose, the restriction.
#pragma once

#include "core/types.hpp"

namespace polymech::fem {

template <class T>
struct Transfer {
  Kokkos::View<Offset*, MemSpace> row_ptr;  // rows + 1
  View1<Index> cols;
  View1<T> weights;

  Index rows() const { return row_ptr.extent(0) > 0 ? static_cast<Index>(row_ptr.extent(0)) - 1 : 0; }

  // y = P x (Add = false) or y += P x (Add = true); rows without entries give 0.
  template <bool Add, class V>
  void apply(const View1<V>& x, const View1<V>& y) const {
    const auto rp = row_ptr;
    const auto c = cols;
    const auto w = weights;
    Kokkos::parallel_for(
        "polymech::fem::transfer", range(rows()), KOKKOS_LAMBDA(const Index i) {
          V s = V(0);
          for (Offset k = rp(i); k < rp(i + 1); ++k) s += w(k) * x(c(k));
          if (Add)
            y(i) += s;
          else
            y(i) = s;
        });
  }
};

}  // namespace polymech::fem
