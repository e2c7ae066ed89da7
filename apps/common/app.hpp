// What every app shares: the common command-line options, Kokkos set-up, and turning errors into
// one clear message and a non-zero exit code (2: bad input, 1: a failure while running).
#pragma once

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/cli.hpp"
#include "core/kokkos_shim.hpp"
#include "core/types.hpp"
#include "io/cost.hpp"
#include "io/output.hpp"
#include "io/scene.hpp"

namespace polymech::apps {

struct CommonOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::string accuracy;   // "" = the scene's default
  std::string precision;  // "" = the scene's default
  std::int64_t steps = -1;
  int threads = -1;
  bool quiet = false;
  bool dry_run = false;
  std::string subnormals;  // "flush" | "keep"; "" = POLYMECH_SUBNORMALS, else flush (core/float_env.hpp)
};

inline constexpr std::int64_t max_steps = 1000000000000;  // --steps at most (1e12)

// --scene, --out, --accuracy, --precision, --steps, --threads, --quiet, --dry-run, --subnormals.
inline void add_common_options(CLI::App& app, CommonOptions& o, const std::string& default_scene,
                               const std::string& default_out) {
  o.scene = default_scene;
  o.out = default_out;
  app.add_option("--scene", o.scene, "scene file (TOML)")->capture_default_str();
  app.add_option("--out", o.out, "output folder (created if missing)")->capture_default_str();
  one_of(app.add_option("--accuracy", o.accuracy, "accuracy preset (default: the scene's [accuracy].default)"),
         {"draft", "standard", "paper"});
  one_of(app.add_option("--precision", o.precision, "floating-point precision of the kernels (default: the scene's)"),
         {"double", "float"});
  within<std::int64_t>(app.add_option("--steps", o.steps, "number of time steps (default: the scene's, scaled to the accuracy)"),
                       1, max_steps);
  within(app.add_option("--threads", o.threads, "OpenMP threads (default: OMP_NUM_THREADS or all cores)"), 1, max_threads,
         "this machine has " + std::to_string(machine_cores()) + (machine_cores() == 1 ? " core" : " cores"));
  app.add_flag("--quiet", o.quiet, "no progress lines");
  app.add_flag("--dry-run", o.dry_run, "check the scene, print the run's size, memory and predicted time, and stop");
  one_of(app.add_option("--subnormals", o.subnormals,
                        "subnormal numbers in the host threads: flushed to zero (default; POLYMECH_SUBNORMALS sets it too) "
                        "or kept; results do not depend on it, speed does (docs/METHODS.md)"),
         {"flush", "keep"});
}

// A common option that means nothing to this app (its run length is not a step count, its scenes have no
// accuracy presets): hidden from --help, and refused with the reason, exit 2, after the value's own checks
// ("--steps 5: does not apply: ..."), never accepted and ignored (issue 33 item 8).
inline void refuse_option(CLI::App& app, const std::string& name, const std::string& why) {
  CLI::Option* o = app.get_option(name);
  o->group("");
  o->check(CLI::Validator([name, why](std::string& v) { return name + " " + cli::shown(v) + ": does not apply: " + why; }, ""));
}

// The estimate of a scene whose loader counted `scene_steps` steps, for a run of --steps instead (when
// given): time and steps scale with the step count (the set-up of these methods is small beside it).
inline io::CostEstimate with_steps(io::CostEstimate c, std::int64_t scene_steps, std::int64_t steps) {
  if (steps > 0 && scene_steps > 0 && steps != scene_steps) {
    const double f = static_cast<double>(steps) / static_cast<double>(scene_steps);
    c.seconds *= f;
    c.steps *= f;
  }
  return c;
}

// Prints the cost estimate of the loaded scene before a run (stderr, unless --quiet), or for --dry-run
// on stdout; true when the app should stop here (--dry-run: nothing has been allocated for the run).
inline bool announce_cost(const char* name, const io::SceneHeader& scene, const io::CostEstimate& cost,
                          const CommonOptions& o) {
  // The rate was measured with cost.rate_threads threads; this run has its own (perfect scaling assumed,
  // at most the machine's cores: more threads than cores do not run faster; issue 33 item 8).
  io::CostEstimate mine = cost;
  const long long threads =
      o.threads > 0 ? o.threads : cli::integer_from(std::getenv("OMP_NUM_THREADS")).value_or(machine_cores());
  const int used = static_cast<int>(std::max(1LL, std::min<long long>(threads, machine_cores())));
  if (used != cost.rate_threads) {
    mine.seconds = cost.seconds * cost.rate_threads / used;
    mine.rate += "; scaled to " + std::to_string(used) + (used == 1 ? " thread" : " threads");
  }
  const std::string text = "[" + std::string(name) + "] " + scene.file.string() + " at accuracy '" + scene.accuracy +
                           "', " + scene.precision + " precision\n" + io::describe(mine);
  if (o.dry_run) {
    std::printf("%sdry run: scene checked, nothing run\n", text.c_str());
    return true;
  }
  if (!o.quiet) std::fprintf(stderr, "%s", text.c_str());
  return false;
}

