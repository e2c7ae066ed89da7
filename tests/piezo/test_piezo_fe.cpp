// The finite-element piezoelectric beam (issue 35; models/piezo/{fe_law,assembly,beam_model,transient}.hpp):
// - static: the PVDF bimorph bender of Hwang & Park against its closed forms (plane stress = the narrow beam,
//   3 d31 V L^2 / (2 t^2); plane strain = the wide plate, (1 + nu) times that; 3D), converging with the order,
//   and the locking of linear elements with one cell per layer (a hard case: shown, not hidden);
// - the capacitance of a free layer against eps33^T A / t (2D and 3D, to round-off: the stress-free state is
//   in the element space);
// - the duToit harvester's short- and open-circuit frequencies against the distributed-parameter model
//   (EI09) with and without the induced-potential stiffening, and the harmonic voltage and power over a
//   sweep of loads against it;
// - the steady state's power balance; the time-domain energy balance; monolithic = partitioned; the time-
//   domain steady amplitude against the harmonic solve; the short- and open-circuit limits and a stiff
//   circuit (R C << dt) staying bounded; bad input refused with a message naming the item.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>

#include "piezo/analytic.hpp"
#include "piezo/beam_model.hpp"
#include "piezo/cases.hpp"
#include "piezo/transient.hpp"

namespace pz = polymech::piezo;

namespace {

const pz::Pvdf kPvdf{};

pz::BeamSpec pvdf_bender(int dim, pz::Plane plane, int order, int cells_length) {
  return pz::pvdf_bender_spec(dim, plane, order, cells_length);
}

pz::BeamSpec dutoit(int order, int cells_length, int cells_per_piezo_layer) {
  return pz::dutoit_harvester_spec(order, cells_length, cells_per_piezo_layer);
}

pz::Circuit load(const pz::PiezoBeam& b, double R) { return pz::harvester_load(b, R); }

double load_voltage(const pz::HarmonicResponse& h) { return std::abs(h.V[1] - h.V[0]); }

template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PiezoFe, BimorphBenderPlaneStressIsTheNarrowBeam) {
  const double beam = pz::series_bimorph_tip_deflection(kPvdf.d31, 100.0, 0.1, 1e-3);  // 3.30e-5 m
  double previous = 0.0;
  for (const int p : {2, 3}) {
    const pz::PiezoBeam b(pvdf_bender(2, pz::Plane::stress, p, 40));
    const double tip = std::fabs(b.tip(b.solve_static()));
    std::printf("plane stress p %d: tip %.6e m, closed form %.6e (%+.3f %%)\n", p, tip, beam, 100.0 * (tip / beam - 1.0));
    EXPECT_NEAR(tip / beam, 1.0, 3e-3);  // the clamped root's local constraint: -0.23 %
    if (previous > 0.0) {
      EXPECT_NEAR(tip / previous, 1.0, 1e-4);  // converged in the order
    }
    previous = tip;
  }
}

TEST(PiezoFe, BimorphBenderPlaneStrainIsTheWidePlate) {
  const double plate = pz::series_bimorph_tip_deflection_plane_strain(kPvdf.d31, 100.0, 0.1, 1e-3, kPvdf.nu);
  const pz::PiezoBeam b(pvdf_bender(2, pz::Plane::strain, 2, 40));
  const double tip = std::fabs(b.tip(b.solve_static()));
  std::printf("plane strain: tip %.6e m, closed form %.6e (%+.3f %%)\n", tip, plate, 100.0 * (tip / plate - 1.0));
  EXPECT_NEAR(tip / plate, 1.0, 5e-3);
}

TEST(PiezoFe, BimorphBender3DLiesBetweenBeamAndPlate) {
  const double beam = pz::series_bimorph_tip_deflection(kPvdf.d31, 100.0, 0.1, 1e-3);
  const pz::PiezoBeam b(pvdf_bender(3, pz::Plane::stress, 2, 20));
  const double tip = std::fabs(b.tip(b.solve_static()));
  std::printf("3D (b/t = 5): tip %.6e m (%+.3f %% from the beam)\n", tip, 100.0 * (tip / beam - 1.0));
  // the 5 mm wide strip bends a little more than a beam (partial plate action), far less than a plate (+29 %)
  EXPECT_GT(tip, beam);
  EXPECT_LT(tip, 1.02 * beam);
}

