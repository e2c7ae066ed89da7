// Discrete elements: spheres with Hertz-Mindlin contact (seed 002 paper 2, eqs. (11)-(17)) against each
// other, analytic planes and quadrilateral FE surfaces (inside-outside, eqs. (1)-(10)).
//
//   polymech::dem::Config c;          // or io::load_dem_scene(...)
//   c.effects = EffectSet::resolve({"friction", "damping"}, dem::effect_table());
//   dem::Dem<double> model(c);
//   models::run(model, steps);
//
// One step (models/common/explicit_model.hpp), velocity Verlet on translation and spin:
//   kick (v, omega) + drift -> x = x0 + u, a = g -> broad phase (Verlet skin, history carried)
//   -> sphere_sphere -> sphere_plane -> [sphere_facet] -> kick.
// Effects: `friction` (the tangential spring, its history), `damping` (restitution < 1), `fe_surfaces`,
// `clumps`, `rigid_wheel` (the surface is a wheel, dem/wheel.hpp, driven by dem/wheel_drive.hpp: set
// on the bed at WheelSpec::start, then its x velocity and spin prescribed, its height free under the
// load; the reaction of the spheres on it summed in index order each step), `fe_tyre` (the surface is the
// outer side of a deformable FE tyre, dem/tyre_drive.hpp, on the same schedule: stepped with the spheres,
// the contacts' forces returned to its nodes, dem/surface_loads.hpp).
// The time step is refused above time_step_limit() (dem/setup.hpp: Rayleigh and Hertz contact time).
// The members that fill the device arrays from the configuration: dem/allocation.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/clock.hpp"
#include "common/contact_pairs_archive.hpp"
#include "common/explicit_model.hpp"
#include "common/particle_health.hpp"
#include "common/run.hpp"
#include "contact/contact_pairs.hpp"
#include "contact/surface_mesh.hpp"
#include "dem/config.hpp"
#include "dem/clumps.hpp"
#include "dem/contact_forces.hpp"
#include "dem/effect_table.hpp"
#include "dem/setup.hpp"
#include "dem/surface_loads.hpp"
#include "dem/tyre_drive.hpp"
#include "dem/wheel_drive.hpp"
#include "particles/integrators.hpp"
#include "rigid/rigid_body.hpp"

namespace polymech::dem {

struct SphereState {  // host copy of one sphere
  double x[3], v[3], omega[3], a[3];
};

template <class T = double>
class Dem {
 public:
  static constexpr int dimension = 3;
  using Pairs = contact::ContactPairs<T, 3, 3>;

  static const std::vector<EffectSpec>& effects() { return effect_table(); }

