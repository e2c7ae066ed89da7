// One-dimensional ingredients of the hexahedral Lagrange elements (seed 002 paper 3, §3(1), taken to
// order p): Gauss-Lobatto-Legendre (GLL) nodes, Gauss-Legendre quadrature, and the Lagrange basis
// through the nodes with its derivatives. The tensor products of these 1D factors are the element's
// shape functions N_i (eq. (13)) and their gradients (eq. (14)); for p = 1 they are eq. (22).
//
// Host functions compute the 1D rules in double; HexBasis<T, N, Q> carries the small matrices the
// kernels need by value (captured into device lambdas), with N = p + 1 nodes and Q points per direction.
#pragma once

#include <cmath>
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
