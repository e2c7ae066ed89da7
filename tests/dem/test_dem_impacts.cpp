// The Chung & Ooi (2011) benchmark impacts against Hertz theory (tests 1-2), the damping model's
// restitution (test 3), the rebound angle of oblique impacts (test 4, the gross-sliding closed form),
// a meshed wall against the analytic plane, a fast sphere against a thin surface, the time-step limit,
// and the tangential spring kept across neighbour-list rebuilds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/benchmark.hpp"

namespace pm = polymech;
namespace dm = polymech::dem;

namespace {

// Hertz theory of the impact (dm::hertz_impact, models/dem/benchmark.hpp), within 2 %.
void expect_hertz(const dm::ImpactMeasure& got, const dm::HertzImpact& h) {
  EXPECT_NEAR(got.max_force / h.max_force, 1.0, 0.02) << got.max_force << " vs " << h.max_force;
  EXPECT_NEAR(got.max_overlap / h.max_overlap, 1.0, 0.02) << got.max_overlap << " vs " << h.max_overlap;
  EXPECT_NEAR(got.contact_time / h.contact_time, 1.0, 0.02) << got.contact_time << " vs " << h.contact_time;
}

// The restitution the damped Hertz law gives, by RK4 on m x'' = -(4/3 E* sqrt(R) x^1.5 + c sqrt(S_n m) x')
// with S_n = 2 E* sqrt(R x), c = -2 sqrt(5/6) beta, F >= 0 (the same law, integrated independently).
double damped_hertz_restitution(double m, double r, double e_star, double beta, double v0) {
  const double c = -2.0 * std::sqrt(5.0 / 6.0) * beta;
  auto acc = [&](double x, double v) {
    if (x <= 0) return 0.0;
    const double sn = 2 * e_star * std::sqrt(r * x);
    const double f = 4.0 / 3.0 * e_star * std::sqrt(r) * std::pow(x, 1.5) + c * std::sqrt(sn * m) * v;
    return -(f > 0 ? f : 0.0) / m;
  };
  const double tc = dm::hertz_contact_time(m, r, e_star, v0), h = tc / 20000;
  double x = 0, v = v0;
  for (int k = 0; k < 200000; ++k) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
    x += h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (x < 0 && k > 10) break;
  }
  return -v / v0;
}

}  // namespace

TEST(ChungOoi, Test1TwoIdenticalSpheresMatchHertz) {
  const auto k = dm::chung_ooi_test1_glass();
  const auto got = dm::run_impact(dm::two_spheres(k, 400));
  expect_hertz(got, dm::hertz_impact(k, true));
  EXPECT_NEAR(got.normal_restitution, 1.0, 1e-3);  // elastic
}

TEST(ChungOoi, Test2SphereOnRigidPlaneMatchesHertz) {
  for (const auto& k : {dm::chung_ooi_test2_aluminium(), dm::chung_ooi_test2_magnesium()}) {
    const auto got = dm::run_impact(dm::sphere_on_wall(k, 400));
    expect_hertz(got, dm::hertz_impact(k, false));  // the rigid wall: k.wall.young = 0
    EXPECT_NEAR(got.normal_restitution, 1.0, 1e-3);
  }
}

TEST(ChungOoi, Test2MeshedWallGivesThePlanesRebound) {
  const auto k = dm::chung_ooi_test2_aluminium();
  for (double angle : {0.0, 30.0}) {
    auto plane_cfg = dm::sphere_on_wall(k, 200, angle);
    auto mesh_cfg = dm::sphere_on_wall(k, 200, angle, true);
    for (auto* c : {&plane_cfg, &mesh_cfg}) {
      c->friction = 0.3;
      c->restitution = 0.7;
    }
    plane_cfg.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
    mesh_cfg.effects = pm::EffectSet::resolve({"friction", "damping", "fe_surfaces"}, dm::effect_table());
    const auto a = dm::run_impact(plane_cfg), b = dm::run_impact(mesh_cfg);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(b.v_after[c], a.v_after[c], 1e-9 * k.speed) << angle << " " << c;
      EXPECT_NEAR(b.omega_after[c], a.omega_after[c], 1e-9 * k.speed / k.radius) << angle << " " << c;
    }
    EXPECT_NEAR(b.max_force, a.max_force, 1e-9 * a.max_force);
    EXPECT_NEAR(b.contact_time, a.contact_time, 1e-9 * a.contact_time);
  }
}

