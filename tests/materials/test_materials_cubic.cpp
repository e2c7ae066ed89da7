// Rotated cubic elasticity (seed 002 paper 5 eqs. (1)-(2)): the Bond rotation equals the rotation of the
// fourth-order tensor; along the six beam axes of the paper, the rotated stiffness inverted gives the
// closed-form uniaxial modulus; an isotropic crystal (C11 - C12 = 2 C44) is rotation invariant; the rotated
// matrix is symmetric positive definite; the law gives the same answer inside a Kokkos kernel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/types.hpp"
#include "materials/cubic_elastic.hpp"
#include "material_fixtures.hpp"

namespace pm = polymech;
namespace mt = polymech::materials;

namespace {

using pm::testing::rad;
const auto& kAnglesDeg = pm::testing::kBeamAnglesDeg;

double max_abs(const mt::Stiffness6<double>& A) {
  double m = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m = std::max(m, std::fabs(A.c[i][j]));
  return m;
}
double max_abs_difference(const mt::Stiffness6<double>& A, const mt::Stiffness6<double>& B) {
  double m = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) m = std::max(m, std::fabs(A.c[i][j] - B.c[i][j]));
  return m;
}

// C_ijkl from the Voigt stiffness (engineering shear strains: C_ijkl = C[I][J] for every index pair).
double tensor_entry(const mt::Stiffness6<double>& C, int i, int j, int k, int l) {
  auto slot = [](int a, int b) {
    if (a == b) return a;
    const int s = a + b;  // 1+2 -> 23 (3), 0+2 -> 13 (4), 0+1 -> 12 (5)
    return s == 3 ? 3 : (s == 2 ? 4 : 5);
  };
  return C.c[slot(i, j)][slot(k, l)];
}

}  // namespace

TEST(CubicElastic, BondRotationEqualsTensorRotation) {
  const auto k = mt::ysz8_constants_gpa<double>();
  const auto C = mt::cubic_stiffness(k);
  const auto Q = mt::cantilever_rotation(rad(20.0));
  const auto R = mt::rotate_stiffness(C, Q);
  double worst = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int p = 0; p < 3; ++p)
        for (int q = 0; q < 3; ++q) {
          double s = 0;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
              for (int c = 0; c < 3; ++c)
                for (int d = 0; d < 3; ++d)
                  s += Q.a[i][a] * Q.a[j][b] * Q.a[p][c] * Q.a[q][d] * tensor_entry(C, a, b, c, d);
          worst = std::max(worst, std::fabs(s - tensor_entry(R, i, j, p, q)));
        }
  EXPECT_LT(worst, 1e-12 * k.C11);
  // The strain Bond matrix is the inverse transpose of the stress one.
  const auto NtM = mt::product6(mt::transpose6(mt::bond_strain(Q)), mt::bond_stress(Q));
  EXPECT_LT(max_abs_difference(NtM, mt::identity6<double>()), 1e-14);
}

