// Incompressible Navier-Stokes in 2D on a quadrilateral mesh (issue 36; seed 002 paper 1 eqs. (1)-(3) with the
// mesh at rest: the ALE mesh velocity w enters the convective term and is zero until the mesh moves).
//
// Discretisation: Taylor-Hood Q2/Q1 (velocity biquadratic, pressure bilinear and continuous). The pair
// satisfies the discrete inf-sup (LBB) condition uniformly in h on quadrilateral meshes (Brezzi-Fortin; for
// Q2/Q1 Stenberg's macro-element argument), so it needs no pressure stabilisation and converges with
// velocity order 3 in L2 and pressure order 2. Geometry is isoparametric Q2 (the nodes of a curved boundary on
// the curve). The element residual and exact Newton Jacobian come from one Kokkos kernel over the elements
// (models/flow/kernels.hpp, "polymech::flow::element_residual_jacobian"); the host scatters them into a CSR
// pattern built once and factorises the Jacobian with the sparse direct solver (kernels/solvers/
// host_sparse_lu.hpp), Dirichlet velocities eliminated (their rows and columns left out).
//
// Time: BDF2 with the first step backward Euler, Newton to convergence in every step. BDF2 rather than
// Crank-Nicolson: it is L-stable (CN keeps the stiff viscous and pressure modes undamped and needs the pressure
// at half steps), it costs one nonlinear solve per step like CN, and its form c_t (u - u*) leaves the kernel
// identical to the steady one apart from c_t. Its price: a slight damping of resolved oscillations,
// O((omega dt)^4) per step.
//
// Forces on the obstacle (Babuska-Miller; the "volume" or reaction form): with the discrete solution, the
// residual of the weak momentum equation tested with v = e_k on the obstacle's velocity nodes (zero elsewhere)
// is the integral of the traction over the obstacle, so the force the fluid exerts on it is
//   F_k = - sum_(obstacle nodes a) R_(a,k)(u_h, p_h)
// (Turek & Hron 2006 eq. for F_D, F_L, written as a domain integral over the elements that touch the body).
// It converges at the rate of the energy norm squared, against the rate of the stress for a line integral.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "fem/basis.hpp"
#include "fem/gauss_legendre.hpp"
#include "fem/point_basis.hpp"
#include "flow/kernels.hpp"
#include "flow/mesh.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::flow {

using Vec2 = std::array<double, 2>;

struct FlowConfig {
  double rho = 1.0, nu = 1.0;  // density, kinematic viscosity
  unsigned dirichlet_tags = kInflow | kWall | kObstacle;
  // the prescribed velocity at a Dirichlet node (its tags, position and time); empty: zero (no slip)
  std::function<Vec2(unsigned tags, double x, double y, double t)> boundary_velocity;
  std::function<Vec2(double x, double y)> body_force;  // force per unit volume; empty: none
  // a closed domain (every velocity prescribed) fixes the pressure at the vertex nearest this point
  bool pin_pressure = false;
  Vec2 pin_point{0.0, 0.0};
  double pin_value = 0.0;
  int newton_max = 25;
  double newton_tol = 1e-10;  // converged when the velocity update is below tol x max|u| and the pressure's below tol x max|p|
  int picard_steps = 0;       // first iterations with the Oseen linearisation (a far initial guess)
  // time steps: keep the first iteration's factorisation for the step's later iterations (the chord method),
  // refactorising only when an update shrinks by less than 3x; the converged state is the same
  bool chord = false;
};

struct NewtonReport {
  int iterations = 0;
  bool converged = false;
  double residual = 0.0;  // max norm of the free residual at the last assembly
  double update = 0.0;    // max norm of the last update
};

struct Forces {
  double drag = 0.0, lift = 0.0;
};

