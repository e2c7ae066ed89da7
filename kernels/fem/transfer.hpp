// Transfer between two discretizations of one mesh: y (+)= P x with a sparse real matrix P (CSR, real
// weights) applied to real or complex vectors. The p-multigrids of models/helmholtz/preconditioners.hpp
// and models/solid/two_level.hpp use it for the prolongation from order q to a higher order (the coarse
// interpolant at the fine nodes) and for its transpose, the restriction.
#pragma once

#include <utility>
#include <vector>

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

// The transfer whose row r holds the (column, weight) pairs rows[r] (host lists, copied to the device).
template <class T>
Transfer<T> make_transfer(const std::vector<std::vector<std::pair<Index, double>>>& rows) {
  Transfer<T> t;
  auto& P = t.matrix;
  P.row_ptr = Kokkos::View<Offset*, MemSpace>("polymech::fem::transfer_rows", rows.size() + 1);
  Offset nnz = 0;
  for (const auto& r : rows) nnz += static_cast<Offset>(r.size());
  P.cols = View1<Index>("polymech::fem::transfer_cols", nnz);
  P.values = View1<T>("polymech::fem::transfer_weights", nnz);
  auto hr = Kokkos::create_mirror_view(P.row_ptr);
  auto hc = Kokkos::create_mirror_view(P.cols);
  auto hw = Kokkos::create_mirror_view(P.values);
  Offset at = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    hr(r) = at;
    for (const auto& [col, w] : rows[r]) {
      hc(at) = col;
      hw(at) = static_cast<T>(w);
      ++at;
    }
  }
  hr(rows.size()) = at;
  Kokkos::deep_copy(P.row_ptr, hr);
  Kokkos::deep_copy(P.cols, hc);
  Kokkos::deep_copy(P.values, hw);
  return t;
}

}  // namespace polymech::fem
