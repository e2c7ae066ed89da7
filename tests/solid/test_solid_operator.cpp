// The matrix-free solid operator against the assembled matrix, and the patch test (issue 34).
//  - K x matrix-free (sum factorization, batched, affine and general geometry paths) equals the assembled
//    matrix (full basis at the Gauss points, solid/assembly.hpp) times x, orders 1..4, 2D and 3D, with a
//    general anisotropic C and Dirichlet rows; the Jacobi diagonal equals the matrix's; the same C given per
//    quadrature point (the tangent path of a nonlinear law, PointStiffness) gives the same K x.
//  - Patch test: a linear displacement field prescribed on the whole boundary of a randomly distorted mesh
//    is reproduced at every node to round-off (sparse LU and CG), and the stress at every Gauss point is
//    C eps of that field; orders 1..4, plane strain, plane stress and 3D.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "solid/analysis.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

// A symmetric positive definite Voigt stiffness that couples every component (isotropic plus a random
// symmetric positive semi-definite part), so no entry of C is left untested.
pm::materials::Stiffness6<double> anisotropic_stiffness() {
  auto C = pm::materials::isotropic_stiffness(200.0, 0.3);
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double B[6][6];
  for (auto& row : B)
    for (double& b : row) b = 10.0 * u(gen);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k) C.c[i][j] += B[i][k] * B[j][k];
  return C;
}

template <int D>
so::Config<D> small_case(int order, bool distorted) {
  so::BoxSpec b;
  // 3D: an interior vertex to distort where the assembly stays cheap (order 4: 375 x 375 element matrices)
  b.cells = D == 3 ? std::array<int, 3>{2, 2, order < 4 ? 2 : 1} : std::array<int, 3>{3, 2, 1};
  b.lengths = {1.0, 0.8, 0.6};
  b.distortion = distorted ? so::Distortion::random : so::Distortion::none;
  b.amplitude = 0.2;
  so::Config<D> c;
  c.mesh = so::make_box<D>(b);
  c.order = order;
  c.stiffness = anisotropic_stiffness();
  c.affine_geometry = !distorted;  // distorted: the factors at every point (the general path)
  c.dirichlet.push_back({"xmin", 7u, {}});
  c.dirichlet.push_back({"ymax", 2u, {}});  // one component only: the per-component mask
  return c;
}

template <int D>
void check_against_assembled(int order, bool distorted) {
  so::LinearElastic<double, D> m(small_case<D>(order, distorted));
  const pm::Index n = m.dof_count();
  pm::View1<double> x("x", n), y("y", n), z("z", n);
  auto xh = Kokkos::create_mirror_view(x);
  for (pm::Index i = 0; i < n; ++i) xh(i) = std::sin(0.37 * i + 0.1) + 0.5 * std::cos(1.3 * i);
  Kokkos::deep_copy(x, xh);
  m.op().apply(x, y);
  const auto K = so::to_csr<double>(m.assemble());
  K.template multiply<false>("test::csr", x, z);
  const auto yh = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), y);
  const auto zh = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), z);
  double diff = 0.0, scale = 0.0;
  for (pm::Index i = 0; i < n; ++i) {
    diff = std::max(diff, std::abs(yh(i) - zh(i)));
    scale = std::max(scale, std::abs(zh(i)));
  }
  // measured 2.7e-16 .. 7.7e-15 relative (double, AVX2, orders 1..4); a wrong factor or index gives O(1)
  EXPECT_LT(diff, 1e-12 * scale) << "D " << D << " order " << order << " distorted " << distorted;
  if (distorted)
    EXPECT_GT(m.elements().general_batches, 0);
  else
    EXPECT_EQ(m.elements().general_batches, 0);
  // the tangent path of a nonlinear law: the same C given per quadrature point (PointStiffness) gives K x
  {
    const auto mat = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), m.elements().material);
    const int QD = D == 3 ? (order + 1) * (order + 1) * (order + 1) : (order + 1) * (order + 1);
    so::PointStiffness<double> law{
        Kokkos::View<double***, Kokkos::LayoutRight, pm::MemSpace>("tangent", m.element_count(), QD, 36)};
    auto th = Kokkos::create_mirror_view(law.tangent);
    for (pm::Index e = 0; e < m.element_count(); ++e)
      for (int q = 0; q < QD; ++q)
        for (int k = 0; k < 36; ++k) th(e, q, k) = mat(e, k);
    Kokkos::deep_copy(law.tangent, th);
    pm::View1<double> w("w", n), v("v", n);
    so::add_internal_force<true>("test::tangent", m.elements(), law, x, w);
    so::add_elastic_apply<true>(m.elements(), x, v);
    const auto wh = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), w);
    const auto vh = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), v);
    double d = 0.0;
    for (pm::Index i = 0; i < n; ++i) d = std::max(d, std::abs(wh(i) - vh(i)));
    EXPECT_LT(d, 1e-13 * scale) << "per-point tangent, D " << D << " order " << order;
  }
  // Jacobi: the inverse diagonal is 1 / diag(K)
  const auto inv = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), m.op().inverse_diagonal());
  const auto rp = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), K.row_ptr);
  const auto cols = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), K.cols);
  const auto vals = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), K.values);
  double worst = 0.0;
  for (pm::Index i = 0; i < n; ++i)
    for (pm::Offset k = rp(i); k < rp(i + 1); ++k)
      if (cols(k) == i) worst = std::max(worst, std::abs(inv(i) * vals(k) - 1.0));
  EXPECT_LT(worst, 1e-12) << "D " << D << " order " << order;
  std::printf("operator D=%d order=%d %s: |K_mf x - K x| / |K x| = %.2e, diagonal %.2e\n", D, order,
              distorted ? "general" : "affine", diff / scale, worst);
}

