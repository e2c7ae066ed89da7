// NOSB peridynamics kernels (seed 003 eqs. (1)-(3)) against exact answers: F of an affine field is
// exact on every particle and every layout (eq. (1)), rigid rotations carry no stress, the forces
// are the gradient of the strain energy and conserve momentum, beta of eq. (2), the Johnson-Cook
// return map on the yield surface, the zero-energy controls vanish on affine fields / rigid motions,
// conserve momentum and resist (hourglass) or damp (velocity viscosity) a parity mode, and the
// projectile and short-range contact geometry.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/projectile_penalty.hpp"
#include "pd_test_support.hpp"

namespace pm = polymech;
namespace np = polymech::nosb_pd;
using pm::testing::box_config;
using pm::testing::noise;

namespace {

template <int D>
using Arr = std::array<double, D>;

template <int D>
double max_f_error(np::NosbPd<double, D>& m, const double (&F0)[D][D]) {
  auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().F);
  double err = 0;
  for (pm::Index i = 0; i < m.particles(); ++i)
    for (int r = 0; r < D; ++r)
      for (int c = 0; c < D; ++c) err = std::max(err, std::abs(F(i, r * D + c) - F0[r][c]));
  return err;
}

template <int D>
void check_affine(np::Layout layout, bool weighted) {
  std::vector<std::string> eff;
  if (weighted) eff.push_back("weighted_function");
  np::NosbPd<double, D> m(box_config(D, 7, 3.0, eff, layout));
  double F0[D][D];
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) F0[r][c] = (r == c ? 1.0 : 0.0) + 0.05 * noise(static_cast<std::uint64_t>(r * 3 + c));
  pm::testing::set_displacement<np::NosbPd<double, D>, D>(m, [&](const Arr<D>& x, int) {
    Arr<D> u{};
    for (int r = 0; r < D; ++r) {
      u[r] = -x[r];
      for (int c = 0; c < D; ++c) u[r] += F0[r][c] * x[c];
    }
    return u;
  });
  m.compute_forces();
  EXPECT_LT(max_f_error<D>(m, F0), 1e-12) << "D = " << D << " layout " << int(layout) << " weighted " << weighted;
}

template <int D>
Arr<D> acc(const np::NosbPd<double, D>& m, pm::Index i) {
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  Arr<D> r;
  for (int k = 0; k < D; ++k) r[k] = a(i, k);
  return r;
}

template <int D>
std::vector<double> host_a(const np::NosbPd<double, D>& m) {
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  return std::vector<double>(a.data(), a.data() + D * m.particles());
}

double max_abs(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s = std::max(s, std::abs(x));
  return s;
}

// Total force sum rho V a (per component) and its scale sum rho V |a|.
template <int D>
std::pair<double, double> force_balance(const np::NosbPd<double, D>& m) {
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().volume);
  double sum[D] = {}, scale = 0;
  for (pm::Index i = 0; i < m.particles(); ++i)
    for (int k = 0; k < D; ++k) {
      sum[k] += V(i) * a(i, k);
      scale += V(i) * std::abs(a(i, k));
    }
  double s = 0;
  for (int k = 0; k < D; ++k) s = std::max(s, std::abs(sum[k]));
  return {s, scale};
}

}  // namespace

TEST(PdKernels, AffineDeformationGradientIsExactOnEveryParticleAndLayout) {
  for (bool weighted : {false, true}) {
    check_affine<2>(np::Layout::lattice, weighted);
    check_affine<2>(np::Layout::jittered, weighted);
    check_affine<3>(np::Layout::lattice, weighted);
    check_affine<3>(np::Layout::jittered, weighted);
  }
}

TEST(PdKernels, RigidRotationCarriesNoStress) {
  np::NosbPd<double, 3> m(box_config(3, 6, 3.0, {"weighted_function"}, np::Layout::jittered));
  const double t = 0.6, c = std::cos(t), s = std::sin(t);
  pm::testing::set_displacement<np::NosbPd<double, 3>, 3>(m, [&](const Arr<3>& x, int) {
    return Arr<3>{c * x[0] - s * x[1] - x[0], s * x[0] + c * x[1] - x[1], 0.0};
  });
  m.compute_forces();
  const double rot = max_abs(host_a(m));
  pm::testing::set_displacement<np::NosbPd<double, 3>, 3>(m, [&](const Arr<3>& x, int) { return Arr<3>{1e-3 * x[0], 0, 0}; });
  m.compute_forces();
  const double strained = max_abs(host_a(m));  // the same body at 0.1 % strain
  EXPECT_LT(rot, 1e-9 * strained) << rot << " vs " << strained;
}

