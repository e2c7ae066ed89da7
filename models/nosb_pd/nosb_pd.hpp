// Non-ordinary state-based peridynamics with contact fracture (seed 003): owns the particle Views,
// builds its step from the enabled effects, integrates with velocity Verlet, and exposes diagnostics.
//
//   polymech::nosb_pd::Config c;     // or io::load_nosb_pd_scene(...)
//   c.effects = EffectSet::resolve({"damage", "velocity_viscosity"}, nosb_pd::effect_table());
//   NosbPd<double, 3> model(c);
//   while (model.step_index() < c.steps) model.step();
//
// One step (models/common/explicit_model.hpp): kick, drift, then the forces at the new state:
//   deformation_gradient (eq. (1), bond breakage) -> stress (the law of kernels/materials, by type)
//   -> [velocity_viscosity_state (eq. (3))] -> bond_forces [+hourglass] [+velocity viscosity]
//   -> (a coupled model's interaction, e.g. the projectile) -> [short-range repulsion], then the kick.
// The job of this class is the step and its forces; the constants come from parameters.hpp, the
// grips and clamp from loading.hpp, the stable step from stability.hpp, the projectile from impact.hpp.
#pragma once

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "common/clock.hpp"
#include "common/explicit_model.hpp"
#include "common/host_copy.hpp"
#include "common/particle_health.hpp"
#include "common/run.hpp"
#include "common/stability.hpp"
#include "contact/pd_short_range.hpp"
#include "neighbors/neighbor_search.hpp"
#include "neighbors/verlet_list.hpp"
#include "nosb_pd/config.hpp"
#include "nosb_pd/effect_table.hpp"
#include "nosb_pd/loading.hpp"
#include "nosb_pd/parameters.hpp"
#include "nosb_pd/particles.hpp"
#include "particles/integrators.hpp"
#include "particles/reductions.hpp"
#include "pd/diagnostics.hpp"
#include "pd/energy.hpp"

namespace polymech::nosb_pd {

struct Energies {
  double kinetic = 0, strain = 0, plastic = 0, viscous = 0, hourglass = 0, contact = 0, projectile_kinetic = 0;
  double short_range = 0;  // potential energy of the short-range springs
  double momentum[3] = {0, 0, 0};  // particles (+ projectile, in an impact)
  // everything the system holds or has dissipated; equals the initial energy up to the integrator's
  // error and the energy released by breaking bonds
  double total() const { return kinetic + strain + plastic - viscous - hourglass + contact + short_range + projectile_kinetic; }
};

struct HostFields {
  std::vector<double> x0, u, v;             // n x D
  std::vector<double> damage, eps_p, volume;  // n (damage / eps_p empty without the effect / law)
};

// The degrees of freedom of the power iteration (models/common/stability.hpp): u with the particle
// volume as mass (rho cancels in M^-1 K).
template <class T, int D>
struct DisplacementDofs {
  static constexpr int slots = D;
  pd::Fields<T, D> f;
  KOKKOS_INLINE_FUNCTION T& state(Index i, int s) const { return f.u(i, s); }
  KOKKOS_INLINE_FUNCTION T response(Index i, int s) const { return f.a(i, s); }
  KOKKOS_INLINE_FUNCTION double weight(Index i, int) const { return double(f.volume(i)); }
  KOKKOS_INLINE_FUNCTION T start_divisor(int) const { return T(1); }
};

template <class T, int D>
class NosbPd {
  static_assert(D == 2 || D == 3, "NosbPd is 2D (plane strain) or 3D");

 public:
  static constexpr int dimension = D;

  static const std::vector<EffectSpec>& effects() { return effect_table(); }

  // evaluate_initial_forces = false leaves the first force evaluation to prepare() (a coupled model
  // does it with its interaction included).
  explicit NosbPd(const Config& c, bool evaluate_initial_forces = true)
      : cfg_(c),
        viscosity_(c.effects.has("velocity_viscosity")),
        hourglass_(c.effects.has("hourglass")),
        damage_(c.effects.has("damage")),
        short_range_(c.effects.has("short_range")),
        p_((validate(c), c)) {
    allocate(generate_particles(c));
    constraints_ = Constraints<T, D>(cfg_, f_);
    register_state();
    if (evaluate_initial_forces) prepare();
    if (cfg_.dt <= 0.0) cfg_.dt = cfg_.dt_safety * stable_dt();
  }

