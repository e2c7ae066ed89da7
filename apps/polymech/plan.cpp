// `polymech plan` (issue 38): chooses the resolution, order and precision of a scene's run from the error
// it must reach, with the error and time models of io/plan.hpp fitted to the committed sweeps, and with
// --run runs the choice and writes plan.json (prediction against what the run achieved).
//   polymech plan --scene FILE --target-error E [--quantity KEY] [--threads N] [--run] [--out DIR]
//   polymech plan --fit-report      (the fitted models of every case with sweep data, markdown)
#include "apps/polymech/plan.hpp"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "apps/common/app.hpp"
#include "io/plan.hpp"

namespace polymech::apps {

namespace {

namespace pl = io::plan;
namespace fs = std::filesystem;

struct ChildRun {
  int rc = 1;
  double cpu = 0.0, wall = 0.0;
};

// Runs `exe args...` and waits; its CPU time (user + system, all its threads) from wait4's rusage.
ChildRun run_child(const std::string& exe, const std::vector<std::string>& args) {
  std::vector<char*> argv = {const_cast<char*>(exe.c_str())};
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot start ") + exe + ": " + std::strerror(errno));
  if (pid == 0) {
    execv(exe.c_str(), argv.data());
    std::fprintf(stderr, "polymech plan: failed: cannot run %s: %s\n", exe.c_str(), std::strerror(errno));
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) < 0) throw std::runtime_error(std::string("wait for ") + exe + ": " + std::strerror(errno));
  ChildRun r;
  r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.cpu = ru.ru_utime.tv_sec + 1e-6 * ru.ru_utime.tv_usec + ru.ru_stime.tv_sec + 1e-6 * ru.ru_stime.tv_usec;
  r.rc = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  return r;
}

nlohmann::json candidate_json(const pl::Model& m, const pl::Candidate& c) {
  nlohmann::json j;
  j["setting"] = pl::describe_candidate(m, c);
  j[m.resolution_name] = c.point.resolution;
  if (!m.order_name.empty()) j[m.order_name] = c.point.order;
  j["precision"] = c.point.single ? "float" : "double";
  if (c.point.steps > 0) j["steps"] = c.point.steps;
  j["predicted_error"] = c.predicted_error;
  j["predicted_seconds"] = c.predicted_seconds;
  j["sweep_error"] = c.point.error;
  j["sweep_seconds"] = c.point.seconds;
  return j;
}

// `--measure-overhead`: for one scene of every case, runs the app on the model's cheapest candidate
// `repeat` times and writes, per scene, the median CPU time of the whole process against the model's
// prediction from the sweep's times; the difference (>= 0) is the app's fixed cost (Kokkos start-up,
// scene load, output) that the sweeps' model-only times leave out. The plan adds it to every prediction.
int measure_overhead(const fs::path& root, const fs::path& self_dir, const fs::path& out, int repeat) {
  const fs::path csv = root / pl::overhead_csv();
  fs::create_directories(csv.parent_path());
  std::ostringstream rows;
  rows << "app,scene,setting,runs,model_seconds,median_cpu_seconds,overhead_seconds\n";
  for (const auto& scene : pl::overhead_scenes(root)) {
    const pl::Model m = pl::build_model(scene, "", false);
    const pl::Candidate* cheapest = nullptr;
    for (const auto& c : m.candidates)
      if (!c.beyond_floor && (!cheapest || c.predicted_seconds < cheapest->predicted_seconds)) cheapest = &c;
    if (!cheapest) continue;
    const fs::path dir = out / ("overhead_" + scene.stem().string());
    const auto args = pl::run_arguments(m, scene, *cheapest, dir, 1);
    std::vector<double> cpu;
    for (int k = 0; k < repeat; ++k) {
      const ChildRun r = run_child((self_dir / m.app).string(), args);
      if (r.rc != 0) throw std::runtime_error(m.app + " on " + (dir / "plan_scene.toml").string() + " failed (exit " + std::to_string(r.rc) + ")");
      cpu.push_back(r.cpu);
    }
    std::sort(cpu.begin(), cpu.end());
    const double median = cpu[cpu.size() / 2];
    const double overhead = std::max(0.0, median - cheapest->predicted_seconds);
    std::string setting = pl::describe_candidate(m, *cheapest);
    for (auto& ch : setting)
      if (ch == ',') ch = ';';
    char line[512];
    std::snprintf(line, sizeof line, "%s,%s,%s,%d,%.6g,%.6g,%.6g\n", m.app.c_str(), scene.stem().string().c_str(), setting.c_str(),
                  repeat, cheapest->predicted_seconds, median, overhead);
    rows << line;
    std::printf("[plan] %s %s (%s): model %.3g s, whole run %.3g s CPU (median of %d): overhead %.3g s\n", m.app.c_str(),
                scene.stem().string().c_str(), setting.c_str(), cheapest->predicted_seconds, median, repeat, overhead);
    std::fflush(stdout);
  }
  std::ofstream f(csv);
  f << rows.str();
  if (!f) throw std::runtime_error(csv.string() + ": cannot write");
  std::printf("[plan] wrote %s\n", csv.string().c_str());
  return 0;
}

}  // namespace

