// The analytic bimorph harvester and bender (issue 35; models/piezo/analytic.hpp, materials.hpp): the
// clamped-free eigenvalues against their tabulated values, the mass-normalised modes by quadrature, the
// short- and open-circuit limits of the voltage response, the open-circuit frequency of the modal coupling
// formula and of the multi-mode root search, the optimal load against a numerical search and against 1/(w Cp)
// where that approximation holds, the energy balance of the steady response, series against parallel, the
// static bender against the textbook 3 d31 V L^2 / (2 t^2) and the modal static sum, the PZT-5A data against the
// published stiffness form, and the Erturk & Inman 2009 bimorph against its reported frequencies.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>

#include "piezo/analytic.hpp"
#include "piezo/materials.hpp"

namespace pz = polymech::piezo;

namespace {

// Composite Simpson on [a, b] with n (even) intervals.
template <class F>
double simpson(F&& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double s = f(a) + f(b);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return s * h / 3.0;
}

pz::BimorphSpec dutoit(int modes, double zeta) {
  pz::BimorphSpec s = pz::dutoit_wardle_2007_case();
  s.modes = modes;
  s.zeta = {zeta};
  return s;
}

}  // namespace

TEST(PiezoAnalytic, ClampedFreeEigenvalues) {
  // Tabulated roots of 1 + cos l cosh l = 0 (e.g. Blevins, Formulas for natural frequency and mode shape, table 8-1).
  const double table[4] = {1.87510407, 4.69409113, 7.85475744, 10.99554073};
  for (int r = 1; r <= 4; ++r) {
    const double l = pz::clamped_free_lambda(r);
    EXPECT_NEAR(l, table[r - 1], 1e-7) << "r = " << r;
    EXPECT_NEAR(1.0 + std::cos(l) * std::cosh(l), 0.0, 1e-9 * std::cosh(l));
  }
  // the asymptote (2r - 1) pi / 2, exact to within e^-l
  EXPECT_NEAR(pz::clamped_free_lambda(20), 19.5 * pz::kPi, 1e-11);
}

TEST(PiezoAnalytic, ModesOrthonormalByQuadrature) {
  const pz::BimorphHarvester h(dutoit(8, 0.01));
  const double L = h.spec().L, m = h.mass_per_length();
  for (int r = 0; r < 8; ++r) {
    for (int s = r; s < 8; ++s) {
      const double v = simpson([&](double x) { return m * h.phi(r, x) * h.phi(s, x); }, 0.0, L, 4000);
      EXPECT_NEAR(v, r == s ? 1.0 : 0.0, 1e-9) << r << "," << s;
    }
    // int phi dx: the closed form 2 s_r / l_r (times the normalisation) against quadrature
    const double q = simpson([&](double x) { return h.phi(r, x); }, 0.0, L, 4000);
    EXPECT_NEAR(-h.forcing(r) / m, q, 1e-9 * std::fabs(q) + 1e-12 * std::sqrt(L / m));
    // |phi_r(L)| = 2 / sqrt(m L) for every clamped-free mode, phi(0) = phi'(0) = 0
    EXPECT_NEAR(std::fabs(h.phi_tip(r)) * std::sqrt(m * L), 2.0, 1e-9);
    EXPECT_NEAR(h.phi(r, 0.0), 0.0, 1e-12);
    EXPECT_NEAR(h.dphi(r, 0.0), 0.0, 1e-9 * std::fabs(h.dphi(r, L)));
    // slope against a central difference of the value
    const double x = 0.37 * L, dx = 1e-6 * L;
    EXPECT_NEAR(h.dphi(r, x), (h.phi(r, x + dx) - h.phi(r, x - dx)) / (2 * dx), 1e-6 * std::fabs(h.dphi(r, L)));
  }
}

