// A sparse matrix in CSR form with a Kokkos matrix-vector product: the assembled counterpart of the
// matrix-free operator (benchmarks compare their time and memory), an operator for the solvers, and
// (real values on complex vectors) the order transfers of the p-multigrid.
#pragma once

#include "core/types.hpp"

namespace polymech::fem {

template <class V>
struct CsrMatrix {
  Kokkos::View<Offset*, MemSpace> row_ptr;  // rows + 1
  View1<Index> cols;
  View1<V> values;

  using value_type = V;
  Index rows() const { return row_ptr.extent(0) > 0 ? static_cast<Index>(row_ptr.extent(0)) - 1 : 0; }
  Offset nonzeros() const { return static_cast<Offset>(cols.extent(0)); }
  std::size_t bytes() const {
    return row_ptr.extent(0) * sizeof(Offset) + cols.extent(0) * sizeof(Index) + values.extent(0) * sizeof(V);
  }
  // Operator concept (kernels/solvers/krylov.hpp).
  Index local_size() const { return rows(); }
  Index owned_size() const { return rows(); }
  void apply(const View1<V>& x, const View1<V>& y) const { multiply<false>("polymech::fem::csr_apply", x, y); }

  // y = A x (Add = false) or y += A x, for vectors of any type X that V times X makes (real weights
  // on complex vectors: the order transfers of the p-multigrid).
  template <bool Add, class X>
  void multiply(const char* label, const View1<X>& x, const View1<X>& y) const {
    const auto rp = row_ptr;
    const auto c = cols;
    const auto v = values;
    Kokkos::parallel_for(
        label, range(rows()), KOKKOS_LAMBDA(const Index i) {
          X s = X(0);
          for (Offset k = rp(i); k < rp(i + 1); ++k) s += v(k) * x(c(k));
          if (Add)
            y(i) += s;
          else
            y(i) = s;
        });
  }
};

}  // namespace polymech::fem
