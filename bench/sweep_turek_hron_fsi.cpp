// Turek & Hron's steady FSI1 (issue 36; models/fsi/turek_hron_fsi.hpp): the elastic SVK flag behind the
// cylinder at Ubar = 0.2, partitioned Dirichlet-Neumann coupling (IQN-ILS or Aitken) of the Taylor-Hood fluid on
// the pseudo-elastically moved mesh and the total-Lagrangian solid on matching wet nodes. Per level: unknowns,
// ux(A), uy(A), drag, lift and their errors against Table 12, coupling evaluations, fluid / solid Newton
// iterations, CPU seconds (std::clock, one thread: OMP_NUM_THREADS=1) of mesh motion, fluid and solid.
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_turek_hron_fsi --levels 0,1,2 --method iqn_ils
// The unsteady FSI2 / FSI3 (models/fsi/turek_hron_fsi_transient.hpp) on the first level given, one CSV row per step
// (t, ux_A, uy_A, drag, lift, evaluations, |r|, int div u) and, at the end, the last period's mean, amplitude and
// frequency of uy(A) (period from uy's maxima), drag and lift:
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_turek_hron_fsi --test fsi2 --levels 0 --dt 0.005 --end 6 --csv fsi2.csv
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>
#include <string>
#include <vector>

#include "fsi/turek_hron_fsi.hpp"
#include "fsi/turek_hron_fsi_transient.hpp"

namespace fs = polymech::fsi;

