// Stabilized incompressible SPH (seed 002 paper 4; Asai et al. 2012) with improved ghost cell boundary
// (IGCB) walls: tank walls as square (cubic) cells of the particle spacing, one Gauss point each (the
// paper's choice), ghost points mirrored into the fluid.
//
//   polymech::isph::Config c;                 // or io::load_isph_scene(...)
//   c.effects = EffectSet::resolve({"viscosity", "stabilization"}, isph::effect_table());
//   isph::Isph<double, 2> model(c);
//   models::run(model, steps);
//
// One step (the fractional step of eqs. (3)-(5)):
//   x = x0 + u; neighbour lists (fluid-fluid, fluid -> wall points, ghosts -> fluid)
//   -> density eqs. (13) + (18) and the free surface (rho_i < beta rho0: p = 0)
//   -> [viscosity] ghost velocities (23), (27)-(30), u* = u + dt (nu lap u + g) (3), (11), (21)
//   -> ghost velocities of u*, PPE source (4) with div u* (12), (22) [+ stabilization alpha term]
//   -> BiCGSTAB on the PPE (10), (20) with Neumann wall pressure (25)-(26), warm start: its pair coefficients
//      stored once per step (or matrix-free), Jacobi-scaled (or the two-level preconditioner, ppe_two_level.hpp)
//   -> wall pressures, projection (5) with grad p (9), (19) -> x^{n+1} = x^n + dt u^{n+1}.
//   -> [rigid_body] force and moment from the reactions at the body's points, Euler update (CSS).
// The parts, by job: the operators in kernels/sph/ (operators.hpp lists them), the PPE solve in ppe.hpp, the
// tank's IGCB walls in walls.hpp, the floating body (a rigid::RigidBody<2>, touching the tank through the
// shared Hertz-Mindlin law) in floating_body.hpp; this class owns the state and ties them into the step.
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/archive.hpp"
#include "common/clock.hpp"
#include "common/particle_health.hpp"
#include "common/run.hpp"
#include "common/state.hpp"
#include "isph/config.hpp"
#include "isph/effect_table.hpp"
#include "isph/floating_body.hpp"
#include "isph/ppe.hpp"
#include "isph/setup.hpp"
#include "isph/walls.hpp"
#include "neighbors/neighbor_search.hpp"
#include "particles/reductions.hpp"
#include "sph/operators.hpp"
#include "sph/safety_net.hpp"

namespace polymech::isph {

template <class T = double, int D = 2>
class Isph {
 public:
  static constexpr int dimension = D;
  static const std::vector<EffectSpec>& effects() { return effect_table(); }
  using BodyState = isph::BodyState;

  explicit Isph(const Config& c) : cfg_(c) {
    const std::string why = check(c);
    if (!why.empty()) throw std::invalid_argument("isph: " + why);
    if (c.dim != D) throw std::invalid_argument("isph: the configuration is " + std::to_string(c.dim) + "D, the model " +
                                                std::to_string(D) + "D");
    viscosity_ = c.effects.has("viscosity");
    stabilization_ = c.effects.has("stabilization");
    body_ = D == 2 && c.effects.has("rigid_body") && c.body.diameter > 0;
    const double l0 = c.spacing, re = c.radius_factor * l0;
    const double scale = sph::lattice_sum<D>(re, l0);
    par_.w = sph::Wendland<T, D>::make(re, scale);
    par_.mass = T(c.density * std::pow(l0, D));
    par_.rho0 = T(c.density);
    par_.nu = viscosity_ ? T(c.viscosity) : T(0);
    par_.dt = T(c.dt);
    par_.alpha = stabilization_ ? T(c.alpha) : T(0);
    par_.beta = T(c.surface_threshold);
    par_.g = Vec<T, D>::zero();
    par_.g[1] = T(-c.gravity);
    par_.slip = c.wall == WallCondition::slip;
    par_.linear_ghosts = c.ghost_interpolation == GhostInterpolation::linear;
    par_.difference_gradient = c.pressure_gradient == PressureGradient::difference;
    par_.divergence_surface = c.surface_detection != SurfaceDetection::density;
    par_.density_surface_too = c.surface_detection == SurfaceDetection::divergence_or_density;
    par_.surface_divr = T(c.surface_divergence > 0 ? c.surface_divergence : (D == 2 ? 1.5 : 2.4));
    par_.surface_correction = c.surface_correction;
    build_fluid();
    body_begin_ = build_walls<T, D>(cfg_, body_, par_.difference_gradient, wp_, box_, body_model_);
    if constexpr (D == 2) {
      if (body_) body_model_.place(wp_);
    }
    ppe_.configure(c);
    state_.add("u", f_.p.u);
    state_.add("v", f_.p.v);
    state_.add("pressure", f_.pressure);
  }

