// Accuracy against cost of the finite-element harvester (issue 35; models/piezo/, the duToit & Wardle bimorph of
// seed 002 paper 1, 2D plane stress; docs/PERFORMANCE.md, docs/VALIDATION.md). Writes into DIR:
//   piezo_fe_mesh.csv    order,cells_length,cells_per_layer,unknowns,f_sc_hz,f_oc_hz,P2000_W,P50k_W,
//                        err_f_sc,err_P2000,seconds: the short- and open-circuit frequencies (inverse
//                        iteration) and the powers per (1 m/s^2)^2 at the model's own f_sc with 2000 ohm and with
//                        50 kohm (near the optimum), against the finest mesh; seconds = build + both frequencies +
//                        the two harmonic solves, one thread
//   piezo_fe_time.csv    steps_per_period,dt_s,V_steady,V_harmonic,err_V,steps,seconds: the Newmark run to steady
//                        state (zeta 0.05, 40 periods) against the harmonic solve at the same frequency
//   piezo_fe_sweep.json  the 200-frequency sweep of the goal: the mesh, its f_sc error against the finest,
//                        and the wall time of the 200 harmonic solves; the 3D model's frequencies beside the 2D one
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_piezo_fe --out out/piezo   [--quick: fewer meshes]
//   sweep_piezo_fe --bender P N: the PVDF bender (2D plane stress, order P, N x 2 cells) built and solved once;
//   prints {"tip": m, "seconds": s, "unknowns": n} (the FEniCSx peer, bench/peers/dolfinx/piezo_bender.py)
// Plot: python3 tools/plot_piezo_accuracy_cost.py out/piezo
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "piezo/analytic.hpp"
#include "piezo/cases.hpp"
#include "piezo/transient.hpp"

namespace pz = polymech::piezo;

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct MeshPoint {
  int p, nl, cpl;
  long long n = 0;
  double fsc = 0, foc = 0, P2000 = 0, P50k = 0, seconds = 0;
};

