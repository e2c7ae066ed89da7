// The flow-driven piezoelectric harvester (seed 002 paper 1, case 2, Figs. 3, 5, 6; issue 36): a flexible
// bimorph plate clamped behind a rigid square cylinder in a uniform air stream, excited by the wake; the
// resistor across its electrodes harvests the vibration.
//
// The paper gives: air, the inflow 0.85 m/s, the plate "of the same structure as" case 1 (PZT-5A on a brass host,
// models/piezo/cases.hpp) with t_l = 270 mm, t_p = 0.2 mm, t_h = 0.2 mm, 20 s of flow (Fig. 6). It does not give
// the cylinder's size, the channel, the resistor, the damping, nor whether the 2D model is plane stress or
// strain. Choices here (docs/METHODS.md, "The flow-driven harvester"):
//   - the cylinder's side D is chosen so the question of the paper can be asked at 0.85 m/s: the shedding
//     frequency of a square cylinder, St U / D with St = 0.13 (Okajima 1982, Re ~ 10^3), equals the plate's
//     first short-circuit frequency f_1 (D = St U / f_1; lock_in_side()); a sweep of the plate's length then
//     moves f_1 across the shedding frequency at the paper's speed and Reynolds number (sweep_flow_harvester);
//   - the channel 14 D high, 5 D upstream of the cylinder, 8 D behind the plate's tip, its walls moving with the
//     stream (a far-field condition, no boundary layers); the inflow uniform, ramped by (1 - cos(pi t / T)) / 2
//     over T = ramp_time, with a transverse gust 0.02 U sin(pi t / T) over the ramp that breaks the symmetry (a
//     symmetric start sheds only from round-off);
//   - air at 20 C: rho 1.204 kg/m^3, nu 1.516e-5 m^2/s;
//   - the plate per metre of span (the beam's width 1 m: forces N/m, power W/m), plane stress as case 1, one
//     order-2 cell through each layer, the cells along it those of the fluid mesh's plate column (matching
//     nodes); the load resistor R = 1 / (omega_1 C_p) per metre of span (the optimum of a single-mode harvester,
//     C_p the series capacitance of the two layers), Rayleigh damping zeta = 0.01 at omega_1 (case 1's);
//   - the structure is linear (small strain; the piezo model of issue 35): tip amplitudes are a few per cent of
//     the plate's length here; a larger swing would need the finite-strain solid.
//
// One time step, partitioned Dirichlet-Neumann as the Turek-Hron FSI (models/fsi/turek_hron_fsi_transient.hpp):
// x = the wet nodes' displacement at t_n+1; G(x): the mesh (pseudo-elastic, on the reference mesh by default), the mesh velocity
// (BDF2), the wet nodes' no-slip velocity from the structure's Newmark velocity implied by x, the fluid's BDF2
// step, the wet nodes' reaction forces, and the harvester's step under them; IQN-ILS on x. Paper 1's Fig. 3
// nests the piezo-circuit loop (its Fig. 2: the electrode potentials the unknowns of a quasi-Newton iteration on
// the charge residual r^Q, eqs. (9), (10)) inside this FSI loop: scheme = partitioned. scheme = monolithic
// solves the piezo-structure and circuit together in each FSI iterate (one loop; paper 1 mentions it as
// possible). Both give the same state at the coupling's convergence.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/harvester_mesh.hpp"
#include "flow/navier_stokes.hpp"
#include "flow/time_state_archive.hpp"
#include "fsi/coupling.hpp"
#include "fsi/mesh_motion.hpp"
#include "piezo/cases.hpp"
#include "piezo/transient.hpp"

