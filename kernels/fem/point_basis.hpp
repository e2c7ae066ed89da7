// The direct evaluation of a tensor-product Lagrange element at one Gauss point, for the host assemblies that
// form element matrices point by point (kernels/solid/assembly.hpp: stiffness and mass; models/piezo/assembly.hpp)
// rather than by sum factorization; the tables are fem::gauss_tables (basis.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "fem/basis.hpp"

namespace polymech::fem {

// The tensor-product basis of a D-dimensional element at its Gauss point q (q = i + n (j + n k)), evaluated
// directly from the tables: the values val[a] (when val is non-null) and the physical gradients
// grad[a D + j] = dN_a/dx_j of the n^D nodes a = i + n (j + n k), whose coordinates are x[D en[a] + c]; the
// Jacobian J = sum_a x_a (x) grad_ref N_a is formed and inverted at the point. Returns det J (<= 0: an inverted
// element; the gradients are then meaningless) and the point's weight in `weight`.
inline double tensor_point(const GaussTables& t, int D, int q, const std::int64_t* en, const std::vector<double>& x,
                           double* val, double* grad, double& weight) {
  const int n = t.n, nd = D == 3 ? n * n * n : n * n;
  const int qi[3] = {q % n, (q / n) % n, q / (n * n)};
  weight = 1.0;
  for (int d = 0; d < D; ++d) weight *= t.weights[static_cast<std::size_t>(qi[d])];
  double J[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int a = 0; a < nd; ++a) {
    const int ai[3] = {a % n, (a / n) % n, a / (n * n)};
    if (val) {
      double v = 1.0;
      for (int d = 0; d < D; ++d) v *= t.value[static_cast<std::size_t>(qi[d]) * n + ai[d]];
      val[a] = v;
    }
    for (int r = 0; r < D; ++r) {
      double g = 1.0;
      for (int d = 0; d < D; ++d) g *= (d == r ? t.derivative : t.value)[static_cast<std::size_t>(qi[d]) * n + ai[d]];
      grad[static_cast<std::size_t>(a) * D + r] = g;
      for (int c = 0; c < D; ++c) J[c][r] += x[static_cast<std::size_t>(D * en[a] + c)] * g;
    }
  }
  double det, Ji[3][3];
  if (D == 2) {
    det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    Ji[0][0] = J[1][1] / det;
    Ji[0][1] = -J[0][1] / det;
    Ji[1][0] = -J[1][0] / det;
    Ji[1][1] = J[0][0] / det;
  } else {
    det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
          J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {  // adjugate: cofactor of (j, i)
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        Ji[i][j] = (J[r0][c0] * J[r1][c1] - J[r0][c1] * J[r1][c0]) / det;
      }
  }
  for (int a = 0; a < nd; ++a) {  // physical gradients, in place
    double g[3] = {0, 0, 0};
    for (int j = 0; j < D; ++j)
      for (int r = 0; r < D; ++r) g[j] += grad[static_cast<std::size_t>(a) * D + r] * Ji[r][j];
    for (int j = 0; j < D; ++j) grad[static_cast<std::size_t>(a) * D + j] = g[j];
  }
  return det;
}

}  // namespace polymech::fem
