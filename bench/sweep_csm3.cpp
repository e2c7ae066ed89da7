// Turek & Hron's CSM3 (the dynamic structure test of the FSI benchmark; issue 34 "dynamics at finite strain",
// the structure of issue 36): the St. Venant-Kirchhoff bar l = 0.35, h = 0.02 (rho 1000, nu 0.4, mu 0.5e6,
// plane strain) released from rest under gravity g = 2, implicit Newmark (average acceleration) at finite strain
// (models/solid/finite_strain_dynamics.hpp). The benchmark's point A is the middle of the free end; its
// reference (Turek & Hron 2006, Table 6, dt = 0.005): ux = -14.305 +- 14.305 [1.0995] e-3 m, uy = -63.607 +-
// 65.160 [1.0995] e-3 m (mean +- amplitude [frequency, Hz] over the last period). Approximation as in the CSM1
// test: the root is a straight clamped edge at the end of the cylinder's arc (the arc is worth about 1 % in uy).
// Writes DIR/csm3_<cells>_p<order>_dt<dt>.csv (t, ux, uy, energy error) and prints the benchmark's quantities.
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_csm3 --out out/csm3 [--cells 35] [--order 3] [--dt 0.005] [--time 10]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "solid/finite_strain_dynamics.hpp"

namespace pm = polymech;
namespace so = polymech::solid;
namespace mt = polymech::materials;

int main(int argc, char** argv) {
  std::filesystem::path out = "out/csm3";
  int cells = 35, order = 3;
  double dt = 0.005, end = 10.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    if (k == "--out") out = argv[i + 1];
    else if (k == "--cells") cells = std::atoi(argv[i + 1]);
    else if (k == "--order") order = std::atoi(argv[i + 1]);
    else if (k == "--dt") dt = std::atof(argv[i + 1]);
    else if (k == "--time") end = std::atof(argv[i + 1]);
    else {
      std::fprintf(stderr, "sweep_csm3: unknown option '%s' (allowed: --out, --cells, --order, --dt, --time)\n", argv[i]);
      return 2;
    }
  }
  if (cells < 1 || order < 1 || order > 4 || !(dt > 0) || !(end > dt)) {
    std::fprintf(stderr, "sweep_csm3: need --cells >= 1, --order 1..4, --dt > 0, --time > dt\n");
    return 2;
  }
  Kokkos::initialize(argc, argv);
  int rc = 0;
  {
    const double l = 0.35, h = 0.02, rho = 1000.0, nu = 0.4, mu = 0.5e6, g = 2.0;
    so::BoxSpec b;
    b.lengths = {l, h, 1.0};
    b.cells = {cells, 2, 1};
    so::Config<2> c;
    c.mesh = so::make_box<2>(b);
    c.order = order;
    c.dirichlet.push_back({"xmin", 3u, {}});
    c.body_forces.push_back({[&](const double*, double* f) { f[1] = -rho * g; }});
    mt::StVenantKirchhoff<double> svk;
    svk.elastic = {2 * mu * nu / (1 - 2 * nu), mu};
    so::FiniteStrainDynamicsOptions fo;
    fo.dt = dt;
    fo.density = rho;
    so::HyperelasticNewmark<double, 2> m(c, so::HyperelasticLaw(svk), fo);
    const auto& X = m.solid().discretization().coordinates;
    std::int64_t a = -1;
    for (std::size_t v = 0; v < X.size() / 2; ++v)
      if (std::fabs(X[2 * v] - l) < 1e-12 && std::fabs(X[2 * v + 1] - 0.5 * h) < 1e-12) a = static_cast<std::int64_t>(2 * v);
    std::filesystem::create_directories(out);
    char name[128];
    std::snprintf(name, sizeof(name), "csm3_%d_p%d_dt%g.csv", cells, order, dt);
    FILE* f = std::fopen((out / name).c_str(), "w");
    std::fprintf(f, "t,ux,uy,energy_error\n");
    const auto t0 = std::chrono::steady_clock::now();
    m.start();
    std::vector<double> ts, uxs, uys;
    const int steps = static_cast<int>(std::lround(end / dt));
    double kmax = 0.0;
    for (int k = 1; k <= steps; ++k) {
      m.step();
      auto sub = Kokkos::subview(m.displacement(), std::make_pair(static_cast<pm::Index>(a), static_cast<pm::Index>(a + 2)));
      const auto hu = Kokkos::create_mirror_view_and_copy(pm::HostSpace(), sub);
      kmax = std::max(kmax, m.kinetic_energy());
      const double err = (m.energy() - m.initial_energy()) / std::max(kmax, 1e-300);
      ts.push_back(m.time());
      uxs.push_back(hu(0));
      uys.push_back(hu(1));
      std::fprintf(f, "%.6f,%.9e,%.9e,%.3e\n", m.time(), hu(0), hu(1), err);
    }
    std::fclose(f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // the last period: between the last two maxima of uy (quadratic refinement of each)
    std::vector<double> peaks;
    for (std::size_t k = 1; k + 1 < uys.size(); ++k)
      if (uys[k] > uys[k - 1] && uys[k] >= uys[k + 1]) {
        const double y0 = uys[k - 1], y1 = uys[k], y2 = uys[k + 1], d = y0 - 2 * y1 + y2;
        peaks.push_back(ts[k] + (d != 0 ? 0.5 * dt * (y0 - y2) / d : 0.0));
      }
    if (peaks.size() < 2) {
      std::fprintf(stderr, "sweep_csm3: fewer than two periods in %g s\n", end);
      rc = 1;
    } else {
      const double p0 = peaks[peaks.size() - 2], p1 = peaks.back();
      double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
      for (std::size_t k = 0; k < ts.size(); ++k)
        if (ts[k] >= p0 && ts[k] <= p1) {
          xmin = std::min(xmin, uxs[k]);
          xmax = std::max(xmax, uxs[k]);
          ymin = std::min(ymin, uys[k]);
          ymax = std::max(ymax, uys[k]);
        }
      const double fx = 1.0 / (p1 - p0);
      std::printf("CSM3, %d x 2 cells, order %d, dt %g, %g s: ux %.3f +- %.3f, uy %.3f +- %.3f [e-3 m], frequency %.4f Hz; "
                  "%lld Newton iterations, %.1f s\n",
                  cells, order, dt, end, 1e3 * 0.5 * (xmax + xmin), 1e3 * 0.5 * (xmax - xmin), 1e3 * 0.5 * (ymax + ymin),
                  1e3 * 0.5 * (ymax - ymin), fx, static_cast<long long>(m.newton_iterations()), seconds);
      std::printf("reference (Turek & Hron 2006, dt 0.005): ux -14.305 +- 14.305, uy -63.607 +- 65.160 [e-3 m], 1.0995 Hz\n");
    }
  }
  Kokkos::finalize();
  return rc;
}
