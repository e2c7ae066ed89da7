// Finite-strain hyperelastic laws (neo-Hookean, Mooney-Rivlin, the St. Venant-Kirchhoff tangent): P = dW/dF
// and A = dP/dF against central differences at moderate and large deformations, the major symmetry of A,
// a stress-free reference whose tangent is linear isotropic elasticity, objectivity, the kernel path.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/types.hpp"
#include "materials/hyperelastic.hpp"
#include "material_fixtures.hpp"

namespace pm = polymech;
namespace mt = polymech::materials;
using M3 = pm::Mat3<double>;

namespace {

// A law seen through W, P and A, whichever struct it is.
struct LawView {
  const char* name;
  double (*W)(const M3&);
  M3 (*P)(const M3&);
  mt::PiolaTangent<double> (*A)(const M3&);
  double lambda, mu;  // small-strain Lame constants
};

const mt::NeoHookean<double> kNeo{mt::ElasticConstants<double>{100.0, 40.0}};
const mt::MooneyRivlin<double> kMooney{12.0, 5.0, 200.0};
const mt::ElasticConstants<double> kSvk{100.0, 40.0};

const LawView kLaws[] = {
    {"neo-Hookean", [](const M3& F) { return kNeo.energy_density(F); },
     [](const M3& F) { return kNeo.first_piola_kirchhoff(F); }, [](const M3& F) { return kNeo.tangent(F); }, 100.0,
     40.0},
    {"Mooney-Rivlin", [](const M3& F) { return kMooney.energy_density(F); },
     [](const M3& F) { return kMooney.first_piola_kirchhoff(F); }, [](const M3& F) { return kMooney.tangent(F); },
     200.0 - 2.0 / 3.0 * 34.0, 34.0},
    {"St. Venant-Kirchhoff", [](const M3& F) { return mt::svk_energy(F, kSvk); },
     [](const M3& F) { return mt::svk_first_pk(F, kSvk); }, [](const M3& F) { return mt::svk_tangent(F, kSvk); },
     100.0, 40.0},
};

M3 matrix(double a00, double a01, double a02, double a10, double a11, double a12, double a20, double a21,
          double a22) {
  M3 m;
  m.a[0][0] = a00; m.a[0][1] = a01; m.a[0][2] = a02;
  m.a[1][0] = a10; m.a[1][1] = a11; m.a[1][2] = a12;
  m.a[2][0] = a20; m.a[2][1] = a21; m.a[2][2] = a22;
  return m;
}
// Deformations: a small one, a moderate general one, a large stretch with shear, a compression.
const M3 kDeformations[] = {
    matrix(1.001, 0.0005, -0.0002, 0.0003, 0.9995, 0.0004, -0.0001, 0.0002, 1.0008),
    matrix(1.12, 0.08, -0.05, 0.03, 0.94, 0.11, -0.07, 0.04, 1.05),
    matrix(1.6, 0.6, 0.1, 0.0, 0.9, -0.3, 0.2, 0.0, 1.1),
    matrix(0.7, 0.1, 0.0, -0.05, 0.85, 0.02, 0.0, 0.1, 0.8),
};

double norm(const M3& m) { return std::sqrt(mt::double_dot(m, m)); }

}  // namespace

TEST(Hyperelastic, StressIsTheEnergyDerivative) {
  for (const auto& law : kLaws) {
    double worst = 0;
    for (const auto& F : kDeformations) {
      const M3 P = law.P(F);
      M3 fd;
      const double h = 1e-5;  // W carries the cancellation of I1 - 3: a wider step keeps its round-off small
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          M3 Fp = F, Fm = F;
          Fp.a[k][l] += h;
          Fm.a[k][l] -= h;
          fd.a[k][l] = (law.W(Fp) - law.W(Fm)) / (2 * h);
        }
      worst = std::max(worst, norm(P - fd) / std::max(norm(P), 1e-3 * law.mu));
    }
    std::printf("%-22s |P - dW/dF_fd| / |P| <= %.1e\n", law.name, worst);
    EXPECT_LT(worst, 1e-6) << law.name;
  }
}

TEST(Hyperelastic, TangentIsTheStressDerivativeAndSymmetric) {
  for (const auto& law : kLaws) {
    double worst = 0, asym = 0;
    for (const auto& F : kDeformations) {
      const auto A = law.A(F);
      double num = 0, den = 0;
      const double h = 1e-6;
      for (int k = 0; k < 3; ++k)
        for (int L = 0; L < 3; ++L) {
          M3 Fp = F, Fm = F;
          Fp.a[k][L] += h;
          Fm.a[k][L] -= h;
          const M3 dP = law.P(Fp) - law.P(Fm);
          for (int i = 0; i < 3; ++i)
            for (int J = 0; J < 3; ++J) {
              const double d = dP.a[i][J] / (2 * h) - A(i, J, k, L);
              num += d * d;
              den += A(i, J, k, L) * A(i, J, k, L);
              asym = std::max(asym, std::fabs(A(i, J, k, L) - A(k, L, i, J)) / law.mu);
            }
        }
      worst = std::max(worst, std::sqrt(num / den));
    }
    std::printf("%-22s |A - dP/dF_fd| / |A| <= %.1e, asymmetry %.1e\n", law.name, worst, asym);
    EXPECT_LT(worst, 1e-7) << law.name;
    EXPECT_LT(asym, 1e-12) << law.name;
  }
}