  // One step of velocity Verlet, in the phases of models/common/explicit_model.hpp.
  void step() { models::explicit_step(*this); }

  // Accelerations of the initial state (velocity Verlet's a_0).
  void prepare() {
    if (prepared_) return;
    compute_forces();
    add_contact_forces();
    prepared_ = true;
  }
  void mark_prepared() { prepared_ = true; }
  void advance_first_half() {
    const T dt = static_cast<T>(cfg_.dt), h = T(0.5) * dt, damping = static_cast<T>(cfg_.mass_damping);
    particles::kick(f_, h, damping);
    particles::drift(f_, dt);
    work_dt_ = dt;  // the control forces' work is accounted over this step
  }
  // Internal forces at the current displacements and velocities: a = L / rho (overwritten).
  void compute_forces() {
    pd::deformation_gradient(family_, f_, p_.deformation);
    std::visit([&](const auto& law) { pd::update_stress(f_, law, stress_dt(), p_.crush); }, p_.law);
    if (viscosity_) pd::velocity_viscosity_state(f_, p_.viscosity);
    auto fp = p_.force;
    fp.work_dt = work_dt_;
    pd::bond_forces(family_, f_, fp, hourglass_, viscosity_);
  }
  void observe() {}
  // The short-range repulsion of fracture faces and fragments (short_range effect).
  void add_contact_forces() {
    if (!short_range_) return;
    contact::pd_current_positions(f_.x0, f_.u, positions_);
    verlet_->update(positions_);
    contact::pd_short_range(verlet_->list(), positions_, f_.volume, p_.short_range, f_.a);
  }
  void advance_second_half() {
    work_dt_ = T(0);
    const T h = T(0.5) * static_cast<T>(cfg_.dt), damping = static_cast<T>(cfg_.mass_damping);
    particles::kick(f_, h, damping);
    clock_.tick();
  }

  double time() const { return clock_.time(cfg_.dt); }
  std::int64_t step_index() const { return clock_.index(); }
  void set_step_index(std::int64_t k) { clock_.set_index(k); }
  double dt() const { return cfg_.dt; }
  Index particles() const { return n_; }
  Offset bonds() const { return family_.num_pairs; }
  const Config& config() const { return cfg_; }
  const neighbors::BondFamily& family() const { return family_; }
  const pd::Fields<T, D>& fields() const { return f_; }
  pd::Fields<T, D>& fields() { return f_; }
  double beta() const { return p_.beta; }
  double micromodulus() const { return p_.micromodulus; }
  double critical_stretch_value() const { return p_.critical_stretch; }
  int verlet_builds() const { return verlet_ ? verlet_->builds() : 0; }
  const models::StateRegistry& state() const { return state_; }

  // The complete state for a checkpoint (fields, bonds, plastic and control-force history, step, the
  // short-range list's build positions), and back: the run continues bit for bit.
  void save(models::Archive& a, const std::string& prefix) {
    state_.save(a, prefix + "state/");
    clock_.save(a, prefix);
    if (verlet_ && verlet_->builds() > 0) {
      a.put(prefix + "short_range_builds", verlet_->builds());
      models::StateRegistry r;
      r.add("x_at_build", verlet_->positions_at_build());
      r.save(a, prefix + "short_range/");
    }
  }
  void load(const models::Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    clock_.restore(a, prefix);
    prepared_ = true;  // the accelerations of this state are part of it
    if (verlet_ && a.has(prefix + "short_range_builds")) {
      VecView<T, D> x("polymech::nosb_pd::short_range_x_at_build", static_cast<std::size_t>(n_));
      models::StateRegistry r;
      r.add("x_at_build", x);
      r.load(a, prefix + "short_range/");
      verlet_->restore(x, a.get<int>(prefix + "short_range_builds"));
    }
  }