MeshPoint measure(int p, int nl, int cpl) {
  MeshPoint m{p, nl, cpl};
  const auto t0 = std::chrono::steady_clock::now();
  const pz::PiezoBeam b(pz::dutoit_harvester_spec(p, nl, cpl));
  const double w = b.natural_frequency(true);
  m.foc = b.natural_frequency(false) / (2 * pz::kPi);
  const auto damping = pz::Rayleigh::stiffness_proportional(0.01, w);
  m.P2000 = b.harmonic(w, pz::harvester_load(b, 2000.0), damping).power;
  m.P50k = b.harmonic(w, pz::harvester_load(b, 5e4), damping).power;
  m.seconds = seconds_since(t0);
  m.fsc = w / (2 * pz::kPi);
  m.n = static_cast<long long>(b.unknowns());
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  std::filesystem::path out = "out/piezo";
  bool quick = false;
  if (argc == 4 && !std::strcmp(argv[1], "--bender")) {
    const int p = std::atoi(argv[2]), n = std::atoi(argv[3]);
    if (p < 1 || p > 4 || n < 1) {
      std::fprintf(stderr, "sweep_piezo_fe --bender P N: P in 1..4, N >= 1\n");
      return 2;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const pz::PiezoBeam b(pz::pvdf_bender_spec(2, pz::Plane::stress, p, n));
    const double tip = b.tip(b.solve_static());
    std::printf("{\"tip\": %.9e, \"seconds\": %.6f, \"unknowns\": %lld}\n", tip, seconds_since(t0),
                static_cast<long long>(b.unknowns()));
    return 0;
  }
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--out") && i + 1 < argc) {
      out = argv[++i];
    } else if (!std::strcmp(argv[i], "--quick")) {
      quick = true;
    } else {
      std::fprintf(stderr, "sweep_piezo_fe: unknown option '%s' (allowed: --out DIR, --quick)\n", argv[i]);
      return 2;
    }
  }
  std::filesystem::create_directories(out);
  // mesh and order
  const MeshPoint ref = measure(4, quick ? 40 : 80, 2);
  std::fprintf(stderr, "reference p 4, %d x 2 cells per layer: f_sc %.6f Hz, f_oc %.6f Hz (%lld unknowns, %.1f s)\n",
               ref.nl, ref.fsc, ref.foc, ref.n, ref.seconds);
  FILE* f = std::fopen((out / "piezo_fe_mesh.csv").c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "sweep_piezo_fe: cannot write %s\n", (out / "piezo_fe_mesh.csv").c_str());
    return 1;
  }
  std::fprintf(f, "order,cells_length,cells_per_layer,unknowns,f_sc_hz,f_oc_hz,P2000_W,P50k_W,err_f_sc,err_P2000,seconds\n");
  for (int p = 1; p <= 4; ++p)
    for (const int nl : {5, 10, 20, 40, 80, 160}) {
      if (quick && nl > 40) continue;
      if (p >= 3 && nl > 80) continue;
      for (const int cpl : {1, 2}) {
        if (p == 1 && cpl == 1) continue;  // locks (tests/piezo: 29 % of the bender's deflection)
        const MeshPoint m = measure(p, nl, p == 1 ? 2 * cpl : cpl);
        std::fprintf(f, "%d,%d,%d,%lld,%.9f,%.9f,%.9e,%.9e,%.3e,%.3e,%.4f\n", m.p, m.nl, m.cpl, m.n, m.fsc, m.foc, m.P2000,
                     m.P50k, m.fsc / ref.fsc - 1, m.P2000 / ref.P2000 - 1, m.seconds);
        std::fprintf(stderr, "p %d nl %3d cpl %d: %6lld unknowns, f_sc %+.2e, P(2000) %+.2e, %.3f s\n", m.p, m.nl, m.cpl,
                     m.n, m.fsc / ref.fsc - 1, m.P2000 / ref.P2000 - 1, m.seconds);
      }
    }
  std::fclose(f);
  // time step: Newmark against the harmonic solve, 40 periods at zeta 0.05 (the start-up decays to 3.5e-6)
  {
    const pz::PiezoBeam b(pz::dutoit_harvester_spec(2, 20, 1));
    const double w = b.natural_frequency(true);
    const auto damping = pz::Rayleigh::stiffness_proportional(0.05, w);
    const pz::Circuit c = pz::harvester_load(b, 2000.0);
    const auto h = b.harmonic(w, c, damping);
    const double Vh = std::abs(h.V[1] - h.V[0]);
    FILE* g = std::fopen((out / "piezo_fe_time.csv").c_str(), "w");
    std::fprintf(g, "steps_per_period,dt_s,V_steady,V_harmonic,err_V,steps,seconds\n");
    for (const int spp : {10, 20, 40, 80, 160, 320}) {
      if (quick && spp > 80) continue;
      pz::TransientOptions o;
      o.dt = 2 * pz::kPi / w / spp;
      o.damping = damping;
      const auto t0 = std::chrono::steady_clock::now();
      pz::PiezoTransient t(b, c, o);
      t.start(0.0);
      const int steps = 40 * spp;
      double peak = 0.0;
      // the steady amplitude from the last two periods' samples, refined by the phase: |V| = max over a period
      // of the sampled voltage is low by up to 1 - cos(pi / spp); a least-squares sine fit removes that
      double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
      for (int i = 1; i <= steps; ++i) {
        t.step(std::sin(w * i * o.dt));
        if (i > steps - 2 * spp) {
          const double y = t.voltage(1, 0), s = std::sin(w * i * o.dt), co = std::cos(w * i * o.dt);
          ss += s * s;
          sc += s * co;
          cc += co * co;
          ys += y * s;
          yc += y * co;
          peak = std::max(peak, std::fabs(y));
        }
      }
      const double det = ss * cc - sc * sc, A = (ys * cc - yc * sc) / det, B = (yc * ss - ys * sc) / det;
      const double amp = std::hypot(A, B);
      const double sec = seconds_since(t0);
      std::fprintf(g, "%d,%.9e,%.9e,%.9e,%.3e,%d,%.4f\n", spp, o.dt, amp, Vh, amp / Vh - 1, steps, sec);
      std::fprintf(stderr, "dt = T/%d: V %.6e against %.6e (%+.2e), %.3f s\n", spp, amp, Vh, amp / Vh - 1, sec);
    }
    std::fclose(g);
  }
  // the 200-frequency sweep (issue goal: resonance within 1 % of the converged value, under a minute)
  {
    const int p = 2, nl = 20, cpl = 1;
    const auto t0 = std::chrono::steady_clock::now();
    const pz::PiezoBeam b(pz::dutoit_harvester_spec(p, nl, cpl));
    const double wsc = b.natural_frequency(true), woc = b.natural_frequency(false);
    const auto damping = pz::Rayleigh::stiffness_proportional(0.01, wsc);
    const pz::Circuit c = pz::harvester_load(b, 2000.0);
    double best = 0.0, fbest = 0.0;
    for (int k = 0; k < 200; ++k) {
      const double w = 0.9 * wsc + (1.1 * woc - 0.9 * wsc) * k / 199.0;
      const auto h = b.harmonic(w, c, damping);
      if (h.power > best) {
        best = h.power;
        fbest = w / (2 * pz::kPi);
      }
    }
    const double sweep = seconds_since(t0);
    // 3D beside 2D (the same mesh along the length, 2 cells across the width)
    const auto t3 = std::chrono::steady_clock::now();
    const pz::PiezoBeam b3(pz::dutoit_harvester_spec(2, nl, cpl, 3, 2));
    const double f3sc = b3.natural_frequency(true) / (2 * pz::kPi), f3oc = b3.natural_frequency(false) / (2 * pz::kPi);
    const double sec3 = seconds_since(t3);
    FILE* j = std::fopen((out / "piezo_fe_sweep.json").c_str(), "w");
    std::fprintf(j,
                 "{\n  \"order\": %d, \"cells_length\": %d, \"cells_per_layer\": %d, \"unknowns\": %lld,\n"
                 "  \"f_sc_hz\": %.6f, \"f_sc_reference_hz\": %.6f, \"f_sc_error\": %.3e,\n"
                 "  \"frequencies\": 200, \"load_ohm\": 2000, \"peak_power_W\": %.6e, \"peak_frequency_hz\": %.6f,\n"
                 "  \"sweep_seconds\": %.3f,\n"
                 "  \"dim3\": {\"cells_width\": 2, \"unknowns\": %lld, \"f_sc_hz\": %.6f, \"f_oc_hz\": %.6f, \"seconds\": %.3f}\n}\n",
                 p, nl, cpl, static_cast<long long>(b.unknowns()), wsc / (2 * pz::kPi), ref.fsc,
                 wsc / (2 * pz::kPi) / ref.fsc - 1, best, fbest, sweep, static_cast<long long>(b3.unknowns()), f3sc, f3oc, sec3);
    std::fclose(j);
    std::fprintf(stderr, "200-frequency sweep: %lld unknowns, f_sc error %+.2e, %.2f s; 3D f_sc %.4f f_oc %.4f Hz (%.1f s)\n",
                 static_cast<long long>(b.unknowns()), wsc / (2 * pz::kPi) / ref.fsc - 1, sweep, f3sc, f3oc, sec3);
  }
  return 0;
}
