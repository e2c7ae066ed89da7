// Structural dynamics of the linear elastic solid (issue 34): the semi-discrete equations of motion
//   M a + C v + K u = s_f(t) f_ext,   C = alpha M + beta_K K  (Rayleigh damping),
// on the discretization of solid::SolidProblem (problem.hpp), with the consistent mass M or its row-sum
// lumped form M_L (kernels/solid/mass.hpp) at density rho, a load factor s_f(t) on the external force of
// the Config (tractions, body forces) and an optional prescribed motion of the Dirichlet DoFs
//   u_c(t) = g s(t),  v_c = g s'(t),  a_c = g s''(t)
// (g: the Config's Dirichlet values; base excitation by a prescribed root motion). Two integrators:
//
//  - solid::Newmark: Newmark's (1959) family, beta = 1/4, gamma = 1/2 (average acceleration: unconditionally
//    stable, second order, no numerical damping) by default. With a0 = 1 / (beta dt^2), a1 = gamma / (beta dt),
//    the predictors  u~ = a0 u_n + v_n / (beta dt) + (1 / (2 beta) - 1) a_n,
//                    v~ = a1 u_n + (gamma / beta - 1) v_n + dt (gamma / (2 beta) - 1) a_n,
//    and a_{n+1} = a0 u_{n+1} - u~, v_{n+1} = a1 u_{n+1} - v~, the free rows of the equation of motion at
//    t_{n+1} give the effective system (Hughes, The Finite Element Method, 2000, ch. 9, displacement form)
//      [(1 + a1 beta_K) K + (a0 + a1 alpha) M]_ff u_f = [s_f f + M (u~ + alpha v~) + K (beta_K v~)]_f
//                                                        - [M (a_c + alpha v_c) + K (u_c + beta_K v_c)]_f,
//    the constrained DoFs carrying their exact prescribed u_c, v_c, a_c (the last bracket is their lifting).
//    The effective matrix is factorized once with the host sparse LU (NewmarkSolver::direct, default) or
//    solved matrix-free with CG preconditioned by its diagonal (K's exact diagonal, the lumped mass for M's;
//    NewmarkSolver::cg); one elastic and one mass apply per step form the right-hand side.
//
//  - solid::CentralDifference: explicit central differences with the lumped mass (velocity form; Newmark's beta = 0,
//    gamma = 1/2 member, Hughes ch. 9):
//      v_{n+1/2} = v_n + dt/2 a_n,  u_{n+1} = u_n + dt v_{n+1/2},
//      a_{n+1} = M_L^-1 (s_f f - K (u_{n+1} + beta_K v_{n+1/2})) - alpha v_{n+1/2},  v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}
//    (one fused matrix-free elastic apply and two vector kernels per step). Conditionally stable: dt <=
//    dt_crit = (2 / omega_max) (sqrt(1 + xi^2) - xi), xi = alpha / (2 omega_max) + beta_K omega_max / 2 the damping
//    ratio of the highest mode (Hughes ch. 9; Belytschko, Liu, Moran & Elkhodary 2014, §6.3), omega_max^2 the largest
//    eigenvalue of M_L^-1 K, estimated by power iteration (its Rayleigh quotient is a lower bound, so the
//    estimate of dt_crit is an upper bound: the safety factor, 0.9 by default, covers the gap). A requested
//    dt above the estimate is refused with std::invalid_argument unless `allow_unstable`.
//
// Energies (Energies): kinetic 1/2 v^T M v (M_L for central differences), strain 1/2 u^T K u, the external work
// sum (u_{n+1} - u_n)^T (F_n + F_{n+1}) / 2 (F = s_f f on the free DoFs, the support force M a + C v + K u on
// the prescribed ones) and the damping dissipation sum (u_{n+1} - u_n)^T C (v_n + v_{n+1}) / 2 (C v_{n+1/2} for
// central differences). Newmark's average-acceleration rule satisfies kinetic + strain + dissipation =
// initial + external work exactly (u_{n+1} - u_n = dt (v_n + v_{n+1}) / 2), up to the solver's round-off.
#pragma once

#include <chrono>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/mass.hpp"
#include "solid/problem.hpp"
#include "solvers/host_sparse_lu.hpp"
#include "solvers/krylov.hpp"

