// Explicit dynamics at finite strain with nodes tied to a rigid body (issue 34: "explicit central differences
// with a lumped mass", "nodes tied to a rigid body"; issue 37: the tyre is stepped explicitly with the DEM and its
// rim is a rigid body carrying the load, the speed and the slip).
//
// solid::HyperelasticExplicit: the total-Lagrangian hyperelastic solid of models/solid/hyperelastic.hpp (its
// internal force, dead loads and follower pressures; no tangent is ever formed) with the row-sum lumped mass M_L
// (kernels/solid/mass.hpp), integrated by central differences in velocity form (velocity Verlet):
//   v_{n+1/2} = v_n + dt/2 a_n,   u_{n+1} = u_n + dt v_{n+1/2},
//   a_{n+1} = -M_L^-1 r(u_{n+1}, s(t_{n+1})) - alpha v_{n+1/2},   v_{n+1} = v_{n+1/2} + dt/2 a_{n+1},
// r = f_int(u) - s (f_ext + f_p(u)) (Hyperelastic::residual), alpha the mass-proportional damping, s(t) the load
// factor of the dead loads, the pressures and the Dirichlet values (u_c = s(t) g).
//
// Rigid tie (RigidTie): the nodes of a named side follow a rigid body whose degrees of freedom are the D
// translations of its reference point c (the tied nodes' centre of mass c_0 at the start) and one rotation theta
// about a fixed axis n through it (2D: z; 3D: given):
//   x_i = c + R_n(theta) (X_i - c_0),  v_i = V + omega n x (x_i - c).
// Each body DoF is either prescribed (a velocity function of time: the tyre's speed and slip) or free (driven by
// an applied force or torque function: the tyre's vertical load). The tied nodes' lumped masses join the body
// (M_b = m_own + sum m_i, I_b = I_own + sum m_i |n x (X_i - c_0)|^2, constant under the rotation), and the
// structure's force on the body is the sum of -r over the tied DoFs (with its moment about c): so the momentum
// exchanged between the solid and the body is exact, and the body is kicked and drifted with the same Verlet
// halves (with c at the tied nodes' centre of mass, translation and rotation do not couple through the mass).
// What the driver of a prescribed DoF must apply is reported
// (drive_force: M_b A - F along it), as the tyre's tractive force and torque are.
//
// Stability: dt <= dt_crit = 2 / omega_max, omega_max^2 the largest eigenvalue of M_L^-1 K_t, K_t the tangent at
// the current state, estimated by power iteration on directional differences of the residual (matrix-free:
// K_t x ~ (r(u + eps x) - r(u)) / eps) with the tied and constrained DoFs held. A requested dt above safety x
// dt_crit is refused unless allow_unstable; an evaluation that fails (J <= 0, a non-finite stress) stops the run
// with the time and the reason, never a NaN state.
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

#include "solid/hyperelastic.hpp"

