// Transfer between two discretizations of one mesh: y (+)= P x with a sparse real matrix P (CSR, real
// weights) applied to complex vectors. The p-multigrid of models/helmholtz/preconditioners.hpp uses it
// for the prolongation from order q to a higher order (the coarse interpolant at the fine nodes) and
// for its transpose, the restriction.
#pragma once

#include "fem/csr.hpp"

namespace polymech::fem {

template <class T>
struct Transfer {
  CsrMatrix<T> matrix;

  Index rows() const { return matrix.rows(); }
  // y = P x (Add = false) or y += P x (Add = true); rows without entries give 0.
  template <bool Add, class V>
  void apply(const View1<V>& x, const View1<V>& y) const {
    matrix.template multiply<Add>("polymech::fem::transfer", x, y);
  }
};

}  // namespace polymech::fem
