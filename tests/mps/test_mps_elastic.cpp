// MPS elastic model (seed 000 §2.3-3.3): force-free rigid motions, conservation of linear and angular
// momentum, energy over long runs, and the stability limit of symplectic Euler (stable just below,
// visibly unstable just above).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mps_elastic/mps_elastic.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;
using Model = me::MpsElastic<double>;

namespace {

me::Config patch_config(bool rotation, int cells = 20, double l0 = 1e-4) {
  me::Config c;
  c.width = c.height = cells * l0;
  c.spacing = l0;
  c.dt = 2e-9 * l0 / 5e-5;  // the paper's dt / l0 ratio
  c.excitation.kind = me::ExcitationKind::none;
  if (rotation) c.effects = pm::EffectSet::resolve({"rotation"}, Model::effects());
  return c;
}

// Host-side state setting: u(i) = f(x0_i), theta(i) = g(x0_i).
template <class FU, class FT>
void set_state(Model& m, FU fu, FT ft) {
  const auto& f = m.fields();
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.x0);
  auto u = Kokkos::create_mirror_view(f.u);
  for (pm::Index i = 0; i < m.particles(); ++i) {
    auto d = fu(x0(i, 0), x0(i, 1), i);
    u(i, 0) = d[0];
    u(i, 1) = d[1];
  }
  Kokkos::deep_copy(f.u, u);
  if (m.has_rotation()) {
    auto t = Kokkos::create_mirror_view(f.theta);
    for (pm::Index i = 0; i < m.particles(); ++i) t(i) = ft(x0(i, 0), x0(i, 1), i);
    Kokkos::deep_copy(f.theta, t);
    pm::mps::rotation_trigonometry(f);
  }
}

void compute_forces(Model& m) {
  if (m.has_rotation()) {
    pm::mps::volumetric_strain<double, true>(m.family(), m.fields(), m.params());
    pm::mps::elastic_acceleration<double, true>(m.family(), m.fields(), m.params());
  } else {
    pm::mps::volumetric_strain<double, false>(m.family(), m.fields(), m.params());
    pm::mps::elastic_acceleration<double, false>(m.family(), m.fields(), m.params());
  }
}

double max_abs_acceleration(const Model& m) {
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  double mx = 0.0;
  for (pm::Index i = 0; i < m.particles(); ++i) mx = std::max({mx, std::abs(a(i, 0)), std::abs(a(i, 1))});
  return mx;
}

std::array<double, 2> random_pair(std::mt19937& g, double amp) {
  std::uniform_real_distribution<double> u(-amp, amp);
  return {u(g), u(g)};
}

}  // namespace

TEST(MpsElastic, RestStateIsExactlyForceFree) {
  for (bool rot : {false, true}) {
    Model m(patch_config(rot));
    compute_forces(m);
    EXPECT_EQ(max_abs_acceleration(m), 0.0);
  }
}

TEST(MpsElastic, RigidMotionIsForceFreeOnlyWithParticleRotation) {
  const double phi = 1e-4, amp = 1e-9;
  const double rigid_over_random = phi * 1e-4 / amp;  // bond stretch of the rotation vs the random field
  // reference scale: accelerations of a random displacement field of the same size
  Model ref(patch_config(true));
  std::mt19937 g(1);
  set_state(ref, [&](double, double, int) { return random_pair(g, amp); }, [](double, double, int) { return 0.0; });
  compute_forces(ref);
  const double scale = max_abs_acceleration(ref);

  auto rigid = [&](double x, double y, int) {
    return std::array<double, 2>{amp + (std::cos(phi) - 1) * x - std::sin(phi) * y,
                                 -amp + std::sin(phi) * x + (std::cos(phi) - 1) * y};
  };
  Model with(patch_config(true));
  set_state(with, rigid, [&](double, double, int) { return phi; });
  compute_forces(with);
  EXPECT_LT(max_abs_acceleration(with), 1e-9 * scale * rigid_over_random);

  // without the rotation effect a rigid rotation loads the free surfaces (eq. (6) needs R_i)
  Model without(patch_config(false));
  set_state(without, rigid, [](double, double, int) { return 0.0; });
  compute_forces(without);
  EXPECT_GT(max_abs_acceleration(without), 1e-3 * scale * rigid_over_random);
}