  void prepare() {}
  // The smallest determinant of a ghost's neighbour covariance taken as regular (sph::GhostWeights).
  T ghost_det_min() const {
    return T(std::pow(1e-3 * cfg_.radius_factor * cfg_.radius_factor * cfg_.spacing * cfg_.spacing, D));
  }
  void step() {
    sph::current_positions(f_);
    search_ff_.build(f_.x, par_.w.re, neighbors::ListKind::full, ff_);
    search_fw_.build_between(f_.x, wp_.x, par_.w.re, fw_);
    search_gf_.build_between(wp_.ghost, f_.x, par_.w.re, gf_);
    neighbors::for_each_row("polymech::sph::density_fluid", ff_, sph::FluidDensity<T, D>{f_, par_});
    neighbors::for_each_row("polymech::sph::density_wall", fw_, sph::WallDensity<T, D>{f_, wp_, par_});
    if (par_.divergence_surface) {
      neighbors::for_each_row("polymech::sph::position_divergence_fluid", ff_, sph::FluidPositionDivergence<T, D>{f_, par_});
      neighbors::for_each_row("polymech::sph::position_divergence_wall", fw_, sph::WallPositionDivergence<T, D>{f_, wp_, par_});
    }
    neighbors::for_each_row("polymech::sph::ghost_weights", gf_, sph::GhostWeights<T, D>{f_, wp_, par_, ghost_det_min()});
    predict();
    neighbors::for_each_row("polymech::sph::ghost_velocity", gf_, sph::GhostVelocity<T, D>{f_, wp_, par_, f_.vstar});
    neighbors::for_each_row("polymech::sph::divergence_fluid", ff_, sph::FluidDivergence<T, D>{f_, par_});
    neighbors::for_each_row("polymech::sph::diagonal_fluid", ff_, sph::FluidDiagonal<T, D>{f_, par_, diag_});
    neighbors::for_each_row("polymech::sph::ppe_rhs", fw_, sph::WallDivergenceRhs<T, D>{f_, wp_, par_, diag_});
    ppe_.solve(f_, wp_, par_, ff_, fw_, gf_, box_, clock_.index());
    neighbors::for_each_row("polymech::sph::ghost_pressure", gf_,
                            sph::GhostPressure<T, D>{f_, wp_, par_, f_.pressure, true});
    neighbors::for_each_row("polymech::sph::pressure_gradient", ff_, sph::FluidPressureGradient<T, D>{f_, par_});
    neighbors::for_each_row("polymech::sph::project", fw_, sph::WallPressureCorrect<T, D>{f_, wp_, par_});
    escaped_ += keep_inside_tank(f_, box_, cfg_.spacing);
    if constexpr (D == 2) {
      if (body_) escaped_ += body_model_.advance(fw_, gf_, f_, wp_, par_, time(), ghost_det_min());
    }
    clock_.tick();
  }

  double dt() const { return cfg_.dt; }
  double time() const { return clock_.time(cfg_.dt); }
  std::int64_t step_index() const { return clock_.index(); }
  void set_step_index(std::int64_t s) { clock_.set_index(s); }
  const Config& config() const { return cfg_; }
  Index particles() const { return f_.size(); }
  Index wall_points() const { return wp_.size(); }
  const sph::Fluid<T, D>& fluid() const { return f_; }
  const sph::WallPoints<T, D>& walls() const { return wp_; }
  const sph::Params<T, D>& params() const { return par_; }
  const PpeRecord& last_solve() const { return ppe_.last(); }
  // y = D^-1 A x, the PPE operator over the lists of the last step, with its pair coefficients stored
  // (those of the last solve; computed here when the scene does not store them) or matrix-free: benchmarks, tests.
  void apply_ppe(const View1<T>& x, const View1<T>& y, bool stored) const {
    ppe_.apply(f_, wp_, par_, ff_, fw_, gf_, x, y, stored);
  }
  long long ppe_iterations_total() const { return ppe_.iterations_total(); }
  long long ppe_solves() const { return ppe_.solves(); }
  double ppe_seconds() const { return ppe_.seconds(); }
  long long escaped() const { return escaped_; }  // particles put back inside the tank (safety net)
  bool has_body() const { return body_; }
  Index body_begin() const { return body_begin_; }  // the body's points are wall points [body_begin, end)
  const MassProperties& body_properties() const { return body_model_.properties(); }
  // The inner size of the tank as built along axis k: the scene's size rounded to whole spacings.
  double tank_size(int k) const { return box_[k]; }
  // The rigid body's state (2D; floating_body.hpp): centre of the disc, angle, velocities, the fluid force
  // and moment of the last step (eqs. (36)-(37)), the acceleration used by the next step's Neumann
  // condition (25), and the contact with the tank.
  const BodyState& body() const { return body_model_.state(); }
  const FloatingBody<T>& floating_body() const { return body_model_; }

