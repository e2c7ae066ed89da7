// The Turek-Hron FSI benchmark (Turek & Hron 2006, "Proposal for numerical benchmarking of fluid-structure
// interaction between an elastic object and laminar incompressible flow", LNCSE 53, section 3.3), the steady
// FSI1 (issue 36's ladder): the channel flow of models/flow/turek_hron.hpp around the cylinder with an elastic
// St. Venant-Kirchhoff flag, rho_f = 1000, nu_f = 1e-3, Ubar = 0.2 (Re 20); rho_s = 1000, nu_s = 0.4,
// mu_s = 0.5e6. Reference (Table 12): ux(A) = 0.0227e-3, uy(A) = 0.8209e-3, drag 14.295, lift 0.7638 (A: the
// middle of the flag's tip, (0.6, 0.2) at rest; forces on cylinder and flag per unit depth).
//
// Partitioned Dirichlet-Neumann coupling on matching interface meshes:
//   x = the displacement of the flag's wet nodes (top, bottom and tip sides, 2 per node),
//   G(x) = solid(fluid(mesh(x))):
//     mesh:  d = the pseudo-elastic extension of x into the fluid mesh (models/fsi/mesh_motion.hpp), the fluid
//            mesh's nodes at X + d (NavierStokes2D::set_coordinates: the Gauss-point geometry recomputed);
//     fluid: the steady Navier-Stokes solve on the moved mesh (Newton, from the last state);
//     loads: the fluid's reaction forces at the wet nodes, f_a = -R_a(u_h, p_h) (the residual of the momentum
//            equation tested with the basis function of node a: the consistent nodal force of the traction on
//            the deformed interface, the same quantity whose sum is the reaction-form drag and lift);
//     solid: solid::Hyperelastic (total Lagrangian SVK, plane strain) under these nodal forces as dead loads
//            (Hyperelastic::set_nodal_load), Newton from its last state; G(x) = its wet nodes' displacement.
// solved by fsi::InterfaceCoupling (IQN-ILS or Aitken). The solid's lattice is built so that its nodes on the
// wet sides are the fluid mesh's nodes on the flag (order 2, the flag block's cells of make_turek_hron_channel:
// 2^(level+1) cells from the root to x = 0.3, 6 2^level to the tip, 2^level across), so the force is passed node
// to node (momentum exactly conserved: the sum over the wet nodes the solid receives is the fluid's force on the
// flag) and the fluid mesh's wet nodes sit exactly at the solid's nodes plus the interface displacement.
//
// The flag's root: the fluid mesh meets the flag at x_r = 0.2 + sqrt(0.05^2 - 0.01^2) = 0.24899 (where the flag's
// sides meet the circle); the benchmark's flag is clamped on the cylinder's arc between those points. With
// arc_root the solid lattice is mapped so that its root edge is that arc (x = xi + delta(y) (0.3 - xi) /
// (0.3 - x_r) for xi < 0.3, delta(y) = 0.2 + sqrt(0.05^2 - (y - 0.2)^2) - x_r: zero on the wet sides, so they
// stay straight and matched); without it the root is the straight segment x = x_r.
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "fsi/coupling.hpp"
#include "fsi/mesh_motion.hpp"
#include "flow/navier_stokes.hpp"
#include "flow/turek_hron.hpp"
#include "solid/hyperelastic.hpp"