TEST(PiezoAnalytic, ShortAndOpenCircuitPeaks) {
  const pz::BimorphHarvester h(dutoit(1, 0.002));
  const double w1 = h.omega(0), woc = h.open_circuit_frequency_single_mode(0);
  ASSERT_GT(woc, w1 * 1.01);  // the peaks are told apart: k^2 = 7 % here
  // R -> 0: |V| ~ w R |theta F / D| peaks at the short-circuit frequency (to O(zeta^2))
  const double p0 = pz::peak_frequency(h, 1e-3, 0.9 * w1, 1.1 * w1);
  EXPECT_NEAR(p0 / w1, 1.0, 1e-5);
  const double pI = pz::peak_frequency(h, 0.0, 0.9 * w1, 1.1 * w1);  // R = 0: the current
  EXPECT_NEAR(pI / w1, 1.0, 1e-5);
  // R -> inf: V = -theta F / (Cp D + theta^2) peaks at the open-circuit frequency
  const double pinf = pz::peak_frequency(h, 1e12, 0.9 * w1, 1.2 * w1);
  EXPECT_NEAR(pinf / woc, 1.0, 1e-5);
  const double pInf = pz::peak_frequency(h, INFINITY, 0.9 * w1, 1.2 * w1);
  EXPECT_NEAR(pInf / woc, 1.0, 1e-5);
  // and the limits are approached: 1 ohm and 1e9 ohm give the same peaks to 1e-5
  EXPECT_NEAR(pz::peak_frequency(h, 1.0, 0.9 * w1, 1.1 * w1) / w1, 1.0, 1e-5);
  EXPECT_NEAR(pz::peak_frequency(h, 1e9, 0.9 * w1, 1.2 * w1) / woc, 1.0, 1e-5);
  std::printf("duToit (b = 6.4 mm): f_sc %.4f Hz, f_oc %.4f Hz, k^2 %.5f, Cp %.4e F\n", w1 / (2 * pz::kPi),
              woc / (2 * pz::kPi), h.coupling_k2(0), h.capacitance());
}

TEST(PiezoAnalytic, OpenCircuitFrequencies) {
  const pz::BimorphHarvester h1(dutoit(1, 0.01));
  const auto oc1 = h1.open_circuit_frequencies();
  ASSERT_EQ(oc1.size(), 1u);
  EXPECT_NEAR(oc1[0] / h1.open_circuit_frequency_single_mode(0), 1.0, 1e-12);
  // the modal coupling formula: (w_oc / w_sc)^2 - 1 = theta^2 / (Cp w^2), from the constants directly
  const auto& s = h1.spec();
  const double vartheta = s.piezo.e31 * s.b * (s.hp + s.hs) / 2, Cp = s.piezo.eps33 * s.b * s.L / (2 * s.hp);
  const double theta = vartheta * h1.dphi(0, s.L);  // theta_1 = vartheta phi_1'(L)
  EXPECT_NEAR(std::pow(oc1[0] / h1.omega(0), 2) - 1.0, theta * theta / (Cp * h1.omega(0) * h1.omega(0)), 1e-10);
  // four modes: one open-circuit frequency in each (w_r, w_r+1); the modes above load the first one like a
  // capacitance and lower it below the single-mode value (the modes below raise the higher ones: within 1 %)
  const pz::BimorphHarvester h4(dutoit(4, 0.01));
  const auto oc4 = h4.open_circuit_frequencies();
  ASSERT_EQ(oc4.size(), 4u);
  for (int r = 0; r < 4; ++r) {
    EXPECT_GT(oc4[r], h4.omega(r));
    if (r < 3) {
      EXPECT_LT(oc4[r], h4.omega(r + 1));
    }
    EXPECT_NEAR(oc4[r] / h4.open_circuit_frequency_single_mode(r), 1.0, 0.01);
  }
  EXPECT_LT(oc4[0], oc1[0]);
  EXPECT_NEAR(oc4[0] / oc1[0], 1.0, 5e-3);
  std::printf("duToit open circuit: single mode %.4f Hz, 4 modes %.4f %.2f %.2f %.2f Hz\n", oc1[0] / (2 * pz::kPi),
              oc4[0] / (2 * pz::kPi), oc4[1] / (2 * pz::kPi), oc4[2] / (2 * pz::kPi), oc4[3] / (2 * pz::kPi));
  // the 4-mode open-circuit voltage peaks there too (light damping)
  const pz::BimorphHarvester h4l(dutoit(4, 0.002));
  const auto oc4l = h4l.open_circuit_frequencies();
  EXPECT_NEAR(pz::peak_frequency(h4l, INFINITY, 0.9 * oc4l[0], 1.1 * oc4l[0]) / oc4l[0], 1.0, 1e-5);
  EXPECT_NEAR(pz::peak_frequency(h4l, INFINITY, 0.97 * oc4l[1], 1.03 * oc4l[1]) / oc4l[1], 1.0, 1e-5);
}

