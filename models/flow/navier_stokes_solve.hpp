// The solve of flow::NavierStokes2D (models/flow/navier_stokes.hpp): the element kernel and the host scatter
// into the residual, the forces on the obstacle and the CSR Jacobian; Newton (Oseen steps first, the chord
// method for time steps); the steady solve and the BDF2 step.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "flow/navier_stokes_model.hpp"

namespace polymech::flow {

// The steady problem by Newton (Oseen steps first when picard_steps > 0).
inline NewtonReport NavierStokes2D::solve_steady() {
  apply_dirichlet(time_);
  return newton(0.0, false);
}

// One step of dt: BDF2 (backward Euler for the first step after a start or a change of dt).
inline NewtonReport NavierStokes2D::step(double dt) {
  if (!(dt > 0)) throw std::invalid_argument("flow: the time step must be positive");
  const bool bdf2 = steps_ > 0 && dt == last_dt_;
  const double ct = bdf2 ? 1.5 / dt : 1.0 / dt;
  std::vector<double> star(u_host_.size());
  for (std::size_t k = 0; k < star.size(); ++k) star[k] = bdf2 ? (4.0 * u_host_[k] - u_prev_[k]) / 3.0 : u_host_[k];
  copy_to(Ustar_, star);
  u_prev2_ = u_prev_;
  u_prev_ = u_host_;
  time_ += dt;
  apply_dirichlet(time_);
  // the free values start from the extrapolation 2 u^n - u^(n-1) (BDF2) or u^n
  if (bdf2)
    for (std::size_t k = 0; k < u_host_.size(); ++k)
      if (free_[k] >= 0) u_host_[k] = 2.0 * u_prev_[k] - u_prev2_[k];
  if (cfg_.smagorinsky > 0.0) {  // the step's eddy viscosity from the extrapolated velocity (FlowConfig::smagorinsky)
    if (in_.eddy.extent(0) != static_cast<std::size_t>(ne_)) in_.eddy = View2<double>("polymech::flow::eddy_viscosity", static_cast<std::size_t>(ne_), kPoints);
    std::vector<double> v = u_host_;
    if (bdf2)
      for (std::size_t k = 0; k < v.size(); ++k) v[k] = 2.0 * u_prev_[k] - u_prev2_[k];
    copy_to(U_, v);
    smagorinsky_viscosity(in_, U_, cfg_.smagorinsky);
    Kokkos::fence();
  }
  const NewtonReport r = newton(ct, true);
  last_dt_ = dt;
  ++steps_;
  return r;
}

// Assembles the residual only (no Jacobian) at the current state and returns the forces on kObstacle.
inline Forces NavierStokes2D::evaluate_forces(double ct) {
  assemble(ct, false, false);
  return forces_;
}

inline void NavierStokes2D::copy_to(const View1<double>& v, const std::vector<double>& h) {
  auto m = Kokkos::create_mirror_view(v);
  for (std::size_t k = 0; k < h.size(); ++k) m(k) = h[k];
  Kokkos::deep_copy(v, m);
}

// The element kernel, then the host scatter: the full residual (forces) and, when asked, the free Jacobian.
inline void NavierStokes2D::assemble(double ct, bool jacobian, bool picard) {
  copy_to(U_, u_host_);
  if (ct == 0.0) Kokkos::deep_copy(Ustar_, 0.0);
  const ElementCoefficients co{cfg_.rho, cfg_.rho * cfg_.nu, ct};
  const std::clock_t c0 = std::clock();
  element_residual_jacobian(in_, basis_, co, U_, Ustar_, W_, Re_, Ke_, jacobian, picard);
  Kokkos::fence();
  const std::clock_t c1 = std::clock();
  timings_.element_kernel += static_cast<double>(c1 - c0) / CLOCKS_PER_SEC;
  ++timings_.assemblies;
  struct AddOnExit {
    FlowTimings& t;
    std::clock_t c;
    ~AddOnExit() { t.scatter += static_cast<double>(std::clock() - c) / CLOCKS_PER_SEC; }
  } add_scatter{timings_, c1};
  auto Rh = Kokkos::create_mirror_view(Re_);
  Kokkos::deep_copy(Rh, Re_);
  r_full_.assign(static_cast<std::size_t>(ndof_), 0.0);
  for (std::int64_t e = 0; e < ne_; ++e)
    for (int k = 0; k < kElementDofs; ++k) r_full_[static_cast<std::size_t>(elem_dofs_[static_cast<std::size_t>(e) * kElementDofs + k])] += Rh(e, k);
  forces_ = Forces{};
  for (std::int64_t n = 0; n < nn_; ++n)
    if (mesh_.tags[static_cast<std::size_t>(n)] & kObstacle) {
      forces_.drag -= r_full_[2 * static_cast<std::size_t>(n)];
      forces_.lift -= r_full_[2 * static_cast<std::size_t>(n) + 1];
    }
  if (!jacobian) return;
  auto Kh = Kokkos::create_mirror_view(Ke_);
  Kokkos::deep_copy(Kh, Ke_);
  std::fill(values_.begin(), values_.end(), 0.0);
  const std::size_t per = static_cast<std::size_t>(kElementDofs) * kElementDofs;
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* pos = &position_[static_cast<std::size_t>(e) * per];
    for (std::size_t k = 0; k < per; ++k)
      if (pos[k] >= 0) values_[static_cast<std::size_t>(pos[k])] += Kh(e, k);
  }
}