TEST(PdKernels, ForcesConserveMomentumAndAreTheGradientOfTheStrainEnergy) {
  for (bool weighted : {false, true}) {
    np::NosbPd<double, 3> m(box_config(3, 6, 2.5, weighted ? std::vector<std::string>{"weighted_function"} : std::vector<std::string>{},
                                       np::Layout::jittered));
    const double h = 1e-3;
    pm::testing::set_displacement<np::NosbPd<double, 3>, 3>(
        m, [&](const Arr<3>&, int i) { return Arr<3>{2e-3 * h * noise(3 * i), 2e-3 * h * noise(3 * i + 1), 2e-3 * h * noise(3 * i + 2)}; });
    m.compute_forces();
    const auto [sum, scale] = force_balance<3>(m);
    EXPECT_LT(sum, 1e-12 * scale);
    // -dE/du_k = V_k rho a_k (St. Venant-Kirchhoff is hyperelastic, the force state its gradient)
    auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().volume);
    auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().u);
    for (pm::Index k : {pm::Index(0), pm::Index(m.particles() / 2), pm::Index(m.particles() - 1)}) {
      const auto a = acc<3>(m, k);
      for (int d = 0; d < 3; ++d) {
        const double eps = 1e-7 * h, u0 = u(k, d);
        u(k, d) = u0 + eps;
        Kokkos::deep_copy(m.fields().u, u);
        m.compute_forces();
        const double ep = m.energy().strain;
        u(k, d) = u0 - eps;
        Kokkos::deep_copy(m.fields().u, u);
        m.compute_forces();
        const double em = m.energy().strain;
        u(k, d) = u0;
        Kokkos::deep_copy(m.fields().u, u);
        const double force = -(ep - em) / (2 * eps);
        EXPECT_NEAR(force, 7850.0 * V(k) * a[d], 1e-5 * std::abs(force) + 1e-9) << "particle " << k << " dir " << d;
      }
    }
  }
}

TEST(PdKernels, UniformStressLeavesTheInteriorOfALatticeInEquilibrium) {
  // (the forces of particles within 2 delta of a surface feel the surface's truncated shape tensors)
  np::NosbPd<double, 3> m(box_config(3, 12, 2.0, {}));
  pm::testing::set_displacement<np::NosbPd<double, 3>, 3>(m, [&](const Arr<3>& x, int) { return Arr<3>{1e-3 * x[0], 0, 0}; });
  m.compute_forces();
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  double interior = 0, boundary = 0;
  const double lo = 4e-3, hi = 8e-3;
  for (pm::Index i = 0; i < m.particles(); ++i) {
    bool in = true;
    for (int k = 0; k < 3; ++k) in = in && x0(i, k) > lo && x0(i, k) < hi;
    for (int k = 0; k < 3; ++k) (in ? interior : boundary) = std::max(in ? interior : boundary, std::abs(a(i, k)));
  }
  EXPECT_LT(interior, 1e-10 * boundary) << interior << " vs " << boundary;
}

TEST(PdKernels, WeightedFunctionBetaGivesTheLatticeItsPlainVolume) {
  for (int dim : {2, 3})
    for (double mm : {1.5, 2.0, 3.0, 4.0}) {
      const double beta = np::weighted_function_beta(dim, mm);
      const auto plain = np::lattice_family(dim, 1.0, mm, false, 1.0);
      const auto w = np::lattice_family(dim, 1.0, mm, true, beta);
      EXPECT_NEAR(beta * w.weighted_volume, plain.plain_volume, 1e-12 * plain.plain_volume);
      // continuum limit: 1 / (1 - D/(D+2)) = (D + 2) / 2
      if (mm >= 3.0) {
        EXPECT_NEAR(beta, (dim + 2) / 2.0, 0.25 * (dim + 2) / 2.0) << dim << " " << mm;
      }
    }
}

