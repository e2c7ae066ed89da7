// The shared layer of the particle and contact methods: rigid bodies, the run driver's watchdog, the
// coupled model's momentum exchange, and the neighbour loop's strategies.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "mps_elastic/run.hpp"
#include "nosb_pd/impact.hpp"
#include "rigid/rigid_body.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;
namespace np = polymech::nosb_pd;

namespace {

double norm3(const double (&v)[3]) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// Velocity Verlet of one body under its own loads (none: a free body).
template <int D>
void advance(pm::rigid::RigidBody<D>& b, double dt, int steps) {
  for (int s = 0; s < steps; ++s) {
    b.kick(0.5 * dt);
    b.drift(dt);
    b.kick(0.5 * dt);
  }
}

// A small MPS plate with the point source of seed 000, at dt_factor x its stability limit.
me::Config mps_plate(double dt_factor) {
  me::Config c;
  c.width = c.height = 24e-4;
  c.spacing = 1e-4;
  c.excitation.kind = me::ExcitationKind::point;
  c.effects = pm::EffectSet::resolve({"rotation"}, me::effect_table());
  c.dt = dt_factor * me::MpsElastic<double>::stable_time_step(c);
  c.allow_unstable_dt = dt_factor > 1;
  return c;
}

}  // namespace

// A free asymmetric top (principal moments 1, 2, 3) spinning about a tilted axis: the angular momentum
// is constant in the world frame (exactly: no torque), the kinetic energy to the scheme's accuracy, and
// the quaternion stays a unit quaternion.
TEST(RigidBody, FreeAsymmetricTopKeepsAngularMomentumAndEnergy) {
  pm::rigid::RigidBody<3> b;
  b.mass = 2.0;
  b.inertia[0] = 1.0, b.inertia[1] = 2.0, b.inertia[2] = 3.0;
  b.spin[0] = 0.3, b.spin[1] = 2.0, b.spin[2] = 0.2;  // near the unstable middle axis: it tumbles
  b.velocity[0] = 1.0;
  const double L0[3] = {b.spin[0], b.spin[1], b.spin[2]};
  const double e0 = b.kinetic_energy();
  advance(b, 1e-3, 20000);
  for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(b.spin[k], L0[k]);
  const double q = std::sqrt(b.orientation[0] * b.orientation[0] + b.orientation[1] * b.orientation[1] +
                             b.orientation[2] * b.orientation[2] + b.orientation[3] * b.orientation[3]);
  EXPECT_NEAR(q, 1.0, 1e-14);
  EXPECT_NEAR(b.kinetic_energy() / e0, 1.0, 2e-3) << "energy after 20 time units of tumbling";
  EXPECT_NEAR(b.position[0], 20.0, 1e-9);
  // the body frame turned: a body axis is no longer where it started
  double ex[3] = {1, 0, 0}, w[3];
  b.to_world(ex, w);
  EXPECT_NEAR(norm3(w), 1.0, 1e-14);
  EXPECT_LT(w[0], 0.999);
}

// Constant loads: velocity Verlet is exact for a constant force and torque.
TEST(RigidBody, ConstantForceAndTorqueAreIntegratedExactly) {
  pm::rigid::RigidBody<2> b;
  b.mass = 4.0;
  b.inertia[0] = 0.5;
  const double dt = 1e-2;
  const int steps = 300;
  for (int s = 0; s < steps; ++s) {
    b.kick(0.5 * dt);
    b.drift(dt);
    b.clear_loads();
    const double f[2] = {8.0, 0.0}, at[2] = {0.0, 1.0};  // 8 N along x at 1 m above the centre
    b.add_force_at(f, at);
    b.kick(0.5 * dt);
  }
  const double t = dt * steps;
  // the first kick of the first step saw no load (as a run's first step sees the initial forces)
  EXPECT_NEAR(b.velocity[0], 2.0 * t - 2.0 * 0.5 * dt, 1e-12);
  EXPECT_NEAR(b.spin[0], -16.0 * t + 16.0 * 0.5 * dt, 1e-11);  // torque (0, 1) x (8, 0) = -8
  pm::rigid::RigidBody<3> locked;
  locked.mass = 1.0;
  locked.inertia[0] = locked.inertia[1] = locked.inertia[2] = 1.0;
  locked.rotation_locked = true;
  locked.torque[2] = 5.0;
  advance(locked, 1e-2, 10);
  EXPECT_EQ(locked.spin[2], 0.0);
  EXPECT_EQ(locked.orientation[0], 1.0);
}

