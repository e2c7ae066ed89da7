// CG and COCG over the operator concept: solutions of known systems, and every way a solve can fail
// says why (breakdown of r^T z, NaN, iteration limit, stagnation at the precision floor, an indefinite
// operator given to CG).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include "solvers/chebyshev.hpp"
#include "solvers/krylov.hpp"

namespace pm = polymech;
namespace sv = polymech::solvers;
using C = Kokkos::complex<double>;

namespace {

template <class V>
void tridiagonal_apply(pm::Index n, V diag, V off, const pm::View1<V>& x, const pm::View1<V>& y) {
  Kokkos::parallel_for(
      "test::tridiagonal", pm::range(n), KOKKOS_LAMBDA(const pm::Index i) {
        V s = diag * x(i);
        if (i > 0) s += off * x(i - 1);
        if (i + 1 < n) s += off * x(i + 1);
        y(i) = s;
      });
}

// Tridiagonal operator: a_ii = diag, a_i,i+1 = a_i+1,i = off (symmetric, complex allowed).
template <class V>
struct Tridiagonal {
  using value_type = V;
  pm::Index n;
  V diag, off;
  pm::Index local_size() const { return n; }
  pm::Index owned_size() const { return n; }
  void apply(const pm::View1<V>& x, const pm::View1<V>& y) const { tridiagonal_apply(n, diag, off, x, y); }
};

template <class V>
pm::View1<V> filled(pm::Index n, V (*f)(pm::Index)) {
  pm::View1<V> v("v", n);
  auto h = Kokkos::create_mirror_view(v);
  for (pm::Index i = 0; i < n; ++i) h(i) = f(i);
  Kokkos::deep_copy(v, h);
  return v;
}

template <class V>
double max_error(const pm::View1<V>& x, V (*f)(pm::Index)) {
  auto h = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), x);
  double e = 0;
  for (pm::Index i = 0; i < static_cast<pm::Index>(h.extent(0)); ++i)
    e = std::max(e, std::sqrt(static_cast<double>(sv::abs2(h(i) - f(i)))));
  return e;
}

double real_solution(pm::Index i) { return std::sin(0.1 * i) + 0.5; }
C complex_solution(pm::Index i) { return C(std::cos(0.07 * i), std::sin(0.13 * i) - 0.2); }

template <class V, class Op>
sv::SolveResult solve_known(const Op& A, V (*f)(pm::Index), bool complex_method, double& error,
                            const sv::SolverOptions& o = {}) {
  const pm::Index n = A.local_size();
  const auto xs = filled<V>(n, f);
  pm::View1<V> b("b", n), x("x", n), inv;
  A.apply(xs, b);
  sv::SolveResult r;
  if constexpr (sv::ScalarTraits<V>::is_complex)
    r = sv::cocg(A, inv, b, x, o);
  else
    r = complex_method ? sv::cocg(A, inv, b, x, o) : sv::cg(A, inv, b, x, o);
  error = max_error<V>(x, f);
  return r;
}

}  // namespace

TEST(Krylov, CgSolvesARealSpdSystem) {
  Tridiagonal<double> A{200, 2.05, -1.0};  // shifted 1D Laplacian
  double err = 1;
  const auto r = solve_known<double>(A, real_solution, false, err);
  EXPECT_EQ(r.status, sv::SolveStatus::converged) << r.reason;
  EXPECT_LE(r.true_relative_residual, 1e-10);
  EXPECT_LT(err, 1e-8);
  EXPECT_EQ(r.history.size(), static_cast<std::size_t>(r.iterations) + 1);
  EXPECT_TRUE(r.reason.empty());
}

TEST(Krylov, CocgSolvesAComplexSymmetricSystem) {
  // Helmholtz-like: indefinite real part, absorbing imaginary part; symmetric, not Hermitian.
  Tridiagonal<C> A{300, C(1.2, 0.3), C(-1.0, 0.0)};
  double err = 1;
  const auto r = solve_known<C>(A, complex_solution, true, err);
  EXPECT_EQ(r.status, sv::SolveStatus::converged) << r.reason;
  EXPECT_LE(r.true_relative_residual, 1e-10);
  EXPECT_LT(err, 1e-7);
}

