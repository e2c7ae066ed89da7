// Uniaxial tension (seed 003 §4(1)): Young's modulus recovered within 2 % on a regular lattice and on
// the irregular layout that conforms to a curved surface with the weighted-function method (eq. (2)),
// reduced in size from scenes/pd/tension_*.toml. On a jittered layout the zero-energy modes soften the
// strip: the weighted function halves the error at least, the hourglass force removes it.
#include <gtest/gtest.h>

#include <cmath>

#include "nosb_pd/tension.hpp"
#include "pd_test_support.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

np::Config strip(int cells_across, np::Layout layout, std::vector<std::string> effects) {
  np::Config c = pm::testing::box_config(2, 1, 3.0, effects, layout);
  c.geometry.height = cells_across * c.spacing;
  c.geometry.length = 4 * c.geometry.height;
  c.geometry.jitter = 0.1;
  c.geometry.seed = 7;
  c.material.poisson_ratio = 0.33;
  c.loading = np::Loading::tension;
  c.dt = 0.0;  // automatic
  c.mass_damping = np::relaxation_damping(c);
  return c;
}

np::Config round_bar(int cells_across, np::Layout layout, std::vector<std::string> effects) {
  np::Config c = strip(cells_across, layout, effects);
  c.dimension = 3;
  c.geometry.shape = np::Shape::round_bar;
  c.geometry.radius = 0.5 * cells_across * c.spacing;
  c.geometry.length = 4 * cells_across * c.spacing;
  c.mass_damping = np::relaxation_damping(c);
  return c;
}

template <int D>
double modulus_error(const np::Config& c) {
  np::NosbPd<double, D> m(c);
  const auto r = np::run_tension(m);
  if (c.geometry.layout != np::Layout::jittered) {
    EXPECT_NEAR(r.gauge_strain, 1e-3, 2e-4) << "the gauge section carries the nominal strain";
  }
  return r.relative_error;
}

}  // namespace

TEST(PdTension, ModulusOnARegularLatticeWithin2Percent) {
  EXPECT_LT(std::abs(modulus_error<2>(strip(20, np::Layout::lattice, {}))), 0.02);
  EXPECT_LT(std::abs(modulus_error<2>(strip(20, np::Layout::lattice, {"weighted_function"}))), 0.02);
  EXPECT_LT(std::abs(modulus_error<3>(round_bar(10, np::Layout::lattice, {}))), 0.02);
}

TEST(PdTension, ModulusOnTheConformingLayoutWithTheWeightedFunctionWithin2Percent) {
  const double e = modulus_error<3>(round_bar(8, np::Layout::cylindrical, {"weighted_function"}));
  EXPECT_LT(std::abs(e), 0.02) << e;
}

TEST(PdTension, JitteredLayoutIsSoftenedByZeroEnergyModes) {
  const double plain = modulus_error<2>(strip(8, np::Layout::jittered, {}));
  const double weighted = modulus_error<2>(strip(8, np::Layout::jittered, {"weighted_function"}));
  const double controlled = modulus_error<2>(strip(8, np::Layout::jittered, {"weighted_function", "hourglass"}));
  EXPECT_LT(plain, -0.10) << "zero-energy modes make the jittered strip soft";
  EXPECT_LT(std::abs(weighted), 0.5 * std::abs(plain)) << "the weighted function removes at least half of it";
  EXPECT_LT(std::abs(controlled), 0.02) << "the hourglass force removes the rest";
}