// The keys every summary.json starts with: the case, its scene file and title, what it ran with, and the
// build (version, commit).
inline nlohmann::json summary_header(const std::string& name, const io::SceneHeader& scene) {
  nlohmann::json j;
  j["case"] = name;
  j["scene"] = scene.file.string();
  j["title"] = scene.title;
  j["accuracy"] = scene.accuracy;
  j["precision"] = scene.precision;
  j["effects"] = std::vector<std::string>(scene.effects.names().begin(), scene.effects.names().end());
  j["subnormals"] = kx::to_string(kx::thread_subnormals());  // as this thread runs (every host thread alike)
  j["version"] = version();  // the build: project() version and git commit (cli.hpp)
  j["commit"] = commit();
  j["command"] = invocation();
  j["threads"] = kx::concurrency<ExecSpace>();  // per MPI rank where there are ranks
  return j;
}

// [[x, y], ...]: a summary's list of pairs (built by hand: GCC 12 sees a null dereference in nlohmann's
// conversion of std::array), from pairs or from two columns of one length.
inline nlohmann::json json_pairs(const std::vector<std::array<double, 2>>& v) {
  auto a = nlohmann::json::array();
  for (const auto& p : v) a.push_back({p[0], p[1]});
  return a;
}
inline nlohmann::json json_pairs(const std::vector<double>& x, const std::vector<double>& y) {
  auto a = nlohmann::json::array();
  for (std::size_t k = 0; k < x.size() && k < y.size(); ++k) a.push_back({x[k], y[k]});
  return a;
}

// "1 thread", "2 threads": the thread count of this run, for the apps' first lines (issue 33 item 10).
inline std::string thread_count() {
  const int n = kx::concurrency<ExecSpace>();
  return std::to_string(n) + (n == 1 ? " thread" : " threads");
}

// The thread count Kokkos starts with: --threads, else OMP_NUM_THREADS (checked by parse_command_line),
// else all cores but at most max_threads (more overrun Kokkos' OpenMP thread table, cli.hpp).
inline int session_threads(int threads) {
  if (threads > 0) return threads;
  const auto env = cli::integer_from(std::getenv("OMP_NUM_THREADS"));
  if ((!env || *env < 1) && machine_cores() > max_threads) return max_threads;
  return -1;
}

// Kokkos 3.4 warns on every start when OMP_PROC_BIND is unset (issue 33 item 10). The OpenMP runtime read
// its environment when it was loaded, before main, so setting it here changes nothing but the warning:
// the threads stay unbound, as they were (right on a shared machine; on one's own, OMP_PROC_BIND=spread
// OMP_PLACES=threads binds them).
inline void quiet_proc_bind_warning() {
  if (!std::getenv("OMP_PROC_BIND")) setenv("OMP_PROC_BIND", "false", 0);
}

// Kokkos for the lifetime of an app, with its threads and subnormal mode (--threads, --subnormals).
class KokkosSession {
 public:
  explicit KokkosSession(int threads) {
    quiet_proc_bind_warning();
    kx::initialize(session_threads(threads));
  }
  explicit KokkosSession(const CommonOptions& o) {
    quiet_proc_bind_warning();
    kx::initialize(session_threads(o.threads), o.subnormals.empty() ? kx::subnormals_from_environment()
                                                   : kx::parse_subnormals(o.subnormals, "--subnormals"));
  }
  ~KokkosSession() { Kokkos::finalize(); }
  KokkosSession(const KokkosSession&) = delete;
  KokkosSession& operator=(const KokkosSession&) = delete;
};

// Runs body(); scene and input errors print "error: <message>" and return 2, other failures 1.
template <class Body>
int guarded(const char* name, Body&& body) {
  try {
    return body();
  } catch (const io::SceneError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name, e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: error: %s\n", name, e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: failed: %s\n", name, e.what());
    return 1;
  }
}

}  // namespace polymech::apps
