// MPS elastic-wave model in 2D plane strain (seed 000 §2-3, §5.1): owns the particle Views, builds
// its step from the enabled effects and exposes diagnostics (energy, probes, fields).
//
//   polymech::mps_elastic::Config cfg;            // or io::load_mps_elastic_scene(...)
//   cfg.effects = EffectSet::resolve({"rotation"}, MpsElastic<double>::effects());
//   MpsElastic<double> model(cfg);
//   while (model.step_index() < cfg.steps) model.step();
//
// Effects: `rotation` (relative displacement with particle rotation, eqs. (6)-(7), and the rotation
// equation (12), (15)-(16)). Without it the model solves rho dv/dt = C13 grad div u + 2 C55 lap u
// with no rotation correction: S waves then travel at sqrt(2) cs (tests/mps/test_mps_wave_speeds.cpp).
// `crack_contact.open_close` and `crack_contact.slip`: contact between the faces of Config::crack
// (seed 000 §4, models/mps_elastic/crack.hpp).
#pragma once

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "mps/elastic.hpp"
#include "mps/excitation.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/crack.hpp"
#include "mps_elastic/lattice.hpp"
#include "mps_elastic/power_iteration.hpp"
#include "mps_elastic/probe_recorder.hpp"
#include "neighbors/neighbor_search.hpp"

namespace polymech::mps_elastic {

inline std::string format_g(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", x);
  return buf;
}

// Fractions of the crack's contact pairs in each state over time (seed 000 §4).
struct ContactHistory {
  std::vector<double> times, separation, stick, slip;
};

// Fields copied to the host for output, row-major N x 2 for vectors.
struct HostFields {
  std::vector<double> x0, u, v, e, theta;
};


template <class T>
class MpsElastic {
 public:
  static const std::vector<EffectSpec>& effects() {
    static const std::vector<EffectSpec> specs = {
        {"rotation",
         "relative displacement with particle rotation (seed 000 eqs. (6)-(7)) and the rotation equation (12)",
         {},
         {"polymech::mps::volumetric_strain_with_rotation", "polymech::mps::elastic_acceleration_with_rotation",
          "polymech::mps::rotation_update"},
         "5 reals per particle (theta, omega, alpha, sin theta, (1 - cos theta)/2)"},
        {"crack_contact.open_close",
         "crack faces open and close: penalty repulsion between S+ and S- pairs (seed 000 eqs. (17)-(19))",
         {},
         {"polymech::contact::crack_open_close", "polymech::contact::crack_apply_forces"},
         "per crack pair: state (1 int) and force (2 reals)"},
        {"crack_contact.slip",
         "crack faces stick and slip: Coulomb friction with a fixed or contact normal force (seed 000 eqs. (20)-(21))",
         {},
         {"polymech::contact::crack_slip", "polymech::contact::crack_apply_forces"},
         "per crack pair: state, force, anchor (2 reals), preload, slip sign; + normal force with open_close"},
    };
    return specs;
  }

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

    f_.x0 = VecView<T, 2>("polymech::mps_elastic::x0", n_);
    f_.u = VecView<T, 2>("polymech::mps_elastic::u", n_);
    f_.v = VecView<T, 2>("polymech::mps_elastic::v", n_);
    f_.a = VecView<T, 2>("polymech::mps_elastic::a", n_);
    f_.e = View1<T>("polymech::mps_elastic::e", n_);
    if (rotation_) {
      f_.theta = View1<T>("polymech::mps_elastic::rotation_theta", n_);
      f_.omega = View1<T>("polymech::mps_elastic::rotation_omega", n_);
      f_.alpha = View1<T>("polymech::mps_elastic::rotation_alpha", n_);
      f_.sin_theta = View1<T>("polymech::mps_elastic::rotation_sin_theta", n_);
      f_.half_omc = View1<T>("polymech::mps_elastic::rotation_half_omc", n_);
    }
    {
      auto h = Kokkos::create_mirror_view(f_.x0);
      for (Index i = 0; i < n_; ++i) {
        h(i, 0) = static_cast<T>(lat.x1(i));
        h(i, 1) = static_cast<T>(lat.x3(i));
      }
      Kokkos::deep_copy(f_.x0, h);
    }
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
    crack_ = CrackFaces<T>(c.crack, c.effects, f_.x0, family_, c.spacing, c.density * c.spacing * c.spacing, c.dt);
    if (c.crack.mode == CrackMode::cut) family_ = crack_.cut(family_, f_.x0);  // seed 000 §4: no operator across
    f_.inv_r0 = View1<T>("polymech::mps_elastic::inv_r0", family_.num_pairs);
    mps::reference_bond_lengths(family_, f_);