  // Energies of the particles (contact and projectile terms are an impact's, impact.hpp).
  Energies energy() const {
    const auto e = std::visit(
        [&](const auto& law) { return pd::particle_energies(f_, law, static_cast<T>(cfg_.material.density)); }, p_.law);
    Energies out;
    out.kinetic = e.kinetic;
    out.strain = e.strain;
    out.plastic = e.plastic;
    out.viscous = e.viscous;
    out.hourglass = e.hourglass;
    for (int k = 0; k < D; ++k) out.momentum[k] = e.momentum[k];
    if (short_range_) {
      contact::pd_short_range_energy(verlet_->list(), positions_, f_.volume, p_.short_range, short_range_energy_);
      out.short_range = particles::scalar_sum("polymech::nosb_pd::short_range_energy", short_range_energy_);
    }
    return out;
  }

  // How much of the bond deformation F does not see (zero-energy measure, pd/diagnostics.hpp), from
  // the F of the last force evaluation; interior_only: particles with a complete family only.
  pd::NonAffineMeasure nonaffine_deviation(bool interior_only = false) const {
    const auto bonds = lattice_family(D, cfg_.spacing, cfg_.horizon_ratio, false, 1.0).bonds;
    return pd::nonaffine_deviation(family_, f_, interior_only ? static_cast<Index>(bonds) : 0);
  }

  // Broken bonds (full list: each counted from both ends).
  std::int64_t broken_bonds() const {
    if (!damage_) return 0;
    const auto intact = f_.bond_intact;
    std::int64_t broken = 0;
    Kokkos::parallel_reduce(
        "polymech::nosb_pd::broken_bonds", range(family_.num_pairs),
        KOKKOS_LAMBDA(const std::int64_t k, std::int64_t& b) { b += intact(k) ? 0 : 1; }, broken);
    return broken;
  }

  // The watchdog's check: the first particle whose displacement or velocity is NaN or infinite, or that
  // moves a spacing in one step (issue 33 item 2): at dt_safety x the stable step that is about c / dt_safety
  // (P-wave speed c), a material speed no solid reaches without shock physics, which the model does not
  // have; a lattice that blew up gets there long before its values overflow.
  models::Health health() const {
    const models::Health h = models::particle_health(f_);
    if (!h.finite || !(cfg_.dt > 0)) return h;
    return models::speed_health(f_, cfg_.spacing / cfg_.dt, "one spacing per step (dx / dt)");
  }
  bool finite() const { return health().finite; }

  HostFields host_fields() const {
    HostFields h;
    h.x0 = models::to_host(f_.x0);
    h.u = models::to_host(f_.u);
    h.v = models::to_host(f_.v);
    h.damage = models::to_host(f_.damage);
    h.eps_p = models::to_host(f_.eps_p);
    h.volume = models::to_host(f_.volume);
    return h;
  }

  // Tension loading (loading.hpp): pull the x = length grip at `velocity` (0: hold); the measurements.
  void set_grip_velocity(double velocity) { constraints_.set_grip_velocity(f_, velocity); }
  TensionMeasure tension_measure() const { return constraints_.tension_measure(f_); }
  double cross_section() const { return constraints_.cross_section(); }

  // Largest eigenvalue of M^-1 K of the linearised elastic operator (with the hourglass force when
  // enabled), by power iteration on this model's particles. Leaves the state at rest.
  double max_eigenvalue(int iterations = 150) {
    const T eps = static_cast<T>(1e-9 * cfg_.spacing);
    auto linear = p_.deformation;
    linear.damage = false;
    linear.mean_velocity = false;
    const auto elastic = materials::StVenantKirchhoff<T>{std::visit([](const auto& law) { return law.elastic; }, p_.law)};
    auto apply = [&] {
      pd::deformation_gradient(family_, f_, linear);
      pd::update_stress(f_, elastic);
      pd::bond_forces(family_, f_, p_.force, hourglass_, false);
    };
    const double lambda = models::largest_eigenvalue(DisplacementDofs<T, D>{f_}, n_, apply, eps, iterations,
                                                     particles::StartVector{D, 2654435761u, 12345u});
    Kokkos::deep_copy(f_.u, T(0));
    Kokkos::deep_copy(f_.a, T(0));
    return lambda;
  }

