// ISPH floating body (seed 002 paper 4 §4, eqs. (31)-(43)): mass properties by quadrature over the
// body's cells, the momentum exchange through its integration points, and a neutrally buoyant cylinder.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <utility>

#include "common.hpp"

using namespace isph_test;

namespace {

ip::Config body_config(double ratio, double cx, double cy) {
  auto c = tank_config(2, 0.01, 0.2, 0.16, 1e-3);
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization", "rigid_body"}, ip::effect_table());
  c.body.diameter = 0.06;
  c.body.centre[0] = cx;
  c.body.centre[1] = cy;
  c.body.density_ratio = ratio;
  c.body.release_time = 0.1;
  return c;
}

}  // namespace

// Eqs. (33)-(35): the polar cells' one-point quadrature gives the area exactly, the centroid at the
// centre, and the polar inertia rho pi R^4 / 2 within 1 %.
TEST(IsphBody, MassPropertiesByQuadratureOverTheCells) {
  const auto c = body_config(0.8, 0.1, 0.08);
  const auto cells = ip::body_cells(c);
  const auto p = ip::mass_properties(c, cells);
  const double pi = 3.14159265358979323846, R = 0.03;
  EXPECT_NEAR(p.area, pi * R * R, 1e-12);
  EXPECT_NEAR(p.centroid[0], 0.0, 1e-12);
  EXPECT_NEAR(p.centroid[1], 0.0, 1e-12);
  // one Gauss point per cell (the paper's choice): the midpoint rule in r, -5.6 % with 3 rings, O(dr^2)
  const double exact = 800.0 * pi * R * R * R * R / 2;
  EXPECT_NEAR(p.inertia, exact, 0.06 * exact);
  auto fine = c;
  fine.spacing = 0.0025;  // 12 rings
  EXPECT_NEAR(ip::mass_properties(fine, ip::body_cells(fine)).inertia, exact, 0.005 * exact);
  EXPECT_NEAR(ip::archimedes_draft_over_diameter(0.5), 0.5, 1e-9);
  EXPECT_NEAR(ip::archimedes_draft_over_diameter(1.0), 1.0, 1e-9);
  const double d = ip::archimedes_draft_over_diameter(0.8);  // segment area check
  const double phi = 2 * std::acos(1 - 2 * d);
  EXPECT_NEAR((phi - std::sin(phi)) / 2, 0.8 * pi, 1e-9);
}

// Eqs. (36)-(43): the force the model gives the body is the sum of the reactions at its integration
// points, which is minus the wall force the body's points exert on the fluid, to round-off.
// (The paper's symmetric form of the pressure gradient, where the reactions are the body's whole force.)
TEST(IsphBody, BodyForceIsMinusTheWallForceOnTheFluid) {
  auto c = body_config(1.0, 0.1, 0.08);
  c.pressure_gradient = ip::PressureGradient::symmetric;
  c.ghost_interpolation = ip::GhostInterpolation::shepard;
  ip::Isph<double, 2> m(c);
  ASSERT_TRUE(m.has_body());
  for (int k = 0; k < 100; ++k) m.step();  // held until 0.1 s: the pressure settles
  std::vector<double> on_fluid, on_points;
  m.wall_forces(on_fluid, on_points);
  double fb[2] = {0, 0}, mag = 0;
  for (std::size_t k = static_cast<std::size_t>(m.body_begin()); k < on_points.size() / 2; ++k)
    for (int d = 0; d < 2; ++d) {
      fb[d] += on_points[2 * k + d];
      mag += std::fabs(on_points[2 * k + d]);
    }
  ASSERT_GT(mag, 0.0);
  // the model's force of the last step was computed before the body moved: recompute on this state
  // through the same reactions (wall_forces), and compare the total exchange (tank + body) too
  double ff[2] = {0, 0}, fp[2] = {0, 0};
  for (std::size_t i = 0; i < on_fluid.size(); ++i) ff[i % 2] += on_fluid[i];
  for (std::size_t i = 0; i < on_points.size(); ++i) fp[i % 2] += on_points[i];
  for (int d = 0; d < 2; ++d) EXPECT_NEAR(ff[d] + fp[d], 0.0, 1e-12 * mag);
  // buoyancy of a fully immersed cylinder: rho g A upwards, within 15 % after 0.1 s
  const double buoy = 1000.0 * 9.8 * 3.14159265358979323846 * 0.03 * 0.03;
  std::printf("body force on its points (%.4f, %.4f) N/m, model's last force (%.4f, %.4f), buoyancy %.4f\n", fb[0],
              fb[1], m.body().force[0], m.body().force[1], buoy);
  EXPECT_NEAR(fb[1], buoy, 0.15 * buoy);
  EXPECT_NEAR(fb[0], 0.0, 0.05 * buoy);
}

