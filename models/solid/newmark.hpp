// Implicit Newmark time integration of the linear elastic solid (issue 34; the equations of motion and the
// energies: solid_dynamics.hpp).
//
// solid::Newmark: Newmark's (1959) family, beta = 1/4, gamma = 1/2 (average acceleration: unconditionally
// stable, second order, no numerical damping) by default. With a0 = 1 / (beta dt^2), a1 = gamma / (beta dt),
// the predictors  u~ = a0 u_n + v_n / (beta dt) + (1 / (2 beta) - 1) a_n,
//                 v~ = a1 u_n + (gamma / beta - 1) v_n + dt (gamma / (2 beta) - 1) a_n,
// and a_{n+1} = a0 u_{n+1} - u~, v_{n+1} = a1 u_{n+1} - v~, the free rows of the equation of motion at
// t_{n+1} give the effective system (Hughes, The Finite Element Method, 2000, ch. 9, displacement form)
//   [(1 + a1 beta_K) K + (a0 + a1 alpha) M]_ff u_f = [s_f f + M (u~ + alpha v~) + K (beta_K v~)]_f
//                                                     - [M (a_c + alpha v_c) + K (u_c + beta_K v_c)]_f,
// the constrained DoFs carrying their exact prescribed u_c, v_c, a_c (the last bracket is their lifting).
// The effective matrix is factorized once with the host sparse LU (NewmarkSolver::direct, default) or
// solved matrix-free with CG preconditioned by its diagonal (K's exact diagonal, the lumped mass for M's;
// NewmarkSolver::cg); one elastic and one mass apply per step form the right-hand side.
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

enum class NewmarkSolver { direct, cg };

struct NewmarkOptions {
  double beta = 0.25, gamma = 0.5;  // average acceleration
  NewmarkSolver solver = NewmarkSolver::direct;
  solvers::SolverOptions cg;        // NewmarkSolver::cg, and the initial-acceleration solve with M
  NewmarkOptions() { cg.tolerance = 1e-12; }
};

// Implicit Newmark time integration (see the header).
template <class T, int D>
class Newmark : public SolidDynamics<T, D> {
  using Base = SolidDynamics<T, D>;

 public:
  Newmark(const Config<D>& c, const DynamicsOptions& o, double dt, const NewmarkOptions& n = {})
      : Base(c, o), nopt_(n), dt_(dt) {
    if (!(dt > 0.0)) throw std::invalid_argument("solid::Newmark: time step " + models::format_g(dt) + " (allowed: > 0)");
    if (!(n.beta > 0.0) || !(n.gamma >= 0.5))
      throw std::invalid_argument("solid::Newmark: beta = " + models::format_g(n.beta) + ", gamma = " +
                                  models::format_g(n.gamma) + " (allowed: beta > 0, gamma >= 1/2)");
    const double b = n.beta, g = n.gamma;
    c0_ = 1.0 / (b * dt * dt);
    c1_ = g / (b * dt);
    c2_ = 1.0 / (b * dt);
    c3_ = 1.0 / (2.0 * b) - 1.0;
    c4_ = g / b - 1.0;
    c5_ = dt * (g / (2.0 * b) - 1.0);
    cK_ = 1.0 + c1_ * o.rayleigh_stiffness;
    cM_ = c0_ + c1_ * o.rayleigh_mass;
    const Index nd = this->dof_count();
    rhs_ = View1<T>("polymech::solid::newmark_rhs", nd);
    ut_ = View1<T>("polymech::solid::newmark_u_pred", nd);
    vt_ = View1<T>("polymech::solid::newmark_v_pred", nd);
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    if (n.solver == NewmarkSolver::direct) {
      Triplets k = this->assemble_elastic();
      for (std::size_t i = 0; i < k.values.size(); ++i)
        if (!this->constrained_[static_cast<std::size_t>(k.rows[i])]) k.values[i] *= cK_;
      const Triplets m = assemble_mass(this->assembly_input(), o.density);
      k.rows.insert(k.rows.end(), m.rows.begin(), m.rows.end());
      k.cols.insert(k.cols.end(), m.cols.begin(), m.cols.end());
      for (const double v : m.values) k.values.push_back(cM_ * v);
      lu_.factor(k.n, k.rows, k.cols, k.values);
      nonzeros_ = static_cast<std::int64_t>(k.values.size());
    } else {
      inv_diag_ = effective_inverse_diagonal(cK_, cM_);
    }
    setup_seconds_ = std::chrono::duration<double>(clock::now() - t0).count();
  }

