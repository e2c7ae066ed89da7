// The incompressible flow model (issue 36; models/flow): Taylor-Hood Q2/Q1, Newton, BDF2, the reaction forces.
// - Poiseuille flow is in the discrete space (velocity quadratic in y, pressure linear in x, the cells bilinear:
//   Q2 holds y^2 on any bilinear cell, not on a curved one): reproduced to round-off with the do-nothing outflow;
// - Kovasznay's exact Navier-Stokes solution at Re = 40 on curved meshes: L2 errors of order 3 (velocity) and
//   2 (pressure), the divergence's L2 norm of order 2;
// - Turek-Hron CFD1 (Re 20) on the two coarsest channel meshes: drag and lift against the reference, the error
//   falling with the level; the mass balance (outflow = inflow) to solver accuracy;
// - BDF2's second order in time on a ramped start-up; bad input refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/navier_stokes.hpp"
#include "flow/turek_hron.hpp"

namespace fl = polymech::flow;

namespace {

double max_abs(double a, double b) { return std::max(std::abs(a), std::abs(b)); }

// Poiseuille: u = 4 Umax y (H - y) / H^2, p = 8 mu Umax (L - x) / H^2 (zero at the do-nothing outflow).
TEST(Flow, PoiseuilleIsReproducedToRoundOff) {
  const double L = 2.0, H = 1.0, Umax = 1.5, rho = 2.0, nu = 0.25, mu = rho * nu;
  for (const double distortion : {0.0, 0.2}) {
    fl::FlowConfig c;
    c.rho = rho;
    c.nu = nu;
    c.dirichlet_tags = fl::kInflow | fl::kWall;
    c.boundary_velocity = [&](unsigned tags, double, double y, double) -> fl::Vec2 {
      if (tags & fl::kWall) return {0.0, 0.0};
      return {4 * Umax * y * (H - y) / (H * H), 0.0};
    };
    fl::QuadMesh mesh = fl::make_rectangle(0, 0, L, H, 4, 3, distortion);
    fl::make_bilinear(mesh);  // bilinear cells: y^2 is in the isoparametric Q2 space (not on curved cells)
    fl::NavierStokes2D ns(mesh, c);
    const auto r = ns.solve_steady();
    ASSERT_TRUE(r.converged);
    double eu = 0.0, ep = 0.0;
    const auto& U = ns.state();
    for (std::int64_t n = 0; n < ns.velocity_nodes(); ++n) {
      const double x = ns.mesh().x[2 * n], y = ns.mesh().x[2 * n + 1];
      eu = std::max(eu, max_abs(U[2 * n] - 4 * Umax * y * (H - y) / (H * H), U[2 * n + 1]));
      const std::int64_t pd = ns.pressure_dof_of_node(n);
      if (pd >= 0) ep = std::max(ep, std::abs(U[pd] - 8 * mu * Umax * (L - x) / (H * H)));
    }
    std::printf("Poiseuille, distortion %.1f: max nodal error u %.2e, p %.2e\n", distortion, eu, ep);
    // measured (Intel Xeon, AVX-512, this machine): u 5.6e-16 / 7.9e-16, p 5.3e-15 / 2.7e-15 (straight / distorted)
    EXPECT_LT(eu, 1e-12 * Umax) << "distortion " << distortion;
    EXPECT_LT(ep, 1e-12 * 8 * mu * Umax * L / (H * H)) << "distortion " << distortion;
    EXPECT_LT(ns.divergence_l2(), 1e-12);
  }
}

// Kovasznay (1948): u = 1 - e^(l x) cos(2 pi y), v = l / (2 pi) e^(l x) sin(2 pi y), p = (1 - e^(2 l x)) / 2
// (rho = 1), l = Re / 2 - sqrt(Re^2 / 4 + 4 pi^2), nu = 1 / Re; on [-0.5, 1] x [-0.5, 1.5], every side Dirichlet,
// the pressure fixed at one vertex.
struct KovasznayErrors {
  double u = 0.0, p = 0.0, div = 0.0;
};
KovasznayErrors kovasznay(int k, double distortion) {
  const double Re = 40.0, pi = 3.14159265358979323846, lam = Re / 2 - std::sqrt(Re * Re / 4 + 4 * pi * pi);
  auto exact = [=](double x, double y, double& u, double& v, double& p) {
    u = 1 - std::exp(lam * x) * std::cos(2 * pi * y);
    v = lam / (2 * pi) * std::exp(lam * x) * std::sin(2 * pi * y);
    p = 0.5 * (1 - std::exp(2 * lam * x));
  };
  fl::FlowConfig c;
  c.rho = 1.0;
  c.nu = 1.0 / Re;
  c.dirichlet_tags = fl::kInflow | fl::kWall | fl::kOutflow;
  c.boundary_velocity = [=](unsigned, double x, double y, double) -> fl::Vec2 {
    double u, v, p;
    exact(x, y, u, v, p);
    return {u, v};
  };
  c.pin_pressure = true;
  c.pin_point = {-0.5, -0.5};
  double u0, v0, p0;
  exact(-0.5, -0.5, u0, v0, p0);
  c.pin_value = p0;
  fl::NavierStokes2D ns(fl::make_rectangle(-0.5, -0.5, 1.5, 2.0, 3 * k, 4 * k, distortion), c);
  const auto r = ns.solve_steady();
  EXPECT_TRUE(r.converged) << k;
  KovasznayErrors e;
  e.u = std::sqrt(ns.integrate([&](const fl::NavierStokes2D::PointValue& pv) {
    double u, v, p;
    exact(pv.x[0], pv.x[1], u, v, p);
    return (pv.u[0] - u) * (pv.u[0] - u) + (pv.u[1] - v) * (pv.u[1] - v);
  }));
  e.p = std::sqrt(ns.integrate([&](const fl::NavierStokes2D::PointValue& pv) {
    double u, v, p;
    exact(pv.x[0], pv.x[1], u, v, p);
    return (pv.p - p) * (pv.p - p);
  }));
  e.div = ns.divergence_l2();
  return e;
}

TEST(Flow, KovasznayConvergesAtTaylorHoodRates) {
  std::vector<KovasznayErrors> e;
  for (const int k : {2, 4, 8}) e.push_back(kovasznay(k, 0.15));
  for (std::size_t i = 1; i < e.size(); ++i) {
    const double ru = std::log2(e[i - 1].u / e[i].u), rp = std::log2(e[i - 1].p / e[i].p),
                 rd = std::log2(e[i - 1].div / e[i].div);
    std::printf("Kovasznay: h / %d: |u - u_h| %.3e (rate %.2f), |p - p_h| %.3e (rate %.2f), |div u_h| %.3e (rate %.2f)\n",
                1 << (i + 1), e[i].u, ru, e[i].p, rp, e[i].div, rd);
    // measured (Intel Xeon, AVX-512, this machine): see docs/VALIDATION.md
    EXPECT_GT(ru, 2.7);
    EXPECT_GT(rp, 1.8);
    EXPECT_GT(rd, 1.7);
  }
}

TEST(Flow, TurekHronCfd1CoarseMeshes) {
  const fl::TurekHronReference ref = fl::turek_hron_reference(1);
  double previous = 1e300;
  for (const int level : {0, 1}) {
    fl::TurekHronCase tc;
    tc.mean_velocity = 0.2;
    tc.level = level;
    fl::NavierStokes2D ns(fl::make_turek_hron_channel(level), fl::turek_hron_config(tc));
    const auto r = ns.solve_steady();
    ASSERT_TRUE(r.converged) << level;
    const double ed = std::abs(ns.forces().drag / ref.drag - 1), el = std::abs(ns.forces().lift / ref.lift - 1);
    std::printf("CFD1 level %d: %lld unknowns, drag %.4f (%.3f %%), lift %.4f (%.3f %%)\n", level,
                static_cast<long long>(ns.unknowns()), ns.forces().drag, 100 * ed, ns.forces().lift, 100 * el);
    // measured (Intel Xeon, AVX-512, this machine): level 0 drag -1.35 %, lift -1.92 %; level 1 -0.25 %, -0.47 %; level 2 -0.09 %,
    // -0.18 % (the reference's 4 digits, 14.29 and 1.119, are good to 0.04 % and 0.05 %). Asserted: the level's
    // error with a margin of about 1.5x, and its decrease.
    EXPECT_LT(ed, level == 0 ? 0.02 : 0.004);
    EXPECT_LT(el, level == 0 ? 0.03 : 0.008);
    EXPECT_LT(ed, previous);
    previous = ed;
    // mass balance: the discrete velocity is weakly divergence-free (tested with every Q1 function, whose sum
    // is one), so the outflow equals the inflow to the solver's accuracy
    const double in = ns.flux_through(fl::kInflow), out = ns.flux_through(fl::kOutflow);
    EXPECT_NEAR(in, 0.2 * 0.41, 1e-12);  // Ubar H: the parabola is in the space, Gauss exact
    EXPECT_NEAR(out / in, 1.0, 1e-9) << level;
  }
}

// The ring graded towards the circle (TurekHronGeometry::ring_grading, the map (exp(a t) - 1) / (exp(a) - 1)): the
// planes nest under refinement (a mesh family), and CFD2 at level 1 with a = 1 is within 0.3 % in drag where the
// uniform level 1 is 2.9 % off (measured, Intel Xeon: -0.290 %, lift +2.46 %; level 2 -0.002 %, -0.70 %).
TEST(Flow, GradedRingNestsAndImprovesCfd2Drag) {
  const auto p4 = fl::graded_planes(4, 1.0), p8 = fl::graded_planes(8, 1.0);
  ASSERT_EQ(p4.size(), 5u);
  EXPECT_EQ(p4.front(), 0.0);
  EXPECT_EQ(p4.back(), 1.0);
  for (std::size_t k = 1; k < p4.size(); ++k) {
    EXPECT_GT(p4[k] - p4[k - 1], p4[k > 1 ? k - 1 : 0] - p4[k > 1 ? k - 2 : 0] - 1e-15);  // growing cells
    EXPECT_NEAR(p8[2 * k], p4[k], 1e-15);                                                     // nested
  }
  EXPECT_EQ(fl::graded_planes(4, 0.0), fl::uniform_planes(4));
  const fl::TurekHronReference ref = fl::turek_hron_reference(2);
  fl::TurekHronCase tc;
  tc.mean_velocity = 1.0;
  tc.level = 1;
  fl::TurekHronGeometry g;
  g.ring_grading = 1.0;
  fl::FlowConfig cfg = fl::turek_hron_config(tc, g);
  cfg.picard_steps = 3;
  fl::NavierStokes2D ns(fl::make_turek_hron_channel(1, g), cfg);
  ASSERT_TRUE(ns.solve_steady().converged);
  EXPECT_LT(std::abs(ns.forces().drag / ref.drag - 1), 0.005);
  EXPECT_LT(std::abs(ns.forces().lift / ref.lift - 1), 0.04);
}

// BDF2 on a start-up: the channel of the Poiseuille test with the inflow ramped in as (1 - cos(pi t)) / 2; the
// velocity at the channel's centre at t = 0.5 converges at order 2 in dt (differences of successive halvings).
TEST(Flow, Bdf2IsSecondOrderInTime) {
  auto run = [](double dt, bool chord = false) {
    fl::FlowConfig c;
    c.chord = chord;
    c.rho = 1.0;
    c.nu = 0.1;
    c.dirichlet_tags = fl::kInflow | fl::kWall;
    c.boundary_velocity = [](unsigned tags, double, double y, double t) -> fl::Vec2 {
      if (tags & fl::kWall) return {0.0, 0.0};
      const double pi = 3.14159265358979323846;
      return {0.5 * (1 - std::cos(pi * t)) * 6 * y * (1 - y), 0.3 * std::sin(pi * t) * y * (1 - y)};
    };
    fl::NavierStokes2D ns(fl::make_rectangle(0, 0, 2.0, 1.0, 4, 2, 0.1), c);
    const int steps = static_cast<int>(std::lround(0.5 / dt));
    for (int k = 0; k < steps; ++k) EXPECT_TRUE(ns.step(dt).converged);
    double best = 1e300, value = 0.0;
    for (std::int64_t n = 0; n < ns.velocity_nodes(); ++n) {
      const double d = std::hypot(ns.mesh().x[2 * n] - 1.0, ns.mesh().x[2 * n + 1] - 0.5);
      if (d < best) best = d, value = ns.state()[2 * n + 1];
    }
    return value;
  };
  const double a = run(0.025), b = run(0.0125), c = run(0.00625);
  const double rate = std::log2(std::abs(a - b) / std::abs(b - c));
  std::printf("BDF2: v(1, 0.5, t = 0.5) %.9f %.9f %.9f, rate %.2f\n", a, b, c, rate);
  EXPECT_GT(rate, 1.8);
  EXPECT_LT(rate, 2.3);
  // the chord iteration (one factorisation per step) converges to the same states
  EXPECT_NEAR(run(0.025, true), a, 1e-9 * std::abs(a));
}

TEST(Flow, BadInputIsRefused) {
  fl::FlowConfig c;
  EXPECT_THROW(fl::make_turek_hron_channel(-1), std::invalid_argument);
  EXPECT_THROW(fl::make_turek_hron_channel(7), std::invalid_argument);
  EXPECT_THROW(fl::make_rectangle(0, 0, 1, 1, 0, 1), std::invalid_argument);
  EXPECT_THROW(fl::turek_hron_reference(4), std::invalid_argument);
  fl::TurekHronCase tc;
  tc.mean_velocity = -1.0;
  EXPECT_THROW(fl::turek_hron_config(tc), std::invalid_argument);
  c.nu = 0.0;
  EXPECT_THROW(fl::NavierStokes2D(fl::make_rectangle(0, 0, 1, 1, 2, 2), c), std::invalid_argument);
  c.nu = 1.0;
  fl::QuadMesh inverted = fl::make_rectangle(0, 0, 1, 1, 2, 2);
  for (int j = 0; j < 3; ++j) std::swap(inverted.elements[3 * j], inverted.elements[3 * j + 2]);  // element 0 mirrored
  try {
    fl::NavierStokes2D ns(inverted, c);
    ADD_FAILURE() << "an inverted element was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("element 0 is inverted"), std::string::npos) << e.what();
  }
  fl::NavierStokes2D ns(fl::make_rectangle(0, 0, 1, 1, 2, 2), c);
  EXPECT_THROW(ns.step(0.0), std::invalid_argument);
}

}  // namespace