  explicit Dem(const Config& c)
      : cfg_((validate(c), c)),
        friction_(c.effects.has("friction")),
        damping_(c.effects.has("damping")),
        surfaces_(c.effects.has("fe_surfaces")),
        clumps_(c.effects.has("clumps")),
        wheel_(c.effects.has("rigid_wheel")),
        tyre_(c.effects.has("fe_tyre")),
        clump_init_(c.clumps.empty() ? ClumpBodies{} : expand_clumps(c)),
        pairs_(T(2 * max_radius(c, clump_init_)), T(skin(c, clump_init_)), neighbors::ListKind::half, "polymech::dem::sphere_pairs", friction_),
        facet_pairs_(T(0), T(skin(c, clump_init_)), neighbors::ListKind::full, "polymech::dem::facet_pairs", friction_) {
    limit_ = time_step_limit(cfg_);
    const bool automatic = cfg_.dt <= 0;
    if (cfg_.dt <= 0) cfg_.dt = cfg_.dt_safety * limit_.limit;
    if (cfg_.dt > limit_.limit)
      throw std::invalid_argument("time step " + std::to_string(cfg_.dt) + " s exceeds the limit " + limit_.describe());
    const double beta = damping_ ? hertz_damping_ratio(cfg_.restitution) : 0.0;  // calibrated on the Hertz law
    const double mu = friction_ ? cfg_.friction : 0.0;
    const auto& p = cfg_.particle;
    const auto& w = cfg_.wall;
    pp_ = law(p, p, beta, mu);
    pw_ = law(p, w, beta, mu);
    if (friction_ && cfg_.pour_friction >= 0) {  // the pour's laws, to its step count (a step index: restarts agree)
      if (!(cfg_.pour_friction_until > 0)) throw std::invalid_argument("dem: pour_friction needs pour_friction_until > 0 (s)");
      pour_pp_ = law(p, p, beta, cfg_.pour_friction);
      pour_pw_ = law(p, w, beta, cfg_.pour_friction);
      pour_steps_ = static_cast<std::int64_t>(std::ceil(cfg_.pour_friction_until / cfg_.dt - 1e-9));
    }
    pf_ = tyre_ ? law(p, Material{cfg_.tyre.tread_young, cfg_.tyre.tread_poisson, 0.0}, beta, mu) : pw_;  // spheres on the tread
    allocate_spheres();
    pairs_.set_sizes(s_.radius);  // sphere pairs within r_i + r_j + skin (LIGGGHTS' rule), not 2 r_max + skin
    pairs_.set_row_capacity(16);  // a half row holds a sphere's few larger-index neighbours: one search per build
    if (clumps_) allocate_clumps();
    allocate_planes();
    if (tyre_) {
      if (!surfaces_ || wheel_) throw std::invalid_argument("dem: effect fe_tyre needs fe_surfaces and excludes rigid_wheel");
      // one common step (substeps 1): the smaller of the spheres' and the tyre's (safety x its critical step) when
      // the scene gives none; a given step above the tyre's is refused (solid::HyperelasticExplicit's message).
      // Subcycled (substeps 0 or > 1): the DEM's step, the tyre's dt / k (dem/tyre_drive.hpp).
      const bool common = cfg_.tyre.substeps == 1;
      tyre_drive_ = TyreDrive<T>(cfg_.wheel, cfg_.tyre, automatic || !common ? 0.0 : cfg_.dt);
      if (common) {
        if (automatic && tyre_drive_.solid().time_step() < cfg_.dt) cfg_.dt = tyre_drive_.solid().time_step();
        tyre_drive_.set_time_step(cfg_.dt);
      } else {
        tyre_drive_.subcycle(cfg_.dt, cfg_.tyre.substeps);
      }
      if (const auto bad = cfg_.wheel.damping_problem(tyre_drive_.solid().time_step()); !bad.empty())
        throw std::invalid_argument("dem: the wheel's damping " + bad);
      cfg_.surface = tyre_drive_.surface();
    }
    if (surfaces_) allocate_surface();
    if (wheel_) {
      if (!surfaces_) throw std::invalid_argument("dem: effect rigid_wheel needs fe_surfaces (the wheel's mesh)");
      if (const auto bad = cfg_.wheel.damping_problem(cfg_.dt); !bad.empty()) throw std::invalid_argument("dem: the wheel's damping " + bad);
      wheel_drive_ = WheelDrive<T>(cfg_.wheel, mesh_, s_.size());
    }
    register_state();
  }