TEST(PdKernels, JohnsonCookReturnMapStaysOnTheYieldSurface) {
  pm::materials::ElasticConstants<double> el{121.1e9, 75.2e9};
  pm::materials::JohnsonCook<double> jc;
  jc.A = 490e6;
  jc.B = 807e6;
  jc.n = 0.73;
  jc.rate0 = 5e-4;
  for (double C : {0.0, 0.0114}) {
    jc.C = C;
    const double rate = 1e4, dt = 1e-8;  // isochoric stretching, equivalent strain rate 1e4 /s
    pm::Mat3<double> L = pm::Mat3<double>::zero();
    L(0, 0) = rate;
    L(1, 1) = L(2, 2) = -0.5 * rate;
    auto sigma = pm::Mat3<double>::zero();
    double eps = 0, t = 0;
    for (int s = 0; s < 20000; ++s) {
      const auto st = pm::materials::j2_update(sigma, L, dt, el, jc, eps, 293.0);
      sigma = st.sigma;
      eps += st.d_eps_p;
      t += dt;
      if (eps > 0 && s % 5000 == 4999) {
        const double seq = pm::materials::von_mises(sigma);
        EXPECT_NEAR(seq, pm::materials::jc_flow_stress(jc, eps, st.d_eps_p / (dt * jc.rate0), 293.0), 1e-6 * seq);
        EXPECT_NEAR(eps, rate * t - seq / (3 * el.mu), 1e-9) << "plastic + elastic = total equivalent strain";
      }
    }
    EXPECT_NEAR(eps, 2.0 - pm::materials::von_mises(sigma) / (3 * el.mu), 1e-9);
  }
}

TEST(PdKernels, HourglassForceVanishesOnAffineFieldsAndResistsTheParityMode) {
  auto parity = [](const Arr<2>& x, int) {
    const auto ix = std::llround(x[0] / 1e-3 - 0.5), iy = std::llround(x[1] / 1e-3 - 0.5);
    return Arr<2>{((ix + iy) % 2 ? 1e-6 : -1e-6), 0.0};
  };
  for (bool hg : {false, true}) {
    np::NosbPd<double, 2> m(box_config(2, 16, 2.0, hg ? std::vector<std::string>{"hourglass"} : std::vector<std::string>{}));
    pm::testing::set_displacement<np::NosbPd<double, 2>, 2>(m, [](const Arr<2>& x, int) { return Arr<2>{1e-3 * x[0] + 2e-4 * x[1], -3e-4 * x[1]}; });
    m.compute_forces();
    const auto affine = host_a(m);
    pm::testing::set_displacement<np::NosbPd<double, 2>, 2>(m, parity);
    m.compute_forces();
    // interior particles only: there the NOSB force of the parity mode is exactly zero (F = I)
    auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
    auto u = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().u);
    auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
    double work = 0, amax = 0;
    for (pm::Index i = 0; i < m.particles(); ++i) {
      if (x0(i, 0) < 5e-3 || x0(i, 0) > 11e-3 || x0(i, 1) < 5e-3 || x0(i, 1) > 11e-3) continue;
      work += u(i, 0) * a(i, 0) + u(i, 1) * a(i, 1);
      amax = std::max({amax, std::abs(a(i, 0)), std::abs(a(i, 1))});
    }
    if (!hg) {
      EXPECT_LT(amax, 1e-6) << "the parity mode is a zero-energy mode of the interior";
    } else {
      EXPECT_LT(work, 0.0) << "the hourglass force opposes the parity mode";
      EXPECT_GT(amax, 1e3);
      // and does nothing to an affine field: compare with the run without it (same F everywhere)
      np::NosbPd<double, 2> plain(box_config(2, 16, 2.0, {}));
      pm::testing::set_displacement<np::NosbPd<double, 2>, 2>(plain, [](const Arr<2>& x, int) { return Arr<2>{1e-3 * x[0] + 2e-4 * x[1], -3e-4 * x[1]}; });
      plain.compute_forces();
      const auto ref = host_a(plain);
      for (std::size_t k = 0; k < ref.size(); ++k) EXPECT_NEAR(affine[k], ref[k], 1e-9 * max_abs(ref));
    }
  }
}