  double time_step() const { return dt_; }
  double setup_seconds() const { return setup_seconds_; }
  std::int64_t nonzeros() const { return nonzeros_; }
  int last_iterations() const { return last_iterations_; }  // CG iterations of the last step (cg)

  // The initial acceleration from the equation of motion: M_ff a_f = [s_f f - K (u + beta_K v) - M (alpha v + a_c)]_f.
  void start() {
    const double t = this->t_;
    const Index n = this->dof_count();
    const T alpha = static_cast<T>(this->opt_.rayleigh_mass), bk = static_cast<T>(this->opt_.rayleigh_stiffness);
    this->prescribe(t, this->u_, this->v_, this->a_);
    const auto u = this->u_, v = this->v_, a = this->a_, w = this->work_, w2 = this->work2_;
    const auto fixed = this->is_fixed_;
    Kokkos::parallel_for(
        "polymech::solid::newmark_start", range(n), KOKKOS_LAMBDA(const Index i) {
          w(i) = -(u(i) + bk * v(i));
          w2(i) = -(alpha * v(i) + (fixed(i) ? a(i) : T(0)));
        });
    Kokkos::deep_copy(rhs_, T(0));
    add_elastic_apply<false>(this->op_.el, w, rhs_);
    add_mass_apply<false>(this->op_.el, static_cast<T>(this->opt_.density), w2, rhs_);
    add_scaled_force(this->load_factor(t), rhs_);
    fem::copy_constrained_rows(this->op_.constrained, a, rhs_);
    const ShiftedOperator op{this->op_.el, this->op_.constrained, T(0), T(1), static_cast<T>(this->opt_.density)};
    View1<T> inv = effective_inverse_diagonal(0.0, 1.0);
    const auto r = solvers::cg(op, inv, rhs_, this->a_, nopt_.cg);
    if (!r.converged()) throw std::runtime_error("solid::Newmark: the initial-acceleration solve failed: " + r.reason);
    this->energy_.initial = this->energies().total();
    if (this->opt_.track_energy && this->has_motion()) support_ = support_force();
    this->started_ = true;
  }

