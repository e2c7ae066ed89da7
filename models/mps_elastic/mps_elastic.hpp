// MPS elastic-wave model in 2D plane strain (seed 000 §2-3, §5.1): owns the particle Views, builds
// its step from the enabled effects and exposes diagnostics (energy, probes, fields).
//
//   polymech::mps_elastic::Config cfg;            // or io::load_mps_elastic_scene(...)
//   cfg.effects = EffectSet::resolve({"rotation"}, mps_elastic::effect_table());
//   MpsElastic<double> model(cfg);
//   while (model.step_index() < cfg.steps) model.step();
//
// Effects: `rotation` (relative displacement with particle rotation, eqs. (6)-(7), and the rotation
// equation (12), (15)-(16)). Without it the model solves rho dv/dt = C13 grad div u + 2 C55 lap u
// with no rotation correction: S waves then travel at sqrt(2) cs (tests/mps/test_mps_wave_speeds.cpp).
// `crack_contact.open_close` and `crack_contact.slip`: contact between the faces of Config::crack
// (seed 000 §4, models/mps_elastic/crack.hpp).
//
// A step (models/common/explicit_model.hpp; symplectic Euler, eqs. (13)-(16)): compute_forces (volumetric
// strain eq. (4), accelerations eqs. (11)-(12), the crack-line monitor), observe (probes), add_contact_forces
// (crack faces, eqs. (17)-(21)), advance_second_half (integration, then the prescribed excitation).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/clock.hpp"
#include "common/explicit_model.hpp"
#include "common/host_copy.hpp"
#include "common/particle_health.hpp"
#include "common/run.hpp"
#include "common/stability.hpp"
#include "mps/elastic.hpp"
#include "mps/excitation.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/crack.hpp"
#include "mps_elastic/effect_table.hpp"
#include "mps_elastic/lattice.hpp"
#include "mps_elastic/probe_recorder.hpp"
#include "neighbors/neighbor_search.hpp"
#include "particles/integrators.hpp"
#include "particles/reductions.hpp"

namespace polymech::mps_elastic {

// Fractions of the crack's contact pairs in each state over time (seed 000 §4).
struct ContactHistory {
  std::vector<double> times, separation, stick, slip;
};

// Fields copied to the host for output, row-major N x 2 for vectors.
struct HostFields {
  std::vector<double> x0, u, v, e, theta;
};

// The degrees of freedom of the power iteration (models/common/stability.hpp): u1, u3 with the
// particle mass and, with rotation, theta with the moment of inertia.
template <class T, bool Rotation>
struct ElasticDofs {
  static constexpr int slots = Rotation ? 3 : 2;
  mps::ElasticFields<T> f;
  T mass, inertia, l0;
  KOKKOS_INLINE_FUNCTION T& state(Index i, int s) const { return s < 2 ? f.u(i, s) : f.theta(i); }
  KOKKOS_INLINE_FUNCTION T response(Index i, int s) const { return s < 2 ? f.a(i, s) : f.alpha(i); }
  KOKKOS_INLINE_FUNCTION double weight(Index, int s) const { return double(s < 2 ? mass : inertia); }
  KOKKOS_INLINE_FUNCTION T start_divisor(int s) const { return s < 2 ? T(1) : l0; }  // theta ~ u / l0
};

template <class T>
class MpsElastic {
 public:
  static constexpr int dimension = 2;

  static const std::vector<EffectSpec>& effects() { return effect_table(); }