// The fluid force on a cylinder held fully immersed (6 particles across, 2.5 diameters under the surface),
// averaged over 0.2-0.4 s, against the buoyancy rho g pi R^2. The paper's form (symmetric gradient, eqs. (9)
// and (19), Shepard ghosts, eq. (23)) lifts it by 4.4 % (measured; 8.5 % with linear ghosts, 14 % at
// 2.2 x the depth): its error is proportional to the absolute pressure. The difference form with linear
// ghosts and the surface integral of the pressure (the default): 1.65 % (measured; 0.01 % at 12 particles
// across), docs/VALIDATION.md.
static double held_body_force(ip::PressureGradient form, ip::GhostInterpolation ghosts, double water = 0.16,
                              double l0 = 0.01, double dt = 1e-3,
                              ip::SurfaceDetection surface = ip::SurfaceDetection::density, double alpha = 5e-3) {
  auto c = body_config(1.0, 0.1, 0.08);  // the body 8 cm above the bottom, in `water` metres of water
  auto t = tank_config(2, l0, 0.2, water, dt);
  t.effects = c.effects;
  t.body = c.body;
  c = t;
  c.body.release_time = 1.0;
  c.pressure_gradient = form;
  c.ghost_interpolation = ghosts;
  c.surface_detection = surface;
  c.alpha = alpha;
  ip::Isph<double, 2> m(c);
  double sum = 0.0;
  int n = 0;
  const int steps = static_cast<int>(std::lround(0.4 / c.dt));
  for (int k = 0; k < steps; ++k) {
    m.step();
    if (!m.health().finite) return 1e300;
    if (k >= steps / 2) {
      sum += m.body().force[1];
      ++n;
    }
  }
  return sum / n;
}

TEST(IsphBody, ImmersedBodyForceIsTheBuoyancy) {
  const double buoy = 1000.0 * 9.8 * 3.14159265358979323846 * 0.03 * 0.03;
  const double diff = held_body_force(ip::PressureGradient::difference, ip::GhostInterpolation::linear) / buoy - 1;
  const double paper = held_body_force(ip::PressureGradient::symmetric, ip::GhostInterpolation::shepard) / buoy - 1;
  std::printf("held immersed body, force / buoyancy - 1: difference form %.4f, the paper's symmetric form %.4f\n", diff,
              paper);
  EXPECT_LT(std::fabs(diff), 0.025);
  EXPECT_GT(paper, 2.0 * std::fabs(diff));
  // the paper's form with the divergence surface and a stronger density relaxation (alpha = 0.1, 20 x
  // Table 1's; the density surface blows up from alpha = 0.02): measured -0.24 % (docs/VALIDATION.md)
  const double relaxed = held_body_force(ip::PressureGradient::symmetric, ip::GhostInterpolation::shepard, 0.16, 0.01, 1e-3,
                                         ip::SurfaceDetection::divergence, 0.1) / buoy - 1;
  std::printf("held immersed body, the paper's form, divergence surface, alpha = 0.1: %.4f\n", relaxed);
  EXPECT_LT(std::fabs(relaxed), 0.015);
}