  // The stable step of this configuration (stability.hpp), computed once.
  static double stable_time_step(const Config& c);
  double stable_dt() {
    if (stable_dt_ <= 0) stable_dt_ = stable_time_step(cfg_);
    return stable_dt_;
  }

 private:
  static void validate(const Config& c) {
    auto fail = [](const std::string& m) { throw std::invalid_argument("nosb_pd: " + m); };
    if (c.dimension != D) fail("dimension " + std::to_string(c.dimension) + " does not match the model's " + std::to_string(D));
    if (!(c.spacing > 0)) fail("spacing must be > 0");
    if (!(c.horizon_ratio >= 1.0)) fail("horizon ratio m = delta / spacing must be >= 1");
    const auto& g = c.geometry;
    if (g.shape == Shape::round_bar && D != 3) fail("a round bar is 3D");
    if (g.layout == Layout::cylindrical && (g.shape == Shape::box || D != 3)) fail("the cylindrical layout needs a 3D disc or round bar");
    if (g.shape == Shape::box && (!(g.length >= c.spacing) || !(g.height >= c.spacing) || (D == 3 && !(g.width >= c.spacing))))
      fail("the box must be at least one spacing in every direction");
    if (g.shape != Shape::box && (!(g.radius >= c.spacing))) fail("radius must be >= spacing");
    if (g.shape == Shape::disc && !(g.thickness >= c.spacing)) fail("thickness must be >= spacing");
    if (g.shape == Shape::round_bar && !(g.length >= c.spacing)) fail("length must be >= spacing");
    if (!(g.jitter >= 0.0 && g.jitter < 0.5)) fail("jitter must be in [0, 0.5)");
    const auto& mat = c.material;
    if (!(mat.density > 0) || !(mat.youngs_modulus > 0) || !(mat.poisson_ratio > -1.0 && mat.poisson_ratio < 0.5))
      fail("material constants out of range");
    if (c.effects.has("damage") && !(critical_stretch(c) > 0)) fail("damage needs a critical stretch > 0");
    if (c.effects.has("velocity_viscosity") && !(c.stabilization.omega_v > 0 && c.stabilization.c_v >= 0))
      fail("velocity viscosity needs omega_v > 0 and c_v >= 0");
    if (c.loading == Loading::tension && g.shape == Shape::disc) fail("tension loading needs a box or round bar");
    if (!(c.dt >= 0) || !(c.mass_damping >= 0) || !(c.dt_safety > 0 && c.dt_safety <= 1)) fail("time settings out of range");
  }

  // The step of the rate law's update: dt (before dt is resolved, a placeholder that cannot matter:
  // the first evaluation is at rest).
  T stress_dt() const { return static_cast<T>(cfg_.dt > 0 ? cfg_.dt : 1e-9); }