TEST(ChungOoi, Test3RestitutionMatchesTheDampingModel) {
  for (const auto& k : {dm::chung_ooi_alumina(), dm::chung_ooi_cast_iron()}) {
    const double e_star = dm::effective_modulus(k.particle.young, k.particle.poisson, 0.0, 0.0);
    for (double e : {0.2, 0.4, 0.6, 0.8}) {
      auto c = dm::sphere_on_wall(k, 200);
      c.restitution = e;
      c.effects = pm::EffectSet::resolve({"damping"}, dm::effect_table());
      const auto got = dm::run_impact(c);
      const double beta = dm::hertz_damping_ratio(e);
      const double predicted = damped_hertz_restitution(dm::sphere_mass(k), k.radius, e_star, beta, k.speed);
      EXPECT_NEAR(got.normal_restitution, predicted, 0.01 * predicted) << "e = " << e;
      // beta calibrated on the Hertz law: the restitution asked for (the linear spring's beta gives 0.32 for 0.2)
      EXPECT_NEAR(got.normal_restitution, e, 0.01 * e) << "e = " << e;
      EXPECT_GT(damped_hertz_restitution(dm::sphere_mass(k), k.radius, e_star, dm::damping_ratio(e), k.speed), e + 0.005);
    }
  }
}

TEST(ChungOoi, Test4ReboundAnglesFollowTheSlidingLimitAndTurnNegativeInStickSlip) {
  const auto k = dm::chung_ooi_alumina();
  const double mu = 0.092;
  for (double angle : {5.0, 10.0, 20.0, 40.0, 60.0, 80.0}) {
    auto c = dm::sphere_on_wall(k, 200, angle);
    c.friction = mu;
    c.restitution = 0.98;
    c.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
    const auto got = dm::run_impact(c);
    const double rebound = dm::rebound_angle_deg(got, k.radius);
    const double th = angle * dm::kPi / 180, e = got.normal_restitution;
    if (std::tan(th) > 3.5 * mu * (1 + e) * 1.05) {  // gross sliding throughout: the rigid-body impulse result
      const double expected = std::atan((std::tan(th) - 3.5 * mu * (1 + e)) / e) * 180 / dm::kPi;
      EXPECT_NEAR(rebound, expected, 0.5) << "incidence " << angle;
    }
    if (angle == 20.0) {  // stick then slip: the spring reverses the contact point (Maw et al. 1976)
      EXPECT_LT(rebound, -3.0) << "incidence " << angle;
    }
    std::printf("test 4: incidence %.0f deg, rebound %.3f deg, e %.4f\n", angle, rebound, e);
  }
}