// The table of docs/VALIDATION.md (about 12 min with its three columns; not run by ctest):
//   build/ci/tests/isph/test_isph_body --gtest_also_run_disabled_tests --gtest_filter='*HeldBodyForceTable*'
TEST(IsphBody, DISABLED_HeldBodyForceTable) {
  const double buoy = 1000.0 * 9.8 * 3.14159265358979323846 * 0.03 * 0.03;
  const double cases[8][3] = {{0.16, 0.01, 1e-3},  {0.16, 0.01, 5e-4},  {0.23, 0.01, 1e-3},   {0.23, 0.01, 5e-4},
                              {0.30, 0.01, 1e-3},  {0.30, 0.01, 5e-4},  {0.16, 0.005, 5e-4}, {0.16, 0.005, 2.5e-4}};
  std::printf("| water [m] | l0 [m] | dt [s] | the paper's form | difference form | the paper's form, divergence surface |\n");
  for (const auto& k : cases) {
    const double paper =
        held_body_force(ip::PressureGradient::symmetric, ip::GhostInterpolation::shepard, k[0], k[1], k[2]);
    const double diff = held_body_force(ip::PressureGradient::difference, ip::GhostInterpolation::linear, k[0], k[1], k[2]);
    const double divr = held_body_force(ip::PressureGradient::symmetric, ip::GhostInterpolation::shepard, k[0], k[1], k[2],
                                        ip::SurfaceDetection::divergence);
    auto cell = [&](double f) {
      char b[64];
      if (f > 1e100)
        std::snprintf(b, sizeof b, "diverged");
      else
        std::snprintf(b, sizeof b, "%+.2f %%", 100 * (f / buoy - 1));
      return std::string(b);
    };
    std::printf("| %.2f | %.3f | %.2g | %s | %s | %s |\n", k[0], k[1], k[2], cell(paper).c_str(), cell(diff).c_str(),
                cell(divr).c_str());
    std::fflush(stdout);
  }
}

// A cylinder held with its lowest point on the free surface (floating_cylinder_small at D/l0 = 4): the top
// layer of water compacts onto the one below until its summation density hovers at the surface threshold
// (0.95 rho0); with the density test a stretch of it then loses its p = 0 (no surface particle above
// it), its pressure swings from step to step with growing amplitude and the water blows up at about
// 0.7 s (measured: max speed 5.8 m/s at 0.8 s, 8 983 put-backs by 3 s; docs/VALIDATION.md). With the
// divergence-of-position test (SurfaceDetection::divergence) the top layer stays flagged and the water
// settles (0.10 m/s at 0.7 s, 0.02 m/s at 3 s).
static double held_at_surface_max_speed(ip::SurfaceDetection surface, double until) {
  auto c = tank_config(2, 0.025, 0.5, 0.3, 1e-3);
  c.tank[1] = 0.45;
  c.surface_threshold = 0.95;
  c.surface_detection = surface;
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization", "rigid_body"}, ip::effect_table());
  c.body.diameter = 0.1;
  c.body.centre[0] = 0.25;
  c.body.centre[1] = 0.35;
  c.body.density_ratio = 0.8;
  c.body.release_time = 100.0;  // held
  ip::Isph<double, 2> m(c);
  double vmax = 0.0;
  const int steps = static_cast<int>(std::lround(until / c.dt));
  for (int k = 0; k < steps; ++k) {
    m.step();
    if (!m.health().finite) return 1e300;
    if (k >= steps - 100) {  // the last 0.1 s
      const auto v = m.host_velocities();
      for (std::size_t i = 0; i < v.size() / 2; ++i) vmax = std::max(vmax, std::hypot(v[2 * i], v[2 * i + 1]));
    }
  }
  return vmax;
}