int plan_main(int argc, char** argv, const fs::path& self_dir) {
  CLI::App app{"polymech plan: the resolution, order and precision that reach a target error soonest (issue 38)"};
  app.name("polymech plan");
  fs::path scene, out = "out/plan";
  double target = 0.0;
  std::string quantity;
  int threads = 1;
  bool run = false, report = false, overhead = false;
  int repeat = 3;
  app.add_option("--scene", scene, "scene file (TOML) whose case has a committed accuracy-cost sweep");
  app.add_option("--target-error", target, "the largest acceptable relative error of the quantity")
      ->check(CLI::PositiveNumber);
  app.add_option("--quantity", quantity, "the quantity (default: the case's first; the output lists them)");
  app.add_option("--threads", threads, "threads of the planned run (the time models are one-thread CPU times)")
      ->check(CLI::Range(1, 4096));
  app.add_option("--out", out, "output folder of --run")->capture_default_str();
  app.add_flag("--run", run, "run the chosen case and write plan.json (prediction and achievement) in --out");
  app.add_flag("--measure-overhead", overhead,
               "run every case's app on its cheapest sweep point (--repeat times, one thread) and write the app's fixed "
               "cost over the sweep's model time to docs/figures/plan/app_overhead.csv");
  app.add_option("--repeat", repeat, "runs per scene of --measure-overhead (the median is kept)")->check(CLI::Range(1, 99));
  app.add_flag("--fit-report", report, "print the fitted models of every case with sweep data (markdown) and stop");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return guarded("polymech plan", [&]() -> int {
    KokkosSession kokkos(1);  // the loaders check stability limits with the models' kernels
    try {
      if (report) {
        std::printf("%s", pl::fit_report(pl::source_dir(scene.empty() ? fs::path(".") : scene)).c_str());
        return 0;
      }
      if (overhead) return measure_overhead(pl::source_dir(scene.empty() ? fs::path(".") : scene), self_dir, out, repeat);
      if (scene.empty()) throw std::invalid_argument("give --scene FILE (and --target-error E)");
      if (!(target > 0)) throw std::invalid_argument("give --target-error E (a relative error > 0, e.g. 0.01)");
      if (!fs::is_regular_file(scene)) throw std::invalid_argument("--scene " + scene.string() + ": scene file not found");
      const pl::Model model = pl::build_model(scene, quantity);
      const pl::Plan plan = pl::choose(model, target);
      std::printf("%s", pl::describe_plan(model, plan, target).c_str());
      if (threads != 1)
        std::printf("  note: the time models are one-thread CPU times; with %d threads expect less wall time\n", threads);
      if (plan.refused) {
        std::fprintf(stderr, "polymech plan: error: %s\n", plan.reason.c_str());
        return 2;
      }
      if (!run) return 0;
      const auto args = pl::run_arguments(model, scene, plan.choice, out, threads);
      const std::string exe = (self_dir / model.app).string();
      std::string line = model.app;
      for (const auto& a : args) line += " " + a;
      std::printf("[plan] running: %s\n", line.c_str());
      std::fflush(stdout);
      const ChildRun r = run_child(exe, args);
      nlohmann::json j;
      j["scene"] = scene.string();
      j["method"] = model.method;
      j["quantity"] = model.quantity;
      j["quantity_text"] = model.quantity_text;
      j["target_error"] = target;
      j["sweep_data"] = model.csv.string();
      j["overhead_seconds"] = model.overhead_seconds;
      if (!model.reference_note.empty()) j["reference"] = model.reference_note;
      j["choice"] = candidate_json(model, plan.choice);
      nlohmann::json pareto = nlohmann::json::array();
      for (const auto& c : plan.pareto) pareto.push_back(candidate_json(model, c));
      j["pareto"] = pareto;
      j["command"] = line;
      j["exit_code"] = r.rc;
      j["cpu_seconds"] = r.cpu;
      j["wall_seconds"] = r.wall;
      j["threads"] = threads;
      double achieved = NAN;
      std::ifstream in(out / "summary.json");
      if (in) {
        const auto s = nlohmann::json::parse(in, nullptr, false);
        // the key, or "key/k": element k of an array (the harmonic ratios)
        nlohmann::json value;
        if (!s.is_discarded()) {
          const auto slash = model.summary_key.find('/');
          const std::string key = model.summary_key.substr(0, slash);
          if (s.contains(key)) value = s[key];
          if (slash != std::string::npos) {
            const std::size_t k = std::stoul(model.summary_key.substr(slash + 1));
            value = value.is_array() && k < value.size() ? value[k] : nlohmann::json();
          }
        }
        if (value.is_number()) {
          const double v = value.get<double>();
          // Richardson: the run's value against the chosen group's extrapolated limit
          achieved = std::isfinite(plan.choice.reference) ? std::abs(v - plan.choice.reference) / std::abs(plan.choice.reference)
                                                          : std::abs(v);
          if (std::isfinite(plan.choice.reference)) j["achieved_value"] = v;
        }
      }
      if (std::isfinite(plan.choice.reference)) j["richardson_limit"] = plan.choice.reference;
      j["achieved_error"] = std::isfinite(achieved) ? nlohmann::json(achieved) : nlohmann::json(nullptr);
      j["target_met"] = std::isfinite(achieved) && achieved <= target;
      j["time_ratio"] = r.cpu / plan.choice.predicted_seconds;  // measured CPU / predicted
      std::ofstream(out / "plan.json") << j.dump(2) << "\n";
      std::printf("[plan] achieved error %.3g (target %.3g: %s), CPU time %.3g s against predicted %.3g s (ratio %.2f), "
                  "wall %.3g s; %s\n",
                  achieved, target, std::isfinite(achieved) && achieved <= target ? "met" : "NOT met", r.cpu,
                  plan.choice.predicted_seconds, r.cpu / plan.choice.predicted_seconds, r.wall,
                  (out / "plan.json").string().c_str());
      return r.rc;
    } catch (const pl::PlanError& e) {
      std::fprintf(stderr, "polymech plan: error: %s\n", e.what());
      return 2;
    }
  });
}

}  // namespace polymech::apps
