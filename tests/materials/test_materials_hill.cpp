// Hill plasticity with cubic symmetry and the power-law hardening of seed 002 paper 5 eqs. (3)-(4), at one
// quadrature point, against closed forms: the hardening law; the yield metric (von Mises at R12 = 1, the
// shear yield R12 sigma_y/sqrt3, the printed form's meaning); the uniaxial yield stress along the rotated
// beam axes; the hardening curve under uniaxial stress (mixed-control point driver); unloading along the
// elastic slope; the consistent tangent against central differences; quadratic Newton convergence of the
// one-point mixed-control problem; the J2 limit against the classical radial return; the kernel path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "core/types.hpp"
#include "materials/hill_plasticity.hpp"
#include "material_fixtures.hpp"

namespace pm = polymech;
namespace mt = polymech::materials;

namespace {

using pm::testing::rad;
const auto& kAnglesDeg = pm::testing::kBeamAnglesDeg;

// 8YSZ elastic constants (GPa) with plastic parameters of the size the paper estimates (GPa).
mt::CubicHillParameters<double> crystal(double R12, double n = 0.3,
                                         mt::HillForm form = mt::HillForm::yield_stress_ratio) {
  mt::CubicHillParameters<double> p;
  p.elastic = mt::ysz8_constants_gpa<double>();
  p.yield_stress = 3.0;
  p.hardening_exponent = n;
  p.R12 = R12;
  p.form = form;
  return p;
}

mt::Voigt6<double> scaled(const mt::Voigt6<double>& v, double a) {
  mt::Voigt6<double> r;
  for (int i = 0; i < 6; ++i) r[i] = a * v[i];
  return r;
}
double norm6(const mt::Voigt6<double>& v) { return std::sqrt(mt::dot6(v, v)); }
double frobenius(const mt::Stiffness6<double>& A) {
  double s = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) s += A.c[i][j] * A.c[i][j];
  return std::sqrt(s);
}
double frobenius_difference(const mt::Stiffness6<double>& A, const mt::Stiffness6<double>& B) {
  double s = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) s += (A.c[i][j] - B.c[i][j]) * (A.c[i][j] - B.c[i][j]);
  return std::sqrt(s);
}

// Mixed control at one point: e_xx prescribed, the other five strains solved so that the other five stresses
// vanish (uniaxial stress along the specimen x axis), by Newton with the law's tangent (or, to contrast, the
// elastic stiffness). Residual: |lateral stresses| / sigma0.
struct UniaxialDriver {
  mt::HillPlasticity<double> law;
  mt::PlasticState<double> h;  // converged history
  mt::Voigt6<double> e, s;     // converged strain and stress
  bool consistent = true;
  std::vector<double> residuals;  // of the last step
  int local_iterations = 0;

  bool step(double exx, int max_iterations = 30) {
    mt::Voigt6<double> trial = e;
    trial[0] = exx;
    residuals.clear();
    for (int it = 0; it <= max_iterations; ++it) {
      auto hh = h;
      mt::Voigt6<double> ss;
      mt::Stiffness6<double> D;
      const int li = law.update(trial, hh, ss, D);
      if (li < 0) return false;
      double r = 0;
      for (int i = 1; i < 6; ++i) r += ss[i] * ss[i];
      r = std::sqrt(r) / law.hardening.sigma0;
      residuals.push_back(r);
      if (r < 1e-13) {
        h = hh;
        e = trial;
        s = ss;
        local_iterations = li;
        return true;
      }
      mt::Stiffness6<double> A = consistent ? D : law.C, L;
      mt::Voigt6<double> rhs = scaled(ss, -1.0);
      for (int i = 0; i < 6; ++i) A.c[0][i] = A.c[i][0] = 0.0;
      A.c[0][0] = 1.0;
      rhs[0] = 0.0;
      if (!mt::cholesky6(A, L)) return false;
      const auto dx = mt::cholesky_solve6(L, rhs);
      for (int i = 1; i < 6; ++i) trial[i] += dx[i];
    }
    return false;
  }
};