// Test 4 against the experiment it stands for: Kharaz, Gorham & Salman (2001), 5 mm alumina spheres at
// 3.9 m/s on a glass anvil, the rebound angle of the centre of mass against the incidence angle (their
// measured points as digitised in MFiX's DEM05 test data, tests/dem/data/kharaz2001_centre_rebound.csv).
// Measured here at 400 steps per contact, the code lies above the experiment at every point, by 0.40-1.05
// degrees from 9.9 degrees of incidence on (1.05 at 20.6) and by 0.12, 0.55, 1.52 degrees at 0.24, 2.3,
// 4.3. In gross sliding it is the rigid-body result tan(r) = (tan(i) - mu (1 + e)) / e with the scene's
// mu = 0.092 and e = 0.98; the experiment's spheres rebound a little steeper (a larger effective friction
// or a lower e there). Near normal incidence the contact sticks throughout and the Mindlin spring gives
// back the tangential velocity it took (centre rebound = incidence x 1.04 at 4.3 degrees), where the
// experiment lost a third of it (x 0.69, Maw's micro-slip): a limit of the no-slip spring, not of the step.
TEST(ChungOoi, Test4CentreReboundFollowsKharazsExperiment) {
  const char* src = std::getenv("POLYMECH_SOURCE_DIR");
  ASSERT_NE(src, nullptr) << "ctest sets POLYMECH_SOURCE_DIR";
  const std::string path = std::string(src) + "/tests/dem/data/kharaz2001_centre_rebound.csv";
  std::ifstream in(path);
  ASSERT_TRUE(in) << path;
  std::string line;
  std::getline(in, line);  // header
  const auto k = dm::chung_ooi_alumina();
  int points = 0;
  double worst = 0.0;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    ASSERT_NE(comma, std::string::npos) << line;
    const double incidence = std::stod(line.substr(0, comma)), measured = std::stod(line.substr(comma + 1));
    auto c = dm::sphere_on_wall(k, 400, incidence);
    c.friction = 0.092;
    c.restitution = 0.98;
    c.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
    const double got = dm::centre_rebound_angle_deg(dm::run_impact(c));
    EXPECT_NEAR(got, measured, incidence < 5.0 ? 1.6 : 1.2) << "incidence " << incidence;
    EXPECT_GT(got, measured - 0.05) << "incidence " << incidence;  // the side measured: never below
    worst = std::max(worst, std::abs(got - measured));
    std::printf("Kharaz 2001: incidence %7.3f deg, centre rebound %7.3f deg (measured %7.3f)\n", incidence, got,
                measured);
    ++points;
  }
  EXPECT_EQ(points, 9);
  std::printf("largest difference %.3f deg\n", worst);
}

// The kernels in float (dem_benchmark --precision float) give the double run's impacts to the float
// round-off: measured at 400 steps per contact, test 1's peak force -1.4e-6 (double +2.2e-6) from Hertz,
// test 4's rebound at 20 degrees (stick then slip) and 45 (gross sliding) 5e-5 degrees from double's
// (bench/sweep_dem_impacts.py: below 400 steps per contact float and double agree, above it float's error
// stalls at its round-off while double's keeps falling).
TEST(ChungOoi, FloatKernelsGiveTheDoubleImpacts) {
  const auto k1 = dm::chung_ooi_test1_glass();
  const auto d1 = dm::run_impact<double>(dm::two_spheres(k1, 400));
  const auto f1 = dm::run_impact<float>(dm::two_spheres(k1, 400));
  EXPECT_NEAR(f1.max_force / d1.max_force, 1.0, 2e-5);
  EXPECT_NEAR(f1.contact_time / d1.contact_time, 1.0, 2e-5);
  EXPECT_NEAR(f1.normal_restitution, 1.0, 1e-3);
  EXPECT_NE(f1.max_force, d1.max_force);  // the float kernels did run (the apps once ran double for float)
  const auto k4 = dm::chung_ooi_alumina();
  for (double angle : {20.0, 45.0}) {
    auto c = dm::sphere_on_wall(k4, 400, angle);
    c.friction = 0.092;
    c.restitution = 0.98;
    c.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
    const double d = dm::rebound_angle_deg(dm::run_impact<double>(c), k4.radius);
    const double f = dm::rebound_angle_deg(dm::run_impact<float>(c), k4.radius);
    EXPECT_NEAR(f, d, 2e-3) << "incidence " << angle;
    std::printf("float against double: incidence %.0f deg, rebound %.6f against %.6f deg\n", angle, f, d);
  }
}
TEST(DemHardCases, FiftyMetresPerSecondDoNotTunnelThroughAThinSurface) {
  auto k = dm::chung_ooi_test1_glass();
  k.radius = 0.005;
  k.speed = 50.0;
  k.wall = {2.1e11, 0.3, 7800};
  auto c = dm::sphere_on_wall(k, 10, 0.0, true);  // one layer of quads, no thickness
  c.dt = 0;                                       // the model's own: half the limit
  c.effects = pm::EffectSet::resolve({"fe_surfaces"}, dm::effect_table());
  const auto got = dm::run_impact(c);
  EXPECT_GT(got.v_after[2], 0.9 * k.speed);  // bounced back
  EXPECT_GT(got.max_overlap, 0.0);
  EXPECT_LT(got.max_overlap, 0.2 * k.radius);
}