  explicit MpsElastic(const Config& c) : cfg_(c), rotation_(c.effects.has("rotation")) {
    validate(c);
    const Lattice lat = make_lattice(c);
    n_ = lat.count();
    params_.re = static_cast<T>(c.re());
    params_.rho = static_cast<T>(c.density);
    params_.c13 = static_cast<T>(c.c13);
    params_.c55 = static_cast<T>(c.c55);
    params_.mass = static_cast<T>(c.density * c.spacing * c.spacing);
    params_.inertia = static_cast<T>(c.inertia_factor * c.density * c.spacing * c.spacing * c.spacing * c.spacing);

    const std::string pre = "polymech::mps_elastic::";
    particles::allocate(f_, n_, pre);
    f_.e = View1<T>(pre + "e", n_);
    if (rotation_) {
      f_.theta = View1<T>(pre + "rotation_theta", n_);
      f_.omega = View1<T>(pre + "rotation_omega", n_);
      f_.alpha = View1<T>(pre + "rotation_alpha", n_);
      f_.sin_theta = View1<T>(pre + "rotation_sin_theta", n_);
      f_.half_omc = View1<T>(pre + "rotation_half_omc", n_);
    }
    particles::set_reference_positions(f_, [&](Index i, int k) { return k == 0 ? lat.x1(i) : lat.x3(i); });
    // Reference-configuration family; r_e slightly enlarged so round-off never drops a pair whose
    // weight would be (nearly) zero anyway.
    family_ = neighbors::build_bond_family<T, 2>(f_.x0, params_.re * T(1 + 1e-6));
    {
      // n0 of the uncut body: the crack changes which particles interact, not the reference density
      View1<T> n_i("polymech::mps_elastic::number_density", n_);
      mps::number_density<T, 2>(family_, f_.x0, params_.re, n_i);
      n0_ = c.number_density == NumberDensityReference::mean
                ? static_cast<double>(mps::mean_number_density(n_i))
                : mps::lattice_number_density(2, c.spacing, c.re());
      if (c.n0_override > 0.0) n0_ = c.n0_override;
      params_.n0 = static_cast<T>(n0_);
    }
    crack_ = CrackFaces<T>(c, family_, c.density * c.spacing * c.spacing, c.dt);
    if (c.crack.mode == CrackMode::cut) family_ = crack_.cut(family_);  // seed 000 §4: no operator across
    f_.inv_r0 = View1<T>(pre + "inv_r0", family_.num_pairs);
    mps::reference_bond_lengths(family_, f_);

    setup_excitation(lat);
    probes_ = ProbeRecorder<T>(cfg_, lat);
    register_state();
    if (!c.allow_unstable_dt && c.dt > stable_dt())
      throw std::invalid_argument("mps_elastic: dt = " + models::format_g(c.dt) + " s is above the stability limit " +
                                  models::format_g(stable_dt_) + " s of this resolution (spacing " +
                                  models::format_g(c.spacing) + " m)");
  }

  // One time step (seed 000 eqs. (11)-(16)), in the phases of models/common/explicit_model.hpp.
  void step() { models::explicit_step(*this); }

  // Symplectic Euler needs no forces of the initial state.
  void prepare() {}
  void mark_prepared() {}
  void advance_first_half() {}
  void compute_forces() {
    if (rotation_) {
      mps::volumetric_strain<T, true>(family_, f_, params_);
      mps::elastic_acceleration<T, true>(family_, f_, params_);
      crack_.template monitor<true>(f_, params_);
    } else {
      mps::volumetric_strain<T, false>(family_, f_, params_);
      mps::elastic_acceleration<T, false>(family_, f_, params_);
      crack_.template monitor<false>(f_, params_);
    }
  }
  // Probes and crack-state fractions at this step's state (u and e of step k, time t_k).
  void observe() {
    if (probes_.count() > 0 && clock_.index() % cfg_.probe_every == 0) sample();
  }
  void add_contact_forces() { crack_.add_contact_forces(f_); }
  void advance_second_half() {
    const T dt = static_cast<T>(cfg_.dt);
    particles::symplectic_euler(f_, dt);  // eqs. (13)-(14)
    if (rotation_) mps::rotation_update(f_, dt);  // eqs. (15)-(16)
    clock_.tick();
    const double t = time();
    if (excitation_on_ && pulse_.active(t)) {
      const double u_old = pulse_.displacement(t - cfg_.dt);
      mps::prescribe_displacement<T>(sources_, f_.u, f_.v, pulse_.component, pulse_.displacement(t), u_old, cfg_.dt);
    }
  }

  double dt() const { return cfg_.dt; }
  double time() const { return clock_.time(cfg_.dt); }
  // Time at which the prescribed excitation ends (0 without one); afterwards the system is free.
  double excitation_end_time() const { return excitation_on_ ? pulse_.duration() : 0.0; }
  std::int64_t step_index() const { return clock_.index(); }
  void set_step_index(std::int64_t k) { clock_.set_index(k); }
  Index particles() const { return n_; }
  Offset bonds() const { return family_.num_pairs; }
  double n0() const { return n0_; }
  const Config& config() const { return cfg_; }
  bool has_rotation() const { return rotation_; }
  double cp_analytic() const { return std::sqrt((cfg_.c13 + 2.0 * cfg_.c55) / cfg_.density); }
  double cs_analytic() const { return std::sqrt(cfg_.c55 / cfg_.density); }
  const neighbors::BondFamily& family() const { return family_; }
  const mps::ElasticFields<T>& fields() const { return f_; }
  const mps::ElasticParams<T>& params() const { return params_; }
  Index source_count() const { return static_cast<Index>(sources_.extent(0)); }
  const CrackFaces<T>& crack() const { return crack_; }
  // Fractions of crack pairs in separation / stick / slip at the probe samples (contact effects only).
  const ContactHistory& contact_history() const { return contact_history_; }
  const models::StateRegistry& state() const { return state_; }