namespace polymech::fsi {

struct FlowHarvesterCase {
  int level = 0;
  double inflow = 0.85;                  // U [m/s]
  double rho_f = 1.204, nu_f = 1.516e-5; // air at 20 C
  double side = 0.0;                     // D [m]; 0: lock_in_side() at `inflow`
  double strouhal = 0.13;                // the square cylinder's (Okajima 1982), for lock_in_side()
  double plate_length = 0.27, piezo_thickness = 0.2e-3, host_thickness = 0.2e-3;
  double upstream = 5.0, downstream = 8.0, height = 14.0;  // in D
  double ramp_time = 1.0, gust = 0.02;   // the inflow's ramp [s] and the transverse gust over it (of U)
  double resistance = 0.0;               // [ohm] per metre of span; 0: 1 / (omega_1 C_p)
  double zeta = 0.01;                    // stiffness-proportional damping at omega_1
  piezo::Scheme scheme = piezo::Scheme::monolithic;
  double dt = 0.0025;
  double smagorinsky = 0.1;              // C_s of the fluid's eddy viscosity (flow::FlowConfig::smagorinsky; 0: none)
  // the mesh motion: false (default) the pseudo-elastic extension of x on the reference mesh, assembled and
  // factorised once; true: incremental from the mesh at t_n (FSI2's default: refactorised every step, 40 % of a
  // level-0 step here). The plate moves < 1 mm (< 0.03 D): the two give the same mesh to O(|x|^2 / D).
  bool incremental_mesh = false;
  CouplingOptions coupling{CouplingMethod::iqn_ils, 0.5, 1.0, 1e-6, 1e-3, 50, 8, 1e-10, 1e6};
  MeshMotionOptions mesh;
};

// The bimorph of paper 1 case 2, per metre of span: PZT-5A / brass / PZT-5A, poled oppositely (series), the
// outer faces the electrodes; order 2, `cells` along the plate.
inline piezo::BeamSpec flow_harvester_plate(const FlowHarvesterCase& c, int cells) {
  piezo::BeamSpec s = piezo::dutoit_harvester_spec(2, cells, 1);
  s.length = c.plate_length;
  s.width = 1.0;
  s.layers[0].thickness = s.layers[2].thickness = c.piezo_thickness;
  s.layers[1].thickness = c.host_thickness;
  return s;
}

// The plate's series capacitance per metre of span, C_p = eps33_bar L / (2 t_p), eps33_bar = eps33^T - d31^2 / s11^E
// (the beam-theory permittivity of the clamped-in-thickness layer).
inline double flow_harvester_capacitance(const FlowHarvesterCase& c) {
  const piezo::PiezoCeramic m = piezo::pzt5a();
  const double eps = m.eps33T - m.d31 * m.d31 / m.s11E;
  return eps * c.plate_length / (2.0 * c.piezo_thickness);
}

// D = St U / f_1: the cylinder whose shedding frequency (alone) is the plate's first short-circuit frequency.
inline double lock_in_side(const FlowHarvesterCase& c) {
  const piezo::PiezoBeam beam(flow_harvester_plate(c, 12));
  const double f1 = beam.natural_frequency(true) / (2.0 * 3.14159265358979323846);
  return c.strouhal * c.inflow / f1;
}

struct FlowHarvesterStep {
  double t = 0.0, tip = 0.0, drag = 0.0, lift = 0.0, voltage = 0.0, power = 0.0;
  int evaluations = 0, circuit_iterations = 0;  // FSI iterates; piezo-circuit solves summed over them
  double residual = 0.0;
};

struct FlowHarvesterTimings {
  double mesh = 0.0, fluid = 0.0, structure = 0.0, setup = 0.0;
  long evaluations = 0, circuit_solves = 0, fluid_newton = 0;
};

class FlowHarvester {
 public:
  explicit FlowHarvester(FlowHarvesterCase c) : case_(c), coupling_(c.coupling) {
    const std::clock_t c0 = std::clock();
    auto bad = [](const std::string& m) { throw std::invalid_argument("flow harvester: " + m); };
    if (!(c.inflow > 0.0) || !(c.rho_f > 0.0) || !(c.nu_f > 0.0)) bad("inflow, rho_f and nu_f must be positive");
    if (!(c.dt > 0.0) || !(c.ramp_time >= 0.0) || !(c.zeta >= 0.0) || !(c.resistance >= 0.0)) bad("dt > 0, ramp_time, zeta, resistance >= 0");
    if (!(c.plate_length > 0.0) || !(c.piezo_thickness > 0.0) || !(c.host_thickness > 0.0)) bad("the plate's sizes must be positive");
    if (case_.side == 0.0) case_.side = lock_in_side(case_);
    if (!(case_.side > 0.0)) bad("the cylinder's side must be positive");
    geometry_.side = case_.side;
    geometry_.plate_length = c.plate_length;
    geometry_.plate_thickness = 2.0 * c.piezo_thickness + c.host_thickness;
    geometry_.upstream = c.upstream, geometry_.downstream = c.downstream, geometry_.height = c.height;
    flow::HarvesterCells cells;
    flow::QuadMesh mesh = flow::make_harvester_channel(c.level, geometry_, cells);
    // the plate: order 2 on the plate column's cells
    beam_ = std::make_unique<piezo::PiezoBeam>(flow_harvester_plate(case_, cells.plate << c.level));
    omega_sc_ = beam_->natural_frequency(true);
    omega_oc_ = beam_->natural_frequency(false);
    capacitance_ = flow_harvester_capacitance(case_);
    resistance_ = c.resistance > 0.0 ? c.resistance : 1.0 / (omega_sc_ * capacitance_);
    piezo::TransientOptions po;
    po.dt = c.dt;
    po.scheme = c.scheme;
    po.damping = piezo::Rayleigh::stiffness_proportional(c.zeta, omega_sc_);
    transient_ = std::make_unique<piezo::PiezoTransient>(*beam_, piezo::harvester_load(*beam_, resistance_), po);
    transient_->start(0.0);
    match_wet_nodes(mesh);
    motion_ = std::make_unique<PseudoElasticMeshMotion>(mesh, fluid_wet_, c.mesh);
    X_ = mesh.x;
    flow::FlowConfig cfg;
    cfg.rho = c.rho_f;
    cfg.nu = c.nu_f;
    cfg.dirichlet_tags = flow::kInflow | flow::kWall | flow::kObstacle;
    cfg.chord = true;
    cfg.smagorinsky = c.smagorinsky;
    const double U = c.inflow, T = c.ramp_time, gust = c.gust;
    cfg.boundary_velocity = [U, T, gust](unsigned tags, double, double, double t) -> flow::Vec2 {
      if (tags & flow::kObstacle) return {0.0, 0.0};
      const double pi = 3.14159265358979323846, ramp = (T > 0.0 && t < T) ? 0.5 * (1.0 - std::cos(pi * t / T)) : 1.0;
      const double v = (T > 0.0 && t < T && (tags & flow::kInflow) && !(tags & flow::kWall)) ? gust * U * std::sin(pi * t / T) : 0.0;
      return {ramp * U, v};
    };
    fluid_ = std::make_unique<flow::NavierStokes2D>(std::move(mesh), cfg);
    d_n_.assign(X_.size(), 0.0);
    d_m_ = d_n_;
    x_n_.assign(2 * fluid_wet_.size(), 0.0);
    timings_.setup = seconds(c0);
  }