TEST(Krylov, JacobiPreconditioningIsExactForADiagonalOperator) {
  Tridiagonal<C> A{50, C(3.0, -2.0), C(0.0, 0.0)};
  pm::View1<C> b("b", 50), x("x", 50), d("d", 50), inv("inv", 50);
  Kokkos::deep_copy(b, C(1.0, 1.0));
  Kokkos::deep_copy(d, C(3.0, -2.0));
  const auto s = sv::jacobi_inverse(50, 50, d, inv);
  EXPECT_NEAR(s.min_abs, std::sqrt(13.0), 1e-12);
  const auto r = sv::cocg(A, inv, b, x);
  EXPECT_EQ(r.status, sv::SolveStatus::converged);
  EXPECT_EQ(r.iterations, 1);
}

TEST(Krylov, CocgReportsTheQuasiNullBreakdown) {
  // A = I, b = (1, j): r0^T r0 = 1 + j^2 = 0 although r0 != 0.
  Tridiagonal<C> A{2, C(1.0, 0.0), C(0.0, 0.0)};
  pm::View1<C> b("b", 2), x("x", 2), inv;
  auto h = Kokkos::create_mirror_view(b);
  h(0) = C(1, 0);
  h(1) = C(0, 1);
  Kokkos::deep_copy(b, h);
  const auto r = sv::cocg(A, inv, b, x);
  EXPECT_EQ(r.status, sv::SolveStatus::breakdown_rho);
  EXPECT_NE(r.reason.find("breakdown at iteration 0"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("r^T z"), std::string::npos) << r.reason;
}

TEST(Krylov, NanInTheOperatorIsReported) {
  Tridiagonal<double> A{20, std::numeric_limits<double>::quiet_NaN(), -1.0};
  pm::View1<double> b("b", 20), x("x", 20), inv;
  Kokkos::deep_copy(b, 1.0);
  const auto r = sv::cg(A, inv, b, x);
  EXPECT_EQ(r.status, sv::SolveStatus::non_finite);
  EXPECT_NE(r.reason.find("NaN"), std::string::npos) << r.reason;
}

TEST(Krylov, IterationLimitIsReportedWithTheResidual) {
  Tridiagonal<double> A{400, 2.0, -1.0};
  sv::SolverOptions o;
  o.max_iterations = 10;
  double err = 0;
  const auto r = solve_known<double>(A, real_solution, false, err, o);
  EXPECT_EQ(r.status, sv::SolveStatus::max_iterations);
  EXPECT_EQ(r.iterations, 10);
  EXPECT_NE(r.reason.find("iteration limit 10"), std::string::npos) << r.reason;
  EXPECT_GT(r.true_relative_residual, 1e-3);
}

TEST(Krylov, CgRefusesAnIndefiniteOperator) {
  Tridiagonal<double> A{100, 0.5, -1.0};  // eigenvalues 0.5 - 2 cos(..): both signs
  double err = 0;
  const auto r = solve_known<double>(A, real_solution, false, err);
  EXPECT_EQ(r.status, sv::SolveStatus::not_positive_definite) << r.reason;
  EXPECT_NE(r.reason.find("not positive definite"), std::string::npos) << r.reason;
  // COCG (no definiteness needed) solves the same system
  const auto r2 = solve_known<double>(A, real_solution, true, err);
  EXPECT_EQ(r2.status, sv::SolveStatus::converged) << r2.reason;
}

// In float the recursive residual can be driven below 1e-10 while the true residual stays at the
// precision floor: the solver restarts from the true residual and then stops as stagnated, saying so.
TEST(Krylov, FloatStopsAtItsAttainableAccuracy) {
  using F = Kokkos::complex<float>;
  Tridiagonal<F> A{2000, F(2.3f, 0.05f), F(-1.0f, 0.0f)};
  pm::View1<F> b("b", 2000), x("x", 2000), inv;
  Kokkos::deep_copy(b, F(1.0f, 0.5f));
  sv::SolverOptions o;
  o.tolerance = 1e-10;
  const auto r = sv::cocg(A, inv, b, x, o);
  EXPECT_EQ(r.status, sv::SolveStatus::stagnated) << r.reason;
  EXPECT_NE(r.reason.find("float"), std::string::npos) << r.reason;
  EXPECT_GT(r.true_relative_residual, 1e-9);
  EXPECT_LT(r.true_relative_residual, 1e-4);
  std::printf("%s after %d iterations: %s\n", sv::to_string(r.status), r.iterations, r.reason.c_str());
}

TEST(Krylov, StagnationWindowStopsAnIterationWithoutProgress) {
  // The unpreconditioned 1D Laplacian converges slowly and not monotonically: a window of 3
  // iterations without a 10 % reduction of the best residual stops it, with the reason.
  Tridiagonal<double> A{400, 2.0, -1.0};
  sv::SolverOptions o;
  o.stagnation_window = 3;
  double err = 0;
  const auto r = solve_known<double>(A, real_solution, true, err, o);
  EXPECT_EQ(r.status, sv::SolveStatus::stagnated) << r.reason;
  EXPECT_NE(r.reason.find("no 10 % reduction"), std::string::npos) << r.reason;
  EXPECT_LT(r.iterations, 400);
}

TEST(Krylov, ZeroOperatorIsABreakdownOfPAp) {
  Tridiagonal<double> A{64, 0.0, 0.0};
  pm::View1<double> b("b", 64), x("x", 64), inv;
  Kokkos::deep_copy(b, 1.0);
  const auto r = sv::cocg(A, inv, b, x);
  EXPECT_EQ(r.status, sv::SolveStatus::breakdown_pap) << r.reason;
  EXPECT_NE(r.reason.find("p^T A p"), std::string::npos) << r.reason;
}

TEST(Krylov, ZeroRightHandSideGivesZero) {
  Tridiagonal<C> A{10, C(1.0, 1.0), C(0.5, 0.0)};
  pm::View1<C> b("b", 10), x("x", 10), inv;
  Kokkos::deep_copy(x, C(3.0, 0.0));
  const auto r = sv::cocg(A, inv, b, x);
  EXPECT_EQ(r.status, sv::SolveStatus::converged);
  auto h = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), x);
  EXPECT_EQ(h(3), C(0.0, 0.0));
}

