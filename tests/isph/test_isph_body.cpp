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
static double held_at_surface_max_speed(ip::SurfaceDetection surface, double until, double alpha = 5e-3) {
  auto c = tank_config(2, 0.025, 0.5, 0.3, 1e-3);
  c.alpha = alpha;
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
  // either test, with alpha = 0.1 as in the scenes that use it: measured 0.065 m/s. With the paper's alpha
  // (5e-3) the union blows up like the density test (3.5 m/s): the weak relaxation leaves water below the
  // top layer under 0.95 rho0, the density test gives it p = 0 inside the water.
  const double either = held_at_surface_max_speed(ip::SurfaceDetection::divergence_or_density, 0.9, 0.1);
  std::printf("held at the surface, max speed over 0.8-0.9 s: %.3f m/s (divergence or density)\n", either);
  EXPECT_LT(either, 0.3);
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
// A body released onto the tank's bottom: run `steps` steps (stopping on the first non-finite state) and
// measure the lowest gap between body and bottom over the run, the contact force averaged over the last
// `average` steps, the final gap, speed and sideways move. R = 0.03, started at x = 0.1 (body_config).
// Over the last `average` steps (the window) also the body's mean and largest speed and its largest gap: a
// landing in agitated water is chaotic (round-off of another CPU's vector width or FMA gives another
// trajectory, issue 31), so its assertions bound what holds over a window, not a snapshot.
struct Landing {
  bool finite = true;
  std::string problem;
  double lowest = 1e300, contact = 0.0, gap = 0.0, speed = 0.0, sideways = 0.0, net_weight = 0.0;
  double window_speed_mean = 0.0, window_speed_max = 0.0, window_gap_max = -1e300;
};
static Landing land(const ip::Config& c, int steps, int average) {
  ip::Isph<double, 2> m(c);
  const double R = 0.03;
  Landing r;
  double contact_sum = 0.0, speed_sum = 0.0;
  for (int k = 0; k < steps; ++k) {
    m.step();
    if (!m.health().finite) {
      r.finite = false;
      r.problem = m.health().problem;
      return r;
    }
    r.lowest = std::min(r.lowest, m.body().centre[1] - R);
    if (k >= steps - average) {
      const auto& b = m.body();
      const double speed = std::hypot(b.v[0], b.v[1]);
      contact_sum += b.contact_force[1];
      speed_sum += speed;
      r.window_speed_max = std::max(r.window_speed_max, speed);
      r.window_gap_max = std::max(r.window_gap_max, b.centre[1] - R);
    }
  }
  const auto& b = m.body();
  r.contact = contact_sum / average;
  r.window_speed_mean = speed_sum / average;
  r.gap = b.centre[1] - R;
  r.speed = std::hypot(b.v[0], b.v[1]);
  r.sideways = b.centre[0] - 0.1;
  r.net_weight = (c.body.density_ratio - 1.0) * c.density * c.gravity * 3.14159265358979323846 * R * R;
  return r;
}

TEST(IsphBody, HeavyBodyRestsOnTheBottomWithoutPassingThrough) {
  auto c = body_config(2.0, 0.1, 0.035);  // R = 0.03: 5 mm above the bottom
  c.body.release_time = 0.05;
  const double l0 = c.spacing;
  const auto r = land(c, 500, 100);
  ASSERT_TRUE(r.finite) << r.problem;
  std::printf("heavy body: lowest gap %.3g m (%.3f l0), final gap %.3g m, speed %.3g m/s, contact force %.2f N/m "
              "(weight - buoyancy %.2f N/m), moved sideways %.3g m\n",
              r.lowest, r.lowest / l0, r.gap, r.speed, r.contact, r.net_weight, r.sideways);
  EXPECT_GT(r.lowest, -0.5 * l0);               // never through the bottom
  EXPECT_LT(r.gap, 0.05 * l0);                  // resting on it
  EXPECT_LT(r.speed, 0.02);                     // at rest
  EXPECT_GT(r.contact, 0.9 * r.net_weight);     // carried by the bottom
  EXPECT_LT(r.contact, 4.0 * r.net_weight);
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

// The hard cases of the body's density: ratio 0.3 (floats high, two thirds of it in the air) and
// ratio 3 (falls through the water and lands hard on the bottom), with the choices that meet the floating
// targets with alpha = 0.1 and the surface by either test (SurfaceDetection::divergence_or_density: the
// divergence test alone blows up when the dense body lands at D/l0 = 10, scenes/isph/cylinder_dense.toml)
// and with the paper's (density surface, alpha = 5e-3). Reduced: D = 6 l0 in a 0.3 m (light) / 0.2 m (dense) wide tank at
// l0 = 1 cm; full size (D/l0 = 10, 6 s): scenes/isph/cylinder_light.toml, cylinder_dense.toml and
// docs/VALIDATION.md.
namespace {

struct LightRun {
  double draft = 0.0;  // over D, from the water's volume, averaged over the last 0.5 s
  double max_speed = 0.0;
  bool finite = true;
};

LightRun light_body(ip::SurfaceDetection surface, double alpha) {
  auto c = tank_config(2, 0.01, 0.3, 0.16, 1e-3);
  c.tank[1] = 0.3;
  c.surface_detection = surface;
  c.alpha = alpha;
  c.effects = pm::EffectSet::resolve({"viscosity", "stabilization", "rigid_body"}, ip::effect_table());
  c.body.diameter = 0.06;
  c.body.centre[0] = 0.15;
  c.body.centre[1] = 0.19;  // lowest point on the surface
  c.body.density_ratio = 0.3;
  c.body.release_time = 0.0;
  ip::Isph<double, 2> m(c);
  const double R = 0.03, W = 0.3, water = double(m.particles()) * c.spacing * c.spacing;
  LightRun r;
  double sum = 0.0;
  int n = 0;
  for (int k = 0; k < 1500; ++k) {
    m.step();
    if (!m.health().finite) {
      r.finite = false;
      return r;
    }
    if (k < 1000) continue;
    const double bottom = m.body().centre[1] - R;
    double lo = 0.0, hi = 1.0;  // the level of a flat surface holding the water and the body's part below it
    for (int it = 0; it < 80; ++it) {
      const double mid = 0.5 * (lo + hi);
      (W * mid - ip::segment_area(R, mid - bottom) < water ? lo : hi) = mid;
    }
    sum += (0.5 * (lo + hi) - bottom) / (2 * R);
    ++n;
    const auto v = m.host_velocities();
    for (std::size_t i = 0; i < v.size() / 2; ++i) r.max_speed = std::max(r.max_speed, std::hypot(v[2 * i], v[2 * i + 1]));
  }
  r.draft = sum / n;
  return r;
}

}  // namespace

TEST(IsphBody, VeryLightBodyFloatsAtItsDraft) {
  const double arch = ip::archimedes_draft_over_diameter(0.3);
  const auto div = light_body(ip::SurfaceDetection::divergence_or_density, 0.1);
  const auto paper = light_body(ip::SurfaceDetection::density, 5e-3);
  std::printf("density ratio 0.3 (Archimedes %.4f): draft %.4f (%+.1f %%), max speed %.3f m/s (divergence or density, alpha 0.1); "
              "%.4f (%+.1f %%), %.3f m/s (the paper's choices)\n",
              arch, div.draft, 100 * (div.draft / arch - 1), div.max_speed, paper.draft, 100 * (paper.draft / arch - 1),
              paper.max_speed);
  ASSERT_TRUE(div.finite);
  ASSERT_TRUE(paper.finite);
  // measured -6.1 % (divergence or density, alpha 0.1) and -6.7 % (the paper's), 0.05 / 0.09 m/s: at D/l0 = 6
  // the body floats high, as the ratio-0.8 body does at this spacing
  EXPECT_NEAR(div.draft / arch, 1.0, 0.15);
  EXPECT_NEAR(paper.draft / arch, 1.0, 0.15);
  EXPECT_LT(div.max_speed, 0.2);
  EXPECT_LT(paper.max_speed, 0.2);
}

// The contact law's stiffness is set so that an impact at the free-fall speed from the tank's top lasts 20
// steps (Config::Body::contact_modulus = 0); its Hertz overlap at that speed, v t_c / 2.94, is the bound on
// the landing's overlap (1.35 l0 here: soft on purpose, a stiffer contact needs a smaller dt; measured
// 0.50 l0 with the surface by either test and alpha = 0.1, 0.88 l0 with the paper's choices).
TEST(IsphBody, VeryDenseBodyLandsAndRests) {
  for (const bool paper : {false, true}) {
    auto c = body_config(3.0, 0.1, 0.08);  // mid-depth: 5 cm of water under it
    c.body.release_time = 0.05;
    if (!paper) {
      c.surface_detection = ip::SurfaceDetection::divergence_or_density;
      c.alpha = 0.1;
    }
    const auto hertz = ip::body_contact(c);
    const double hertz_overlap = hertz.reference_speed * hertz.contact_time / 2.94;
    const double l0 = c.spacing;
    const auto r = land(c, 1000, 100);
    ASSERT_TRUE(r.finite) << r.problem;
    std::printf("density ratio 3 (%s): lowest gap %.3f l0 (Hertz overlap at the free-fall speed %.2f l0), final gap "
                "%.3f l0, speed %.3g m/s, contact force %.1f N/m (weight - buoyancy %.1f), sideways %.3g m; over the "
                "last 100 steps: speed mean %.3g / max %.3g m/s (free fall %.3g m/s), largest gap %.3f l0\n",
                paper ? "the paper's choices" : "divergence or density, alpha 0.1", r.lowest / l0, hertz_overlap / l0,
                r.gap / l0, r.speed, r.contact, r.net_weight, r.sideways, r.window_speed_mean, r.window_speed_max,
                hertz.reference_speed, r.window_gap_max / l0);
    EXPECT_GT(r.lowest, -hertz_overlap);  // never through the bottom
    if (!paper) {
      // On it over the whole last 100 steps (window), not only at the end: measured -0.149 l0.
      EXPECT_LT(r.window_gap_max, 0.05 * l0);
      // at rest: measured 1.3e-3 / 1.9e-3 m/s (mean / largest over the window), the same in every build
      EXPECT_LT(r.window_speed_max, 0.02);
      // the bottom carries the body: measured 114.6 N/m, mean over the window (the sealed contact, see above)
      EXPECT_GT(r.contact, 0.9 * r.net_weight);
      EXPECT_LT(r.contact, 3.0 * r.net_weight);
    } else {
      // With the paper's choices the water stays agitated after the landing: a chaotic motion, whose value at
      // one step depends on the round-off of the CPU, the build and the thread count (issue 31: the final
      // speed 0.034 m/s with one thread, 0.138 with two, 0.096 built for x86-64-v2, 0.161 on an AVX-512 Xeon).
      // On an AMD EPYC (Zen 5) it does not come to rest: with one thread it bounces on (mean speed 0.11 of the
      // free-fall speed over the window, 0.21 l0 off the bottom), with two the water throws it 3 l0 up (0.72
      // m/s at the end); of six releases 1-3 ms apart on one thread three rest and three bounce (up to 0.26 of
      // the free-fall speed, 0.45 l0 up; docs/VALIDATION.md). At full size this variant diverges. What holds in
      // every build is only that it lands without passing through the bottom (above) and stays finite.
    }
  }
}
