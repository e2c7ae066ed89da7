// Checkpoint and restart for the time-stepping apps, through the shared run driver
// (models/common/run.hpp): every --checkpoint-every seconds of wall time (or --checkpoint-steps steps)
// the run's complete state goes to <out>/checkpoints/checkpoint_<step>.bin, atomically, the last two
// kept; `--restart <out>` continues the run that wrote them, into the same folder, and its results
// (fields.h5 + XDMF, CSV series, summary.json) are those of a run never interrupted. A finished run
// removes its checkpoints.
//
// A checkpoint is resumed only by the app, scene file (its bytes) and options that wrote it; anything
// else is refused with exit code 2 naming what differs.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

#include "apps/common/app.hpp"
#include "common/run.hpp"
#include "io/checkpoint.hpp"

namespace polymech::apps {

struct RestartOptions {
  std::filesystem::path restart;     // the output folder of the run to continue ("" = a new run)
  double checkpoint_every = 600.0;   // wall seconds between checkpoints (0: none by time)
  std::int64_t checkpoint_steps = 0; // also every n steps (0: none by steps)
  bool keep_checkpoints = false;     // keep them after the run has finished
  bool overwrite = false;            // start over where an interrupted run of the same case left checkpoints
};

inline void add_restart_options(CLI::App& app, RestartOptions& r) {
  app.add_option("--restart", r.restart,
                 "continue the run whose output folder is DIR from its newest checkpoint (same scene and options)");
  within(app.add_option("--checkpoint-every", r.checkpoint_every, "wall seconds between checkpoints (0: none)")
             ->capture_default_str(),
         0.0, 1e7);
  non_negative<std::int64_t>(app.add_option("--checkpoint-steps", r.checkpoint_steps, "also checkpoint every N steps (0: none)"));
  app.add_flag("--keep-checkpoints", r.keep_checkpoints, "keep the checkpoints after the run has finished");
  app.add_flag("--overwrite", r.overwrite,
               "start over in an output folder that holds the checkpoints of this same run, interrupted (they are deleted)");
}

namespace detail {
inline std::string file_digest(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::uint64_t h = 1469598103934665603ull;
  char buf[4096];
  while (in.read(buf, sizeof buf) || in.gcount() > 0)
    for (std::streamsize i = 0; i < in.gcount(); ++i) h = (h ^ static_cast<unsigned char>(buf[i])) * 1099511628211ull;
  char b[20];
  std::snprintf(b, sizeof b, "%016llx", static_cast<unsigned long long>(h));
  return b;
}
}  // namespace detail

// What a checkpoint must match to be resumed: the app, the scene file's bytes, the accuracy and
// precision, the step count, the subnormal mode (flushed or kept: results agree to round-off, not
// bitwise) and any app option that changes the run (`extra`). Not the thread count: results do not
// depend on it.
inline std::string run_key(const std::string& app, const io::SceneHeader& h, std::int64_t steps, const std::string& extra = "") {
  return "app=" + app + "; scene=" + h.file.string() + " (" + detail::file_digest(h.file) + "); accuracy=" + h.accuracy +
         "; precision=" + h.precision + "; steps=" + std::to_string(steps) + "; subnormals=" + kx::to_string(kx::thread_subnormals()) + (extra.empty() ? "" : "; " + extra);
}

// POLYMECH_SUBNORMAL_CENSUS: steps between censuses of the state's subnormal values (unset: none).
inline std::int64_t census_steps_from_environment() {
  const char* v = std::getenv("POLYMECH_SUBNORMAL_CENSUS");
  if (v == nullptr || *v == '\0') return 0;
  char* end = nullptr;
  const long long n = std::strtoll(v, &end, 10);
  if (*end != '\0' || n <= 0)
    throw std::invalid_argument(std::string("POLYMECH_SUBNORMAL_CENSUS = '") + v +
                                "': give the number of steps between censuses (a positive integer)");
  return n;
}

class Checkpoints {
 public:
  // Before the run: with --restart, reads the newest whole checkpoint of that folder (the output
  // folder is then that folder) and checks that it belongs to this run.
  Checkpoints(CommonOptions& o, const RestartOptions& r, const std::string& key)
      : options_(r), key_(key), store_(resolve(o, r) / "checkpoints") {
    if (r.restart.empty()) {
      // A new run in a folder that holds an interrupted run's checkpoints: of this same run (app, scene
      // bytes, options), re-typing the command without --restart would throw its work away, so it is
      // refused unless --overwrite; of another run, they are stale.
      if (const auto previous = store_.latest()) {
        if (!r.overwrite && previous->archive.get_string("run/key") == key_)
          throw std::invalid_argument(o.out.string() + " holds the checkpoint of this same run, interrupted at step " +
                                      std::to_string(previous->step) + " (" + previous->file.string() +
                                      "): continue it with --restart " + o.out.string() + ", or start over with --overwrite");
      }
      store_.clear();
      return;
    }
    from_ = store_.latest();
    if (!from_)
      throw std::invalid_argument(r.restart.string() + ": no checkpoint to restart from (expected " +
                                  store_.dir().string() + "/checkpoint_<step>.bin; was the run started with checkpoints?)");
    const std::string written = from_->archive.get_string("run/key");
    if (written != key_)
      throw std::invalid_argument(from_->file.string() + ": written by another run;\n  checkpoint: " + written +
                                  "\n  this run:   " + key_ + "\n  restart with the scene and options of the interrupted run");
  }

