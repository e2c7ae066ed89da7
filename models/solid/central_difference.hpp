// Explicit central differences of the linear elastic solid (issue 34; the equations of motion and the
// energies: solid_dynamics.hpp).
//
// solid::CentralDifference: explicit central differences with the lumped mass (velocity form; Newmark's beta = 0,
// gamma = 1/2 member, Hughes ch. 9):
//   v_{n+1/2} = v_n + dt/2 a_n,  u_{n+1} = u_n + dt v_{n+1/2},
//   a_{n+1} = M_L^-1 (s_f f - K (u_{n+1} + beta_K v_{n+1/2})) - alpha v_{n+1/2},  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
// (one fused matrix-free elastic apply and two vector kernels per step). Conditionally stable: dt <=
// dt_crit = (2 / omega_max) (sqrt(1 + xi^2) - xi), xi = alpha / (2 omega_max) + beta_K omega_max / 2 the damping
// ratio of the highest mode (Hughes ch. 9; Belytschko, Liu, Moran & Elkhodary 2014, §6.3), omega_max^2 the largest
// eigenvalue of M_L^-1 K, estimated by power iteration (its Rayleigh quotient is a lower bound, so the
// estimate of dt_crit is an upper bound: the safety factor, 0.9 by default, covers the gap). A requested
// dt above the estimate is refused with std::invalid_argument unless `allow_unstable`.
#pragma once

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/solid_dynamics.hpp"
#include "solvers/host_sparse_lu.hpp"
#include "solvers/krylov.hpp"

namespace polymech::solid {

struct ExplicitOptions {
  double safety = 0.9;          // dt = safety x dt_crit when no time step is given
  bool allow_unstable = false;  // accept a dt above the estimated dt_crit (to show the instability)
  int power_iterations = 500;   // maximum power iterations for omega_max
  double power_tolerance = 1e-6;  // relative change of the Rayleigh quotient that ends them
};

// Explicit central differences with the lumped mass (see the header).
template <class T, int D>
class CentralDifference : public SolidDynamics<T, D> {
  using Base = SolidDynamics<T, D>;

 public:
  // dt <= 0: safety x dt_crit.
  CentralDifference(const Config<D>& c, const DynamicsOptions& o, double dt = 0.0, const ExplicitOptions& e = {})
      : Base(c, o), eopt_(e) {
    this->lumped_kinetic_ = true;
    estimate_omega_max();
    set_time_step(dt > 0.0 ? dt : e.safety * dt_crit_);
  }

  double omega_max() const { return omega_max_; }
  int power_iterations_used() const { return power_its_; }
  double critical_time_step() const { return dt_crit_; }
  double time_step() const { return dt_; }
  // Throws std::invalid_argument for dt > dt_crit unless allow_unstable.
  void set_time_step(double dt) {
    if (!(dt > 0.0)) throw std::invalid_argument("solid::CentralDifference: time step " + models::format_g(dt) + " (allowed: > 0)");
    if (dt > dt_crit_ && !eopt_.allow_unstable)
      throw std::invalid_argument("solid::CentralDifference: time step " + models::format_g(dt) +
                                  " exceeds the critical time step " + models::format_g(dt_crit_) +
                                  " (2 / omega_max with omega_max = " + models::format_g(omega_max_) +
                                  " from power iteration on M_L^-1 K, reduced for damping): the scheme is unstable; "
                                  "use dt <= " + models::format_g(eopt_.safety * dt_crit_) +
                                  " or set ExplicitOptions::allow_unstable");
    dt_ = dt;
  }

  // a_0 = M_L^-1 (s_f f - K (u + beta_K v)) - alpha v on the free DoFs, prescribed on the constrained ones.
  void start() {
    this->prescribe(this->t_, this->u_, this->v_, this->a_);
    const auto u = this->u_, v = this->v_, w = this->work_;
    const T bk = T(this->opt_.rayleigh_stiffness);
    Kokkos::parallel_for(
        "polymech::solid::cd_start", range(this->dof_count()), KOKKOS_LAMBDA(const Index i) { w(i) = u(i) + bk * v(i); });
    this->stiffness_apply(w, this->work2_);
    accelerate(this->load_factor(this->t_), this->v_);
    if (this->opt_.track_energy) {
      if (this->has_motion()) support_ = support(this->a_, this->v_);  // before energies(), which reuses work2
      this->energy_.initial = this->energies().total();
    }
    this->started_ = true;
  }