namespace polymech::fsi {

struct TurekHronFsiReference {
  double ux = 0.0, uy = 0.0, drag = 0.0, lift = 0.0;
};
// Turek & Hron 2006, Table 12 (FSI1).
inline TurekHronFsiReference turek_hron_fsi1_reference() { return {0.0227e-3, 0.8209e-3, 14.295, 0.7638}; }

struct TurekHronFsiCase {
  int level = 0;
  double mean_velocity = 0.2;             // Ubar (FSI1)
  double rho_f = 1000.0, nu_f = 1e-3;     // fluid
  double rho_s = 1000.0, nu_s = 0.4, mu_s = 0.5e6;  // solid (SVK; rho_s enters only unsteady runs)
  // gravity on the flag, m/s^2 along -y (CSM3's g = 2): the dead body force rho_s g per reference volume; the
  // fluid gets none (no buoyancy). 0 (FSI1/2/3): no body force, the runs as before bitwise.
  double gravity = 0.0;
  bool arc_root = true;                   // clamp the flag on the cylinder's arc (false: straight root at x_r)
  double ramp_time = 0.0;                 // the inflow's (1 - cos) ramp (unsteady runs: 2 s; 0: full from t = 0)
  bool fluid_chord = false;               // the fluid's time steps keep their first factorisation (FlowConfig::chord)
  double solid_tolerance = 1e-10;         // the solid's Newton test |r| <= tol F_ref (below the coupling's)
  MeshMotionOptions mesh;
  CouplingOptions coupling;               // tolerance relative to |x~| (the wet nodes' displacement)
};

// CPU seconds (std::clock, one thread) per part of the interface map, and the counts.
struct TurekHronFsiTimings {
  double mesh = 0.0, fluid = 0.0, solid = 0.0, setup = 0.0;
  int evaluations = 0, fluid_newton = 0, solid_newton = 0;
};

struct TurekHronFsiResult {
  CouplingResult coupling;
  double ux = 0.0, uy = 0.0;         // point A
  double drag = 0.0, lift = 0.0;     // cylinder and flag
  double flag_drag = 0.0, flag_lift = 0.0;  // the flag's share: the sum of the nodal forces passed to the solid
  double min_jacobian_ratio = 0.0;   // of the moved fluid mesh (Gauss points), > 0: no cell inverted
  double interface_mismatch = 0.0;   // max |x_fluid - (X_solid + u_solid)| over the wet nodes
};

class TurekHronFsi {
 public:
  explicit TurekHronFsi(const TurekHronFsiCase& c) : case_(c) {
    const std::clock_t c0 = std::clock();
    if (c.level < 0 || c.level > 4) throw std::invalid_argument("turek-hron fsi: level " + std::to_string(c.level) + " outside 0..4");
    const flow::TurekHronGeometry g{};
    flow::QuadMesh mesh = flow::make_turek_hron_channel(c.level, g);
    X_ = mesh.x;
    // the solid lattice on the flag block's cells
    const int f = 1 << c.level;
    const double xr = g.cx + g.radius * std::cos(std::asin((g.flag_high - g.cy) / g.radius)), xm = g.cx + 0.1;
    std::vector<double> px, py;
    for (int k = 0; k <= 2 * f; ++k) px.push_back(xr + (xm - xr) * k / (2.0 * f));
    for (int k = 1; k <= 6 * f; ++k) px.push_back(xm + (g.flag_end - xm) * k / (6.0 * f));
    for (int k = 0; k <= f; ++k) py.push_back(g.flag_low + (g.flag_high - g.flag_low) * k / f);
    solid::Config<2> sc;
    sc.mesh = solid::make_tensor_box<2>({px, py});
    if (c.arc_root) {
      const double cx = g.cx, cy = g.cy, r = g.radius;
      sc.mesh.map = [xr, xm, cx, cy, r](const double* xi, double* x) {
        const double dy = xi[1] - cy, delta = cx + std::sqrt(std::max(0.0, r * r - dy * dy)) - xr;
        x[0] = xi[0] + (xi[0] < xm ? delta * (xm - xi[0]) / (xm - xr) : 0.0);
        x[1] = xi[1];
      };
      sc.affine_geometry = false;
    }
    sc.order = 2;
    sc.dirichlet.push_back({"xmin", 3u, {}});
    if (!std::isfinite(c.gravity)) throw std::invalid_argument("turek-hron fsi: gravity must be finite");
    if (c.gravity != 0.0) {
      const double w = c.rho_s * c.gravity;
      sc.body_forces.push_back({[w](const double*, double* b) { b[0] = 0.0, b[1] = -w; }});
    }
    if (!(c.mu_s > 0) || !(c.nu_s > 0 && c.nu_s < 0.5)) throw std::invalid_argument("turek-hron fsi: need mu_s > 0 and 0 < nu_s < 0.5");
    materials::StVenantKirchhoff<double> law;
    law.elastic.mu = c.mu_s;
    law.elastic.lambda = 2 * c.mu_s * c.nu_s / (1 - 2 * c.nu_s);
    solid::NewtonOptions so = solid::finite_strain_newton_options();
    so.tolerance = c.solid_tolerance;
    solid_ = std::make_unique<solid::Hyperelastic<double, 2>>(sc, solid::HyperelasticLaw(law), std::vector<solid::FollowerPressure>{}, so);
    // the wet nodes: the solid's nodes on ymin, ymax, xmax (root corners included: clamped, zero displacement)
    const auto& Xs = solid_->discretization().coordinates;
    const double tol = 1e-9;
    point_a_ = -1;
    for (std::size_t v = 0; v < Xs.size() / 2; ++v) {
      const double x = Xs[2 * v], y = Xs[2 * v + 1];
      if (std::fabs(x - g.flag_end) < tol && std::fabs(y - g.cy) < tol) point_a_ = static_cast<std::int64_t>(v);
      if (!(std::fabs(y - g.flag_low) < tol || std::fabs(y - g.flag_high) < tol || std::fabs(x - g.flag_end) < tol)) continue;
      std::int64_t best = -1;
      double dmin = 1e300;
      for (std::int64_t n = 0; n < mesh.node_count(); ++n) {
        if (!(mesh.tags[static_cast<std::size_t>(n)] & flow::kObstacle)) continue;
        const double dd = std::hypot(mesh.x[2 * n] - x, mesh.x[2 * n + 1] - y);
        if (dd < dmin) dmin = dd, best = n;
      }
      if (!(dmin < tol))
        throw std::logic_error("turek-hron fsi: the solid's wet node at (" + std::to_string(x) + ", " + std::to_string(y) +
                               ") has no fluid node (nearest " + std::to_string(dmin) + " away)");
      solid_wet_.push_back(static_cast<std::int64_t>(v));
      fluid_wet_.push_back(best);
    }
    if (point_a_ < 0) throw std::logic_error("turek-hron fsi: no solid node at point A");
    // every fluid node on the flag (obstacle nodes right of the root) must be a wet node
    std::size_t flag_nodes = 0;
    for (std::int64_t n = 0; n < mesh.node_count(); ++n)
      if ((mesh.tags[static_cast<std::size_t>(n)] & flow::kObstacle) && mesh.x[2 * n] > xr - tol && mesh.x[2 * n + 1] > g.flag_low - tol &&
          mesh.x[2 * n + 1] < g.flag_high + tol)
        ++flag_nodes;
    if (flag_nodes != fluid_wet_.size())
      throw std::logic_error("turek-hron fsi: " + std::to_string(flag_nodes) + " fluid nodes on the flag, " +
                             std::to_string(fluid_wet_.size()) + " matched to the solid");
    motion_ = std::make_unique<PseudoElasticMeshMotion>(mesh, fluid_wet_, c.mesh);
    flow::TurekHronCase fc;
    fc.mean_velocity = c.mean_velocity;
    fc.rho = c.rho_f;
    fc.nu = c.nu_f;
    fc.level = c.level;
    fc.ramp_time = c.ramp_time;
    flow::FlowConfig cfg = flow::turek_hron_config(fc, g);
    cfg.picard_steps = 3;
    cfg.chord = c.fluid_chord;
    fluid_ = std::make_unique<flow::NavierStokes2D>(std::move(mesh), cfg);
    timings_.setup = seconds(c0);
  }