  // The complete state for a checkpoint (fields, crack contact states, step, probe and contact
  // histories), and back: the run continues bit for bit (models/common/run.hpp).
  void save(models::Archive& a, const std::string& prefix) {
    state_.save(a, prefix + "state/");
    clock_.save(a, prefix);
    probes_.save(a, prefix + "probes/");
    const std::vector<std::vector<double>> h = {contact_history_.times, contact_history_.separation, contact_history_.stick,
                                                contact_history_.slip};
    a.put_columns(prefix + "contact_history", h);
  }
  void load(const models::Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    clock_.restore(a, prefix);
    probes_.load(a, prefix + "probes/");
    const auto h = a.get_columns<double>(prefix + "contact_history");
    if (h.size() != 4) throw std::runtime_error("checkpoint: contact_history needs 4 columns");
    contact_history_ = {h[0], h[1], h[2], h[3]};
  }

  // Kinetic and strain energy now. The strain term uses e from the start of the last step.
  mps::ElasticEnergy energy() const {
    return rotation_ ? mps::elastic_energy<T, true>(family_, f_, params_)
                     : mps::elastic_energy<T, false>(family_, f_, params_);
  }

  // The watchdog's check: the first particle whose displacement or velocity is NaN or infinite, or
  // whose displacement is more than half a spacing (elastic waves are small-displacement motion: an
  // unstable lattice flies apart, its interactions vanish and its energy stays finite).
  models::Health health() const {
    return models::particle_health(f_, static_cast<T>(0.5 * cfg_.spacing), "half a spacing: the lattice is torn apart");
  }
  bool finite() const { return health().finite; }

  // Probe time series so far (copies pending samples from the device).
  const ProbeHistory& probes() { return probes_.history(); }

  HostFields host_fields() const {
    HostFields h;
    h.x0 = models::to_host(f_.x0);
    h.u = models::to_host(f_.u);
    h.v = models::to_host(f_.v);
    h.e = models::to_host(f_.e);
    h.theta = models::to_host(f_.theta);
    return h;
  }

  // Largest stable dt of symplectic Euler for this discretisation: 2 / omega_max, with omega_max^2
  // the largest eigenvalue of M^-1 K estimated by power iteration on a small patch of the same
  // lattice (same l0, r_e, n0, material, effects, with free edges and corners).
  static double stable_time_step(const Config& c, int iterations = 400) {
    Config patch = c;
    patch.width = patch.height = 16 * c.spacing;
    patch.excitation.kind = ExcitationKind::none;
    patch.probes.clear();
    // the elastic operator alone: the contact springs have their own bound (k' < 2, CrackFaces)
    patch.crack = CrackConfig{};
    patch.effects = EffectSet::resolve(c.effects.has("rotation") ? std::vector<std::string>{"rotation"}
                                                                 : std::vector<std::string>{},
                                       effects());
    patch.allow_unstable_dt = true;
    patch.n0_override = c.n0_override > 0.0 ? c.n0_override : reference_number_density(c);
    MpsElastic<double> m(patch);
    return models::leapfrog_stable_step(m.max_eigenvalue(iterations));
  }

  // n0 the full model uses, computed from the lattice alone (no particles allocated).
  static double reference_number_density(const Config& c) {
    if (c.number_density == NumberDensityReference::interior) return mps::lattice_number_density(2, c.spacing, c.re());
    const Lattice lat = make_lattice(c);
    return lattice_mean_number_density(lat, c.re());
  }

  // Power iteration for the largest eigenvalue of M^-1 K, the linearised operator of this model.
  // Leaves the state at rest.
  double max_eigenvalue(int iterations) {
    const double lambda = rotation_ ? max_eigenvalue_of<true>(iterations) : max_eigenvalue_of<false>(iterations);
    reset_state();
    return lambda;
  }

  // The stable dt of this configuration (computed once, on first use).
  double stable_dt() {
    if (stable_dt_ <= 0.0) stable_dt_ = stable_time_step(cfg_);
    return stable_dt_;
  }

