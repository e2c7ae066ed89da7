// Frequency responses of the analytic bimorph harvester (issue 35; models/piezo/analytic.hpp, the Erturk &
// Inman 2009 distributed-parameter model): voltage, current, tip displacement and power per base acceleration
// over frequency for a set of load resistances, the power against the load at the short- and open-circuit
// frequencies, the optimal loads and the global optimum. Plain C++17, no Kokkos. Writes into DIR:
//   piezo_<case>_frf.csv        R_ohm,f_hz,V_per_g,V_phase_deg,I_per_g,P_per_g2,tip_rel_per_g,tip_phase_deg
//                               (amplitudes per 1 g = 9.81 m/s^2 base acceleration; P the mean power |V|^2/(2R))
//   piezo_<case>_power_R.csv    R_ohm,P_fsc_per_g2,P_foc_per_g2,P_max_per_g2,f_at_max_hz
//   piezo_<case>_summary.json   the constants, frequencies, optimal loads and powers, the sweep's wall time
//   build/h-piezo/bench/sweep_piezo_analytic --case erturk --out out/piezo
//   options: --modes N (1), --zeta z, --width b [m], --connection series|parallel, --points n (801),
//            --fmin Hz --fmax Hz (default 0.8 f_sc .. 1.2 f_oc)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <string>
#include <vector>

#include "piezo/analytic.hpp"

namespace pz = polymech::piezo;

