// The matrix-free operator of seed 002 paper 3 eq. (16) equals an independently assembled sparse matrix
// (Eigen, full 3D basis at the Gauss points) to 1e-12 relative, for p = 1..4, on affine, distorted
// (moved vertices) and curved (moved high-order nodes) elements, with impedance faces and Dirichlet
// rows; its diagonal equals the matrix diagonal; it is complex symmetric, y^T (K x) = x^T (K y).
#include <gtest/gtest.h>

#include <complex>
#include <cstdio>

#include "helmholtz_fixtures.hpp"
#include "helmholtz/assembled.hpp"

namespace pm = polymech;
namespace hz = polymech::helmholtz;
using C = Kokkos::complex<double>;

namespace {

std::vector<std::complex<double>> host(const pm::View1<C>& v) {
  auto m = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), v);
  std::vector<std::complex<double>> out(m.extent(0));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {m(i).real(), m(i).imag()};
  return out;
}

double relative_difference(const std::vector<std::complex<double>>& a, const Eigen::VectorXcd& b) {
  double num = 0, den = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    num += std::norm(a[i] - b[static_cast<Eigen::Index>(i)]);
    den += std::norm(b[static_cast<Eigen::Index>(i)]);
  }
  return std::sqrt(num / den);
}

// |K_mf x - K_ref x| / |K_ref x| for a random complex x, and the same for the diagonals.
struct Comparison {
  double apply = 1.0, diagonal = 1.0;
  pm::Index dofs = 0;
};

Comparison compare_with_assembled(const hz::Config& cfg) {
  hz::Helmholtz<double> model(cfg);
  const auto K = hz::assemble_reference(model);
  const pm::Index n = model.dof_count();
  const auto x = pm::testing::random_complex<double>(n, 11);
  pm::View1<C> y("y", n), d("d", n);
  model.op().apply(x, y);
  model.op().diagonal(d);
  Eigen::VectorXcd xe(n);
  const auto xh = host(x);
  for (pm::Index i = 0; i < n; ++i) xe[i] = xh[i];
  Comparison c;
  c.apply = relative_difference(host(y), K * xe);
  c.diagonal = relative_difference(host(d), K.diagonal());
  c.dofs = n;
  std::printf("p = %d, %d DoFs: |K_mf x - K x| / |K x| = %.2e, diagonal %.2e\n", cfg.order, n, c.apply, c.diagonal);
  return c;
}

std::vector<hz::BoundaryCondition> mixed_boundaries() {
  return {{"xmax", hz::BoundaryKind::impedance, 445.9, 0.0},
          {"ymin", hz::BoundaryKind::impedance, 200.0, 0.0},
          {"zmin", hz::BoundaryKind::dirichlet, 0.0, 0.0, 1.0}};
}

}  // namespace

class OperatorVsAssembled : public ::testing::TestWithParam<int> {};

TEST_P(OperatorVsAssembled, AffineElements) {
  const int p = GetParam();
  auto cfg = pm::testing::box_config(p, {3, 2, 2}, {0.6, 0.3, 0.25}, mixed_boundaries());
  const auto c = compare_with_assembled(cfg);
  EXPECT_LT(c.apply, 1e-12) << "p = " << p << ", " << c.dofs << " DoFs";
  EXPECT_LT(c.diagonal, 1e-12) << "p = " << p;
}

TEST_P(OperatorVsAssembled, DistortedElements) {
  const int p = GetParam();
  auto cfg = pm::testing::box_config(p, {3, 3, 2}, {1.0, 0.7, 0.5}, mixed_boundaries(), 0.25);
  const auto c = compare_with_assembled(cfg);
  EXPECT_LT(c.apply, 1e-12) << "p = " << p;
  EXPECT_LT(c.diagonal, 1e-12) << "p = " << p;
}

TEST_P(OperatorVsAssembled, CurvedElements) {
  const int p = GetParam();
  auto cfg = pm::testing::box_config(p, {2, 2, 2}, {1.0, 1.0, 1.0}, mixed_boundaries(), 0.2, 0.08);
  const auto c = compare_with_assembled(cfg);
  EXPECT_LT(c.apply, 1e-12) << "p = " << p;
  EXPECT_LT(c.diagonal, 1e-12) << "p = " << p;
}

// Parallelepipeds (a sheared box): affine but not rectilinear, so the batches take the quadrature
// path with one Jacobian per element; partial batches (3 elements per chunk) included.
TEST_P(OperatorVsAssembled, ShearedAffineElementsInPartialBatches) {
  const int p = GetParam();
  auto cfg = pm::testing::box_config(p, {3, 3, 2}, {1.0, 0.7, 0.5}, mixed_boundaries());
  for (std::size_t v = 0; v < cfg.mesh.vertices.size(); v += 3) {
    cfg.mesh.vertices[v] += 0.3 * cfg.mesh.vertices[v + 1] + 0.2 * cfg.mesh.vertices[v + 2];
    cfg.mesh.vertices[v + 1] += 0.1 * cfg.mesh.vertices[v + 2];
  }
  cfg.chunk_elements = 3;
  const auto c = compare_with_assembled(cfg);
  EXPECT_LT(c.apply, 1e-12) << "p = " << p;
  EXPECT_LT(c.diagonal, 1e-12) << "p = " << p;
}