namespace polymech::solid {

// A scalar function of time with its first two derivatives (host). Empty `value`: constant 1.
struct TimeFunction {
  std::function<double(double)> value, rate, acceleration;  // s, s', s'' (empty rate / acceleration: zero)
  double s(double t) const { return value ? value(t) : 1.0; }
  double ds(double t) const { return rate ? rate(t) : 0.0; }
  double dds(double t) const { return acceleration ? acceleration(t) : 0.0; }
};

struct DynamicsOptions {
  double density = 1.0;                        // rho (mass per volume; per area and unit thickness in 2D)
  double rayleigh_mass = 0.0;                  // alpha of C = alpha M + beta_K K
  double rayleigh_stiffness = 0.0;             // beta_K
  std::function<double(double)> load_factor;   // s_f(t) on the Config's external force; empty: 1
  TimeFunction base_motion;                    // the Dirichlet values g times s(t); empty: g, at rest
  bool track_energy = true;                    // accumulate the external work and the damping dissipation
};

// Energies at the current step (see the header).
struct Energies {
  double kinetic = 0.0, strain = 0.0;
  double external_work = 0.0;       // since the start
  double dissipated = 0.0;          // damping, since the start
  double dissipated_step = 0.0;     // damping, the last step
  double initial = 0.0;             // kinetic + strain at the start
  double total() const { return kinetic + strain; }
  // kinetic + strain + dissipated - initial - external work, relative to the largest of the energies
  double balance_error() const {
    const double scale = std::fmax(std::fmax(initial, std::fabs(external_work)), std::fmax(total(), 1e-300));
    return (total() + dissipated - initial - external_work) / scale;
  }
};

// The shared part of the integrators: mass, damping, loads, prescribed motion, state and energies.
template <class T, int D>
class SolidDynamics : public SolidProblem<T, D> {
  using Base = SolidProblem<T, D>;

 public:
  SolidDynamics(const Config<D>& c, const DynamicsOptions& o) : Base(c), opt_(o) {
    if (c.plasticity) throw std::invalid_argument("solid dynamics: the configuration carries a plastic law; linear elasticity only");
    if (!(o.density > 0.0)) throw std::invalid_argument("solid dynamics: density " + models::format_g(o.density) + " (allowed: > 0)");
    if (o.rayleigh_mass < 0.0 || o.rayleigh_stiffness < 0.0)
      throw std::invalid_argument("solid dynamics: Rayleigh coefficients must be >= 0");
    const Index n = this->dof_count();
    u_ = View1<T>("polymech::solid::dyn_u", n);
    v_ = View1<T>("polymech::solid::dyn_v", n);
    a_ = View1<T>("polymech::solid::dyn_a", n);
    work_ = View1<T>("polymech::solid::dyn_work", n);
    work2_ = View1<T>("polymech::solid::dyn_work2", n);
    mass_ = View1<T>("polymech::solid::lumped_mass", n);
    add_lumped_mass(this->op_.el, static_cast<T>(o.density), mass_);
    is_fixed_ = View1<char>("polymech::solid::dyn_fixed", n);
    g_full_ = View1<T>("polymech::solid::dyn_g", n);
    auto fh = Kokkos::create_mirror_view(is_fixed_);
    for (Index i = 0; i < n; ++i) fh(i) = this->constrained_[static_cast<std::size_t>(i)];
    Kokkos::deep_copy(is_fixed_, fh);
    fem::set_constrained_values(this->op_.constrained, this->g_, g_full_);
    set_state(std::vector<double>{}, std::vector<double>{});
  }

  const DynamicsOptions& options() const { return opt_; }
  double time() const { return t_; }
  long steps() const { return steps_; }
  const View1<T>& displacement() const { return u_; }
  const View1<T>& velocity() const { return v_; }
  const View1<T>& acceleration() const { return a_; }
  const View1<T>& lumped_mass() const { return mass_; }  // per DoF