  const FlowHarvesterCase& config() const { return case_; }
  const flow::HarvesterGeometry& geometry() const { return geometry_; }
  const piezo::PiezoBeam& beam() const { return *beam_; }
  const piezo::PiezoTransient& transient() const { return *transient_; }
  const flow::NavierStokes2D& fluid() const { return *fluid_; }
  const FlowHarvesterTimings& timings() const { return timings_; }
  double omega_sc() const { return omega_sc_; }
  double omega_oc() const { return omega_oc_; }
  double resistance() const { return resistance_; }
  double capacitance() const { return capacitance_; }
  std::size_t interface_nodes() const { return fluid_wet_.size(); }
  std::int64_t fluid_unknowns() const { return fluid_->unknowns(); }
  double time() const { return fluid_->time(); }
  // The sum of the last loads handed to the structure (the fluid's force on the plate, wet nodes incl. the
  // clamped root's, N/m) and the part the free nodes received.
  const double* plate_force() const { return plate_force_; }

  // The state one step hands to the next, into a checkpoint (apps/turek_hron/harvester.cpp) and back, as
  // TurekHronFsiTransient's: the fluid's time state (its mesh is X + d_n), the mesh displacement at t_n and t_n-1,
  // the wet nodes' x_n, the piezo transient's whole state (x, v, a, Q, the partitioned loop's Broyden Jacobian,
  // the last external load, the work sums, step, time, base acceleration, energy0), the coupling's Aitken omega and
  // IQN-ILS columns, the plate force, the timings and counts. load() on a model built from the same case continues
  // bitwise.
  void save(models::Archive& a, const std::string& prefix) const {
    flow::save_time_state(a, prefix + "fluid/", fluid_->time_state());
    a.put_vector(prefix + "d_n", d_n_);
    a.put_vector(prefix + "d_m", d_m_);
    a.put_vector(prefix + "x_n", x_n_);
    const piezo::TransientState& t = transient_->state();
    a.put(prefix + "piezo/step", t.step);
    a.put_vector(prefix + "piezo/scalars", std::vector<double>{t.time, t.base_acceleration, t.work_in, t.work_damping, t.work_circuit,
                                                               t.energy0});
    a.put_vector(prefix + "piezo/x", t.x);
    a.put_vector(prefix + "piezo/v", t.v);
    a.put_vector(prefix + "piezo/a", t.a);
    a.put_vector(prefix + "piezo/Q", t.Q);
    a.put_vector(prefix + "piezo/jacobian", t.jacobian);
    a.put_vector(prefix + "piezo/f_ext", t.f_ext);
    a.put_vector(prefix + "plate_force", std::vector<double>{plate_force_[0], plate_force_[1]});
    a.put(prefix + "timings", timings_);
    coupling_.save(a, prefix + "coupling/");
  }
  void load(const models::Archive& a, const std::string& prefix) {
    d_n_ = a.get_vector_sized<double>(prefix + "d_n", d_n_.size());
    d_m_ = a.get_vector_sized<double>(prefix + "d_m", d_m_.size());
    x_n_ = a.get_vector_sized<double>(prefix + "x_n", x_n_.size());
    piezo::TransientState t;
    t.step = a.get<std::int64_t>(prefix + "piezo/step");
    const std::vector<double> sc = a.get_vector_sized<double>(prefix + "piezo/scalars", 6);
    t.time = sc[0], t.base_acceleration = sc[1], t.work_in = sc[2], t.work_damping = sc[3], t.work_circuit = sc[4], t.energy0 = sc[5];
    t.x = a.get_vector<double>(prefix + "piezo/x");
    t.v = a.get_vector<double>(prefix + "piezo/v");
    t.a = a.get_vector<double>(prefix + "piezo/a");
    t.Q = a.get_vector<double>(prefix + "piezo/Q");
    t.jacobian = a.get_vector<double>(prefix + "piezo/jacobian");
    t.f_ext = a.get_vector<double>(prefix + "piezo/f_ext");
    try {
      transient_->restore(t);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error("checkpoint: " + prefix + "piezo: " + e.what());
    }
    const std::vector<double> pf = a.get_vector_sized<double>(prefix + "plate_force", 2);
    plate_force_[0] = pf[0], plate_force_[1] = pf[1];
    timings_ = a.get<FlowHarvesterTimings>(prefix + "timings");
    coupling_.load(a, prefix + "coupling/");
    fluid_->set_time_state(flow::load_time_state(a, prefix + "fluid/"));
    fluid_->set_coordinates(motion_->coordinates(d_n_));  // the fluid's mesh at t_n, as the last step left it
  }

