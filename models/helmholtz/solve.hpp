// Solving the Helmholtz model's system, eq. (16), and its results (seed 002 paper 3): the right-hand
// side (the vibrating load of eq. (20) less the Dirichlet lifting), COCG with Jacobi, Chebyshev or
// p-multigrid preconditioning (preconditioners.hpp), the operator's apply rate, the L2 error of eq. (28)
// and host copies of the solution. Out-of-class members of Helmholtz<T> (helmholtz.hpp, which includes
// this file after the class): compiled once, in models/helmholtz/helmholtz.cpp.
#pragma once

#include <chrono>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "helmholtz/helmholtz.hpp"
#include "helmholtz/preconditioners.hpp"
#include "solvers/krylov.hpp"

namespace polymech::helmholtz {

namespace detail {

template <class T>
void to_double(const View1<Kokkos::complex<T>>& from, const View1<Kokkos::complex<double>>& to) {
  Kokkos::parallel_for(
      "polymech::helmholtz::to_double", range(static_cast<Index>(from.extent(0))), KOKKOS_LAMBDA(const Index i) {
        to(i) = Kokkos::complex<double>(static_cast<double>(from(i).real()), static_cast<double>(from(i).imag()));
      });
}

template <class V>
void subtract(const View1<V>& a, const View1<V>& b) {  // a -= b
  Kokkos::parallel_for(
      "polymech::helmholtz::lift_rhs", range(static_cast<Index>(a.extent(0))), KOKKOS_LAMBDA(const Index i) { a(i) -= b(i); });
}

}  // namespace detail

template <class T>
void Helmholtz<T>::right_hand_side(const View1<C>& rhs, const View1<C>& x0) const {
  Kokkos::deep_copy(rhs, C(0));
  Kokkos::deep_copy(x0, C(0));
  if (d_.vibrating.faces() > 0) fem::add_face_load(d_.vibrating, rhs);
  if (d_.constrained.extent(0) > 0) {
    fem::set_constrained_values(d_.constrained, d_.dirichlet_values, x0);
    View1<C> lift("polymech::helmholtz::dirichlet_lift", rhs.extent(0));
    d_.op.apply_unconstrained(x0, lift);
    detail::subtract(rhs, lift);
    fem::set_constrained_values(d_.constrained, d_.dirichlet_values, rhs);
  }
}

template <class T>
solvers::SolveResult Helmholtz<T>::solve(const solvers::SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const Index n = d_.op.local_size();
  View1<C> rhs("polymech::helmholtz::rhs", n);
  right_hand_side(rhs, solution_);
  View1<C> inv;
  if (cfg_.preconditioner == Preconditioner::chebyshev || cfg_.preconditioner == Preconditioner::pmg) {
    const auto tp = std::chrono::steady_clock::now();
    if (cfg_.preconditioner == Preconditioner::chebyshev) {
      const ChebyshevPreconditioner<T> P(d_, cfg_);
      preconditioner_ = P.describe();
      preconditioner_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
      result_ = solvers::cocg_preconditioned(d_.op, P, rhs, solution_, options);
    } else {
      if (d_.comm->size() > 1)
        throw std::invalid_argument("helmholtz: preconditioner 'pmg' runs on one part only (its transfers have no halo "
                                    "exchange); allowed with " + std::to_string(d_.comm->size()) + " ranks: jacobi, "
                                    "chebyshev, none");
      const PMultigrid<T> P(d_, cfg_);
      preconditioner_ = P.describe();
      preconditioner_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
      result_ = solvers::cocg_preconditioned(d_.op, P, rhs, solution_, options);
    }
    Kokkos::fence();
    solve_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result_;
  }
  if (cfg_.preconditioner == Preconditioner::jacobi) inv = jacobi_inverse_diagonal();
  result_ = solvers::cocg(d_.op, inv, rhs, solution_, options);
  Kokkos::fence();
  solve_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result_;
}

template <class T>
double Helmholtz<T>::apply_rate(int applies) const {
  const Index n = d_.op.local_size();
  View1<C> x("polymech::helmholtz::rate_x", n), y("polymech::helmholtz::rate_y", n);
  Kokkos::deep_copy(x, C(1));
  d_.op.apply(x, y);
  Kokkos::fence();
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < applies; ++k) d_.op.apply(x, y);
  Kokkos::fence();
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  d_.comm->max(&s, 1);  // the slowest part
  return s > 0 ? static_cast<double>(d_.dofs.count) * applies / s : 0.0;
}

