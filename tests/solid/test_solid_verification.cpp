// Verification of the solid layer against analytic and published answers (issue 34); every number the
// assertions rest on is printed, and the measured values are in the comments (double, AVX2 and x86-64-v2).
//  - manufactured smooth solution: L2 error of order p + 1 (p = 1..3), 2D plane strain on a smoothly
//    distorted mesh and 3D;
//  - slender cantilever: tip deflection against Timoshenko beam theory;
//  - Cook's membrane (plane stress, E = 70, nu = 1/3, traction 6250): converged in mesh and order, against
//    the published 23.96 F / E;
//  - nearly incompressible plane strain (nu = 0.4999): volumetric locking of order 1 and its cure at higher
//    order.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solid/analysis.hpp"
#include "solid/cases.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

template <int D>
double manufactured_error(int order, int n) {
  const double E = 1.0, nu = 0.3;
  so::Manufactured<D> mf{E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))};
  so::BoxSpec b;
  b.cells = {n, n, n};
  b.distortion = so::Distortion::smooth;
  b.amplitude = 0.15;
  so::Config<D> c;
  c.mesh = so::make_box<D>(b);
  c.order = order;
  c.stiffness = pm::materials::isotropic_stiffness(E, nu);
  for (const char* s : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"})
    if (D == 3 || s[0] != 'z') c.dirichlet.push_back({s, 7u, {}});
  c.body_forces.push_back({[mf](const double* x, double* f) { mf.body_force(x, f); }});
  so::LinearElastic<double, D> m(c);
  pm::solvers::SolverOptions o;
  o.tolerance = 1e-12;
  const auto r = m.solve_cg(o);
  EXPECT_TRUE(r.converged()) << r.reason;
  return so::l2_error(m, [mf](const double* x, double* u) { mf.displacement(x, u); }).relative();
}

template <int D>
void manufactured_rates(const std::vector<std::vector<int>>& meshes) {
  for (int p = 1; p <= 3; ++p) {
    const auto& ns = meshes[p - 1];
    std::vector<double> e;
    for (int n : ns) e.push_back(manufactured_error<D>(p, n));
    for (std::size_t k = 0; k < ns.size(); ++k) std::printf("manufactured D=%d p=%d n=%d: L2 %.3e\n", D, p, ns[k], e[k]);
    const double rate = std::log(e[e.size() - 2] / e.back()) / std::log(static_cast<double>(ns.back()) / ns[ns.size() - 2]);
    std::printf("manufactured D=%d p=%d: rate %.2f (expected %d)\n", D, p, rate, p + 1);
    EXPECT_GT(rate, p + 1 - 0.2) << "D " << D << " p " << p;
    EXPECT_LT(rate, p + 1 + 0.5) << "D " << D << " p " << p;
  }
}

double cook_tip(const so::CookSpec& s) {
  so::LinearElastic<double, 2> m(so::cook_membrane(s));
  m.solve_direct();
  return so::displacement_at(m, {48.0, 60.0})[1];
}

}  // namespace

TEST(SolidManufactured, PlaneStrainRates) { manufactured_rates<2>({{8, 16, 32}, {4, 8, 16}, {4, 8, 16}}); }

TEST(SolidManufactured, HexahedraRates) { manufactured_rates<3>({{4, 8, 16}, {2, 4, 8}, {2, 4, 6}}); }

TEST(SolidCantilever, TipDeflectionAgainstTimoshenko) {
  so::CantileverSpec s;
  const double beam = so::timoshenko_tip_deflection(s);
  for (int p = 2; p <= 3; ++p) {
    s.order = p;
    so::LinearElastic<double, 3> m(so::cantilever(s));
    pm::solvers::SolverOptions o;
    o.tolerance = 1e-8;  // 1e-9: the attainable accuracy of double for p = 3 (condition number ~ (L / h)^2 p^4)
    const auto r = m.solve_cg(o);
    ASSERT_TRUE(r.converged()) << r.reason;
    // the residual r(u) = f_int(u) - f_ext of the solution vanishes to the solver's tolerance
    pm::View1<double> res("r", m.dof_count());
    m.residual(m.displacement(), res);
    const auto rh = pm::models::to_host(res), fh = pm::models::to_host(m.external_force());
    double rn = 0.0, fn = 0.0;
    for (std::size_t i = 0; i < rh.size(); ++i) {
      rn += rh[i] * rh[i];
      fn += fh[i] * fh[i];
    }
    EXPECT_LT(std::sqrt(rn / fn), 1e-7) << "p " << p;
    const double tip = so::displacement_at(m, {s.length, 0.5 * s.height, 0.5 * s.width})[1];
    std::printf("cantilever p=%d cells %dx%dx%d: tip %.6f, Timoshenko %.6f, Euler-Bernoulli %.6f, relative %.2e (%d CG "
                "iterations, |r(u)| / |f_ext| %.1e)\n",
                p, s.cells[0], s.cells[1], s.cells[2], tip, beam,
                s.force * s.length * s.length * s.length / (3 * s.young * s.width * s.height * s.height * s.height / 12),
                tip / beam - 1.0, r.iterations, std::sqrt(rn / fn));
    // measured -7.4e-5 (p = 2); Euler-Bernoulli alone would be 1.5e-3 off
    EXPECT_NEAR(tip / beam, 1.0, 5e-4);
  }
}