  std::int64_t fluid_unknowns() const { return fluid_->unknowns(); }
  std::int64_t mesh_unknowns() const { return motion_->unknowns(); }
  std::int64_t solid_unknowns() const {
    std::int64_t n = 0;
    for (const char m : solid_->constrained_mask()) n += m ? 0 : 1;
    return n;
  }
  std::size_t interface_nodes() const { return solid_wet_.size(); }
  const flow::NavierStokes2D& fluid() const { return *fluid_; }
  const solid::Hyperelastic<double, 2>& solid() const { return *solid_; }
  const PseudoElasticMeshMotion& motion() const { return *motion_; }
  const TurekHronFsiTimings& timings() const { return timings_; }
  const std::vector<std::int64_t>& fluid_wet_nodes() const { return fluid_wet_; }
  const std::vector<std::int64_t>& solid_wet_nodes() const { return solid_wet_; }
  // The nodal forces of the last fluid solve on the solid's DoFs (the wet nodes' -R_a, zero elsewhere).
  const std::vector<double>& last_loads() const { return last_loads_; }

  // The fluid on the mesh moved by the interface displacement x: mesh motion, steady solve; returns the wet
  // nodes' forces (2 per node) on the solid's DoF vector.
  std::vector<double> fluid_loads(const std::vector<double>& x) {
    std::clock_t c0 = std::clock();
    const std::vector<double> d = motion_->displacement(x);
    fluid_->set_coordinates(motion_->coordinates(d));
    timings_.mesh += seconds(c0);
    c0 = std::clock();
    const flow::NewtonReport rep = fluid_->solve_steady();
    fluid_->set_picard_steps(0);  // later solves start next to the solution
    timings_.fluid += seconds(c0);
    timings_.fluid_newton += rep.iterations;
    if (!rep.converged)
      throw std::runtime_error("turek-hron fsi: the fluid's Newton iteration did not converge (" + std::to_string(rep.iterations) +
                               " iterations, |r| " + std::to_string(rep.residual) + ")");
    return wet_loads();
  }