  // One coupled step; throws std::runtime_error when the coupling or a sub-solver fails.
  FlowHarvesterStep step() {
    const double dt = case_.dt;
    const piezo::TransientOptions& po = transient_->options();
    const double b = po.beta, g = po.gamma, c0 = 1.0 / (b * dt * dt);
    const flow::NavierStokes2D::TimeState saved = fluid_->time_state();
    const bool bdf2 = saved.steps > 0 && saved.last_dt == dt;
    const piezo::TransientState ps = transient_->state();
    const std::size_t nw = fluid_wet_.size();
    std::vector<double> x(2 * nw, 0.0);
    for (std::size_t k = 0; k < 2 * nw; ++k) {
      const std::int64_t d = wet_dof_[k];
      if (d >= 0) x[k] = ps.x[static_cast<std::size_t>(d)] + dt * ps.v[static_cast<std::size_t>(d)] + 0.5 * dt * dt * ps.a[static_cast<std::size_t>(d)];
    }
    std::clock_t t0 = std::clock();
    std::unique_ptr<PseudoElasticMeshMotion> step_motion;
    if (case_.incremental_mesh) step_motion = std::make_unique<PseudoElasticMeshMotion>(fluid_->mesh(), fluid_wet_, case_.mesh);
    timings_.mesh += seconds(t0);
    std::vector<double> d_last, x_last, vwet(2 * nw);
    int circuit = 0;
    last_ = coupling_.solve(x, [&](const std::vector<double>& xi) {
      ++timings_.evaluations;
      std::clock_t t1 = std::clock();
      std::vector<double> d;
      if (step_motion) {  // incremental: d_n + the extension of x - x_n on the mesh at t_n
        std::vector<double> dx(xi.size());
        for (std::size_t i = 0; i < xi.size(); ++i) dx[i] = xi[i] - x_n_[i];
        d = step_motion->displacement(dx);
        for (std::size_t i = 0; i < d.size(); ++i) d[i] += d_n_[i];
      } else {  // total: the extension of x on the reference mesh (factorised once)
        d = motion_->displacement(xi);
      }
      fluid_->set_coordinates(motion_->coordinates(d));
      fluid_->set_mesh_velocity(PseudoElasticMeshMotion::mesh_velocity(d, d_n_, d_m_, dt, bdf2));
      for (std::size_t k = 0; k < 2 * nw; ++k) {  // Newmark's velocity implied by x (zero at the clamped root)
        const std::int64_t dof = wet_dof_[k];
        if (dof < 0) {
          vwet[k] = 0.0;
          continue;
        }
        const std::size_t s = static_cast<std::size_t>(dof);
        const double a = c0 * (xi[k] - ps.x[s]) - ps.v[s] / (b * dt) - (0.5 / b - 1.0) * ps.a[s];
        vwet[k] = ps.v[s] + dt * ((1.0 - g) * ps.a[s] + g * a);
      }
      fluid_->set_node_velocity(fluid_wet_, vwet);
      d_last = std::move(d);
      x_last = xi;
      timings_.mesh += seconds(t1);
      t1 = std::clock();
      fluid_->set_time_state(saved);
      const flow::NewtonReport rep = fluid_->step(dt);
      timings_.fluid += seconds(t1);
      timings_.fluid_newton += rep.iterations;
      if (!rep.converged)
        throw std::runtime_error("flow harvester: the fluid's Newton iteration did not converge at t = " + std::to_string(saved.time + dt) +
                                 " (" + std::to_string(rep.iterations) + " iterations, |r| " + std::to_string(rep.residual) + ")");
      t1 = std::clock();
      const std::vector<double> f = wet_loads();
      transient_->restore(ps);
      circuit += transient_->step(0.0, &f);
      timings_.structure += seconds(t1);
      return wet_displacement();
    });
    timings_.circuit_solves += circuit;
    if (!last_.converged)
      throw std::runtime_error("flow harvester: the coupling did not converge at t = " + std::to_string(saved.time + dt) + " after " +
                               std::to_string(last_.iterations) + " evaluations: " + last_.reason);
    d_m_ = std::move(d_n_);
    d_n_ = std::move(d_last);
    x_n_ = std::move(x_last);
    FlowHarvesterStep out;
    out.t = fluid_->time();
    out.tip = transient_->tip();
    out.drag = fluid_->forces().drag;
    out.lift = fluid_->forces().lift;
    out.voltage = transient_->voltage(beam_->electrode("top"), beam_->electrode("bottom"));
    out.power = transient_->power();
    out.evaluations = last_.iterations;
    out.circuit_iterations = circuit;
    out.residual = last_.residual;
    return out;
  }