inline NewtonReport NavierStokes2D::newton(double ct, bool transient) {
  NewtonReport rep;
  std::vector<double> rhs(static_cast<std::size_t>(nfree_));
  double previous_update = 0.0, update_u = 0.0, update_p = 0.0;
  for (int it = 0;; ++it) {
    const bool last = it >= cfg_.newton_max;
    // velocities and pressures each against their own scale (one max over both mixes units: at the start of
    // a ramped inflow max |u| ~ 1e-5 while the pressure's round-off is ~1e-13, and Newton never "converged")
    const bool converged = it > 0 && update_u <= cfg_.newton_tol * std::max(1e-300, umax()) &&
                           update_p <= cfg_.newton_tol * std::max(1e-300, pmax());
    const bool refactor = !(transient && cfg_.chord) || it == 0 || (it >= 2 && rep.update > previous_update / 3.0);
    previous_update = rep.update;
    assemble(ct, !(converged || last) && refactor, it < cfg_.picard_steps);
    double rmax = 0.0;
    for (std::int64_t k = 0; k < ndof_; ++k) {
      const std::int64_t f = free_[static_cast<std::size_t>(k)];
      if (f < 0) continue;
      rhs[static_cast<std::size_t>(f)] = r_full_[static_cast<std::size_t>(k)];
      rmax = std::max(rmax, std::abs(r_full_[static_cast<std::size_t>(k)]));
    }
    rep.residual = rmax;
    rep.iterations = it;
    if (!std::isfinite(rmax)) return rep;
    if (converged) {
      rep.converged = true;
      return rep;
    }
    if (last) return rep;
    const std::clock_t c0 = std::clock();
    if (refactor) {
      lu_.factor(nfree_, rows_, cols_, values_);
      ++timings_.factorizations;
    }
    const std::clock_t c1 = std::clock();
    lu_.solve(rhs.data());
    timings_.factor += static_cast<double>(c1 - c0) / CLOCKS_PER_SEC;
    timings_.solve += static_cast<double>(std::clock() - c1) / CLOCKS_PER_SEC;
    update_u = update_p = 0.0;
    for (std::int64_t k = 0; k < ndof_; ++k) {
      const std::int64_t f = free_[static_cast<std::size_t>(k)];
      if (f < 0) continue;
      u_host_[static_cast<std::size_t>(k)] -= rhs[static_cast<std::size_t>(f)];
      double& d = k < 2 * nn_ ? update_u : update_p;
      d = std::max(d, std::abs(rhs[static_cast<std::size_t>(f)]));
    }
    rep.update = std::max(update_u, update_p);
  }
}

inline double NavierStokes2D::pmax() const {
  double m = 0.0;
  for (std::int64_t k = 2 * nn_; k < ndof_; ++k) m = std::max(m, std::abs(u_host_[static_cast<std::size_t>(k)]));
  return m;
}

inline double NavierStokes2D::umax() const {
  double m = 0.0;
  for (std::int64_t n = 0; n < 2 * nn_; ++n) m = std::max(m, std::abs(u_host_[static_cast<std::size_t>(n)]));
  return m;
}

}  // namespace polymech::flow
