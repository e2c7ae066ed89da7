// Zero-energy modes of the NOSB correspondence model (seed 003 §3(2)) and their controls, the hard
// case of the method:
//  - the stiffness of a periodic patch (Eigen) has spurious zero eigenvalues without control (the
//    parity patterns, F_i = I on every particle), none with the hourglass force (Silling 2017), and
//    velocity viscosity (eq. (3)) damps every one of them;
//  - a small block hit by a short pull keeps a spurious, undamped non-affine oscillation without
//    control; velocity viscosity stops it, the hourglass force keeps the non-affine part small.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>
#include <tuple>

#include "nosb_pd/patch_stiffness.hpp"
#include "pd_test_support.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;

namespace {

template <int D>
np::PatchSpectrum spectrum(double m, int tile, std::vector<std::string> effects, bool damping) {
  np::Config c = pm::testing::box_config(D, 3 * tile, m, effects);
  c.stabilization.c_v = 0.3;
  c.stabilization.omega_v = 1e6;
  c.stabilization.hourglass = 0.02;
  np::NosbPd<double, D> model(c);
  return np::periodic_patch_spectrum<D>(model, tile, 1e-7, damping);
}

// A 20 x 10 block (m = 2) held at x = 0 and pulled at 1 m/s for 20 steps at x = L, then left to ring.
// Returns the non-affine amplitude sqrt(sum W |Y - F xi|^2) over the interior at `samples` times of
// the second half, its ratio to the whole deformation, and the kinetic energies at 1/4 and at the end.
struct Ringing {
  std::vector<double> amplitude;
  double ratio = 0, kinetic_early = 0, kinetic_late = 0;
};

Ringing ring(std::vector<std::string> effects) {
  np::Config c = pm::testing::box_config(2, 1, 2.0, effects);
  c.geometry.length = 20 * c.spacing;
  c.geometry.height = 10 * c.spacing;
  c.loading = np::Loading::tension;
  c.stabilization.c_v = 0.3;
  c.stabilization.omega_v = 0.2 * c.material.p_wave_speed() / c.spacing;  // pd_tension --identify-omega-v
  c.stabilization.hourglass = 0.02;
  c.dt = 1.5e-7;
  np::NosbPd<double, 2> m(c);
  Ringing r;
  const int steps = 3000;
  m.set_grip_velocity(1.0);
  for (int s = 1; s <= steps; ++s) {
    if (s == 20) m.set_grip_velocity(0.0);
    m.step();
    if (s == steps / 4) r.kinetic_early = m.energy().kinetic;
    if (s > steps / 2 && s % 100 == 0) r.amplitude.push_back(std::sqrt(m.nonaffine_deviation(true).nonaffine));
  }
  r.ratio = m.nonaffine_deviation(true).ratio();
  r.kinetic_late = m.energy().kinetic;
  return r;
}

// Relative fluctuation (max - min) / mean of a series.
double fluctuation(const std::vector<double>& a) {
  double lo = 1e300, hi = -1e300, mean = 0;
  for (double x : a) lo = std::min(lo, x), hi = std::max(hi, x), mean += x / a.size();
  return (hi - lo) / mean;
}

}  // namespace

TEST(PdZeroEnergy, PeriodicPatchHasSpuriousZeroEigenvaluesWithoutControlAndNoneWithHourglass) {
  for (double m : {2.0, 3.0}) {
    const auto none = spectrum<2>(m, 6, {}, false);
    EXPECT_EQ(none.rigid_modes, 2);
    EXPECT_GE(none.zero_modes - none.rigid_modes, 6) << "m = " << m << ": the parity patterns (2 components x 3)";
    const auto hg = spectrum<2>(m, 6, {"hourglass"}, false);
    EXPECT_EQ(hg.zero_modes, hg.rigid_modes) << "m = " << m << ": only the translations are left";
    EXPECT_GT(hg.smallest_nonzero, 1e-4);
    std::printf("[zero-energy] 2D m = %g: spurious zero eigenvalues %d without control, %d with hourglass "
                "(smallest non-zero %.3g)\n", m, none.zero_modes - none.rigid_modes, hg.zero_modes - hg.rigid_modes,
                hg.smallest_nonzero);
  }
  const auto none3 = spectrum<3>(2.0, 4, {}, false);
  EXPECT_GE(none3.zero_modes - none3.rigid_modes, 9) << "3D: 3 components x 3 parity patterns at least";
  const auto hg3 = spectrum<3>(2.0, 4, {"hourglass"}, false);
  EXPECT_EQ(hg3.zero_modes, hg3.rigid_modes);
  std::printf("[zero-energy] 3D m = 2: spurious zero eigenvalues %d without control, %d with hourglass\n",
              none3.zero_modes - none3.rigid_modes, hg3.zero_modes - hg3.rigid_modes);
}

TEST(PdZeroEnergy, VelocityViscosityDampsEveryZeroEnergyMode) {
  const auto vv = spectrum<2>(2.0, 6, {"velocity_viscosity"}, true);
  ASSERT_EQ(vv.spurious_damping.size(), static_cast<std::size_t>(vv.zero_modes - vv.rigid_modes));
  ASSERT_FALSE(vv.spurious_damping.empty()) << "velocity viscosity adds no stiffness: the zero modes stay";
  // rate of the damping on the weakest-damped spurious mode, against c_v 2 omega_v of eq. (3)
  EXPECT_GT(vv.spurious_damping.front(), 0.1 * 0.3 * 2 * 1e6);
  std::printf("[zero-energy] velocity viscosity: %zu spurious modes, weakest damping rate %.3g 1/s (c_v 2 omega_v = %.3g)\n",
              vv.spurious_damping.size(), vv.spurious_damping.front(), 0.3 * 2 * 1e6);
}

TEST(PdZeroEnergy, LoadedBlockRingsInSpuriousModesWithoutControl) {
  const Ringing none = ring({});
  const Ringing vv = ring({"velocity_viscosity"});
  const Ringing hg = ring({"hourglass"});
  // without control the interior deformation is mostly invisible to F and keeps oscillating
  EXPECT_GT(none.ratio, 0.8);
  EXPECT_GT(fluctuation(none.amplitude), 0.2);
  EXPECT_GT(none.kinetic_late, 0.5 * none.kinetic_early) << "nothing removes it";
  // velocity viscosity stops the spurious motion (and everything with it)
  EXPECT_LT(fluctuation(vv.amplitude), 0.05 * fluctuation(none.amplitude));
  EXPECT_LT(vv.kinetic_late, 0.2 * none.kinetic_late);
  // the hourglass force keeps the non-affine part small
  EXPECT_LT(hg.ratio, 0.6 * none.ratio);
  const double hg_mean = std::accumulate(hg.amplitude.begin(), hg.amplitude.end(), 0.0) / hg.amplitude.size();
  const double none_mean = std::accumulate(none.amplitude.begin(), none.amplitude.end(), 0.0) / none.amplitude.size();
  EXPECT_LT(hg_mean, 0.3 * none_mean);
  const double vv_mean = std::accumulate(vv.amplitude.begin(), vv.amplitude.end(), 0.0) / vv.amplitude.size();
  for (const auto& [name, r, mean] : {std::tuple{"none", none, none_mean}, std::tuple{"velocity_viscosity", vv, vv_mean},
                                      std::tuple{"hourglass", hg, hg_mean}})
    std::printf("[zero-energy] ringing block, %s: non-affine share %.3f, amplitude mean %.3g fluctuation %.3f, "
                "kinetic energy late / early %.3f\n", name, r.ratio, mean, fluctuation(r.amplitude),
                r.kinetic_late / r.kinetic_early);
}
