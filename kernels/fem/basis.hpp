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
#include "fem/orders.hpp"

namespace polymech::fem {

namespace detail {

// Legendre polynomial P_n(x) and its derivative, by the three-term recurrence.
inline void legendre(int n, double x, double& p, double& dp) {
  double p0 = 1.0, p1 = x;
  if (n == 0) {
    p = 1.0;
    dp = 0.0;
    return;
  }
  for (int k = 2; k <= n; ++k) {
    const double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
    p0 = p1;
    p1 = pk;
  }
  p = p1;
  // P_n'(x) = n (x P_n - P_{n-1}) / (x^2 - 1), used away from x = +-1 only
  dp = n * (x * p1 - p0) / (x * x - 1.0);
}

// Makes a symmetric rule exactly symmetric: x[n-1-i] = -x[i] bit for bit, so that nodes of
// neighbouring elements seen from either side coincide exactly (the DoF numbering relies on it).
inline void symmetrize(std::vector<double>& x, std::vector<double>* w = nullptr) {
  const int n = static_cast<int>(x.size());
  for (int i = 0; i < n / 2; ++i) {
    const double a = 0.5 * (x[n - 1 - i] - x[i]);
    x[i] = -a;
    x[n - 1 - i] = a;
    if (w) {
      const double b = 0.5 * ((*w)[i] + (*w)[n - 1 - i]);
      (*w)[i] = (*w)[n - 1 - i] = b;
    }
  }
  if (n % 2 == 1) x[n / 2] = 0.0;
}

}  // namespace detail

// Gauss-Legendre points and weights on [-1, 1]: n points integrate polynomials of degree 2n - 1 exactly.
inline void gauss_legendre(int n, std::vector<double>& x, std::vector<double>& w) {
  if (n < 1) throw std::invalid_argument("gauss_legendre: n = " + std::to_string(n) + " must be >= 1");
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) {
    double t = -std::cos(pi * (i + 0.75) / (n + 0.5));  // Chebyshev-like start, ascending order
    double p = 0.0, dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      detail::legendre(n, t, p, dp);
      const double dt = p / dp;
      t -= dt;
      if (std::abs(dt) < 1e-16) break;
    }
    detail::legendre(n, t, p, dp);
    x[i] = t;
    w[i] = 2.0 / ((1.0 - t * t) * dp * dp);
  }
  detail::symmetrize(x, &w);
}

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