// u = A x + b, |A| ~ 1e-3
void linear_field(const double* x, double* u) {
  static const double A[3][3] = {{1.0e-3, 2.0e-4, -3.0e-4}, {-5.0e-4, 0.7e-3, 4.0e-4}, {2.5e-4, -1.5e-4, -0.6e-3}};
  static const double b[3] = {1e-4, -2e-4, 3e-4};
  for (int i = 0; i < 3; ++i) u[i] = b[i] + A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
}

template <int D>
void patch_test(int order, so::Plane plane) {
  so::BoxSpec b;
  b.cells = {3, 3, 3};
  b.lengths = {1.0, 1.2, 0.9};
  b.distortion = so::Distortion::random;
  b.amplitude = 0.25;
  so::Config<D> c;
  c.mesh = so::make_box<D>(b);
  c.order = order;
  c.plane = plane;
  c.stiffness = pm::materials::isotropic_stiffness(210e3, 0.3);
  for (const char* s : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    if (D == 3 || s[0] != 'z') c.dirichlet.push_back({s, 7u, linear_field});
  so::LinearElastic<double, D> m(c);
  auto nodal_error = [&] {
    const auto u = m.displacement_host();
    const auto& x = m.discretization().coordinates;
    double e = 0.0;
    for (std::int64_t v = 0; v < m.discretization().nodes; ++v) {
      double p[3] = {x[D * v], x[D * v + 1], D == 3 ? x[D * v + D - 1] : 0.0}, ex[3];
      linear_field(p, ex);
      for (int k = 0; k < D; ++k) e = std::max(e, std::abs(u[D * v + k] - ex[k]));
    }
    return e / 1e-3;  // relative to the field's size
  };
  m.solve_direct();
  const double lu = nodal_error();
  EXPECT_LT(lu, 1e-11) << "LU, D " << D << " order " << order;
  // stresses at the Gauss points: C eps(A) of the linear field
  const auto C = D == 2 && plane == so::Plane::stress ? pm::materials::plane_stress_condensed(c.stiffness) : c.stiffness;
  double g[3][3];
  {
    double o[3] = {0, 0, 0}, u0[3];
    linear_field(o, u0);
    for (int j = 0; j < 3; ++j) {
      double p[3] = {0, 0, 0}, uj[3];
      p[j] = 1.0;
      linear_field(p, uj);
      for (int i = 0; i < 3; ++i) g[i][j] = uj[i] - u0[i];
    }
  }
  double eps[6] = {g[0][0], g[1][1], D == 3 ? g[2][2] : 0.0, D == 3 ? g[1][2] + g[2][1] : 0.0,
                   D == 3 ? g[0][2] + g[2][0] : 0.0, g[0][1] + g[1][0]};
  const auto sig = so::quadrature_stresses(m);
  constexpr int S = so::strain_components<D>;
  double worst = 0.0;
  for (std::size_t k = 0; k < sig.size(); ++k) {
    const int i = so::voigt_component<D>(static_cast<int>(k % S));
    double s = 0.0;
    for (int j = 0; j < 6; ++j) s += C.c[i][j] * eps[j];
    worst = std::max(worst, std::abs(sig[k] - s) / 210.0);  // relative to E |A|
  }
  EXPECT_LT(worst, 1e-9) << "stress, D " << D << " order " << order;
  pm::solvers::SolverOptions o;
  o.tolerance = 1e-13;
  const auto r = m.solve_cg(o);
  EXPECT_TRUE(r.converged()) << r.reason;
  const double cg = nodal_error();
  EXPECT_LT(cg, 1e-10) << "CG, D " << D << " order " << order;
  std::printf("patch D=%d order=%d plane=%s: max nodal error / |A| LU %.2e, CG %.2e (%d iterations), stress %.2e\n", D,
              order, plane == so::Plane::stress ? "stress" : "strain", lu, cg, r.iterations, worst);
}

}  // namespace

TEST(SolidOperator, MatrixFreeEqualsAssembled2D) {
  for (int p = 1; p <= 4; ++p)
    for (bool distorted : {false, true}) check_against_assembled<2>(p, distorted);
}

TEST(SolidOperator, MatrixFreeEqualsAssembled3D) {
  for (int p = 1; p <= 4; ++p)
    for (bool distorted : {false, true}) check_against_assembled<3>(p, distorted);
}

TEST(SolidPatch, PlaneStrainAndStress) {
  for (int p = 1; p <= 4; ++p) {
    patch_test<2>(p, so::Plane::strain);
    patch_test<2>(p, so::Plane::stress);
  }
}

TEST(SolidPatch, Hexahedra) {
  for (int p = 1; p <= 4; ++p) patch_test<3>(p, so::Plane::strain);
}
