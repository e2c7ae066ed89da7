// BiCGSTAB (van der Vorst 1992) for the unsymmetric pressure Poisson operator of the IGCB walls: the
// wall pressure p_c,m is the Shepard interpolation of fluid pressures at a ghost point (eqs. (23)-(26)),
// so row i depends on p_j through a weight that row j does not share. kernels/solvers/krylov.hpp has
// CG/COCG only (symmetric operators); this is the unsymmetric solver, over the same Operator concept
// (local_size(), apply(x, y)) and returning the same SolveResult (iterations, residual history).
// The operator is expected to be row-scaled already (Jacobi), as the ISPH model's is.
#pragma once

#include <chrono>
#include <cmath>
#include <string>
#include <type_traits>

#include "solvers/krylov.hpp"

namespace polymech::sph {

namespace detail {
template <class T>
double dotp(const char* label, const View1<T>& a, const View1<T>& b, Index n) {
  double s = 0.0;
  Kokkos::parallel_reduce(
      label, range(n), KOKKOS_LAMBDA(const Index i, double& acc) { acc += double(a(i)) * double(b(i)); }, s);
  return s;
}
}  // namespace detail

// No preconditioner beyond the operator's own row scaling (the default).
struct NoPreconditioner {};

// x: initial guess on entry (warm start; replaced by zero when its residual exceeds |b|), solution on exit. Stops at |b - A x| / |b| <= tolerance.
// M: a right preconditioner, M.apply(r, z) giving z ~ A^-1 r (A M^-1 y = b, x = M^-1 y; the residual
// the iteration tracks is still b - A x); NoPreconditioner leaves the plain iteration, unchanged to the bit.
template <class Op, class T, class Prec = NoPreconditioner>
solvers::SolveResult bicgstab(const Op& A, const View1<T>& b, const View1<T>& x, const solvers::SolverOptions& o,
                              const Prec& M = {}) {
  constexpr bool preconditioned = !std::is_same_v<Prec, NoPreconditioner>;
  using solvers::SolveStatus;
  const auto t0 = std::chrono::steady_clock::now();
  solvers::SolveResult res;
  const Index n = A.local_size();
  const double bnorm = std::sqrt(detail::dotp("polymech::sph::bicgstab_norm", b, b, n));
  auto done = [&](SolveStatus s, std::string why) {
    res.status = s;
    res.reason = std::move(why);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  };
  if (!std::isfinite(bnorm)) return done(SolveStatus::non_finite, "BiCGSTAB: the right-hand side holds NaN or Inf");
  if (bnorm == 0.0) {
    Kokkos::deep_copy(x, T(0));
    res.history.push_back(0.0);
    return done(SolveStatus::converged, "");
  }
  View1<T> r("polymech::sph::bicgstab_r", n), r0("polymech::sph::bicgstab_r0", n), p("polymech::sph::bicgstab_p", n),
      v("polymech::sph::bicgstab_v", n), s("polymech::sph::bicgstab_s", n), t("polymech::sph::bicgstab_t", n);
  // M^-1 p and M^-1 s (preconditioned only; otherwise p and s themselves)
  View1<T> ph = p, sh = s;
  if constexpr (preconditioned) {
    ph = View1<T>("polymech::sph::bicgstab_ph", n);
    sh = View1<T>("polymech::sph::bicgstab_sh", n);
  }
  A.apply(x, r);
  Kokkos::parallel_for(
      "polymech::sph::bicgstab_init", range(n), KOKKOS_LAMBDA(const Index i) {
        r(i) = b(i) - r(i);
        r0(i) = r(i);
        p(i) = r(i);
      });
  double rel = std::sqrt(detail::dotp("polymech::sph::bicgstab_norm", r, r, n)) / bnorm;
  if (rel > 1.0) {  // the warm start is worse than zero (the free-surface set changed): start from zero
    Kokkos::parallel_for(
        "polymech::sph::bicgstab_zero_start", range(n), KOKKOS_LAMBDA(const Index i) {
          x(i) = T(0);
          r(i) = b(i);
          r0(i) = b(i);
          p(i) = b(i);
        });
    rel = 1.0;
  }
  res.history.push_back(rel);
  double rho = detail::dotp("polymech::sph::bicgstab_dot", r0, r, n);
  while (rel > o.tolerance) {
    if (res.iterations >= o.max_iterations)
      return done(SolveStatus::max_iterations, "BiCGSTAB: reached " + std::to_string(o.max_iterations) +
                                                   " iterations at relative residual " + std::to_string(rel));
    if constexpr (preconditioned) M.apply(p, ph);
    A.apply(ph, v);
    const double r0v = detail::dotp("polymech::sph::bicgstab_dot", r0, v, n);
    if (r0v == 0.0 || !std::isfinite(r0v)) return done(SolveStatus::breakdown_pap, "BiCGSTAB: r0^T A p vanished");
    const T alpha = T(rho / r0v);
    Kokkos::parallel_for(
        "polymech::sph::bicgstab_s", range(n), KOKKOS_LAMBDA(const Index i) { s(i) = r(i) - alpha * v(i); });
    if constexpr (preconditioned) M.apply(s, sh);
    A.apply(sh, t);
    const double tt = detail::dotp("polymech::sph::bicgstab_dot", t, t, n);
    const double ts = detail::dotp("polymech::sph::bicgstab_dot", t, s, n);
    const T omega = tt > 0.0 ? T(ts / tt) : T(0);
    Kokkos::parallel_for(
        "polymech::sph::bicgstab_update", range(n), KOKKOS_LAMBDA(const Index i) {
          x(i) += alpha * ph(i) + omega * sh(i);
          r(i) = s(i) - omega * t(i);
        });
    ++res.iterations;
    rel = std::sqrt(detail::dotp("polymech::sph::bicgstab_norm", r, r, n)) / bnorm;
    res.history.push_back(rel);
    if (!std::isfinite(rel)) return done(SolveStatus::non_finite, "BiCGSTAB: the residual became NaN/Inf");
    if (rel <= o.tolerance) break;
    const double rho_new = detail::dotp("polymech::sph::bicgstab_dot", r0, r, n);
    if (rho_new == 0.0 || omega == T(0)) return done(SolveStatus::breakdown_rho, "BiCGSTAB: r0^T r or omega vanished");
    const T beta = T((rho_new / rho) * (double(alpha) / double(omega)));
    rho = rho_new;
    Kokkos::parallel_for(
        "polymech::sph::bicgstab_direction", range(n),
        KOKKOS_LAMBDA(const Index i) { p(i) = r(i) + beta * (p(i) - omega * v(i)); });
  }
  res.relative_residual = rel;
  A.apply(x, t);
  Kokkos::parallel_for(
      "polymech::sph::bicgstab_true", range(n), KOKKOS_LAMBDA(const Index i) { t(i) = b(i) - t(i); });
  res.true_relative_residual = std::sqrt(detail::dotp("polymech::sph::bicgstab_norm", t, t, n)) / bnorm;
  return done(SolveStatus::converged, "");
}

}  // namespace polymech::sph