  // Initial state at time t0 (host vectors of dof_count() values, empty: zero) on the free DoFs; the
  // prescribed DoFs take g s(t0), g s'(t0). The acceleration follows from the equation of motion at the
  // first step. Resets the energies.
  void set_state(const std::vector<double>& u0, const std::vector<double>& v0, double t0 = 0.0) {
    const Index n = this->dof_count();
    auto load = [&](const std::vector<double>& h, const View1<T>& v, const char* what) {
      if (!h.empty() && static_cast<Index>(h.size()) != n)
        throw std::invalid_argument(std::string("solid dynamics: initial ") + what + " has " + std::to_string(h.size()) +
                                    " values for " + std::to_string(n) + " DoFs");
      auto m = Kokkos::create_mirror_view(v);
      for (Index i = 0; i < n; ++i) m(i) = h.empty() ? T(0) : static_cast<T>(h[static_cast<std::size_t>(i)]);
      Kokkos::deep_copy(v, m);
    };
    load(u0, u_, "displacement");
    load(v0, v_, "velocity");
    t_ = t0;
    steps_ = 0;
    prescribe(t0, u_, v_, View1<T>());
    Kokkos::deep_copy(a_, T(0));
    started_ = false;
    energy_ = Energies{};
  }
  // Initial displacement / velocity as functions of the position (nodes: D values each).
  void set_initial(const PointFunction& u0, const PointFunction& v0 = {}, double t0 = 0.0) {
    set_state(nodal(u0), nodal(v0), t0);
  }

  // Host values of a function at the nodes (empty function: empty vector).
  std::vector<double> nodal(const PointFunction& f) const {
    if (!f) return {};
    const auto& x = this->disc_.coordinates;
    std::vector<double> out(static_cast<std::size_t>(this->dof_count()), 0.0);
    for (std::int64_t v = 0; v < this->disc_.nodes; ++v) {
      double p[3] = {0, 0, 0}, val[3] = {0, 0, 0};
      for (int d = 0; d < D; ++d) p[d] = x[static_cast<std::size_t>(D * v + d)];
      f(p, val);
      for (int d = 0; d < D; ++d) out[static_cast<std::size_t>(D * v + d)] = val[d];
    }
    return out;
  }

  // y = M x over every DoF (consistent mass).
  void mass_apply(const View1<T>& x, const View1<T>& y) const {
    Kokkos::deep_copy(y, T(0));
    add_mass_apply<false>(this->op_.el, static_cast<T>(opt_.density), x, y);
  }
  // y = K x over every DoF.
  void stiffness_apply(const View1<T>& x, const View1<T>& y) const {
    Kokkos::deep_copy(y, T(0));
    add_elastic_apply<false>(this->op_.el, x, y);
  }

  // The lowest natural circular frequency omega_1 of the consistent (lumped: `lumped`) semi-discrete system on
  // the free DoFs, by inverse iteration x <- K^-1 M x with the host sparse LU of K (moderate meshes).
  double fundamental_frequency(bool lumped = false, int iterations = 200, double tolerance = 1e-12) const {
    const Triplets t = this->assemble_elastic();
    solvers::HostSparseLU lu;
    lu.factor(t.n, t.rows, t.cols, t.values);
    const Index n = this->dof_count();
    View1<T> x("x", n), y("y", n);
    std::vector<double> xh(static_cast<std::size_t>(n));
    for (Index i = 0; i < n; ++i) xh[static_cast<std::size_t>(i)] = this->constrained_[static_cast<std::size_t>(i)] ? 0.0 : 1.0;
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
      copy_in(xh, x);
      mass_free(x, y, lumped);
      std::vector<double> b = models::to_host(y);
      lu.solve(b.data());
      for (Index i = 0; i < n; ++i)
        if (this->constrained_[static_cast<std::size_t>(i)]) b[static_cast<std::size_t>(i)] = 0.0;
      // Rayleigh quotient b^T K b / b^T M b with K b = M x
      double bKb = 0.0, nb = 0.0;
      const std::vector<double> mx = models::to_host(y);
      for (Index i = 0; i < n; ++i) bKb += b[static_cast<std::size_t>(i)] * mx[static_cast<std::size_t>(i)];
      copy_in(b, x);
      mass_free(x, y, lumped);
      const std::vector<double> mb = models::to_host(y);
      double bMb = 0.0;
      for (Index i = 0; i < n; ++i) {
        bMb += b[static_cast<std::size_t>(i)] * mb[static_cast<std::size_t>(i)];
        nb = std::fmax(nb, std::fabs(b[static_cast<std::size_t>(i)]));
      }
      const double next = bKb / bMb;
      for (auto& v : b) v /= nb;
      xh = b;
      const bool done = it > 0 && std::fabs(next - lambda) <= tolerance * next;
      lambda = next;
      if (done) break;
    }
    return std::sqrt(lambda);
  }

