// Chebyshev iteration on a Jacobi-scaled symmetric positive definite operator S: an approximate
// inverse z ~ S^-1 r that is a fixed polynomial in D^-1 S (D = diag S), hence linear and symmetric,
// so it can precondition CG and COCG and smooth in a multigrid cycle. With the eigenvalues of D^-1 S
// in [lo, hi] the error after k steps is bounded by 2 ((sqrt(hi/lo) - 1) / (sqrt(hi/lo) + 1))^k
// (Saad, "Iterative methods for sparse linear systems", Alg. 12.1, with the Jacobi scaling); as a
// smoother the interval is [hi / range, hi], which damps the upper part of the spectrum.
//
// S is any operator of the concept of krylov.hpp (apply, local_size, owned_size; reduce_sum when
// distributed); it is applied to vectors of V = T or Kokkos::complex<T> (S real: complex vectors are
// two real ones). The bounds come from estimate_spectrum(): a few CG steps on S, whose coefficients
// form the Lanczos tridiagonal matrix, whose extreme eigenvalues (Ritz values) approach those of D^-1 S.
#pragma once

#include <Eigen/Dense>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "solvers/krylov.hpp"

namespace polymech::solvers {

namespace detail {

// z = a z + b inv .* res (Chebyshev direction update); with first = true, z = b inv .* res.
template <class V>
void chebyshev_direction(Index local, real_of<V> a, real_of<V> b, const View1<V>& inv, const View1<V>& res,
                         const View1<V>& d, bool first) {
  Kokkos::parallel_for(
      "polymech::solvers::chebyshev_step", range(local), KOKKOS_LAMBDA(const Index i) {
        d(i) = first ? b * (inv(i) * res(i)) : a * d(i) + b * (inv(i) * res(i));
      });
}

// z += d; res = r - S z is formed by the caller.
template <class V>
void add_to(Index local, const View1<V>& d, const View1<V>& z) {
  Kokkos::parallel_for(
      "polymech::solvers::chebyshev_add", range(local), KOKKOS_LAMBDA(const Index i) { z(i) += d(i); });
}

template <class V>
void subtract_from(Index local, const View1<V>& r, const View1<V>& s, const View1<V>& res) {  // res = r - s
  Kokkos::parallel_for(
      "polymech::solvers::chebyshev_residual", range(local), KOKKOS_LAMBDA(const Index i) { res(i) = r(i) - s(i); });
}

}  // namespace detail

// Extreme eigenvalues of D^-1 S from `steps` CG steps on S z = b (b a fixed pseudo-random vector):
// the Lanczos tridiagonal matrix of the CG coefficients and its eigenvalues (Ritz values).
struct Spectrum {
  double lo = 0.0, hi = 0.0;
  int steps = 0;
};

template <class Op, class V>
Spectrum estimate_spectrum(const Op& S, const View1<V>& inv_diag, int steps) {
  using Sc = ScalarTraits<V>;
  using T = real_of<V>;
  const Index local = S.local_size(), owned = S.owned_size();
  View1<V> r("polymech::solvers::lanczos_r", local), x("polymech::solvers::lanczos_x", local),
      z("polymech::solvers::lanczos_z", local), p("polymech::solvers::lanczos_p", local),
      q("polymech::solvers::lanczos_q", local);
  {
    auto h = Kokkos::create_mirror_view(r);
    std::uint32_t s = 12345u;
    for (Index i = 0; i < local; ++i) {
      s = s * 1664525u + 1013904223u;
      h(i) = V(static_cast<T>(0.5 + static_cast<double>(s >> 8) / 16777216.0));  // in (0.5, 1.5): rich in low modes
    }
    Kokkos::deep_copy(r, h);
  }
  // the CG recurrences of krylov.hpp (S real symmetric: real values in the real parts), keeping alpha, beta
  std::vector<double> alpha, beta;
  DotNorms<V> rz = detail::global_sum(S, precondition_and_dot(owned, local, inv_diag, r, z));
  Kokkos::deep_copy(p, z);
  double rho = static_cast<double>(Sc::re(rz.dot));
  for (int k = 0; k < steps && rho > 0; ++k) {
    S.apply(p, q);
    const double pq =
        static_cast<double>(Sc::re(detail::global_sum(S, dot_with_norms("polymech::solvers::lanczos_pq", owned, p, q)).dot));
    if (!(pq > 0)) break;
    const double a = rho / pq;
    update_solution_and_residual(owned, local, V(static_cast<T>(a)), p, q, x, r);
    rz = detail::global_sum(S, precondition_and_dot(owned, local, inv_diag, r, z));
    const double rho_new = static_cast<double>(Sc::re(rz.dot));
    const double bt = rho_new / rho;
    alpha.push_back(a);
    beta.push_back(bt);
    rho = rho_new;
    if (!(rho > 1e-30 * rz.norm2_x)) break;
    update_direction(local, V(static_cast<T>(bt)), z, p);
  }
  const int m = static_cast<int>(alpha.size());
  if (m == 0) throw std::runtime_error("estimate_spectrum: CG on the operator broke down at once (not SPD?)");
  // Lanczos matrix from CG: T_jj = 1/alpha_j + beta_(j-1)/alpha_(j-1), T_j,j+1 = sqrt(beta_j)/alpha_j
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(m, m);
  for (int j = 0; j < m; ++j) {
    L(j, j) = 1.0 / alpha[j] + (j > 0 ? beta[j - 1] / alpha[j - 1] : 0.0);
    if (j + 1 < m) L(j, j + 1) = L(j + 1, j) = std::sqrt(beta[j]) / alpha[j];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(L, Eigen::EigenvaluesOnly);
  return {es.eigenvalues().minCoeff(), es.eigenvalues().maxCoeff(), m};
}

// Smallest Chebyshev degree whose error bound 2 ((sqrt(k) - 1) / (sqrt(k) + 1))^d, k = hi / lo, is
// below `reduction` (at most max_degree).
inline int chebyshev_degree(double lo, double hi, double reduction, int max_degree) {
  const double sk = std::sqrt(hi / lo), c = (sk - 1.0) / (sk + 1.0);
  if (!(c > 0)) return 1;
  const int d = static_cast<int>(std::ceil(std::log(reduction / 2.0) / std::log(c)));
  return d < 1 ? 1 : d > max_degree ? max_degree : d;
}

// z = p(D^-1 S) D^-1 r, the Chebyshev polynomial of the given degree for the interval [lo, hi]
// (degree - 1 applications of S from a zero start); smooth() improves a z that holds an initial guess
// by `degree` steps (degree applications of S).
template <class Op, class V>
class Chebyshev {
 public:
  Chebyshev() = default;
  Chebyshev(const Op* S, View1<V> inv_diag, double lo, double hi, int degree)
      : S_(S), inv_(inv_diag), lo_(lo), hi_(hi), degree_(degree) {
    if (!(lo > 0) || !(hi > lo) || degree < 1)
      throw std::invalid_argument("Chebyshev: need 0 < lo < hi and degree >= 1 (lo = " + std::to_string(lo) +
                                  ", hi = " + std::to_string(hi) + ", degree = " + std::to_string(degree) + ")");
    const Index n = S->local_size();
    res_ = View1<V>("polymech::solvers::chebyshev_res", n);
    d_ = View1<V>("polymech::solvers::chebyshev_d", n);
    s_ = View1<V>("polymech::solvers::chebyshev_s", n);
  }

  int degree() const { return degree_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }

  // z = P r (zero start). The preconditioner concept of krylov.hpp.
  void apply(const View1<V>& r, const View1<V>& z) const { run(r, z, false); }
  // z improved towards S^-1 r from its current value.
  void smooth(const View1<V>& r, const View1<V>& z) const { run(r, z, true); }

 private:
  void run(const View1<V>& r, const View1<V>& z, bool from_guess) const {
    using T = real_of<V>;
    const Index n = S_->local_size();
    const double theta = 0.5 * (hi_ + lo_), delta = 0.5 * (hi_ - lo_), sigma = theta / delta;
    double rho = 1.0 / sigma;
    if (from_guess) {
      S_->apply(z, s_);
      detail::subtract_from(n, r, s_, res_);
    } else {
      Kokkos::deep_copy(z, V(0));
      Kokkos::deep_copy(res_, r);
    }
    detail::chebyshev_direction(n, T(0), static_cast<T>(1.0 / theta), inv_, res_, d_, true);
    detail::add_to(n, d_, z);
    for (int k = 1; k < degree_; ++k) {
      S_->apply(z, s_);
      detail::subtract_from(n, r, s_, res_);
      const double rho_new = 1.0 / (2.0 * sigma - rho);
      detail::chebyshev_direction(n, static_cast<T>(rho_new * rho), static_cast<T>(2.0 * rho_new / delta), inv_, res_,
                                  d_, false);
      detail::add_to(n, d_, z);
      rho = rho_new;
    }
  }

  const Op* S_ = nullptr;
  View1<V> inv_;
  double lo_ = 0.0, hi_ = 0.0;
  int degree_ = 1;
  View1<V> res_, d_, s_;
};

}  // namespace polymech::solvers