// Process CPU seconds spent in the parts of the solve (std::clock: one thread's time with OMP_NUM_THREADS=1).
struct FlowTimings {
  double element_kernel = 0.0;  // the Kokkos element pass (residual and Jacobian)
  double scatter = 0.0;         // host copies and the scatter into the residual and the CSR values
  double factor = 0.0;          // sparse LU factorisation
  double solve = 0.0;           // the triangular solves
  long assemblies = 0, factorizations = 0;
};

// A flow problem on the mesh, its discretisation and state.
class NavierStokes2D {
 public:
  NavierStokes2D(QuadMesh mesh, FlowConfig config) : mesh_(std::move(mesh)), cfg_(std::move(config)) {
    if (!(cfg_.rho > 0) || !(cfg_.nu > 0)) throw std::invalid_argument("flow: density and viscosity must be positive");
    if (mesh_.element_count() < 1) throw std::invalid_argument("flow: the mesh has no elements");
    if (mesh_.tags.size() != static_cast<std::size_t>(mesh_.node_count()))
      throw std::invalid_argument("flow: the mesh has " + std::to_string(mesh_.tags.size()) + " node tags for " +
                                  std::to_string(mesh_.node_count()) + " nodes");
    number_dofs();
    build_basis();
    update_geometry();
    build_pattern();
    U_ = View1<double>("polymech::flow::U", static_cast<std::size_t>(ndof_));
    Ustar_ = View1<double>("polymech::flow::Ustar", static_cast<std::size_t>(ndof_));
    Re_ = View2<double>("polymech::flow::element_residual", static_cast<std::size_t>(ne_), kElementDofs);
    Ke_ = View2<double>("polymech::flow::element_jacobian", static_cast<std::size_t>(ne_), kElementDofs * kElementDofs);
    u_host_.assign(static_cast<std::size_t>(ndof_), 0.0);
    u_prev_ = u_prev2_ = u_host_;
    if (cfg_.body_force) set_body_force();
    apply_dirichlet(0.0);
  }

  const QuadMesh& mesh() const { return mesh_; }
  const FlowConfig& config() const { return cfg_; }
  std::int64_t unknowns() const { return nfree_; }
  std::int64_t dofs() const { return ndof_; }
  std::int64_t velocity_nodes() const { return nn_; }
  std::int64_t pressure_vertices() const { return nv_; }
  double time() const { return time_; }
  std::int64_t steps() const { return steps_; }
  // The state: velocity (node, c) at 2 node + c, pressure of vertex v at 2 nodes + v.
  const std::vector<double>& state() const { return u_host_; }
  std::vector<double>& state() { return u_host_; }
  std::int64_t pressure_dof_of_node(std::int64_t node) const { return vertex_[static_cast<std::size_t>(node)] < 0 ? -1 : 2 * nn_ + vertex_[static_cast<std::size_t>(node)]; }
  const Forces& forces() const { return forces_; }
  const FlowTimings& timings() const { return timings_; }
  // The full residual (every DoF, Dirichlet ones included) at the last assembly.
  const std::vector<double>& residual() const { return r_full_; }

  // The steady problem by Newton (Oseen steps first when picard_steps > 0).
  NewtonReport solve_steady() {
    apply_dirichlet(time_);
    return newton(0.0, false);
  }

  // One step of dt: BDF2 (backward Euler for the first step after a start or a change of dt).
  NewtonReport step(double dt) {
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
    const NewtonReport r = newton(ct, true);
    last_dt_ = dt;
    ++steps_;
    return r;
  }