TEST(PiezoAnalytic, OpenCircuitModalSumConvergesToTheContinuum) {
  // The exact open-circuit frequency (the tip rotational spring vartheta^2/Cp, an independent continuum
  // solution) against the N-mode root search: decreasing in N, the gap falling like 1/N.
  for (auto c : {pz::Connection::series, pz::Connection::parallel}) {
    pz::BimorphSpec s = dutoit(1, 0.01);
    s.connection = c;
    double exact[2], prev_gap = 1e300;
    for (int r = 0; r < 2; ++r) exact[r] = pz::BimorphHarvester(s).open_circuit_frequency_exact(r);
    for (int N : {2, 5, 15, 45}) {
      s.modes = N;
      const pz::BimorphHarvester h(s);
      const auto oc = h.open_circuit_frequencies();
      const double gap = oc[0] / exact[0] - 1.0;
      EXPECT_GT(gap, 0.0) << N;
      EXPECT_LT(gap, prev_gap) << N;
      EXPECT_LT(gap * N, 0.01) << N;  // ~1/N tail
      prev_gap = gap;
      EXPECT_NEAR(oc[1] / exact[1], 1.0, 0.02 / N) << N;
    }
    EXPECT_LT(prev_gap, 2e-4);
    // no coupling: the exact open-circuit frequency is the short-circuit one
    pz::BimorphSpec z = dutoit(1, 0.01);
    z.piezo.e31 = 0.0;
    EXPECT_NEAR(pz::BimorphHarvester(z).open_circuit_frequency_exact(0) / pz::BimorphHarvester(z).omega(0), 1.0,
                1e-12);
  }
}

TEST(PiezoAnalytic, OptimalLoad) {
  const pz::BimorphHarvester h(dutoit(1, 0.01));
  const double w1 = h.omega(0), woc = h.open_circuit_frequencies()[0];
  for (double w : {w1, woc, 0.5 * (w1 + woc)}) {
    const double Rc = h.optimal_load(w);
    const double Rn = pz::optimal_load_numeric(h, w, 1.0, 1e9);
    EXPECT_NEAR(Rn / Rc, 1.0, 1e-5) << "w = " << w;
    const double P = h.response(w, Rc).power;
    EXPECT_GT(P, h.response(w, 0.95 * Rc).power);
    EXPECT_GT(P, h.response(w, 1.05 * Rc).power);
  }
  // strongly coupled (k^2 / (2 zeta) = 3.5): at w_sc the optimum is 1/(w Cp) / sqrt(1 + (k^2 / (2 zeta))^2),
  // far below the textbook 1/(w Cp)
  const double a = h.coupling_k2(0) / (2 * h.zeta(0));
  const double Rtext = 1.0 / (w1 * h.capacitance());
  EXPECT_NEAR(h.optimal_load(w1) * std::sqrt(1 + a * a) / Rtext, 1.0, 1e-9);
  EXPECT_LT(h.optimal_load(w1), 0.5 * Rtext);
  // weakly coupled (e31 scaled by 0.05: k^2 / (2 zeta) = 0.009): R_opt = 1/(w Cp) to within 1e-3
  pz::BimorphSpec ws = dutoit(1, 0.01);
  ws.piezo.e31 *= 0.05;
  const pz::BimorphHarvester hw(ws);
  const double wr = hw.omega(0);
  EXPECT_NEAR(pz::optimal_load_numeric(hw, wr, 1.0, 1e9) * wr * hw.capacitance(), 1.0, 1e-3);
  std::printf("duToit zeta 0.01: R_opt(f_sc) %.1f ohm (1/(w Cp) %.1f), R_opt(f_oc) %.1f ohm, P %.4e / %.4e W per "
              "(m/s^2)^2\n",
              h.optimal_load(w1), Rtext, h.optimal_load(woc), h.response(w1, h.optimal_load(w1)).power,
              h.response(woc, h.optimal_load(woc)).power);
}