  void step() { models::explicit_step(*this); }
  void prepare() {
    if (prepared_) return;
    compute_forces();
    add_contact_forces();
    if (gather_pending_) {  // the first forces are complete before the first kick
      sphere_sphere_gather(s_, transposed_, pair_load_);
      gather_pending_ = false;
    }
    prepared_ = true;
  }
  // Spheres without clumps take the first half, the start of the forces (x = x0 + u, a = g) and the
  // sphere list's displacement check in one pass (kick_drift_start); the second half kick is the gather's
  // pass (sphere_sphere_gather with h). With clumps, the members' motion is the clumps': separate passes.
  void advance_first_half() {
    if (wheel_) wheel_drive_.first_half(clock_.index(), cfg_.dt, s_, mesh_);
    if (tyre_) tyre_drive_.first_half(clock_.index(), cfg_.dt, s_, mesh_);
    const T dt = T(cfg_.dt);
    if (!clumps_) {
      moved_ = kick_drift_start(s_, T(0.5) * dt, dt, gravity(), pairs_.queries_at_build());
      forces_started_ = true;
      return;
    }
    kick_drift(s_, T(0.5) * dt, dt);
    clump_kick(clumps_set_, 0.5 * cfg_.dt);
    clump_drift(clumps_set_, cfg_.dt);
    clump_members(s_, clumps_set_, true);
  }
  void compute_forces() {
    if (!forces_started_) start_forces(s_, gravity());
    forces_started_ = false;
  }
  void observe() {}
  void add_contact_forces() {
    const T dt = T(cfg_.dt);
    if (moved_ >= T(0))
      pairs_.update(s_.x, moved_);
    else
      pairs_.update(s_.x);
    moved_ = T(-1);
    if (transposed_at_ != pairs_.builds()) {  // a new list: its transpose and the pairs' load rows
      neighbors::transpose(pairs_.list(), transposed_);
      const auto np = static_cast<std::size_t>(pairs_.list().num_pairs);
      if (pair_load_.extent(0) < np)
        pair_load_ = PairLoadView<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::dem::pair_load")), np + np / 8 + 16);
      transposed_at_ = pairs_.builds();
    }
    const bool pouring = clock_.index() < pour_steps_;  // the pour's friction (Config::pour_friction)
    const HertzMindlin<T>& pp = pouring ? pour_pp_ : pp_;
    PlaneContacts<T> walls;
    if (planes_.extent(0) > 0) {
      if (planes_at_ != pairs_.builds()) {  // the planes' Verlet mask, with the sphere list
        near_planes(s_, planes_, T(skin(cfg_, clump_init_)), near_planes_, plane_history_, friction_);
        planes_at_ = pairs_.builds();
      }
      walls = PlaneContacts<T>{planes_, plane_history_, near_planes_, pouring ? pour_pw_ : pw_};
    }
    sphere_sphere_rows(s_, pairs_.list(), pairs_.history().values, pair_load_, pp, friction_, dt, walls);
    if (tyre_) {
      if (tyre_drive_.placed()) tyre_contacts(dt);
    } else if (surfaces_) {
      facet_pairs_.update(s_.x, mesh_.centroid);
      sphere_facet_forces(s_, mesh_, facet_pairs_.list(), facet_pairs_.history().values, pw_, friction_, dt,
                          wheel_ ? wheel_drive_.motion(clock_.index(), cfg_.dt) : SurfaceMotion<T>(), wheel_drive_.reaction());
      if (wheel_) wheel_drive_.add_loads(clock_.index(), cfg_.dt);
    }
    if (clumps_) {
      sphere_sphere_gather(s_, transposed_, pair_load_);
      clump_loads(s_, clumps_set_, gravity());
    } else {
      gather_pending_ = true;  // with the second half kick (advance_second_half)
    }
  }
  void advance_second_half() {
    if (wheel_) wheel_drive_.second_half(cfg_.dt);  // the wheel's height: m z'' = F_z (gravel + load)
    if (tyre_) tyre_drive_.second_half();           // the tyre under the contacts' node forces
    const T h = T(0.5) * T(cfg_.dt);
    if (gather_pending_) {
      sphere_sphere_gather(s_, transposed_, pair_load_, h);
      gather_pending_ = false;
    } else {
      kick(s_, h);
    }
    if (clumps_) {
      clump_kick(clumps_set_, 0.5 * cfg_.dt);
      clump_members(s_, clumps_set_, false);
    }
    clock_.tick();
  }