TEST(IsphBody, HeldAtTheSurfaceStaysCalmWithTheDivergenceSurface) {
  const double divr = held_at_surface_max_speed(ip::SurfaceDetection::divergence, 0.9);
  std::printf("held at the surface, max speed over 0.8-0.9 s: %.3f m/s (divergence surface)\n", divr);
  EXPECT_LT(divr, 0.3);  // measured 0.15
}
// The density test on the same case (not run by ctest; --gtest_also_run_disabled_tests).
TEST(IsphBody, DISABLED_HeldAtTheSurfaceWithTheDensitySurface) {
  const double dens = held_at_surface_max_speed(ip::SurfaceDetection::density, 0.9);
  std::printf("held at the surface, max speed over 0.8-0.9 s: %.3f m/s (density surface)\n", dens);
}

// A neutrally buoyant cylinder (density ratio 1) placed in the water stays near where it is put:
// released at 0.1 s, 0.3 s later; the drift in cylinder diameters.
static double neutral_drift(ip::PressureGradient form, ip::GhostInterpolation ghosts) {
  auto c = body_config(1.0, 0.1, 0.08);
  c.pressure_gradient = form;
  c.ghost_interpolation = ghosts;
  ip::Isph<double, 2> m(c);
  for (int k = 0; k < 400; ++k) {
    m.step();
    if (!m.health().finite) return 1e300;
    if (std::getenv("ISPH_TRACE") && k % 20 == 0)
      std::printf("t %.3f c (%.4f, %.4f) v (%.4f, %.4f) F (%.3f, %.3f) weight %.3f\n", m.time(), m.body().centre[0],
                  m.body().centre[1], m.body().v[0], m.body().v[1], m.body().force[0], m.body().force[1],
                  m.body_properties().mass * 9.8);
  }
  const auto& b = m.body();
  return std::hypot(b.centre[0] - 0.1, b.centre[1] - 0.08) / 0.06;
}

TEST(IsphBody, NeutralBuoyancyStaysPut) {
  const double paper = neutral_drift(ip::PressureGradient::symmetric, ip::GhostInterpolation::shepard);
  const double diff = neutral_drift(ip::PressureGradient::difference, ip::GhostInterpolation::linear);
  std::printf("neutral body after 0.3 s: drift %.3f D (the paper's form), %.3f D (difference form)\n", paper, diff);
  // Measured 0.068 D (the paper's form: its +4 % buoyancy lifts the body) and 0.009 D (difference form),
  // docs/VALIDATION.md. The paper form's bound catches the coupling instability (plain CSS, added_mass = 0: 2 D).
  EXPECT_LT(paper, 0.1);
  EXPECT_LT(diff, 0.03);
}

