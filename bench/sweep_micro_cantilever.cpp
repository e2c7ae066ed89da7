// The elastic studies that fix the micro-cantilever model of seed 002 paper 5 (issue 34;
// models/solid/micro_cantilever.hpp): 8YSZ beam 12 um long, pentagon 2.5 x 1.5 um (walls 0.75 um), force
// F = 0.05 mN along -z on the loading section (about 1 GPa of elastic bending stress at the root); units um,
// GPa, mN.
//  (a) support size (the paper's "fixed region" study, §3 (3)): the tip compliance delta / F against the
//      modelled block's size, (L_b, W_b, H_b) = s (1.5, 5, 3) um for s = 1, 2, 4, 8, then each dimension
//      alone at 2 s and 4 s with the others at 8 s; the clamped-root beam (L_b = 0) beside them; relative
//      change against the largest block. h_root = 0.4, order 2, theta = 0 and 54.7356 deg;
//  (b) mesh (paper 5 §4: 0.2 um at the root was found sufficient): order 2 with h_root = 0.4, 0.3, 0.2
//      (and 0.15 with --fine), order 3 with h_root = 0.4 (and 0.3 with --fine); the compliance, the root stress
//      sigma_xx(0.5, 0, 0) on the top face's centre line, sigma_xx(0, 0, 0) at the root, and the largest
//      Gauss-point sigma_xx in the beam's first micrometre (at the re-entrant root edges: singular, grows
//      with refinement), with DoFs and the wall time of the set-up and of the Jacobi CG solve (to 1e-9; the
//      sparse LU once at h_root = 0.4 for comparison, at every theta with --lu-too).
// Writes OUT/micro_cantilever_support.csv and OUT/micro_cantilever_mesh.csv (every column numeric):
//   study,theta,support_length,support_width,support_depth,dofs,compliance,relative_change,sigma_root,seconds
//   theta,order,h_root,dofs,elements,direct,iterations,compliance,relative_change,sigma_root,sigma_root0,
//     sigma_peak,setup_seconds,solve_seconds
// (study: 0 joint scaling, 1 L_b alone, 2 W_b alone, 3 H_b alone, 4 clamped root; direct: 1 LU, 0 CG;
// relative_change against the largest block / the finest mesh of the same theta and order 2).
//   OMP_NUM_THREADS=2 build/ci/bench/sweep_micro_cantilever OUT [--fine] [--lu-too] [--support-only | --mesh-only]
//   /usr/bin/python3 tools/plot_micro_cantilever.py OUT
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "core/kokkos_shim.hpp"
#include "solid/micro_cantilever.hpp"

namespace so = polymech::solid;