TEST(DemHardCases, TimeStepAboveTheLimitIsRefusedWithTheLimit) {
  auto c = dm::sphere_on_wall(dm::chung_ooi_test1_glass(), 400);
  const auto limit = dm::time_step_limit(c);
  EXPECT_GT(limit.limit, 0.0);
  EXPECT_LE(limit.limit, limit.rayleigh);
  c.dt = 1.01 * limit.limit;
  try {
    dm::Dem<double> m(c);
    FAIL() << "a step above the limit was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("exceeds the limit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Rayleigh"), std::string::npos) << e.what();
  }
  c.dt = 0.99 * limit.limit;
  EXPECT_NO_THROW(dm::Dem<double> m(c));
}

TEST(DemHardCases, TangentialSpringSurvivesNeighbourListRebuilds) {
  // two spheres pressed together and sheared past each other: the same result with a skin that rebuilds
  // the list every few steps as with one that never does (the spring is carried, not restarted)
  auto run = [](double skin) {
    auto k = dm::chung_ooi_test1_glass();
    dm::Config c;
    c.particle = k.particle;
    dm::SphereInit a, b;
    a.radius = b.radius = k.radius;
    a.position = {0, 0, 0};
    b.position = {2 * k.radius - 2e-6, 0, 0};
    a.velocity = {0, 0.05, 0};
    b.velocity = {-0.01, -0.05, 0};
    c.spheres = {a, b};
    c.friction = 0.5;
    c.skin = skin;
    c.max_speed = 1.0;
    c.effects = pm::EffectSet::resolve({"friction"}, dm::effect_table());
    dm::Dem<double> m(c);
    for (int s = 0; s < 300; ++s) m.step();
    return std::make_pair(m.sphere(0), m.sphere_list_builds());
  };
  const auto [rebuilt, n_rebuilt] = run(1e-6);
  const auto [once, n_once] = run(1.0);
  EXPECT_GT(n_rebuilt, 10);
  EXPECT_EQ(n_once, 1);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(rebuilt.v[c], once.v[c], 1e-12);
    EXPECT_NEAR(rebuilt.omega[c], once.omega[c], 1e-9);
  }
  EXPECT_GT(std::abs(once.omega[2]), 0.0);  // friction did spin it
}

TEST(DemHardCases, ASphereRollingAcrossFacetEdgesKeepsItsSpringAndMatchesThePlane) {
  // a sphere rolls without slipping down the wall (gravity tilted by 20 degrees, mu = 0.5): its contact
  // sticks, the spring holding the static friction (2/7) m g sin 20; it crosses two edges between
  // quadrilaterals of side r, and its path must be the analytic plane's. At each edge the contact passes
  // from one facet to the next: without carrying the spring over, the friction would drop and rebuild.
  auto k = dm::chung_ooi_alumina();
  k.particle = {1e7, 0.3, 2500};  // soft: a large step, a test of a second
  k.radius = 0.005;
  k.speed = 0.0;
  const double th = 20.0 * dm::kPi / 180;
  auto run = [&](bool meshed) {
    auto c = dm::sphere_on_wall(k, 200, 0.0, meshed);
    for (std::size_t i = 0; i < c.surface.nodes.size(); i += 3) c.surface.nodes[i] *= 3.0;  // 12 r along x
    c.spheres[0].position = {-1.3 * k.radius, 0.3 * k.radius, k.radius * (1 - 1e-3)};
    c.spheres[0].velocity = {0, 0, 0};
    c.gravity = {9.81 * std::sin(th), 0, -9.81 * std::cos(th)};
    c.friction = 0.5;
    c.restitution = 0.5;
    c.max_speed = 0.5;
    c.dt = 0;
    c.effects = pm::EffectSet::resolve(meshed ? std::vector<std::string>{"friction", "damping", "fe_surfaces"}
                                              : std::vector<std::string>{"friction", "damping"},
                                       dm::effect_table());
    dm::Dem<double> m(c);
    const double a = 5.0 / 7.0 * 9.81 * std::sin(th);  // rolling without slip
    const auto steps = static_cast<int>(std::sqrt(2 * 2.6 * k.radius / a) / m.dt());
    for (int s = 0; s < steps; ++s) m.step();
    return m.sphere(0);
  };
  const auto plane = run(false), mesh = run(true);
  EXPECT_GT(plane.x[0], 0.5 * k.radius);  // it did cross x = -r and x = 0 (two edges)
  EXPECT_NEAR(plane.v[0] / (k.radius * plane.omega[1]), 1.0, 0.01);  // rolling: v = r w
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(mesh.x[c], plane.x[c], 1e-9 * k.radius) << c;
    EXPECT_NEAR(mesh.v[c], plane.v[c], 1e-7) << c;
    EXPECT_NEAR(mesh.omega[c], plane.omega[c], 1e-4) << c;
  }
}

