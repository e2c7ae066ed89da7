// Non-ordinary state-based peridynamics with contact fracture (seed 003): owns the particle Views,
// builds its step from the enabled effects, integrates with velocity Verlet, and exposes diagnostics.
//
//   polymech::nosb_pd::Config c;     // or io::load_nosb_pd_scene(...)
//   c.effects = EffectSet::resolve({"damage", "contact", "velocity_viscosity"}, NosbPd<double, 3>::effects());
//   NosbPd<double, 3> model(c);
//   while (model.step_index() < c.steps) model.step();
//
// One step: kick, drift, then the forces at the new state:
//   deformation_gradient (eq. (1), bond breakage) -> stress (St. Venant-Kirchhoff or J2/Johnson-Cook)
//   -> [velocity_viscosity_state (eq. (3))] -> bond_forces [+hourglass] [+velocity viscosity]
//   -> [projectile_penalty] -> [short-range repulsion], then the second kick.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/pd_short_range.hpp"
#include "contact/projectile_penalty.hpp"
#include "neighbors/neighbor_search.hpp"
#include "neighbors/verlet_list.hpp"
#include "nosb_pd/config.hpp"
#include "nosb_pd/lattice_sums.hpp"
#include "nosb_pd/model_kernels.hpp"
#include "nosb_pd/particles.hpp"
#include "pd/deformation.hpp"
#include "pd/diagnostics.hpp"
#include "pd/energy.hpp"
#include "pd/forces.hpp"
#include "pd/integrate.hpp"
#include "pd/stress.hpp"
#include "pd/viscosity.hpp"

namespace polymech::nosb_pd {

struct Energies {
  double kinetic = 0, strain = 0, plastic = 0, viscous = 0, hourglass = 0, contact = 0, projectile_kinetic = 0;
  double short_range = 0;  // potential energy of the short-range springs
  double momentum[3] = {0, 0, 0};  // particles + projectile
  // everything the system holds or has dissipated; equals the initial energy up to the integrator's
  // error and the energy released by breaking bonds
  double total() const { return kinetic + strain + plastic - viscous - hourglass + contact + short_range + projectile_kinetic; }
};

struct ProjectileState {
  double position[3] = {0, 0, 0}, velocity[3] = {0, 0, 0}, acceleration[3] = {0, 0, 0};
  double reaction[3] = {0, 0, 0};  // force on the projectile [N]
  double mass = 0.0;
};

struct HostFields {
  std::vector<double> x0, u, v;             // n x D
  std::vector<double> damage, eps_p, volume;  // n (damage / eps_p empty without the effect / law)
};

inline std::string format_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

template <class T, int D>
class NosbPd {
  static_assert(D == 2 || D == 3, "NosbPd is 2D (plane strain) or 3D");

 public:
  static const std::vector<EffectSpec>& effects() {
    static const std::vector<EffectSpec> specs = {
        {"weighted_function", "W'_ij = beta V (1 - |xi|^2/delta^2) in place of V_ij (seed 003 eq. (2)): irregular layouts",
         {}, {}, "nothing (weights are evaluated per bond)"},
        {"velocity_viscosity", "zero-energy control by velocity viscosity (seed 003 eq. (3), c_v and omega_v)",
         {}, {"polymech::pd::velocity_viscosity_state"},
         "3D+2 reals per particle (mean velocity, horizon volume, force state, force, work)"},
        {"hourglass", "zero-energy control by a stabilising force state (Silling 2017)", {},
         {}, "D+1 reals per particle (force, work)"},
        {"damage", "bonds break above a critical stretch (or the one of a critical energy release rate)", {},
         {"polymech::pd::deformation_gradient_with_damage"}, "1 byte per bond, 1 real per particle"},
        {"contact", "rigid projectile (blunt cylinder or sphere) against the particles by penalty", {},
         {"polymech::contact::projectile_penalty"}, "D reals per particle (contact force)"},
        {"short_range", "short-range repulsion of close particles: fracture faces, fragments (Silling & Askari 2005)",
         {"damage"}, {"polymech::contact::pd_current_positions", "polymech::contact::pd_short_range"},
         "D+1 reals per particle and a Verlet list (radius d_s + skin) over the current positions"},
    };
    return specs;
  }

