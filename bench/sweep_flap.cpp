// The weakly coupled flap (issue 36's first FSI check): Turek & Hron's CSM3 flag (SVK, rho_s 1000, mu_s 0.5e6,
// nu_s 0.4, g = 2) on the cylinder of the Turek-Hron channel, released from rest undeformed in a fluid at rest
// (no inflow) of density rho_f, strongly coupled by the partitioned loop (models/fsi/turek_hron_fsi_transient.hpp,
// IQN-ILS); the reference is the same solid, mesh, integrator and dt without the fluid (step_in_vacuo). Prints,
// per density, the period of uy(A) (the mean half period between turning points: flap_swing), its ratio to the
// in-vacuo one, the first minimum of uy(A), the coupling's evaluations per step and the CPU time (one thread).
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_flap [--level 0] [--dt 0.01] [--end 2.5] [--rho-f 1,10,100] [--nu-f 1e-3]
//       [--csv DIR]   (DIR/flap_rho<rho_f>.csv: t, ux_A, uy_A, evaluations; rho 0: in vacuo)
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fsi/turek_hron_fsi_transient.hpp"

namespace fs = polymech::fsi;

int main(int argc, char** argv) {
  int level = 0;
  double dt = 0.01, end = 2.5, nu_f = 1e-3;
  std::vector<double> rhos{1.0, 10.0, 100.0};
  std::string csv;
  for (int i = 1; i < argc; i += 2) {
    const std::string k = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "sweep_flap: option '%s' needs a value\n", k.c_str());
      return 2;
    }
    const std::string v = argv[i + 1];
    if (k == "--level") level = std::atoi(v.c_str());
    else if (k == "--dt") dt = std::atof(v.c_str());
    else if (k == "--end") end = std::atof(v.c_str());
    else if (k == "--nu-f") nu_f = std::atof(v.c_str());
    else if (k == "--csv") csv = v;
    else if (k == "--rho-f") {
      rhos.clear();
      std::stringstream ss(v);
      for (std::string item; std::getline(ss, item, ',');) rhos.push_back(std::atof(item.c_str()));
    } else {
      std::fprintf(stderr, "sweep_flap: unknown option '%s' (allowed: --level L, --dt DT, --end T, --rho-f R1,R2,.., --nu-f NU, --csv DIR)\n",
                   k.c_str());
      return 2;
    }
  }
  for (const double r : rhos)
    if (!(r > 0.0)) {
      std::fprintf(stderr, "sweep_flap: --rho-f values must be positive\n");
      return 2;
    }
  if (level < 0 || level > 4 || !(dt > 0.0) || !(end > dt) || !(nu_f > 0.0)) {
    std::fprintf(stderr, "sweep_flap: need --level 0..4, --dt > 0, --end > dt, --nu-f > 0\n");
    return 2;
  }
  if (!csv.empty()) std::filesystem::create_directories(csv);
  Kokkos::ScopeGuard kokkos(argc, argv);
  auto write = [&](double rho, const std::vector<fs::TurekHronFsiStep>& rows) {
    if (csv.empty()) return;
    char name[64];
    std::snprintf(name, sizeof(name), "/flap_rho%g.csv", rho);
    std::FILE* f = std::fopen((csv + name).c_str(), "w");
    if (!f) return;
    std::fprintf(f, "t,ux_A,uy_A,evaluations\n");
    for (const auto& s : rows) std::fprintf(f, "%.6f,%.9e,%.9e,%d\n", s.t, s.ux, s.uy, s.evaluations);
    std::fclose(f);
  };
  try {
    double cpu = 0.0, eps = 0.0;
    const std::vector<fs::TurekHronFsiStep> vac = fs::run_flap(fs::flap_case(level, 1.0, nu_f), dt, end, true, &cpu, &eps);
    write(0.0, vac);
    fs::FlapSwing v;
    if (!fs::flap_swing(vac, v)) {
      std::fprintf(stderr, "sweep_flap: no turning point in vacuo within %g s\n", end);
      return 1;
    }
    std::printf("flap, level %d, dt %g, %g s, nu_f %g (uy(A) e-3 m; period from %d turning points in vacuo)\n", level, dt, end, nu_f,
                v.turning_points);
    std::printf("| rho_f | period [s] | / vacuo | first min uy | next max uy | evaluations / step | CPU [s] |\n");
    std::printf("| vacuo | %.5f | 1 | %.3f | %.3f | - | %.1f |\n", v.period, 1e3 * v.first_min, 1e3 * v.first_max, cpu);
    std::fflush(stdout);
    for (const double rho : rhos) {
      const std::vector<fs::TurekHronFsiStep> rows = fs::run_flap(fs::flap_case(level, rho, nu_f), dt, end, false, &cpu, &eps);
      write(rho, rows);
      fs::FlapSwing s;
      if (!fs::flap_swing(rows, s)) {
        std::printf("| %g | no turning point | | | | %.2f | %.1f |\n", rho, eps, cpu);
        continue;
      }
      std::printf("| %g | %.5f | %.4f | %.3f | %.3f | %.2f | %.1f |\n", rho, s.period, s.period / v.period, 1e3 * s.first_min,
                  1e3 * s.first_max, eps, cpu);
      std::fflush(stdout);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep_flap: %s\n", e.what());
    return 1;
  }
  return 0;
}
