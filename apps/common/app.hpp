// What every app shares: the common command-line options, Kokkos set-up, and turning errors into
// one clear message and a non-zero exit code (2: bad input, 1: a failure while running).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "apps/common/cli.hpp"
#include "core/kokkos_shim.hpp"
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

// Prints the cost estimate of the loaded scene before a run (stderr, unless --quiet), or for --dry-run
// on stdout; true when the app should stop here (--dry-run: nothing has been allocated for the run).
inline bool announce_cost(const char* name, const io::SceneHeader& scene, const io::CostEstimate& cost,
                          const CommonOptions& o) {
  const std::string text = "[" + std::string(name) + "] " + scene.file.string() + " at accuracy '" + scene.accuracy +
                           "', " + scene.precision + " precision\n" + io::describe(cost);
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
  return j;
}

// The thread count Kokkos starts with: --threads, else OMP_NUM_THREADS (checked by parse_command_line),
// else all cores but at most max_threads (more overrun Kokkos' OpenMP thread table, cli.hpp).
inline int session_threads(int threads) {
  if (threads > 0) return threads;
  const auto env = cli::integer_from(std::getenv("OMP_NUM_THREADS"));
  if ((!env || *env < 1) && machine_cores() > max_threads) return max_threads;
  return -1;
}

// Kokkos for the lifetime of an app, with its threads and subnormal mode (--threads, --subnormals).
class KokkosSession {
 public:
  explicit KokkosSession(int threads) { kx::initialize(session_threads(threads)); }
  explicit KokkosSession(const CommonOptions& o) {
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
