// The flow-driven harvester (seed 002 paper 1 case 2; models/fsi/flow_harvester.hpp) across lock-in: for each
// plate length and inflow speed the coupled run from rest, then over the last `window` seconds the tip amplitude,
// the frequencies of the lift (the wake's forcing) and of the tip, the mean harvested power, against the plate's
// first short-circuit frequency f_1. The cylinder's side is fixed for the whole sweep (default: the lock-in side
// of the paper's 270 mm plate at 0.85 m/s): the speed moves the wake's frequency, the length moves f_1.
//   OMP_NUM_THREADS=1 build/ci/bench/sweep_flow_harvester [--level 0] [--dt 0.0025] [--end 8] [--window 3]
//       [--length L1,L2,..] [--side D] [--inflow U1,U2,..] [--smagorinsky 0.1] [--scheme monolithic|partitioned] [--csv DIR]
//   DIR/harvester_L<mm>_U<cm/s>.csv: t, tip, drag, lift, voltage, power, evaluations, circuit_solves, residual (every step);
//   DIR/harvester_sweep.csv: one row per length and speed (written when every run finished).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "fsi/flow_harvester.hpp"

namespace fs = polymech::fsi;

namespace {

// Mean and (max - min) / 2 of s over t >= t0, and the frequency from its upward crossings of that mean
// (linear interpolation between samples; 0 when fewer than two crossings).
struct WindowStats {
  double mean = 0.0, amplitude = 0.0, frequency = 0.0;
};
WindowStats window_stats(const std::vector<double>& t, const std::vector<double>& s, double t0) {
  WindowStats w;
  double lo = 1e300, hi = -1e300;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t0) lo = std::min(lo, s[k]), hi = std::max(hi, s[k]);
  if (!(hi >= lo)) return w;
  w.mean = 0.5 * (hi + lo);
  w.amplitude = 0.5 * (hi - lo);
  std::vector<double> up;
  for (std::size_t k = 1; k < t.size(); ++k)
    if (t[k - 1] >= t0 && s[k - 1] < w.mean && s[k] >= w.mean)
      up.push_back(t[k - 1] + (w.mean - s[k - 1]) / (s[k] - s[k - 1]) * (t[k] - t[k - 1]));
  if (up.size() >= 2) w.frequency = static_cast<double>(up.size() - 1) / (up.back() - up.front());
  return w;
}

}  // namespace