namespace polymech::solid {

// Nodes of a named side tied to a rigid body (see the header).
template <int D>
struct RigidTie {
  static constexpr int dofs = D + 1;  // D translations and the rotation about `axis`
  std::string boundary;
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // 3D: the rotation axis (normalised here); 2D: z
  double mass = 0.0;     // the body's own mass (the tied nodes' lumped mass is added)
  double inertia = 0.0;  // its own moment of inertia about the axis through the reference point
  // Per body DoF (x, y, (z), rotation): a prescribed velocity of time, or empty (free).
  std::array<std::function<double(double)>, D + 1> velocity;
  // Per free body DoF: the applied force (torque) as a function of time; empty: none.
  std::array<std::function<double(double)>, D + 1> load;
};

struct ExplicitFiniteStrainOptions {
  double density = 1.0;
  double dt = 0.0;               // 0: safety x dt_crit of the initial state
  double safety = 0.9;
  double damping = 0.0;          // alpha: mass-proportional damping of the free nodes (1/s)
  bool allow_unstable = false;   // accept dt > safety x dt_crit (to show the instability)
  int power_iterations = 300;
  double power_tolerance = 1e-4;
  std::function<double(double)> load_factor;  // s(t); empty: 1
};

// The body's state (host): the reference point, the rotation, their rates, the forces of the last evaluation.
template <int D>
struct TieState {
  std::array<double, D> position{}, velocity{};
  double angle = 0.0, omega = 0.0;
  std::array<double, D + 1> force{};        // the structure's force (torque) on the body, plus the applied loads
  std::array<double, D + 1> drive_force{};  // what the driver of each prescribed DoF applies (0 on free DoFs)
};

template <class T, int D>
class HyperelasticExplicit {
 public:
  HyperelasticExplicit(const Config<D>& c, const HyperelasticLaw& law, const ExplicitFiniteStrainOptions& o,
                       const std::vector<FollowerPressure>& pressures = {}, const std::vector<RigidTie<D>>& ties = {})
      : solid_(c, law, pressures), o_(o), ties_(ties) {
    if (!(o.density > 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: density must be > 0");
    if (!(o.damping >= 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: damping must be >= 0");
    if (!(o.safety > 0.0 && o.safety <= 1.0)) throw std::invalid_argument("solid::HyperelasticExplicit: safety must be in (0, 1]");
    if (o.dt < 0.0 || !std::isfinite(o.dt)) throw std::invalid_argument("solid::HyperelasticExplicit: dt must be >= 0 (0: automatic)");
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
  double time() const { return t_; }
  std::int64_t steps() const { return steps_; }
  double time_step() const { return dt_; }
  double critical_time_step() const { return dt_crit_; }
  double omega_max() const { return omega_max_; }
  int power_iterations_used() const { return power_its_; }
  const View1<T>& displacement() const { return u_; }
  const View1<T>& velocity() const { return v_; }
  const View1<T>& lumped_mass() const { return mass_; }
  const std::vector<TieState<D>>& ties() const { return state_; }
  double tie_mass(std::size_t k) const { return body_[k].mass; }
  double tie_inertia(std::size_t k) const { return body_[k].inertia; }
  double strain_energy() const { return solid_.strain_energy(); }
  // External nodal forces that depend on the state (contact: models/solid/tyre.hpp's plate): called after each
  // residual with (t, u, v, r); it subtracts its forces from r (r = f_int - f_ext), so they reach the free nodes'
  // accelerations and, on tied nodes, the bodies. Not part of the critical-step estimate.
  using ExternalForce = std::function<void(double, const View1<T>&, const View1<T>&, const View1<T>&)>;
  void set_external_force(ExternalForce f) { external_ = std::move(f); }
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
    const auto v = v_, m = mass_;
    double e = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::fse_kinetic", range(solid_.dof_count()),
        KOKKOS_LAMBDA(const Index i, double& s) { s += 0.5 * double(m(i)) * double(v(i)) * double(v(i)); }, e);
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
    const double t0 = t_, t1 = t0 + dt_, h = 0.5 * dt_;
    const Index n = solid_.dof_count();
    {  // the free nodes: kick and drift
      const auto u = u_, v = v_, a = a_;
      const auto kind = kind_;
      const T th = static_cast<T>(h), tdt = static_cast<T>(dt_);
      Kokkos::parallel_for(
          "polymech::solid::fse_kick_drift", range(n), KOKKOS_LAMBDA(const Index i) {
            if (kind(i) != 0) return;
            v(i) += th * a(i);
            u(i) += tdt * v(i);
          });
    }
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
    evaluate(t1);
    {  // the free nodes: second kick
      const auto v = v_, a = a_;
      const auto kind = kind_;
      const T th = static_cast<T>(h);
      Kokkos::parallel_for(
          "polymech::solid::fse_kick", range(n), KOKKOS_LAMBDA(const Index i) {
            if (kind(i) == 0) v(i) += th * a(i);
          });
    }
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
  // Implementation (public only for nvcc's extended lambdas, docs/DEVELOPING.md).
  struct Body {
    double mass = 0.0, inertia = 0.0;
    std::array<double, 3> centre{}, axis{0.0, 0.0, 1.0};
    std::vector<std::int64_t> nodes;
    Kokkos::View<Index*, MemSpace> node_view;
    Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> offsets;  // X_i - c_0
    Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> gathered;        // -r at the tied nodes
  };

  double acceleration(std::size_t k, int q) const {
    const double m = q < D ? body_[k].mass : body_[k].inertia;
    return m > 0.0 ? state_[k].force[static_cast<std::size_t>(q)] / m : 0.0;
  }

  // The driver's force on each prescribed DoF: M_b A - F with A the prescribed acceleration (differenced).
  void drive_forces(std::size_t k, double t) {
    TieState<D>& s = state_[k];
    for (int q = 0; q <= D; ++q) {
      const auto& pv = ties_[k].velocity[static_cast<std::size_t>(q)];
      if (!pv) {
        s.drive_force[static_cast<std::size_t>(q)] = 0.0;
        continue;
      }
      const double e = 1e-3 * dt_ > 0.0 ? 1e-3 * dt_ : 1e-9;
      const double A = (pv(t + e) - pv(t - e)) / (2.0 * e);
      const double m = q < D ? body_[k].mass : body_[k].inertia;
      s.drive_force[static_cast<std::size_t>(q)] = m * A - s.force[static_cast<std::size_t>(q)];
    }
  }

  // Rotation of a body-fixed offset by theta about the axis (Rodrigues; 2D: about z).
  static void rotate(const std::array<double, 3>& n, double theta, const double* x, double* y) {
    const double c = std::cos(theta), s = std::sin(theta);
    if (D == 2) {
      y[0] = c * x[0] - s * x[1];
      y[1] = s * x[0] + c * x[1];
      return;
    }
    const double nx = n[0] * x[0] + n[1] * x[1] + n[2] * x[2];
    const double cr[3] = {n[1] * x[2] - n[2] * x[1], n[2] * x[0] - n[0] * x[2], n[0] * x[1] - n[1] * x[0]};
    for (int d = 0; d < 3; ++d) y[d] = c * x[d] + s * cr[d] + (1.0 - c) * nx * n[static_cast<std::size_t>(d)];
  }

  // The tied nodes' displacement (and with velocities, velocity) from the body's pose.
  void place_tied(std::size_t k, bool velocities) {
    const Body& b = body_[k];
    const TieState<D>& s = state_[k];
    const double ct = std::cos(s.angle), st = std::sin(s.angle);
    const double n0 = b.axis[0], n1 = b.axis[1], n2 = b.axis[2];
    double c[3] = {0, 0, 0}, c0[3] = {0, 0, 0}, V[3] = {0, 0, 0};
    for (int d = 0; d < D; ++d) {
      c[d] = s.position[static_cast<std::size_t>(d)];
      c0[d] = b.centre[static_cast<std::size_t>(d)];
      V[d] = s.velocity[static_cast<std::size_t>(d)];
    }
    const double w = s.omega;
    const auto nodes = b.node_view;
    const auto off = b.offsets;
    const auto u = u_, v = v_;
    Kokkos::parallel_for(
        "polymech::solid::fse_place_tied", range(static_cast<Index>(b.nodes.size())), KOKKOS_LAMBDA(const Index j) {
          const Index i = nodes(j);
          double x[3] = {0, 0, 0}, y[3] = {0, 0, 0};
          for (int d = 0; d < D; ++d) x[d] = off(j, d);
          if (D == 2) {
            y[0] = ct * x[0] - st * x[1];
            y[1] = st * x[0] + ct * x[1];
          } else {
            const double nx = n0 * x[0] + n1 * x[1] + n2 * x[2];
            const double cr[3] = {n1 * x[2] - n2 * x[1], n2 * x[0] - n0 * x[2], n0 * x[1] - n1 * x[0]};
            const double nn[3] = {n0, n1, n2};
            for (int d = 0; d < 3; ++d) y[d] = ct * x[d] + st * cr[d] + (1.0 - ct) * nx * nn[d];
          }
          for (int d = 0; d < D; ++d) u(D * i + d) = static_cast<T>(c[d] + y[d] - (c0[d] + x[d]));
          if (velocities) {  // V + omega n x y
            double wy[3];
            if (D == 2) {
              wy[0] = -w * y[1];
              wy[1] = w * y[0];
            } else {
              wy[0] = w * (n1 * y[2] - n2 * y[1]);
              wy[1] = w * (n2 * y[0] - n0 * y[2]);
              wy[2] = w * (n0 * y[1] - n1 * y[0]);
            }
            for (int d = 0; d < D; ++d) v(D * i + d) = static_cast<T>(V[d] + wy[d]);
          }
        });
  }

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
    const auto a = a_, r = r_, v = v_, m = mass_;
    const auto kind = kind_;
    const T alpha = static_cast<T>(o_.damping);
    Kokkos::parallel_for(
        "polymech::solid::fse_accelerate", range(solid_.dof_count()), KOKKOS_LAMBDA(const Index i) {
          a(i) = kind(i) == 0 ? -r(i) / m(i) - alpha * v(i) : T(0);
        });
    for (std::size_t k = 0; k < ties_.size(); ++k) body_force(k, t);
  }

  // The structure's force on body k: sum of -r over the tied DoFs, and its moment about c; plus the applied loads.
  void body_force(std::size_t k, double t) {
    Body& b = body_[k];
    const auto nodes = b.node_view;
    const auto gath = b.gathered;
    const auto r = r_;
    Kokkos::parallel_for(
        "polymech::solid::fse_gather_tied", range(static_cast<Index>(b.nodes.size())), KOKKOS_LAMBDA(const Index j) {
          for (int d = 0; d < D; ++d) gath(j, d) = -r(D * nodes(j) + d);
        });
    const auto gh = Kokkos::create_mirror_view_and_copy(HostSpace(), b.gathered);
    const auto oh = Kokkos::create_mirror_view_and_copy(HostSpace(), b.offsets);
    TieState<D>& s = state_[k];
    std::array<double, D + 1> F{};
    for (std::size_t j = 0; j < b.nodes.size(); ++j) {
      double x[3] = {0, 0, 0}, y[3] = {0, 0, 0}, f[3] = {0, 0, 0};
      for (int d = 0; d < D; ++d) {
        x[d] = oh(j, d);
        f[d] = gh(j, d);
        F[static_cast<std::size_t>(d)] += f[d];
      }
      rotate(b.axis, s.angle, x, y);  // x_i - c
      if (D == 2)
        F[D] += y[0] * f[1] - y[1] * f[0];
      else
        F[D] += b.axis[0] * (y[1] * f[2] - y[2] * f[1]) + b.axis[1] * (y[2] * f[0] - y[0] * f[2]) +
                b.axis[2] * (y[0] * f[1] - y[1] * f[0]);
    }
    for (int q = 0; q <= D; ++q) {
      const auto& l = ties_[k].load[static_cast<std::size_t>(q)];
      if (l && !ties_[k].velocity[static_cast<std::size_t>(q)]) F[static_cast<std::size_t>(q)] += l(t);
    }
    s.force = F;
  }

  // The largest eigenvalue of M_L^-1 K_t on the free DoFs by power iteration, K_t x by a directional
  // difference of the residual at the current state (the constrained and tied DoFs held).
  double largest_eigenvalue() {
    const Index n = solid_.dof_count();
    View1<T> x("polymech::solid::fse_power_x", n), r0("polymech::solid::fse_power_r0", n), up("polymech::solid::fse_power_u", n);
    const auto kind = kind_;
    Kokkos::parallel_for(
        "polymech::solid::fse_power_start", range(n), KOKKOS_LAMBDA(const Index i) {
          const unsigned long long hsh = (static_cast<unsigned long long>(i) + 1ull) * 0x9E3779B97F4A7C15ull;
          const T q = T(static_cast<double>((hsh >> 11) & 0xFFFFFull) / double(0xFFFFF)) * T(2) - T(1);
          x(i) = kind(i) == 0 ? q : T(0);
        });
    const double s = o_.load_factor ? o_.load_factor(t_) : 1.0;
    Kokkos::deep_copy(r0, r_);
    // eps: a perturbation ~1e-7 of the body's size per unit |x|_inf (|x|_inf = 1 after each normalisation)
    double size = 0.0;
    for (const double c : solid_.discretization().coordinates) size = std::fmax(size, std::fabs(c));
    const double eps = (std::is_same<T, float>::value ? 1e-3 : 1e-7) * std::fmax(size, 1e-300);
    const auto m = mass_;
    double lambda = 0.0;
    int it = 0;
    for (; it < o_.power_iterations; ++it) {
      const auto u = u_, xx = x, upp = up;
      const T te = static_cast<T>(eps);
      Kokkos::parallel_for(
          "polymech::solid::fse_power_perturb", range(n), KOKKOS_LAMBDA(const Index i) { upp(i) = u(i) + te * xx(i); });
      const double rn = solid_.residual(up, s, work_);
      if (!std::isfinite(rn)) throw std::runtime_error("solid::HyperelasticExplicit: the power iteration's perturbed state does not evaluate");
      const auto w = work_, rr = r0;
      double xkx = 0.0, xmx = 0.0, amax = 0.0;
      const T inv = static_cast<T>(1.0 / eps);
      Kokkos::parallel_reduce(
          "polymech::solid::fse_power_quotient", range(n),
          KOKKOS_LAMBDA(const Index i, double& s1, double& s2) {
            if (kind(i) != 0) return;
            const T kx = (w(i) - rr(i)) * inv;
            s1 += double(xx(i)) * double(kx);
            s2 += double(m(i)) * double(xx(i)) * double(xx(i));
            w(i) = kx / m(i);  // M_L^-1 K x
          },
          xkx, xmx);
      Kokkos::parallel_reduce(
          "polymech::solid::fse_power_norm", range(n),
          KOKKOS_LAMBDA(const Index i, double& mx) {
            const double wi = double(w(i)) < 0.0 ? -double(w(i)) : double(w(i));
            if (kind(i) == 0 && wi > mx) mx = wi;
          },
          Kokkos::Max<double>(amax));
      const double next = xkx / xmx;
      if (!(amax > 0.0)) break;
      const T sc = static_cast<T>(1.0 / amax);
      Kokkos::parallel_for(
          "polymech::solid::fse_power_update", range(n), KOKKOS_LAMBDA(const Index i) { xx(i) = kind(i) == 0 ? sc * w(i) : T(0); });
      const bool done = it > 0 && std::fabs(next - lambda) <= o_.power_tolerance * next;
      lambda = next;
      if (done) break;
    }
    power_its_ = it + 1;
    solid_.residual(u_, s, r_);  // restore the state's residual (and strain energy)
    if (!(lambda > 0.0)) throw std::runtime_error("solid::HyperelasticExplicit: the power iteration found no positive eigenvalue of M_L^-1 K_t");
    return lambda;
  }

 private:
  void set_up_ties() {
    const auto& X = solid_.discretization().coordinates;
    for (std::size_t k = 0; k < ties_.size(); ++k) {
      const RigidTie<D>& tie = ties_[k];
      Body b;
      if (!(tie.mass >= 0.0) || !(tie.inertia >= 0.0))
        throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "': mass and inertia must be >= 0");
      b.nodes = side_nodes(solid_.discretization(), tie.boundary);
      if (b.nodes.empty()) throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "' has no nodes");
      if (D == 3) {
        const double nn = std::sqrt(tie.axis[0] * tie.axis[0] + tie.axis[1] * tie.axis[1] + tie.axis[2] * tie.axis[2]);
        if (!(nn > 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "': the axis is zero");
        for (int d = 0; d < 3; ++d) b.axis[static_cast<std::size_t>(d)] = tie.axis[static_cast<std::size_t>(d)] / nn;
      }
      // mass, centre of mass of the tied nodes
      double m = 0.0, cm[3] = {0, 0, 0};
      for (const std::int64_t v : b.nodes)
        for (int d = 0; d < D; ++d) {
          const std::size_t i = static_cast<std::size_t>(D * v + d);
          if (kind_host_[i] != 0)
            throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary +
                                        "': a tied node is also constrained (a Dirichlet condition or another tie)");
          kind_host_[i] = 2;
          if (d == 0) m += mass_host_[i];
          cm[d] += mass_host_[i] * X[i];
        }
      for (int d = 0; d < D; ++d) b.centre[static_cast<std::size_t>(d)] = cm[d] / m;
      b.mass = tie.mass + m;
      const std::size_t nt = b.nodes.size();
      std::vector<double> off(nt * D);
      double I = tie.inertia;
      for (std::size_t j = 0; j < nt; ++j) {
        double y[3] = {0, 0, 0};
        for (int d = 0; d < D; ++d) y[d] = X[static_cast<std::size_t>(D * b.nodes[j] + d)] - b.centre[static_cast<std::size_t>(d)];
        for (int d = 0; d < D; ++d) off[j * D + static_cast<std::size_t>(d)] = y[d];
        double r2;
        if (D == 2) {
          r2 = y[0] * y[0] + y[1] * y[1];
        } else {
          const double ny = b.axis[0] * y[0] + b.axis[1] * y[1] + b.axis[2] * y[2];
          r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - ny * ny;
        }
        I += mass_host_[static_cast<std::size_t>(D * b.nodes[j])] * r2;
      }
      b.inertia = I;
      for (int q = 0; q <= D; ++q) {
        const bool free = !tie.velocity[static_cast<std::size_t>(q)];
        if (free && !((q < D ? b.mass : b.inertia) > 0.0))
          throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary +
                                      "': a free degree of freedom without mass or inertia");
      }
      b.node_view = Kokkos::View<Index*, MemSpace>("polymech::solid::fse_tied_nodes", nt);
      b.offsets = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::fse_tied_offsets", nt, D);
      b.gathered = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::solid::fse_tied_forces", nt, D);
      auto nh = Kokkos::create_mirror_view(b.node_view);
      auto oh = Kokkos::create_mirror_view(b.offsets);
      for (std::size_t j = 0; j < nt; ++j) {
        nh(j) = static_cast<Index>(b.nodes[j]);
        for (int d = 0; d < D; ++d) oh(j, d) = off[j * D + static_cast<std::size_t>(d)];
      }
      Kokkos::deep_copy(b.node_view, nh);
      Kokkos::deep_copy(b.offsets, oh);
      body_.push_back(b);
    }
    state_.assign(ties_.size(), TieState<D>{});
  }

  Hyperelastic<T, D> solid_;
  ExplicitFiniteStrainOptions o_;
  std::vector<RigidTie<D>> ties_;
  std::vector<Body> body_;
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