INSTANTIATE_TEST_SUITE_P(Orders, OperatorVsAssembled, ::testing::Values(1, 2, 3, 4));

// The storage form of each batch is detected from the Jacobians, not assumed: a box is rectilinear
// (Kronecker path), a sheared box affine (one Jacobian per element), moved vertices general (factors
// at every point); the batches of each mesh all take one form, and the three forms agree with the
// factors stored at every point (Config::affine_geometry = false) to rounding (1e-13).
TEST(HelmholtzOperator, GeometryFormsAreDetectedAndAgree) {
  struct Case {
    const char* name;
    double shear, perturbation;
    int rectilinear, affine, general;  // which counts must be non-zero
  };
  for (const Case& k : {Case{"box", 0.0, 0.0, 1, 0, 0}, Case{"sheared", 0.4, 0.0, 0, 1, 0},
                        Case{"distorted", 0.0, 0.2, 0, 0, 1}}) {
    for (int p = 1; p <= 4; ++p) {
      auto cfg = pm::testing::box_config(p, {4, 3, 3}, {1.0, 0.8, 0.6}, mixed_boundaries(), k.perturbation);
      for (std::size_t v = 0; v < cfg.mesh.vertices.size(); v += 3) cfg.mesh.vertices[v] += k.shear * cfg.mesh.vertices[v + 1];
      hz::Helmholtz<double> model(cfg);
      cfg.affine_geometry = false;
      hz::Helmholtz<double> points(cfg);
      const auto& el = model.op().elements();
      EXPECT_EQ(el.rectilinear_batches > 0, k.rectilinear == 1) << k.name << " p = " << p;
      EXPECT_EQ(el.affine_batches > 0, k.affine == 1) << k.name << " p = " << p;
      EXPECT_EQ(el.general_batches > 0, k.general == 1) << k.name << " p = " << p;
      EXPECT_EQ(points.op().elements().general_batches,
                el.rectilinear_batches + el.affine_batches + el.general_batches);
      const pm::Index n = model.dof_count();
      const auto x = pm::testing::random_complex<double>(n, 7);
      pm::View1<C> y1("y1", n), y2("y2", n);
      model.op().apply(x, y1);
      points.op().apply(x, y2);
      const auto a = host(y1), b = host(y2);
      double num = 0, den = 0;
      for (pm::Index i = 0; i < n; ++i) {
        num += std::norm(a[i] - b[i]);
        den += std::norm(b[i]);
      }
      EXPECT_LT(std::sqrt(num / den), 1e-13) << k.name << " p = " << p;
    }
  }
}

// Complex symmetry (the property COCG needs): y^T (K x) = x^T (K y) for random complex x, y, with
// impedance faces and Dirichlet rows, on curved elements.
TEST(HelmholtzOperator, ComplexSymmetric) {
  for (int p = 1; p <= 4; ++p) {
    auto cfg = pm::testing::box_config(p, {2, 3, 2}, {1.0, 0.8, 0.6}, mixed_boundaries(), 0.2, p > 1 ? 0.05 : 0.0);
    hz::Helmholtz<double> model(cfg);
    const pm::Index n = model.dof_count();
    const auto x = pm::testing::random_complex<double>(n, 3), y = pm::testing::random_complex<double>(n, 5);
    pm::View1<C> Kx("Kx", n), Ky("Ky", n);
    model.op().apply(x, Kx);
    model.op().apply(y, Ky);
    const auto a = pm::solvers::dot_with_norms("test", n, y, Kx), b = pm::solvers::dot_with_norms("test", n, x, Ky);
    const double scale = std::sqrt(a.norm2_x * a.norm2_y);
    EXPECT_LT(Kokkos::abs(a.dot - b.dot) / scale, 1e-14) << "p = " << p;
    // and not Hermitian: the impedance term makes y^H K x != conj(x^H K y)
    EXPECT_GT(std::abs(a.dot.imag()), 1e-6 * scale);
  }
}

// The orders the kernels are instantiated for, and a clear refusal of the others.
TEST(HelmholtzOperator, OrderOutOfRangeIsRefused) {
  for (int p : {0, 5, 7}) {
    auto cfg = pm::testing::box_config(1, {1, 1, 1}, {1, 1, 1}, {});
    cfg.order = p;
    try {
      hz::Helmholtz<double> model(cfg);
      FAIL() << "order " << p << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("allowed: 1..4"), std::string::npos) << e.what();
    }
  }
}