template <class T>
fem::ErrorIntegrals Helmholtz<T>::l2_error() const {
  if (field_.kind == AnalyticKind::none) throw std::invalid_argument("helmholtz: this case has no analytic field");
  if (d_.op.halo()) d_.op.halo()->update(solution_);  // the ghosts of the elements this part integrates
  View1<Kokkos::complex<double>> u("polymech::helmholtz::solution_double", solution_.extent(0));
  detail::to_double(solution_, u);
  fem::ErrorIntegrals e = fem::l2_error(cfg_.order, d_.error_dofs, d_.x, u, field_);
  double v[3] = {e.error2, e.reference2, e.volume};
  d_.comm->sum(v, 3);
  return {v[0], v[1], v[2]};
}

template <class T>
std::vector<std::complex<double>> Helmholtz<T>::host_solution() const {
  auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), solution_);
  if (d_.comm->size() == 1) {
    std::vector<std::complex<double>> out(m.extent(0));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {static_cast<double>(m(i).real()), static_cast<double>(m(i).imag())};
    return out;
  }
  // owned values with their global indices, gathered on rank 0
  std::vector<double> mine;
  mine.reserve(3 * static_cast<std::size_t>(d_.layout.owned));
  for (Index i = 0; i < d_.layout.owned; ++i)
    mine.insert(mine.end(), {static_cast<double>(d_.layout.global_of_local[i]), static_cast<double>(m(i).real()),
                             static_cast<double>(m(i).imag())});
  const std::vector<double> all = d_.comm->gather(mine);
  std::vector<std::complex<double>> out(d_.comm->rank() == 0 ? static_cast<std::size_t>(d_.dofs.count) : 0);
  for (std::size_t k = 0; k + 2 < all.size(); k += 3) out[static_cast<std::size_t>(all[k])] = {all[k + 1], all[k + 2]};
  return out;
}

// The inverse diagonal of the operator for Jacobi preconditioning; a diagonal that vanishes or is not
// finite on any part is a std::runtime_error saying where.
template <class T>
auto Helmholtz<T>::jacobi_inverse_diagonal() const -> View1<C> {
  const Index n = d_.op.local_size();
  View1<C> diag("polymech::helmholtz::diagonal", n);
  d_.op.diagonal(diag);
  View1<C> inv("polymech::helmholtz::inverse_diagonal", n);
  auto s = solvers::jacobi_inverse(d_.op.owned_size(), n, diag, inv);
  {  // over all parts
    double v[3] = {-s.min_abs, s.max_abs, static_cast<double>(s.non_finite)};
    d_.comm->max(v, 2);
    d_.comm->sum(v + 2, 1);
    if (-v[0] < s.min_abs) s.argmin = -1;
    s.min_abs = -v[0];
    s.max_abs = v[1];
    s.non_finite = static_cast<Index>(v[2]);
  }
  if (s.non_finite > 0 || !(s.min_abs > 1e-12 * s.max_abs))
    throw std::runtime_error("helmholtz: the operator diagonal " +
                             (s.non_finite > 0 ? std::string("is not finite")
                                               : "vanishes (|d| = " + models::format_g(s.min_abs) + " vs max " +
                                                     models::format_g(s.max_abs) + ") at DoF " +
                                                     std::to_string(s.argmin) + " " + where(s.argmin)) +
                             ": Jacobi preconditioning is impossible at this k h; refine the mesh or set "
                             "solver.preconditioner = \"none\"");
  return inv;
}

}  // namespace polymech::helmholtz
