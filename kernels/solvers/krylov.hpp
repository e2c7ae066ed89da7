// Conjugate-gradient solvers over a matrix-free operator:
//  - cocg: COCG (van der Vorst & Melissen 1990; seed 002 paper 3 §2(2), ref. [8]) for complex
//    symmetric A = A^T (not Hermitian), such as (A - k^2 M + j rho omega C) of eq. (16). It is CG with
//    the unconjugated bilinear form x^T y in place of x^H y;
//  - cg: the same iteration for real symmetric positive definite operators, which must then keep
//    r^T z > 0 and p^T A p > 0.
// Both take a Jacobi preconditioner as the inverse diagonal (empty View: none), whose update is fused
// into the vector kernels (x, r and r^T z in one pass, z never stored), or any linear preconditioner
// (cocg_preconditioned / cg_preconditioned), which must be symmetric (P^T = P) for the method to hold:
//   void apply(const View1<V>& r, const View1<V>& z) const;   // z = P r
//
// Operator concept (the matrix-free operator of kernels/fem, a CSR matrix, a test operator):
//   using value_type = V;                        // T or Kokkos::complex<T>
//   Index local_size() const;                    // owned + ghost entries of a vector
//   Index owned_size() const;                    // owned entries, reduced over
//   void apply(const View1<V>& x, const View1<V>& y) const;   // y = A x
//   void reduce_sum(double* values, int count) const;          // optional: sums over the parts of a
//                                                              // distributed operator (MPI_Allreduce)
//
// Guards: relative breakdown checks on r^T z and p^T A p, NaN/Inf, stagnation (no 10 % reduction
// of the best residual over `stagnation_window` iterations), and the true residual |b - A x| / |b|
// recomputed at exit. When the recursive residual meets the tolerance but the true one does not, the
// iteration restarts from the true residual (up to `max_restarts` times); if a restart does not halve
// the true residual, the solve stops as `stagnated` at the attainable accuracy of the precision.
// A failed solve says why in SolveResult::reason.
#pragma once

#include "solvers/options.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solvers/vector_ops.hpp"

