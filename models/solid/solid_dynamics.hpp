// Structural dynamics of the linear elastic solid (issue 34): the semi-discrete equations of motion
//   M a + C v + K u = s_f(t) f_ext,   C = alpha M + beta_K K  (Rayleigh damping),
// on the discretization of solid::SolidProblem (problem.hpp), with the consistent mass M or its row-sum
// lumped form M_L (kernels/solid/mass.hpp) at density rho, a load factor s_f(t) on the external force of
// the Config (tractions, body forces) and an optional prescribed motion of the Dirichlet DoFs
//   u_c(t) = g s(t),  v_c = g s'(t),  a_c = g s''(t)
// (g: the Config's Dirichlet values; base excitation by a prescribed root motion). The integrators: solid::Newmark (newmark.hpp) and solid::CentralDifference (central_difference.hpp); this
// header has what they share (the options, the time functions, the energies, solid::SolidDynamics: masses,
// the prescribed motion, the energy bookkeeping); solid/dynamics.hpp includes all three.
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

}  // namespace polymech::solid
