// Implicit dynamics at finite strain (issue 34: "dynamics at finite strain"; the structure of the Turek-Hron
// CSM3 test and of the FSI benchmarks of issue 36): the total-Lagrangian hyperelastic solid of
// models/solid/hyperelastic.hpp with the consistent mass, integrated by Newmark's scheme (average acceleration by
// default: beta = 1/4, gamma = 1/2; second order, unconditionally stable for linear problems, no numerical
// damping). At every step the equation of motion at t_{n+1},
//   rho M a_{n+1} + f_int(u_{n+1}) = s(t_{n+1}) f_ext,   a_{n+1} = c0 (u_{n+1} - u_pred),
//   u_pred = u_n + dt v_n + dt^2 (1/2 - beta) a_n,  c0 = 1 / (beta dt^2),
// is solved by the model's Newton iteration (its line search, its exact tangent plus c0 rho M: Hyperelastic::
// set_inertia), then v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}). s(t) is the load factor of the dead
// loads and Dirichlet values (default 1: loads applied at t = 0, as CSM3 does). No damping.
//
// Energy: E = 1/2 rho v^T M v + W(u) - s f_ext . u (kinetic + strain + the dead loads' potential, constant s). The
// average-acceleration rule conserves it exactly for linear problems; at finite strain it conserves it to
// O(dt^2) per unit time (tests/solid/test_solid_finite_strain_dynamics.cpp measures the drift).
#pragma once

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/hyperelastic.hpp"
#include "solid/start_mass.hpp"

namespace polymech::solid {

struct FiniteStrainDynamicsOptions {
  double dt = 0.0;
  double density = 1.0;
  double beta = 0.25, gamma = 0.5;
  std::function<double(double)> load_factor;  // s(t); empty: 1
};

template <class T, int D>
class HyperelasticNewmark {
 public:
  HyperelasticNewmark(const Config<D>& c, const HyperelasticLaw& law, const FiniteStrainDynamicsOptions& o,
                      const std::vector<FollowerPressure>& pressures = {},
                      const NewtonOptions& newton = finite_strain_newton_options())
      : solid_(c, law, pressures, dynamics_newton(newton)), o_(o) {
    if (!(o.dt > 0.0) || !std::isfinite(o.dt)) throw std::invalid_argument("solid::HyperelasticNewmark: dt must be positive");
    if (!(o.density > 0.0)) throw std::invalid_argument("solid::HyperelasticNewmark: density must be positive");
    if (!(o.beta > 0.0) || !(o.gamma >= 0.5))
      throw std::invalid_argument("solid::HyperelasticNewmark: Newmark needs beta > 0 and gamma >= 1/2");
    const Index n = solid_.dof_count();
    v_ = View1<T>("polymech::solid::fsd_velocity", n);
    a_ = View1<T>("polymech::solid::fsd_acceleration", n);
    u_pred_ = View1<T>("polymech::solid::fsd_predictor", n);
    u_old_ = View1<T>("polymech::solid::fsd_previous", n);
    work_ = View1<T>("polymech::solid::fsd_work", n);
  }

  Hyperelastic<T, D>& solid() { return solid_; }
  const Hyperelastic<T, D>& solid() const { return solid_; }
  double time() const { return t_; }
  std::int64_t steps() const { return steps_; }
  const View1<T>& displacement() const { return solid_.displacement(); }
  const View1<T>& velocity() const { return v_; }
  int last_newton_iterations() const { return last_iterations_; }
  std::int64_t newton_iterations() const { return total_iterations_; }