  // One step t -> t + dt.
  void step() {
    if (!this->started_) start();
    const Index n = this->dof_count();
    const double t0 = this->t_, t1 = t0 + dt_;
    const T dt = T(dt_), h = T(0.5 * dt_), bk = T(this->opt_.rayleigh_stiffness);
    const bool track = this->opt_.track_energy;
    if (track && du_.extent(0) == 0) du_ = View1<T>("polymech::solid::cd_du", n);
    const auto u = this->u_, v = this->v_, a = this->a_, w = this->work_, du = du_;
    const auto fixed = this->is_fixed_;
    // the prescribed DoFs: u(t1), v(t + dt/2) for the damping force
    const TimeFunction& bm = this->opt_.base_motion;
    const T s0 = T(bm.s(t0)), s1 = T(bm.s(t1)), sh = T(bm.ds(t0 + 0.5 * dt_));
    const auto g = this->g_full_;
    Kokkos::parallel_for(
        "polymech::solid::cd_predict", range(n), KOKKOS_LAMBDA(const Index i) {
          T d, vh;
          if (fixed(i)) {
            d = (s1 - s0) * g(i);
            vh = sh * g(i);
          } else {
            vh = v(i) + h * a(i);
            d = dt * vh;
          }
          v(i) = vh;
          u(i) += d;
          w(i) = u(i) + bk * vh;
          if (track) du(i) = d;
        });
    this->stiffness_apply(w, this->work2_);  // K (u_{n+1} + beta_K v_{n+1/2})
    if (track) accumulate_damping();  // uses v = v_{n+1/2}
    const double sf0 = this->load_factor(t0), sf1 = this->load_factor(t1);
    accelerate(sf1, this->v_);
    // v_{n+1} = v_{n+1/2} + dt/2 a_{n+1} on the free DoFs
    Kokkos::parallel_for(
        "polymech::solid::cd_velocity", range(n), KOKKOS_LAMBDA(const Index i) {
          if (!fixed(i)) v(i) += h * a(i);
        });
    this->prescribe(t1, View1<T>(), this->v_, this->a_);
    this->t_ = t1;
    ++this->steps_;
    if (track) accumulate_work(sf0, sf1);
  }

  void advance(long steps) {
    for (long k = 0; k < steps; ++k) step();
  }

 public:
  // Implementation. (Public only because nvcc's extended lambdas may not live in private or protected member
  // functions, docs/DEVELOPING.md.)
  // a = (s_f f - work2) / m - alpha vh on the free DoFs (work2 = K (u + beta_K vh)).
  void accelerate(double sf, const View1<T>& vh) {
    const auto a = this->a_, y = this->work2_, f = this->f_ext_, m = this->mass_;
    const auto fixed = this->is_fixed_;
    const T s = T(sf), alpha = T(this->opt_.rayleigh_mass);
    Kokkos::parallel_for(
        "polymech::solid::cd_accelerate", range(this->dof_count()), KOKKOS_LAMBDA(const Index i) {
          if (!fixed(i)) a(i) = (s * f(i) - y(i)) / m(i) - alpha * vh(i);
        });
  }

  // support force M_L a + alpha M_L v + K (u + beta_K v) on every DoF (work2 holds the K term)
  View1<T> support(const View1<T>& a, const View1<T>& v) const {
    View1<T> F("polymech::solid::cd_support", this->dof_count());
    const auto y = this->work2_, m = this->mass_;
    const T alpha = T(this->opt_.rayleigh_mass);
    Kokkos::parallel_for(
        "polymech::solid::cd_support", range(this->dof_count()),
        KOKKOS_LAMBDA(const Index i) { F(i) = m(i) * (a(i) + alpha * v(i)) + y(i); });
    return F;
  }

  // dissipation du^T C v_{n+1/2} (the K part needs its own apply)
  void accumulate_damping() {
    const Index n = this->dof_count();
    const T alpha = T(this->opt_.rayleigh_mass), bk = T(this->opt_.rayleigh_stiffness);
    double diss = 0.0;
    if (alpha != T(0) || bk != T(0)) {
      const auto du = du_, v = this->v_, m = this->mass_;
      if (kv_.extent(0) == 0) kv_ = View1<T>("polymech::solid::cd_kv", n);
      if (bk != T(0)) this->stiffness_apply(v, kv_);
      const auto kv = kv_;
      const bool stiff = bk != T(0);
      Kokkos::parallel_reduce(
          "polymech::solid::cd_dissipation", range(n),
          KOKKOS_LAMBDA(const Index i, double& s) { s += double(du(i)) * (alpha * m(i) * v(i) + (stiff ? bk * kv(i) : T(0))); }, diss);
    }
    this->energy_.dissipated += diss;
    this->energy_.dissipated_step = diss;
  }