TEST(PiezoAnalytic, PowerBoundOfTheModalDamper) {
  // One mode with modal force F (per unit base acceleration) and damper c = 2 zeta w_1: no load can take more
  // than F^2 / (8 c) = F^2 / (16 zeta w_1) (the matched-impedance bound). A strongly coupled harvester
  // (k^2 / (2 zeta) = 3.5) reaches it at two frequencies (near w_sc and w_oc); a weakly coupled one stays below.
  const pz::BimorphHarvester h(dutoit(1, 0.01));
  const double F = h.forcing(0), w1 = h.omega(0), woc = h.open_circuit_frequencies()[0];
  const double bound = F * F / (16 * h.zeta(0) * w1);
  auto Pmax = [&](double w) { return h.response(w, h.optimal_load(w)).power; };
  const double mid = 0.5 * (w1 + woc);
  const double wa = pz::golden_max(Pmax, 0.95 * w1, mid), wb = pz::golden_max(Pmax, mid, 1.05 * woc);
  EXPECT_NEAR(Pmax(wa) / bound, 1.0, 1e-7);
  EXPECT_NEAR(Pmax(wb) / bound, 1.0, 1e-7);
  EXPECT_LT(Pmax(mid), 0.99 * bound);  // two separate optima, a dip between
  pz::BimorphSpec ws = dutoit(1, 0.01);
  ws.piezo.e31 *= 0.2;  // k^2 / (2 zeta) = 0.14
  const pz::BimorphHarvester hw(ws);
  const double ww = pz::golden_max([&](double w) { return hw.response(w, hw.optimal_load(w)).power; }, 0.95 * w1,
                                   1.05 * w1);
  const double Pw = hw.response(ww, hw.optimal_load(ww)).power;
  EXPECT_LT(Pw, 0.9 * bound);
  EXPECT_GT(Pw, 0.1 * bound);
}

TEST(PiezoAnalytic, EnergyBalance) {
  for (auto c : {pz::Connection::series, pz::Connection::parallel}) {
    pz::BimorphSpec s = dutoit(3, 0.02);
    s.connection = c;
    s.zeta = {0.02, 0.015, 0.01};
    const pz::BimorphHarvester h(s);
    for (double R : {10.0, 2000.0, 1e5, 1e7})
      for (double f : {0.5, 0.98, 1.0, 1.03, 3.0, 6.27}) {
        const double w = f * h.omega(0);
        const pz::Response o = h.response(w, R);
        // base work = resistor + damping (steady state: the stored energy returns each period)
        EXPECT_NEAR(o.power_in, o.power + o.power_damping, 1e-10 * o.power_in) << "R " << R << " f " << f;
        EXPECT_GT(o.power, 0.0);
        // the mean of v(t)^2 / R over a period by quadrature (trapezoid: exact for a trigonometric polynomial)
        const int n = 16;
        double acc = 0;
        for (int k = 0; k < n; ++k) {
          const double v = std::real(o.V * std::polar(1.0, 2 * pz::kPi * k / n));
          acc += v * v / R;
        }
        EXPECT_NEAR(acc / n, std::norm(o.V) / (2 * R), 1e-12 * o.power);
        EXPECT_NEAR(std::abs(o.I), std::abs(o.V) / R, 1e-14 * std::abs(o.I));
      }
  }
}

TEST(PiezoAnalytic, SeriesAgainstParallel) {
  // parallel: vartheta x2, Cp x4 -> the same k^2, frequencies and maximum power; R_opt / 4, V / 2, I x 2
  pz::BimorphSpec s = dutoit(1, 0.01), p = s;
  p.connection = pz::Connection::parallel;
  const pz::BimorphHarvester hs(s), hp(p);
  EXPECT_NEAR(hp.open_circuit_frequencies()[0] / hs.open_circuit_frequencies()[0], 1.0, 1e-12);
  const double w = hs.omega(0);
  EXPECT_NEAR(hp.optimal_load(w) * 4 / hs.optimal_load(w), 1.0, 1e-12);
  EXPECT_NEAR(hp.response(w, hp.optimal_load(w)).power / hs.response(w, hs.optimal_load(w)).power, 1.0, 1e-12);
  const double R = 5000;
  EXPECT_NEAR(std::abs(hp.response(w, R / 4).V) * 2 / std::abs(hs.response(w, R).V), 1.0, 1e-12);
}