TEST(PiezoFe, LinearElementsLockWithOneCellPerLayer) {
  // a hard case the issue asks to show: bilinear elements, 40 x 2 cells, bend in shear-locked mode
  const double beam = pz::series_bimorph_tip_deflection(kPvdf.d31, 100.0, 0.1, 1e-3);
  const pz::PiezoBeam b(pvdf_bender(2, pz::Plane::stress, 1, 40));
  const double tip = std::fabs(b.tip(b.solve_static()));
  std::printf("p = 1, one cell per layer: tip %.6e m = %.1f %% of the closed form (locking)\n", tip, 100.0 * tip / beam);
  EXPECT_LT(tip, 0.5 * beam);
  EXPECT_GT(tip, 0.0);
}

TEST(PiezoFe, ThinPiezoelectricLayersAgainstTheBeam) {
  // a hard case: PZT-5A layers 100x thinner than the brass (2.7 um on 0.14 mm, aspect ratio of a cell 1:2000),
  // driven at +-V/2 on the outer faces with the host grounded (the series bimorph's static bender); against
  // the beam's vartheta V L^2 / (2 YI), with and without the induced potential (negligible in a thin layer)
  for (const double hp : {0.27e-3, 2.7e-6}) {
    pz::BeamSpec s = dutoit(2, 40, 1);
    s.layers[0].thickness = s.layers[2].thickness = hp;
    s.electrodes = {{"bottom", "bottom", pz::ElectrodeKind::prescribed, -0.5},
                    {"top", "top", pz::ElectrodeKind::prescribed, 0.5}};
    const pz::PiezoBeam b(s);
    const double tip = std::fabs(b.tip(b.solve_static()));
    pz::BimorphSpec as = pz::dutoit_wardle_2007_case();
    as.hp = hp;
    as.induced_potential = true;
    const double beam = std::fabs(pz::BimorphHarvester(as).static_tip_deflection(1.0));
    std::printf("hp %.1e m: tip per volt FE %.6e, beam %.6e (%+.3f %%)\n", hp, tip, beam, 100 * (tip / beam - 1));
    EXPECT_NEAR(tip / beam, 1.0, 0.01);
  }
}

TEST(PiezoFe, FreeLayerCapacitanceIsThePlateFormula) {
  for (const int dim : {2, 3}) {
    pz::BeamSpec s = pvdf_bender(dim, pz::Plane::stress, 2, 6);
    s.layers = {{"layer", 5e-4, true, 1, 2}};
    s.support = pz::Support::free;
    s.electrodes = {{"ground", "bottom", pz::ElectrodeKind::grounded, 0.0},
                    {"top", "top", pz::ElectrodeKind::prescribed, 1.0}};
    const pz::PiezoBeam b(s);
    const double C = b.charges(b.solve_static())[0];
    const double plate = pz::plate_capacitance(kPvdf.eps33T(), 0.1 * 5e-3, 5e-4);  // 106.25 pF
    std::printf("free layer, %dD: C = %.8e F, eps33T A / t = %.8e F\n", dim, C, plate);
    EXPECT_NEAR(C / plate, 1.0, 1e-9);
  }
}

TEST(PiezoFe, HarvesterFrequenciesAgainstTheDistributedParameterModel) {
  const pz::PiezoBeam b(dutoit(3, 20, 1));
  const double fsc = b.natural_frequency(true) / (2 * pz::kPi), foc = b.natural_frequency(false) / (2 * pz::kPi);
  pz::BimorphSpec as = pz::dutoit_wardle_2007_case();
  const pz::BimorphHarvester ei09(as);
  as.induced_potential = true;
  const pz::BimorphHarvester stiffened(as);
  const double fsc_ei = ei09.omega(0) / (2 * pz::kPi), fsc_st = stiffened.omega(0) / (2 * pz::kPi);
  const double foc_st = stiffened.open_circuit_frequency_exact(0) / (2 * pz::kPi);
  std::printf("f_sc FE %.4f Hz, EI09 %.4f (%+.3f %%), with the induced potential %.4f (%+.3f %%)\n", fsc, fsc_ei,
              100 * (fsc / fsc_ei - 1), fsc_st, 100 * (fsc / fsc_st - 1));
  std::printf("f_oc FE %.4f Hz, beam (exact, induced potential) %.4f (%+.3f %%)\n", foc, foc_st, 100 * (foc / foc_st - 1));
  EXPECT_NEAR(fsc / fsc_st, 1.0, 1.5e-3);
  EXPECT_NEAR(foc / foc_st, 1.0, 1.5e-3);
  EXPECT_GT(fsc / fsc_ei, 1.005);  // the uniform-field beam is softer by the induced potential's 0.83 %
  EXPECT_GT(foc, fsc * 1.02);      // open circuit stiffer: k^2 = 6.7 %
}