  // The structure's displacement at the wet nodes (2 per node, the fluid's order; zero on clamped components).
  std::vector<double> wet_displacement() const {
    const std::vector<double>& u = transient_->state().x;
    std::vector<double> x(wet_dof_.size(), 0.0);
    for (std::size_t k = 0; k < wet_dof_.size(); ++k)
      if (wet_dof_[k] >= 0) x[k] = u[static_cast<std::size_t>(wet_dof_[k])];
    return x;
  }
  // max |x_fluid - (X_plate + u)| over the wet nodes (the mesh follows the structure to the coupling's tolerance)
  double interface_mismatch() const {
    const std::vector<double> u = wet_displacement();
    double m = 0.0;
    for (std::size_t k = 0; k < u.size(); ++k) {
      const std::size_t n = static_cast<std::size_t>(2 * fluid_wet_[k / 2]) + k % 2;
      m = std::max(m, std::fabs(fluid_->mesh().x[n] - (X_[n] + u[k])));
    }
    return m;
  }

 private:
  // The beam's nodes on the plate's wet faces (bottom, top, tip) against the fluid's kObstacle nodes: the beam's
  // (x, y) maps to (x_root + x, y_c - t / 2 + y); each must have a fluid node there, and every fluid node on the
  // plate must be matched (the root's two corners included: clamped, zero displacement). The tip face is one fluid
// cell (three nodes: the corners and the middle, the host's mid-plane) and three order-2 solid cells (seven nodes):
// its four other solid nodes are not wet (the fluid's traction on the 0.6 mm face goes to the three; the face's
// shape differs from the solid's by the bending of a 0.6 mm segment, far below the coupling's tolerance).
  void match_wet_nodes(const flow::QuadMesh& mesh) {
    const std::vector<double>& Xb = beam_->coordinates();
    const double t = geometry_.plate_thickness, L = geometry_.plate_length, xr = geometry_.x_root(), yb = geometry_.y_centre() - 0.5 * t;
    const double tol = 1e-9 * geometry_.length();
    for (std::int64_t v = 0; v < beam_->nodes(); ++v) {
      const double x = Xb[2 * static_cast<std::size_t>(v)], y = Xb[2 * static_cast<std::size_t>(v) + 1];
      const bool wet = std::fabs(y) < tol || std::fabs(y - t) < tol || std::fabs(x - L) < tol;
      if (!wet) continue;
      std::int64_t best = -1;
      double dmin = 1e300;
      for (std::int64_t n = 0; n < mesh.node_count(); ++n) {
        if (!(mesh.tags[static_cast<std::size_t>(n)] & flow::kObstacle)) continue;
        const double dd = std::hypot(mesh.x[2 * static_cast<std::size_t>(n)] - (xr + x), mesh.x[2 * static_cast<std::size_t>(n) + 1] - (yb + y));
        if (dd < dmin) dmin = dd, best = n;
      }
      const bool face = std::fabs(y) < tol || std::fabs(y - t) < tol;
      if (!(dmin < tol) && !face) continue;  // an inner node of the tip face (the fluid's one cell has three nodes there)
      if (!(dmin < tol))
        throw std::logic_error("flow harvester: the plate's wet node at (" + std::to_string(x) + ", " + std::to_string(y) + ") has no fluid node");
      fluid_wet_.push_back(best);
      wet_dof_.push_back(beam_->dof_u(v, 0));
      wet_dof_.push_back(beam_->dof_u(v, 1));
    }
    std::size_t on_plate = 0;
    for (std::int64_t n = 0; n < mesh.node_count(); ++n)
      if ((mesh.tags[static_cast<std::size_t>(n)] & flow::kObstacle) && mesh.x[2 * static_cast<std::size_t>(n)] > xr - tol &&
          std::fabs(mesh.x[2 * static_cast<std::size_t>(n) + 1] - geometry_.y_centre()) < 0.5 * t + tol)
        ++on_plate;
    if (on_plate != fluid_wet_.size())
      throw std::logic_error("flow harvester: " + std::to_string(on_plate) + " fluid nodes on the plate, " + std::to_string(fluid_wet_.size()) +
                             " matched to the structure");
  }