namespace {

// z = d .* r (CUDA: the kernel in a free function, not in a member of a local class).
void scale_kernel(const pm::View1<C>& d, const pm::View1<C>& r, const pm::View1<C>& z) {
  Kokkos::parallel_for(
      "test::scale", pm::range(static_cast<pm::Index>(r.extent(0))), KOKKOS_LAMBDA(const pm::Index i) { z(i) = d(i) * r(i); });
}

// z = inv .* r, as a general preconditioner.
struct Scale {
  pm::View1<C> inv;
  void apply(const pm::View1<C>& r, const pm::View1<C>& z) const { scale_kernel(inv, r, z); }
};

// e = x - z.
void difference(const pm::View1<double>& x, const pm::View1<double>& z, const pm::View1<double>& e) {
  Kokkos::parallel_for(
      "test::error", pm::range(static_cast<pm::Index>(x.extent(0))), KOKKOS_LAMBDA(const pm::Index i) { e(i) = x(i) - z(i); });
}

// A tridiagonal operator that reports its global sums (as a distributed operator would).
template <class V>
struct CountingTridiagonal : Tridiagonal<V> {
  mutable int reductions = 0;
  void reduce_sum(double*, int count) const { reductions += count > 0 ? 1 : 0; }
};

}  // namespace

// Jacobi through the fused kernels (non-empty inverse diagonal) gives the same iterates as the
// unfused path: the solution of a variable-coefficient SPD system matches, in the same iterations.
TEST(Krylov, FusedJacobiMatchesAGeneralPreconditionerDoingTheSame) {
  const pm::Index n = 300;
  Tridiagonal<C> A{n, C(2.5, 0.2), C(-1.0, 0.0)};
  pm::View1<C> b("b", n), x1("x1", n), x2("x2", n), inv("inv", n);
  Kokkos::deep_copy(b, C(1.0, -0.5));
  Kokkos::deep_copy(inv, C(1.0, 0.0) / C(2.5, 0.2));
  const auto r1 = sv::cocg(A, inv, b, x1);
  const auto r2 = sv::cocg_preconditioned(A, Scale{inv}, b, x2);
  ASSERT_TRUE(r1.converged()) << r1.reason;
  ASSERT_TRUE(r2.converged()) << r2.reason;
  EXPECT_EQ(r1.iterations, r2.iterations);
  auto h1 = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), x1);
  auto h2 = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), x2);
  double d = 0;
  for (pm::Index i = 0; i < n; ++i) d = std::max(d, static_cast<double>(Kokkos::abs(h1(i) - h2(i))));
  EXPECT_LT(d, 1e-12);
}

