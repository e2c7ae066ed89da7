// The explicit finite-strain solid with nodes tied to rigid bodies (issue 34: "explicit central differences
// with a lumped mass"; issue 37): its options and the class solid::HyperelasticExplicit (construction, the
// step, the start, the evaluation of the accelerations, energies and momentum). The rigid ties' members are
// defined in models/solid/explicit_ties.hpp, the critical step's power iteration in
// models/solid/explicit_stability.hpp; include models/solid/finite_strain_explicit.hpp, which holds all.
//
// solid::HyperelasticExplicit: the total-Lagrangian hyperelastic solid of models/solid/hyperelastic.hpp (its
// internal force, dead loads and follower pressures; no tangent is ever formed) with the row-sum lumped mass M_L
// (kernels/solid/mass.hpp), integrated by central differences in velocity form (velocity Verlet):
//   v_{n+1/2} = v_n + dt/2 a_n,   u_{n+1} = u_n + dt v_{n+1/2},
//   a_{n+1} = -M_L^-1 r(u_{n+1}, s(t_{n+1})) - alpha v_{n+1/2},   v_{n+1} = v_{n+1/2} + dt/2 a_{n+1},
// r = f_int(u) - s (f_ext + f_p(u)) (Hyperelastic::residual), alpha the mass-proportional damping, s(t) the load
// factor of the dead loads, the pressures and the Dirichlet values (u_c = s(t) g).
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "solid/explicit_dynamics.hpp"
#include "solid/hyperelastic.hpp"
#include "solid/rigid_tie.hpp"