  double dt() const { return cfg_.dt; }
  double time() const { return clock_.time(cfg_.dt); }
  std::int64_t step_index() const { return clock_.index(); }
  void set_step_index(std::int64_t s) { clock_.set_index(s); }
  const TimeStepLimit& limit() const { return limit_; }
  const Config& config() const { return cfg_; }
  const SphereSet<T>& spheres() const { return s_; }
  const contact::SurfaceMesh<T>& surface() const { return mesh_; }
  int sphere_list_builds() const { return pairs_.builds(); }
  // Moves plane q to pass through `point` (its normal kept): a wall that opens (the heap's release)
  // is moved far behind the spheres. The planes are part of the state, so a restart keeps the move.
  void move_plane(std::size_t q, const std::array<double, 3>& point) {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), planes_);
    for (int k = 0; k < 3; ++k) h(q, k) = T(point[k]);
    Kokkos::deep_copy(planes_, h);
    planes_at_ = -1;  // the near-plane mask is stale
  }
  // Spheres: the free ones (Config::spheres) first, then the clumps' members in clump order.
  Index sphere_count() const { return s_.size(); }
  std::size_t clump_count() const { return clump_init_.bodies.size(); }
  // Host copy of clump b's rigid body (pose, velocity, angular momentum, last loads).
  rigid::RigidBody<3> clump(std::size_t b) const {
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(clumps_set_.bodies, b));
    return h();
  }

  // The wheel (effect rigid_wheel) after the last step.
  WheelState wheel() const {
    if (tyre_) return tyre_drive_.state(clock_.index(), cfg_.dt);
    return wheel_ ? wheel_drive_.state(clock_.index(), cfg_.dt) : WheelState();
  }
  // The spheres' total force on the wheel (tyre) and its moment about the wheel's (rim's) centre (last step).
  std::array<double, 6> wheel_contact() const { return tyre_ ? tyre_drive_.contact() : wheel_drive_.contact(); }
  // The deformable tyre (effect fe_tyre).
  const TyreDrive<T>& tyre() const { return tyre_drive_; }

  // The watchdog's check: the first sphere whose state is not finite, or that moves more than the
  // neighbour lists' skin in one step (issue 33 item 2): the lists are rebuilt when a sphere has moved half
  // the skin, so beyond that contacts are missed and spheres pass through each other or a wall.
  models::Health health() const {
    if (tyre_ && !tyre_drive_.failure().empty()) {  // the tyre stopped evaluating (dem/tyre_drive.hpp)
      models::Health t;
      t.finite = false;
      t.what = "tyre";
      t.first_bad = 0;
      t.problem = tyre_drive_.failure();
      return t;
    }
    const models::Health h = models::particle_health<T, 3>(s_);
    if (!h.finite || !(cfg_.dt > 0)) return h;
    return models::speed_health(s_, skin(cfg_, clump_init_) / cfg_.dt, "the neighbour skin per step (skin / dt)");
  }
  const models::StateRegistry& state() const { return state_; }
  // Checkpoints (models/common/run.hpp): the registered state, the step and both contact lists with
  // the tangential springs of their pairs (models/common/contact_pairs_archive.hpp): a restarted run
  // continues bit for bit.
  void save(models::Archive& a, const std::string& prefix) const {
    state_.save(a, prefix + "state/");
    clock_.save(a, prefix);
    models::save_contact_pairs(a, prefix + "sphere_pairs/", pairs_);
    if (surfaces_) models::save_contact_pairs(a, prefix + "facet_pairs/", facet_pairs_);
  }
  void load(const models::Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    clock_.restore(a, prefix);
    models::load_contact_pairs(a, prefix + "sphere_pairs/", pairs_);
    transposed_at_ = -1;
    planes_at_ = -1;
    if (surfaces_) models::load_contact_pairs(a, prefix + "facet_pairs/", facet_pairs_);
    by_facet_at_ = -1;
    tyre_drive_.restored(mesh_);  // its clock and rim from the record, its surface placed
    current_positions(s_);
    prepared_ = true;  // the accelerations of this state are part of it
  }

  // Host copy of sphere i (positions x0 + u).
  SphereState sphere(Index i) const {
    SphereState out;
    auto x0 = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(s_.x0, i, Kokkos::ALL()));
    auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(s_.u, i, Kokkos::ALL()));
    auto v = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(s_.v, i, Kokkos::ALL()));
    auto w = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(s_.omega, i, Kokkos::ALL()));
    auto a = Kokkos::create_mirror_view_and_copy(HostSpace(), Kokkos::subview(s_.a, i, Kokkos::ALL()));
    for (int k = 0; k < 3; ++k) {
      out.x[k] = double(x0(k)) + double(u(k));
      out.v[k] = double(v(k));
      out.omega[k] = double(w(k));
      out.a[k] = double(a(k));
    }
    return out;
  }
  // |m (a - g)| of sphere i: the magnitude of the contact force on it (after a step).
  double contact_force(Index i) const {
    const SphereState st = sphere(i);
    const double m = cfg_.particle.density * 4.0 / 3.0 * kPi * std::pow(cfg_.spheres.at(i).radius, 3);
    double f2 = 0;
    for (int k = 0; k < 3; ++k) f2 += std::pow(m * (st.a[k] - cfg_.gravity[k]), 2);
    return std::sqrt(f2);
  }
  // Translational + rotational kinetic energy of the free spheres and the clumps (host sum).
  double kinetic_energy() const {
    auto v = Kokkos::create_mirror_view_and_copy(HostSpace(), s_.v);
    auto w = Kokkos::create_mirror_view_and_copy(HostSpace(), s_.omega);
    double e = 0;
    for (std::size_t i = 0; i < cfg_.spheres.size(); ++i) {
      const double r = cfg_.spheres[i].radius, m = cfg_.particle.density * 4.0 / 3.0 * kPi * r * r * r;
      for (int k = 0; k < 3; ++k) e += 0.5 * m * double(v(i, k)) * double(v(i, k)) + 0.2 * m * r * r * double(w(i, k)) * double(w(i, k));
    }
    if (clumps_) {
      auto b = Kokkos::create_mirror_view_and_copy(HostSpace(), clumps_set_.bodies);
      for (std::size_t k = 0; k < b.extent(0); ++k) e += b(k).kinetic_energy();
    }
    return e;
  }

 private:
  static double max_radius(const Config& c, const ClumpBodies& k) {
    double r = 0;
    for (const auto& s : c.spheres) r = std::max(r, s.radius);
    for (const auto& s : k.members) r = std::max(r, s.radius);
    return r;
  }
  static double skin(const Config& c, const ClumpBodies& k) {
    if (c.skin > 0) return c.skin;
    double r = max_radius(c, k);
    for (const auto& s : c.spheres) r = std::min(r, s.radius);
    for (const auto& s : k.members) r = std::min(r, s.radius);
    return 0.2 * r;
  }
  Vec3<T> gravity() const {
    Vec3<T> g;  // named, not a braced list passed to a call (nvcc 11.8, docs/DEVELOPING.md)
    for (int k = 0; k < 3; ++k) g[k] = T(cfg_.gravity[k]);
    return g;
  }
  static HertzMindlin<T> law(const Material& a, const Material& b, double beta, double mu) {
    HertzMindlin<T> h;
    h.e_star = T(effective_modulus(a.young, a.poisson, b.young, b.poisson));
    h.g_star = T(effective_shear_modulus(a.young, a.poisson, b.young, b.poisson));
    h.beta = T(beta);
    h.mu = T(mu);
    return h;
  }
  static void validate(const Config& c) {
    if (c.spheres.empty() && c.clumps.empty()) throw std::invalid_argument("dem: no spheres and no clumps");
    if (!c.clumps.empty() && !c.effects.has("clumps"))
      throw std::invalid_argument("dem: clumps need the effect `clumps`");
    if (c.effects.has("clumps") && c.clumps.empty()) throw std::invalid_argument("dem: effect clumps without clumps");
    for (const auto& s : c.spheres)
      if (!(s.radius > 0)) throw std::invalid_argument("dem: a sphere radius must be > 0");
    if (!(c.particle.young > 0) || !(c.particle.density > 0) || !(c.particle.poisson < 0.5))
      throw std::invalid_argument("dem: particle E > 0, rho > 0 and nu < 0.5 are required");
    if (c.effects.has("damping") && !(c.restitution > 0 && c.restitution <= 1))
      throw std::invalid_argument("dem: restitution must be in (0, 1]");
    if (c.effects.has("fe_surfaces") && c.surface.empty() && !c.effects.has("fe_tyre"))
      throw std::invalid_argument("dem: effect fe_surfaces without a surface");
  }

  // The device arrays of the spheres, the clumps and the planes (dem/allocation.hpp).
  void allocate_spheres();
  void allocate_clumps();
  void allocate_planes();
  void allocate_surface() {
    std::vector<Index> nodes(cfg_.surface.facet_nodes.begin(), cfg_.surface.facet_nodes.end());
    mesh_ = contact::make_surface_mesh<T>(cfg_.surface.nodes, cfg_.surface.facet_sizes, nodes, "polymech::dem::surface");
    // a deforming surface's facets grow (the tyre's inflation, a few per cent): a quarter more reach
    const T reach = contact::max_facet_radius(mesh_) * T(tyre_ ? 1.25 : 1.0);
    facet_pairs_ = Pairs(T(max_radius(cfg_, clump_init_)) + reach, T(skin(cfg_, clump_init_)), neighbors::ListKind::full,
                         "polymech::dem::facet_pairs", friction_);
  }
  // The spheres against the tyre's deforming surface: the contacts (the material velocity interpolated from
  // its nodes), each entry's force and weights, then the node forces gathered over the list's transpose by
  // facet (dem/surface_loads.hpp).
  void tyre_contacts(T dt) {
    facet_pairs_.update(s_.x, mesh_.centroid);
    const auto& list = facet_pairs_.list();
    if (by_facet_at_ != facet_pairs_.builds()) {
      neighbors::transpose(list, by_facet_, mesh_.facet_count());
      const auto np = static_cast<std::size_t>(list.num_pairs);
      if (entry_load_.extent(0) < np)
        entry_load_ = EntryLoadView<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::dem::tyre_entry_load")), np + np / 8 + 16);
      by_facet_at_ = facet_pairs_.builds();
    }
    sphere_deforming_facet_forces(s_, mesh_, list, facet_pairs_.history().values, pf_, friction_, dt, tyre_drive_.node_velocity(), entry_load_);
    surface_node_loads(tyre_drive_.adjacency(), by_facet_, entry_load_, tyre_drive_.node_force());
  }
  void register_state() {
    state_.add("u", s_.u);
    state_.add("v", s_.v);
    state_.add("a", s_.a);
    state_.add("omega", s_.omega);
    state_.add("alpha", s_.alpha);
    state_.add("plane_history", plane_history_);
    state_.add("planes", planes_);
    state_.add("clump_bodies", clumps_set_.bodies);
    wheel_drive_.register_state(state_);  // "wheel", "wheel_info" (nothing without the wheel)
    tyre_drive_.register_state(state_);   // "tyre_u", "tyre_v", "tyre_a", "tyre_info" (nothing without the tyre)
    // Not registered: the pair histories (tangential springs), double-buffered inside ContactPairs and
    // reallocated when a list grows; a watchdog restore keeps the current springs (docs/METHODS.md), a
    // checkpoint writes them with the lists (save()).
  }

  Config cfg_;
  bool friction_, damping_, surfaces_, clumps_, wheel_, tyre_;
  ClumpBodies clump_init_;
  Pairs pairs_, facet_pairs_;
  neighbors::ListTranspose transposed_;  // of the half list pairs_ (built with it)
  PairLoadView<T> pair_load_;            // per listed pair: what its second sphere gets
  int transposed_at_ = -1;               // the pairs_.builds() the transpose is of
  PlaneMask near_planes_;                // per sphere: the planes within reach (near_planes)
  int planes_at_ = -1;                   // the pairs_.builds() the mask is of
  ClumpSet<T> clumps_set_;
  TimeStepLimit limit_;
  HertzMindlin<T> pp_, pw_, pf_;  // sphere-sphere, sphere-wall, sphere-facet
  HertzMindlin<T> pour_pp_, pour_pw_;  // the same with the pour's friction, for the first pour_steps_ steps
  std::int64_t pour_steps_ = 0;
  SphereSet<T> s_;
  PlaneView<T> planes_;
  SpringView<T> plane_history_;
  contact::SurfaceMesh<T> mesh_;
  WheelDrive<T> wheel_drive_;  // the wheel (rigid_wheel; dem/wheel_drive.hpp)
  TyreDrive<T> tyre_drive_;    // the tyre (fe_tyre; dem/tyre_drive.hpp)
  neighbors::ListTranspose by_facet_;  // of the sphere-facet list over the facets (fe_tyre)
  EntryLoadView<T> entry_load_;         // per sphere-facet entry: force on the tyre and corner weights (fe_tyre)
  int by_facet_at_ = -1;                // the facet_pairs_.builds() by_facet_ is of
  models::StateRegistry state_;
  models::StepClock clock_;  // step index and time (models/common/clock.hpp)
  bool prepared_ = false;
  bool forces_started_ = false;  // kick_drift_start did start_forces' work this step
  bool gather_pending_ = false;  // the sphere-sphere gather waits for the second half kick
  T moved_ = T(-1);              // the sphere list's displacement check, from kick_drift_start (< 0: none)
};

}  // namespace polymech::dem

#include "dem/allocation.hpp"  // the members declared above: the model's device arrays