// Eq. (4) residual x - (x + a)^n with std::pow: an independent check of the law's hardening solve.
double hardening_residual(double x, double a, double n) { return x - std::pow(x + a, n); }

}  // namespace

TEST(HillPlasticity, PowerLawHardeningEq4) {
  mt::PowerLawHardening<double> hd{3.0, 0.5, 56.0};
  double H = 0;
  for (double eps : {0.0, 1e-6, 1e-3, 0.01, 0.1, 1.0}) {
    const double sy = hd.flow_stress(eps, H);
    const double a = 3 * hd.shear_modulus * eps / hd.sigma0;
    // n = 1/2: x^2 = x + a, x = (1 + sqrt(1 + 4a)) / 2.
    EXPECT_NEAR(sy / hd.sigma0, 0.5 * (1 + std::sqrt(1 + 4 * a)), 1e-14 * sy);
    // slope: d sigma_y/d eps = 3 G / sqrt(1 + 4a) for n = 1/2.
    EXPECT_NEAR(H, 3 * hd.shear_modulus / std::sqrt(1 + 4 * a), 1e-12 * H);
  }
  for (double n : {0.05, 0.2, 0.3, 0.6, 0.9}) {
    hd.exponent = n;
    EXPECT_DOUBLE_EQ(hd.flow_stress(0.0, H), hd.sigma0);
    EXPECT_NEAR(H, 3 * hd.shear_modulus * n / (1 - n), 1e-12 * H);  // initial slope
    for (double eps : {1e-5, 1e-3, 0.02, 0.5}) {
      const double sy = hd.flow_stress(eps, H);
      const double a = 3 * hd.shear_modulus * eps / hd.sigma0;
      EXPECT_LT(std::fabs(hardening_residual(sy / hd.sigma0, a, n)), 1e-13 * sy / hd.sigma0);
      double Hp = 0, Hm = 0;
      const double d = 1e-4 * eps;  // central differences: truncation ~1e-8, round-off ~1e-11 relative
      const double fd = (hd.flow_stress(eps + d, Hp) - hd.flow_stress(eps - d, Hm)) / (2 * d);
      EXPECT_NEAR(H / fd, 1.0, 1e-6);
    }
  }
  hd.exponent = 0.0;  // perfectly plastic
  EXPECT_DOUBLE_EQ(hd.flow_stress(0.3, H), hd.sigma0);
  EXPECT_EQ(H, 0.0);
}

TEST(HillPlasticity, MetricReadingsOfEq3) {
  const mt::Voigt6<double> s{{1.3, -0.4, 0.7, 0.25, -0.6, 0.9}};
  // von Mises: phi^2 = 3/2 dev(s):dev(s).
  const double p = (s[0] + s[1] + s[2]) / 3;
  double dd = 0;
  for (int i = 0; i < 3; ++i) dd += (s[i] - p) * (s[i] - p);
  for (int i = 3; i < 6; ++i) dd += 2 * s[i] * s[i];
  const auto vm = mt::von_mises_metric<double>();
  EXPECT_NEAR(mt::quadratic6(s, vm, s), 1.5 * dd, 1e-14);
  // The ratio reading: <100> tensile yield = sigma_y, cube-plane shear yield = R12 sigma_y / sqrt3.
  for (double R12 : {0.6, 1.0, 1.4}) {
    const auto P = mt::cubic_hill_metric(R12);
    EXPECT_NEAR(mt::hill_uniaxial_yield_ratio(P, pm::Vec3<double>{{1, 0, 0}}), 1.0, 1e-15);
    mt::Voigt6<double> shear;
    shear[5] = 1.0;
    EXPECT_NEAR(1.0 / std::sqrt(mt::quadratic6(shear, P, shear)), R12 / std::sqrt(3.0), 1e-15);
    // Hydrostatic stress never yields (the metric's null space).
    const mt::Voigt6<double> hyd{{1, 1, 1, 0, 0, 0}};
    EXPECT_NEAR(mt::quadratic6(hyd, P, hyd), 0.0, 1e-15);
  }
  // The printed coefficients under a square root: <100> yield sigma_y/sqrt3, and sqrt3 von Mises at R12 = 1/3.
  const auto printed = mt::cubic_hill_metric(1.0 / 3.0, mt::HillForm::as_printed);
  EXPECT_NEAR(mt::hill_uniaxial_yield_ratio(printed, pm::Vec3<double>{{0, 0, 1}}), 1 / std::sqrt(3.0), 1e-15);
  EXPECT_NEAR(mt::quadratic6(s, printed, s), 3 * mt::quadratic6(s, vm, s), 1e-13);
}