TEST(PiezoFe, HarvesterVoltageAndPowerOverLoads) {
  const pz::PiezoBeam b(dutoit(3, 20, 1));
  const double wsc = b.natural_frequency(true);
  const auto damping = pz::Rayleigh::stiffness_proportional(0.01, wsc);
  pz::BimorphSpec as = pz::dutoit_wardle_2007_case();
  as.induced_potential = true;
  const pz::BimorphHarvester beam(as);
  double best_R = 0.0, best_P = 0.0;
  for (const double R : {1e2, 2e3, 1e4, 5e4, 2e5, 1e6}) {
    const auto h = b.harmonic(wsc, load(b, R), damping);
    const auto a = beam.response(beam.omega(0), R);
    std::printf("R %8.0f ohm: |V| FE %.5e beam %.5e V, P FE %.5e beam %.5e W (%+.2f %%), balance %.1e\n", R,
                load_voltage(h), std::abs(a.V), h.power, a.power, 100 * (h.power / a.power - 1),
                (h.power + h.power_damping) / h.power_in - 1);
    EXPECT_NEAR(h.power / a.power, 1.0, 0.02);  // each at its own resonance; single mode against all modes
    EXPECT_NEAR((h.power + h.power_damping) / h.power_in, 1.0, 1e-6);  // the steady state's power balance (3e-8 seen)
    if (h.power > best_P) {
      best_P = h.power;
      best_R = R;
    }
  }
  EXPECT_EQ(best_R, 5e4);  // the optimum near R_opt = 50 kohm (beam: 1/|Y| = 50.0 kohm)
}

TEST(PiezoFe, ShortAndOpenCircuitLimits) {
  const pz::PiezoBeam b(dutoit(2, 12, 1));
  const double wsc = b.natural_frequency(true), woc = b.natural_frequency(false);
  const auto damping = pz::Rayleigh::stiffness_proportional(0.01, wsc);
  // a tiny load is a short circuit: the voltage vanishes like R and the tip peaks at w_sc
  const auto small = b.harmonic(wsc, load(b, 1e-3), damping);
  EXPECT_LT(load_voltage(small), 1e-7);
  EXPECT_GT(std::abs(small.tip), std::abs(b.harmonic(1.01 * wsc, load(b, 1e-3), damping).tip));
  // a huge load is an open circuit: the response peaks at w_oc
  const auto huge = b.harmonic(woc, load(b, 1e12), damping);
  EXPECT_GT(std::abs(huge.tip), std::abs(b.harmonic(0.99 * woc, load(b, 1e12), damping).tip));
  EXPECT_GT(std::abs(huge.tip), std::abs(b.harmonic(1.01 * woc, load(b, 1e12), damping).tip));
  const double open = load_voltage(b.harmonic(woc, load(b, 1e14), damping));
  EXPECT_NEAR(load_voltage(huge) / open, 1.0, 1e-6);  // the open-circuit voltage reached
}