  // The energies at the current state (kinetic with the consistent mass unless `lumped`).
  Energies energies() const { return energies_with(lumped_kinetic_); }

 public:
  // Implementation. (Public only because nvcc's extended lambdas may not live in private or protected member
  // functions, docs/DEVELOPING.md.)

  Energies energies_with(bool lumped) const {
    Energies e = energy_;
    const Index n = this->dof_count();
    double ke = 0.0, se = 0.0;
    if (lumped) {
      const auto v = v_;
      const auto m = mass_;
      Kokkos::parallel_reduce(
          "polymech::solid::kinetic_lumped", range(n), KOKKOS_LAMBDA(const Index i, double& s) { s += double(m(i)) * v(i) * v(i); }, ke);
    } else {
      mass_apply(v_, work2_);
      ke = dot(v_, work2_);
    }
    stiffness_apply(u_, work2_);
    se = dot(u_, work2_);
    e.kinetic = 0.5 * ke;
    e.strain = 0.5 * se;
    return e;
  }

  double dot(const View1<T>& x, const View1<T>& y) const {
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::dyn_dot", range(this->dof_count()), KOKKOS_LAMBDA(const Index i, double& a) { a += double(x(i)) * y(i); }, s);
    return s;
  }
  void copy_in(const std::vector<double>& h, const View1<T>& v) const {
    auto m = Kokkos::create_mirror_view(v);
    for (std::size_t i = 0; i < h.size(); ++i) m(i) = static_cast<T>(h[i]);
    Kokkos::deep_copy(v, m);
  }
  // y = M x on the free DoFs (zero on the constrained ones), consistent or lumped.
  void mass_free(const View1<T>& x, const View1<T>& y, bool lumped) const {
    if (lumped) {
      const auto m = mass_;
      const auto fixed = is_fixed_;
      Kokkos::parallel_for(
          "polymech::solid::lumped_apply", range(this->dof_count()),
          KOKKOS_LAMBDA(const Index i) { y(i) = fixed(i) ? T(0) : m(i) * x(i); });
    } else {
      Kokkos::deep_copy(y, T(0));
      add_mass_apply<true>(this->op_.el, static_cast<T>(opt_.density), x, y);
    }
  }

  double load_factor(double t) const { return opt_.load_factor ? opt_.load_factor(t) : 1.0; }
  bool has_motion() const { return static_cast<bool>(opt_.base_motion.value) && this->op_.constrained.extent(0) > 0; }

  // The prescribed DoFs of u, v, a (any may be empty) at time t: g s(t), g s'(t), g s''(t).
  void prescribe(double t, const View1<T>& u, const View1<T>& v, const View1<T>& a) const {
    const TimeFunction& f = opt_.base_motion;
    const T s = static_cast<T>(f.s(t)), ds = static_cast<T>(f.ds(t)), dds = static_cast<T>(f.dds(t));
    const auto c = this->op_.constrained;
    const auto g = this->g_;
    const bool hu = u.extent(0) > 0, hv = v.extent(0) > 0, ha = a.extent(0) > 0;
    Kokkos::parallel_for(
        "polymech::solid::prescribe", range(static_cast<Index>(c.extent(0))), KOKKOS_LAMBDA(const Index k) {
          if (hu) u(c(k)) = s * g(k);
          if (hv) v(c(k)) = ds * g(k);
          if (ha) a(c(k)) = dds * g(k);
        });
  }

 protected:
  bool lumped_kinetic_ = false;  // the kinetic energy with M_L (central differences)
  DynamicsOptions opt_;
  View1<T> u_, v_, a_, work_, work2_, mass_, g_full_;
  View1<char> is_fixed_;
  double t_ = 0.0;
  long steps_ = 0;
  bool started_ = false;
  Energies energy_;
};

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
