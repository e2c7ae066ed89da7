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
// Walls: the tank of an axis-aligned box (sides and bottom, open top) and, with `rigid_body`, a 2D
// cylinder of polar cells; a general cell mesh of IGCB (arbitrary walls) is not built (docs/METHODS.md).
// The body touches the tank through the shared Hertz-Mindlin law (kernels/contact/hertz_mindlin.hpp).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "contact/hertz_mindlin.hpp"
#include "common/particle_health.hpp"
#include "common/run.hpp"
#include "common/state.hpp"
#include "isph/config.hpp"
#include "isph/effect_table.hpp"
#include "isph/ppe_two_level.hpp"
#include "isph/setup.hpp"
#include "neighbors/neighbor_search.hpp"
#include "particles/reductions.hpp"
#include "sph/bicgstab.hpp"
#include "sph/operators.hpp"

namespace polymech::isph {

// The PPE operator y = D^-1 A x as a Krylov operator (kernels/sph/bicgstab.hpp concept).
template <class T, int D>
struct PressureOperator {
  sph::Fluid<T, D> f;
  sph::WallPoints<T, D> wp;
  sph::Params<T, D> c;
  const neighbors::NeighborList* ff = nullptr;
  const neighbors::NeighborList* fw = nullptr;
  const neighbors::NeighborList* gf = nullptr;
  Index local_size() const { return f.size(); }
  Index owned_size() const { return f.size(); }
  // the pair coefficients of the three passes (empty: matrix-free, computed in every apply)
  View1<T> ghost_coef, fluid_coef, wall_coef;
  void apply(const View1<T>& x, const View1<T>& y) const {
    neighbors::for_each_row("polymech::sph::ghost_pressure", *gf, sph::GhostPressure<T, D>{f, wp, c, x, false, ghost_coef});
    neighbors::for_each_row("polymech::sph::laplacian_fluid", *ff, sph::FluidLaplacian<T, D>{f, c, x, fluid_coef});
    neighbors::for_each_row("polymech::sph::laplacian_wall", *fw, sph::WallLaplacian<T, D>{f, wp, c, x, y, wall_coef});
  }
  // Store the coefficients for the lists as they are now (once per step, before the solve), reusing
  // `ghost_coef`, ... when they are large enough.
  void store_coefficients() {
    store(*gf, sph::GhostPressure<T, D>{f, wp, c, f.pressure, false}, ghost_coef, "polymech::isph::ppe_ghost_coef");
    store(*ff, sph::FluidLaplacian<T, D>{f, c, f.pressure}, fluid_coef, "polymech::isph::ppe_fluid_coef");
    store(*fw, sph::WallLaplacian<T, D>{f, wp, c, f.pressure, f.scratch}, wall_coef, "polymech::isph::ppe_wall_coef");
  }
  template <class Pass>
  static void store(const neighbors::NeighborList& list, const Pass& pass, View1<T>& coef, const char* label) {
    const auto pairs = static_cast<std::size_t>(list.num_pairs);
    if (coef.extent(0) < pairs) coef = View1<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), pairs + pairs / 4);
    neighbors::for_each_row(label, list, sph::StorePairCoefficients<T, Pass>{pass, coef});
  }
};

struct PpeRecord {
  int iterations = 0;
  double residual = 0.0;
  std::vector<double> history;  // of the last solve
};