TEST(HillPlasticity, UniaxialYieldAlongTheBeamAxes) {
  for (double R12 : {0.8, 1.25}) {
    const auto p = crystal(R12);
    for (double deg : kAnglesDeg) {
      const auto Q = mt::cantilever_rotation(rad(deg));
      const auto law = mt::make_cubic_hill(p, Q);
      // Closed form: sigma_u = sigma_y / sqrt(1 + 3 Gamma (1/R12^2 - 1)), Gamma = n1^2 n2^2 + n2^2 n3^2 + n3^2 n1^2.
      const auto n = mt::cantilever_axis(rad(deg));
      const double g = n[0] * n[0] * n[1] * n[1] + n[1] * n[1] * n[2] * n[2] + n[2] * n[2] * n[0] * n[0];
      const double closed = p.yield_stress / std::sqrt(1 + 3 * g * (1 / (R12 * R12) - 1));
      const double from_metric = p.yield_stress / std::sqrt(law.P.c[0][0]);  // rotated metric, specimen x
      EXPECT_NEAR(from_metric / closed, 1.0, 1e-13);
      // The law: the elastic strain of a uniaxial stress 0.1 % below the closed form stays elastic, 0.1 %
      // above it flows.
      for (double f : {0.999, 1.001}) {
        mt::Voigt6<double> eps;
        for (int i = 0; i < 6; ++i) eps[i] = f * closed * law.S.c[i][0];
        mt::PlasticState<double> h;
        mt::Voigt6<double> s;
        mt::Stiffness6<double> D;
        const int it = law.update(eps, h, s, D);
        if (f < 1) {
          EXPECT_EQ(it, 0);
          EXPECT_EQ(h.equivalent_plastic_strain, 0.0);
        } else {
          EXPECT_GT(it, 0);
          EXPECT_GT(h.equivalent_plastic_strain, 0.0);
        }
      }
      if (R12 == 0.8) std::printf("R12 %.2f theta %7.4f deg: uniaxial yield %.6f GPa\n", R12, deg, closed);
    }
  }
}

TEST(HillPlasticity, HardeningCurveUnderUniaxialStress) {
  const auto p = crystal(0.8);
  for (double deg : {20.0, 54.735610317245345}) {
    UniaxialDriver d;
    d.law = mt::make_cubic_hill(p, mt::cantilever_rotation(rad(deg)));
    const double E = 1.0 / d.law.S.c[0][0];
    const double sigma_u = p.yield_stress / std::sqrt(d.law.P.c[0][0]);  // checked against the closed form above
    const double ey = sigma_u / E;
    double worst_stress = 0, worst_strain = 0;
    for (int k = 1; k <= 40; ++k) {
      ASSERT_TRUE(d.step(ey * 0.1 * k)) << "step " << k;
      const double ebar = d.h.equivalent_plastic_strain;
      // Eq. (4) along this axis: sigma_xx / sigma_u = x with x = (x + 3 C44 ebar / sigma_y)^n.
      const double x = d.s[0] / sigma_u;
      const double a = 3 * p.elastic.C44 * ebar / p.yield_stress;
      if (ebar > 0) worst_stress = std::max(worst_stress, std::fabs(hardening_residual(x, a, p.hardening_exponent)));
      // The strain splits into the elastic part and the axial plastic strain ebar * sqrt(P'_11) (work conjugacy).
      worst_strain = std::max(worst_strain, std::fabs(d.e[0] - d.s[0] / E - ebar * std::sqrt(d.law.P.c[0][0])) / ey);
      if (k == 40) std::printf("theta %.4f: e_xx = 4 e_y: sigma_xx / sigma_u = %.6f, ebar = %.6e\n", deg, x, ebar);
    }
    EXPECT_LT(worst_stress, 1e-12);
    EXPECT_LT(worst_strain, 1e-10);
    EXPECT_GT(d.h.equivalent_plastic_strain, 1.0 * ey);  // it did flow
  }
}