  models::Health health() const {
    models::Health h = models::particle_health<T, D>(f_.p);
    if (h.finite && !ppe_.ok()) {
      h.finite = false;
      h.problem = "the pressure Poisson solve failed: " + ppe_.reason();
    }
    // Out of range: a particle that moves ten spacings in a step (CFL 10, forty times the paper's 0.25)
    // has jumped across its whole neighbourhood; only a state that blew up gets there (issue 33: the draft
    // hydrostatic tank reached 3e28 m/s with every solve converged and every value finite). The fastest
    // valid flow seen: 1.8 spacings per step, water squeezed from under the dense body as it lands.
    const double vmax = 10.0 * cfg_.spacing / cfg_.dt;
    if (h.finite) h = models::speed_health(f_.p, vmax, "ten spacings per step (10 l0 / dt)");
    return h;
  }
  const models::StateRegistry& state() const { return state_; }
  // The complete state a step depends on: u, v, the pressure (the PPE's warm start), the step, the rigid
  // body; with the solver's record (the last solve, the iteration counts) and the safety-net count the
  // summary reports. The density, the free-surface flags, the wall points' ghost values and the
  // neighbour lists are recomputed from these at the start of every step.
  void save(models::Archive& a, const std::string& prefix) const {
    state_.save(a, prefix + "state/");
    clock_.save(a, prefix);
    body_model_.save(a, prefix + "body");
    const PpeRecord& last = ppe_.last();
    const long long counts[4] = {ppe_.iterations_total(), ppe_.solves(), escaped_, static_cast<long long>(last.iterations)};
    a.put_bytes(prefix + "counts", counts, sizeof counts);
    const double reals[3] = {ppe_.seconds(), last.residual, ppe_.ok() ? 1.0 : 0.0};
    a.put_bytes(prefix + "reals", reals, sizeof reals);
    a.put_vector(prefix + "last_history", last.history);
    a.put_string(prefix + "last_reason", ppe_.reason());
  }
  void load(const models::Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    clock_.restore(a, prefix);
    body_model_.load(a, prefix + "body");
    const auto counts = a.get_vector<long long>(prefix + "counts");
    const auto reals = a.get_vector<double>(prefix + "reals");
    if (counts.size() != 4 || reals.size() != 3) throw std::runtime_error("checkpoint: " + prefix + "counts/reals have the wrong size");
    escaped_ = counts[2];
    PpeRecord last;
    last.iterations = static_cast<decltype(last.iterations)>(counts[3]);
    last.residual = reals[1];
    last.history = a.get_vector<double>(prefix + "last_history");
    ppe_.restore(counts[0], counts[1], reals[0], std::move(last), reals[2] != 0.0, a.get_string(prefix + "last_reason"));
    if constexpr (D == 2) {
      if (body_) body_model_.place(wp_);
    }
  }