namespace {

using clock_type = std::chrono::steady_clock;
double since(clock_type::time_point t) { return std::chrono::duration<double>(clock_type::now() - t).count(); }
const double theta111 = std::atan(std::sqrt(2.0)) * 180.0 / 3.14159265358979323846;

struct Result {
  long long dofs = 0, elements = 0;
  int iterations = 0;
  double compliance = 0, sigma_root = 0, sigma_root0 = 0, sigma_peak = 0, setup = 0, solve = 0;
};

Result run(const so::MicroCantileverSpec& s, bool direct, bool stresses) {
  Result r;
  const auto t0 = clock_type::now();
  so::LinearElastic<double, 3> m(so::micro_cantilever(s));
  Kokkos::fence();
  r.setup = since(t0);
  const auto t1 = clock_type::now();
  if (direct) {
    m.solve_direct();
  } else {
    polymech::solvers::SolverOptions o;
    o.tolerance = 1e-9;
    o.max_iterations = 100000;
    o.stagnation_window = 20000;
    const auto res = m.solve_cg(o);
    r.iterations = res.iterations;
    if (!res.converged()) std::fprintf(stderr, "CG did not converge: %s\n", res.reason.c_str());
  }
  Kokkos::fence();
  r.solve = since(t1);
  r.dofs = m.dof_count();
  r.elements = m.element_count();
  r.compliance = so::tip_deflection(m) / s.force;
  if (stresses) {
    r.sigma_root = so::axial_stress_at(m, {0.5, 0.0, 0.0});
    r.sigma_root0 = so::axial_stress_at(m, {0.0, 0.0, 0.0});
    r.sigma_peak = so::max_axial_stress(m, 0.0, 1.0);
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  std::string dir = ".";
  bool fine = false, lu_too = false, do_support = true, do_mesh = true;
  double probe = 0.0;
  int probe_order = 2;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--fine")) fine = true;
    else if (!std::strcmp(argv[i], "--probe") && i + 2 < argc) {  // --probe H P: the default model, LU and CG
      probe = std::atof(argv[++i]);
      probe_order = std::atoi(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--lu-too")) lu_too = true;
    else if (!std::strcmp(argv[i], "--support-only")) do_mesh = false;
    else if (!std::strcmp(argv[i], "--mesh-only")) do_support = false;
    else dir = argv[i];
  }
  polymech::kx::initialize();
  if (probe > 0) {
    so::MicroCantileverSpec s;
    s.h_root = probe;
    s.order = probe_order;
    {
      so::LinearElastic<double, 3> m(so::micro_cantilever(s));
      polymech::View1<double> x("x", m.dof_count()), y("y", m.dof_count());
      Kokkos::deep_copy(x, 1.0);
      m.op().apply(x, y);
      Kokkos::fence();
      const auto t = clock_type::now();
      for (int k = 0; k < 20; ++k) m.op().apply(x, y);
      Kokkos::fence();
      std::printf("probe: %lld DoFs, apply %.2f ms, %.1f M DoF/s\n", static_cast<long long>(m.dof_count()),
                  since(t) / 20 * 1e3, m.dof_count() * 20 / since(t) * 1e-6);
    }
    for (const bool direct : {true, false}) {
      if (probe_order > 3 && direct) continue;
      const Result r = run(s, direct, true);
      std::printf("probe h=%.3f p=%d %s: %lld DoFs, %lld elements, compliance %.7f, sigma(0.5,0,0) %.5f, sigma(0,0,0) "
                  "%.5f, peak %.4f, set-up %.2f s, solve %.2f s, %d iterations\n",
                  probe, probe_order, direct ? "LU" : "CG", r.dofs, r.elements, r.compliance, r.sigma_root,
                  r.sigma_root0, r.sigma_peak, r.setup, r.solve, r.iterations);
      std::fflush(stdout);
    }
  } else {
    const auto start = clock_type::now();
    const double pi = 3.14159265358979323846;
    for (const double th : {0.0, theta111}) {
      so::MicroCantileverSpec s;
      s.theta_degrees = th;
      const so::PentagonSection sec = so::pentagon_section(s);
      const auto k = polymech::materials::ysz8_constants_gpa<double>();
      const double E = polymech::materials::cubic_uniaxial_modulus(k, polymech::materials::cantilever_axis(th * pi / 180));
      std::printf("theta %.4f: E_axis %.1f GPa, Euler-Bernoulli compliance L^3 / (3 E I) %.5f um/mN, beam-theory "
                  "sigma_xx(0.5, 0, 0) = F (L - 0.5) c / I = %.4f GPa\n",
                  th, E, std::pow(s.length, 3) / (3 * E * sec.second_moment),
                  s.force * (s.length - 0.5) * sec.centroid_depth / sec.second_moment);
    }
    // (a) support size
    if (do_support) {
      std::ofstream out(dir + "/micro_cantilever_support.csv");
      out << "study,theta,support_length,support_width,support_depth,dofs,compliance,relative_change,sigma_root,seconds\n";
      const double base[3] = {1.5, 5.0, 3.0};
      for (const double th : {0.0, theta111}) {
        struct Row {
          int study;
          double L, W, H;
          Result r;
        };
        std::vector<Row> rows;
        for (const double f : {1.0, 2.0, 4.0, 8.0}) rows.push_back({0, f * base[0], f * base[1], f * base[2], {}});
        const double big[3] = {8 * base[0], 8 * base[1], 8 * base[2]};
        for (int d = 0; d < 3; ++d)
          for (const double f : {2.0, 4.0}) {
            double v[3] = {big[0], big[1], big[2]};
            v[d] = f * base[d];
            rows.push_back({1 + d, v[0], v[1], v[2], {}});
          }
        rows.push_back({4, 0.0, 0.0, 0.0, {}});
        for (auto& row : rows) {
          so::MicroCantileverSpec s;
          s.theta_degrees = th;
          s.h_root = 0.4;
          s.support_length = row.L;
          s.support_width = row.W;
          s.support_depth = row.H;
          row.r = run(s, false, true);
          std::printf("  theta %.1f support %.2f x %.2f x %.2f: %lld DoFs, compliance %.6f, %.1f s\n", th, row.L,
                      row.W, row.H, row.r.dofs, row.r.compliance, row.r.setup + row.r.solve);
          std::fflush(stdout);
        }
        const double ref = rows[3].r.compliance;  // the largest block
        for (const auto& row : rows) {
          char line[320];
          std::snprintf(line, sizeof line, "%d,%.4f,%.3f,%.3f,%.3f,%lld,%.9g,%.6e,%.6g,%.3f\n", row.study, th, row.L, row.W,
                        row.H, row.r.dofs, row.r.compliance, row.r.compliance / ref - 1.0, row.r.sigma_root,
                        row.r.setup + row.r.solve);
          out << line;
          std::fputs(line, stdout);
          std::fflush(stdout);
        }
      }
    }
    // (b) mesh
    if (do_mesh) {
      std::ofstream out(dir + "/micro_cantilever_mesh.csv");
      out << "theta,order,h_root,dofs,elements,direct,iterations,compliance,relative_change,sigma_root,sigma_root0,"
             "sigma_peak,setup_seconds,solve_seconds\n";
      for (const double th : {0.0, theta111}) {
        struct Row {
          int order;
          double h;
          bool direct;
          Result r;
        };
        std::vector<Row> rows;
        std::vector<double> hs{0.4, 0.3, 0.2};
        if (fine) hs.push_back(0.15);
        // CG throughout (the sparse LU is 6x slower already at h_root = 0.4: 52 s against 8 s); the LU once
        // for the comparison
        if (th == 0.0 || lu_too) rows.push_back({2, 0.4, true, {}});
        for (const double h : hs) rows.push_back({2, h, false, {}});
        rows.push_back({3, 0.4, false, {}});
        if (fine) rows.push_back({3, 0.3, false, {}});
        for (auto& row : rows) {
          so::MicroCantileverSpec s;  // the default block (6, 20, 12): the support study's s = 4
          s.theta_degrees = th;
          s.order = row.order;
          s.h_root = row.h;
          row.r = run(s, row.direct, true);
          std::printf("  theta %.1f p=%d h=%.2f %s: %lld DoFs, compliance %.6f, %.1f s\n", th, row.order, row.h,
                      row.direct ? "LU" : "CG", row.r.dofs, row.r.compliance, row.r.setup + row.r.solve);
          std::fflush(stdout);
        }
        double ref = 0;
        for (const auto& row : rows)
          if (row.order == 2 && !row.direct && row.h == hs.back()) ref = row.r.compliance;
        for (const auto& row : rows) {
          char line[400];
          std::snprintf(line, sizeof line, "%.4f,%d,%.3f,%lld,%lld,%d,%d,%.9g,%.6e,%.6g,%.6g,%.6g,%.3f,%.3f\n", th,
                        row.order, row.h, row.r.dofs, row.r.elements, row.direct ? 1 : 0, row.r.iterations,
                        row.r.compliance, row.r.compliance / ref - 1.0, row.r.sigma_root, row.r.sigma_root0,
                        row.r.sigma_peak, row.r.setup, row.r.solve);
          out << line;
          std::fputs(line, stdout);
          std::fflush(stdout);
        }
      }
    }
    std::printf("total %.1f s\n", since(start));
  }
  Kokkos::finalize();
  return 0;
}
