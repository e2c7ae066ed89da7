// The Gauss-Legendre rule on [-1, 1] (host, double), shared by the hexahedral elements (fem/basis.hpp)
// and the element-free Galerkin background cells and J-integral paths (models/efg): Newton on the
// Legendre polynomial P_n from Chebyshev-like starts, the nodes made exactly symmetric. Kokkos-free, so
// that set-up code compiled without Kokkos (models/*/setup.cpp) can include it.
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

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

}  // namespace polymech::fem