int main(int argc, char** argv) {
  fs::FlowHarvesterCase base;
  double end = 8.0, window = 3.0, side = 0.0;
  std::vector<double> lengths{0.27}, inflows{0.85};
  std::string csv;
  auto list = [](const std::string& v) {
    std::vector<double> out;
    std::stringstream ss(v);
    for (std::string item; std::getline(ss, item, ',');) out.push_back(std::atof(item.c_str()));
    return out;
  };
  for (int i = 1; i < argc; i += 2) {
    const std::string k = argv[i];
    if (i + 1 >= argc) {
      std::fprintf(stderr, "sweep_flow_harvester: option '%s' needs a value\n", k.c_str());
      return 2;
    }
    const std::string v = argv[i + 1];
    if (k == "--level") base.level = std::atoi(v.c_str());
    else if (k == "--dt") base.dt = std::atof(v.c_str());
    else if (k == "--end") end = std::atof(v.c_str());
    else if (k == "--window") window = std::atof(v.c_str());
    else if (k == "--length") lengths = list(v);
    else if (k == "--side") side = std::atof(v.c_str());
    else if (k == "--inflow") inflows = list(v);
    else if (k == "--smagorinsky") base.smagorinsky = std::atof(v.c_str());
    else if (k == "--csv") csv = v;
    else if (k == "--scheme") {
      if (v != "monolithic" && v != "partitioned") {
        std::fprintf(stderr, "sweep_flow_harvester: --scheme is '%s'; allowed: monolithic, partitioned\n", v.c_str());
        return 2;
      }
      base.scheme = v == "monolithic" ? polymech::piezo::Scheme::monolithic : polymech::piezo::Scheme::partitioned;
    } else {
      std::fprintf(stderr,
                   "sweep_flow_harvester: unknown option '%s' (allowed: --level L, --dt DT, --end T, --window T, --length L1,L2,.., "
                   "--side D, --inflow U, --smagorinsky CS, --scheme S, --csv DIR)\n",
                   k.c_str());
      return 2;
    }
  }
  bool lengths_ok = !lengths.empty() && !inflows.empty();
  for (const double l : lengths) lengths_ok = lengths_ok && l > 0.0 && l < 10.0;
  for (const double u : inflows) lengths_ok = lengths_ok && u > 0.0 && u < 100.0;
  if (base.level < 0 || base.level > 4 || !(base.dt > 0.0) || !(end > base.dt) || !(window > 0.0 && window < end) || !lengths_ok ||
      !(side >= 0.0) || !(base.smagorinsky >= 0.0 && base.smagorinsky < 1.0)) {
    std::fprintf(stderr,
                 "sweep_flow_harvester: need --level 0..4, --dt > 0, --end > dt, 0 < --window < --end, --length values in (0, 10) m, "
                 "--side >= 0 (0: the lock-in side of the 270 mm plate at 0.85 m/s), --inflow values in (0, 100) m/s, 0 <= --smagorinsky < 1\n");
    return 2;
  }
  if (!csv.empty()) std::filesystem::create_directories(csv);
  Kokkos::ScopeGuard kokkos(argc, argv);
  if (side == 0.0) {
    fs::FlowHarvesterCase c = base;
    c.plate_length = 0.27;
    c.inflow = 0.85;
    side = fs::lock_in_side(c);
  }
  std::printf("# flow harvester: D %.4f m, level %d, dt %g, %g s, window %g s, C_s %g\n", side, base.level, base.dt, end, window,
              base.smagorinsky);
  std::printf("%8s %6s %6s %8s %9s %9s %9s %9s %11s %10s %9s %8s %8s\n", "L_m", "U", "Re", "f1_Hz", "f_lift", "f_tip", "ratio", "tip_amp_m", "P_mean_W/m",
              "V_amp", "eval/st", "cpu_s", "s/step");
  struct Row {
    double L, U, f1, foc, fl, ft, tip, tip_mean, p, v, ev, cpu, lift_amp, drag_mean, R;
    fs::FlowHarvesterTimings timing;
    long cells, unknowns;
  };
  std::vector<Row> rows;
  for (const double L : lengths)
  for (const double U : inflows) {
    fs::FlowHarvesterCase c = base;
    c.plate_length = L;
    c.inflow = U;
    c.side = side;
    const std::clock_t c0 = std::clock();
    std::vector<double> t, tip, lift, drag, power, volt;
    long evaluations = 0;
    std::FILE* f = nullptr;
    char name[512];
    std::snprintf(name, sizeof(name), "%s/harvester_L%03d_U%03d.csv", csv.c_str(), static_cast<int>(std::lround(L * 1000)),
                  static_cast<int>(std::lround(U * 100)));
    try {
      fs::FlowHarvester model(c);
      if (!csv.empty()) {
        f = std::fopen(name, "w");
        if (!f) throw std::runtime_error(std::string("cannot write ") + name);
        std::fprintf(f, "t,tip,drag,lift,voltage,power,evaluations,circuit_solves,residual\n");
      }
      const long steps = std::lround(end / c.dt);
      for (long n = 0; n < steps; ++n) {
        const fs::FlowHarvesterStep s = model.step();
        if (!std::isfinite(s.tip) || !std::isfinite(s.lift)) throw std::runtime_error("a value is not finite at t = " + std::to_string(s.t));
        t.push_back(s.t), tip.push_back(s.tip), lift.push_back(s.lift), drag.push_back(s.drag), power.push_back(s.power),
            volt.push_back(s.voltage);
        evaluations += s.evaluations;
        if (f) std::fprintf(f, "%.6f,%.9e,%.9e,%.9e,%.9e,%.9e,%d,%d,%.3e\n", s.t, s.tip, s.drag, s.lift, s.voltage, s.power, s.evaluations,
                            s.circuit_iterations, s.residual);
        if (n % 200 == 199) {
          std::fprintf(stderr, "  L %.3f, U %.3f: t %.3f s, tip %.3e m, lift %.3e N/m, %.2f CPU s/step\n", L, U, s.t, s.tip, s.lift,
                       static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / static_cast<double>(n + 1));
          if (f) std::fflush(f);
        }
      }
      if (f) std::fclose(f), f = nullptr;
      const double t0 = end - window;
      const WindowStats st = window_stats(t, tip, t0), sl = window_stats(t, lift, t0), sv = window_stats(t, volt, t0),
                        sd = window_stats(t, drag, t0);
      double pm = 0.0;
      int np = 0;
      for (std::size_t k = 0; k < t.size(); ++k)
        if (t[k] >= t0) pm += power[k], ++np;
      pm /= std::max(np, 1);
      const double two_pi = 2.0 * 3.14159265358979323846, cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
      Row r{L, U, model.omega_sc() / two_pi, model.omega_oc() / two_pi, sl.frequency, st.frequency, st.amplitude, st.mean, pm, sv.amplitude,
            static_cast<double>(evaluations) / static_cast<double>(steps), cpu, sl.amplitude, sd.mean, model.resistance(),
            model.timings(), static_cast<long>(model.fluid().mesh().element_count()), static_cast<long>(model.fluid_unknowns())};
      rows.push_back(r);
      std::printf("%8.4f %6.3f %6.0f %8.3f %9.3f %9.3f %9.3f %9.3e %11.3e %10.3e %9.2f %8.1f %8.3f\n", r.L, U, U * side / c.nu_f, r.f1, r.fl, r.ft, r.fl / r.f1, r.tip, r.p,
                  r.v, r.ev, r.cpu, r.cpu / static_cast<double>(steps));
      std::printf("#   %ld cells, %ld fluid unknowns; CPU s: fluid %.1f, mesh %.1f, structure and circuit %.1f, set-up %.1f; "
                  "%ld circuit solves\n",
                  r.cells, r.unknowns, r.timing.fluid, r.timing.mesh, r.timing.structure, r.timing.setup, r.timing.circuit_solves);
      std::fflush(stdout);
    } catch (const std::exception& e) {
      if (f) std::fclose(f);
      std::fprintf(stderr, "sweep_flow_harvester: L = %g m, U = %g m/s: %s\n", L, U, e.what());
      return 1;
    }
  }
  if (!csv.empty()) {
    const std::string path = csv + "/harvester_sweep.csv", tmp = path + ".part";
    std::FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) {
      std::fprintf(stderr, "sweep_flow_harvester: cannot write %s\n", tmp.c_str());
      return 1;
    }
    std::fprintf(f, "length_m,side_m,inflow,f1_sc_Hz,f1_oc_Hz,f_lift_Hz,f_tip_Hz,ratio_lift_f1,tip_amplitude_m,tip_mean_m,power_mean_W_per_m,"
                    "voltage_amplitude_V,lift_amplitude,drag_mean,resistance_ohm_m,evaluations_per_step,cpu_s,cpu_fluid_s,cpu_mesh_s,cpu_structure_s,circuit_solves,cells,unknowns\n");
    for (const Row& r : rows)
      std::fprintf(f, "%.4f,%.5f,%.4f,%.5f,%.5f,%.5f,%.5f,%.5f,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.6e,%.3f,%.1f,%.1f,%.1f,%.1f,%ld,%ld,%ld\n", r.L,
                   side, r.U, r.f1, r.foc, r.fl, r.ft, r.fl / r.f1, r.tip, r.tip_mean, r.p, r.v, r.lift_amp, r.drag_mean, r.R, r.ev, r.cpu,
                   r.timing.fluid, r.timing.mesh, r.timing.structure, r.timing.circuit_solves, r.cells, r.unknowns);
    std::fclose(f);
    std::filesystem::rename(tmp, path);
  }
  return 0;
}