  explicit NosbPd(const Config& c)
      : cfg_(c),
        weighted_(c.effects.has("weighted_function")),
        viscosity_(c.effects.has("velocity_viscosity")),
        hourglass_(c.effects.has("hourglass")),
        damage_(c.effects.has("damage")),
        contact_(c.effects.has("contact")),
        short_range_(c.effects.has("short_range")),
        plastic_(c.material.law == Law::johnson_cook) {
    validate(c);
    set_constants();
    allocate(generate_particles(c));
    setup_constraints();
    if (contact_) setup_projectile();
    compute_forces();
    if (cfg_.dt <= 0.0) cfg_.dt = cfg_.dt_safety * stable_dt();
  }

  // Advance one step (velocity Verlet).
  void step() {
    const T dt = static_cast<T>(cfg_.dt), h = T(0.5) * dt, damping = static_cast<T>(cfg_.mass_damping);
    pd::kick(f_, h, damping);
    pd::drift(f_, dt);
    for (int k = 0; k < D; ++k) {
      proj_.velocity[k] += 0.5 * cfg_.dt * proj_.acceleration[k];
      proj_.position[k] += cfg_.dt * proj_.velocity[k];
    }
    work_dt_ = dt;
    compute_forces();
    work_dt_ = T(0);
    pd::kick(f_, h, damping);
    for (int k = 0; k < D; ++k) proj_.velocity[k] += 0.5 * cfg_.dt * proj_.acceleration[k];
    ++step_;
  }

  // Accelerations at the current displacements and velocities (forces of one step, without moving).
  void compute_forces() {
    pd::deformation_gradient(family_, f_, deformation_params_);
    if (plastic_) pd::stress_johnson_cook(f_, elastic_, jc_, static_cast<T>(cfg_.dt > 0 ? cfg_.dt : 1e-9), crush_);
    else pd::stress_elastic(f_, elastic_);
    if (viscosity_) pd::velocity_viscosity_state(f_, viscosity_params_);
    auto fp = force_params_;
    fp.work_dt = work_dt_;
    pd::bond_forces(family_, f_, fp, hourglass_, viscosity_);
    if (contact_) apply_projectile();
    if (short_range_) {
      contact::pd_current_positions(f_.x0, f_.u, positions_);
      verlet_->update(positions_);
      contact::pd_short_range(verlet_->list(), positions_, f_.volume, short_range_params_, f_.a);
    }
  }

  double time() const { return static_cast<double>(step_) * cfg_.dt; }
  std::int64_t step_index() const { return step_; }
  double dt() const { return cfg_.dt; }
  Index particles() const { return n_; }
  Offset bonds() const { return family_.num_pairs; }
  const Config& config() const { return cfg_; }
  const neighbors::BondFamily& family() const { return family_; }
  const pd::Fields<T, D>& fields() const { return f_; }
  double beta() const { return beta_; }
  double micromodulus() const { return micromodulus_; }
  double critical_stretch_value() const { return critical_stretch_; }
  const ProjectileState& projectile() const { return proj_; }
  int verlet_builds() const { return verlet_ ? verlet_->builds() : 0; }

  Energies energy() const {
    const auto e = pd::particle_energies(f_, elastic_, static_cast<T>(cfg_.material.density), plastic_);
    Energies out;
    out.kinetic = e.kinetic;
    out.strain = e.strain;
    out.plastic = e.plastic;
    out.viscous = e.viscous;
    out.hourglass = e.hourglass;
    for (int k = 0; k < D; ++k) out.momentum[k] = e.momentum[k] + proj_.mass * proj_.velocity[k];
    if (short_range_) {
      contact::pd_short_range_energy(verlet_->list(), positions_, f_.volume, short_range_params_, short_range_energy_);
      out.short_range = detail::scalar_sum("polymech::nosb_pd::short_range_energy", short_range_energy_);
    }
    if (contact_) {
      out.contact = detail::penalty_energy(contact_force_, static_cast<double>(penalty_));
      for (int k = 0; k < D; ++k) out.projectile_kinetic += 0.5 * proj_.mass * proj_.velocity[k] * proj_.velocity[k];
    }
    return out;
  }

  // How much of the bond deformation F does not see (zero-energy measure, pd/diagnostics.hpp), from
  // the F of the last force evaluation; interior_only: particles with a complete family only.
  pd::NonAffineMeasure nonaffine_deviation(bool interior_only = false) const {
    const auto bonds = lattice_family(D, cfg_.spacing, cfg_.horizon_ratio, false, 1.0).bonds;
    return pd::nonaffine_deviation(family_, f_, interior_only ? static_cast<Index>(bonds) : 0);
  }