// Mass, centre and inertia of a solid sphere from a cubic sampling of its volume.
TEST(RigidBody, MassPropertiesOfASampledSphere) {
  const double R = 1.0, h = 0.025, rho = 3.0;
  std::vector<double> x, m;
  for (double a = -R + h / 2; a < R; a += h)
    for (double b = -R + h / 2; b < R; b += h)
      for (double c = -R + h / 2; c < R; c += h)
        if (a * a + b * b + c * c <= R * R) {
          x.insert(x.end(), {a + 2.0, b - 1.0, c});
          m.push_back(rho * h * h * h);
        }
  const auto p = pm::rigid::mass_properties<3>(x, m, static_cast<std::int64_t>(m.size()));
  const double M = rho * 4.0 / 3.0 * 3.14159265358979323846 * R * R * R;
  EXPECT_NEAR(p.mass / M, 1.0, 2e-3);
  EXPECT_NEAR(p.centre[0], 2.0, 1e-9);
  EXPECT_NEAR(p.centre[1], -1.0, 1e-9);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(p.inertia[k][k] / (0.4 * M * R * R), 1.0, 5e-3);
  EXPECT_NEAR(p.inertia[0][1], 0.0, 1e-9 * M);
}

// The watchdog stops a run that blows up (dt three times the stability limit: the lattice flies apart
// and its energy grows by orders of magnitude, though it stays finite), names the step, and hands the
// last good state to the snapshot hook.
TEST(RunDriver, WatchdogStopsAnUnstableRunWithTheLastGoodState) {
  me::MpsElastic<double> m(mps_plate(3.0));
  me::RunHooks hooks;
  hooks.sample_every = 10;
  hooks.watchdog.keep_last_good = true;
  std::vector<std::int64_t> snapshots;
  double energy_at_snapshot = 0;
  hooks.snapshot = [&](std::int64_t k) {
    snapshots.push_back(k);
    energy_at_snapshot = m.energy().total();
  };
  const auto s = me::run(m, 2000, hooks);
  ASSERT_TRUE(s.diverged) << "dt = 3 x the limit must blow up within 2000 steps";
  EXPECT_FALSE(s.finite);
  EXPECT_GT(s.bad_step, 0);
  EXPECT_EQ(s.bad_step % 10, 0);
  EXPECT_EQ(s.last_good_step, s.bad_step - 10);
  EXPECT_NE(s.reason.find("(half a spacing: the lattice is torn apart)"), std::string::npos) << s.reason;
  ASSERT_FALSE(snapshots.empty());
  EXPECT_EQ(snapshots.back(), s.last_good_step);
  EXPECT_EQ(m.step_index(), s.last_good_step);
  EXPECT_TRUE(m.finite()) << "the snapshot holds the last good state";
  EXPECT_LT(energy_at_snapshot, 1e3 * s.energy.total.front());
  // the same scene below the limit runs through
  me::MpsElastic<double> ok(mps_plate(0.9));
  EXPECT_FALSE(me::run(ok, 500, hooks).diverged);
}