TEST(PiezoAnalytic, MultiModeNearFirstResonance) {
  // near the first resonance one mode carries the response: 1 vs 6 modes within 2 % at 2 kohm
  const pz::BimorphHarvester h1(dutoit(1, 0.01)), h6(dutoit(6, 0.01));
  for (double f : {0.98, 1.0, 1.02}) {
    const double w = f * h1.omega(0);
    EXPECT_NEAR(std::abs(h6.response(w, 2000).V) / std::abs(h1.response(w, 2000).V), 1.0, 0.02) << f;
    EXPECT_NEAR(std::abs(h6.response(w, 2000).tip_rel) / std::abs(h1.response(w, 2000).tip_rel), 1.0, 0.02) << f;
  }
  // the second resonance is where the 6-mode voltage peaks (short circuit-like load)
  const double w2 = h6.omega(1);
  EXPECT_NEAR(pz::peak_frequency(h6, 1.0, 0.95 * w2, 1.05 * w2) / w2, 1.0, 1e-4);
  EXPECT_NEAR(h6.omega(1) / h6.omega(0), std::pow(pz::clamped_free_lambda(2) / pz::clamped_free_lambda(1), 2), 1e-12);
}

TEST(PiezoAnalytic, StaticBimorphBender) {
  // Hwang & Park 1993 (after Tzou & Tseng 1990): PVDF, L = 100 mm, two 0.5 mm layers in series, 100 V
  const pz::Pvdf pv{};
  const double L = 0.1, t = 1e-3, V = 100.0, b = 5e-3;
  const double textbook = pz::series_bimorph_tip_deflection(pv.d31, V, L, t);
  EXPECT_NEAR(textbook, 3.3e-5, 1e-15);  // 3 * 2.2e-11 * 100 * 0.01 / (2 * 1e-6); 3.3e-7 m per volt
  // the general three-layer beam with no host gives the same (the modulus cancels; e31_bar = d31 E)
  pz::BimorphSpec s;
  s.L = L;
  s.b = b;
  s.hs = 0.0;
  s.hp = t / 2;
  s.host = {pv.E, pv.nu, 1780.0};
  s.piezo = {pv.E, pv.d31 * pv.E, pv.eps33_bar(), 1780.0};
  s.connection = pz::Connection::series;
  s.modes = 40;
  const pz::BimorphHarvester h(s);
  EXPECT_NEAR(h.static_tip_deflection(V) / textbook, 1.0, 1e-12);
  // the modal static sum sum_r phi_r(L) theta_r V / w_r^2 converges to it (tail ~ 1/N^2)
  double sum = 0;
  for (int r = 0; r < h.modes(); ++r) sum += h.phi_tip(r) * h.theta(r) * V / (h.omega(r) * h.omega(r));
  EXPECT_NEAR(sum / textbook, 1.0, 2e-3);
  // wide-plate reading (eps_2 = 0): (1 + nu) times
  EXPECT_NEAR(pz::series_bimorph_tip_deflection_plane_strain(pv.d31, V, L, t, pv.nu), 1.29 * 3.3e-5, 1e-15);
  // capacitance of one free layer: eps33^T A / t = 12 eps0 * 0.1 * 0.005 / 0.5e-3 = 106.25 pF; the series
  // pair is half of one layer (the beam model uses the bonded eps33_bar, 0.9 % lower)
  const double C1 = pz::plate_capacitance(pv.eps33T(), L * b, t / 2);
  EXPECT_NEAR(C1, 12 * pz::kEps0 * 1.0, 1e-18);
  EXPECT_NEAR(h.capacitance() / (0.5 * pz::plate_capacitance(pv.eps33_bar(), L * b, t / 2)), 1.0, 1e-12);
  EXPECT_NEAR(pv.eps33_bar() / pv.eps33T(), 1.0 - pv.d31 * pv.d31 * pv.E / pv.eps33T(), 1e-15);
  std::printf("PVDF bimorph: tip %.4e m at 100 V (plane strain %.4e m), modal sum (40 modes) %.6e m, free-layer "
              "C %.4e F\n",
              textbook, 1.29 * textbook, sum, C1);
}