  // Broken bonds (full list: each counted from both ends) and the largest damage.
  std::int64_t broken_bonds() const {
    if (!damage_) return 0;
    const auto intact = f_.bond_intact;
    std::int64_t broken = 0;
    Kokkos::parallel_reduce(
        "polymech::nosb_pd::broken_bonds", range(family_.num_pairs),
        KOKKOS_LAMBDA(const std::int64_t k, std::int64_t& b) { b += intact(k) ? 0 : 1; }, broken);
    return broken;
  }

  bool finite() const {
    int bad = 0;
    const auto u = f_.u, v = f_.v;
    Kokkos::parallel_reduce(
        "polymech::nosb_pd::finite_check", range(n_),
        KOKKOS_LAMBDA(const Index i, int& b) {
          for (int k = 0; k < D; ++k)
            if (!kx::isfinite(u(i, k)) || !kx::isfinite(v(i, k))) ++b;
        },
        bad);
    return bad == 0;
  }

  HostFields host_fields() const {
    HostFields h;
    auto vec = [&](const VecView<T, D>& v, std::vector<double>& out) {
      auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
      out.resize(static_cast<std::size_t>(D) * static_cast<std::size_t>(n_));
      for (Index i = 0; i < n_; ++i)
        for (int k = 0; k < D; ++k) out[static_cast<std::size_t>(D * i + k)] = static_cast<double>(m(i, k));
    };
    auto scalar = [&](const View1<T>& v, std::vector<double>& out) {
      if (v.extent(0) == 0) return;
      auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
      out.assign(m.data(), m.data() + n_);
    };
    vec(f_.x0, h.x0);
    vec(f_.u, h.u);
    vec(f_.v, h.v);
    scalar(f_.damage, h.damage);
    scalar(f_.eps_p, h.eps_p);
    scalar(f_.volume, h.volume);
    return h;
  }

  // Tension loading: pull the x = length grip at `velocity` (0: hold); measurements of the test.
  void set_grip_velocity(double velocity) {
    auto pv = Kokkos::create_mirror_view_and_copy(HostSpace(), f_.prescribed_v);
    auto g = Kokkos::create_mirror_view_and_copy(HostSpace(), group_);
    for (Index i = 0; i < n_; ++i)
      if (g(i) == 2) pv(i, 0) = static_cast<T>(velocity);
    Kokkos::deep_copy(f_.prescribed_v, pv);
  }
  detail::TensionMeasure tension_measure() const {
    const double L = cfg_.geometry.length;
    return detail::tension_measure(f_, group_, static_cast<T>(cfg_.material.density), static_cast<T>(L / 3),
                                   static_cast<T>(2 * L / 3));
  }
  double cross_section() const { return cross_section_; }

  // Largest eigenvalue of M^-1 K of the linearised elastic operator (with the hourglass force when
  // enabled), by power iteration on this model's particles. Leaves the state at rest.
  double max_eigenvalue(int iterations = 150) {
    const T eps = static_cast<T>(1e-9 * cfg_.spacing);
    const bool saved_damage = deformation_params_.damage, saved_mean = deformation_params_.mean_velocity;
    deformation_params_.damage = false;
    deformation_params_.mean_velocity = false;
    detail::random_displacement(f_, eps);
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
      pd::deformation_gradient(family_, f_, deformation_params_);
      pd::stress_elastic(f_, elastic_);
      pd::bond_forces(family_, f_, force_params_, hourglass_, false);
      lambda = detail::rayleigh_quotient(f_);
      detail::acceleration_as_displacement(f_, eps);
    }
    deformation_params_.damage = saved_damage;
    deformation_params_.mean_velocity = saved_mean;
    Kokkos::deep_copy(f_.u, T(0));
    Kokkos::deep_copy(f_.a, T(0));
    return lambda;
  }