TEST(PiezoFe, TransientEnergyBalanceAndSchemesAgree) {
  const pz::PiezoBeam b(dutoit(2, 10, 1));
  const double w = b.natural_frequency(true);
  pz::TransientOptions o;
  o.dt = 2 * pz::kPi / w / 40;
  o.damping = pz::Rayleigh::stiffness_proportional(0.05, w);
  const pz::Circuit c = load(b, 2000.0);
  pz::PiezoTransient mono(b, c, o);
  o.scheme = pz::Scheme::partitioned;
  pz::PiezoTransient part(b, c, o);
  mono.start(0.0);
  part.start(0.0);
  int max_solves = 0;
  double Vmax = 0.0, difference = 0.0;
  for (int i = 1; i <= 400; ++i) {
    const double ab = std::sin(w * i * o.dt);
    mono.step(ab);
    const int solves = part.step(ab);
    if (i > 1) max_solves = std::max(max_solves, solves);  // step 1 also forms the Jacobian (one solve per electrode)
    Vmax = std::max(Vmax, std::fabs(mono.voltage(1, 0)));
    difference = std::max(difference, std::fabs(part.voltage(1, 0) - mono.voltage(1, 0)));
  }
  std::printf("10 periods: max |V| %.6e, max |V_partitioned - V_monolithic| %.2e; solves %lld / %lld; energy balance %.2e\n",
              Vmax, difference, static_cast<long long>(mono.total_solves()), static_cast<long long>(part.total_solves()),
              mono.energy_balance_error());
  EXPECT_LT(difference, 1e-6 * Vmax);  // the loop stops at 1e-9 of the charge scale
  EXPECT_LE(max_solves, 4);
  EXPECT_LE(part.total_solves(), 2 * 400 + 8);  // two solves per step: predict, correct
  EXPECT_LT(std::fabs(mono.energy_balance_error()), 1e-6);  // exact but for round-off (7e-9 .. 9e-8 seen; the issue: 1 %)
  EXPECT_LT(std::fabs(part.energy_balance_error()), 1e-6);
  EXPECT_GT(mono.state().work_circuit, 0.0);
}

// The external-load path of a step (the fluid's forces in models/fsi/flow_harvester.hpp): the base acceleration's
// load -M r a_b given as external nodal loads instead gives the same states, and the energy balance holds with
// the external loads' work; the partitioned (paper 1's nested) and monolithic schemes agree under it too.
TEST(PiezoFe, ExternalLoadsActLikeTheBaseLoadAndBalanceEnergy) {
  const pz::PiezoBeam b(dutoit(2, 10, 1));
  const double w = b.natural_frequency(true);
  pz::TransientOptions o;
  o.dt = 2 * pz::kPi / w / 40;
  o.damping = pz::Rayleigh::stiffness_proportional(0.05, w);
  const pz::Circuit c = load(b, 2000.0);
  pz::PiezoTransient base(b, c, o), ext(b, c, o);
  o.scheme = pz::Scheme::partitioned;
  pz::PiezoTransient part(b, c, o);
  base.start(0.0), ext.start(0.0), part.start(0.0);
  std::vector<double> Mr;
  b.M().apply(b.base_direction(), Mr);
  for (std::size_t i = static_cast<std::size_t>(b.displacement_unknowns()); i < Mr.size(); ++i) Mr[i] = 0.0;
  double vmax = 0.0, diff = 0.0, diff_part = 0.0;
  for (int i = 1; i <= 200; ++i) {
    const double ab = std::sin(w * i * o.dt);
    std::vector<double> f(Mr.size());
    for (std::size_t k = 0; k < f.size(); ++k) f[k] = -Mr[k] * ab;
    base.step(ab);
    ext.step(0.0, &f);
    part.step(0.0, &f);
    vmax = std::max(vmax, std::fabs(base.voltage(1, 0)));
    diff = std::max(diff, std::fabs(ext.voltage(1, 0) - base.voltage(1, 0)));
    diff_part = std::max(diff_part, std::fabs(part.voltage(1, 0) - base.voltage(1, 0)));
  }
  std::printf("external loads: max |V| %.6e, |V_ext - V_base| %.2e, partitioned %.2e; energy balance %.2e / %.2e\n", vmax, diff,
              diff_part, ext.energy_balance_error(), part.energy_balance_error());
  EXPECT_GT(vmax, 0.0);
  EXPECT_LT(diff, 1e-6 * vmax);  // round-off of a differently summed right-hand side through the bordered solve (2e-7 seen)
  EXPECT_LT(diff_part, 1e-6 * vmax);
  EXPECT_NEAR(ext.state().work_in, base.state().work_in, 1e-6 * std::fabs(base.state().work_in));
  EXPECT_LT(std::fabs(ext.energy_balance_error()), 1e-6);
  EXPECT_LT(std::fabs(part.energy_balance_error()), 1e-6);
  std::vector<double> wrong(3, 0.0);
  EXPECT_THROW(ext.step(0.0, &wrong), std::invalid_argument);
}