  const models::Archive* resume() const { return from_ ? &from_->archive : nullptr; }
  std::int64_t resume_step() const { return from_ ? from_->step : 0; }

  // Checkpoints during the run: `add` puts the app's own records (its snapshot writer) into each.
  // Also the run's diagnostics from the environment: POLYMECH_SUBNORMAL_CENSUS=N counts the state's
  // subnormal values every N steps (summary.json "subnormal_census"; docs/DEVELOPING.md).
  void attach(models::RunHooks& hooks, std::function<void(models::Archive&)> add, bool quiet) {
    hooks.census_every = census_steps_from_environment();
    hooks.resume = resume();
    hooks.checkpoint.every_seconds = options_.checkpoint_every;
    hooks.checkpoint.every_steps = options_.checkpoint_steps;
    hooks.checkpoint.write = [this, add = std::move(add), quiet](std::int64_t step, models::Archive& a) {
      a.put_string("run/key", key_);
      if (add) add(a);
      const auto f = store_.write(step, a);
      if (!quiet) std::fprintf(stderr, "  checkpoint at step %lld: %s\n", static_cast<long long>(step), f.c_str());
    };
    if (from_ && !quiet)
      std::fprintf(stderr, "  restarting from %s (step %lld)\n", from_->file.c_str(), static_cast<long long>(from_->step));
  }

  // After every result is written: the checkpoints are no longer needed.
  void finished() const {
    if (options_.keep_checkpoints) return;
    store_.clear();
    std::error_code ec;
    std::filesystem::remove(store_.dir(), ec);  // only when empty
  }

 private:
  static std::filesystem::path resolve(CommonOptions& o, const RestartOptions& r) {
    if (!r.restart.empty()) {
      if (!std::filesystem::is_directory(r.restart))
        throw std::invalid_argument(r.restart.string() + ": --restart needs the output folder of an interrupted run");
      o.out = r.restart;
    }
    return o.out;
  }
  RestartOptions options_;
  std::string key_;
  io::CheckpointStore store_;
  std::optional<io::Checkpoint> from_;
};

// With POLYMECH_SUBNORMAL_CENSUS: the largest share of subnormal values each View of the state held, and
// when, under `key`.
inline void put_subnormal_census(nlohmann::json& j, const models::RunStats& s, const std::string& key = "subnormal_census") {
  if (s.subnormals.empty()) return;
  nlohmann::json c = nlohmann::json::object();
  for (const auto& p : s.subnormals) c[p.name] = {{"largest_share", p.share}, {"at_step", p.step}};
  j[key] = c;
}

// What summary.json says about how the run went: diverged (with the reason, the step, the first bad
// particle or DoF and where it is, and the step of the last good state, the last snapshot), and how
// often it was resumed from a checkpoint.
inline void put_run_record(nlohmann::json& j, const models::RunStats& s) {
  j["diverged"] = s.diverged;
  if (s.diverged) {
    j["diverged_reason"] = s.reason;
    j["diverged_step"] = s.bad_step;
    j["last_good_step"] = s.last_good_step;
    if (s.health.first_bad >= 0) {
      j["first_bad"] = {{"what", s.health.what}, {"index", s.health.first_bad}, {"problem", s.health.problem}};
      j["first_bad"]["position"] = {s.health.position[0], s.health.position[1], s.health.position[2]};
    }
  }
  j["restarts"] = s.restarts;
  put_subnormal_census(j, s);
}

}  // namespace polymech::apps