TEST(PiezoMaterials, Pzt5aDerivedAgainstPublished) {
  const pz::PiezoCeramic m = pz::pzt5a();
  const auto C = m.stiffness_E();
  const auto e = m.e_matrix();
  const auto eS = m.eps_S();
  const auto P = pz::pzt5a_published_stiffness_form();
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) EXPECT_NEAR(C[i][j], C[j][i], 1e-6 * C[0][0]);
  auto rel = [](double a, double b) { return std::fabs(a / b - 1.0); };
  EXPECT_LT(rel(C[0][0], P.c11), 0.015);
  EXPECT_LT(rel(C[0][1], P.c12), 0.015);
  EXPECT_LT(rel(C[0][2], P.c13), 0.015);
  EXPECT_LT(rel(C[2][2], P.c33), 0.015);
  EXPECT_LT(rel(C[3][3], P.c44), 0.015);
  EXPECT_LT(rel(C[5][5], P.c66), 0.015);
  EXPECT_LT(rel(e[2][0], P.e31), 0.015);
  EXPECT_LT(rel(e[2][1], P.e31), 0.015);
  EXPECT_LT(rel(e[2][2], P.e33), 0.015);
  EXPECT_LT(rel(e[0][4], P.e15), 0.015);
  EXPECT_LT(rel(e[1][3], P.e15), 0.015);
  EXPECT_LT(rel(eS[0][0], P.eps11S), 0.015);
  EXPECT_LT(rel(eS[2][2], P.eps33S), 0.015);
  EXPECT_NEAR(C[5][5], 0.5 * (C[0][0] - C[0][1]), 1e-6 * C[0][0]);  // transverse isotropy
  // the reduced constants (Erturk & Inman 2009's PZT-5A: 61 GPa, -10.4 C/m^2, 13.3 nF/m)
  EXPECT_LT(rel(m.c11_bar(), 61e9), 0.005);
  EXPECT_LT(rel(m.e31_bar(), -10.4), 0.005);
  EXPECT_LT(rel(m.eps33_bar(), 13.3e-9), 0.005);
  // e31_bar = d31 / s11E (sigma_2 = sigma_3 = 0: the strain-charge law with only sigma_1 left)
  EXPECT_NEAR(m.e31_bar() * m.s11E, m.d31, 1e-24);
  // PZT-5H of EI09 Table 1 from d31 = -274 pm/V, s11E = 16.5e-12, eps33T = 3400 eps0
  const auto h = pz::pzt5h_erturk_inman_2009();
  EXPECT_LT(rel(h.e31, -274e-12 / 16.5e-12), 0.002);
  EXPECT_LT(rel(h.eps33, 3400 * pz::kEps0 - 274e-12 * 274e-12 / 16.5e-12), 0.002);
  EXPECT_LT(rel(h.c11, 1 / 16.5e-12), 0.002);
}

TEST(PiezoAnalytic, ErturkInman2009Frequencies) {
  // EI09's bimorph without tip mass: reported 502.5 Hz (short circuit) and 524.7 Hz (open circuit)
  const pz::BimorphHarvester h(pz::erturk_inman_2009_case());
  const double fsc = h.omega(0) / (2 * pz::kPi), foc = h.open_circuit_frequencies()[0] / (2 * pz::kPi);
  const double foc_exact = h.open_circuit_frequency_exact(0) / (2 * pz::kPi);
  pz::BimorphSpec s4 = pz::erturk_inman_2009_case();
  s4.modes = 4;
  const double foc4 = pz::BimorphHarvester(s4).open_circuit_frequencies()[0] / (2 * pz::kPi);
  EXPECT_NEAR(fsc / 502.5, 1.0, 0.001);
  EXPECT_NEAR(foc / 524.7, 1.0, 0.005);        // one mode: +0.19 %
  EXPECT_NEAR(foc4 / 524.7, 1.0, 0.001);       // four modes
  EXPECT_NEAR(foc_exact / 524.7, 1.0, 0.001);  // all modes
  EXPECT_NEAR((foc_exact - fsc) / (524.7 - 502.5), 1.0, 0.03);
  std::printf("EI09 bimorph: f_sc %.2f Hz (502.5), f_oc %.2f Hz one mode, %.2f four modes, %.2f exact (524.7), "
              "Cp %.4e F\n",
              fsc, foc, foc4, foc_exact, h.capacitance());
}