TEST(PiezoFe, TransientSteadyAmplitudeMatchesTheHarmonicSolve) {
  const pz::PiezoBeam b(dutoit(2, 10, 1));
  const double w = b.natural_frequency(true);
  const auto damping = pz::Rayleigh::stiffness_proportional(0.05, w);
  const pz::Circuit c = load(b, 2000.0);
  const double harmonic = load_voltage(b.harmonic(w, c, damping));
  pz::TransientOptions o;
  o.dt = 2 * pz::kPi / w / 80;
  o.damping = damping;
  pz::PiezoTransient t(b, c, o);
  t.start(0.0);
  double peak = 0.0;
  for (int i = 1; i <= 80 * 40; ++i) {  // 40 periods: e^(-2 pi 0.05 40) = 3.5e-6 of the start-up left
    t.step(std::sin(w * i * o.dt));
    if (i > 80 * 38) peak = std::max(peak, std::fabs(t.voltage(1, 0)));
  }
  std::printf("steady |V|: transient %.6e, harmonic %.6e (%+.3f %%)\n", peak, harmonic, 100 * (peak / harmonic - 1));
  EXPECT_NEAR(peak / harmonic, 1.0, 2e-3);  // the period error of dt = T/80 and the sampling of the peak
}

TEST(PiezoFe, StiffCircuitStaysBounded) {
  // R C = 1e-2 ohm x 9 nF ~ 1e-10 s, 1e6 times smaller than dt: the trapezoidal charge balance is A-stable
  const pz::PiezoBeam b(dutoit(2, 8, 1));
  const double w = b.natural_frequency(true);
  pz::TransientOptions o;
  o.dt = 2 * pz::kPi / w / 40;
  o.damping = pz::Rayleigh::stiffness_proportional(0.01, w);
  pz::PiezoTransient t(b, load(b, 1e-2), o);
  t.start(0.0);
  double vmax = 0.0;
  for (int i = 1; i <= 200; ++i) {
    t.step(std::sin(w * i * o.dt));
    vmax = std::max(vmax, std::fabs(t.voltage(1, 0)));
  }
  EXPECT_TRUE(std::isfinite(vmax));
  EXPECT_LT(vmax, 1e-5);
  EXPECT_LT(std::fabs(t.energy_balance_error()), 1e-6);
}

TEST(PiezoFe, BadInputIsRefusedWithTheItemNamed) {
  pz::BeamSpec s = dutoit(2, 4, 1);
  s.layers[1].thickness = -1.0;
  EXPECT_NE(error_of([&] { pz::PiezoBeam b(s); }).find("brass"), std::string::npos);
  s = dutoit(2, 4, 1);
  s.electrodes[0].surface = "side";
  EXPECT_NE(error_of([&] { pz::PiezoBeam b(s); }).find("'side'"), std::string::npos);
  s = dutoit(2, 4, 1);
  s.electrodes[0].surface = "interface 1";  // the grounded brass
  EXPECT_NE(error_of([&] { pz::PiezoBeam b(s); }).find("grounded conducting host"), std::string::npos);
  s = dutoit(2, 4, 1);
  s.layers[0].piezoelectric = s.layers[2].piezoelectric = false;
  EXPECT_NE(error_of([&] { pz::PiezoBeam b(s); }).find("no piezoelectric layer"), std::string::npos);
  const pz::PiezoBeam b(dutoit(2, 4, 1));
  EXPECT_NE(error_of([&] { load(b, 0.0); }).find("positive"), std::string::npos);
  EXPECT_NE(error_of([&] { pz::Circuit c(2); c.add_resistor(0, 5, 1.0); }).find("electrode 5"), std::string::npos);
  pz::TransientOptions o;
  EXPECT_NE(error_of([&] { pz::PiezoTransient t(b, load(b, 1.0), o); }).find("dt"), std::string::npos);
}
