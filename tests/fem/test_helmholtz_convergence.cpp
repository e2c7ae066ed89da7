// Verification against the analytic solutions of seed 002 paper 3 (reduced sizes; the full study is
// bench/sweep_helmholtz and docs/VALIDATION.md): the L2 error of eq. (28) converges at order p + 1 for
// p = 1..4 on the unit cube with Dirichlet data from eq. (27) and on the duct of eq. (29)
// (fitted slope within 0.2 of p + 1), with COCG at the paper's tolerance 1e-10 (Table 1).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "helmholtz_fixtures.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;

namespace {

// Least-squares slope of log(error) against log(h).
double fitted_slope(const std::vector<double>& h, const std::vector<double>& e) {
  double mx = 0, my = 0;
  const double n = static_cast<double>(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    mx += std::log(h[i]) / n;
    my += std::log(e[i]) / n;
  }
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    sxy += (std::log(h[i]) - mx) * (std::log(e[i]) - my);
    sxx += (std::log(h[i]) - mx) * (std::log(h[i]) - mx);
  }
  return sxy / sxx;
}

struct Run {
  double error;
  int iterations;
};

template <class T = double>
Run solve(const hz::Config& cfg) {
  hz::Helmholtz<T> m(cfg);
  const auto r = m.solve();
  EXPECT_EQ(r.status, pm::solvers::SolveStatus::converged) << r.reason;
  EXPECT_LE(r.true_relative_residual, 1e-10);
  return {m.l2_error().relative(), r.iterations};
}

void expect_order(const char* name, int p, const std::vector<int>& ns, double length,
                  hz::Config (*make)(int, int, double)) {
  std::vector<double> h, e;
  for (int n : ns) {
    const Run r = solve(make(p, n, 500.0));
    h.push_back(length / n);
    e.push_back(r.error);
    std::printf("%s p = %d, %d elements per length: L2 error %.4e (%d COCG iterations)\n", name, p, n, r.error,
                r.iterations);
  }
  const double slope = fitted_slope(h, e);
  std::printf("%s p = %d: fitted slope %.3f (expected %d)\n", name, p, slope, p + 1);
  EXPECT_NEAR(slope, p + 1, 0.2) << name << " p = " << p;
}

}  // namespace

TEST(HelmholtzConvergence, CubeConvergesAtOrderPPlusOne) {
  expect_order("cube", 1, {12, 16, 24}, 1.0, pm::testing::cube_case);
  expect_order("cube", 2, {4, 6, 8}, 1.0, pm::testing::cube_case);
  expect_order("cube", 3, {4, 6, 8}, 1.0, pm::testing::cube_case);
  expect_order("cube", 4, {4, 5, 6}, 1.0, pm::testing::cube_case);
}

TEST(HelmholtzConvergence, DuctConvergesAtOrderPPlusOne) {
  expect_order("duct", 1, {20, 40, 80}, 1.0, pm::testing::duct_case);
  expect_order("duct", 2, {10, 20, 40}, 1.0, pm::testing::duct_case);
  expect_order("duct", 3, {5, 10, 20}, 1.0, pm::testing::duct_case);
  expect_order("duct", 4, {5, 10, 20}, 1.0, pm::testing::duct_case);
}

// The paper's linear duct mesh with 315 nodes (§3(3), Fig. 5): 20 x 4 x 2 elements.
TEST(HelmholtzConvergence, PaperDuctMeshMatchesEq29) {
  hz::Helmholtz<double> m(pm::testing::duct_case(1, 20));
  EXPECT_EQ(m.dof_count(), 315);
  const auto r = m.solve();
  EXPECT_TRUE(r.converged()) << r.reason;
  const double eps = m.l2_error().relative();
  EXPECT_LT(eps, 0.06);  // 4.5e-2: linear elements, 0.05 m at a 0.69 m wavelength
  EXPECT_GT(eps, 0.03);
}

// A real symmetric positive definite FEM problem, (A + sigma M) u = A u* + sigma M u* (rigid
// boundaries), solved by CG with the same matrix-free kernels on real values.
namespace {
struct RealFemOperator {
  using value_type = double;
  pm::fem::HexElements<double> el;
  double sigma;
  pm::Index local_size() const { return el.local_size(); }
  pm::Index owned_size() const { return el.owned; }
  void apply(const pm::View1<double>& x, const pm::View1<double>& y) const {
    Kokkos::deep_copy(y, 0.0);
    pm::fem::apply_helmholtz_volume(el, sigma, x, y);
  }
};
}  // namespace

TEST(HelmholtzConvergence, CgSolvesTheRealSpdFemProblem) {
  for (int p = 1; p <= 4; ++p) {
    auto cfg = pm::testing::box_config(p, {3, 3, 3}, {1.0, 1.0, 1.0}, {}, 0.2);
    hz::Helmholtz<double> m(cfg);
    RealFemOperator A{m.op().elements(), 10.0};
    const pm::Index n = A.local_size();
    pm::View1<double> xs("x*", n), b("b", n), x("x", n), d("d", n), inv("inv", n);
    auto h = Kokkos::create_mirror_view(xs);
    for (pm::Index i = 0; i < n; ++i) h(i) = std::sin(0.37 * i) + 0.1 * (i % 7);
    Kokkos::deep_copy(xs, h);
    A.apply(xs, b);
    pm::fem::add_helmholtz_volume_diagonal(A.el, A.sigma, d);
    pm::solvers::jacobi_inverse(n, n, d, inv);
    const auto r = pm::solvers::cg(A, inv, b, x);
    EXPECT_EQ(r.status, pm::solvers::SolveStatus::converged) << r.reason;
    auto hx = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), x);
    double err = 0;
    for (pm::Index i = 0; i < n; ++i) err = std::max(err, std::abs(hx(i) - h(i)));
    EXPECT_LT(err, 1e-7) << "p = " << p;
  }
}
