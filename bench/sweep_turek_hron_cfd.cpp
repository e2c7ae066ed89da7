// Turek & Hron's CFD tests (issue 36; models/flow): the rigid cylinder and flag in the channel, Taylor-Hood
// Q2/Q1. CFD1 and CFD2 are solved steady by Newton; CFD3 by BDF2 from rest with the inflow ramped over 2 s, the
// forces written per step to DIR/cfd3_l<level>_dt<dt>.csv and the mean, amplitude and frequency of the last
// period printed. CPU time of the solve (one thread: OMP_NUM_THREADS=1).
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_turek_hron_cfd --test 1 --level 2
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_turek_hron_cfd --test 3 --level 1 --dt 0.01 --time 12 --out out/cfd3
//   --ring-grading A: the ring around the circle graded towards it (TurekHronGeometry::ring_grading)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "flow/turek_hron.hpp"

namespace fl = polymech::flow;

int main(int argc, char** argv) {
  std::filesystem::path out = "out/cfd";
  int test = 1, level = 1;
  double dt = 0.01, end = 12.0;
  bool chord = true;
  fl::TurekHronGeometry geometry;  // --ring-grading A: the ring around the circle graded towards it (0: uniform)
  double kick = 0.0;  // CFD3: peak angular velocity (rad/s) of the obstacle's rigid-rotation kick at t = 2..2.25 s
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i];
    if (k == "--out") out = argv[i + 1];
    else if (k == "--test") test = std::atoi(argv[i + 1]);
    else if (k == "--level") level = std::atoi(argv[i + 1]);
    else if (k == "--dt") dt = std::atof(argv[i + 1]);
    else if (k == "--time") end = std::atof(argv[i + 1]);
    else if (k == "--chord") chord = std::atoi(argv[i + 1]) != 0;
    else if (k == "--kick") kick = std::atof(argv[i + 1]);
    else if (k == "--ring-grading") geometry.ring_grading = std::atof(argv[i + 1]);
    else {
      std::fprintf(stderr, "sweep_turek_hron_cfd: unknown option '%s' (allowed: --out, --test, --level, --dt, --time, --chord 0|1, "
                   "--kick OMEGA, --ring-grading A)\n", argv[i]);
      return 2;
    }
  }
  if (test < 1 || test > 3 || level < 0 || level > 6 || !(dt > 0) || !(end > dt)) {
    std::fprintf(stderr, "sweep_turek_hron_cfd: need --test 1..3, --level 0..6, --dt > 0, --time > dt\n");
    return 2;
  }
  Kokkos::initialize(argc, argv);
  int rc = 0;
  {
    const double ubar[4] = {0, 0.2, 1.0, 2.0};
    fl::TurekHronCase c;
    c.mean_velocity = ubar[test];
    c.ramp_time = test == 3 ? 2.0 : 0.0;
    c.level = level;
    if (test == 3) c.kick_omega = kick;
    const fl::TurekHronReference ref = fl::turek_hron_reference(test);
    const std::clock_t c0 = std::clock();
    fl::FlowConfig cfg = fl::turek_hron_config(c);
    cfg.chord = chord;
    if (test < 3) cfg.picard_steps = 3;  // Oseen steps from rest before Newton (CFD2 on level 0 diverges without)
    fl::NavierStokes2D ns(fl::make_turek_hron_channel(level, geometry), cfg);
    const double setup = double(std::clock() - c0) / CLOCKS_PER_SEC;
    if (test < 3) {
      const auto r = ns.solve_steady();
      const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
      const auto& f = ns.forces();
      std::printf("CFD%d level %d: %lld cells, %lld unknowns; Newton %d (converged %d, residual %.1e); drag %.5f (%+.3f %%), "
                  "lift %.5f (%+.3f %%); CPU %.2f s (set-up %.2f s)\n",
                  test, level, (long long)ns.mesh().element_count(), (long long)ns.unknowns(), r.iterations, r.converged,
                  r.residual, f.drag, 100 * (f.drag / ref.drag - 1), f.lift, 100 * (f.lift / ref.lift - 1), cpu, setup);
      const auto& tm = ns.timings();
      std::printf("  CPU: element kernel %.3f s (%ld passes), scatter %.3f s, LU factor %.3f s (%ld), solves %.3f s\n",
                  tm.element_kernel, tm.assemblies, tm.scatter, tm.factor, tm.factorizations, tm.solve);
      rc = r.converged ? 0 : 1;
    } else {
      std::filesystem::create_directories(out);
      char name[128];
      std::snprintf(name, sizeof(name), "cfd3_l%d_dt%g%s%s.csv", level, dt, chord ? "" : "_newton", kick != 0.0 ? "_kick" : "");
      FILE* fp = std::fopen((out / name).c_str(), "w");
      std::fprintf(fp, "t,drag,lift,newton\n");
      std::vector<double> ts, drag, lift;
      const long steps = std::lround(end / dt);
      long newton = 0;
      for (long k = 1; k <= steps; ++k) {
        const auto r = ns.step(dt);
        newton += r.iterations;
        if (!r.converged) {
          std::fprintf(stderr, "step %ld: Newton did not converge (residual %.3e)\n", k, r.residual);
          rc = 1;
          break;
        }
        ts.push_back(ns.time());
        drag.push_back(ns.forces().drag);
        lift.push_back(ns.forces().lift);
        std::fprintf(fp, "%.6f,%.9e,%.9e,%d\n", ns.time(), ns.forces().drag, ns.forces().lift, r.iterations);
        if (k % 100 == 0) {
          std::fflush(fp);
          std::fprintf(stderr, "t = %.3f s: drag %.3f, lift %.3f (CPU %.0f s)\n", ns.time(), ns.forces().drag, ns.forces().lift,
                       double(std::clock() - c0) / CLOCKS_PER_SEC);
        }
      }
      std::fclose(fp);
      const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
      double t0, t1;
      bool periodic = rc == 0 && fl::last_period(ts, lift, t0, t1);
      fl::PeriodicStats d, l;
      if (periodic) {
        d = fl::periodic_stats(ts, drag, t0, t1);
        l = fl::periodic_stats(ts, lift, t0, t1);
        periodic = l.amplitude > 1e-3 * (std::abs(l.mean) + std::abs(d.mean));  // round-off wiggles are no shedding
      }
      if (periodic) {
        std::printf("CFD3 level %d dt %g, %g s: %lld cells, %lld unknowns; drag %.3f +- %.4f, lift %.3f +- %.3f, frequency %.4f Hz "
                    "(last period %.3f-%.3f s); %ld Newton iterations, CPU %.1f s\n",
                    level, dt, end, (long long)ns.mesh().element_count(), (long long)ns.unknowns(), d.mean, d.amplitude,
                    l.mean, l.amplitude, d.frequency, t0, t1, newton, cpu);
        const auto& tm = ns.timings();
        std::printf("  CPU: element kernel %.3f s (%ld passes), scatter %.3f s, LU factor %.3f s (%ld), solves %.3f s\n",
                    tm.element_kernel, tm.assemblies, tm.scatter, tm.factor, tm.factorizations, tm.solve);
        std::printf("reference (Turek & Hron 2006): drag 439.45 +- 5.6183, lift -11.893 +- 437.81, 4.3956 Hz\n");
      } else if (rc == 0) {
        std::fprintf(stderr, "sweep_turek_hron_cfd: no shedding in %g s (lift %.3f, drag %.3f at the end)\n", end, lift.back(), drag.back());
        rc = 1;
      }
    }
  }
  Kokkos::finalize();
  return rc;
}
