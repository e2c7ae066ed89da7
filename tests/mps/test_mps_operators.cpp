// MPS weight, number density and particle-interaction models (seed 000 eqs. (1)-(5)) against
// analytic values: exact for linear (gradient, divergence) and quadratic (Laplacian) fields at
// particles with a full neighbourhood, second-order convergence for a smooth field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "mps/operators.hpp"
#include "neighbors/neighbor_search.hpp"

namespace pm = polymech;
namespace mps = polymech::mps;
namespace nb = polymech::neighbors;

namespace {

struct Cloud {
  int side;
  double l0, re;
  pm::VecView<double, 2> x;
  nb::BondFamily family;
  double n0;

  Cloud(int s, double spacing, double re_ratio) : side(s), l0(spacing), re(re_ratio * spacing) {
    x = pm::VecView<double, 2>("x", side * side);
    auto h = Kokkos::create_mirror_view(x);
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        h(j * side + i, 0) = (i + 0.5) * l0;
        h(j * side + i, 1) = (j + 0.5) * l0;
      }
    Kokkos::deep_copy(x, h);
    family = nb::build_bond_family<double, 2>(x, re * (1 + 1e-9));
    n0 = mps::lattice_number_density(2, l0, re);
  }
  int id(int i, int j) const { return j * side + i; }
  bool interior(int i, int j, int margin) const {
    return i >= margin && j >= margin && i < side - margin && j < side - margin;
  }
  pm::View1<double> scalar(const std::function<double(double, double)>& f) const {
    pm::View1<double> v("phi", side * side);
    auto h = Kokkos::create_mirror_view(v);
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) h(id(i, j)) = f((i + 0.5) * l0, (j + 0.5) * l0);
    Kokkos::deep_copy(v, h);
    return v;
  }
};

}  // namespace

TEST(MpsWeight, MatchesEquationOne) {
  EXPECT_DOUBLE_EQ(mps::weight(1.0, 2.1), 1.1);
  EXPECT_DOUBLE_EQ(mps::weight(2.1, 2.1), 0.0);
  EXPECT_DOUBLE_EQ(mps::weight(2.2, 2.1), 0.0);
  EXPECT_DOUBLE_EQ(mps::weight(0.0, 2.1), 0.0);  // coincident particles: 0, never inf
  EXPECT_DOUBLE_EQ(mps::weight(1.05, 2.1), 1.0);
}

TEST(MpsNumberDensity, InteriorValueMatchesTableOne) {
  // seed 000 Table 1: n0 = 6.53 for re = 2.1 l0 in 2D (4 * 1.1 + 4 * (2.1/sqrt2 - 1) + 4 * 0.05 = 6.5397)
  EXPECT_NEAR(mps::lattice_number_density(2, 5e-5, 2.1 * 5e-5), 6.53, 0.01);
  Cloud c(12, 1e-3, 2.1);
  pm::View1<double> n("n", 144);
  mps::number_density<double, 2>(c.family, c.x, c.re, n);
  auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), n);
  EXPECT_NEAR(h(c.id(6, 6)), c.n0, 1e-12);
  EXPECT_LT(h(c.id(0, 0)), 0.5 * c.n0);  // a corner has about a quarter of the neighbourhood
}

TEST(MpsOperators, ExactForLinearAndQuadraticFieldsAtInteriorParticles) {
  Cloud c(16, 1e-3, 2.1);
  const mps::OperatorParams p{c.re, c.n0};
  const double a = 3.0, b = -2.0;
  auto phi = c.scalar([&](double x, double y) { return a * x + b * y + 1.0; });
  pm::VecView<double, 2> grad("grad", 256);
  mps::gradient<double, 2>(c.family, c.x, c.x, phi, p, grad);

  pm::VecView<double, 2> psi("psi", 256);  // psi = (2x + y, x - 5y): div = -3
  {
    auto h = Kokkos::create_mirror_view(psi);
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const double x = (i + 0.5) * c.l0, y = (j + 0.5) * c.l0;
        h(c.id(i, j), 0) = 2 * x + y;
        h(c.id(i, j), 1) = x - 5 * y;
      }
    Kokkos::deep_copy(psi, h);
  }
  pm::View1<double> div("div", 256);
  mps::divergence<double, 2>(c.family, c.x, c.x, psi, p, div);

  auto quad = c.scalar([](double x, double y) { return 3 * x * x + 2 * y * y + x * y; });  // lap = 10
  pm::View1<double> lap("lap", 256);
  mps::laplacian<double, 2>(c.family, c.x, c.x, quad, p, lap);

  auto one = c.scalar([](double, double) { return 1.0; });
  pm::VecView<double, 2> iso("iso", 256);  // div(1 I) = 0 by symmetry
  mps::divergence_of_isotropic<double, 2>(c.family, c.x, c.x, one, p, iso);

  auto hg = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), grad);
  auto hd = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), div);
  auto hl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), lap);
  auto hi = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), iso);
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      if (!c.interior(i, j, 2)) continue;
      const int k = c.id(i, j);
      EXPECT_NEAR(hg(k, 0), a, 1e-9);
      EXPECT_NEAR(hg(k, 1), b, 1e-9);
      EXPECT_NEAR(hd(k), -3.0, 1e-9);
      EXPECT_NEAR(hl(k), 10.0, 1e-6);
      EXPECT_NEAR(hi(k, 0), 0.0, 1e-6);
      EXPECT_NEAR(hi(k, 1), 0.0, 1e-6);
    }
  // near a free surface the models are not exact: the gradient there is visibly off
  EXPECT_GT(std::abs(hg(c.id(0, 8), 0) - a), 0.1 * std::abs(a));
}

TEST(MpsOperators, LaplacianConvergesAtSecondOrderForSmoothField) {
  // phi = sin(kx x) cos(ky y) on the unit-free square [0, 1 cm]^2; error at interior particles
  // (two r_e from the edge) should fall by ~4 when l0 halves.
  double prev = 0.0;
  for (int side : {20, 40, 80}) {
    const double L = 1e-2, l0 = L / side;
    Cloud c(side, l0, 2.1);
    const double kx = 2 * M_PI / L, ky = M_PI / L;
    auto phi = c.scalar([&](double x, double y) { return std::sin(kx * x) * std::cos(ky * y); });
    pm::View1<double> lap("lap", side * side);
    mps::laplacian<double, 2>(c.family, c.x, c.x, phi, {c.re, c.n0}, lap);
    auto hl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), lap);
    double err = 0.0, ref = 0.0;
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        if (!c.interior(i, j, 3)) continue;
        const double x = (i + 0.5) * l0, y = (j + 0.5) * l0;
        const double exact = -(kx * kx + ky * ky) * std::sin(kx * x) * std::cos(ky * y);
        err = std::max(err, std::abs(hl(c.id(i, j)) - exact));
        ref = std::max(ref, std::abs(exact));
      }
    err /= ref;
    if (prev > 0) {
      EXPECT_GT(prev / err, 3.5) << "side " << side;
      EXPECT_LT(prev / err, 4.5) << "side " << side;
    }
    prev = err;
  }
}