 private:
  static void validate(const Config& c) {
    auto fail = [](const std::string& m) { throw std::invalid_argument("mps_elastic: " + m); };
    if (!(c.spacing > 0)) fail("spacing must be > 0");
    if (!(c.width >= c.spacing) || !(c.height >= c.spacing)) fail("the domain must be at least one spacing wide");
    if (!(c.influence_radius >= 1.0)) fail("influence radius must be >= 1 spacing");
    if (!(c.dt > 0)) fail("dt must be > 0");
    if (!(c.density > 0) || !(c.c55 > 0) || !(c.c13 + c.c55 > 0)) fail("material constants out of range");
    if (!(c.inertia_factor > 0)) fail("inertia factor must be > 0");
    if (c.probe_every < 1) fail("probe_every must be >= 1");
    if (!(c.n0_override >= 0.0)) fail("n0 override must be >= 0");
  }

  // What a step reads that it did not compute: u, v (and theta, omega with rotation; sin theta and
  // (1 - cos theta)/2 follow theta), the crack's contact state and the crack-line monitor.
  void register_state() {
    state_.add("u", f_.u);
    state_.add("v", f_.v);
    state_.add("rotation_theta", f_.theta);
    state_.add("rotation_omega", f_.omega);
    state_.add("rotation_sin_theta", f_.sin_theta);
    state_.add("rotation_half_omc", f_.half_omc);
    crack_.register_state(state_);
  }

  template <bool Rotation>
  double max_eigenvalue_of(int iterations) {
    const T eps = static_cast<T>(1e-9 * cfg_.spacing);  // small enough that the operator is linear
    const ElasticDofs<T, Rotation> dofs{f_, params_.mass, params_.inertia, static_cast<T>(cfg_.spacing)};
    auto apply = [&] {
      if (Rotation) mps::rotation_trigonometry(f_);
      mps::volumetric_strain<T, Rotation>(family_, f_, params_);
      mps::elastic_acceleration<T, Rotation>(family_, f_, params_);
    };
    return models::largest_eigenvalue(dofs, n_, apply, eps, iterations, particles::StartVector{3, 1u, 1u});
  }

  void setup_excitation(const Lattice& lat) {
    const auto& ex = cfg_.excitation;
    excitation_on_ = ex.kind != ExcitationKind::none;
    if (!excitation_on_) return;
    pulse_.amplitude = ex.amplitude;
    pulse_.period = ex.period;
    pulse_.cycles = ex.cycles;
    pulse_.shape = ex.kind == ExcitationKind::point ? mps::PulseShape::hann : mps::PulseShape::sine;
    pulse_.component = ex.kind == ExcitationKind::plane_s ? 0 : 1;
    const std::vector<Index> src = source_particles(cfg_, lat);
    sources_ = View1<Index>("polymech::mps_elastic::sources", src.size());
    auto h = Kokkos::create_mirror_view(sources_);
    for (std::size_t k = 0; k < src.size(); ++k) h(k) = src[k];
    Kokkos::deep_copy(sources_, h);
  }

  void sample() {
    if (rotation_)
      probes_.template sample<true>(family_, f_, params_, time());
    else
      probes_.template sample<false>(family_, f_, params_, time());
    if (crack_.contact()) {
      const auto n = crack_.counts();
      const double total = static_cast<double>(crack_.pair_count());
      contact_history_.times.push_back(time());
      contact_history_.separation.push_back(static_cast<double>(n.separation) / total);
      contact_history_.stick.push_back(static_cast<double>(n.stick) / total);
      contact_history_.slip.push_back(static_cast<double>(n.slip) / total);
    }
  }

  void reset_state() {
    Kokkos::deep_copy(f_.u, T(0));
    Kokkos::deep_copy(f_.v, T(0));
    Kokkos::deep_copy(f_.a, T(0));
    Kokkos::deep_copy(f_.e, T(0));
    if (rotation_) {
      Kokkos::deep_copy(f_.theta, T(0));
      Kokkos::deep_copy(f_.omega, T(0));
      Kokkos::deep_copy(f_.alpha, T(0));
      Kokkos::deep_copy(f_.sin_theta, T(0));
      Kokkos::deep_copy(f_.half_omc, T(0));
    }
  }

  Config cfg_;
  bool rotation_;
  double stable_dt_ = 0.0;
  Index n_ = 0;
  double n0_ = 0.0;
  mps::ElasticParams<T> params_{};
  mps::ElasticFields<T> f_;
  neighbors::BondFamily family_;
  models::StepClock clock_;  // step index and time (models/common/clock.hpp)
  // excitation
  bool excitation_on_ = false;
  mps::Pulse pulse_;
  View1<Index> sources_;
  ProbeRecorder<T> probes_;
  // crack
  CrackFaces<T> crack_;
  ContactHistory contact_history_;
  models::StateRegistry state_;
};

}  // namespace polymech::mps_elastic
