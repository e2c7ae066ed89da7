// The assembled stiffness matrix of the small-strain solid (issue 34), host, double: element matrices
//   K_e[(a, c), (b, d)] = sum_q w_q det J  dN_a/dx_j  C_cjdl  dN_b/dx_l
// by direct evaluation of the full tensor-product basis at the Gauss points, the Jacobian formed and inverted
// point by point: no sum factorization and no stored geometry, so the matrix-free operator can be checked
// against it (tests/solid). It feeds the host sparse LU (kernels/solvers/host_sparse_lu.hpp) and, as CSR
// (fem::CsrMatrix), the assembled matrix-vector product. Rows and columns of constrained DoFs are replaced
// by the identity, as ElasticOperator does. O(N^(3D)) per element: for small and moderate meshes.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "fem/basis.hpp"
#include "fem/point_basis.hpp"
#include "fem/csr.hpp"
#include "materials/voigt.hpp"

namespace polymech::solid {

// Coordinate form of a sparse matrix (repeated entries are summed by the consumers).
struct Triplets {
  std::int64_t n = 0;
  std::vector<std::int64_t> rows, cols;
  std::vector<double> values;
};

// What the assembly reads, on the host: element node table (elements x N^D, node ids, not encoded), node
// coordinates (nodes x D), one Voigt stiffness per element (elements x 36) or, when point_material is given,
// one per quadrature point (elements x Q^D x 36, q = i + Q (j + Q k) as the kernels number the points: a
// nonlinear law's consistent tangent, PointStiffness), and the constrained DoFs' flags.
struct AssemblyInput {
  int dim = 3, order = 1;
  std::vector<std::int64_t> element_nodes;
  std::vector<double> coordinates;
  std::vector<double> material;
  std::vector<double> point_material;  // non-empty: a C per point, `material` is not read
  std::vector<char> constrained;  // per DoF (D node + c)
};

inline Triplets assemble_stiffness(const AssemblyInput& in) {
  const int D = in.dim, N = in.order + 1, Q = N;
  const int ND = D == 3 ? N * N * N : N * N, S = D == 3 ? 6 : 3;
  const fem::GaussTables tables = fem::gauss_tables(N);  // Q = N: l_i(x_q), l_i'(x_q), w_q
  const std::int64_t ne = static_cast<std::int64_t>(in.element_nodes.size()) / ND;
  const std::int64_t ndof = static_cast<std::int64_t>(in.constrained.size());
  auto voigt = [&](int s) { return D == 3 ? s : (s == 2 ? 5 : s); };
  auto pair = [&](int i, int j) { return i == j ? i : (D == 3 ? 6 - i - j : 2); };
  Triplets t;
  t.n = ndof;
  std::vector<double> grad(static_cast<std::size_t>(ND) * D), Ke;
  for (std::int64_t e = 0; e < ne; ++e) {
    const std::int64_t* en = &in.element_nodes[static_cast<std::size_t>(e) * ND];
    const int QD = D == 3 ? Q * Q * Q : Q * Q;
    const bool per_point = !in.point_material.empty();
    double C[6][6];
    auto load_material = [&](const double* m) {
      for (int i = 0; i < S; ++i)
        for (int j = 0; j < S; ++j) C[i][j] = m[6 * voigt(i) + voigt(j)];
    };
    if (!per_point) load_material(&in.material[static_cast<std::size_t>(e) * 36]);
    Ke.assign(static_cast<std::size_t>(ND * D) * (ND * D), 0.0);
    for (int q = 0; q < QD; ++q) {
      if (per_point) load_material(&in.point_material[(static_cast<std::size_t>(e) * QD + q) * 36]);
      double w;
      const double det = fem::tensor_point(tables, D, q, en, in.coordinates, nullptr, grad.data(), w);
      const double wd = w * det;
      for (int a = 0; a < ND; ++a)
        for (int c = 0; c < D; ++c)
          for (int b = 0; b < ND; ++b)
            for (int d = 0; d < D; ++d) {
              double s = 0.0;
              for (int j = 0; j < D; ++j)
                for (int l = 0; l < D; ++l)
                  s += grad[static_cast<std::size_t>(a) * D + j] * C[pair(c, j)][pair(d, l)] *
                       grad[static_cast<std::size_t>(b) * D + l];
              Ke[static_cast<std::size_t>(a * D + c) * (ND * D) + (b * D + d)] += wd * s;
            }
    }
    for (int a = 0; a < ND; ++a)
      for (int c = 0; c < D; ++c) {
        const std::int64_t r = D * en[a] + c;
        if (in.constrained[r]) continue;
        for (int b = 0; b < ND; ++b)
          for (int d = 0; d < D; ++d) {
            const std::int64_t col = D * en[b] + d;
            if (in.constrained[col]) continue;
            t.rows.push_back(r);
            t.cols.push_back(col);
            t.values.push_back(Ke[static_cast<std::size_t>(a * D + c) * (ND * D) + (b * D + d)]);
          }
      }
  }
  for (std::int64_t i = 0; i < ndof; ++i)
    if (in.constrained[i]) {
      t.rows.push_back(i);
      t.cols.push_back(i);
      t.values.push_back(1.0);
    }
  return t;
}

// CSR on the device in precision T (repeated entries summed, columns sorted per row).
template <class T>
fem::CsrMatrix<T> to_csr(const Triplets& t) {
  std::vector<std::size_t> order(t.values.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return t.rows[a] != t.rows[b] ? t.rows[a] < t.rows[b] : t.cols[a] < t.cols[b];
  });
  std::vector<Offset> rp(static_cast<std::size_t>(t.n) + 1, 0);
  std::vector<Index> cols;
  std::vector<double> vals;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (k > 0 && t.rows[i] == t.rows[order[k - 1]] && t.cols[i] == t.cols[order[k - 1]]) {
      vals.back() += t.values[i];
      continue;
    }
    cols.push_back(static_cast<Index>(t.cols[i]));
    vals.push_back(t.values[i]);
    ++rp[static_cast<std::size_t>(t.rows[i]) + 1];
  }
  for (std::size_t r = 0; r + 1 < rp.size(); ++r) rp[r + 1] += rp[r];
  fem::CsrMatrix<T> m;
  m.row_ptr = Kokkos::View<Offset*, MemSpace>("polymech::solid::csr_rows", rp.size());
  m.cols = View1<Index>("polymech::solid::csr_cols", cols.size());
  m.values = View1<T>("polymech::solid::csr_values", vals.size());
  auto rh = Kokkos::create_mirror_view(m.row_ptr);
  auto ch = Kokkos::create_mirror_view(m.cols);
  auto vh = Kokkos::create_mirror_view(m.values);
  for (std::size_t k = 0; k < rp.size(); ++k) rh(k) = rp[k];
  for (std::size_t k = 0; k < cols.size(); ++k) {
    ch(k) = cols[k];
    vh(k) = static_cast<T>(vals[k]);
  }
  Kokkos::deep_copy(m.row_ptr, rh);
  Kokkos::deep_copy(m.cols, ch);
  Kokkos::deep_copy(m.values, vh);
  return m;
}

}  // namespace polymech::solid
