// Efg<T>, part: dynamics by Newmark's rule, beta = 1/4, gamma = 1/2, in the incremental form of seed 004
// eqs. (6)-(11) (config newmark_gamma > 1/2: beta = (gamma + 1/2)^2 / 4, numerically damped; gamma enters
// dv only). The state is the nodal coefficients u, v, a on the host (Eigen), copied to the device after
// each step for the J-integrals and probes. Included by efg/efg.hpp.
#pragma once

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "efg/efg.hpp"
#include "efg/host_copy.hpp"

namespace polymech::efg {

// Starts a run from rest under the load f (a Heaviside step at t = 0: a_0 = M^-1 f) and factorises the
// effective stiffness K + M / (beta dt^2) once for this dt.
template <class T>
inline void Efg<T>::start_dynamic(double dt) {
  if (!assembled_) assemble();
  const auto t0 = std::chrono::steady_clock::now();
  dt_ = dt;
  const Index n2 = 2 * nodes();
  ud_ = Eigen::VectorXd::Zero(n2);
  vd_ = Eigen::VectorXd::Zero(n2);
  Eigen::SimplicialLDLT<SparseMatrix> mass;
  mass.compute(M_);
  if (mass.info() != Eigen::Success) throw std::runtime_error("EFG: the mass matrix factorisation failed");
  ad_ = mass.solve(f_);
  factor_effective_stiffness();
  time_ = 0.0;
  step_ = 0;
  timings_.factor_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sync_dynamic();
}

// One step: K_eff du = df + r + M (v_n / (beta dt) + a_n / (2 beta)), r = f_n - K u_n - M a_n (eq. (11),
// the residual of the previous step); then da, dv from Newmark's relations. The load is constant
// after t = 0 (df = 0). With set_prescribed_growth(true) the crack first grows (efg/crack_growth.hpp).
template <class T>
inline void Efg<T>::step() {
  if (prescribed_growth_) grow_crack();
  const auto t0 = std::chrono::steady_clock::now();
  const double b = beta_, dt = dt_;
  const Eigen::VectorXd r = f_ - K_ * ud_ - M_ * ad_;
  const Eigen::VectorXd rhs = r + M_ * (vd_ * (1.0 / (b * dt)) + ad_ * (1.0 / (2 * b)));
  const Eigen::VectorXd du = keff_.solve(rhs);
  const Eigen::VectorXd da = du * (1.0 / (b * dt * dt)) - vd_ * (1.0 / (b * dt)) - ad_ * (1.0 / (2 * b));
  vd_ += dt * ad_ + gamma_ * dt * da;
  ud_ += du;
  ad_ += da;
  time_ += dt;
  ++step_;
  timings_.step_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  sync_dynamic();
}

// The effective stiffness K + M / (beta dt^2) of the current K, M and dt, factorised.
template <class T>
inline void Efg<T>::factor_effective_stiffness() {
  SparseMatrix keff = K_ + M_ * (1.0 / (beta_ * dt_ * dt_));
  keff_.compute(keff);
  if (keff_.info() != Eigen::Success) throw std::runtime_error("EFG: the effective stiffness factorisation failed");
}

// The host coefficients u, v, a to the device.
template <class T>
inline void Efg<T>::sync_dynamic() {
  detail::to_device(ud_, u_, "polymech::efg::coefficients");
  detail::to_device(vd_, v_, "polymech::efg::velocity_coefficients");
  detail::to_device(ad_, a_, "polymech::efg::acceleration_coefficients");
}

template <class T>
inline models::Health Efg<T>::health() const {
  models::Health h;
  h.what = "DoF";
  for (const Eigen::VectorXd* x : {&ud_, &vd_})
    for (Eigen::Index i = 0; i < x->size(); ++i)
      if (!std::isfinite((*x)(i))) {
        h.finite = false;
        h.first_bad = static_cast<std::int64_t>(i);
        h.problem = std::string(x == &ud_ ? "(displacement coefficient)" : "(velocity coefficient)") + " is not finite";
        return h;
      }
  return h;
}

}  // namespace polymech::efg