  void allocate(const Particles& p) {
    n_ = static_cast<Index>(p.size());
    const auto n = static_cast<std::size_t>(n_);
    const std::string pre = "polymech::nosb_pd::";
    particles::allocate(f_, n_, pre, particles::ParticleLayout{true, false});
    f_.kinv = pd::MatView<T, D>(pre + "kinv", n);
    f_.F = pd::MatView<T, D>(pre + "F", n);
    f_.A = pd::MatView<T, D>(pre + "A", n);
    f_.status = Kokkos::View<std::uint8_t*, MemSpace>(pre + "status", n);
    if (p_.plastic()) {
      f_.Fdot = pd::MatView<T, D>(pre + "plastic_Fdot", n);
      f_.sigma = pd::SymView<T>(pre + "plastic_sigma", n);
      f_.eps_p = View1<T>(pre + "plastic_eps_p", n);
      f_.temperature = View1<T>(pre + "plastic_temperature", n);
      f_.plastic_work = View1<T>(pre + "plastic_work", n);
      Kokkos::deep_copy(f_.temperature, static_cast<T>(cfg_.material.room_temperature));
    }
    particles::set_reference_positions(f_, [&](std::size_t i, int k) { return p.coord(i, k); });
    {
      auto hv = Kokkos::create_mirror_view(f_.volume);
      for (std::size_t i = 0; i < n; ++i) hv(i) = static_cast<T>(p.volume[i]);
      Kokkos::deep_copy(f_.volume, hv);
    }
    // Reference family (seed 003 §3(1): the particles within the horizon delta of x_i), slightly
    // enlarged so that round-off never drops a lattice bond at exactly delta.
    family_ = neighbors::build_bond_family<T, D>(f_.x0, static_cast<T>(cfg_.horizon() * (1 + 1e-6)));
    f_.bond_weight = View1<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, pre + "bond_weight"),
                              static_cast<std::size_t>(family_.num_pairs));
    pd::bond_weights(family_, f_.x0, f_.volume, p_.weight, f_.bond_weight);
    if (damage_) {
      f_.bond_intact = Kokkos::View<std::uint8_t*, MemSpace>(pre + "damage_bond_intact", static_cast<std::size_t>(family_.num_pairs));
      Kokkos::deep_copy(f_.bond_intact, std::uint8_t(1));
      f_.damage = View1<T>(pre + "damage_field", n);
    }
    if (viscosity_) {
      f_.vbar = VecView<T, D>(pre + "velocity_viscosity_mean_velocity", n);
      f_.horizon_weight = View1<T>(pre + "velocity_viscosity_horizon_weight", n);
      f_.vv_state = VecView<T, D>(pre + "velocity_viscosity_state", n);
      f_.viscous_work = View1<T>(pre + "velocity_viscosity_work", n);
      f_.vv_force = VecView<T, D>(pre + "velocity_viscosity_force", n);
    }
    if (hourglass_) {
      f_.hourglass_work = View1<T>(pre + "hourglass_work", n);
      f_.hg_force = VecView<T, D>(pre + "hourglass_force", n);
    }
    if (short_range_) {
      positions_ = VecView<T, D>(pre + "short_range_positions", n);
      short_range_energy_ = View1<T>(pre + "short_range_energy", n);
      verlet_ = std::make_unique<neighbors::VerletList<T, D>>(p_.short_range.distance,
                                                             static_cast<T>(cfg_.contact.skin * cfg_.spacing),
                                                             neighbors::ListKind::full);
    }
  }

  // What a step reads that it did not compute in the same step: motion (a: velocity Verlet's first
  // kick), the shape tensors and particle status, bonds, material history, the controls' force of the
  // last evaluation and their work.
  void register_state() {
    state_.add("u", f_.u);
    state_.add("v", f_.v);
    state_.add("a", f_.a);
    state_.add("kinv", f_.kinv);
    state_.add("status", f_.status);
    state_.add("damage_bond_intact", f_.bond_intact);
    state_.add("plastic_sigma", f_.sigma);
    state_.add("plastic_eps_p", f_.eps_p);
    state_.add("plastic_temperature", f_.temperature);
    state_.add("plastic_work", f_.plastic_work);
    state_.add("velocity_viscosity_work", f_.viscous_work);
    state_.add("velocity_viscosity_force", f_.vv_force);
    state_.add("hourglass_work", f_.hourglass_work);
    state_.add("hourglass_force", f_.hg_force);
    state_.add("prescribed_v", f_.prescribed_v);
  }

  Config cfg_;
  bool viscosity_, hourglass_, damage_, short_range_;
  Parameters<T, D> p_;
  Index n_ = 0;
  double stable_dt_ = 0.0;
  bool prepared_ = false;
  pd::Fields<T, D> f_;
  neighbors::BondFamily family_;
  Constraints<T, D> constraints_;
  T work_dt_ = T(0);
  VecView<T, D> positions_;
  View1<T> short_range_energy_;
  std::unique_ptr<neighbors::VerletList<T, D>> verlet_;
  models::StepClock clock_;  // step index and time (models/common/clock.hpp)
  models::StateRegistry state_;
};

}  // namespace polymech::nosb_pd

#include "nosb_pd/stability.hpp"