namespace polymech::solvers {

enum class SolveStatus {
  converged,            // true relative residual <= tolerance
  max_iterations,       // iteration limit reached
  breakdown_rho,        // r^T z vanished relative to |r| |z| (COCG quasi-null breakdown)
  breakdown_pap,        // p^T A p vanished relative to |p| |A p|
  not_positive_definite,  // cg: r^T z <= 0 or p^T A p <= 0
  stagnated,            // no progress, or the true residual stays above the tolerance
  non_finite,           // NaN or Inf in a residual or scalar
};

inline const char* to_string(SolveStatus s) {
  switch (s) {
    case SolveStatus::converged: return "converged";
    case SolveStatus::max_iterations: return "max_iterations";
    case SolveStatus::breakdown_rho: return "breakdown_rho";
    case SolveStatus::breakdown_pap: return "breakdown_pAp";
    case SolveStatus::not_positive_definite: return "not_positive_definite";
    case SolveStatus::stagnated: return "stagnated";
    case SolveStatus::non_finite: return "non_finite";
  }
  return "unknown";
}

struct SolveResult {
  SolveStatus status = SolveStatus::max_iterations;
  std::string reason;                 // empty when converged
  int iterations = 0;                 // operator applications inside the iteration
  int restarts = 0;
  double relative_residual = 0.0;     // recursive |r| / |b| at exit
  double true_relative_residual = 0.0;  // |b - A x| / |b| at exit
  double seconds = 0.0;
  std::vector<double> history;        // recursive relative residual after each iteration (index 0: start)
  std::vector<int> restart_iterations;
  bool converged() const { return status == SolveStatus::converged; }
};

namespace detail {

// Global sums of a distributed operator: A.reduce_sum when it has one, nothing otherwise.
template <class Op, class = void>
struct has_reduce_sum : std::false_type {};
template <class Op>
struct has_reduce_sum<Op, std::void_t<decltype(std::declval<const Op&>().reduce_sum(std::declval<double*>(), 0))>>
    : std::true_type {};

template <class Op>
double global_sum(const Op& A, double v) {
  if constexpr (has_reduce_sum<Op>::value) A.reduce_sum(&v, 1);
  return v;
}
template <class Op, class V>
DotNorms<V> global_sum(const Op& A, DotNorms<V> d) {
  if constexpr (has_reduce_sum<Op>::value) {
    using S = ScalarTraits<V>;
    using T = real_of<V>;
    double v[4] = {static_cast<double>(S::re(d.dot)), static_cast<double>(S::im(d.dot)), d.norm2_x, d.norm2_y};
    A.reduce_sum(v, 4);
    d.dot = S::make(static_cast<T>(v[0]), static_cast<T>(v[1]));
    d.norm2_x = v[2];
    d.norm2_y = v[3];
  }
  return d;
}

// Jacobi (or no) preconditioning, given as the inverse diagonal: the fused vector kernels.
template <class V>
struct JacobiPreconditioner {
  View1<V> inv_diag;  // empty: none
};
template <class P>
struct is_jacobi : std::false_type {};
template <class V>
struct is_jacobi<JacobiPreconditioner<V>> : std::true_type {};

inline std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.3g", x);
  return b;
}

template <class V>
bool finite(const V& v) {
  using S = ScalarTraits<V>;
  return std::isfinite(static_cast<double>(S::re(v))) && std::isfinite(static_cast<double>(S::im(v)));
}

template <class V>
double magnitude(const V& v) {  // in double: |v|^2 of a small float scalar would underflow
  using S = ScalarTraits<V>;
  return std::hypot(static_cast<double>(S::re(v)), static_cast<double>(S::im(v)));
}

template <class Op, class Prec, class V>
SolveResult conjugate_gradients(const Op& A, const Prec& P, const View1<V>& b_in, const View1<V>& x,
                                const SolverOptions& o, bool require_spd) {
  using T = real_of<V>;
  using S = ScalarTraits<V>;
  const auto t0 = std::chrono::steady_clock::now();
  const Index local = A.local_size(), owned = A.owned_size();
  const double eps_bd =
      o.breakdown_tolerance >= 0 ? o.breakdown_tolerance : 64.0 * std::numeric_limits<T>::epsilon();
  const std::string method = require_spd ? "CG" : "COCG";
  SolveResult res;

  const double bnorm = std::sqrt(global_sum(A, norm2("polymech::solvers::rhs_norm", owned, b_in)));
  if (!std::isfinite(bnorm)) {
    res.status = SolveStatus::non_finite;
    res.reason = method + ": the right-hand side holds NaN or Inf";
    return res;
  }
  if (bnorm == 0.0) {
    Kokkos::deep_copy(x, V(0));
    res.history.push_back(0.0);
    res.status = SolveStatus::converged;
    return res;
  }
  // Iterate on b / |b| (and x / |b|): the same relative residuals, and no underflow of small data
  // in float (the duct's right-hand side is ~1e-5 per entry).
  View1<V> b("polymech::solvers::b_scaled", local), r("polymech::solvers::r", local), z("polymech::solvers::z", local),
      p("polymech::solvers::p", local), q("polymech::solvers::q", local);
  scale(local, T(1.0 / bnorm), b_in, b);
  scale(local, T(1.0 / bnorm), x, x);
  auto true_residual = [&] {  // r = b - A x; returns |r| / |b|
    A.apply(x, r);
    return std::sqrt(global_sum(A, residual_from_product(owned, local, b, r)));
  };
  // Jacobi: z = inv_diag .* r is formed inside the fused kernels; otherwise z = P r.
  constexpr bool jacobi = is_jacobi<Prec>::value;
  auto precondition = [&] {
    if constexpr (jacobi)
      return global_sum(A, precondition_and_dot(owned, local, P.inv_diag, r, z));
    else {
      P.apply(r, z);
      return global_sum(A, dot_with_norms("polymech::solvers::rz", owned, r, z));
    }
  };
  const bool fused = jacobi && [&] {
    if constexpr (jacobi) return P.inv_diag.extent(0) > 0;
    return false;
  }();
  bool true_known = false;
  auto finish = [&](SolveStatus st, std::string why) {
    res.status = st;
    res.reason = std::move(why);
    if (!true_known) res.true_relative_residual = true_residual();
    scale(local, T(bnorm), x, x);
    Kokkos::fence();
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  };

  double rel = true_residual();
  res.history.push_back(rel);
  double last_true = rel;
  while (true) {  // one pass per (re)start from the true residual in r
    DotNorms<V> rz = precondition();
    Kokkos::deep_copy(p, z);
    V rho = rz.dot;
    double best = rel;
    int best_at = res.iterations;
    while (rel > o.tolerance) {
      res.relative_residual = rel;
      if (res.iterations >= o.max_iterations)
        return finish(SolveStatus::max_iterations,
                      method + ": reached the iteration limit " + std::to_string(o.max_iterations) +
                          " at relative residual " + fmt(rel) + " (tolerance " + fmt(o.tolerance) + ")");
      if (!finite(rho)) return finish(SolveStatus::non_finite, method + ": r^T z is NaN/Inf");
      if (detail::magnitude(rho) <= eps_bd * std::sqrt(rz.norm2_x * rz.norm2_y))
        return finish(SolveStatus::breakdown_rho,
                      method + ": breakdown at iteration " + std::to_string(res.iterations) + ": |r^T z| = " +
                          fmt(detail::magnitude(rho)) + " is below " + fmt(eps_bd) + " |r| |z| = " +
                          fmt(eps_bd * std::sqrt(rz.norm2_x * rz.norm2_y)) +
                          " (a quasi-null residual of the complex symmetric form)");
      if (require_spd && !(S::re(rho) > 0))
        return finish(SolveStatus::not_positive_definite, "CG: r^T z = " + fmt(static_cast<double>(S::re(rho))) +
                                                              " <= 0: the preconditioner is not positive definite");

      A.apply(p, q);
      const DotNorms<V> pq = global_sum(A, dot_with_norms("polymech::solvers::pAp", owned, p, q));
      const V mu = pq.dot;
      if (!finite(mu)) return finish(SolveStatus::non_finite, method + ": p^T A p is NaN/Inf");
      if (detail::magnitude(mu) <= eps_bd * std::sqrt(pq.norm2_x * pq.norm2_y))
        return finish(SolveStatus::breakdown_pap, method + ": breakdown at iteration " +
                                                      std::to_string(res.iterations) + ": |p^T A p| = " +
                                                      fmt(detail::magnitude(mu)) + " is below " + fmt(eps_bd) +
                                                      " |p| |A p| = " + fmt(eps_bd * std::sqrt(pq.norm2_x * pq.norm2_y)));
      if (require_spd && !(S::re(mu) > 0))
        return finish(SolveStatus::not_positive_definite, "CG: p^T A p = " + fmt(static_cast<double>(S::re(mu))) +
                                                              " <= 0: the operator is not positive definite");
      const V alpha = rho / mu;
      double rr = 0.0;
      if constexpr (jacobi) {
        if (fused) {
          rz = global_sum(A, update_and_precondition(owned, local, alpha, p, q, x, r, P.inv_diag));
          rr = rz.norm2_x;
        } else {
          rr = global_sum(A, update_solution_and_residual(owned, local, alpha, p, q, x, r));
        }
      } else {
        rr = global_sum(A, update_solution_and_residual(owned, local, alpha, p, q, x, r));
      }
      ++res.iterations;
      rel = std::sqrt(rr);
      res.relative_residual = rel;
      res.history.push_back(rel);
      if (o.monitor) o.monitor(res.iterations, rel);
      if (!std::isfinite(rel))
        return finish(SolveStatus::non_finite,
                      method + ": the residual became NaN/Inf at iteration " + std::to_string(res.iterations));
      if (rel <= o.tolerance) break;
      if (rel < 0.9 * best) {
        best = rel;
        best_at = res.iterations;
      } else if (res.iterations - best_at >= o.stagnation_window) {
        return finish(SolveStatus::stagnated, method + ": stagnated: no 10 % reduction of the best residual " +
                                                  fmt(best) + " in " + std::to_string(o.stagnation_window) +
                                                  " iterations (at iteration " + std::to_string(res.iterations) + ")");
      }
      if (!fused) rz = precondition();
      const V beta = rz.dot / rho;
      rho = rz.dot;
      if constexpr (jacobi) {
        if (fused)
          update_direction_jacobi(local, beta, P.inv_diag, r, p);
        else
          update_direction(local, beta, z, p);
      } else {
        update_direction(local, beta, z, p);
      }
    }
    const double tr = true_residual();  // r now holds b - A x
    res.true_relative_residual = tr;
    true_known = true;
    if (!std::isfinite(tr)) return finish(SolveStatus::non_finite, method + ": the true residual is NaN/Inf");
    if (tr <= o.tolerance) return finish(SolveStatus::converged, "");
    const bool progress = res.restarts == 0 || tr < 0.5 * last_true;
    if (res.restarts >= o.max_restarts || !progress)
      return finish(SolveStatus::stagnated,
                    method + ": the recursive residual reached " + fmt(rel) + " but the true residual " + fmt(tr) +
                        " stays above the tolerance " + fmt(o.tolerance) + " after " + std::to_string(res.restarts) +
                        " restart(s): the attainable accuracy in " + (sizeof(T) == 4 ? "float" : "double") +
                        " precision");
    true_known = false;
    last_true = tr;
    rel = tr;
    ++res.restarts;
    res.restart_iterations.push_back(res.iterations);
  }
}

}  // namespace detail

