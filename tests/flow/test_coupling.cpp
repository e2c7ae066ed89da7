// Partitioned coupling (issue 36; models/fsi/coupling.hpp) on the model problem of the added-mass effect: a
// structure M_s u'' + K u = f wetted by an incompressible fluid whose only force on it is its added mass,
// f = -M_a u'' (potential flow; Causin, Gerbeau & Nobile 2005). Each time step (Newmark, average acceleration) the
// Dirichlet-Neumann map G takes the interface displacement x, lets the "fluid" return f = -M_a c0 (x - u_pred),
// and the "structure" solve (c0 M_s + K) u = f + c0 M_s u_pred: G(x) = u. The monolithic step solves
// (c0 (M_s + M_a) + K) u = c0 (M_s + M_a) u_pred. The plain iteration's factor is -(c0 M_s + K)^-1 c0 M_a, whose
// spectral radius is about the added-mass ratio mu = lambda_max(M_a) / m_s: below 1 it converges, above it
// diverges (and says so); Aitken and IQN-ILS converge at any ratio, IQN-ILS in at most n + 1 evaluations on this
// linear map and in fewer once it reuses earlier steps' columns; every coupled history equals the monolithic one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Dense>

#include "fsi/coupling.hpp"

namespace fs = polymech::fsi;

namespace {

struct AddedMassProblem {
  int n = 6;
  double ms = 1.0, dt = 0.05;
  Eigen::MatrixXd Ms, Ma, K;
  AddedMassProblem(double mu) {
    Ms = ms * Eigen::MatrixXd::Identity(n, n);
    K = Eigen::MatrixXd::Zero(n, n);
    for (int i = 0; i < n; ++i) {  // a spring chain fixed at both ends, k = 400
      K(i, i) = 800.0;
      if (i + 1 < n) K(i, i + 1) = K(i + 1, i) = -400.0;
    }
    Eigen::MatrixXd A(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) A(i, j) = std::exp(-std::fabs(i - j) / 2.0);
    const double lmax = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues().maxCoeff();
    Ma = mu * ms / lmax * A;
  }
};

// Steps of the coupled (method) and monolithic problems from u0 = a smooth shape at rest; returns the largest
// |u_coupled - u_mono| over the run and fills the iteration counts (0 on the first failed step).
double run(const AddedMassProblem& p, const fs::CouplingOptions& o, int steps, std::vector<int>& iterations,
           fs::CouplingResult* failure = nullptr) {
  const double c0 = 4.0 / (p.dt * p.dt);
  Eigen::VectorXd u(p.n), v = Eigen::VectorXd::Zero(p.n), a = Eigen::VectorXd::Zero(p.n);
  for (int i = 0; i < p.n; ++i) u(i) = std::sin(3.14159265358979 * (i + 1) / (p.n + 1));
  Eigen::VectorXd um = u, vm = v, am = a;
  // a_0 from the equation of motion: (M_s + M_a) a = -K u
  a = (p.Ms + p.Ma).ldlt().solve(-p.K * u);
  am = a;
  const Eigen::LDLT<Eigen::MatrixXd> structure((c0 * p.Ms + p.K).eval()), mono((c0 * (p.Ms + p.Ma) + p.K).eval());
  fs::InterfaceCoupling coupling(o);
  double worst = 0.0;
  for (int s = 0; s < steps; ++s) {
    const Eigen::VectorXd up = u + p.dt * v + 0.25 * p.dt * p.dt * a;
    auto G = [&](const std::vector<double>& x) {
      Eigen::VectorXd xv = Eigen::Map<const Eigen::VectorXd>(x.data(), p.n);
      const Eigen::VectorXd f = -p.Ma * (c0 * (xv - up));  // the fluid: its added-mass force
      const Eigen::VectorXd un = structure.solve(f + c0 * p.Ms * up);
      return std::vector<double>(un.data(), un.data() + p.n);
    };
    std::vector<double> x(up.data(), up.data() + p.n);
    const fs::CouplingResult r = coupling.solve(x, G);
    if (!r.converged) {
      iterations.push_back(0);
      if (failure) *failure = r;
      return worst;
    }
    iterations.push_back(r.iterations);
    const Eigen::VectorXd un = Eigen::Map<const Eigen::VectorXd>(x.data(), p.n);
    const Eigen::VectorXd an = c0 * (un - up);
    v += 0.5 * p.dt * (a + an);
    a = an;
    u = un;
    const Eigen::VectorXd upm = um + p.dt * vm + 0.25 * p.dt * p.dt * am;
    const Eigen::VectorXd umn = mono.solve(c0 * (p.Ms + p.Ma) * upm), amn = c0 * (umn - upm);
    vm += 0.5 * p.dt * (am + amn);
    am = amn;
    um = umn;
    worst = std::max(worst, (u - um).cwiseAbs().maxCoeff());
  }
  return worst;
}

double mean(const std::vector<int>& v, std::size_t from) {
  double s = 0.0;
  for (std::size_t i = from; i < v.size(); ++i) s += v[i];
  return s / static_cast<double>(v.size() - from);
}

}  // namespace