  // Start from rest at the current displacement (the reference configuration unless set otherwise) with the
  // loads at s(0): a_0 = (rho M)^-1 (s(0) f_ext - f_int(u_0)) on the free DoFs, the assembled mass factorised once.
  void start() {
    Kokkos::deep_copy(v_, T(0));
    solid_.set_inertia(0.0, o_.density, u_pred_);  // quasi-static residual
    View1<T> r("polymech::solid::fsd_initial_residual", solid_.dof_count());
    const double rn = solid_.residual(solid_.displacement(), s(0.0), r);
    if (!std::isfinite(rn)) throw std::runtime_error("solid::HyperelasticNewmark: the initial state does not evaluate");
    solvers::HostSparseLU lu;
    factor_start_mass(lu, solid_.assembly_input(), o_.density, solid_.constrained_mask());
    solvers::scale(solid_.dof_count(), T(-1), r, r);  // s f_ext - f_int, zero on the constrained rows
    detail::HostLUPreconditioner<T>{&lu}.apply(r, a_);
    t_ = 0.0;
    steps_ = 0;
    started_ = true;
    energy0_ = energy();
  }

  // One step to t + dt. Throws std::runtime_error when Newton fails (the reason and the time).
  void step() {
    if (!started_) start();
    const double dt = o_.dt, b = o_.beta, g = o_.gamma, c0 = 1.0 / (b * dt * dt);
    {
      const auto up = u_pred_, u = solid_.displacement(), v = v_, a = a_, uo = u_old_;
      const T tdt = static_cast<T>(dt), k = static_cast<T>(dt * dt * (0.5 - b));
      Kokkos::parallel_for(
          "polymech::solid::fsd_predict", Kokkos::RangePolicy<ExecSpace>(0, solid_.dof_count()), KOKKOS_LAMBDA(const Index i) {
            uo(i) = u(i);
            up(i) = u(i) + tdt * v(i) + k * a(i);
          });
    }
    solid_.set_inertia(c0, o_.density, u_pred_);
    StepResult r;
    const double t1 = t_ + dt;
    if (!solid_.solve_step(s(t1), r))
      throw std::runtime_error("solid::HyperelasticNewmark: Newton failed at t = " + models::format_g(t1) + ": " +
                               solid_.last_failure());
    last_iterations_ = r.newton_iterations;
    total_iterations_ += r.newton_iterations;
    {
      const auto up = u_pred_, u = solid_.displacement(), v = v_, a = a_;
      const T c = static_cast<T>(c0), w0 = static_cast<T>(dt * (1.0 - g)), w1 = static_cast<T>(dt * g);
      Kokkos::parallel_for(
          "polymech::solid::fsd_update", Kokkos::RangePolicy<ExecSpace>(0, solid_.dof_count()), KOKKOS_LAMBDA(const Index i) {
            const T an = c * (u(i) - up(i));
            v(i) += w0 * a(i) + w1 * an;
            a(i) = an;
          });
    }
    t_ = t1;
    ++steps_;
  }

  // 1/2 rho v^T M v + W(u) - s f_ext . u at the current state (W of the last evaluation: the converged one).
  double energy() const {
    Kokkos::deep_copy(work_, T(0));
    solid_.add_mass(o_.density, v_, work_);
    const double kinetic = 0.5 * solid_.dot(v_, work_);
    const double potential = -s(t_) * solid_.dot(solid_.external_force(), solid_.displacement());
    return kinetic + solid_.strain_energy() + potential;
  }
  double kinetic_energy() const {
    Kokkos::deep_copy(work_, T(0));
    solid_.add_mass(o_.density, v_, work_);
    return 0.5 * solid_.dot(v_, work_);
  }
  double initial_energy() const { return energy0_; }

 private:
  static NewtonOptions dynamics_newton(NewtonOptions o) {
    o.secant_predictor = false;  // the load factor does not move: the step starts from u_n
    o.max_cuts = 0;              // a failed step is the driver's to handle (no load cutting inside a time step)
    return o;
  }
  double s(double t) const { return o_.load_factor ? o_.load_factor(t) : 1.0; }

  Hyperelastic<T, D> solid_;
  FiniteStrainDynamicsOptions o_;
  View1<T> v_, a_, u_pred_, u_old_;
  mutable View1<T> work_;
  double t_ = 0.0, energy0_ = 0.0;
  std::int64_t steps_ = 0, total_iterations_ = 0;
  int last_iterations_ = 0;
  bool started_ = false;
};

}  // namespace polymech::solid