// COCG with Jacobi preconditioning (inv_diag empty: none) for complex symmetric operators.
// x holds the initial guess on entry and the solution on exit.
template <class Op, class V>
SolveResult cocg(const Op& A, const View1<V>& inv_diag, const View1<V>& b, const View1<V>& x,
                 const SolverOptions& options = {}) {
  return detail::conjugate_gradients(A, detail::JacobiPreconditioner<V>{inv_diag}, b, x, options, false);
}

// COCG with a linear, complex symmetric preconditioner P (z = P r by P.apply(r, z)).
template <class Op, class Prec, class V>
SolveResult cocg_preconditioned(const Op& A, const Prec& P, const View1<V>& b, const View1<V>& x,
                                const SolverOptions& options = {}) {
  return detail::conjugate_gradients(A, P, b, x, options, false);
}

// CG with Jacobi preconditioning for real symmetric positive definite operators.
template <class Op, class T>
SolveResult cg(const Op& A, const View1<T>& inv_diag, const View1<T>& b, const View1<T>& x,
               const SolverOptions& options = {}) {
  static_assert(!ScalarTraits<T>::is_complex, "cg is for real SPD operators; use cocg for complex symmetric ones");
  return detail::conjugate_gradients(A, detail::JacobiPreconditioner<T>{inv_diag}, b, x, options, true);
}

// CG with a linear, symmetric positive definite preconditioner P.
template <class Op, class Prec, class T>
SolveResult cg_preconditioned(const Op& A, const Prec& P, const View1<T>& b, const View1<T>& x,
                              const SolverOptions& options = {}) {
  static_assert(!ScalarTraits<T>::is_complex, "cg is for real SPD operators; use cocg for complex symmetric ones");
  return detail::conjugate_gradients(A, P, b, x, options, true);
}

}  // namespace polymech::solvers