int main(int argc, char** argv) {
  std::vector<int> levels{0, 1, 2};
  std::string method = "iqn_ils";
  double tol = 1e-8, chi = 1.0;
  int arc = 1;
  std::string test = "fsi1", csv, motion = "incremental";
  double dt = 0.005, end = 1.0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--levels") {
      levels.clear();
      std::stringstream ss(v);
      std::string t;
      while (std::getline(ss, t, ',')) levels.push_back(std::atoi(t.c_str()));
    } else if (k == "--method") method = v;
    else if (k == "--tol") tol = std::atof(v.c_str());
    else if (k == "--chi") chi = std::atof(v.c_str());
    else if (k == "--arc-root") arc = std::atoi(v.c_str());
    else if (k == "--test") test = v;
    else if (k == "--dt") dt = std::atof(v.c_str());
    else if (k == "--end") end = std::atof(v.c_str());
    else if (k == "--csv") csv = v;
    else if (k == "--mesh-motion") motion = v;
    else {
      std::fprintf(stderr, "sweep_turek_hron_fsi: unknown option '%s' (allowed: --levels L0,L1,.., --method relaxation|aitken|iqn_ils, "
                           "--tol T, --chi X, --arc-root 0|1, --test fsi1|fsi2|fsi3, --dt DT, --end T, --csv FILE, --mesh-motion incremental|total)\n", argv[i]);
      return 2;
    }
  }
  fs::CouplingOptions co;
  try {
    co.method = fs::coupling_method(method);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep_turek_hron_fsi: %s\n", e.what());
    return 2;
  }
  co.tolerance = tol;
  co.omega = 0.5;
  co.max_iterations = 60;
  const fs::TurekHronFsiReference ref = fs::turek_hron_fsi1_reference();
  Kokkos::ScopeGuard kokkos(argc, argv);
  if (test != "fsi1") {
    if ((test != "fsi2" && test != "fsi3") || !(dt > 0) || !(end > 0) || levels.empty() || (motion != "incremental" && motion != "total")) {
      std::fprintf(stderr, "sweep_turek_hron_fsi: --test fsi2|fsi3 needs --dt > 0, --end > 0, a level and --mesh-motion incremental|total\n");
      return 2;
    }
    fs::TurekHronFsiRunConfig rc;
    rc.test = test;
    rc.level = levels.front();
    rc.dt = dt;
    rc.end_time = end;
    rc.incremental_mesh = motion == "incremental";
    rc.coupling.method = co.method;
    std::FILE* f = csv.empty() ? nullptr : std::fopen(csv.c_str(), "w");
    if (!csv.empty() && !f) {
      std::fprintf(stderr, "sweep_turek_hron_fsi: cannot write '%s'\n", csv.c_str());
      return 2;
    }
    const std::clock_t c0 = std::clock();
    fs::TurekHronFsiTimings tm;
    std::vector<fs::TurekHronFsiStep> rows;
    try {
      rows = fs::run_turek_hron_fsi(rc, f, &tm);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep_turek_hron_fsi: %s\n", e.what());
      if (f) std::fclose(f);
      return 1;
    }
    if (f) std::fclose(f);
    const double total = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::vector<double> t, ux, uy, drag, lift;
    long evals = 0;
    int max_evals = 0;
    for (const auto& r : rows) {
      t.push_back(r.t), ux.push_back(r.ux), uy.push_back(r.uy), drag.push_back(r.drag), lift.push_back(r.lift);
      evals += r.evaluations;
      max_evals = std::max(max_evals, r.evaluations);
    }
    std::printf("# %s level %d dt %g to t = %g (%s, %s mesh motion): %zu steps, %ld evaluations (mean %.2f, max %d), fluid Newton %d, solid Newton %d; "
                "CPU s: total %.1f, mesh %.1f, fluid %.1f, solid %.1f\n",
                test.c_str(), rc.level, dt, end, method.c_str(), motion.c_str(), rows.size(), evals, static_cast<double>(evals) / rows.size(), max_evals,
                tm.fluid_newton, tm.solid_newton, total, tm.mesh, tm.fluid, tm.solid);
    double t0 = 0.0, t1 = 0.0;
    if (polymech::flow::last_period(t, uy, t0, t1)) {
      const auto sx = polymech::flow::periodic_stats(t, ux, t0, t1), sy = polymech::flow::periodic_stats(t, uy, t0, t1);
      const auto sd = polymech::flow::periodic_stats(t, drag, t0, t1), sl = polymech::flow::periodic_stats(t, lift, t0, t1);
      std::printf("# last period of uy(A) [%.4f, %.4f]: frequency %.4f Hz\n", t0, t1, sy.frequency);
      std::printf("# ux(A) %.4e +- %.4e, uy(A) %.4e +- %.4e, drag %.3f +- %.3f, lift %.3f +- %.3f\n", sx.mean, sx.amplitude, sy.mean,
                  sy.amplitude, sd.mean, sd.amplitude, sl.mean, sl.amplitude);
    } else {
      std::printf("# uy(A) has fewer than two maxima: no period\n");
    }
    return 0;
  }
  std::printf("# FSI1 (Ubar 0.2), coupling %s, tolerance %.1e, mesh stiffening chi %.1f, %s root\n", method.c_str(), tol, chi,
              arc ? "arc" : "straight");
  std::printf("# level fluid_unknowns mesh_unknowns solid_unknowns wet_nodes | ux(A) err%% uy(A) err%% drag err%% lift err%% | "
              "evaluations fluid_newton solid_newton | cpu_setup cpu_mesh cpu_fluid cpu_solid cpu_total | min_detJ_ratio "
              "mismatch flag_drag flag_lift\n");
  for (const int level : levels) {
    fs::TurekHronFsiCase c;
    c.level = level;
    c.coupling = co;
    c.mesh.chi = chi;
    c.arc_root = arc != 0;
    const std::clock_t c0 = std::clock();
    try {
      fs::TurekHronFsi model(c);
      const fs::TurekHronFsiResult r = model.solve_steady();
      const double total = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      const auto& t = model.timings();
      std::printf("%d %lld %lld %lld %zu | %.5e %+.2f %.5e %+.2f %.5f %+.3f %.5f %+.3f | %d %d %d | %.2f %.2f %.2f %.2f %.2f | %.4f %.1e %.5f %.5f%s\n",
                  level, static_cast<long long>(model.fluid_unknowns()), static_cast<long long>(model.mesh_unknowns()),
                  static_cast<long long>(model.solid_unknowns()), model.interface_nodes(), r.ux, 100 * (r.ux / ref.ux - 1), r.uy,
                  100 * (r.uy / ref.uy - 1), r.drag, 100 * (r.drag / ref.drag - 1), r.lift, 100 * (r.lift / ref.lift - 1),
                  r.coupling.iterations, t.fluid_newton, t.solid_newton, t.setup, t.mesh, t.fluid, t.solid, total,
                  r.min_jacobian_ratio, r.interface_mismatch, r.flag_drag, r.flag_lift,
                  r.coupling.converged ? "" : (" NOT CONVERGED: " + r.coupling.reason).c_str());
      std::printf("#   |r_k|:");
      for (const double h : r.coupling.history) std::printf(" %.2e", h);
      std::printf("\n");
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "sweep_turek_hron_fsi: level %d: %s\n", level, e.what());
      return 1;
    }
  }
  return 0;
}