TEST(CubicElastic, CantileverAxesAreTheTopFaceAndAnAxisInIt) {
  for (double deg : kAnglesDeg) {
    const auto Q = mt::cantilever_rotation(rad(deg));
    const auto QQt = Q * pm::transpose(Q);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(QQt.a[i][j], i == j ? 1.0 : 0.0, 1e-15);
    EXPECT_NEAR(pm::det(Q), 1.0, 1e-15);                          // right-handed
    EXPECT_NEAR(Q.a[2][0] * std::sqrt(2.0), 1.0, 1e-15);          // z = [110]/sqrt2
    EXPECT_NEAR(Q.a[0][0] + Q.a[0][1], 0.0, 1e-15);               // beam axis in the (110) plane
    EXPECT_NEAR(Q.a[0][2], std::cos(rad(deg)), 1e-15);            // at theta from [001]
  }
  // 54.7356 deg is the <111> direction [1-11]/sqrt3.
  const auto n = mt::cantilever_axis(rad(kAnglesDeg[5]));
  EXPECT_NEAR(n[0], 1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(n[1], -1 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(n[2], 1 / std::sqrt(3.0), 1e-12);
}

TEST(CubicElastic, RotatedComplianceGivesTheClosedFormModulus) {
  const auto k = mt::ysz8_constants_gpa<double>();
  EXPECT_LT(max_abs_difference(mt::spd_inverse6(mt::cubic_stiffness(k)), mt::cubic_compliance(k)), 1e-15);
  std::printf("8YSZ (C11, C12, C44) = (%.0f, %.0f, %.0f) GPa, Zener ratio %.4f\n", k.C11, k.C12, k.C44,
              k.zener_ratio());
  for (double deg : kAnglesDeg) {
    const auto Q = mt::cantilever_rotation(rad(deg));
    const auto S = mt::spd_inverse6(mt::rotated_cubic_stiffness(k, Q));
    const double e_fe = 1.0 / S.c[0][0];
    const double e_closed = mt::cubic_uniaxial_modulus(k, mt::cantilever_axis(rad(deg)));
    // The mirror image n = (sin/sqrt2, +sin/sqrt2, cos), in the (1-10) plane, has the same modulus.
    const double s = std::sin(rad(deg)) / std::sqrt(2.0);
    const double e_mirror = mt::cubic_uniaxial_modulus(k, pm::Vec3<double>{{s, s, std::cos(rad(deg))}});
    // The rotated compliance directly (N S N^T) as well.
    const double e_rot_s = 1.0 / mt::rotate_compliance(mt::cubic_compliance(k), Q).c[0][0];
    std::printf("theta %8.4f deg: E = %.6f GPa (inverted rotated C), %.6f (closed form)\n", deg, e_fe, e_closed);
    EXPECT_NEAR(e_fe / e_closed, 1.0, 1e-13);
    EXPECT_NEAR(e_mirror / e_closed, 1.0, 1e-13);
    EXPECT_NEAR(e_rot_s / e_closed, 1.0, 1e-13);
  }
  // The ends of the range: <100> = 1/S11, <111> = 3 / (S11 + 2 S12 + S44).
  EXPECT_NEAR(mt::cubic_uniaxial_modulus(k, pm::Vec3<double>{{0, 0, 1}}) * k.S11(), 1.0, 1e-14);
  EXPECT_NEAR(mt::cubic_uniaxial_modulus(k, mt::cantilever_axis(rad(kAnglesDeg[5]))) *
                  (k.S11() + 2 * k.S12() + k.S44()) / 3.0,
              1.0, 1e-13);
}

TEST(CubicElastic, IsotropicCrystalIsRotationInvariant) {
  mt::CubicConstants<double> k;
  k.C11 = 300;
  k.C12 = 120;
  k.C44 = 90;  // C11 - C12 = 2 C44
  const auto C = mt::cubic_stiffness(k);
  // It is the isotropic stiffness of E, nu with lambda = C12, mu = C44.
  const double mu = k.C44, lambda = k.C12;
  const double young = mu * (3 * lambda + 2 * mu) / (lambda + mu), nu = lambda / (2 * (lambda + mu));
  EXPECT_LT(max_abs_difference(C, mt::isotropic_stiffness(young, nu)), 1e-12 * k.C11);
  for (double deg : {0.0, 17.0, 54.7, 77.0, 123.0}) {
    EXPECT_LT(max_abs_difference(mt::rotated_cubic_stiffness(k, mt::cantilever_rotation(rad(deg))), C),
              1e-12 * k.C11);
  }
  // A rotation about an axis that is not a beam rotation: 0.7 rad about (1, 2, 3)/sqrt14.
  const double w[3] = {1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0)};
  const auto Q = pm::testing::axis_angle_rotation(w, 0.7);
  EXPECT_NEAR(pm::det(Q), 1.0, 1e-14);
  EXPECT_LT(max_abs_difference(mt::rotate_stiffness(C, Q), C), 1e-12 * k.C11);
  // The anisotropic crystal is not: its rotated C11 changes by tens of percent.
  const auto ysz = mt::ysz8_constants_gpa<double>();
  const auto R = mt::rotated_cubic_stiffness(ysz, mt::cantilever_rotation(rad(30.0)));
  EXPECT_GT(std::fabs(R.c[0][0] - ysz.C11), 0.1 * ysz.C11);
}

TEST(CubicElastic, RotatedStiffnessIsSymmetricPositiveDefinite) {
  const auto k = mt::ysz8_constants_gpa<double>();
  for (double deg : kAnglesDeg) {
    const auto C = mt::rotated_cubic_stiffness(k, mt::cantilever_rotation(rad(deg)));
    EXPECT_LT(max_abs_difference(C, mt::transpose6(C)), 1e-13 * max_abs(C));
    mt::Stiffness6<double> L;
    ASSERT_TRUE(mt::cholesky6(C, L));
    // Positive definite with margin: the smallest Cholesky pivot squared stays above the smallest
    // eigenvalue of the crystal stiffness, min(C11 - C12, C11 + 2 C12, C44) = 56 GPa, times a fraction
    // (pivots bound eigenvalues from above, so only a positive lower bound is asserted).
    double smallest = 1e300;
    for (int i = 0; i < 6; ++i) smallest = std::min(smallest, L.c[i][i] * L.c[i][i]);
    EXPECT_GT(smallest, 0.5 * k.C44);
    // The strain energy of a random strain is the same in both frames (the rotation does no work).
    mt::Voigt6<double> e;
    for (int i = 0; i < 6; ++i) e[i] = 1e-3 * (0.3 + 0.17 * i - 0.05 * i * i);
    const auto Q = mt::cantilever_rotation(rad(deg));
    const auto e_c = mt::transpose6(mt::bond_stress(Q)) * e;  // crystal components of the same strain
    const double w_s = 0.5 * mt::dot6(C * e, e), w_c = 0.5 * mt::dot6(mt::cubic_stiffness(k) * e_c, e_c);
    EXPECT_NEAR(w_s / w_c, 1.0, 1e-13);
  }
  // A non-positive-definite matrix is reported, not factored.
  auto bad = mt::cubic_stiffness(k);
  bad.c[3][3] = -1.0;
  mt::Stiffness6<double> L;
  EXPECT_FALSE(mt::cholesky6(bad, L));
  EXPECT_TRUE(std::isnan(mt::spd_inverse6(bad).c[0][0]));
}

// The law runs in a Kokkos kernel (the device path the elements use) and agrees with the host call;
// float compiles and agrees to single precision.
template <class T>
void check_law_in_kernel(double tol) {
  const auto k = mt::ysz8_constants_gpa<T>();
  const auto law = mt::make_cubic_elastic(k, mt::cantilever_rotation(T(rad(10.0))));
  const int n = 16;
  Kokkos::View<T* [6]> stress("stress", n);
  Kokkos::View<T*> energy("energy", n);
  Kokkos::parallel_for(
      "test::materials::elastic_law", Kokkos::RangePolicy<pm::ExecSpace>(0, n), KOKKOS_LAMBDA(const int p) {
        mt::Voigt6<T> e, s;
        for (int i = 0; i < 6; ++i) e[i] = T(1e-3) * T((p + 1) * (i + 2) % 7 - 3);
        mt::NoHistory h;
        mt::Stiffness6<T> D;
        law.update(e, h, s, D);
        for (int i = 0; i < 6; ++i) stress(p, i) = s[i];
        energy(p) = law.energy_density(e);
      });
  auto hs = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), stress);
  auto he = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), energy);
  for (int p = 0; p < n; ++p) {
    mt::Voigt6<T> e;
    for (int i = 0; i < 6; ++i) e[i] = T(1e-3) * T((p + 1) * (i + 2) % 7 - 3);
    const auto s = law.stress(e);
    double scale = 0;
    for (int i = 0; i < 6; ++i) scale = std::max(scale, std::fabs(double(s[i])));
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(double(hs(p, i)), double(s[i]), tol * scale);
    EXPECT_NEAR(double(he(p)), 0.5 * double(mt::dot6(s, e)), tol * double(he(p)) + 1e-30);
  }
}

TEST(CubicElastic, LawInKernelDoubleAndFloat) {
  static_assert(!mt::AnisotropicElastic<double>::has_history, "the elastic law keeps no history");
  check_law_in_kernel<double>(1e-14);
  check_law_in_kernel<float>(1e-5);
}
