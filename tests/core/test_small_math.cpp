// Small fixed-size math: host checks against hand values and a device round trip (the same functions
// run inside a Kokkos kernel, as they do in every model).
#include <gtest/gtest.h>

#include <random>

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace pm = polymech;

TEST(SmallMath, Det2And3MatchHandValues) {
  pm::Mat2<double> a{{{3.0, 1.0}, {2.0, 4.0}}};
  EXPECT_DOUBLE_EQ(pm::det(a), 10.0);
  pm::Mat3<double> b{{{2.0, 0.0, 1.0}, {1.0, 3.0, 2.0}, {1.0, 1.0, 1.0}}};
  // 2*(3-2) - 0 + 1*(1-3) = 0: singular by construction.
  EXPECT_DOUBLE_EQ(pm::det(b), 0.0);
  b(2, 2) = 2.0;  // 2*(6-2) + 1*(1-3) = 6
  EXPECT_DOUBLE_EQ(pm::det(b), 6.0);
}

template <int D>
static double inverse_residual(const pm::Mat<double, D>& m) {
  auto p = m * pm::inverse(m);
  double r = 0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) r = std::max(r, std::abs(p(i, j) - (i == j ? 1.0 : 0.0)));
  return r;
}

TEST(SmallMath, InverseTimesMatrixIsIdentityForRandomMatrices) {
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    pm::Mat2<double> a;
    pm::Mat3<double> b;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (i < 2 && j < 2) a(i, j) = u(gen) + (i == j ? 2.0 : 0.0);
        b(i, j) = u(gen) + (i == j ? 3.0 : 0.0);
      }
    EXPECT_LT(inverse_residual<2>(a), 1e-13);
    EXPECT_LT(inverse_residual<3>(b), 1e-13);
  }
}

TEST(SmallMath, CrossPerpAndRotation) {
  pm::Vec2<double> a{{1.0, 2.0}}, b{{-3.0, 0.5}};
  EXPECT_DOUBLE_EQ(pm::cross(a, b), pm::dot(pm::perp(a), b));
  EXPECT_DOUBLE_EQ(pm::cross(a, b), 1.0 * 0.5 - 2.0 * (-3.0));
  auto r = pm::rotation(0.3);
  auto ra = r * a;
  EXPECT_NEAR(pm::norm(ra), pm::norm(a), 1e-15);
  EXPECT_NEAR(pm::det(r), 1.0, 1e-15);
  // rotating by +90 degrees equals perp
  auto q = pm::rotation(M_PI / 2) * a;
  EXPECT_NEAR(q[0], pm::perp(a)[0], 1e-15);
  EXPECT_NEAR(q[1], pm::perp(a)[1], 1e-15);
  pm::Vec3<double> x{{1, 0, 0}}, y{{0, 1, 0}};
  auto z = pm::cross(x, y);
  EXPECT_DOUBLE_EQ(z[2], 1.0);
}

// Device round trip: det and inverse of 3x3 matrices computed inside a kernel.
static void device_inverse(Kokkos::View<double* [3][3]> m, Kokkos::View<double*> dets) {
  Kokkos::parallel_for(
      "test::device_inverse", pm::range(m.extent(0)), KOKKOS_LAMBDA(const int i) {
        pm::Mat3<double> a;
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) a(r, c) = m(i, r, c);
        dets(i) = pm::det(a);
        auto inv = pm::inverse(a);
        for (int r = 0; r < 3; ++r)
          for (int c = 0; c < 3; ++c) m(i, r, c) = inv(r, c);
      });
}

TEST(SmallMath, DeviceInverseMatchesHost) {
  const int n = 64;
  Kokkos::View<double* [3][3]> m("m", n);
  Kokkos::View<double*> d("d", n);
  auto h = Kokkos::create_mirror_view(m);
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < n; ++i)
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) h(i, r, c) = u(gen) + (r == c ? 3.0 : 0.0);
  auto orig = Kokkos::create_mirror(m);
  Kokkos::deep_copy(orig, h);
  Kokkos::deep_copy(m, h);
  device_inverse(m, d);
  Kokkos::deep_copy(h, m);
  auto hd = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), d);
  for (int i = 0; i < n; ++i) {
    pm::Mat3<double> a, ai;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        a(r, c) = orig(i, r, c);
        ai(r, c) = h(i, r, c);
      }
    EXPECT_NEAR(hd(i), pm::det(a), 1e-13);
    auto p = a * ai;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p(r, c), r == c ? 1.0 : 0.0, 1e-13);
  }
}