template <class T = double, int D = 2>
class Isph {
 public:
  static constexpr int dimension = D;
  static const std::vector<EffectSpec>& effects() { return effect_table(); }

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
    build_walls();
    if (body_) {
      body_state_.centre[0] = c.body.centre[0];
      body_state_.centre[1] = c.body.centre[1];
      place_body_points();
    }
    opts_.tolerance = c.tolerance;
    opts_.max_iterations = c.max_iterations;
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
    solve_pressure();
    neighbors::for_each_row("polymech::sph::ghost_pressure", gf_,
                            sph::GhostPressure<T, D>{f_, wp_, par_, f_.pressure, true});
    neighbors::for_each_row("polymech::sph::pressure_gradient", ff_, sph::FluidPressureGradient<T, D>{f_, par_});
    neighbors::for_each_row("polymech::sph::project", fw_, sph::WallPressureCorrect<T, D>{f_, wp_, par_});
    keep_inside();
    if (body_) advance_body();
    ++step_;
  }

  double dt() const { return cfg_.dt; }
  double time() const { return static_cast<double>(step_) * cfg_.dt; }
  std::int64_t step_index() const { return step_; }
  void set_step_index(std::int64_t s) { step_ = s; }
  const Config& config() const { return cfg_; }
  Index particles() const { return f_.size(); }
  Index wall_points() const { return wp_.size(); }
  const sph::Fluid<T, D>& fluid() const { return f_; }
  const sph::WallPoints<T, D>& walls() const { return wp_; }
  const sph::Params<T, D>& params() const { return par_; }
  const PpeRecord& last_solve() const { return last_; }
  // y = D^-1 A x, the PPE operator over the lists of the last step, with its pair coefficients stored
  // (those of the last solve; computed here when the scene does not store them) or matrix-free: benchmarks, tests.
  void apply_ppe(const View1<T>& x, const View1<T>& y, bool stored) const {
    PressureOperator<T, D> op{f_, wp_, par_, &ff_, &fw_, &gf_, {}, {}, {}};
    if (stored && cfg_.ppe_stored) {
      op.ghost_coef = ppe_coef_[0];
      op.fluid_coef = ppe_coef_[1];
      op.wall_coef = ppe_coef_[2];
    } else if (stored) {
      op.store_coefficients();
    }
    op.apply(x, y);
  }
  long long ppe_iterations_total() const { return ppe_total_; }
  long long ppe_solves() const { return ppe_solves_; }
  double ppe_seconds() const { return ppe_seconds_; }
  long long escaped() const { return escaped_; }  // particles put back inside the tank (safety net)
  bool has_body() const { return body_; }
  Index body_begin() const { return body_begin_; }  // the body's points are wall points [body_begin, end)
  const MassProperties& body_properties() const { return props_; }
  // The inner size of the tank as built along axis k: the scene's size rounded to whole spacings.
  double tank_size(int k) const { return box_[k]; }
  // The rigid body's state (2D): centre of the disk, angle, velocities, the fluid force and moment of the
  // last step (eqs. (36)-(37)), and the acceleration used by the next step's Neumann condition (25).
  struct BodyState {
    double centre[2] = {0, 0}, theta = 0, v[2] = {0, 0}, omega = 0, a[2] = {0, 0}, alpha = 0, force[2] = {0, 0},
           moment = 0;
    // contact with the tank (bottom, left, right wall): the force and moment of the last step and the
    // tangential spring of each wall (kernels/contact/hertz_mindlin.hpp)
    double contact_force[2] = {0, 0}, contact_moment = 0, spring[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  };
  const BodyState& body() const { return body_state_; }

  models::Health health() const {
    models::Health h = models::particle_health<T, D>(f_.p);
    if (h.finite && !last_ok_) {
      h.finite = false;
      h.problem = "the pressure Poisson solve failed: " + last_reason_;
    }
    // Out of range: a particle that moves ten spacings in a step (CFL 10, forty times the paper's 0.25)
    // has jumped across its whole neighbourhood; only a state that blew up gets there (issue 33: the draft
    // hydrostatic tank reached 3e28 m/s with every solve converged and every value finite). The fastest
    // valid flow seen: 1.8 spacings per step, water squeezed from under the dense body as it lands.
    const double vmax = 10.0 * cfg_.spacing / cfg_.dt;
    const Index fast = h.finite ? first_faster_than(f_.p.v, T(vmax)) : Index(-1);
    if (fast >= 0) {
      const auto x = host_positions();
      const auto v = host_vec(f_.p.v, false);
      double s2 = 0;
      for (int d = 0; d < D; ++d) {
        h.position[d] = x[static_cast<std::size_t>(fast) * D + d];
        s2 += v[static_cast<std::size_t>(fast) * D + d] * v[static_cast<std::size_t>(fast) * D + d];
      }
      h.finite = false;
      h.first_bad = fast;
      h.problem = "moves at " + models::format_g(std::sqrt(s2)) + " m/s, more than ten spacings per step (10 l0 / dt = " +
                  models::format_g(vmax) + " m/s)";
    }
    return h;
  }
  // The first particle with |v| > vmax, or -1. Public for nvcc (no lambdas in private members).
  static Index first_faster_than(const VecView<T, D>& v, T vmax) {
    const Index n = static_cast<Index>(v.extent(0));
    Index first = n;
    Kokkos::parallel_reduce(
        "polymech::isph::first_too_fast", range(n),
        KOKKOS_LAMBDA(const Index i, Index& m) {
          T s2 = T(0);
          for (int d = 0; d < D; ++d) s2 += v(i, d) * v(i, d);
          if (!(s2 <= vmax * vmax) && i < m) m = i;
        },
        Kokkos::Min<Index>(first));
    return first < n ? first : Index(-1);
  }
  const models::StateRegistry& state() const { return state_; }
  // The complete state a step depends on: u, v, the pressure (the PPE's warm start), the step, the rigid
  // body; with the solver's record (the last solve, the iteration counts) and the safety-net count the
  // summary reports. The density, the free-surface flags, the wall points' ghost values and the
  // neighbour lists are recomputed from these at the start of every step.
  void save(models::Archive& a, const std::string& prefix) const {
    state_.save(a, prefix + "state/");
    a.put(prefix + "step", step_);
    a.put(prefix + "body", body_state_);
    const long long counts[4] = {ppe_total_, ppe_solves_, escaped_, static_cast<long long>(last_.iterations)};
    a.put_bytes(prefix + "counts", counts, sizeof counts);
    const double reals[3] = {ppe_seconds_, last_.residual, last_ok_ ? 1.0 : 0.0};
    a.put_bytes(prefix + "reals", reals, sizeof reals);
    a.put_vector(prefix + "last_history", last_.history);
    a.put_string(prefix + "last_reason", last_reason_);
  }
  void load(const models::Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    step_ = a.get<std::int64_t>(prefix + "step");
    body_state_ = a.get<BodyState>(prefix + "body");
    const auto counts = a.get_vector<long long>(prefix + "counts");
    const auto reals = a.get_vector<double>(prefix + "reals");
    if (counts.size() != 4 || reals.size() != 3) throw std::runtime_error("checkpoint: " + prefix + "counts/reals have the wrong size");
    ppe_total_ = counts[0];
    ppe_solves_ = counts[1];
    escaped_ = counts[2];
    last_.iterations = static_cast<decltype(last_.iterations)>(counts[3]);
    ppe_seconds_ = reals[0];
    last_.residual = reals[1];
    last_ok_ = reals[2] != 0.0;
    last_.history = a.get_vector<double>(prefix + "last_history");
    last_reason_ = a.get_string(prefix + "last_reason");
    if (body_) place_body_points();
  }

  // Host copies for output and tests: positions (n x D), velocities, pressure, density, surface flags.
  // x = x0 + u, current: f_.x is refreshed at the start of a step, so between steps (and before the first)
  // it holds the positions the last step started from.
  std::vector<double> host_positions() const {
    std::vector<double> x = host_vec(f_.p.x0, true);
    const std::vector<double> u = host_vec(f_.p.u, true);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] += u[i];
    return x;
  }
  std::vector<double> host_velocities() const { return host_vec(f_.p.v, false); }
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
    on_fluid = host_vec(out, false);
    on_points.assign(static_cast<std::size_t>(wp_.size()) * D, 0.0);
    auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), fw_.offsets);
    auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), fw_.neighbors);
    // the reaction of each pair, eq. (42), from the same device function, copied per pair
    View2<T> pf("polymech::isph::pair_force", static_cast<std::size_t>(fw_.num_pairs), D);
    const auto f = f_;
    const auto wp = wp_;
    const auto c = par_;
    const auto list = fw_;
    pair_forces(list, f, wp, c, pf);
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), pf);
    for (Index i = 0; i < f_.size(); ++i)
      for (Offset k = off(i); k < off(i + 1); ++k)
        for (int d = 0; d < D; ++d) on_points[static_cast<std::size_t>(nb(k)) * D + d] -= double(h(k, d));
  }

  // Public for nvcc (no lambdas in private members).
  static void pair_forces(const neighbors::NeighborList& list, const sph::Fluid<T, D>& f, const sph::WallPoints<T, D>& wp,
                          const sph::Params<T, D>& c, const View2<T>& out) {
    Kokkos::parallel_for(
        "polymech::sph::wall_pair_forces", range(list.num_particles), KOKKOS_LAMBDA(const Index i) {
          for (Offset k = list.begin(i); k < list.end(i); ++k) {
            const Vec<T, D> fk = sph::wall_pair_force<T, D>(f, wp, c, i, list.neighbor(k));
            for (int d = 0; d < D; ++d) out(k, d) = fk[d];
          }
        });
  }
  static void gravity_predict(const sph::Fluid<T, D>& f, const sph::Params<T, D>& c) {
    Kokkos::parallel_for(
        "polymech::sph::predict", range(f.size()),
        KOKKOS_LAMBDA(const Index i) { store<D>(f.vstar, i, polymech::load<D>(f.p.v, i) + c.dt * c.g); });
  }
  // Moves the body's points rigidly: x = c + Rot(theta) r0, the ghost mirrored through the circle
  // (q = c + R (x - c)/|x - c|, ghost = 2q - x, n = -(x - c)/|x - c|, d = 2 (R - |x - c|)), the wall
  // velocity v + omega x r and acceleration a + alpha x r - omega^2 r (eq. (25)).
  static void place_body(const sph::WallPoints<T, D>& wp, const VecView<T, D>& offset, Index begin, T R, const T* st) {
    const T cx = st[0], cy = st[1], th = st[2], vx = st[3], vy = st[4], om = st[5], ax = st[6], ay = st[7], al = st[8];
    const T cs = kx::cos(th), sn = kx::sin(th);
    Kokkos::parallel_for(
        "polymech::sph::place_body", range(static_cast<Index>(offset.extent(0))), KOKKOS_LAMBDA(const Index k) {
          const Index w = begin + k;
          const T rx = cs * offset(k, 0) - sn * offset(k, 1), ry = sn * offset(k, 0) + cs * offset(k, 1);
          const T r = kx::sqrt(rx * rx + ry * ry);
          const T ex = rx / r, ey = ry / r;
          wp.x(w, 0) = cx + rx;
          wp.x(w, 1) = cy + ry;
          const T qx = cx + R * ex, qy = cy + R * ey;
          wp.ghost(w, 0) = T(2) * qx - (cx + rx);
          wp.ghost(w, 1) = T(2) * qy - (cy + ry);
          wp.normal(w, 0) = -ex;
          wp.normal(w, 1) = -ey;
          wp.dist(w) = T(2) * (R - r);
          wp.velocity(w, 0) = vx - om * ry;
          wp.velocity(w, 1) = vy + om * rx;
          wp.accel(w, 0) = ax - al * ry - om * om * rx;
          wp.accel(w, 1) = ay + al * rx - om * om * ry;
        });
  }
  // The fluid force and moment on the body, eqs. (36)-(37) with (42)-(43): minus the wall force of each
  // (particle, body point) pair, summed. out = {Fx, Fy, M about the centre (cx, cy)}.
  static void body_force(const neighbors::NeighborList& list, const sph::Fluid<T, D>& f, const sph::WallPoints<T, D>& wp,
                         const sph::Params<T, D>& c, Index begin, T cx, T cy, double* out) {
    double fx = 0, fy = 0, mz = 0;
    Kokkos::parallel_reduce(
        "polymech::sph::body_force", range(list.num_particles),
        KOKKOS_LAMBDA(const Index i, double& ax, double& ay, double& am) {
          for (Offset k = list.begin(i); k < list.end(i); ++k) {
            const Index w = list.neighbor(k);
            if (w < begin) continue;
            Vec<T, D> fw, fv;
            sph::wall_pair_force_parts<T, D>(f, wp, c, i, w, fw, fv);
            if (c.difference_gradient) fw = Vec<T, D>::zero();  // the pressure from body_surface_force
            fw += fv;
            const double gx = -double(fw[0]), gy = -double(fw[1]);  // eq. (42)
            ax += gx;
            ay += gy;
            am += (double(wp.x(w, 0)) - double(cx)) * gy - (double(wp.x(w, 1)) - double(cy)) * gx;  // eq. (37)
          }
        },
        fx, fy, mz);
    out[0] = fx;
    out[1] = fy;
    out[2] = mz;
  }
  // With the difference form of the pressure gradient the pair terms of eq. (40) are not the force between
  // a particle and the wall (they need not sum to it: the form does not conserve momentum pair by pair), so
  // the body's pressure force is the surface integral -oint p n_out ds over its circle, with p the fluid's
  // pressure at the surface point of each outer-ring point (sph::SurfacePressure: the linear fit of the
  // ghost's neighbours, 0 above the water), each point carrying the arc R dtheta of its cell. Adds to
  // out[0..1]; a circle's pressure has no moment about its centre.
  static void body_surface_force(const sph::WallPoints<T, D>& wp, const View1<T>& ps, Index begin, Index count,
                                 double arc, double* out) {
    double fx = 0, fy = 0;
    Kokkos::parallel_reduce(
        "polymech::sph::body_surface_force", range(count),
        KOKKOS_LAMBDA(const Index k, double& ax, double& ay) {
          const Index w = begin + k;
          ax += double(ps(k)) * double(wp.normal(w, 0)) * arc;
          ay += double(ps(k)) * double(wp.normal(w, 1)) * arc;
        },
        fx, fy);
    out[0] += fx;
    out[1] += fy;
  }
  static long long push_out_of_body(const sph::Fluid<T, D>& f, T cx, T cy, T rmin) {
    long long n = 0;
    Kokkos::parallel_reduce(
        "polymech::sph::push_out_of_body", range(f.size()),
        KOKKOS_LAMBDA(const Index i, long long& count) {
          const Vec<T, D> x = f.p.position(i);
          const T dx = x[0] - cx, dy = x[1] - cy, r = kx::sqrt(dx * dx + dy * dy);
          if (r >= rmin || r <= T(0)) return;
          f.p.u(i, 0) += (rmin - r) * dx / r;
          f.p.u(i, 1) += (rmin - r) * dy / r;
          ++count;
        },
        n);
    return n;
  }
  static long long keep_inside(const sph::Fluid<T, D>& f, const Vec<T, D>& lo, const Vec<T, D>& hi) {
    long long n = 0;
    Kokkos::parallel_reduce(
        "polymech::sph::keep_inside", range(f.size()),
        KOKKOS_LAMBDA(const Index i, long long& count) {
          bool moved = false;
          Vec<T, D> x = f.p.position(i);
          for (int k = 0; k < D; ++k) {
            if (x[k] < lo[k]) {
              f.p.u(i, k) += lo[k] - x[k];
              if (f.p.v(i, k) < T(0)) f.p.v(i, k) = T(0);
              moved = true;
            } else if (x[k] > hi[k]) {
              f.p.u(i, k) += hi[k] - x[k];
              if (f.p.v(i, k) > T(0)) f.p.v(i, k) = T(0);
              moved = true;
            }
          }
          if (moved) ++count;
        },
        n);
    return n;
  }

 private:
  void predict() {
    if (viscosity_) {
      neighbors::for_each_row("polymech::sph::ghost_velocity", gf_, sph::GhostVelocity<T, D>{f_, wp_, par_, f_.p.v});
      neighbors::for_each_row("polymech::sph::viscosity_fluid", ff_, sph::FluidViscosity<T, D>{f_, par_});
      neighbors::for_each_row("polymech::sph::viscosity_wall", fw_, sph::WallViscosityPredict<T, D>{f_, wp_, par_});
    } else {
      gravity_predict(f_, par_);
    }
  }
  void solve_pressure() {
    PressureOperator<T, D> op{f_, wp_, par_, &ff_, &fw_, &gf_, ppe_coef_[0], ppe_coef_[1], ppe_coef_[2]};
    if (cfg_.ppe_stored) {
      op.store_coefficients();
      ppe_coef_[0] = op.ghost_coef;  // kept for the next step's lists (grown when they grow)
      ppe_coef_[1] = op.fluid_coef;
      ppe_coef_[2] = op.wall_coef;
    }
    solvers::SolveResult r;
    if (cfg_.ppe_preconditioner == Config::Preconditioner::two_level) {
      two_level_.setup(op, box_, cfg_.ppe_coarse_cell * cfg_.spacing);
      r = sph::bicgstab(op, f_.rhs, f_.pressure, opts_, two_level_);
    } else {
      r = sph::bicgstab(op, f_.rhs, f_.pressure, opts_);  // warm start: p^n in f_.pressure
    }
    last_.iterations = r.iterations;
    last_.residual = r.true_relative_residual;
    last_.history = r.history;
    last_ok_ = r.converged();
    last_reason_ = r.reason;
    ppe_total_ += r.iterations;
    ++ppe_solves_;
    ppe_seconds_ += r.seconds;
  }
  void place_body_points() {
    if constexpr (D == 2) {
      const auto& b = body_state_;
      const T st[9] = {T(b.centre[0]), T(b.centre[1]), T(b.theta), T(b.v[0]), T(b.v[1]), T(b.omega), T(b.a[0]),
                       T(b.a[1]), T(b.alpha)};
      place_body(wp_, body_offset_, body_begin_, T(0.5 * cfg_.body.diameter), st);
    }
  }
  // Conventional serial staggered coupling (CSS), explicit Euler as the paper: the fluid step just taken
  // saw the body at its old pose; the body now moves with the fluid force of that step, eqs. (31)-(32),
  // and the next fluid step sees the new pose. A body that reaches a tank wall stops there (a kinematic
  // contact, standing in for the shared contact module).
  void advance_body() {
    if constexpr (D == 2) {
      auto& b = body_state_;
      double out[3];
      body_force(fw_, f_, wp_, par_, body_begin_, T(b.centre[0]), T(b.centre[1]), out);
      if (par_.difference_gradient) {
        neighbors::for_each_row("polymech::sph::surface_pressure", gf_,
                                sph::SurfacePressure<T, D>{f_, wp_, par_, body_begin_, body_begin_ + body_outer_,
                                                           ghost_det_min(), surface_p_});
        const double arc = 3.14159265358979323846 * cfg_.body.diameter / double(body_outer_);
        body_surface_force(wp_, surface_p_, body_begin_, body_outer_, arc, out);
      }
      b.force[0] = out[0];
      b.force[1] = out[1];
      b.moment = out[2];
      const double dt = cfg_.dt, m = props_.mass, R = 0.5 * cfg_.body.diameter;
      if (time() + dt < cfg_.body.release_time) return;  // held fixed: the force is recorded only
      const double v0[2] = {b.v[0], b.v[1]}, w0 = b.omega;
      // eq. (31) by explicit Euler, with an added-mass term: the fluid force of a body accelerating at a
      // contains -m_a a (m_a = C_a rho0 pi R^2 for a cylinder); explicit staggered coupling then updates
      // a_{n+1} = (F_rest - m_a a_n) / m, which diverges when m_a >= m (density ratio <= 1 at C_a = 1).
      // Moving m_a a to the left, (m + m_a) a_{n+1} = F + m_a a_n - m g, has the same fixed point and is
      // stable (not in the paper; added_mass = 0 gives the paper's plain CSS). (The Neumann pressure of
      // eq. (26) alone carries little of m_a: -dF/da through it is 1.0-1.4 kg/m against m_a = 7.9 kg/m for
      // D = 0.1 m at l0 = D/5 and D/10, measured; the rest acts through the PPE's wall velocities.)
      const double pi = 3.14159265358979323846;
      const double ma = cfg_.body.added_mass * cfg_.density * pi * R * R;
      tank_contact(R);
      const double fx = out[0] + b.contact_force[0], fy = out[1] + b.contact_force[1];
      b.v[0] += dt * (fx + ma * b.a[0]) / (m + ma);
      b.v[1] += dt * (fy + ma * b.a[1] - m * cfg_.gravity) / (m + ma);
      b.omega += dt * (out[2] + b.contact_moment) / props_.inertia;  // eq. (32)
      b.centre[0] += dt * b.v[0];
      b.centre[1] += dt * b.v[1];
      b.theta += dt * b.omega;
      b.a[0] = (b.v[0] - v0[0]) / dt;
      b.a[1] = (b.v[1] - v0[1]) / dt;
      b.alpha = (b.omega - w0) / dt;
      place_body_points();
      escaped_ += push_out_of_body(f_, T(b.centre[0]), T(b.centre[1]), T(R + 0.25 * cfg_.spacing));
    }
  }
  // The body against the tank's bottom (y = 0) and sides (x = 0, x = width): the shared Hertz-Mindlin law
  // (kernels/contact/hertz_mindlin.hpp) of a disc of unit thickness on a rigid plane, with damping and
  // Coulomb friction, explicit like the fluid coupling; its force and moment join the fluid's in eqs.
  // (31)-(32). (It replaces a kinematic stop: a body that reaches a wall must not pass through it.)
  void tank_contact(double R) {
    auto& b = body_state_;
    // a rigid body and a rigid wall: the law's moduli are the contact's (nu = 0: G* = G / 2 = E* / 4)
    const contact::HertzMindlin<double> law{bc_.e_star, 0.25 * bc_.e_star, bc_.beta, bc_.mu};
    const double planes[3][3] = {{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {-1.0, 0.0, box_[0]}};  // n . x + d >= 0 inside
    b.contact_force[0] = b.contact_force[1] = b.contact_moment = 0.0;
    for (int w = 0; w < 3; ++w) {
      const double nx = planes[w][0], ny = planes[w][1];
      const double gap = nx * b.centre[0] + ny * b.centre[1] + planes[w][2] - R;  // < 0: overlap
      Vec3<double> xi{{b.spring[w][0], b.spring[w][1], b.spring[w][2]}};
      if (gap >= 0.0) {
        b.spring[w][0] = b.spring[w][1] = b.spring[w][2] = 0.0;
        continue;
      }
      const Vec3<double> n{{nx, ny, 0.0}};
      // the body's velocity at the contact point c - R n: v + omega x (-R n)
      const Vec3<double> vc{{b.v[0] + b.omega * R * ny, b.v[1] - b.omega * R * nx, 0.0}};
      const auto f = contact::hertz_mindlin_force(law, R, bc_.mass, -gap, n, vc, bc_.mu > 0.0, cfg_.dt, xi);
      b.contact_force[0] += f.force[0];
      b.contact_force[1] += f.force[1];
      b.contact_moment += -R * (nx * f.force[1] - ny * f.force[0]);  // lever -R n
      for (int k = 0; k < 3; ++k) b.spring[w][k] = xi[k];
    }
  }
  void keep_inside() {
    Vec<T, D> lo, hi;
    const T margin = T(0.25 * cfg_.spacing);
    for (int k = 0; k < D; ++k) {
      lo[k] = margin;
      hi[k] = T(box_[k]) - margin;
    }
    hi[1] = T(1e30);  // open top
    escaped_ += keep_inside(f_, lo, hi);
  }

  std::vector<double> host_vec(const VecView<T, D>& v, bool) const {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
    std::vector<double> out(h.extent(0) * D);
    for (std::size_t i = 0; i < h.extent(0); ++i)
      for (int d = 0; d < D; ++d) out[i * D + d] = double(h(i, d));
    return out;
  }
  std::vector<double> host_scalar(const View1<T>& v) const {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
    std::vector<double> out(h.extent(0));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = double(h(i));
    return out;
  }

  static long long cells(double length, double l0) { return static_cast<long long>(std::llround(length / l0)); }

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

  // Tank walls: cells of size l0 in ceil(re/l0) layers below and beside the tank (open top), one Gauss
  // point at each centre (weight H |J| = l0^D). The ghost of a point is its mirror through the nearest
  // point q of the tank box (a face, an edge or a corner): ghost = 2 q - x, n = (x - q)/|x - q|, d = 2|x - q|.
  void build_walls() {
    const double l0 = cfg_.spacing;
    const long long layers = static_cast<long long>(std::ceil(cfg_.radius_factor - 1e-9));
    const long long nx = cells(cfg_.tank[0], l0), ny = cells(cfg_.tank[1], l0), nz = D == 3 ? cells(cfg_.tank[2], l0) : 1;
    const double box[3] = {nx * l0, ny * l0, nz * l0};
    for (int k = 0; k < 3; ++k) box_[k] = box[k];
    std::vector<double> pts;
    const long long z0 = D == 3 ? -layers : 0, z1 = D == 3 ? nz + layers : 1;
    for (long long c = z0; c < z1; ++c)
      for (long long b = -layers; b < ny; ++b)
        for (long long a = -layers; a < nx + layers; ++a) {
          const bool inside = a >= 0 && a < nx && b >= 0 && (D == 2 || (c >= 0 && c < nz));
          if (inside) continue;
          pts.push_back((a + 0.5) * l0);
          pts.push_back((b + 0.5) * l0);
          if (D == 3) pts.push_back((c + 0.5) * l0);
        }
    const std::size_t tank_points = pts.size() / D;
    BodyCells cells_b;
    if constexpr (D == 2) {
      if (body_) {
        cells_b = body_cells(cfg_);
        props_ = mass_properties(cfg_, cells_b);
        bc_ = body_contact(cfg_);
      }
    }
    const std::size_t m = tank_points + cells_b.weight.size();
    body_begin_ = static_cast<Index>(tank_points);
    const std::string pre = "polymech::isph::wall_";
    wp_.x = VecView<T, D>(pre + "x", m);
    wp_.vol = View1<T>(pre + "vol", m);
    wp_.normal = VecView<T, D>(pre + "normal", m);
    wp_.ghost = VecView<T, D>(pre + "ghost", m);
    wp_.dist = View1<T>(pre + "dist", m);
    wp_.velocity = VecView<T, D>(pre + "velocity", m);
    wp_.accel = VecView<T, D>(pre + "accel", m);
    wp_.p = View1<T>(pre + "p", m);
    wp_.u = VecView<T, D>(pre + "u", m);
    wp_.shepard = View1<T>(pre + "shepard", m);
    wp_.interp = VecView<T, D + 1>(pre + "interp", m);
    auto hx = Kokkos::create_mirror_view(wp_.x);
    auto hv = Kokkos::create_mirror_view(wp_.vol);
    auto hn = Kokkos::create_mirror_view(wp_.normal);
    auto hg = Kokkos::create_mirror_view(wp_.ghost);
    auto hd = Kokkos::create_mirror_view(wp_.dist);
    for (std::size_t k = 0; k < tank_points; ++k) {
      double q[3], r2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double x = pts[k * D + d];
        q[d] = std::min(std::max(x, 0.0), box[d]);
        r2 += (x - q[d]) * (x - q[d]);
      }
      const double r = std::sqrt(r2);
      for (int d = 0; d < D; ++d) {
        const double x = pts[k * D + d];
        hx(k, d) = T(x);
        hn(k, d) = T((x - q[d]) / r);
        hg(k, d) = T(2 * q[d] - x);
      }
      hv(k) = T(std::pow(l0, D));
      hd(k) = T(2 * r);
    }
    if (!cells_b.weight.empty()) {  // effect `rigid_body` only: nothing allocated without it
      body_offset_ = VecView<T, D>("polymech::isph::body_offset", cells_b.weight.size());
      auto ho = Kokkos::create_mirror_view(body_offset_);
      for (std::size_t k = 0; k < cells_b.weight.size(); ++k) {
        for (int d = 0; d < D; ++d) ho(k, d) = T(cells_b.offset[2 * k + d]);
        hv(tank_points + k) = T(cells_b.weight[k]);
      }
      Kokkos::deep_copy(body_offset_, ho);
      // the outer ring (body_cells builds the rings from the outside in): the points at the first radius
      const double r0 = std::hypot(cells_b.offset[0], cells_b.offset[1]);
      body_outer_ = 0;
      while (static_cast<std::size_t>(body_outer_) < cells_b.weight.size() &&
             std::fabs(std::hypot(cells_b.offset[2 * body_outer_], cells_b.offset[2 * body_outer_ + 1]) - r0) < 1e-9 * r0)
        ++body_outer_;
      if (par_.difference_gradient) surface_p_ = View1<T>("polymech::isph::body_surface_pressure", body_outer_);
    }
    Kokkos::deep_copy(wp_.x, hx);
    Kokkos::deep_copy(wp_.vol, hv);
    Kokkos::deep_copy(wp_.normal, hn);
    Kokkos::deep_copy(wp_.ghost, hg);
    Kokkos::deep_copy(wp_.dist, hd);
  }

  Config cfg_;
  bool viscosity_ = false, stabilization_ = false, body_ = false;
  Index body_begin_ = 0, body_outer_ = 0;
  VecView<T, D> body_offset_;
  View1<T> surface_p_;  // the fluid pressure at the body's surface points (difference form only)
  MassProperties props_;
  BodyContact bc_;
  // the tank as built: whole cells of l0 (tank sizes rounded to a multiple of the spacing), which the
  // walls, the safety net and the body's contact all use
  double box_[3] = {0.0, 0.0, 0.0};
  BodyState body_state_;
  sph::Params<T, D> par_;
  sph::Fluid<T, D> f_;
  sph::WallPoints<T, D> wp_;
  View1<T> diag_;
  TwoLevelPpe<T, D, PressureOperator<T, D>> two_level_;  // ppe_preconditioner two_level only (empty otherwise)
  View1<T> ppe_coef_[3];  // the PPE operator's stored pair coefficients (ppe_stored): ghost, fluid, wall lists
  neighbors::NeighborSearch<T, D> search_ff_, search_fw_, search_gf_;
  neighbors::NeighborList ff_, fw_, gf_;
  solvers::SolverOptions opts_;
  PpeRecord last_;
  bool last_ok_ = true;
  std::string last_reason_;
  long long ppe_total_ = 0, ppe_solves_ = 0, escaped_ = 0;
  double ppe_seconds_ = 0.0;
  models::StateRegistry state_;
  std::int64_t step_ = 0;
};

}  // namespace polymech::isph