namespace {

constexpr double kTwoPi = 2.0 * pz::kPi;
double deg(std::complex<double> z) { return std::arg(z) * 180.0 / pz::kPi; }

void usage() {
  std::fprintf(stderr,
               "usage: sweep_piezo_analytic --case dutoit|erturk --out DIR [--modes N] [--zeta z] [--width b_m]\n"
               "       [--connection series|parallel] [--points n] [--fmin Hz] [--fmax Hz]\n");
}

// The local maxima over frequency in [w_lo, w_hi] of the mean power at the frequency's own optimal load
// (one for a weakly coupled harvester, two, near w_sc and w_oc, for a strongly coupled one): the local maxima
// of a grid, each refined by golden section between its neighbours.
struct Optimum {
  double w, R, P;
};
std::vector<Optimum> optima(const pz::BimorphHarvester& h, double w_lo, double w_hi) {
  auto Pmax = [&](double w) { return h.response(w, h.optimal_load(w)).power; };
  const int n = 800;
  const double d = (w_hi - w_lo) / n;
  std::vector<double> p(n + 1);
  for (int k = 0; k <= n; ++k) p[k] = Pmax(w_lo + d * k);
  std::vector<Optimum> out;
  for (int k = 1; k < n; ++k)
    if (p[k] > p[k - 1] && p[k] >= p[k + 1]) {
      const double w = pz::golden_max(Pmax, w_lo + (k - 1) * d, w_lo + (k + 1) * d);
      out.push_back({w, h.optimal_load(w), Pmax(w)});
    }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::string which, out;
  int modes = 1, points = 801;
  double zeta = -1, width = -1, fmin = -1, fmax = -1;
  std::string connection;
  for (int a = 1; a < argc; ++a) {
    const std::string k = argv[a];
    auto next = [&]() -> std::string {
      if (a + 1 >= argc) {
        usage();
        std::exit(2);
      }
      return argv[++a];
    };
    if (k == "--case") which = next();
    else if (k == "--out") out = next();
    else if (k == "--modes") modes = std::atoi(next().c_str());
    else if (k == "--zeta") zeta = std::atof(next().c_str());
    else if (k == "--width") width = std::atof(next().c_str());
    else if (k == "--connection") connection = next();
    else if (k == "--points") points = std::atoi(next().c_str());
    else if (k == "--fmin") fmin = std::atof(next().c_str());
    else if (k == "--fmax") fmax = std::atof(next().c_str());
    else {
      usage();
      return 2;
    }
  }
  if ((which != "dutoit" && which != "erturk") || out.empty() || modes < 1 || points < 2) {
    usage();
    return 2;
  }
  pz::BimorphSpec s = which == "dutoit" ? pz::dutoit_wardle_2007_case() : pz::erturk_inman_2009_case();
  s.modes = modes;
  if (zeta > 0) s.zeta = {zeta};
  if (width > 0) s.b = width;
  if (connection == "parallel") s.connection = pz::Connection::parallel;
  else if (connection == "series") s.connection = pz::Connection::series;
  else if (!connection.empty()) {
    usage();
    return 2;
  }
  std::error_code ec;
  std::filesystem::create_directories(out, ec);
  if (ec) {
    std::fprintf(stderr, "cannot create %s\n", out.c_str());
    return 1;
  }
  const pz::BimorphHarvester h(s);
  const double g = pz::kGravity;
  const double wsc = h.omega(0), woc = h.open_circuit_frequencies()[0];
  const double fsc = wsc / kTwoPi, foc = woc / kTwoPi;
  const double f0 = fmin > 0 ? fmin : 0.8 * fsc, f1 = fmax > 0 ? fmax : 1.2 * foc;
  const std::vector<double> loads = {1e2, 1e3, 2e3, 1e4, 3e4, 1e5, 3e5, 1e6, 1e7};
  const std::string base = out + "/piezo_" + which;

  // 1. the FRFs
  const auto t0 = std::chrono::steady_clock::now();
  std::FILE* f = std::fopen((base + "_frf.csv").c_str(), "w");
  if (!f) {
    std::fprintf(stderr, "cannot write %s_frf.csv\n", base.c_str());
    return 1;
  }
  std::fprintf(f, "R_ohm,f_hz,V_per_g,V_phase_deg,I_per_g,P_per_g2,tip_rel_per_g,tip_phase_deg\n");
  for (double R : loads)
    for (int k = 0; k < points; ++k) {
      const double fh = f0 + (f1 - f0) * k / (points - 1);
      const pz::Response o = h.response(kTwoPi * fh, R);
      std::fprintf(f, "%.6g,%.8g,%.8e,%.4f,%.8e,%.8e,%.8e,%.4f\n", R, fh, std::abs(o.V) * g, deg(o.V),
                   std::abs(o.I) * g, o.power * g * g, std::abs(o.tip_rel) * g, deg(o.tip_rel));
    }
  std::fclose(f);
  const double t_frf = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  // 2. the power against the load
  f = std::fopen((base + "_power_R.csv").c_str(), "w");
  if (!f) return 1;
  std::fprintf(f, "R_ohm,P_fsc_per_g2,P_foc_per_g2,P_max_per_g2,f_at_max_hz\n");
  for (int k = 0; k <= 120; ++k) {
    const double R = std::pow(10.0, 1.0 + 7.0 * k / 120);
    const double wm = pz::golden_max([&](double w) { return h.response(w, R).power; }, 0.9 * wsc, 1.1 * woc);
    std::fprintf(f, "%.6e,%.8e,%.8e,%.8e,%.6f\n", R, h.response(wsc, R).power * g * g,
                 h.response(woc, R).power * g * g, h.response(wm, R).power * g * g, wm / kTwoPi);
  }
  std::fclose(f);

  // 3. the optimal loads and the summary
  const double Rsc = h.optimal_load(wsc), Roc = h.optimal_load(woc);
  const double Psc = h.response(wsc, Rsc).power, Poc = h.response(woc, Roc).power;
  const std::vector<Optimum> opt = optima(h, 0.9 * wsc, 1.1 * woc);
  Optimum best{0, 0, -1};
  for (const auto& o : opt)
    if (o.P > best.P) best = o;
  // the time of one 200-frequency sweep at one load (the sweep goal, analytic side)
  const auto t1 = std::chrono::steady_clock::now();
  double sink = 0;
  const int reps = 1000;
  for (int r = 0; r < reps; ++r)
    for (int k = 0; k < 200; ++k) sink += h.response(kTwoPi * (f0 + (f1 - f0) * k / 199), 2000.0).power;
  const double t_200 = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count() / reps;
  const pz::Response at2k = h.response(wsc, 2000.0);

  f = std::fopen((base + "_summary.json").c_str(), "w");
  if (!f) return 1;
  std::fprintf(f, "{\n  \"case\": \"%s\", \"connection\": \"%s\", \"modes\": %d, \"zeta\": %.6g,\n", which.c_str(),
               pz::to_string(s.connection), s.modes, s.zeta[0]);
  std::fprintf(f, "  \"L\": %.6g, \"b\": %.6g, \"hp\": %.6g, \"hs\": %.6g,\n", s.L, s.b, s.hp, s.hs);
  std::fprintf(f, "  \"c11_bar\": %.6g, \"e31_bar\": %.6g, \"eps33_bar\": %.6g, \"rho_p\": %.6g, \"Y_s\": %.6g, "
               "\"rho_s\": %.6g,\n", s.piezo.c11, s.piezo.e31, s.piezo.eps33, s.piezo.rho, s.host.E, s.host.rho);
  std::fprintf(f, "  \"YI\": %.8g, \"m\": %.8g, \"Cp\": %.8g, \"vartheta\": %.8g, \"theta_1\": %.8g, \"k2_1\": %.8g,\n",
               h.YI(), h.mass_per_length(), h.capacitance(), h.vartheta(), h.theta(0), h.coupling_k2(0));
  std::fprintf(f, "  \"f_sc_hz\": %.6f, \"f_oc_hz\": %.6f, \"f_oc_single_mode_hz\": %.6f, \"f_oc_exact_hz\": %.6f,\n",
               fsc, foc, h.open_circuit_frequency_single_mode(0) / kTwoPi, h.open_circuit_frequency_exact(0) / kTwoPi);
  std::fprintf(f, "  \"R_opt_fsc_ohm\": %.6g, \"P_opt_fsc_W_per_g2\": %.6g, \"V_opt_fsc_per_g\": %.6g, "
               "\"R_textbook_fsc_ohm\": %.6g,\n", Rsc, Psc * g * g, std::abs(h.response(wsc, Rsc).V) * g,
               1.0 / (wsc * h.capacitance()));
  std::fprintf(f, "  \"R_opt_foc_ohm\": %.6g, \"P_opt_foc_W_per_g2\": %.6g, \"V_opt_foc_per_g\": %.6g,\n", Roc,
               Poc * g * g, std::abs(h.response(woc, Roc).V) * g);
  std::fprintf(f, "  \"global_opt\": {\"f_hz\": %.6f, \"R_ohm\": %.6g, \"P_W_per_g2\": %.6g},\n", best.w / kTwoPi,
               best.R, best.P * g * g);
  std::fprintf(f, "  \"local_optima\": [");
  for (std::size_t k = 0; k < opt.size(); ++k)
    std::fprintf(f, "%s{\"f_hz\": %.6f, \"R_ohm\": %.6g, \"P_W_per_g2\": %.6g}", k ? ", " : "", opt[k].w / kTwoPi,
                 opt[k].R, opt[k].P * g * g);
  std::fprintf(f, "],\n");
  std::fprintf(f, "  \"at_fsc_2000ohm\": {\"V_per_g\": %.6g, \"P_W_per_g2\": %.6g, \"tip_rel_per_g\": %.6g},\n",
               std::abs(at2k.V) * g, at2k.power * g * g, std::abs(at2k.tip_rel) * g);
  std::fprintf(f, "  \"static_tip_per_volt_m\": %.6g,\n", h.static_tip_deflection(1.0));
  std::fprintf(f, "  \"frf_csv_seconds\": %.4g, \"sweep_200_freq_seconds\": %.4g\n}\n", t_frf, t_200);
  std::fclose(f);

  std::printf("%s (%s, b = %.4g mm, %d mode%s, zeta %.4g): f_sc %.3f Hz, f_oc %.3f Hz (all modes %.3f Hz), k^2 %.5f, "
              "Cp %.4e F\n",
              which.c_str(), pz::to_string(s.connection), s.b * 1e3, s.modes, s.modes > 1 ? "s" : "", s.zeta[0], fsc,
              foc, h.open_circuit_frequency_exact(0) / kTwoPi, h.coupling_k2(0), h.capacitance());
  std::printf("  R_opt at f_sc %.4g ohm (1/(w Cp) %.4g): P %.4e W/g^2, |V| %.4g V/g\n", Rsc,
              1.0 / (wsc * h.capacitance()), Psc * g * g, std::abs(h.response(wsc, Rsc).V) * g);
  std::printf("  R_opt at f_oc %.4g ohm: P %.4e W/g^2, |V| %.4g V/g\n", Roc, Poc * g * g,
              std::abs(h.response(woc, Roc).V) * g);
  for (const auto& o : opt)
    std::printf("  local optimum over f and R: %.3f Hz, %.4g ohm, %.4e W/g^2\n", o.w / kTwoPi, o.R, o.P * g * g);
  std::printf("  at f_sc, 2000 ohm: |V| %.4g V/g, P %.4e W/g^2, tip %.4e m/g\n", std::abs(at2k.V) * g,
              at2k.power * g * g, std::abs(at2k.tip_rel) * g);
  std::printf("  a 200-frequency sweep: %.3g s (%s)\n", t_200, sink > 0 ? "ok" : "?");
  std::printf("  wrote %s_frf.csv, %s_power_R.csv, %s_summary.json\n", base.c_str(), base.c_str(), base.c_str());
  return 0;
}