  // The wet nodes' reaction forces of the fluid's last step (f_a = -R_a) on the beam's unknowns (clamped
  // components dropped: the support takes them).
  std::vector<double> wet_loads() {
    const std::vector<double>& r = fluid_->residual();
    std::vector<double> f(static_cast<std::size_t>(beam_->unknowns()), 0.0);
    plate_force_[0] = plate_force_[1] = 0.0;
    for (std::size_t k = 0; k < wet_dof_.size(); ++k) {
      const double fk = -r[static_cast<std::size_t>(2 * fluid_wet_[k / 2]) + k % 2];
      plate_force_[k % 2] += fk;
      if (wet_dof_[k] >= 0) f[static_cast<std::size_t>(wet_dof_[k])] += fk;
    }
    return f;
  }

  static double seconds(std::clock_t c0) { return static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC; }

  FlowHarvesterCase case_;
  flow::HarvesterGeometry geometry_;
  std::unique_ptr<piezo::PiezoBeam> beam_;
  std::unique_ptr<piezo::PiezoTransient> transient_;
  std::unique_ptr<PseudoElasticMeshMotion> motion_;
  std::unique_ptr<flow::NavierStokes2D> fluid_;
  std::vector<std::int64_t> fluid_wet_, wet_dof_;  // wet fluid nodes; the beam's unknown of each component (-1: clamped)
  std::vector<double> X_, d_n_, d_m_, x_n_;
  InterfaceCoupling coupling_;
  CouplingResult last_;
  double omega_sc_ = 0.0, omega_oc_ = 0.0, capacitance_ = 0.0, resistance_ = 0.0;
  double plate_force_[2] = {0.0, 0.0};
  FlowHarvesterTimings timings_;
};

}  // namespace polymech::fsi