// Cook's membrane, the data (E = 70, nu = 1/3, traction 6250: F = 1e5), in mesh and order. Printed
// as u E / F, the value for E = 1, F = 1.
std::vector<double> cook_table(so::Plane plane) {
  so::CookSpec s;
  s.plane = plane;
  std::vector<double> p4;
  for (int p = 1; p <= 4; ++p)
    for (int n : {2, 4, 8, 16, 32}) {
      if (n == 32 && p < 4) continue;  // the table's finest mesh for the limit only (test time)
      s.order = p;
      s.n = n;
      const double tip = cook_tip(s);
      std::printf("cook %s p=%d n=%2d: tip %.2f  (u E / F = %.4f)\n", plane == so::Plane::stress ? "stress" : "strain", p,
                  n, tip, tip * s.young / (16.0 * s.traction));
      if (p == 4) p4.push_back(tip);
    }
  return p4;
}

// Richardson limit of the last three values of a sequence that converges geometrically in the mesh.
double extrapolate(const std::vector<double>& v) {
  const double a = v[v.size() - 3], b = v[v.size() - 2], c = v.back();
  return c + (c - b) * (c - b) / ((b - a) - (c - b));
}

TEST(SolidCook, PlaneStressConvergedInMeshAndOrder) {
  const std::vector<double> p4 = cook_table(so::Plane::stress);
  const double scale = 1e5 / 70.0, limit = extrapolate(p4);
  // order 4: differences 0.068, 0.032, ... (u E / F) per halving: converging with the corner singularity
  for (std::size_t k = 2; k < p4.size(); ++k) EXPECT_GT((p4[k - 1] - p4[k - 2]) / (p4[k] - p4[k - 1]), 1.5);
  std::printf("cook plane stress: order 4 Richardson limit u E / F = %.4f; CalculiX 2.20 CPS8 64x64 25.1513 (limit "
              "~25.175); the often-quoted 23.96 is %.1f %% below\n", limit / scale, 100.0 * (1.0 - 23.96 / (limit / scale)));
  // CalculiX 2.20 (bench/peers/calculix/cook_membrane.py), CPS8 on the same meshes, E = 1, F = 1: 24.9012 (8 x 8), 25.0579
  // (16), 25.1227 (32), 25.1513 (64); its Richardson limit 25.175. Ours measured: see docs/VALIDATION.md.
  EXPECT_NEAR(p4.back() / scale, 25.175, 0.05);
  EXPECT_NEAR(limit / scale, 25.175, 0.05);
}

TEST(SolidCook, PlaneStrainAgainstPublishedCodes) {
  const std::vector<double> p4 = cook_table(so::Plane::strain);
  // The data are solids4foam's Cook tutorial (E = 70 MPa, nu = 1/3, traction 6.25 MPa, plane strain),
  // which quotes CoFEA's very fine quadratic meshes: CalculiX 32.27, Code_Aster 32.20, Elmer 32.28 mm; with the
  // traction 6250 the same numbers times 1000.
  const double limit = extrapolate(p4);
  std::printf("cook plane strain: order 4 n=32 %.1f, Richardson limit %.1f; CalculiX 32270, Code_Aster 32200, Elmer 32280\n",
              p4.back(), limit);
  EXPECT_GT(limit, 32200.0 * (1 - 1e-3));
  EXPECT_LT(limit, 32280.0 * (1 + 1e-3));
}

// Nearly incompressible plane strain (nu = 0.4999) on Cook's membrane: order 1 locks (the tip a third of the
// converged value, and refinement barely helps), orders 2..4 do not.
TEST(SolidLocking, NearlyIncompressiblePlaneStrain) {
  so::CookSpec s;
  s.poisson = 0.4999;
  s.plane = so::Plane::strain;
  s.order = 4;
  s.n = 32;
  const double converged = cook_tip(s);
  std::printf("locking: nu 0.4999 plane strain, p=4 n=32 tip %.2f (u E / F = %.4f)\n", converged, converged * 70.0 / 1e5);
  double ratio[5][3];
  for (int p = 1; p <= 4; ++p)
    for (int k = 0; k < 3; ++k) {
      s.order = p;
      s.n = 4 << k;
      ratio[p][k] = cook_tip(s) / converged;
      std::printf("locking p=%d n=%2d: ratio to converged %.4f\n", p, s.n, ratio[p][k]);
    }
  // measured: p = 1: 0.269, 0.277, 0.299 (n = 4, 8, 16); p = 2: 0.867, 0.943, 0.976; p = 3: 0.964, 0.985, 0.996
  EXPECT_LT(ratio[1][2], 0.4);
  EXPECT_LT(ratio[1][2] - ratio[1][1], 0.05);  // refinement does not cure it
  EXPECT_GT(ratio[2][2], 0.95);
  EXPECT_GT(ratio[3][2], 0.99);
  EXPECT_GT(ratio[4][2], 0.995);
  // the same mesh and order 1 with nu = 0.3 is within a few per cent: the loss is volumetric locking
  s.poisson = 0.3;
  s.order = 1;
  s.n = 16;
  const double compressible = cook_tip(s);
  s.order = 4;
  const double compressible_converged = cook_tip(s);
  std::printf("locking control: nu 0.3, p=1 n=16 ratio %.4f\n", compressible / compressible_converged);
  EXPECT_GT(compressible / compressible_converged, 0.9);
}