TEST(Coupling, LightFluidEveryMethodConverges) {
  const AddedMassProblem p(0.5);
  for (const char* m : {"relaxation", "aitken", "iqn_ils"}) {
    fs::CouplingOptions o;
    o.method = fs::coupling_method(m);
    o.omega = o.method == fs::CouplingMethod::relaxation ? 1.0 : 0.5;
    o.tolerance = 1e-12;
    std::vector<int> its;
    const double err = run(p, o, 40, its);
    std::printf("mu = 0.5, %-10s: iterations per step %.2f (first %d), max |u - u_monolithic| %.2e\n", m, mean(its, 0), its[0], err);
    ASSERT_EQ(its.size(), 40u);
    EXPECT_LT(err, 1e-9);
  }
}

TEST(Coupling, HeavyFluidPlainDivergesWithAReasonAitkenAndIqnConverge) {
  const AddedMassProblem p(4.0);
  fs::CouplingOptions plain;
  plain.method = fs::CouplingMethod::relaxation;
  plain.omega = 1.0;
  plain.tolerance = 1e-12;
  std::vector<int> its;
  fs::CouplingResult failure;
  run(p, plain, 5, its, &failure);
  std::printf("mu = 4, plain: stopped after %d evaluations: %s\n", failure.iterations, failure.reason.c_str());
  EXPECT_FALSE(failure.converged);
  EXPECT_NE(failure.reason.find("diverges"), std::string::npos);
  EXPECT_EQ(its.back(), 0);

  fs::CouplingOptions aitken;
  aitken.method = fs::CouplingMethod::aitken;
  aitken.tolerance = 1e-12;
  aitken.max_iterations = 200;
  std::vector<int> ia;
  const double ea = run(p, aitken, 40, ia);
  fs::CouplingOptions iqn;
  iqn.tolerance = 1e-12;
  iqn.reuse = 0;
  std::vector<int> iq;
  const double eq = run(p, iqn, 40, iq);
  iqn.reuse = 8;
  std::vector<int> ir;
  const double er = run(p, iqn, 40, ir);
  std::printf("mu = 4: aitken %.2f evaluations per step (err %.2e); iqn_ils %.2f (no reuse, err %.2e), %.2f with 8 steps "
              "reused (steps 10-40: %.2f, err %.2e)\n",
              mean(ia, 0), ea, mean(iq, 0), eq, mean(ir, 0), mean(ir, 10), er);
  ASSERT_EQ(ia.size(), 40u);
  ASSERT_EQ(iq.size(), 40u);
  ASSERT_EQ(ir.size(), 40u);
  EXPECT_LT(ea, 1e-9);
  EXPECT_LT(eq, 1e-9);
  EXPECT_LT(er, 1e-9);
  EXPECT_LE(*std::max_element(iq.begin(), iq.end()), p.n + 2);  // exact on a linear map after n + 1 columns
  EXPECT_LT(mean(ir, 10), mean(iq, 10));                        // reuse pays once the model is learned
  EXPECT_LT(mean(iq, 0), mean(ia, 0));                          // and the quasi-Newton beats Aitken here
}

TEST(Coupling, BadOptionsAreRefused) {
  fs::CouplingOptions o;
  o.omega = 0.0;
  EXPECT_THROW(fs::InterfaceCoupling{o}, std::invalid_argument);
  EXPECT_THROW(fs::coupling_method("newton"), std::invalid_argument);
  fs::InterfaceCoupling c;
  std::vector<double> x{1.0, 2.0};
  EXPECT_THROW(c.solve(x, [](const std::vector<double>&) { return std::vector<double>{1.0}; }), std::invalid_argument);
  // a map that never settles: stops at the limit with the reason
  fs::CouplingOptions lim;
  lim.method = fs::CouplingMethod::relaxation;
  lim.max_iterations = 5;
  fs::InterfaceCoupling c2(lim);
  const auto r = c2.solve(x, [](const std::vector<double>& y) { return std::vector<double>{-y[0] + 1.0, y[1] + 1.0}; });
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.reason.find("no convergence"), std::string::npos);
}