TEST(PdKernels, VelocityViscosityIgnoresRigidMotionConservesMomentumAndDissipates) {
  np::NosbPd<double, 3> m(box_config(3, 6, 3.0, {"velocity_viscosity", "weighted_function"}, np::Layout::jittered));
  // rigid translation + rotation: no force (the mean of a linear field over a family is not its
  // centre value on an irregular family, so this holds for translation exactly, for rotation to the
  // family's asymmetry; the test uses translation)
  pm::testing::set_velocity<np::NosbPd<double, 3>, 3>(m, [](const Arr<3>&, int) { return Arr<3>{3.0, -2.0, 1.0}; });
  m.compute_forces();
  EXPECT_LT(max_abs(host_a(m)), 1e-6);
  pm::testing::set_velocity<np::NosbPd<double, 3>, 3>(m, [](const Arr<3>&, int i) { return Arr<3>{noise(3 * i), noise(3 * i + 1), noise(3 * i + 2)}; });
  m.compute_forces();
  const auto [sum, scale] = force_balance<3>(m);
  EXPECT_LT(sum, 1e-12 * scale);
  auto v = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().v);
  auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().a);
  auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().volume);
  double power = 0;
  for (pm::Index i = 0; i < m.particles(); ++i)
    for (int k = 0; k < 3; ++k) power += V(i) * 7850 * v(i, k) * a(i, k);
  EXPECT_LT(power, 0.0) << "velocity viscosity removes kinetic energy";
}

TEST(PdKernels, ProjectileOverlapGeometry) {
  pm::contact::RigidProjectile<double, 3> cyl;
  cyl.radius = 0.01;
  cyl.length = 0.08;
  cyl.position = pm::Vec3<double>{{0, 0, 0.001}};
  const double rc = 5e-4;
  // below the face, inside the radius: pushed down by the face overlap
  auto o = pm::contact::projectile_overlap(cyl, pm::Vec3<double>{{0.002, 0.001, 0.0008}}, rc);
  EXPECT_NEAR(o.depth, 0.0008 - (0.001 - rc), 1e-15);
  EXPECT_DOUBLE_EQ(o.normal[2], -1.0);
  // near the rim, deep below the face: pushed out radially
  o = pm::contact::projectile_overlap(cyl, pm::Vec3<double>{{0.0102, 0.0, 0.004}}, rc);
  EXPECT_NEAR(o.depth, 0.0105 - 0.0102, 1e-15);
  EXPECT_NEAR(o.normal[0], 1.0, 1e-15);
  // outside
  EXPECT_EQ(pm::contact::projectile_overlap(cyl, pm::Vec3<double>{{0, 0, 0.0001}}, rc).depth, 0.0);
  EXPECT_EQ(pm::contact::projectile_overlap(cyl, pm::Vec3<double>{{0.011, 0, 0.004}}, rc).depth, 0.0);
  pm::contact::RigidProjectile<double, 3> ball;
  ball.shape = pm::contact::ProjectileShape::sphere;
  ball.radius = 0.005;
  o = pm::contact::projectile_overlap(ball, pm::Vec3<double>{{0.003, 0.004, 0.0}}, rc);
  EXPECT_NEAR(o.depth, rc, 1e-15);
  EXPECT_NEAR(o.normal[0], 0.6, 1e-15);
}

// Single precision at fine spacings: K ~ V |xi|^2 x (bonds) is ~1e-13 m^5 at 0.5 mm, its determinant
// ~1e-39 is below FLT_MIN; the shape tensor is scaled before its determinant and inverse are taken,
// so a homogeneous 0.1 % stretch still gives F = diag(1.001, 1, 1) on every particle with a full family.
TEST(PdKernels, SinglePrecisionShapeTensorAtFineSpacing) {
  np::NosbPd<float, 3> m(box_config(3, 8, 3.0, {"damage"}, np::Layout::lattice, 0.5e-3));
  auto u = Kokkos::create_mirror_view(m.fields().u);
  auto x0 = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().x0);
  for (pm::Index i = 0; i < m.particles(); ++i) {
    u(i, 0) = 1e-3f * x0(i, 0);
    u(i, 1) = u(i, 2) = 0.0f;
  }
  Kokkos::deep_copy(m.fields().u, u);
  m.compute_forces();
  auto F = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().F);
  auto status = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), m.fields().status);
  int failed = 0;
  double err = 0;
  for (pm::Index i = 0; i < m.particles(); ++i) {
    failed += (status(i) & pm::pd::status_failed) ? 1 : 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const double exact = r == c ? (r == 0 ? 1.001 : 1.0) : 0.0;
        const double v = F(i, 3 * r + c);
        err = std::isfinite(v) ? std::max(err, std::abs(v - exact)) : 1e300;
      }
  }
  EXPECT_EQ(failed, 0);
  EXPECT_LT(err, 2e-5) << "F of a homogeneous stretch in float";
}