// A body heavier than the water (density ratio 2) released just above the tank's bottom sinks onto it and
// rests there through the shared Hertz-Mindlin contact (kernels/contact/hertz_mindlin.hpp): it does not
// pass through the bottom, comes to rest, and the bottom carries at least its weight less its buoyancy.
// Measured (1 thread, the paper's form): lowest gap -0.33 l0 while landing, -0.16 l0 at rest, contact force
// 85 N/m against the net weight 27.7 N/m: the particles are squeezed out of the strip where the gap under
// the body is below ~l0 (|x| < sqrt(2 R l0) = 2.4 cm), so the water presses on the body's top and not its
// bottom (a sealed contact at this resolution). The difference form (pressure_gradient = "difference",
// linear ghosts): contact force 26.0 N/m, gap -0.19 l0 landing, -0.07 l0 at rest (docs/VALIDATION.md).
TEST(IsphBody, HeavyBodyRestsOnTheBottomWithoutPassingThrough) {
  auto c = body_config(2.0, 0.1, 0.035);  // R = 0.03: 5 mm above the bottom
  c.body.release_time = 0.05;
  ip::Isph<double, 2> m(c);
  const double l0 = c.spacing, R = 0.03;
  double lowest = 1e300, contact_sum = 0.0;
  int contact_n = 0;
  for (int k = 0; k < 500; ++k) {
    m.step();
    ASSERT_TRUE(m.health().finite) << m.health().problem;
    lowest = std::min(lowest, m.body().centre[1] - R);
    if (k >= 400) {
      contact_sum += m.body().contact_force[1];
      ++contact_n;
    }
  }
  const auto& b = m.body();
  const double pi = 3.14159265358979323846;
  const double net = (2.0 - 1.0) * c.density * c.gravity * pi * R * R;
  const double contact = contact_sum / contact_n;
  std::printf("heavy body: lowest gap %.3g m (%.3f l0), final gap %.3g m, speed %.3g m/s, contact force %.2f N/m "
              "(weight - buoyancy %.2f N/m), moved sideways %.3g m\n",
              lowest, lowest / l0, b.centre[1] - R, std::hypot(b.v[0], b.v[1]), contact, net, b.centre[0] - 0.1);
  EXPECT_GT(lowest, -0.5 * l0);                    // never through the bottom
  EXPECT_LT(b.centre[1] - R, 0.05 * l0);           // resting on it
  EXPECT_LT(std::hypot(b.v[0], b.v[1]), 0.02);     // at rest
  EXPECT_GT(contact, 0.9 * net);                   // carried by the bottom
  EXPECT_LT(contact, 4.0 * net);
}

// The water laid around an immersed body (Body::fluid_clearance, fluid_rings; docs/METHODS.md, "The water
// around an immersed body"): the summation density beside the body at the start. A cylinder of D = 20 l0 at
// mid-depth, on the lattice offsets of scenes/isph/cylinder_neutral.toml at l0 = 5 mm, where the old cut at
// R + l0/2 left 7 % of the density missing beside it (and, with the divergence surface and alpha = 0.1, blew up).
TEST(IsphBody, WaterAroundAnImmersedBodyStartsAtFullDensity) {
  auto density_beside = [](int rings, double clearance) {
    auto c = tank_config(2, 0.005, 0.3, 0.2, 5e-4);
    c.effects = pm::EffectSet::resolve({"viscosity", "stabilization", "rigid_body"}, ip::effect_table());
    c.body.diameter = 0.1;
    c.body.centre[0] = 0.15;
    c.body.centre[1] = 0.1;
    c.body.density_ratio = 1.0;
    c.body.release_time = 1.0;
    c.body.fluid_rings = rings;
    c.body.fluid_clearance = clearance;
    ip::Isph<double, 2> m(c);
    m.step();  // the density of the step is that of the initial layout
    const auto x = m.host_positions();
    const auto rho = m.host_density();
    double lo = 1e300, sum = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < rho.size(); ++i) {
      const double r = std::hypot(x[2 * i] - 0.15, x[2 * i + 1] - 0.1);
      EXPECT_GE(r, 0.05) << "particle " << i << " inside the body";
      if (r > 0.05 + 2 * 0.005) continue;
      lo = std::min(lo, rho[i]);
      sum += rho[i];
      ++n;
    }
    std::printf("rings %d, clearance %.1f l0: %d particles within 2 l0 of the body, density min %.1f, mean %.1f\n", rings,
                clearance, n, lo, sum / n);
    return std::make_pair(lo / 1000.0, sum / n / 1000.0);
  };
  const auto plain = density_beside(0, 0.0), rings = density_beside(2, 0.0), old = density_beside(0, 0.5);
  // measured: min / mean 0.899 / 0.990 (default), 0.965 / 1.023 (two rings), 0.859 / 0.932 (the old cut)
  EXPECT_GT(plain.first, 0.88);
  EXPECT_NEAR(plain.second, 1.0, 0.015);
  EXPECT_GT(rings.first, 0.95);
  EXPECT_NEAR(rings.second, 1.0, 0.03);
  EXPECT_LT(old.first, 0.87);  // the gap of the old layout
  EXPECT_LT(old.second, 0.95);
}