TEST(DemHardCases, ThePoursFrictionHoldsUntilItsTimeThenTheScenesFriction) {
  // Config::pour_friction (a denser bed: a lower mu while the gravel settles): a sphere sliding on the floor at
  // 1 m/s with the pour's mu = 0 keeps its speed and does not spin until pour_friction_until = 20 ms; from then on
  // the scene's mu = 0.5 brakes it at mu g (Coulomb sliding) until it rolls at 5/7 of its speed after 58 ms.
  dm::Config c;
  c.particle = {1e7, 0.3, 2500};
  const double r = 0.005, mu = 0.5, g = 9.81, v0 = 1.0, t0 = 0.02;
  const double m = 2500 * 4.0 / 3.0 * dm::kPi * r * r * r;
  const double e_star = 1e7 / (1 - 0.3 * 0.3);  // on a rigid wall
  const double d_rest = std::pow(m * g / (4.0 / 3.0 * e_star * std::sqrt(r)), 2.0 / 3.0);  // Hertz: m g = 4/3 E* sqrt(R) d^1.5
  dm::SphereInit s;
  s.radius = r;
  s.position = {0, 0, r - d_rest};
  s.velocity = {v0, 0, 0};
  c.spheres = {s};
  c.planes = {dm::PlaneInit{{0, 0, 0}, {0, 0, 1}}};
  c.gravity = {0, 0, -g};
  c.friction = mu;
  c.pour_friction = 0.0;
  c.pour_friction_until = t0;
  c.restitution = 0.3;
  c.max_speed = 1.5;
  c.effects = pm::EffectSet::resolve({"friction", "damping"}, dm::effect_table());
  dm::Dem<double> model(c);
  const auto to = [&](double t) {
    while (model.time() < t - 0.5 * model.dt()) model.step();
    return model.sphere(0);
  };
  const auto before = to(t0 - 2 * model.dt());
  EXPECT_NEAR(before.v[0], v0, 1e-12) << "the pour's mu = 0 must leave the sliding speed";
  EXPECT_NEAR(before.omega[1], 0.0, 1e-12);
  const auto a = to(t0 + 0.01), b = to(t0 + 0.04);
  const double decel = (a.v[0] - b.v[0]) / 0.03;
  std::printf("before %.3f s: v %.12f m/s; after: %.6f -> %.6f m/s over 30 ms: deceleration %.4f m/s^2 (mu g %.4f); spin %.2f rad/s\n",
              t0, before.v[0], a.v[0], b.v[0], decel, mu * g, b.omega[1]);
  EXPECT_NEAR(decel / (mu * g), 1.0, 0.02);
  EXPECT_GT(b.omega[1], 0.0);  // the friction spins it up (about +y for motion along +x)
  const auto rolled = to(t0 + 0.1);
  EXPECT_NEAR(rolled.v[0] / v0, 5.0 / 7.0, 0.01) << "rolling: 5/7 of the sliding speed";
  // without the pour's friction it brakes from the start
  c.pour_friction = -1.0;
  dm::Dem<double> plain(c);
  while (plain.time() < t0 - 2.5 * plain.dt()) plain.step();
  EXPECT_LT(plain.sphere(0).v[0], v0 - 0.9 * mu * g * t0);
}