  // Evaluation of the discrete solution: velocity, its gradient and the pressure at reference point (xi, eta)
  // of element e, with the physical point x and det J.
  struct PointValue {
    Vec2 x{}, u{};
    double grad[2][2] = {{0, 0}, {0, 0}};
    double p = 0.0, det = 0.0;
  };
  PointValue evaluate(std::int64_t e, double xi, double eta) const {
    static const std::vector<double> n2{-1.0, 0.0, 1.0}, n1{-1.0, 1.0};
    double l[2][3], dl[2][3], m[2][2];
    const double r[2] = {xi, eta};
    for (int d = 0; d < 2; ++d) {
      for (int i = 0; i < 3; ++i) {
        l[d][i] = fem::lagrange(n2, i, r[d]);
        dl[d][i] = fem::lagrange_derivative(n2, i, r[d]);
      }
      for (int i = 0; i < 2; ++i) m[d][i] = fem::lagrange(n1, i, r[d]);
    }
    PointValue v;
    double J[2][2] = {{0, 0}, {0, 0}}, gref[9][2];
    const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
    for (int a = 0; a < 9; ++a) {
      const int i = a % 3, j = a / 3;
      const double N = l[0][i] * l[1][j];
      gref[a][0] = dl[0][i] * l[1][j];
      gref[a][1] = l[0][i] * dl[1][j];
      for (int c = 0; c < 2; ++c) {
        const double xc = mesh_.x[2 * static_cast<std::size_t>(en[a]) + c];
        v.x[c] += N * xc;
        v.u[c] += N * u_host_[2 * static_cast<std::size_t>(en[a]) + c];
        J[c][0] += xc * gref[a][0];
        J[c][1] += xc * gref[a][1];
      }
    }
    v.det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    const double Ji[2][2] = {{J[1][1] / v.det, -J[0][1] / v.det}, {-J[1][0] / v.det, J[0][0] / v.det}};
    for (int a = 0; a < 9; ++a) {
      const double gx = gref[a][0] * Ji[0][0] + gref[a][1] * Ji[1][0], gy = gref[a][0] * Ji[0][1] + gref[a][1] * Ji[1][1];
      for (int c = 0; c < 2; ++c) {
        const double uc = u_host_[2 * static_cast<std::size_t>(en[a]) + c];
        v.grad[c][0] += uc * gx;
        v.grad[c][1] += uc * gy;
      }
    }
    const int corner[4] = {0, 2, 6, 8};
    for (int c = 0; c < 4; ++c)
      v.p += m[0][c % 2] * m[1][c / 2] * u_host_[static_cast<std::size_t>(2 * nn_ + vertex_[static_cast<std::size_t>(en[corner[c]])])];
    return v;
  }

  // Integrates g(point value) over the domain with a Gauss rule of `points` per direction.
  template <class F>
  double integrate(F&& g, int points = 5) const {
    std::vector<double> xq, wq;
    fem::gauss_legendre(points, xq, wq);
    double s = 0.0;
    for (std::int64_t e = 0; e < ne_; ++e)
      for (int j = 0; j < points; ++j)
        for (int i = 0; i < points; ++i) {
          const PointValue v = evaluate(e, xq[static_cast<std::size_t>(i)], xq[static_cast<std::size_t>(j)]);
          s += wq[static_cast<std::size_t>(i)] * wq[static_cast<std::size_t>(j)] * v.det * g(v);
        }
    return s;
  }

  // || div u ||_L2 over the domain.
  double divergence_l2() const {
    return std::sqrt(integrate([](const PointValue& v) { const double d = v.grad[0][0] + v.grad[1][1]; return d * d; }));
  }