TEST(Hyperelastic, ReferenceStateIsLinearIsotropicElasticity) {
  const M3 I = M3::identity();
  for (const auto& law : kLaws) {
    EXPECT_LT(norm(law.P(I)), 1e-13 * law.mu) << law.name;
    EXPECT_NEAR(law.W(I), 0.0, 1e-13 * law.mu) << law.name;
    const auto A = law.A(I);
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L) {
            const double c = law.lambda * (i == J) * (k == L) + law.mu * ((i == k) * (J == L) + (i == L) * (J == k));
            EXPECT_NEAR(A(i, J, k, L), c, 1e-12 * law.mu) << law.name;
          }
  }
}

TEST(Hyperelastic, Objectivity) {
  const double w[3] = {2.0 / 3, -1.0 / 3, 2.0 / 3};
  const M3 R = pm::testing::axis_angle_rotation(w, 0.9);
  ASSERT_NEAR(pm::det(R), 1.0, 1e-14);
  for (const auto& law : kLaws)
    for (const auto& F : kDeformations) {
      const M3 RF = R * F;
      EXPECT_NEAR(law.W(RF), law.W(F), 1e-12 * std::max(1.0, std::fabs(law.W(F)))) << law.name;
      EXPECT_LT(norm(law.P(RF) - R * law.P(F)), 1e-12 * std::max(law.mu, norm(law.P(F)))) << law.name;
    }
}

// The laws in a Kokkos kernel agree with the host calls; float compiles and agrees to single precision.
template <class T>
void check_hyperelastic_in_kernel(double tol) {
  mt::NeoHookean<T> neo{mt::ElasticConstants<T>{T(100), T(40)}};
  mt::MooneyRivlin<T> mr{T(12), T(5), T(200)};
  const int n = 8;
  Kokkos::View<T* [2][9]> out("out", n);
  Kokkos::parallel_for(
      "test::materials::hyperelastic", Kokkos::RangePolicy<pm::ExecSpace>(0, n), KOKKOS_LAMBDA(const int q) {
        pm::Mat3<T> F = pm::Mat3<T>::identity();
        F.a[0][1] = T(0.05) * T(q);
        F.a[1][1] = T(1) + T(0.02) * T(q);
        mt::NoHistory h;
        pm::Mat3<T> P;
        mt::PiolaTangent<T> A;
        neo.update(F, h, P, A);
        for (int r = 0; r < 9; ++r) out(q, 0, r) = P.a[r / 3][r % 3];
        mr.update(F, h, P, A);
        for (int r = 0; r < 9; ++r) out(q, 1, r) = P.a[r / 3][r % 3];
      });
  auto ho = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
  for (int q = 0; q < n; ++q) {
    M3 F = M3::identity();
    F.a[0][1] = 0.05 * q;
    F.a[1][1] = 1 + 0.02 * q;
    const M3 Pn = kNeo.first_piola_kirchhoff(F), Pm = kMooney.first_piola_kirchhoff(F);
    for (int r = 0; r < 9; ++r) {
      EXPECT_NEAR(double(ho(q, 0, r)), Pn.a[r / 3][r % 3], tol * 40.0);
      EXPECT_NEAR(double(ho(q, 1, r)), Pm.a[r / 3][r % 3], tol * 40.0);
    }
  }
}

TEST(Hyperelastic, LawsInKernelDoubleAndFloat) {
  static_assert(!mt::NeoHookean<double>::has_history && !mt::MooneyRivlin<double>::has_history, "no history");
  check_hyperelastic_in_kernel<double>(1e-13);
  check_hyperelastic_in_kernel<float>(1e-5);
  // A : dF is the directional derivative of P.
  const M3 F = kDeformations[2];
  M3 dF = matrix(0.3, -0.1, 0.2, 0.05, 0.4, -0.2, 0.1, 0.0, -0.3);
  const double h = 1e-6;
  const M3 fd = (1 / (2 * h)) * (kNeo.first_piola_kirchhoff(F + h * dF) - kNeo.first_piola_kirchhoff(F - h * dF));
  EXPECT_LT(norm(kNeo.tangent(F) * dF - fd) / norm(fd), 1e-8);
}
