// One-dimensional ingredients of the hexahedral Lagrange elements (seed 002 paper 3, §3(1), taken to
// order p): Gauss-Lobatto-Legendre (GLL) nodes, Gauss-Legendre quadrature, and the Lagrange basis
// through the nodes with its derivatives. The tensor products of these 1D factors are the element's
// shape functions N_i (eq. (13)) and their gradients (eq. (14)); for p = 1 they are eq. (22).
//
// Host functions compute the 1D rules in double; HexBasis<T, N, Q> carries the small matrices the
// kernels need by value (captured into device lambdas), with N = p + 1 nodes and Q points per direction.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/kokkos_shim.hpp"
#include "fem/gauss_legendre.hpp"
#include "fem/orders.hpp"

namespace polymech::fem {

// Gauss-Lobatto-Legendre nodes on [-1, 1]: the endpoints and the roots of P'_{n-1}; n >= 2.
inline std::vector<double> gauss_lobatto_nodes(int n) {
  if (n < 2) throw std::invalid_argument("gauss_lobatto_nodes: n = " + std::to_string(n) + " must be >= 2");
  std::vector<double> x(n);
  x[0] = -1.0;
  x[n - 1] = 1.0;
  const int m = n - 1;  // interior nodes: roots of P_m'
  const double pi = 3.14159265358979323846;
  for (int i = 1; i < m; ++i) {
    double t = -std::cos(pi * i / m);
    for (int it = 0; it < 100; ++it) {
      // Newton on P_m'(t): P_m'' = (2 t P_m' - m (m + 1) P_m) / (1 - t^2)
      double p = 0.0, dp = 0.0;
      detail::legendre(m, t, p, dp);
      const double d2p = (2.0 * t * dp - m * (m + 1.0) * p) / (1.0 - t * t);
      const double dt = dp / d2p;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    x[i] = t;
  }
  detail::symmetrize(x);
  return x;
}

// Value of the Lagrange polynomial l_i through `nodes` at x.
inline double lagrange(const std::vector<double>& nodes, int i, double x) {
  double v = 1.0;
  for (int m = 0; m < static_cast<int>(nodes.size()); ++m)
    if (m != i) v *= (x - nodes[m]) / (nodes[i] - nodes[m]);
  return v;
}

// Derivative of l_i at x (product rule; exact at the nodes too).
inline double lagrange_derivative(const std::vector<double>& nodes, int i, double x) {
  const int n = static_cast<int>(nodes.size());
  double s = 0.0;
  for (int k = 0; k < n; ++k) {
    if (k == i) continue;
    double v = 1.0 / (nodes[i] - nodes[k]);
    for (int m = 0; m < n; ++m)
      if (m != i && m != k) v *= (x - nodes[m]) / (nodes[i] - nodes[m]);
    s += v;
  }
  return s;
}

// The 1D basis of the GLL-node Lagrange element of order n - 1 tabulated at the n Gauss points, for the host
// assemblies that evaluate the full tensor-product basis point by point (the solid stiffness and mass, the
// piezoelectric matrices): value[q n + i] = l_i(x_q), derivative[q n + i] = l_i'(x_q), weights[q].
struct GaussTables {
  int n = 0;
  std::vector<double> weights, value, derivative;
};
inline GaussTables gauss_tables(int n) {
  GaussTables t;
  t.n = n;
  const std::vector<double> nodes = gauss_lobatto_nodes(n);
  std::vector<double> xq;
  gauss_legendre(n, xq, t.weights);
  t.value.resize(static_cast<std::size_t>(n) * n);
  t.derivative.resize(t.value.size());
  for (int q = 0; q < n; ++q)
    for (int i = 0; i < n; ++i) {
      t.value[static_cast<std::size_t>(q) * n + i] = lagrange(nodes, i, xq[q]);
      t.derivative[static_cast<std::size_t>(q) * n + i] = lagrange_derivative(nodes, i, xq[q]);
    }
  return t;
}

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

// The 1D factors of an order N-1 hexahedral element evaluated at Q Gauss points per direction:
//   B[q][i]  = l_i(x_q)          values of the nodal basis (interpolation nodes -> points)
//   D[q][i]  = l_i'(x_q)         derivatives of the nodal basis at the points
//   Dq[q][r] = g_r'(x_q)         collocation derivative: g_r is the Lagrange polynomial through the
//                                points; exact on the interpolant of degree N - 1 <= Q - 1
//   Dn[a][i] = l_i'(x_a)         derivatives at the nodes (Jacobian checks at the nodes)
//   w[q]                         Gauss weights; x[q] the points; nodes[i] the GLL nodes
template <class T, int N, int Q>
struct HexBasis {
  static_assert(N >= 2 && Q >= N, "need N >= 2 nodes and Q >= N points per direction");
  T B[Q][N];
  T D[Q][N];
  T Dq[Q][Q];
  T Dn[N][N];
  T w[Q];
  T x[Q];
  T nodes[N];
};

template <class T, int N, int Q>
HexBasis<T, N, Q> make_hex_basis() {
  const std::vector<double> nodes = gauss_lobatto_nodes(N);
  std::vector<double> xq, wq;
  gauss_legendre(Q, xq, wq);
  HexBasis<T, N, Q> b{};
  for (int q = 0; q < Q; ++q) {
    b.w[q] = static_cast<T>(wq[q]);
    b.x[q] = static_cast<T>(xq[q]);
    for (int i = 0; i < N; ++i) {
      b.B[q][i] = static_cast<T>(lagrange(nodes, i, xq[q]));
      b.D[q][i] = static_cast<T>(lagrange_derivative(nodes, i, xq[q]));
    }
    for (int r = 0; r < Q; ++r) b.Dq[q][r] = static_cast<T>(lagrange_derivative(xq, r, xq[q]));
  }
  for (int a = 0; a < N; ++a) {
    b.nodes[a] = static_cast<T>(nodes[a]);
    for (int i = 0; i < N; ++i) b.Dn[a][i] = static_cast<T>(lagrange_derivative(nodes, i, nodes[a]));
  }
  return b;
}

}  // namespace polymech::fem