  // Largest stable step of velocity Verlet for this discretisation, from a patch of the same layout,
  // spacing, horizon, material, weights and hourglass force: 2 / omega with omega^2 the patch's largest
  // eigenvalue plus the projectile penalty k / m and the short-range springs, and the velocity
  // viscosity's rate limit dt <= 1 / (4 c_v omega_v). Needs no model of the full size.
  //
  // The velocity viscosity (seed 003 eq. (3)) is a damping operator on the half-step velocities,
  // which velocity Verlet advances like forward Euler: stable while dt lambda <= 2 for its largest
  // rate lambda. For a velocity pattern with neighbour mean vbar = w v, eq. (3) gives
  // L^ZE = sum_j W (t_i - t_j) = -2 c_v omega_v rho (1 - w)^2 v, so lambda = 2 c_v omega_v (1 - w)^2,
  // largest (8 c_v omega_v) for w = -1: two particles whose only intact bond joins them (fragments,
  // a damaged rim). Intact lattices reach w ~ -0.3 only, which is why 1 / (2 c_v omega_v) sufficed
  // until bonds broke.
  static double stable_time_step(const Config& c) {
    Config patch = c;
    std::vector<std::string> pe;
    if (c.effects.has("weighted_function")) pe.push_back("weighted_function");
    if (c.effects.has("hourglass")) pe.push_back("hourglass");
    patch.effects = EffectSet::resolve(pe, effects());
    patch.geometry.shape = Shape::box;
    if (patch.geometry.layout == Layout::cylindrical) patch.geometry.layout = Layout::jittered;
    const double side = (2.0 * std::ceil(c.horizon_ratio) + 2.0) * c.spacing;  // the fastest modes are local
    patch.geometry.length = patch.geometry.width = patch.geometry.height = side;
    patch.loading = Loading::none;
    patch.material.law = Law::elastic;
    patch.dt = 1.0;  // not used
    NosbPd<double, D> m(patch);
    double omega2 = m.max_eigenvalue();
    const double V = std::pow(c.spacing, D);
    if (c.effects.has("contact"))  // a quarter of a lattice cell: the smallest particle of the layouts
      omega2 += c.contact.penalty * c.material.youngs_modulus * c.spacing / (c.material.density * 0.25 * V);
    if (c.effects.has("short_range"))  // up to 12 touching neighbours, each a spring c_s V / d_s
      omega2 += 12.0 * c.contact.short_range_factor * m.micromodulus() * V /
                (c.contact.short_range_distance * c.spacing * c.material.density);
    double dt = 2.0 / std::sqrt(omega2);
    if (c.effects.has("velocity_viscosity") && c.stabilization.omega_v > 0 && c.stabilization.c_v > 0)
      dt = std::min(dt, 1.0 / (4.0 * c.stabilization.c_v * c.stabilization.omega_v));
    return dt;
  }
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
    if (c.loading == Loading::impact && !c.effects.has("contact")) fail("impact loading needs the contact effect");
    if (c.loading == Loading::tension && g.shape == Shape::disc) fail("tension loading needs a box or round bar");
    if (!(c.dt >= 0) || !(c.mass_damping >= 0) || !(c.dt_safety > 0 && c.dt_safety <= 1)) fail("time settings out of range");
  }

  void set_constants() {
    const Config& c = cfg_;
    const double delta = c.horizon();
    beta_ = weighted_ ? weighted_function_beta(D, c.horizon_ratio) : 1.0;
    const LatticeFamily lf = lattice_family(D, c.spacing, c.horizon_ratio, weighted_, beta_);
    // bond-based micromodulus c = 18 K / sum_j |xi| W_ij (3D; 2D plane strain: 2 (lambda + mu) ... with
    // the 2D bulk modulus of plane strain, K_2D = lambda + mu, c = 8 K_2D / sum |xi| W)
    const double K = D == 3 ? c.material.bulk() : c.material.lambda() + c.material.mu();
    micromodulus_ = (D == 3 ? 18.0 : 8.0) * K / lf.length_weighted;
    critical_stretch_ = damage_ ? critical_stretch(c) : 0.0;
    elastic_.lambda = static_cast<T>(c.material.lambda());
    elastic_.mu = static_cast<T>(c.material.mu());
    const auto& m = c.material;
    jc_.A = static_cast<T>(m.jc_a);
    jc_.B = static_cast<T>(m.jc_b);
    jc_.n = static_cast<T>(m.jc_n);
    jc_.C = static_cast<T>(m.jc_c);
    jc_.rate0 = static_cast<T>(m.jc_reference_rate);
    jc_.m = static_cast<T>(m.jc_m);
    jc_.T_room = static_cast<T>(m.room_temperature);
    jc_.T_melt = static_cast<T>(m.melting_temperature);
    jc_.rho_cp = static_cast<T>(m.density * m.specific_heat);
    jc_.chi = static_cast<T>(m.taylor_quinney);
    if (damage_) crush_.j_min = static_cast<T>(c.damage.crush_volume_ratio);
    pd::BondWeight<T> w;
    w.delta2 = static_cast<T>(delta * delta);
    w.beta = static_cast<T>(beta_);
    w.weighted = weighted_;
    weight_ = w;
    deformation_params_.damage = damage_;
    deformation_params_.critical_stretch = static_cast<T>(critical_stretch_);
    if (damage_) deformation_params_.min_shape_quality = static_cast<T>(c.damage.min_shape_quality);
    deformation_params_.rate = plastic_;
    deformation_params_.mean_velocity = viscosity_;
    force_params_.density = static_cast<T>(m.density);
    force_params_.damage = damage_;
    force_params_.hourglass_c = static_cast<T>(hourglass_ ? c.stabilization.hourglass * micromodulus_ : 0.0);
    viscosity_params_.c_v = static_cast<T>(c.stabilization.c_v);
    viscosity_params_.omega_v = static_cast<T>(c.stabilization.omega_v);
    viscosity_params_.density = static_cast<T>(m.density);
    penalty_ = static_cast<T>(c.contact.penalty * m.youngs_modulus * c.spacing);
    short_range_params_.distance = static_cast<T>(c.contact.short_range_distance * c.spacing);
    short_range_params_.coefficient = static_cast<T>(c.contact.short_range_factor * micromodulus_);
    short_range_params_.density = static_cast<T>(m.density);
  }

  void allocate(const Particles& p) {
    n_ = static_cast<Index>(p.size());
    const auto n = static_cast<std::size_t>(n_);
    const std::string pre = "polymech::nosb_pd::";
    f_.x0 = VecView<T, D>(pre + "x0", n);
    f_.volume = View1<T>(pre + "volume", n);
    f_.u = VecView<T, D>(pre + "u", n);
    f_.v = VecView<T, D>(pre + "v", n);
    f_.a = VecView<T, D>(pre + "a", n);
    f_.kinv = pd::MatView<T, D>(pre + "kinv", n);
    f_.F = pd::MatView<T, D>(pre + "F", n);
    f_.A = pd::MatView<T, D>(pre + "A", n);
    f_.status = Kokkos::View<std::uint8_t*, MemSpace>(pre + "status", n);
    if (plastic_) {
      f_.Fdot = pd::MatView<T, D>(pre + "plastic_Fdot", n);
      f_.sigma = pd::SymView<T>(pre + "plastic_sigma", n);
      f_.eps_p = View1<T>(pre + "plastic_eps_p", n);
      f_.temperature = View1<T>(pre + "plastic_temperature", n);
      f_.plastic_work = View1<T>(pre + "plastic_work", n);
      Kokkos::deep_copy(f_.temperature, static_cast<T>(cfg_.material.room_temperature));
    }
    {
      auto hx = Kokkos::create_mirror_view(f_.x0);
      auto hv = Kokkos::create_mirror_view(f_.volume);
      for (std::size_t i = 0; i < n; ++i) {
        for (int k = 0; k < D; ++k) hx(i, k) = static_cast<T>(p.coord(i, k));
        hv(i) = static_cast<T>(p.volume[i]);
      }
      Kokkos::deep_copy(f_.x0, hx);
      Kokkos::deep_copy(f_.volume, hv);
    }
    // Reference family (seed 003 §3(1): the particles within the horizon delta of x_i), slightly
    // enlarged so that round-off never drops a lattice bond at exactly delta.
    family_ = neighbors::build_bond_family<T, D>(f_.x0, static_cast<T>(cfg_.horizon() * (1 + 1e-6)));
    f_.bond_weight = View1<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, pre + "bond_weight"), static_cast<std::size_t>(family_.num_pairs));
    pd::bond_weights(family_, f_.x0, f_.volume, weight_, f_.bond_weight);
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
    if (contact_) contact_force_ = VecView<T, D>(pre + "contact_force", n);
    if (short_range_) {
      positions_ = VecView<T, D>(pre + "short_range_positions", n);
      short_range_energy_ = View1<T>(pre + "short_range_energy", n);
      verlet_ = std::make_unique<neighbors::VerletList<T, D>>(short_range_params_.distance,
                                                             static_cast<T>(cfg_.contact.skin * cfg_.spacing),
                                                             neighbors::ListKind::full);
    }
  }

  void setup_constraints() {
    const Config& c = cfg_;
    if (c.loading == Loading::none) return;
    if (c.loading == Loading::impact && !(c.clamp_radius > 0)) return;
    const std::string pre = "polymech::nosb_pd::";
    f_.constraint = Kokkos::View<std::uint8_t*, MemSpace>(pre + "constraint", static_cast<std::size_t>(n_));
    f_.prescribed_v = VecView<T, D>(pre + "prescribed_v", static_cast<std::size_t>(n_));
    auto hc = Kokkos::create_mirror_view(f_.constraint);
    auto hx = Kokkos::create_mirror_view_and_copy(HostSpace(), f_.x0);
    Kokkos::deep_copy(hc, std::uint8_t(0));
    if (c.loading == Loading::tension) {
      group_ = Kokkos::View<std::uint8_t*, MemSpace>(pre + "tension_group", static_cast<std::size_t>(n_));
      auto hg = Kokkos::create_mirror_view(group_);
      const double delta = c.horizon(), L = c.geometry.length;
      for (Index i = 0; i < n_; ++i) {
        const double x = static_cast<double>(hx(i, 0));
        hg(i) = x < delta ? 1 : (x > L - delta ? 2 : 0);
        hc(i) = hg(i) ? 1 : 0;  // the grips hold / pull x only: free lateral contraction
      }
      Kokkos::deep_copy(group_, hg);
      cross_section_ = c.geometry.shape == Shape::round_bar ? cross_section_of_bar(hx)
                                                           : (D == 3 ? c.geometry.width * c.geometry.height : c.geometry.height);
    } else {
      for (Index i = 0; i < n_; ++i) {
        double r2 = 0;
        for (int k = 0; k < D - 1; ++k) r2 += static_cast<double>(hx(i, k)) * static_cast<double>(hx(i, k));
        if (r2 > c.clamp_radius * c.clamp_radius) hc(i) = pd::constrain_all;
      }
    }
    Kokkos::deep_copy(f_.constraint, hc);
  }

  // Volume of one x-slab of the round bar / its thickness: the particles' cross-section.
  template <class HostX>
  double cross_section_of_bar(const HostX&) const {
    auto hv = Kokkos::create_mirror_view_and_copy(HostSpace(), f_.volume);
    double vol = 0;
    for (Index i = 0; i < n_; ++i) vol += static_cast<double>(hv(i));
    return vol / cfg_.geometry.length;
  }

  void setup_projectile() {
    const auto& p = cfg_.projectile;
    proj_.mass = p.mass;
    // nose (cylinder) or lowest point (sphere) `standoff` above the plate top (z = 0 / y = 0)
    proj_.position[D - 1] = p.standoff + (p.shape == ProjectileShape::sphere ? p.radius : 0.0);
    proj_.velocity[D - 1] = -p.velocity;
  }

  void apply_projectile() {
    contact::RigidProjectile<T, D> q;
    q.shape = cfg_.projectile.shape == ProjectileShape::sphere ? contact::ProjectileShape::sphere
                                                               : contact::ProjectileShape::blunt_cylinder;
    q.radius = static_cast<T>(cfg_.projectile.radius);
    q.length = static_cast<T>(cfg_.projectile.length);
    for (int k = 0; k < D; ++k) q.position[k] = static_cast<T>(proj_.position[k]);
    contact::projectile_penalty(q, penalty_, static_cast<T>(cfg_.contact.contact_radius * cfg_.spacing), f_.x0, f_.u,
                                f_.volume, static_cast<T>(cfg_.material.density), contact_force_, f_.a);
    const auto s = detail::vector_sum("polymech::nosb_pd::projectile_reaction", contact_force_);
    for (int k = 0; k < D; ++k) {
      proj_.reaction[k] = -s[k];
      proj_.acceleration[k] = -s[k] / proj_.mass;
    }
  }

  Config cfg_;
  bool weighted_, viscosity_, hourglass_, damage_, contact_, short_range_, plastic_;
  Index n_ = 0;
  double beta_ = 1.0, micromodulus_ = 0.0, critical_stretch_ = 0.0, stable_dt_ = 0.0, cross_section_ = 0.0;
  pd::Fields<T, D> f_;
  neighbors::BondFamily family_;
  pd::ElasticConstants<T> elastic_;
  pd::JohnsonCook<T> jc_;
  pd::CrushLimits<T> crush_;
  pd::BondWeight<T> weight_;
  pd::DeformationParams<T> deformation_params_;
  pd::ForceParams<T> force_params_;
  pd::ViscosityParams<T> viscosity_params_;
  contact::ShortRangeParams<T> short_range_params_;
  T penalty_ = T(0), work_dt_ = T(0);
  VecView<T, D> contact_force_, positions_;
  View1<T> short_range_energy_;
  std::unique_ptr<neighbors::VerletList<T, D>> verlet_;
  Kokkos::View<std::uint8_t*, MemSpace> group_;
  ProjectileState proj_;
  std::int64_t step_ = 0;
};

}  // namespace polymech::nosb_pd