  // The flux int u . n over the boundary nodes' edges on x = const (the inflow or outflow line), by Gauss on
  // the element edges whose three nodes carry `tag`.
  double flux_through(unsigned tag) const {
    std::vector<double> xq, wq;
    fem::gauss_legendre(4, xq, wq);
    const int sides[4][3] = {{0, 1, 2}, {6, 7, 8}, {0, 3, 6}, {2, 5, 8}};
    double flux = 0.0;
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
      for (int s = 0; s < 4; ++s) {
        bool on = true;
        for (int k = 0; k < 3; ++k) on = on && (mesh_.tags[static_cast<std::size_t>(en[sides[s][k]])] & tag) != 0;
        if (!on) continue;
        for (std::size_t q = 0; q < xq.size(); ++q) {
          const double xi = s < 2 ? xq[q] : (s == 2 ? -1.0 : 1.0), eta = s < 2 ? (s == 0 ? -1.0 : 1.0) : xq[q];
          const PointValue v = evaluate(e, xi, eta);
          // the edge's tangent from the reference derivative along it: n dl = (dy, -dx) up to orientation
          double dx = 0.0, dy = 0.0;
          static const std::vector<double> n2{-1.0, 0.0, 1.0};
          const double t = xq[q];
          for (int k = 0; k < 3; ++k) {
            const double dk = fem::lagrange_derivative(n2, k, t);
            dx += dk * mesh_.x[2 * static_cast<std::size_t>(en[sides[s][k]])];
            dy += dk * mesh_.x[2 * static_cast<std::size_t>(en[sides[s][k]]) + 1];
          }
          flux += wq[q] * std::abs(v.u[0] * dy - v.u[1] * dx);  // |u . n| dl (the lines are crossed one way)
        }
      }
    }
    return flux;
  }

  // A moving mesh (ALE; models/fsi/mesh_motion.hpp): new node coordinates (node_count x 2, the same topology),
  // then the geometry is recomputed (throws for an inverted element). The state is kept as the next start.
  void set_coordinates(const std::vector<double>& x) {
    if (x.size() != mesh_.x.size())
      throw std::invalid_argument("flow: set_coordinates got " + std::to_string(x.size()) + " values for " +
                                  std::to_string(mesh_.x.size()));
    mesh_.x = x;
    update_geometry();
  }
  // The mesh velocity w per node (node_count x 2, indexed like the state's velocity part) for the ALE convective
  // velocity u - w; an empty vector: a mesh at rest.
  void set_mesh_velocity(const std::vector<double>& w) {
    if (w.empty()) {
      W_ = View1<double>();
      return;
    }
    if (w.size() != static_cast<std::size_t>(2 * nn_))
      throw std::invalid_argument("flow: set_mesh_velocity got " + std::to_string(w.size()) + " values for " +
                                  std::to_string(2 * nn_));
    if (W_.extent(0) != w.size()) W_ = View1<double>("polymech::flow::W", w.size());
    copy_to(W_, w);
  }
  // Per-node prescribed velocities (a moving wall whose velocity is known node by node, e.g. the wet nodes of an
  // elastic body in a partitioned FSI step, models/fsi/turek_hron_fsi_transient.hpp): nodes[k] gets (values[2k],
  // values[2k + 1]) instead of boundary_velocity, from the next solve or step on. Each node must be a Dirichlet
  // node (a tag in dirichlet_tags); empty vectors remove the override.
  void set_node_velocity(const std::vector<std::int64_t>& nodes, const std::vector<double>& values) {
    if (values.size() != 2 * nodes.size())
      throw std::invalid_argument("flow: set_node_velocity got " + std::to_string(values.size()) + " values for " +
                                  std::to_string(nodes.size()) + " nodes (2 per node)");
    for (const std::int64_t n : nodes)
      if (n < 0 || n >= nn_ || !(mesh_.tags[static_cast<std::size_t>(n)] & cfg_.dirichlet_tags))
        throw std::invalid_argument("flow: set_node_velocity: node " + std::to_string(n) + " is not a Dirichlet velocity node");
    node_velocity_nodes_ = nodes;
    node_velocity_values_ = values;
  }

  // The time-stepping state (the solution and the two before it, time, step count, last dt), so a driver can
  // take the same step again (a coupling iteration of a partitioned FSI step: each iterate redoes t_n -> t_n+1).
  struct TimeState {
    std::vector<double> u, u_prev, u_prev2;
    double time = 0.0, last_dt = 0.0;
    std::int64_t steps = 0;
  };
  TimeState time_state() const { return TimeState{u_host_, u_prev_, u_prev2_, time_, last_dt_, steps_}; }
  void set_time_state(const TimeState& s) {
    if (s.u.size() != u_host_.size() || s.u_prev.size() != u_host_.size() || s.u_prev2.size() != u_host_.size())
      throw std::invalid_argument("flow: set_time_state got a state of another size");
    u_host_ = s.u;
    u_prev_ = s.u_prev;
    u_prev2_ = s.u_prev2;
    time_ = s.time;
    last_dt_ = s.last_dt;
    steps_ = s.steps;
  }

  // Oseen steps at the start of later solves (0 once a good initial state exists, e.g. in a coupling loop).
  void set_picard_steps(int n) { cfg_.picard_steps = std::max(0, n); }

  // Assembles the residual only (no Jacobian) at the current state and returns the forces on kObstacle.
  Forces evaluate_forces(double ct = 0.0) {
    assemble(ct, false, false);
    return forces_;
  }

 private:
  void number_dofs() {
    nn_ = mesh_.node_count();
    ne_ = mesh_.element_count();
    vertex_.assign(static_cast<std::size_t>(nn_), -1);
    nv_ = 0;
    for (std::int64_t e = 0; e < ne_; ++e)
      for (const int a : {0, 2, 6, 8}) {
        auto& v = vertex_[static_cast<std::size_t>(mesh_.elements[static_cast<std::size_t>(e) * 9 + a])];
        if (v < 0) v = nv_++;
      }
    ndof_ = 2 * nn_ + nv_;
    free_.assign(static_cast<std::size_t>(ndof_), 0);
    for (std::int64_t n = 0; n < nn_; ++n)
      if (mesh_.tags[static_cast<std::size_t>(n)] & cfg_.dirichlet_tags) free_[2 * n] = free_[2 * n + 1] = -1;
    if (cfg_.pin_pressure) {
      std::int64_t best = -1;
      double dmin = 1e300;
      for (std::int64_t n = 0; n < nn_; ++n) {
        if (vertex_[static_cast<std::size_t>(n)] < 0) continue;
        const double d = std::hypot(mesh_.x[2 * n] - cfg_.pin_point[0], mesh_.x[2 * n + 1] - cfg_.pin_point[1]);
        if (d < dmin) dmin = d, best = n;
      }
      pinned_ = 2 * nn_ + vertex_[static_cast<std::size_t>(best)];
      free_[static_cast<std::size_t>(pinned_)] = -1;
    }
    nfree_ = 0;
    for (auto& f : free_)
      if (f == 0) f = nfree_++;
    std::vector<std::int64_t> dh(static_cast<std::size_t>(ne_) * kElementDofs);
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
      std::int64_t* d = &dh[static_cast<std::size_t>(e) * kElementDofs];
      for (int a = 0; a < 9; ++a) {
        d[2 * a] = 2 * en[a];
        d[2 * a + 1] = 2 * en[a] + 1;
      }
      const int corner[4] = {0, 2, 6, 8};
      for (int c = 0; c < 4; ++c) d[18 + c] = 2 * nn_ + vertex_[static_cast<std::size_t>(en[corner[c]])];
    }
    elem_dofs_ = dh;
    in_.dofs = View2<std::int64_t>("polymech::flow::element_dofs", static_cast<std::size_t>(ne_), kElementDofs);
    auto h = Kokkos::create_mirror_view(in_.dofs);
    for (std::int64_t e = 0; e < ne_; ++e)
      for (int k = 0; k < kElementDofs; ++k) h(e, k) = dh[static_cast<std::size_t>(e) * kElementDofs + k];
    Kokkos::deep_copy(in_.dofs, h);
  }

  void build_basis() {
    tables_ = fem::gauss_tables(3);  // Q2 on the GLL nodes -1, 0, 1 at the 3 Gauss points
    std::vector<double> xq, wq;
    fem::gauss_legendre(3, xq, wq);
    const std::vector<double> n1{-1.0, 1.0};
    for (int q = 0; q < kPoints; ++q) {
      const int qi = q % 3, qj = q / 3;
      for (int a = 0; a < 9; ++a)
        basis_.N[q][a] = tables_.value[static_cast<std::size_t>(qi) * 3 + a % 3] * tables_.value[static_cast<std::size_t>(qj) * 3 + a / 3];
      for (int c = 0; c < 4; ++c)
        basis_.M[q][c] = fem::lagrange(n1, c % 2, xq[static_cast<std::size_t>(qi)]) * fem::lagrange(n1, c / 2, xq[static_cast<std::size_t>(qj)]);
    }
  }

 public:
  // The physical gradients and weights at the Gauss points from the current node coordinates (again after the
  // mesh moves). Throws for an inverted element.
  void update_geometry() {
    if (in_.grad.extent(0) != static_cast<std::size_t>(ne_)) {
      in_.grad = decltype(in_.grad)("polymech::flow::basis_gradients", static_cast<std::size_t>(ne_), kPoints);
      in_.wdet = View2<double>("polymech::flow::weights", static_cast<std::size_t>(ne_), kPoints);
    }
    auto gh = Kokkos::create_mirror_view(in_.grad);
    auto wh = Kokkos::create_mirror_view(in_.wdet);
    std::vector<double> grad(18);
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
      for (int q = 0; q < kPoints; ++q) {
        double w;
        const double det = fem::tensor_point(tables_, 2, q, en, mesh_.x, nullptr, grad.data(), w);
        if (!(det > 0.0)) throw std::invalid_argument("flow: element " + std::to_string(e) + " is inverted (det J <= 0)");
        wh(e, q) = w * det;
        for (int a = 0; a < 9; ++a)
          for (int d = 0; d < 2; ++d) gh(e, q, a, d) = grad[static_cast<std::size_t>(2 * a + d)];
      }
    }
    Kokkos::deep_copy(in_.grad, gh);
    Kokkos::deep_copy(in_.wdet, wh);
  }

 private:
  void set_body_force() {
    in_.force = View2<double>("polymech::flow::body_force", static_cast<std::size_t>(ne_), 2 * kPoints);
    auto fh = Kokkos::create_mirror_view(in_.force);
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
      for (int q = 0; q < kPoints; ++q) {
        double x = 0.0, y = 0.0;
        for (int a = 0; a < 9; ++a) {
          x += basis_.N[q][a] * mesh_.x[2 * static_cast<std::size_t>(en[a])];
          y += basis_.N[q][a] * mesh_.x[2 * static_cast<std::size_t>(en[a]) + 1];
        }
        const Vec2 f = cfg_.body_force(x, y);
        fh(e, 2 * q) = f[0];
        fh(e, 2 * q + 1) = f[1];
      }
    }
    Kokkos::deep_copy(in_.force, fh);
  }

  // The CSR pattern of the free-free Jacobian and, per element entry, its position in the value array.
  void build_pattern() {
    std::vector<std::vector<std::int64_t>> cols(static_cast<std::size_t>(nfree_));
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* d = &elem_dofs_[static_cast<std::size_t>(e) * kElementDofs];
      for (int k = 0; k < kElementDofs; ++k) {
        const std::int64_t r = free_[static_cast<std::size_t>(d[k])];
        if (r < 0) continue;
        for (int l = 0; l < kElementDofs; ++l) {
          const std::int64_t c = free_[static_cast<std::size_t>(d[l])];
          if (c >= 0) cols[static_cast<std::size_t>(r)].push_back(c);
        }
      }
    }
    rows_.clear();
    cols_.clear();
    std::vector<std::int64_t> start(static_cast<std::size_t>(nfree_) + 1, 0);
    for (std::int64_t r = 0; r < nfree_; ++r) {
      auto& c = cols[static_cast<std::size_t>(r)];
      std::sort(c.begin(), c.end());
      c.erase(std::unique(c.begin(), c.end()), c.end());
      start[static_cast<std::size_t>(r) + 1] = start[static_cast<std::size_t>(r)] + static_cast<std::int64_t>(c.size());
      for (const auto cc : c) {
        rows_.push_back(r);
        cols_.push_back(cc);
      }
    }
    values_.assign(cols_.size(), 0.0);
    position_.assign(static_cast<std::size_t>(ne_) * kElementDofs * kElementDofs, -1);
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* d = &elem_dofs_[static_cast<std::size_t>(e) * kElementDofs];
      for (int k = 0; k < kElementDofs; ++k) {
        const std::int64_t r = free_[static_cast<std::size_t>(d[k])];
        if (r < 0) continue;
        const auto& c = cols[static_cast<std::size_t>(r)];
        for (int l = 0; l < kElementDofs; ++l) {
          const std::int64_t cc = free_[static_cast<std::size_t>(d[l])];
          if (cc < 0) continue;
          const auto it = std::lower_bound(c.begin(), c.end(), cc);
          position_[(static_cast<std::size_t>(e) * kElementDofs + k) * kElementDofs + l] =
              start[static_cast<std::size_t>(r)] + (it - c.begin());
        }
      }
    }
  }

  void apply_dirichlet(double t) {
    for (std::int64_t n = 0; n < nn_; ++n) {
      const unsigned tags = mesh_.tags[static_cast<std::size_t>(n)];
      if (!(tags & cfg_.dirichlet_tags)) continue;
      Vec2 v{0.0, 0.0};
      if (cfg_.boundary_velocity) v = cfg_.boundary_velocity(tags, mesh_.x[2 * n], mesh_.x[2 * n + 1], t);
      u_host_[2 * static_cast<std::size_t>(n)] = v[0];
      u_host_[2 * static_cast<std::size_t>(n) + 1] = v[1];
    }
    for (std::size_t k = 0; k < node_velocity_nodes_.size(); ++k) {
      u_host_[2 * static_cast<std::size_t>(node_velocity_nodes_[k])] = node_velocity_values_[2 * k];
      u_host_[2 * static_cast<std::size_t>(node_velocity_nodes_[k]) + 1] = node_velocity_values_[2 * k + 1];
    }
    if (pinned_ >= 0) u_host_[static_cast<std::size_t>(pinned_)] = cfg_.pin_value;
  }

  static void copy_to(const View1<double>& v, const std::vector<double>& h) {
    auto m = Kokkos::create_mirror_view(v);
    for (std::size_t k = 0; k < h.size(); ++k) m(k) = h[k];
    Kokkos::deep_copy(v, m);
  }

  // The element kernel, then the host scatter: the full residual (forces) and, when asked, the free Jacobian.
  void assemble(double ct, bool jacobian, bool picard) {
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

  NewtonReport newton(double ct, bool transient) {
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

  double pmax() const {
    double m = 0.0;
    for (std::int64_t k = 2 * nn_; k < ndof_; ++k) m = std::max(m, std::abs(u_host_[static_cast<std::size_t>(k)]));
    return m;
  }
  double umax() const {
    double m = 0.0;
    for (std::int64_t n = 0; n < 2 * nn_; ++n) m = std::max(m, std::abs(u_host_[static_cast<std::size_t>(n)]));
    return m;
  }

  QuadMesh mesh_;
  FlowConfig cfg_;
  std::int64_t nn_ = 0, ne_ = 0, nv_ = 0, ndof_ = 0, nfree_ = 0, pinned_ = -1;
  std::vector<std::int64_t> vertex_, free_, elem_dofs_;
  fem::GaussTables tables_;
  ElementBasis basis_{};
  ElementInput in_;
  View1<double> U_, Ustar_, W_;  // W_ empty: a fixed mesh
  View2<double> Re_, Ke_;
  std::vector<std::int64_t> rows_, cols_, position_;
  std::vector<double> values_, r_full_;
  solvers::HostSparseLU lu_;
  std::vector<double> u_host_, u_prev_, u_prev2_;
  std::vector<std::int64_t> node_velocity_nodes_;
  std::vector<double> node_velocity_values_;
  Forces forces_;
  FlowTimings timings_;
  double time_ = 0.0, last_dt_ = 0.0;
  std::int64_t steps_ = 0;
};

}  // namespace polymech::flow