// The Lanczos estimate of the spectrum of D^-1 A for the 1D Laplacian tridiag(-1, 2, -1), whose
// eigenvalues are 1 - cos(j pi / (n + 1)), j = 1..n; and the Chebyshev iteration on the exact interval
// meets its error bound 2 ((sqrt(k) - 1) / (sqrt(k) + 1))^d: |A^-1 r - P r|_A <= bound |A^-1 r|_A.
TEST(Krylov, SpectrumEstimateAndChebyshevBound) {
  const pm::Index n = 400;
  Tridiagonal<double> A{n, 2.0, -1.0};
  pm::View1<double> inv("inv", n);
  Kokkos::deep_copy(inv, 0.5);
  const auto s = sv::estimate_spectrum(A, inv, 60);
  const double pi = 3.14159265358979323846, lo = 1 - std::cos(pi / (n + 1)), hi = 1 - std::cos(n * pi / (n + 1));
  std::printf("Lanczos, %d steps: [%.3e, %.6f] (exact [%.3e, %.6f])\n", s.steps, s.lo, s.hi, lo, hi);
  EXPECT_NEAR(s.hi, hi, 1e-3);
  EXPECT_GE(s.lo, lo * (1 - 1e-9));  // Ritz values lie inside the spectrum
  EXPECT_LT(s.lo, 20 * lo);
  // exact solution x of A x = b (b = A x), then z = P b: the A-norm error of z against x
  const auto x = filled<double>(n, real_solution);
  pm::View1<double> b("b", n), z("z", n), e("e", n), Ae("Ae", n);
  A.apply(x, b);
  for (int degree : {10, 100, 300}) {
    const sv::Chebyshev<Tridiagonal<double>, double> P(&A, inv, 2 * lo, 2 * hi, degree);  // D^-1 A = A / 2
    P.apply(b, z);
    difference(x, z, e);
    A.apply(e, Ae);
    const double err = std::sqrt(sv::dot_with_norms("test", n, e, Ae).dot), ref = std::sqrt(sv::dot_with_norms("test", n, x, b).dot);
    const double sk = std::sqrt(hi / lo), bound = 2 * std::pow((sk - 1) / (sk + 1), degree);
    std::printf("Chebyshev degree %d: error %.3e, bound %.3e\n", degree, err / ref, bound);
    EXPECT_LE(err / ref, bound * (1 + 1e-6) + 1e-12) << "degree " << degree;
  }
  EXPECT_EQ(sv::chebyshev_degree(2 * lo, 2 * hi, 0.1, 1000), 383);  // smallest d with bound <= 0.1
}

// A distributed operator's reduce_sum is called for every global quantity.
TEST(Krylov, DistributedOperatorsReduceEveryDotProduct) {
  CountingTridiagonal<C> A;
  A.n = 100;
  A.diag = C(2.2, 0.1);
  A.off = C(-1.0, 0.0);
  pm::View1<C> b("b", 100), x("x", 100), inv("inv", 100);
  Kokkos::deep_copy(b, C(1.0, 0.0));
  Kokkos::deep_copy(inv, C(1.0, 0.0) / C(2.2, 0.1));
  const auto r = sv::cocg(A, inv, b, x);
  ASSERT_TRUE(r.converged()) << r.reason;
  // |b|, the initial and final true residuals, r^T z at the start; per iteration p^T A p and the fused update
  EXPECT_EQ(A.reductions, 4 + 2 * r.iterations);
}