TEST(HillPlasticity, UnloadingFollowsTheElasticSlope) {
  const auto p = crystal(0.8);
  const double deg = 30.0;
  UniaxialDriver d;
  d.law = mt::make_cubic_hill(p, mt::cantilever_rotation(rad(deg)));
  const double E = mt::cubic_uniaxial_modulus(p.elastic, mt::cantilever_axis(rad(deg)));
  const double ey = p.yield_stress / std::sqrt(d.law.P.c[0][0]) / E;
  for (int k = 1; k <= 25; ++k) ASSERT_TRUE(d.step(0.1 * k * ey));
  const double e_max = d.e[0], s_max = d.s[0], ebar_max = d.h.equivalent_plastic_strain;
  ASSERT_GT(ebar_max, 0.0);
  double worst = 0, s_prev = s_max, e_prev = e_max;
  const double e_residual = e_max - s_max / E;  // where the stress returns to zero
  for (int k = 1; k <= 10; ++k) {
    ASSERT_TRUE(d.step(e_max - 0.1 * k * (e_max - e_residual)));
    EXPECT_EQ(d.local_iterations, 0);  // elastic
    worst = std::max(worst, std::fabs((s_prev - d.s[0]) / (e_prev - d.e[0]) / E - 1));
    s_prev = d.s[0];
    e_prev = d.e[0];
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_EQ(d.h.equivalent_plastic_strain, ebar_max);
  EXPECT_LT(std::fabs(d.s[0]) / s_max, 1e-9);
  // Reloading is elastic up to the stress where unloading began, then flows again.
  ASSERT_TRUE(d.step(e_max - 1e-3 * (e_max - e_residual)));
  EXPECT_EQ(d.local_iterations, 0);
  ASSERT_TRUE(d.step(e_max + 0.1 * ey));
  EXPECT_GT(d.local_iterations, 0);
  std::printf("theta 30: loaded to %.4f GPa at e = %.4e, unloading slope within %.1e of E = %.4f GPa, residual "
              "strain %.4e\n", s_max, e_max, worst, E, e_residual);
}

// Central differences of the stress update against the consistent tangent, from a hardened state.
double tangent_error(const mt::HillPlasticity<double>& law, const mt::Voigt6<double>& direction) {
  // A plastic history: load radially to 3x the first yield strain along `direction`.
  mt::PlasticState<double> h0;
  {
    mt::Voigt6<double> s0;
    mt::Stiffness6<double> D0;
    for (int k = 1; k <= 5; ++k) law.update(scaled(direction, 0.6 * k), h0, s0, D0);
  }
  EXPECT_GT(h0.equivalent_plastic_strain, 0.0);
  mt::Voigt6<double> e = scaled(direction, 3.4);  // a further plastic step, not along the previous one
  e[3] += 0.3 * direction[0];
  e[5] -= 0.2 * direction[0];
  auto h = h0;
  mt::Voigt6<double> s;
  mt::Stiffness6<double> D, fd;
  EXPECT_GT(law.update(e, h, s, D), 0);
  const double step = 1e-6 * norm6(e);
  for (int j = 0; j < 6; ++j) {
    auto ep = e, em = e;
    ep[j] += step;
    em[j] -= step;
    auto hp = h0, hm = h0;
    mt::Voigt6<double> sp, sm;
    mt::Stiffness6<double> Dp, Dm;
    law.update(ep, hp, sp, Dp);
    law.update(em, hm, sm, Dm);
    for (int i = 0; i < 6; ++i) fd.c[i][j] = (sp[i] - sm[i]) / (2 * step);
  }
  EXPECT_LT(frobenius_difference(D, mt::transpose6(D)), 1e-13 * frobenius(D));  // symmetric
  return frobenius_difference(D, fd) / frobenius(D);
}

TEST(HillPlasticity, ConsistentTangentEqualsFiniteDifferences) {
  // A strain direction scaled so that 1.0 is at about the first yield.
  mt::Voigt6<double> dir{{1.0, -0.35, -0.2, 0.4, -0.3, 0.5}};
  dir = scaled(dir, 3.0 / 400.0 / norm6(dir) * 1.2);
  struct Case {
    const char* name;
    mt::HillPlasticity<double> law;
  };
  const Case cases[] = {
      {"J2, n = 0.3", mt::make_j2(200.0, 0.3, 3.0, 0.3)},
      {"J2, perfectly plastic", mt::make_j2(200.0, 0.3, 3.0, 0.0)},
      {"cubic R12 = 0.7, 10 deg", mt::make_cubic_hill(crystal(0.7), mt::cantilever_rotation(rad(10.0)))},
      {"cubic R12 = 1.3, 54.7 deg", mt::make_cubic_hill(crystal(1.3, 0.15), mt::cantilever_rotation(rad(54.7)))},
      {"as printed, R12 = 0.5, 20 deg",
       mt::make_cubic_hill(crystal(0.5, 0.3, mt::HillForm::as_printed), mt::cantilever_rotation(rad(20.0)))},
  };
  for (const auto& c : cases) {
    const double err = tangent_error(c.law, dir);
    std::printf("%-32s |D - D_fd| / |D| = %.2e\n", c.name, err);
    EXPECT_LT(err, 1e-6) << c.name;
  }
}

TEST(HillPlasticity, MixedControlNewtonConvergesQuadratically) {
  const auto p = crystal(0.8);
  UniaxialDriver d;
  d.law = mt::make_cubic_hill(p, mt::cantilever_rotation(rad(20.0)));
  const double ey = p.yield_stress / std::sqrt(d.law.P.c[0][0]) * d.law.S.c[0][0];
  ASSERT_TRUE(d.step(1.2 * ey));
  UniaxialDriver slow = d;  // the same state, to solve with the elastic stiffness instead
  ASSERT_TRUE(d.step(3.0 * ey));  // one large plastic step
  std::printf("consistent tangent, residual |lateral stress| / sigma_y:");
  for (double r : d.residuals) std::printf(" %.2e", r);
  std::printf("\n");
  EXPECT_LE(d.residuals.size(), 7u);
  // Quadratic: r_{k+1} <= K r_k^2 over the iterations above round-off (K measured 0.004 to 0.5 here; 10 allowed).
  int quadratic_steps = 0;
  for (std::size_t k = 0; k + 1 < d.residuals.size(); ++k) {
    if (d.residuals[k + 1] < 1e-12) break;
    EXPECT_LT(d.residuals[k + 1], 10 * d.residuals[k] * d.residuals[k]) << "iteration " << k;
    ++quadratic_steps;
  }
  EXPECT_GE(quadratic_steps, 2);
  slow.consistent = false;
  ASSERT_TRUE(slow.step(3.0 * ey, 500));
  std::printf("elastic stiffness instead: %zu iterations (consistent tangent: %zu)\n", slow.residuals.size(),
              d.residuals.size());
  EXPECT_GT(slow.residuals.size(), 3 * d.residuals.size());
  EXPECT_NEAR(slow.s[0] / d.s[0], 1.0, 1e-10);  // the same answer
}

// The classical J2 radial return (Simo & Taylor 1985) in tensor form, with the same hardening law.
void radial_return(double young, double nu, const mt::PowerLawHardening<double>& hd, const mt::Voigt6<double>& e,
                   double ebar_n, mt::Voigt6<double>& s, mt::Stiffness6<double>& D) {
  const double G = young / (2 * (1 + nu)), K = young / (3 * (1 - 2 * nu));
  const double tr = e[0] + e[1] + e[2];
  double dev[6];  // deviatoric trial stress, tensor components
  for (int i = 0; i < 3; ++i) dev[i] = 2 * G * (e[i] - tr / 3);
  for (int i = 3; i < 6; ++i) dev[i] = G * e[i];
  double dd = 0;
  for (int i = 0; i < 6; ++i) dd += (i < 3 ? 1 : 2) * dev[i] * dev[i];
  const double q = std::sqrt(1.5 * dd), norm = std::sqrt(dd);
  double H = 0, dl = 0;
  for (int it = 0; it < 100; ++it) {  // q - 3 G dl - sigma_y(ebar_n + dl) = 0
    const double r = q - 3 * G * dl - hd.flow_stress(ebar_n + dl, H);
    if (it == 0 && r <= 0) break;
    const double step = r / (3 * G + H);
    dl += step;
    if (std::fabs(step) < 1e-16 * (ebar_n + dl)) break;
  }
  hd.flow_stress(ebar_n + dl, H);
  const double f = 1 - 3 * G * dl / q;
  for (int i = 0; i < 6; ++i) s[i] = f * dev[i] + (i < 3 ? K * tr : 0.0);
  D = mt::Stiffness6<double>{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double idev = (i == j ? (i < 3 ? 1.0 : 0.5) : 0.0) - (i < 3 && j < 3 ? 1.0 / 3 : 0.0);
      D.c[i][j] = (i < 3 && j < 3 ? K : 0.0) + 2 * G * f * idev +
                  6 * G * G * (dl / q - 1 / (3 * G + H)) * dev[i] * dev[j] / (norm * norm);
    }
}

TEST(HillPlasticity, J2LimitIsTheRadialReturn) {
  const double young = 210.0, nu = 0.28;
  for (double n : {0.0, 0.2, 0.5}) {
    const auto law = mt::make_j2(young, nu, 0.8, n);
    for (double ebar_n : {0.0, 0.004}) {
      double H = 0;
      const double sy_n = law.hardening.flow_stress(ebar_n, H);
      for (double scale : {1.5, 4.0, 30.0}) {
        mt::Voigt6<double> e{{1.0, -0.2, -0.45, 0.3, 0.0, -0.6}};
        e = scaled(e, scale * sy_n / law.equivalent_stress(law.C * e));  // trial stress at `scale` x yield
        mt::PlasticState<double> h;
        h.equivalent_plastic_strain = ebar_n;
        mt::Voigt6<double> s, s_ref;
        mt::Stiffness6<double> D, D_ref;
        const int iterations = law.update(e, h, s, D);
        ASSERT_GT(iterations, 0);
        radial_return(young, nu, law.hardening, e, ebar_n, s_ref, D_ref);
        mt::Voigt6<double> ds;
        for (int i = 0; i < 6; ++i) ds[i] = s[i] - s_ref[i];
        const double es = norm6(ds) / norm6(s_ref), ed = frobenius_difference(D, D_ref) / frobenius(D_ref);
        std::printf("J2 n %.1f ebar_n %.3f trial %4.1f x yield: %d local iterations, stress %.1e, tangent %.1e\n", n,
                    ebar_n, scale, iterations, es, ed);
        EXPECT_LT(es, 1e-12);
        EXPECT_LT(ed, 1e-10) << "n " << n << " scale " << scale;
      }
    }
  }
}

// The update in a Kokkos kernel (the device path of the elements) agrees with the host call; float compiles
// and agrees to single precision.
template <class T>
void check_hill_in_kernel(double tol) {
  mt::CubicHillParameters<T> p;
  p.elastic = mt::ysz8_constants_gpa<T>();
  p.yield_stress = T(3);
  p.hardening_exponent = T(0.3);
  p.R12 = T(0.8);
  const auto law = mt::make_cubic_hill(p, mt::cantilever_rotation(T(rad(10.0))));
  const int n = 32;
  Kokkos::View<T* [7]> out("out", n);
  auto strain = [](int q, int i) { return T(2e-2) * T(((q + 1) * (i + 3)) % 9 - 4) / T(4); };
  Kokkos::parallel_for(
      "test::materials::hill_law", Kokkos::RangePolicy<pm::ExecSpace>(0, n), KOKKOS_LAMBDA(const int q) {
        mt::Voigt6<T> e, s;
        for (int i = 0; i < 6; ++i) e[i] = T(2e-2) * T(((q + 1) * (i + 3)) % 9 - 4) / T(4);
        mt::PlasticState<T> h;
        mt::Stiffness6<T> D;
        law.update(e, h, s, D);
        for (int i = 0; i < 6; ++i) out(q, i) = s[i];
        out(q, 6) = h.equivalent_plastic_strain;
      });
  auto ho = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
  int plastic = 0;
  for (int q = 0; q < n; ++q) {
    mt::Voigt6<T> e, s;
    for (int i = 0; i < 6; ++i) e[i] = strain(q, i);
    mt::PlasticState<T> h;
    mt::Stiffness6<T> D;
    ASSERT_GE(law.update(e, h, s, D), 0);
    plastic += h.equivalent_plastic_strain > T(0);
    double scale = 0;
    for (int i = 0; i < 6; ++i) scale = std::max(scale, std::fabs(double(s[i])));
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(double(ho(q, i)), double(s[i]), tol * scale);
    EXPECT_NEAR(double(ho(q, 6)), double(h.equivalent_plastic_strain), tol * double(h.equivalent_plastic_strain));
  }
  EXPECT_GT(plastic, n / 4);
}

TEST(HillPlasticity, LawInKernelDoubleAndFloat) {
  static_assert(mt::HillPlasticity<double>::has_history, "plasticity keeps history");
  check_hill_in_kernel<double>(1e-13);
  check_hill_in_kernel<float>(1e-4);
  // float against double on the same points: single precision answers.
  mt::CubicHillParameters<double> pd = crystal(0.8);
  mt::CubicHillParameters<float> pf;
  pf.elastic = mt::ysz8_constants_gpa<float>();
  pf.yield_stress = 3.0f;
  pf.hardening_exponent = 0.3f;
  pf.R12 = 0.8f;
  const auto ld = mt::make_cubic_hill(pd, mt::cantilever_rotation(rad(10.0)));
  const auto lf = mt::make_cubic_hill(pf, mt::cantilever_rotation(float(rad(10.0))));
  mt::Voigt6<double> ed{{18e-3, -6e-3, -3e-3, 9e-3, 3e-3, -6e-3}};
  mt::Voigt6<float> ef;
  for (int i = 0; i < 6; ++i) ef[i] = float(ed[i]);
  mt::PlasticState<double> hd;
  mt::PlasticState<float> hf;
  mt::Voigt6<double> sd;
  mt::Voigt6<float> sf;
  mt::Stiffness6<double> Dd;
  mt::Stiffness6<float> Df;
  ASSERT_GT(ld.update(ed, hd, sd, Dd), 0);
  ASSERT_GT(lf.update(ef, hf, sf, Df), 0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(double(sf[i]), sd[i], 1e-4 * norm6(sd));
  EXPECT_NEAR(double(hf.equivalent_plastic_strain) / hd.equivalent_plastic_strain, 1.0, 1e-3);
}