  void accumulate_work(double sf0, double sf1) {
    const Index n = this->dof_count();
    const auto du = du_, f = this->f_ext_;
    const auto fixed = this->is_fixed_;
    const T s = T(0.5 * (sf0 + sf1));
    double work = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::cd_external_work", range(n),
        KOKKOS_LAMBDA(const Index i, double& acc) {
          if (!fixed(i)) acc += double(du(i)) * s * f(i);
        },
        work);
    if (this->has_motion()) {
      // work2 holds K (u_{n+1} + beta_K v_{n+1/2}) of this step
      const View1<T> F1 = support(this->a_, this->v_);
      const auto F0 = support_;
      double wr = 0.0;
      Kokkos::parallel_reduce(
          "polymech::solid::cd_support_work", range(n),
          KOKKOS_LAMBDA(const Index i, double& acc) {
            if (fixed(i)) acc += double(du(i)) * T(0.5) * (F0(i) + F1(i));
          },
          wr);
      work += wr;
      support_ = F1;
    }
    this->energy_.external_work += work;
  }

  // omega_max^2: the largest eigenvalue of M_L^-1 K on the free DoFs, by power iteration from a fixed
  // pseudo-random vector (the Rayleigh quotient x^T K x / x^T M_L x of the iterate, a lower bound).
  void estimate_omega_max() {
    const Index n = this->dof_count();
    View1<T> x("polymech::solid::power_x", n), y("polymech::solid::power_y", n);
    const auto fixed = this->is_fixed_;
    Kokkos::parallel_for(
        "polymech::solid::power_start", range(n), KOKKOS_LAMBDA(const Index i) {
          // a fixed hash in [-1, 1]: rich in every mode, the same on every run and thread count
          const unsigned long long hsh = (static_cast<unsigned long long>(i) + 1ull) * 0x9E3779B97F4A7C15ull;
          const T r = T(static_cast<double>((hsh >> 11) & 0xFFFFFull) / double(0xFFFFF)) * T(2) - T(1);
          x(i) = fixed(i) ? T(0) : r;
        });
    const auto m = this->mass_;
    double lambda = 0.0;
    int it = 0;
    for (; it < eopt_.power_iterations; ++it) {
      Kokkos::deep_copy(y, T(0));
      add_elastic_apply<true>(this->op_.el, x, y);
      double xy = 0.0, xmx = 0.0;
      Kokkos::parallel_reduce(
          "polymech::solid::power_quotient", range(n),
          KOKKOS_LAMBDA(const Index i, double& s1, double& s2) {
            s1 += double(x(i)) * y(i);
            s2 += double(m(i)) * x(i) * x(i);
          },
          xy, xmx);
      const double next = xy / xmx;
      // x <- M_L^-1 K x, normalized in the M_L norm
      const T scale = T(1.0 / std::sqrt(xmx * next * next));
      Kokkos::parallel_for(
          "polymech::solid::power_update", range(n), KOKKOS_LAMBDA(const Index i) { x(i) = fixed(i) ? T(0) : scale * y(i) / m(i); });
      const bool done = it > 0 && std::fabs(next - lambda) <= eopt_.power_tolerance * next;
      lambda = next;
      if (done) break;
    }
    power_its_ = it + 1;
    if (!(lambda > 0.0)) throw std::runtime_error("solid::CentralDifference: the power iteration found no positive eigenvalue of M_L^-1 K");
    omega_max_ = std::sqrt(lambda);
    const double xi = this->opt_.rayleigh_mass / (2.0 * omega_max_) + this->opt_.rayleigh_stiffness * omega_max_ / 2.0;
    dt_crit_ = 2.0 / omega_max_ * (std::sqrt(1.0 + xi * xi) - xi);
  }

 private:
  ExplicitOptions eopt_;
  double dt_ = 0.0, dt_crit_ = 0.0, omega_max_ = 0.0;
  int power_its_ = 0;
  View1<T> du_, kv_, support_;
};

}  // namespace polymech::solid