  // The solid under the nodal forces f; returns the wet nodes' displacement.
  std::vector<double> solid_displacement(const std::vector<double>& f) {
    const std::clock_t c0 = std::clock();
    solid_->set_nodal_load(f);
    solid::StepResult res;
    if (!solid_->solve_step(1.0, res))
      throw std::runtime_error("turek-hron fsi: the solid's Newton iteration failed: " + solid_->last_failure());
    timings_.solid += seconds(c0);
    timings_.solid_newton += res.newton_iterations;
    return wet_displacement();
  }

  std::vector<double> wet_displacement() const {
    const std::vector<double> u = solid_->displacement_host();
    std::vector<double> x(2 * solid_wet_.size());
    for (std::size_t k = 0; k < solid_wet_.size(); ++k)
      for (int c = 0; c < 2; ++c) x[2 * k + static_cast<std::size_t>(c)] = u[static_cast<std::size_t>(2 * solid_wet_[k] + c)];
    return x;
  }

  // The steady coupled state from the current one. After the coupling converges the fluid is solved once more
  // on the mesh of the converged interface displacement x (= the solid's wet displacement), so the reported
  // forces belong to a fluid mesh that matches the solid to round-off.
  TurekHronFsiResult solve_steady() {
    TurekHronFsiResult out;
    InterfaceCoupling coupling(case_.coupling);
    std::vector<double> x = wet_displacement();
    out.coupling = coupling.solve(x, [&](const std::vector<double>& xi) {
      ++timings_.evaluations;
      return solid_displacement(fluid_loads(xi));
    });
    if (out.coupling.converged) {
      const std::vector<double> xs = wet_displacement();
      fluid_loads(xs);
      out.min_jacobian_ratio = motion_->min_jacobian_ratio(motion_->displacement(xs));
    }
    const std::vector<double> u = solid_->displacement_host();
    out.ux = u[static_cast<std::size_t>(2 * point_a_)];
    out.uy = u[static_cast<std::size_t>(2 * point_a_ + 1)];
    out.drag = fluid_->forces().drag;
    out.lift = fluid_->forces().lift;
    out.flag_drag = flag_force_[0];
    out.flag_lift = flag_force_[1];
    const auto& Xs = solid_->discretization().coordinates;
    const auto& xf = fluid_->mesh().x;
    for (std::size_t k = 0; k < solid_wet_.size(); ++k)
      for (int c = 0; c < 2; ++c) {
        const std::size_t s = static_cast<std::size_t>(2 * solid_wet_[k] + c);
        out.interface_mismatch =
            std::max(out.interface_mismatch, std::fabs(xf[static_cast<std::size_t>(2 * fluid_wet_[k] + c)] - (Xs[s] + u[s])));
      }
    return out;
  }

 protected:  // (the unsteady driver, models/fsi/turek_hron_fsi_transient.hpp, builds on the same set-up)
  // The wet nodes' reaction forces of the fluid's last solve (f_a = -R_a, the consistent nodal force of the
  // traction) on the solid's DoF vector; their sum is the fluid's force on the flag.
  std::vector<double> wet_loads() {
    const std::vector<double>& r = fluid_->residual();
    std::vector<double> f(static_cast<std::size_t>(solid_->dof_count()), 0.0);
    flag_force_[0] = flag_force_[1] = 0.0;
    for (std::size_t k = 0; k < solid_wet_.size(); ++k)
      for (int c = 0; c < 2; ++c) {
        const double fk = -r[static_cast<std::size_t>(2 * fluid_wet_[k] + c)];
        f[static_cast<std::size_t>(2 * solid_wet_[k] + c)] = fk;
        flag_force_[c] += fk;
      }
    last_loads_ = f;
    return f;
  }

  static double seconds(std::clock_t c0) { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; }

  TurekHronFsiCase case_;
  std::vector<double> X_;
  std::unique_ptr<solid::Hyperelastic<double, 2>> solid_;
  std::unique_ptr<PseudoElasticMeshMotion> motion_;
  std::unique_ptr<flow::NavierStokes2D> fluid_;
  std::vector<std::int64_t> solid_wet_, fluid_wet_;
  std::int64_t point_a_ = -1;
  double flag_force_[2] = {0.0, 0.0};
  std::vector<double> last_loads_;
  TurekHronFsiTimings timings_;
};

}  // namespace polymech::fsi