// A NaN (a bad material value, say) is found by the all-finite check, which names the first bad
// particle (the lowest index: deterministic) and where it is.
TEST(RunDriver, WatchdogNamesTheFirstNonFiniteParticle) {
  me::MpsElastic<double> m(mps_plate(0.9));
  for (int s = 0; s < 20; ++s) m.step();
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().v);
  v(123, 1) = std::nan("");
  v(400, 0) = std::numeric_limits<double>::infinity();
  Kokkos::deep_copy(m.fields().v, v);
  const auto h = m.health();
  EXPECT_FALSE(h.finite);
  EXPECT_EQ(h.first_bad, 123);
  const auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
  EXPECT_EQ(h.position[0], x0(123, 0));
  EXPECT_EQ(h.position[1], x0(123, 1));
  EXPECT_EQ(h.problem, "is not finite");
  pm::models::RunHooks hooks;
  hooks.watchdog.check_every = 1;
  const auto s = pm::models::run(m, 100, hooks);
  ASSERT_TRUE(s.diverged);
  EXPECT_EQ(s.bad_step, 21);
  EXPECT_NE(s.reason.find("the first bad particle "), std::string::npos) << s.reason;
  EXPECT_NE(s.reason.find(" is not finite"), std::string::npos) << s.reason;
}

// A sphere hitting a free (unclamped) elastic plate through the coupled model: the contact forces on
// the particles and their reaction on the projectile are one computation, so the total momentum of
// plate and projectile stays what it was.
TEST(CoupledModel, ProjectileAndPlateExchangeMomentumExactly) {
  np::Config c;
  c.dimension = 3;
  c.spacing = 2e-3;
  c.horizon_ratio = 2.0;
  c.geometry.shape = np::Shape::disc;
  c.geometry.radius = 0.012;
  c.geometry.thickness = 0.006;
  c.loading = np::Loading::impact;
  c.clamp_radius = 0.0;  // free plate
  c.projectile.shape = np::ProjectileShape::sphere;
  c.projectile.radius = 0.004;
  c.projectile.mass = 0.01;
  c.projectile.velocity = 50;
  c.projectile.standoff = 0.0;
  c.effects = pm::EffectSet::resolve({"contact"}, np::effect_table());
  np::Impact<double, 3> m(c);
  m.prepare();
  const auto p0 = m.energy().momentum[2];
  double reaction = 0;
  for (int s = 0; s < 200; ++s) {
    m.step();
    reaction = std::max(reaction, std::abs(m.projectile().force[2]));
  }
  EXPECT_GT(reaction, 0.0) << "the sphere reached the plate";
  EXPECT_GT(m.projectile().velocity[2], -49.0) << "slowed (or thrown back) by the plate";
  EXPECT_NEAR(m.energy().momentum[2], p0, 1e-12 * std::abs(p0));
  // the two models' time steps must agree
  np::NosbPd<double, 3> plate(c);
  pm::models::RigidBodies<3> body({np::projectile_body<3>(c.projectile)}, 2 * plate.dt());
  np::ProjectileContact<double, 3> contact(c, plate.particles());
  EXPECT_THROW((pm::models::CoupledModel<np::NosbPd<double, 3>, pm::models::RigidBodies<3>, np::ProjectileContact<double, 3>>(
                   plate, body, contact)),
               std::invalid_argument);
}

// The neighbour loop's team strategy gives the serial results (to round-off: the partial sums of a
// row are added in another order) for the MPS and PD force kernels.
TEST(NeighborLoop, TeamStrategyAgreesWithSerial) {
  me::MpsElastic<double> m(mps_plate(0.5));
  for (int s = 0; s < 30; ++s) m.step();
  const auto& f = m.fields();
  auto a_serial = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.a);
  pm::mps::volumetric_strain<double, true>(m.family(), f, m.params(), pm::neighbors::TeamNeighbors{});
  pm::mps::elastic_acceleration<double, true>(m.family(), f, m.params(), pm::neighbors::TeamNeighbors{});
  auto a_team = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.a);
  double scale = 0, diff = 0;
  for (std::size_t i = 0; i < a_team.extent(0); ++i)
    for (int k = 0; k < 2; ++k) {
      scale = std::max(scale, std::abs(a_serial(i, k)));
      diff = std::max(diff, std::abs(a_team(i, k) - a_serial(i, k)));
    }
  ASSERT_GT(scale, 0.0);
  EXPECT_LT(diff, 1e-12 * scale);
}