  // One step t -> t + dt.
  void step() {
    if (!this->started_) start();
    const Index n = this->dof_count();
    const double t1 = this->t_ + dt_;
    const T c0 = T(c0_), c2 = T(c2_), c3 = T(c3_), c1 = T(c1_), c4 = T(c4_), c5 = T(c5_);
    const T alpha = T(this->opt_.rayleigh_mass), bk = T(this->opt_.rayleigh_stiffness);
    const bool track = this->opt_.track_energy;
    const double sf0 = this->load_factor(this->t_), sf1 = this->load_factor(t1);
    // the predictors on the free DoFs, the prescribed state at t1 on the constrained ones
    const auto u = this->u_, v = this->v_, a = this->a_, ut = ut_, vt = vt_, w = this->work_, w2 = this->work2_;
    const auto fixed = this->is_fixed_;
    Kokkos::parallel_for(
        "polymech::solid::newmark_predict", range(n), KOKKOS_LAMBDA(const Index i) {
          ut(i) = c0 * u(i) + c2 * v(i) + c3 * a(i);
          vt(i) = c1 * u(i) + c4 * v(i) + c5 * a(i);
        });
    const View1<T> u1 = this->work_;  // u_{n+1}: work_ is free again once the right-hand side is formed
    // u_n and v_n for the energy increments (kept only when tracking)
    if (track) {
      if (un_.extent(0) == 0) {
        un_ = View1<T>("polymech::solid::newmark_un", n);
        vn_ = View1<T>("polymech::solid::newmark_vn", n);
      }
      Kokkos::deep_copy(un_, u);
      Kokkos::deep_copy(vn_, v);
    }
    this->prescribe(t1, u, v, a);  // the constrained entries now hold u_c, v_c, a_c at t1
    // w2 = M-argument, w = K-argument
    Kokkos::parallel_for(
        "polymech::solid::newmark_rhs_args", range(n), KOKKOS_LAMBDA(const Index i) {
          if (fixed(i)) {
            w2(i) = -(a(i) + alpha * v(i));
            w(i) = -(u(i) + bk * v(i));
          } else {
            w2(i) = ut(i) + alpha * vt(i);
            w(i) = bk * vt(i);
          }
        });
    Kokkos::deep_copy(rhs_, T(0));
    add_elastic_apply<false>(this->op_.el, w, rhs_);
    add_mass_apply<false>(this->op_.el, static_cast<T>(this->opt_.density), w2, rhs_);
    add_scaled_force(sf1, rhs_);
    fem::copy_constrained_rows(this->op_.constrained, u, rhs_);
    // solve for u_{n+1}
    if (nopt_.solver == NewmarkSolver::direct) {
      std::vector<double> b = models::to_host(rhs_);
      lu_.solve(b.data());
      this->copy_in(b, u1);
    } else {
      // initial guess: the constant-acceleration predictor u_n + dt v_n + dt^2 / 2 a_n (constrained rows exact)
      const T dt = T(dt_), h2 = T(0.5 * dt_ * dt_);
      Kokkos::parallel_for(
          "polymech::solid::newmark_guess", range(n), KOKKOS_LAMBDA(const Index i) {
            u1(i) = fixed(i) ? u(i) : u(i) + dt * v(i) + h2 * a(i);
          });
      const ShiftedOperator op{this->op_.el, this->op_.constrained, T(cK_), T(cM_), static_cast<T>(this->opt_.density)};
      const auto r = solvers::cg(op, inv_diag_, rhs_, u1, nopt_.cg);
      if (!r.converged()) throw std::runtime_error("solid::Newmark: the effective-system CG failed at t = " + models::format_g(t1) + ": " + r.reason);
      last_iterations_ = r.iterations;
    }
    Kokkos::parallel_for(
        "polymech::solid::newmark_update", range(n), KOKKOS_LAMBDA(const Index i) {
          if (fixed(i)) return;
          const T un1 = u1(i);
          a(i) = c0 * un1 - ut(i);
          v(i) = c1 * un1 - vt(i);
          u(i) = un1;
        });
    if (track) accumulate(sf0, sf1);
    this->t_ = t1;
    ++this->steps_;
  }

  void advance(long steps) {
    for (long k = 0; k < steps; ++k) step();
  }

 public:
  // Implementation. (Public only because nvcc's extended lambdas may not live in private or protected member
  // functions, docs/DEVELOPING.md.)
  // y = cK K x + cM M x on the free DoFs, x on the constrained ones (SPD).
  struct ShiftedOperator {
    using value_type = T;
    SolidElements<T, D> el;
    View1<Index> constrained;
    T cK, cM, rho;
    Index local_size() const { return el.dof_count(); }
    Index owned_size() const { return el.dof_count(); }
    void apply(const View1<T>& x, const View1<T>& y) const {
      Kokkos::deep_copy(y, T(0));
      if (cK != T(0)) {
        add_elastic_apply<true>(el, x, y);
        if (cK != T(1)) solvers::scale(el.dof_count(), cK, y, y);
      }
      if (cM != T(0)) add_mass_apply<true>(el, T(cM * rho), x, y);
      fem::copy_constrained_rows(constrained, x, y);
    }
  };

  // 1 / (cK diag(K) + cM m_L), 1 on the constrained rows.
  View1<T> effective_inverse_diagonal(double cK, double cM) const {
    const Index n = this->dof_count();
    View1<T> d("polymech::solid::newmark_diagonal", n), inv("polymech::solid::newmark_inverse_diagonal", n);
    if (cK != 0.0) {
      add_elastic_diagonal(this->op_.el, d);
      solvers::scale(n, T(cK), d, d);
    }
    const auto m = this->mass_;
    const T s = T(cM);
    Kokkos::parallel_for(
        "polymech::solid::newmark_diag_mass", range(n), KOKKOS_LAMBDA(const Index i) { d(i) += s * m(i); });
    fem::fill_constrained(this->op_.constrained, T(1), d);
    solvers::jacobi_inverse(n, n, d, inv);
    return inv;
  }