  // Host copies for output and tests: positions (n x D), velocities, pressure, density, surface flags.
  // x = x0 + u, current: f_.x is refreshed at the start of a step, so between steps (and before the first)
  // it holds the positions the last step started from.
  std::vector<double> host_positions() const {
    std::vector<double> x = host_vec(f_.p.x0);
    const std::vector<double> u = host_vec(f_.p.u);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += u[i];
    return x;
  }
  std::vector<double> host_velocities() const { return host_vec(f_.p.v); }
  std::vector<double> host_pressure() const { return host_scalar(f_.pressure); }
  std::vector<double> host_density() const { return host_scalar(f_.rho); }
  std::vector<int> host_surface() const {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), f_.surface);
    std::vector<int> out(h.extent(0));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = h(i);
    return out;
  }
  // The wall force on every fluid particle, eq. (38), and its sum; and the sum of the reactions at the
  // integration points, eqs. (42)-(43), summed over the same pairs (momentum exchange).
  void wall_forces(std::vector<double>& on_fluid, std::vector<double>& on_points) const {
    VecView<T, D> out("polymech::isph::wall_force", static_cast<std::size_t>(f_.size()));
    neighbors::for_each_row("polymech::sph::wall_force", fw_, sph::WallForceOnFluid<T, D>{f_, wp_, par_, out});
    on_fluid = host_vec(out);
    on_points.assign(static_cast<std::size_t>(wp_.size()) * D, 0.0);
    auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), fw_.offsets);
    auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), fw_.neighbors);
    // the reaction of each pair, eq. (42), from the same device function, copied per pair
    View2<T> pf("polymech::isph::pair_force", static_cast<std::size_t>(fw_.num_pairs), D);
    sph::wall_pair_forces(fw_, f_, wp_, par_, pf);
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), pf);
    for (Index i = 0; i < f_.size(); ++i)
      for (Offset k = off(i); k < off(i + 1); ++k)
        for (int d = 0; d < D; ++d) on_points[static_cast<std::size_t>(nb(k)) * D + d] -= double(h(k, d));
  }

 private:
  void predict() {
    if (viscosity_) {
      neighbors::for_each_row("polymech::sph::ghost_velocity", gf_, sph::GhostVelocity<T, D>{f_, wp_, par_, f_.p.v});
      neighbors::for_each_row("polymech::sph::viscosity_fluid", ff_, sph::FluidViscosity<T, D>{f_, par_});
      neighbors::for_each_row("polymech::sph::viscosity_wall", fw_, sph::WallViscosityPredict<T, D>{f_, wp_, par_});
    } else {
      sph::gravity_predict(f_, par_);
    }
  }

  static std::vector<double> host_vec(const VecView<T, D>& v) {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
    std::vector<double> out(h.extent(0) * D);
    for (std::size_t i = 0; i < h.extent(0); ++i)
      for (int d = 0; d < D; ++d) out[i * D + d] = double(h(i, d));
    return out;
  }
  static std::vector<double> host_scalar(const View1<T>& v) {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
    std::vector<double> out(h.extent(0));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = double(h(i));
    return out;
  }

  void build_fluid() {
    const std::vector<double> pts = fluid_positions(cfg_);
    const Index total = static_cast<Index>(pts.size() / D);
    particles::allocate(f_.p, total, "polymech::isph::");
    const auto size = static_cast<std::size_t>(total);
    f_.x = VecView<T, D>("polymech::isph::x", size);
    f_.vstar = VecView<T, D>("polymech::isph::vstar", size);
    f_.work = VecView<T, D>("polymech::isph::work", size);
    f_.rho = View1<T>("polymech::isph::rho", size);
    f_.pressure = View1<T>("polymech::isph::pressure", size);
    f_.rhs = View1<T>("polymech::isph::rhs", size);
    f_.inv_diag = View1<T>("polymech::isph::inv_diag", size);
    f_.scratch = View1<T>("polymech::isph::scratch", size);
    f_.surface = sph::Flags("polymech::isph::surface", size);
    if (par_.divergence_surface) f_.divr = View1<T>("polymech::isph::position_divergence", size);
    diag_ = View1<T>("polymech::isph::diag", size);
    auto h = Kokkos::create_mirror_view(f_.p.x0);
    for (std::size_t i = 0; i < size; ++i)
      for (int d = 0; d < D; ++d) h(i, d) = T(pts[i * D + d]);
    Kokkos::deep_copy(f_.p.x0, h);
  }

  Config cfg_;
  bool viscosity_ = false, stabilization_ = false, body_ = false;
  Index body_begin_ = 0;
  // the tank as built: whole cells of l0 (tank sizes rounded to a multiple of the spacing), which the
  // walls, the safety net and the body's contact all use
  double box_[3] = {0.0, 0.0, 0.0};
  FloatingBody<T> body_model_;  // effect `rigid_body` (2D) only: empty otherwise
  sph::Params<T, D> par_;
  sph::Fluid<T, D> f_;
  sph::WallPoints<T, D> wp_;
  View1<T> diag_;
  PpeSolver<T, D> ppe_;
  neighbors::NeighborSearch<T, D> search_ff_, search_fw_, search_gf_;
  neighbors::NeighborList ff_, fw_, gf_;
  long long escaped_ = 0;
  models::StateRegistry state_;
  models::StepClock clock_;  // step index and time (models/common/clock.hpp)
};

}  // namespace polymech::isph
