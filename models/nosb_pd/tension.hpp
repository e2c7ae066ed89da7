// Uniaxial tension of a bar (seed 003 §4(1): the weighted-function method and the velocity
// viscosity were checked, and omega_v identified, on uniaxial tension).
//
// Modulus: the x = length grip is pulled to the nominal strain over a ramp, then held while
// mass-proportional damping relaxes the bar to equilibrium; E = (grip force / cross-section) /
// (strain of the gauge section, the middle third, from a least-squares fit of u_x over x). The
// reference is E in 3D and the plane-strain modulus E / (1 - nu^2) in 2D.
//
// omega_v: the same pull without any damping or control; the particle nearest the bar's centre
// oscillates against its neighbourhood (v - vbar, the quantity eq. (3) acts on), and omega_v is the
// angular frequency of that oscillation, pi x (zero crossings) / (time).
#pragma once

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

struct TensionResult {
  double modulus = 0.0;            // measured
  double reference = 0.0;          // E (3D) or E / (1 - nu^2) (2D)
  double relative_error = 0.0;     // (measured - reference) / reference
  double gauge_strain = 0.0, stress = 0.0;
  std::int64_t steps = 0;
  double wall_seconds = 0.0;
  models::RunStats run;            // the run driver's record (diverged, restarts, checkpoints)
};

// The steps of the pull: ramp (grip moving) and hold (relaxation).
struct TensionSteps {
  std::int64_t ramp = 0, hold = 0;
};
template <class T, int D>
TensionSteps tension_steps(const NosbPd<T, D>& m, const TensionSchedule& sched = {}) {
  const Config& c = m.config();
  const double transit = c.geometry.length / bar_wave_speed(c);
  return {static_cast<std::int64_t>(std::ceil(sched.ramp * transit / m.dt())),
          static_cast<std::int64_t>(std::ceil(sched.hold * transit / m.dt()))};
}

// The pull and the measurement, through the shared run driver (models::run): `hooks` may add
// progress, a watchdog, checkpoints and a resume (the grip velocity is model state: a run resumed in
// the hold keeps the grip still).
template <class T, int D>
TensionResult run_tension(NosbPd<T, D>& m, const TensionSchedule& sched = {}, models::RunHooks hooks = {}) {
  const Config& c = m.config();
  const auto n = tension_steps(m, sched);
  // the grips are one horizon long: the pulled length between their inner edges grows by strain x length
  m.set_grip_velocity(n.ramp > 0 ? c.tension.strain * c.geometry.length / (static_cast<double>(n.ramp) * m.dt()) : 0.0);
  auto after = hooks.after_step;
  hooks.after_step = [&m, after, ramp = n.ramp](std::int64_t k) {
    if (k == ramp) m.set_grip_velocity(0.0);
    if (after) after(k);
  };
  const std::int64_t from = hooks.resume ? hooks.resume->get<std::int64_t>("driver/step") : m.step_index();
  TensionResult r;
  r.run = models::run(m, n.ramp + n.hold - from, hooks);
  Kokkos::fence();
  const auto meas = m.tension_measure();
  r.gauge_strain = meas.gauge_strain;
  r.stress = meas.grip_force / m.cross_section();
  r.modulus = r.stress / r.gauge_strain;
  const double E = c.material.youngs_modulus, nu = c.material.poisson_ratio;
  r.reference = D == 3 ? E : E / (1 - nu * nu);
  r.relative_error = (r.modulus - r.reference) / r.reference;
  r.steps = m.step_index();
  r.wall_seconds = r.run.wall_seconds;
  return r;
}

struct OscillationResult {
  double omega = 0.0;        // [rad/s]
  std::int64_t crossings = 0;
  double duration = 0.0;
};

// The configuration of the omega_v identification (seed 003 §4(1): the report identified omega_v on
// the uncontrolled tension test): the velocity_viscosity effect with c_v = 0 (it computes vbar and
// applies no force), the weighted function if the scene has it, no damping and no other control.
inline Config omega_v_identification(Config c) {
  std::vector<std::string> effects = {"velocity_viscosity"};
  if (c.effects.has("weighted_function")) effects.push_back("weighted_function");
  c.effects = EffectSet::resolve(effects, effect_table());
  c.stabilization.c_v = 0.0;
  c.stabilization.omega_v = 1.0;
  c.mass_damping = 0.0;
  return c;
}

// omega_v from the undamped, uncontrolled pull (a model of omega_v_identification(scene)).
template <class T, int D>
OscillationResult identify_omega_v(NosbPd<T, D>& m, const TensionSchedule& sched = {}) {
  const Config& c = m.config();
  const double transit = c.geometry.length / bar_wave_speed(c);
  const auto steps = static_cast<std::int64_t>(std::ceil((sched.ramp + sched.hold) * transit / m.dt()));
  // the particle nearest the centre of the bar
  auto x0 = Kokkos::create_mirror_view_and_copy(HostSpace(), m.fields().x0);
  double centre[3] = {0.5 * c.geometry.length, 0, 0};
  if (c.geometry.shape == Shape::box) {
    centre[1] = 0.5 * (D == 3 ? c.geometry.width : c.geometry.height);
    if (D == 3) centre[2] = 0.5 * c.geometry.height;
  }
  Index probe = 0;
  double best = 1e300;
  for (Index i = 0; i < m.particles(); ++i) {
    double d2 = 0;
    for (int k = 0; k < D; ++k) d2 += (double(x0(i, k)) - centre[k]) * (double(x0(i, k)) - centre[k]);
    if (d2 < best) best = d2, probe = i;
  }
  m.set_grip_velocity(c.tension.strain * c.geometry.length / (sched.ramp * transit));
  OscillationResult r;
  double last = 0.0;
  const auto ramp_steps = static_cast<std::int64_t>(std::ceil(sched.ramp * transit / m.dt()));
  const auto v = Kokkos::subview(m.fields().v, probe, 1);
  const auto vbar = Kokkos::subview(m.fields().vbar, probe, 1);
  auto hv = Kokkos::create_mirror_view(v);
  auto hb = Kokkos::create_mirror_view(vbar);
  for (std::int64_t s = 0; s < steps; ++s) {
    if (s == ramp_steps) m.set_grip_velocity(0.0);
    m.step();
    Kokkos::deep_copy(hv, v);
    Kokkos::deep_copy(hb, vbar);
    const double rel = double(hv()) - double(hb());  // lateral relative velocity: no mean motion
    if (s > 0 && ((rel > 0) != (last > 0)) && rel != 0.0) ++r.crossings;
    if (rel != 0.0) last = rel;
  }
  r.duration = static_cast<double>(steps) * m.dt();
  r.omega = 3.14159265358979323846 * static_cast<double>(r.crossings) / r.duration;
  return r;
}

}  // namespace polymech::nosb_pd