  void add_scaled_force(double sf, const View1<T>& y) const {
    const auto f = this->f_ext_;
    const T s = T(sf);
    Kokkos::parallel_for(
        "polymech::solid::scaled_force", range(this->dof_count()), KOKKOS_LAMBDA(const Index i) { y(i) += s * f(i); });
  }

  // F = M a + C v + K u on every DoF (the support force on the constrained ones).
  View1<T> support_force() const {
    const Index n = this->dof_count();
    View1<T> F("polymech::solid::support_force", n);
    const T alpha = T(this->opt_.rayleigh_mass), bk = T(this->opt_.rayleigh_stiffness);
    const auto u = this->u_, v = this->v_, a = this->a_, w = this->work_, w2 = this->work2_;
    Kokkos::parallel_for(
        "polymech::solid::support_args", range(n), KOKKOS_LAMBDA(const Index i) {
          w(i) = u(i) + bk * v(i);
          w2(i) = a(i) + alpha * v(i);
        });
    Kokkos::deep_copy(F, T(0));
    add_elastic_apply<false>(this->op_.el, w, F);
    add_mass_apply<false>(this->op_.el, static_cast<T>(this->opt_.density), w2, F);
    return F;
  }

  // external work and damping dissipation of the step from (un_, vn_) to (u, v)
  void accumulate(double sf0, double sf1) {
    const Index n = this->dof_count();
    const auto u = this->u_, v = this->v_, un = un_, vn = vn_, f = this->f_ext_;
    const auto fixed = this->is_fixed_;
    const T alpha = T(this->opt_.rayleigh_mass), bk = T(this->opt_.rayleigh_stiffness);
    // damping: du^T C vbar = alpha du^T M vbar + beta_K du^T K vbar, vbar = (v_n + v_{n+1}) / 2
    double diss = 0.0;
    if (alpha != T(0) || bk != T(0)) {
      const auto w = this->work_, w2 = this->work2_;
      Kokkos::parallel_for(
          "polymech::solid::newmark_vbar", range(n), KOKKOS_LAMBDA(const Index i) { w(i) = T(0.5) * (v(i) + vn(i)); });
      Kokkos::deep_copy(w2, T(0));
      if (bk != T(0)) {
        add_elastic_apply<false>(this->op_.el, w, w2);
        solvers::scale(n, bk, w2, w2);
      }
      if (alpha != T(0)) add_mass_apply<false>(this->op_.el, static_cast<T>(alpha * this->opt_.density), w, w2);
      Kokkos::parallel_reduce(
          "polymech::solid::newmark_dissipation", range(n),
          KOKKOS_LAMBDA(const Index i, double& s) { s += double(u(i) - un(i)) * w2(i); }, diss);
    }
    double work = 0.0;
    const T s0 = T(sf0), s1 = T(sf1);
    Kokkos::parallel_reduce(
        "polymech::solid::newmark_external_work", range(n),
        KOKKOS_LAMBDA(const Index i, double& s) {
          if (!fixed(i)) s += double(u(i) - un(i)) * T(0.5) * (s0 + s1) * f(i);
        },
        work);
    if (this->has_motion()) {
      const View1<T> F1 = support_force();
      const auto F0 = support_;
      double wr = 0.0;
      Kokkos::parallel_reduce(
          "polymech::solid::newmark_support_work", range(n),
          KOKKOS_LAMBDA(const Index i, double& s) {
            if (fixed(i)) s += double(u(i) - un(i)) * T(0.5) * (F0(i) + F1(i));
          },
          wr);
      work += wr;
      support_ = F1;
    }
    this->energy_.external_work += work;
    this->energy_.dissipated += diss;
    this->energy_.dissipated_step = diss;
  }

 private:
  NewmarkOptions nopt_;
  double dt_;
  double c0_, c1_, c2_, c3_, c4_, c5_, cK_, cM_;
  solvers::HostSparseLU lu_;
  View1<T> rhs_, ut_, vt_, inv_diag_, un_, vn_, support_;
  double setup_seconds_ = 0.0;
  std::int64_t nonzeros_ = 0;
  int last_iterations_ = 0;
};

}  // namespace polymech::solid