    setup_excitation(lat);
    probes_ = ProbeRecorder<T>(cfg_, lat);
    if (!c.allow_unstable_dt && c.dt > stable_dt())
      throw std::invalid_argument("mps_elastic: dt = " + format_g(c.dt) + " s is above the stability limit " +
                                  format_g(stable_dt_) + " s of this resolution (spacing " + format_g(c.spacing) +
                                  " m)");
  }

  // Advance one time step (seed 000 eqs. (11)-(16)).
  void step() {
    if (rotation_) {
      mps::volumetric_strain<T, true>(family_, f_, params_);
      if (sample_due()) sample();
      mps::elastic_acceleration<T, true>(family_, f_, params_);
      crack_.template monitor<true>(f_, params_);
    } else {
      mps::volumetric_strain<T, false>(family_, f_, params_);
      if (sample_due()) sample();
      mps::elastic_acceleration<T, false>(family_, f_, params_);
      crack_.template monitor<false>(f_, params_);
    }
    crack_.add_contact_forces(f_);
    const T dt = static_cast<T>(cfg_.dt);
    mps::symplectic_euler(f_, dt);
    if (rotation_) mps::rotation_update(f_, dt);
    ++step_;
    const double t = time();
    if (excitation_on_ && pulse_.active(t)) {
      const double u_old = pulse_.displacement(t - cfg_.dt);
      mps::prescribe_displacement<T>(sources_, f_.u, f_.v, pulse_.component, pulse_.displacement(t), u_old, cfg_.dt);
    }
  }

  double time() const { return static_cast<double>(step_) * cfg_.dt; }
  // Time at which the prescribed excitation ends (0 without one); afterwards the system is free.
  double excitation_end_time() const { return excitation_on_ ? pulse_.duration() : 0.0; }
  std::int64_t step_index() const { return step_; }
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

  // Kinetic and strain energy now. The strain term uses e from the start of the last step.
  mps::ElasticEnergy energy() const {
    return rotation_ ? mps::elastic_energy<T, true>(family_, f_, params_)
                     : mps::elastic_energy<T, false>(family_, f_, params_);
  }

  // False once any displacement or velocity is NaN or infinite.
  bool finite() const {
    int bad = 0;
    const auto u = f_.u, v = f_.v;
    Kokkos::parallel_reduce(
        "polymech::mps_elastic::finite_check", range(n_),
        KOKKOS_LAMBDA(const Index i, int& b) {
          for (int k = 0; k < 2; ++k)
            if (!kx::isfinite(u(i, k)) || !kx::isfinite(v(i, k))) ++b;
        },
        bad);
    return bad == 0;
  }

  // Probe time series so far (copies pending samples from the device).
  const ProbeHistory& probes() { return probes_.history(); }

  HostFields host_fields() const {
    HostFields h;
    auto copy_vec = [&](const VecView<T, 2>& v, std::vector<double>& out) {
      auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
      out.resize(2 * static_cast<std::size_t>(n_));
      for (Index i = 0; i < n_; ++i)
        for (int k = 0; k < 2; ++k) out[2 * static_cast<std::size_t>(i) + k] = static_cast<double>(m(i, k));
    };
    auto copy_scalar = [&](const View1<T>& v, std::vector<double>& out) {
      auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
      out.assign(m.data(), m.data() + n_);
    };
    copy_vec(f_.x0, h.x0);
    copy_vec(f_.u, h.u);
    copy_vec(f_.v, h.v);
    copy_scalar(f_.e, h.e);
    if (rotation_) copy_scalar(f_.theta, h.theta);
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
    const double lambda = m.max_eigenvalue(iterations);
    return 2.0 / std::sqrt(lambda);
  }

  // n0 the full model uses, computed from the lattice alone (no particles allocated).
  static double reference_number_density(const Config& c) {
    if (c.number_density == NumberDensityReference::interior) return mps::lattice_number_density(2, c.spacing, c.re());
    const Lattice lat = make_lattice(c);
    return lattice_mean_number_density(lat, c.re());
  }

