// The incompressible Navier-Stokes model of models/flow (issue 36): its configuration, reports and the class
// flow::NavierStokes2D with its state and accessors. Its members are defined by job in the files listed in
// models/flow/navier_stokes.hpp, which holds them all (include that one).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "fem/basis.hpp"
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
  // C_s of a Smagorinsky eddy viscosity nu_t = (C_s Delta)^2 |S| added to nu in time steps (0: none, the model
  // as before). |S| from the step's extrapolated velocity (2 u^n - u^(n-1); u^n after a start), so nu_t is data
  // of the step and Newton's Jacobian stays exact; a stabiliser for meshes too coarse for the Reynolds number
  // (the flow-driven harvester, Re ~ 1700: models/fsi/flow_harvester.hpp), not a turbulence model of 2D flow.
  double smagorinsky = 0.0;
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
    if (!(cfg_.smagorinsky >= 0.0) || !std::isfinite(cfg_.smagorinsky)) throw std::invalid_argument("flow: the Smagorinsky constant must be >= 0 and finite");
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
  NewtonReport solve_steady();
  // One step of dt: BDF2 (backward Euler for the first step after a start or a change of dt).
  NewtonReport step(double dt);
  // Assembles the residual only (no Jacobian) at the current state and returns the forces on kObstacle.
  Forces evaluate_forces(double ct = 0.0);

  // Evaluation of the discrete solution: velocity, its gradient and the pressure at reference point (xi, eta)
  // of element e, with the physical point x and det J.
  struct PointValue {
    Vec2 x{}, u{};
    double grad[2][2] = {{0, 0}, {0, 0}};
    double p = 0.0, det = 0.0;
  };
  PointValue evaluate(std::int64_t e, double xi, double eta) const;
  // Integrates g(point value) over the domain with a Gauss rule of `points` per direction.
  template <class F>
  double integrate(F&& g, int points = 5) const;
  // || div u ||_L2 over the domain.
  double divergence_l2() const;
  // The flux int u . n through the element edges whose three nodes carry `tag` (an inflow or outflow line).
  double flux_through(unsigned tag) const;

  // A moving mesh (ALE): new node coordinates, then the geometry recomputed; the state is kept.
  void set_coordinates(const std::vector<double>& x);
  // The mesh velocity w per node for the ALE convective velocity u - w; an empty vector: a mesh at rest.
  void set_mesh_velocity(const std::vector<double>& w);
  // Per-node prescribed velocities of Dirichlet nodes (a moving wall known node by node); empty: none.
  void set_node_velocity(const std::vector<std::int64_t>& nodes, const std::vector<double>& values);

  // The time-stepping state (the solution and the two before it, time, step count, last dt), so a driver can
  // take the same step again (a coupling iteration of a partitioned FSI step: each iterate redoes t_n -> t_n+1).
  struct TimeState {
    std::vector<double> u, u_prev, u_prev2;
    double time = 0.0, last_dt = 0.0;
    std::int64_t steps = 0;
  };
  TimeState time_state() const { return TimeState{u_host_, u_prev_, u_prev2_, time_, last_dt_, steps_}; }
  void set_time_state(const TimeState& s);

  // Oseen steps at the start of later solves (0 once a good initial state exists, e.g. in a coupling loop).
  void set_picard_steps(int n) { cfg_.picard_steps = std::max(0, n); }

  // The physical gradients and weights at the Gauss points from the current node coordinates (again after the
  // mesh moves). Throws for an inverted element.
  void update_geometry();

 private:
  // the discretisation (navier_stokes_discretization.hpp)
  void number_dofs();
  void build_basis();
  void set_body_force();
  void build_pattern();
  // the boundary values (navier_stokes_motion.hpp)
  void apply_dirichlet(double t);
  // assembly and Newton (navier_stokes_solve.hpp)
  static void copy_to(const View1<double>& v, const std::vector<double>& h);
  void assemble(double ct, bool jacobian, bool picard);
  NewtonReport newton(double ct, bool transient);
  double pmax() const;
  double umax() const;

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
