// Distribution functions of the least-squares estimator's confidence intervals (issue 34; seed 002 paper 5
// section 5): the regularised incomplete beta function and the two-sided quantile of the standard normal
// (noise known) or Student's t distribution (noise estimated, m - rank degrees of freedom). Host-only.
#pragma once

#include <cmath>

namespace polymech::estimation {

namespace detail {

// Regularised incomplete beta I_x(a, b) by its continued fraction (modified Lentz).
inline double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double ln_front = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - incomplete_beta(b, a, 1.0 - x);
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double f = d;
  for (int k = 1; k < 500; ++k) {
    for (int parity = 0; parity < 2; ++parity) {
      const double num = parity == 0 ? k * (b - k) * x / ((a + 2 * k - 1) * (a + 2 * k))
                                     : -(a + k) * (a + b + k) * x / ((a + 2 * k) * (a + 2 * k + 1));
      d = 1.0 + num * d;
      if (std::fabs(d) < tiny) d = tiny;
      c = 1.0 + num / c;
      if (std::fabs(c) < tiny) c = tiny;
      d = 1.0 / d;
      f *= c * d;
      if (parity == 1 && std::fabs(c * d - 1.0) < 1e-15) return std::exp(ln_front) * f / a;
    }
  }
  return std::exp(ln_front) * f / a;
}

}  // namespace detail

// Two-sided quantile: P(|T| <= q) = level, T standard normal (dof <= 0) or Student's t with dof degrees of
// freedom; by bisection on the t distribution function (I_{dof/(dof+q^2)}(dof/2, 1/2) = 1 - level).
inline double two_sided_quantile(double level, int dof) {
  const double tail = 1.0 - level;
  auto tail_of = [&](double q) {
    if (dof <= 0) return std::erfc(q / std::sqrt(2.0));
    return detail::incomplete_beta(0.5 * dof, 0.5, dof / (dof + q * q));
  };
  double lo = 0.0, hi = 1.0;
  while (tail_of(hi) > tail) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tail_of(mid) > tail ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace polymech::estimation