TEST(MpsElastic, LinearAndAngularMomentumAreConserved) {
  for (bool rot : {false, true}) {
    Model m(patch_config(rot));
    std::mt19937 g(2);
    set_state(m, [&](double, double, int) { return random_pair(g, 1e-9); },
              [&](double, double, int) { return std::uniform_real_distribution<double>(-1e-5, 1e-5)(g); });
    compute_forces(m);
    const auto& f = m.fields();
    auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.a);
    auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.u);
    auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.x0);
    const double mass = m.params().mass, inertia = m.params().inertia;
    double px = 0, py = 0, torque = 0, scale = 0, tscale = 0;
    for (pm::Index i = 0; i < m.particles(); ++i) {
      px += mass * a(i, 0);
      py += mass * a(i, 1);
      const double x = x0(i, 0) + u(i, 0), y = x0(i, 1) + u(i, 1);
      torque += mass * (x * a(i, 1) - y * a(i, 0));
      scale += mass * std::hypot(a(i, 0), a(i, 1));
      tscale += mass * std::hypot(x, y) * std::hypot(a(i, 0), a(i, 1));
    }
    double spin = 0.0;
    if (rot) {
      auto alpha = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.alpha);
      for (pm::Index i = 0; i < m.particles(); ++i) spin += inertia * alpha(i);
    }
    EXPECT_LT(std::abs(px), 1e-12 * scale);
    EXPECT_LT(std::abs(py), 1e-12 * scale);
    if (rot)
      EXPECT_LT(std::abs(torque + spin), 1e-10 * tscale);  // orbital + spin: eq. (12)
    else
      EXPECT_GT(std::abs(torque), 1e-6 * tscale);  // non-central shear forces, nothing balances them
  }
}

TEST(MpsElastic, TenThousandStepsAtThePaperTimeStepStayBounded) {
  // the paper's l0 and dt (Table 1) on a 3 mm x 3 mm plate, point source of seed 000 eq. (22)
  me::Config c = patch_config(true, 60, 5e-5);
  c.excitation.kind = me::ExcitationKind::point;
  Model m(c);
  ASSERT_DOUBLE_EQ(c.dt, 2e-9);
  const auto pulse_end = static_cast<std::int64_t>(c.excitation.period / c.dt) + 1;
  double e_ref = 0.0, e_min = 1e300, e_max = 0.0;
  for (std::int64_t s = 1; s <= 10000; ++s) {
    m.step();
    if (s == pulse_end) e_ref = m.energy().total();
    if (s > pulse_end && s % 250 == 0) {
      const double e = m.energy().total();
      e_min = std::min(e_min, e);
      e_max = std::max(e_max, e);
    }
  }
  ASSERT_TRUE(m.finite());
  ASSERT_GT(e_ref, 0.0);
  EXPECT_LT((e_max - e_min) / e_ref, 0.02) << "energy range over the run after the pulse";
}

TEST(MpsElastic, StabilityLimitSeparatesStableFromUnstable) {
  for (bool rot : {false, true}) {
    me::Config c = patch_config(rot, 16);
    const double limit = Model::stable_time_step(c);
    // the paper's dt sits well inside the limit (cp dt / l0 = 0.24)
    EXPECT_GT(limit, 2.0 * c.dt);
    auto run = [&](double dt) {
      me::Config r = c;
      r.dt = dt;
      r.allow_unstable_dt = true;
      Model m(r);
      std::mt19937 g(3);
      set_state(m, [&](double, double, int) { return random_pair(g, 1e-12); }, [](double, double, int) { return 0.0; });
      const double e0 = m.energy().total() + 1e-300;
      for (int s = 0; s < 3000; ++s) m.step();
      return m.finite() ? m.energy().total() / e0 : 1e300;
    };
    EXPECT_LT(run(0.95 * limit), 10.0) << "rotation=" << rot;
    EXPECT_GT(run(1.05 * limit), 1e6) << "rotation=" << rot;
    // dt above the limit is refused before anything runs
    c.dt = 1.2 * limit;
    EXPECT_THROW(Model{c}, std::invalid_argument);
  }
}

TEST(MpsElastic, StableTimeStepScalesWithSpacing) {
  const double a = Model::stable_time_step(patch_config(true, 16, 1e-4));
  const double b = Model::stable_time_step(patch_config(true, 16, 2e-4));
  EXPECT_NEAR(b / a, 2.0, 1e-6);
}

TEST(MpsElastic, MeanNumberDensityMatchesLatticeFormula) {
  me::Config c = patch_config(true, 30);
  c.width = 45 * c.spacing;
  Model m(c);
  EXPECT_NEAR(m.n0(), Model::reference_number_density(c), 1e-12);
  c.number_density = me::NumberDensityReference::interior;
  EXPECT_NEAR(Model::reference_number_density(c), 6.5397, 1e-4);
}