// The scene's size estimate (issue 33 item 8) against the model that is built: the particle count and the
// bonds exactly on every layout without jitter (boxes, lattice and ring sections of discs and bars); a
// section of more than 2e4 points (the lens-area count) within 3 %.
TEST(PdKernels, LatticeSizeEstimateMatchesTheBuiltModel) {
  struct Case {
    const char* name;
    np::Config c;
    double bond_tolerance;
  };
  std::vector<Case> cases;
  cases.push_back({"3D box lattice", box_config(3, 7, 3.0, {}), 0.0});
  cases.push_back({"2D box, m = 4.5", box_config(2, 11, 4.5, {}), 0.0});
  np::Config bar = box_config(3, 7, 3.0, {}, np::Layout::lattice);
  bar.geometry.length = 0.012;
  bar.geometry.height = 0.005;
  cases.push_back({"3D thin box", bar, 0.0});
  np::Config disc = box_config(3, 7, 3.0, {});
  disc.geometry.shape = np::Shape::disc;
  disc.geometry.radius = 0.012;
  disc.geometry.thickness = 0.004;
  cases.push_back({"3D disc lattice", disc, 0.0});
  np::Config rings = disc;
  rings.geometry.layout = np::Layout::cylindrical;
  cases.push_back({"3D disc rings", rings, 0.0});
  np::Config round = disc;
  round.geometry.shape = np::Shape::round_bar;
  round.geometry.radius = 0.0025;  // the draft tension bar: 2.5 spacings (the issue: 393 particles estimated, 480 built)
  round.geometry.length = 0.010;
  cases.push_back({"round bar lattice", round, 0.0});
  round.geometry.layout = np::Layout::cylindrical;
  round.horizon_ratio = 7.0;
  cases.push_back({"round bar rings, m = 7", round, 0.0});
  np::Config wide = disc;  // 21 000 points in the section: the lens-area count
  wide.geometry.radius = 0.082;
  wide.geometry.thickness = 0.001;
  cases.push_back({"one-layer disc of radius 82 spacings", wide, 0.03});
  for (const auto& k : cases) {
    const np::LatticeSize est = np::lattice_size(k.c);
    double particles = 0, bonds = 0;
    if (k.c.dimension == 3) {
      np::NosbPd<double, 3> m(k.c);
      particles = m.particles();
      bonds = static_cast<double>(m.bonds());
    } else {
      np::NosbPd<double, 2> m(k.c);
      particles = m.particles();
      bonds = static_cast<double>(m.bonds());
    }
    EXPECT_EQ(est.particles, particles) << k.name;
    EXPECT_LE(std::abs(est.bonds - bonds), k.bond_tolerance * bonds + 0.5) << k.name << ": estimated " << est.bonds
                                                                             << " bonds, built " << bonds;
  }
}

// The watchdog's speed bound (issue 33 item 2): a particle one spacing per step or slower is healthy, one
// just above it is named with its speed and the bound.
TEST(PdKernels, WatchdogFlagsAParticleMovingASpacingPerStep) {
  np::NosbPd<double, 3> m(box_config(3, 6, 3.0, {}));
  const double limit = m.config().spacing / m.dt();
  const auto set_speed = [&](double s) {
    pm::testing::set_velocity<np::NosbPd<double, 3>, 3>(m, [s](const Arr<3>&, int i) {
      return i == 17 ? Arr<3>{0.0, s, 0.0} : Arr<3>{0.0, 0.0, 0.0};
    });
  };
  set_speed(0.99 * limit);
  EXPECT_TRUE(m.health().finite);
  set_speed(1.01 * limit);
  const pm::models::Health h = m.health();
  EXPECT_FALSE(h.finite);
  EXPECT_EQ(h.first_bad, 17);
  EXPECT_NE(h.problem.find("more than one spacing per step"), std::string::npos) << h.problem;
}