namespace polymech::solid {

struct ExplicitFiniteStrainOptions {
  double density = 1.0;
  double dt = 0.0;               // 0: safety x dt_crit of the initial state
  double safety = 0.9;
  double damping = 0.0;          // alpha: mass-proportional damping of the free nodes (1/s)
  int damping_frame = -1;        // >= 0: the damping acts on the velocity relative to tie k's rigid motion, its
                                 // reaction on that body (a rolling tyre's rigid motion with its rim undamped)
  bool allow_unstable = false;   // accept dt > safety x dt_crit (to show the instability)
  int power_iterations = 300;
  double power_tolerance = 1e-4;
  std::function<double(double)> load_factor;  // s(t); empty: 1
  // Per-cell stiffness scales (Hyperelastic::set_cell_scale; issue 37: the tyre's layered wall); empty: one law.
  // The critical step's power iteration runs on the scaled residual, so a stiffer layer shortens dt_crit as
  // 1/sqrt(s) where it sets the highest mode.
  std::vector<double> cell_scale;
  // Rebar cord families per cell (Hyperelastic::set_fibres; issue 37: the tyre's steel belt, TyreSpec::belt_rebar):
  // the family's smeared modulus k per cell (empty: none), the angle +-fibre_angle_deg to the element's direction 0,
  // tension-only cords. The power iteration runs on the residual with the cords, so dt_crit sees their stiffness.
  std::vector<double> fibre_stiffness;
  double fibre_angle_deg = 0.0;
  bool fibre_tension_only = false;
};

template <class T, int D>
class HyperelasticExplicit {
 public:
  HyperelasticExplicit(const Config<D>& c, const HyperelasticLaw& law, const ExplicitFiniteStrainOptions& o,
                       const std::vector<FollowerPressure>& pressures = {}, const std::vector<RigidTie<D>>& ties = {})
      : solid_(c, law, pressures), o_(o), ties_(ties) {
    if (!(o.density > 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: density must be > 0");
    if (!(o.damping >= 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: damping must be >= 0");
    if (o.damping_frame >= static_cast<int>(ties.size()))
      throw std::invalid_argument("solid::HyperelasticExplicit: damping_frame " + std::to_string(o.damping_frame) + " names no tie (" +
                                  std::to_string(ties.size()) + " ties)");
    if (o.damping_frame >= 0 && D != 3) throw std::invalid_argument("solid::HyperelasticExplicit: damping_frame is for 3D solids");
    if (!(o.safety > 0.0 && o.safety <= 1.0)) throw std::invalid_argument("solid::HyperelasticExplicit: safety must be in (0, 1]");
    if (o.dt < 0.0 || !std::isfinite(o.dt)) throw std::invalid_argument("solid::HyperelasticExplicit: dt must be >= 0 (0: automatic)");
    if (!o.cell_scale.empty()) solid_.set_cell_scale(o.cell_scale);
    if (!o.fibre_stiffness.empty()) solid_.set_fibres(o.fibre_stiffness, o.fibre_angle_deg, o.fibre_tension_only);
    const Index n = solid_.dof_count();
    u_ = View1<T>("polymech::solid::fse_u", n);
    v_ = View1<T>("polymech::solid::fse_v", n);
    a_ = View1<T>("polymech::solid::fse_a", n);
    r_ = View1<T>("polymech::solid::fse_r", n);
    work_ = View1<T>("polymech::solid::fse_work", n);
    mass_ = View1<T>("polymech::solid::fse_lumped_mass", n);
    add_lumped_mass(solid_.op().el, static_cast<T>(o.density), mass_);
    mass_host_ = models::to_host(mass_);
    kind_host_.assign(static_cast<std::size_t>(n), 0);
    const auto& mask = solid_.constrained_mask();
    for (std::size_t i = 0; i < mask.size(); ++i) kind_host_[i] = mask[i] ? 1 : 0;
    g_scaled_ = View1<T>("polymech::solid::fse_dirichlet", solid_.dirichlet_values().extent(0));
    set_up_ties();
    if (o.damping_frame >= 0) coordinates_ = models::to_device<double>("polymech::solid::fse_coordinates", solid_.discretization().coordinates);
    kind_ = models::to_device<char>("polymech::solid::fse_kind", kind_host_);
    start();
    dt_crit_ = estimate_critical_step();
    const double dt = o.dt > 0.0 ? o.dt : o.safety * dt_crit_;
    if (dt > o.safety * dt_crit_ * (1.0 + 1e-12) && !o.allow_unstable)
      throw std::invalid_argument("solid::HyperelasticExplicit: time step " + models::format_g(dt) +
                                  " exceeds safety x the critical step " + models::format_g(o.safety * dt_crit_) +
                                  " (2 / omega_max, omega_max = " + models::format_g(omega_max_) +
                                  " from power iteration on M_L^-1 K_t): central differences are unstable there; use a "
                                  "smaller dt or set allow_unstable");
    dt_ = dt;
  }

  Hyperelastic<T, D>& solid() { return solid_; }
  Index dof_count() const { return static_cast<Index>(u_.extent(0)); }
  double time() const { return t_; }
  std::int64_t steps() const { return steps_; }
  double time_step() const { return dt_; }
  double critical_time_step() const { return dt_crit_; }
  double omega_max() const { return omega_max_; }
  int power_iterations_used() const { return power_its_; }
  const View1<T>& displacement() const { return u_; }
  const View1<T>& velocity() const { return v_; }
  const View1<T>& lumped_mass() const { return mass_; }
  const View1<T>& acceleration_view() const { return a_; }
  const std::vector<TieState<D>>& ties() const { return state_; }
  double tie_mass(std::size_t k) const { return body_[k].mass; }
  double tie_inertia(std::size_t k) const { return body_[k].inertia; }
  double strain_energy() const { return solid_.strain_energy(); }
  // External nodal forces that depend on the state (contact: models/solid/tyre.hpp's plate): called after each
  // residual with (t, u, v, r); it subtracts its forces from r (r = f_int - f_ext), so they reach the free nodes'
  // accelerations and, on tied nodes, the bodies. Not part of the critical-step estimate.
  using ExternalForce = std::function<void(double, const View1<T>&, const View1<T>&, const View1<T>&)>;
  void set_external_force(ExternalForce f) { external_ = std::move(f); }
  // A new time step (a coupling's common step), refused above safety x the critical step unless allow_unstable.
  void set_time_step(double dt) {
    if (!(dt > 0.0) || (dt > o_.safety * dt_crit_ * (1.0 + 1e-12) && !o_.allow_unstable))
      throw std::invalid_argument("solid::HyperelasticExplicit: time step " + models::format_g(dt) + " is not in (0, safety x the critical step " +
                                  models::format_g(o_.safety * dt_crit_) + "]");
    dt_ = dt;
  }
  // The mass-proportional damping from now on (the tyre: settle the inflation, then press on a plate).
  void set_damping(double alpha) {
    if (!(alpha >= 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: damping must be >= 0");
    o_.damping = alpha;
  }

  // The critical step at the current state (power iteration; also re-estimates omega_max).
  double estimate_critical_step() {
    omega_max_ = std::sqrt(largest_eigenvalue());
    return 2.0 / omega_max_;
  }

  // Kinetic energy: the nodes (tied ones moving with the body) and the body's own mass and inertia.
  double kinetic_energy() const {
    double e = explicit_kinetic_energy(solid_.dof_count(), mass_, v_);
    for (std::size_t k = 0; k < ties_.size(); ++k) {
      double v2 = 0.0;
      for (int d = 0; d < D; ++d) v2 += state_[k].velocity[static_cast<std::size_t>(d)] * state_[k].velocity[static_cast<std::size_t>(d)];
      e += 0.5 * ties_[k].mass * v2 + 0.5 * ties_[k].inertia * state_[k].omega * state_[k].omega;
    }
    return e;
  }
  // Linear momentum of the nodes and the bodies' own masses (per component).
  std::array<double, D> momentum() const {
    std::array<double, D> p{};
    const std::vector<double> vh = models::to_host(v_);
    for (std::size_t i = 0; i < vh.size(); ++i) p[i % D] += mass_host_[i] * vh[i];
    for (std::size_t k = 0; k < ties_.size(); ++k)
      for (int d = 0; d < D; ++d) p[static_cast<std::size_t>(d)] += ties_[k].mass * state_[k].velocity[static_cast<std::size_t>(d)];
    return p;
  }

  // One step t -> t + dt. Throws std::runtime_error (with the time and the reason) when the state stops evaluating.
  void step() {
    first_half();
    second_half();
  }
  // The step in its two halves, for a coupling that computes the external forces at t + dt between them (the
  // DEM's contacts on the tyre, models/dem/tyre_drive.hpp): first_half() kicks the free nodes and the bodies by
  // dt/2 and drifts them to t + dt (displacements at t + dt, velocities at the half step); second_half()
  // evaluates the forces at t + dt (the external force included) and takes the second kick.
  void first_half() {
    const double t0 = t_, h = 0.5 * dt_;
    const Index n = solid_.dof_count();
    explicit_kick_drift(n, kind_, u_, v_, a_, static_cast<T>(h), static_cast<T>(dt_));  // the free nodes: kick and drift
    for (std::size_t k = 0; k < ties_.size(); ++k) {  // the bodies: kick (or prescribe) and drift
      TieState<D>& s = state_[k];
      for (int q = 0; q <= D; ++q) {
        double& rate = q < D ? s.velocity[static_cast<std::size_t>(q)] : s.omega;
        const auto& pv = ties_[k].velocity[static_cast<std::size_t>(q)];
        rate = pv ? pv(t0 + h) : rate + h * acceleration(k, q);
      }
      for (int d = 0; d < D; ++d) s.position[static_cast<std::size_t>(d)] += dt_ * s.velocity[static_cast<std::size_t>(d)];
      s.angle += dt_ * s.omega;
      place_tied(k, false);
    }
  }
  void second_half() {
    const double t1 = t_ + dt_, h = 0.5 * dt_;
    const Index n = solid_.dof_count();
    evaluate(t1);
    explicit_kick(n, kind_, v_, a_, static_cast<T>(h));  // the free nodes: second kick
    for (std::size_t k = 0; k < ties_.size(); ++k) {
      TieState<D>& s = state_[k];
      for (int q = 0; q <= D; ++q) {
        double& rate = q < D ? s.velocity[static_cast<std::size_t>(q)] : s.omega;
        const auto& pv = ties_[k].velocity[static_cast<std::size_t>(q)];
        rate = pv ? pv(t1) : rate + h * acceleration(k, q);
      }
      drive_forces(k, t1);
      place_tied(k, true);
    }
    t_ = t1;
    ++steps_;
  }

  // After u, v and a were written back (a checkpoint): the clock and the bodies' states (the tied nodes' u and v
  // are part of the Views already).
  void restore(double t, std::int64_t steps, const std::vector<TieState<D>>& ties) {
    if (ties.size() != ties_.size()) throw std::invalid_argument("solid::HyperelasticExplicit::restore: " + std::to_string(ties.size()) +
                                                                 " body states for " + std::to_string(ties_.size()) + " ties");
    t_ = t;
    steps_ = steps;
    state_ = ties;
  }

  void advance(std::int64_t steps) {
    for (std::int64_t k = 0; k < steps; ++k) step();
  }

  // Start from rest in the reference configuration, the bodies at their reference points.
  void start() {
    Kokkos::deep_copy(u_, T(0));
    Kokkos::deep_copy(v_, T(0));
    t_ = 0.0;
    steps_ = 0;
    for (std::size_t k = 0; k < ties_.size(); ++k) {
      state_[k] = TieState<D>{};
      for (int d = 0; d < D; ++d) state_[k].position[static_cast<std::size_t>(d)] = body_[k].centre[static_cast<std::size_t>(d)];
      for (int q = 0; q <= D; ++q) {
        const auto& pv = ties_[k].velocity[static_cast<std::size_t>(q)];
        if (!pv) continue;
        (q < D ? state_[k].velocity[static_cast<std::size_t>(q)] : state_[k].omega) = pv(0.0);
      }
      place_tied(k, true);
    }
    evaluate(0.0);
    for (std::size_t k = 0; k < ties_.size(); ++k) drive_forces(k, 0.0);
  }

 public:
  // Implementation (public: it held nvcc's extended lambdas, docs/DEVELOPING.md; the kernels are now in
  // kernels/solid/explicit_dynamics.hpp).
  struct Body {
    double mass = 0.0, inertia = 0.0;
    std::array<double, 3> centre{}, axis{0.0, 0.0, 1.0};
    std::vector<std::int64_t> nodes;
    Kokkos::View<Index*, MemSpace> node_view;
    Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> offsets;  // X_i - c_0
    Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> gathered;        // -r at the tied nodes
  };

  // The rigid ties (explicit_ties.hpp): a body's acceleration along DoF q, the drivers' forces, the rotation of an
  // offset, the tied nodes placed from the body's pose, the structure's force on a body.
  double acceleration(std::size_t k, int q) const;
  void drive_forces(std::size_t k, double t);
  static void rotate(const std::array<double, 3>& n, double theta, const double* x, double* y);
  void place_tied(std::size_t k, bool velocities);
  void body_force(std::size_t k, double t);

  // The largest eigenvalue of M_L^-1 K_t (explicit_stability.hpp).
  double largest_eigenvalue();
  // The damping relative to the frame body's rigid motion (ExplicitFiniteStrainOptions::damping_frame), its
  // reaction kept for body_force (explicit_ties.hpp).
  void frame_damping();

  // r(u, s(t)) with u carrying the Dirichlet values s(t) g; a = -r / m - alpha v on the free DoFs; the bodies'
  // forces (structure + applied loads).
  void evaluate(double t) {
    const double s = o_.load_factor ? o_.load_factor(t) : 1.0;
    const Index nc = static_cast<Index>(g_scaled_.extent(0));
    if (nc > 0) {
      solvers::scale(nc, static_cast<T>(s), solid_.dirichlet_values(), g_scaled_);
      fem::set_constrained_values(solid_.op().constrained, g_scaled_, u_);
    }
    const double rn = solid_.residual(u_, s, r_);
    if (!std::isfinite(rn))
      throw std::runtime_error("solid::HyperelasticExplicit: the state at t = " + models::format_g(t) +
                               " does not evaluate (an element inverted or a non-finite stress): the step " +
                               models::format_g(dt_) + " is unstable here (critical step at the start " +
                               models::format_g(dt_crit_) + ") or the load is too large");
    if (external_) external_(t, u_, v_, r_);
    const bool framed = o_.damping_frame >= 0 && o_.damping > 0.0;
    if (framed) frame_damping();
    explicit_accelerate(solid_.dof_count(), kind_, r_, mass_, v_, static_cast<T>(framed ? 0.0 : o_.damping), a_);
    for (std::size_t k = 0; k < ties_.size(); ++k) body_force(k, t);
  }

 private:
  void set_up_ties();

  Hyperelastic<T, D> solid_;
  ExplicitFiniteStrainOptions o_;
  std::vector<RigidTie<D>> ties_;
  std::vector<Body> body_;
  View1<double> coordinates_;            // X on the device (only with a damping frame)
  particles::SumPartials frame_partials_;
  Kokkos::Array<double, 4> frame_force_{};  // the frame damping's force and moment on its body (last evaluation)
  std::vector<TieState<D>> state_;
  ExternalForce external_;
  View1<T> u_, v_, a_, r_, work_, mass_, g_scaled_;
  View1<char> kind_;                // per DoF: 0 free, 1 Dirichlet, 2 tied
  std::vector<char> kind_host_;
  std::vector<double> mass_host_;
  double t_ = 0.0, dt_ = 0.0, dt_crit_ = 0.0, omega_max_ = 0.0;
  std::int64_t steps_ = 0;
  int power_its_ = 0;
};

}  // namespace polymech::solid