  // Power iteration for the largest eigenvalue of M^-1 K, the linearised operator of this model.
  double max_eigenvalue(int iterations) {
    const T eps = static_cast<T>(1e-9 * cfg_.spacing);  // small enough that the operator is linear
    randomize_state(eps);
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
      compute_acceleration();
      lambda = rayleigh_quotient();
      load_acceleration_as_state(eps);
    }
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

  void setup_excitation(const Lattice& lat) {
    const auto& ex = cfg_.excitation;
    excitation_on_ = ex.kind != ExcitationKind::none;
    if (!excitation_on_) return;
    pulse_.amplitude = ex.amplitude;
    pulse_.period = ex.period;
    pulse_.cycles = ex.cycles;
    pulse_.shape = ex.kind == ExcitationKind::point ? mps::PulseShape::hann : mps::PulseShape::sine;
    pulse_.component = ex.kind == ExcitationKind::plane_s ? 0 : 1;
    std::vector<Index> src;
    const std::int64_t top = lat.ny - 1;
    const double xs = ex.position < 0 ? 0.5 * cfg_.width : ex.position;
    if (ex.kind != ExcitationKind::point) {
      for (std::int64_t i = 0; i < lat.nx; ++i) src.push_back(lat.index(i, top));
    } else {
      // The point source drives the top-row particles whose cells lie inside [xs - w/2, xs + w/2], so
      // the driven width is the same physical width at every resolution (w a multiple of l0). When no
      // cell fits (w = 0 or w < l0), the particle(s) nearest to xs (both, when xs is between two).
      const double half = 0.5 * ex.width * (1.0 + 1e-9), l0 = cfg_.spacing;
      double nearest = 1e300;
      for (std::int64_t i = 0; i < lat.nx; ++i) {
        const double d = std::abs(lat.x1(lat.index(i, top)) - xs);
        if (d + 0.5 * l0 <= half) src.push_back(lat.index(i, top));
        nearest = std::min(nearest, d);
      }
      if (src.empty())
        for (std::int64_t i = 0; i < lat.nx; ++i)
          if (std::abs(lat.x1(lat.index(i, top)) - xs) <= nearest + 1e-9 * l0) src.push_back(lat.index(i, top));
    }
    sources_ = View1<Index>("polymech::mps_elastic::sources", src.size());
    auto h = Kokkos::create_mirror_view(sources_);
    for (std::size_t k = 0; k < src.size(); ++k) h(k) = src[k];
    Kokkos::deep_copy(sources_, h);
  }

  bool sample_due() const { return probes_.count() > 0 && step_ % cfg_.probe_every == 0; }

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

  void compute_acceleration() {
    if (rotation_) {
      mps::volumetric_strain<T, true>(family_, f_, params_);
      mps::elastic_acceleration<T, true>(family_, f_, params_);
    } else {
      mps::volumetric_strain<T, false>(family_, f_, params_);
      mps::elastic_acceleration<T, false>(family_, f_, params_);
    }
  }

  // Deterministic pseudo-random start vector of amplitude eps.
  void randomize_state(T eps) {
    detail::power_iteration_start(f_, n_, rotation_, eps, static_cast<T>(cfg_.spacing));
    if (rotation_) mps::rotation_trigonometry(f_);
  }

  // <q, A q>_M / <q, q>_M with A q = -(a, alpha): the Rayleigh quotient of M^-1 K.
  double rayleigh_quotient() {
    return detail::power_iteration_rayleigh_quotient(f_, n_, rotation_, params_.mass, params_.inertia);
  }

  // q <- A q, renormalised to M-norm amplitude eps per particle.
  void load_acceleration_as_state(T eps) {
    detail::power_iteration_step(f_, n_, rotation_, params_.mass, params_.inertia, eps);
    if (rotation_) mps::rotation_trigonometry(f_);
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
  std::int64_t step_ = 0;
  // excitation
  bool excitation_on_ = false;
  mps::Pulse pulse_;
  View1<Index> sources_;
  ProbeRecorder<T> probes_;
  // crack
  CrackFaces<T> crack_;
  ContactHistory contact_history_;
};

}  // namespace polymech::mps_elastic
