// One case runner for every time-stepping app: an app is its scene, its model, its analysis and its
// summary keys; the run plumbing is here, once:
//   - the output folder, checkpoints and --restart (apps/common/restart.hpp): the app's series, sums and
//     snapshot writer go into every checkpoint and come back on a restart (Records, series.hpp);
//   - progress lines on stderr (unless --quiet);
//   - field snapshots, none written twice for one step (the watchdog hands back the last good state,
//     which may be the step just written);
//   - the end: summary.json with the header every app writes, the run record (diverged, where and why,
//     restarts), the checkpoints removed, and the exit code (1: diverged). The app closes the snapshot
//     writer (snapshots().finish(): the XDMF file's name for its list of files) before.
//
//   apps::Case cs(apps::CaseSpec{"isph", scene.header, steps, dt}, opt, ropt);
//   Model model(config);
//   cs.snapshots(mesh).every(n, [&](auto step) { return fields; });
//   cs.records.keep("isph/series", series);
//   cs.hooks.sample = ...;
//   const auto stats = cs.run([&](auto& hooks, auto steps) { return models::run(model, steps, hooks); });
//   auto j = cs.summary();  ...  return cs.finish(j, stats, {"summary.json", "series.csv", ...});
#pragma once

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "apps/common/app.hpp"
#include "apps/common/restart.hpp"
#include "apps/common/series.hpp"
#include "io/output.hpp"
#include "io/progress.hpp"

namespace polymech::apps {

struct CaseSpec {
  CaseSpec(std::string app_, io::SceneHeader scene_, std::int64_t steps_, double dt_ = 0.0, std::string key_extra_ = "")
      : app(std::move(app_)), scene(std::move(scene_)), steps(steps_), dt(dt_), key_extra(std::move(key_extra_)) {}
  std::string app;            // the app's name: summary "case", checkpoint key, messages
  io::SceneHeader scene;      // the loaded scene
  std::int64_t steps = 0;     // the run's length (after --steps)
  double dt = 0.0;            // for the progress lines' simulated time (0: steps only)
  std::string key_extra;      // app options that change the run (checkpoint key: run_key)
  bool progress = true;       // progress lines (also off with --quiet)
  bool checkpoints = true;    // false: a run with no checkpoints (--restart refused)
};

// A mesh of points (particles, nodes): n x dim coordinates.
inline io::SnapshotMesh point_mesh(int dim, std::vector<double> points) {
  io::SnapshotMesh m;
  m.dim = dim;
  m.points = std::move(points);
  return m;
}

// The snapshot writer of a case and what it writes at a step.
class CaseSnapshots {
 public:
  using Fields = std::vector<io::SnapshotField>;
  CaseSnapshots(const std::filesystem::path& out, const std::string& stem, io::SnapshotMesh mesh, bool double_precision)
      : writer_(out, stem, std::move(mesh), double_precision) {}
  // Every n steps (and at step 0, at a stop, and the last good state of a diverged run), `fields(step)`
  // gives the fields and `time(step)` the time.
  CaseSnapshots& every(std::int64_t n, std::function<Fields(std::int64_t)> fields, std::function<double(std::int64_t)> time) {
    every_ = n;
    fields_ = std::move(fields);
    time_ = std::move(time);
    return *this;
  }
  // One snapshot now (an app that writes its fields itself, at the end).
  void add(std::int64_t step, double time, const Fields& f) { writer_.add(step, time, f); }
  // Called by the run driver; a step already written is not written again.
  void at(std::int64_t step) {
    if (step == last_) return;
    last_ = step;
    writer_.add(step, time_(step), fields_(step));
  }
  std::int64_t interval() const { return fields_ ? every_ : 0; }
  bool finished() const { return !xdmf_.empty(); }
  // Closes the writer: the XDMF file (ParaView opens it), the HDF5 file beside it. A writer never
  // finished leaves no file (an app that did not list them).
  const std::filesystem::path& finish() {
    if (xdmf_.empty()) xdmf_ = writer_.finish();
    return xdmf_;
  }
  io::SnapshotWriter& writer() { return writer_; }

 private:
  io::SnapshotWriter writer_;
  std::int64_t every_ = 0, last_ = -1;
  std::function<Fields(std::int64_t)> fields_;
  std::function<double(std::int64_t)> time_;
  std::filesystem::path xdmf_;
};

class Case {
 public:
  // Before the model is built: with --restart, reads the checkpoint to resume and checks it belongs to
  // this run (the output folder is then the restarted run's); makes the output folder.
  Case(CaseSpec spec, CommonOptions opt, const RestartOptions& restart) : spec_(std::move(spec)), opt_(std::move(opt)) {
    if (spec_.checkpoints)
      checkpoints_.emplace(opt_, restart, run_key(spec_.app, spec_.scene, spec_.steps, spec_.key_extra));
    else if (!restart.restart.empty())
      throw std::invalid_argument("--restart: this " + spec_.app + " run has no checkpoints; run it again");
    io::make_output_dir(opt_.out);
    if (restart.restart.empty()) remove_earlier_results();
  }

  const std::filesystem::path& out() const { return opt_.out; }
  const CommonOptions& options() const { return opt_; }
  bool quiet() const { return opt_.quiet; }
  std::int64_t steps() const { return spec_.steps; }
  const std::string& app() const { return spec_.app; }
  // The checkpoint the run resumes from (nullptr: a new run) and its step.
  const models::Archive* resume() const { return checkpoints_ ? checkpoints_->resume() : nullptr; }
  std::int64_t resume_step() const { return checkpoints_ ? checkpoints_->resume_step() : 0; }

  // The run's hooks: the app sets sampling, stop conditions and the watchdog; the case adds progress,
  // snapshots and checkpoints when it runs.
  models::RunHooks hooks;
  // The app's values under way (series, sums): into every checkpoint, back on a restart.
  Records records;
  // Called after every step, after the progress line (e.g. a scheduled event of the scene).
  std::function<void(std::int64_t)> after_step;

  // The field snapshots of the run, `<out>/<stem>.h5` + `.xdmf`; in every checkpoint.
  CaseSnapshots& snapshots(io::SnapshotMesh mesh, const std::string& stem = "fields", bool double_precision = false) {
    snapshots_ = std::make_unique<CaseSnapshots>(opt_.out, stem, std::move(mesh), double_precision);
    records.add([s = snapshots_.get()](models::Archive& a) { s->writer().save(a); },
                [s = snapshots_.get()](const models::Archive& a) { s->writer().resume(a); });
    return *snapshots_;
  }
  CaseSnapshots& snapshots() { return *snapshots_; }

  // Runs the model: `run(hooks, steps)` runs `steps` steps (those left after a restart) and returns its
  // RunStats (models::run, or a model's own run wrapper). Hooks, checkpoints, resume and progress are
  // set here.
  template <class Run>
  auto run(Run&& run) {
    std::optional<io::Progress> progress;
    if (spec_.progress) progress.emplace(spec_.app, spec_.steps, spec_.dt, !opt_.quiet);
    hooks.after_step = [&progress, after = after_step](std::int64_t k) {
      if (progress) progress->update(k);
      if (after) after(k);
    };
    if (snapshots_ && snapshots_->interval() > 0) {
      hooks.snapshot_every = snapshots_->interval();
      hooks.snapshot = [s = snapshots_.get()](std::int64_t k) { s->at(k); };
    }
    if (checkpoints_) {
      checkpoints_->attach(hooks, [this](models::Archive& a) { records.save(a); }, opt_.quiet);
      if (hooks.resume) {
        records.load(*hooks.resume);
        hooks.sample_at_start = false;
        if (progress) progress->resume_at(resume_step());
      }
    }
    auto stats = run(hooks, spec_.steps - resume_step());
    if (progress) progress->done(stats.steps);
    hooks.after_step = nullptr;  // it refers to this function's progress
    return stats;
  }

  // A case of several runs (mps_harmonics: without and with the crack) attaches each run's hooks to the
  // checkpoints itself; `add` puts its records into each checkpoint.
  void attach(models::RunHooks& h, std::function<void(models::Archive&)> add) {
    if (checkpoints_) checkpoints_->attach(h, std::move(add), opt_.quiet);
  }

  // The keys every summary.json starts with (app.hpp: summary_header).
  nlohmann::json summary() const { return summary_header(spec_.app, spec_.scene); }

  // The end of every run: the run record into `j`, summary.json written with `files`, the snapshots
  // closed, the checkpoints removed; a diverged run says so on stderr. The exit code: 1 when diverged.
  int finish(nlohmann::json& j, const models::RunStats& s, const std::vector<std::string>& files) {
    put_run_record(j, s);
    j["files"] = files;
    io::write_json(opt_.out / "summary.json", j);
    if (checkpoints_) checkpoints_->finished();
    if (!s.diverged) return 0;
    std::fprintf(stderr, "%s: the run diverged at step %lld: %s", spec_.app.c_str(), static_cast<long long>(s.bad_step),
                 s.reason.c_str());
    if (s.last_good_step >= 0 && snapshots_ && snapshots_->finished())
      std::fprintf(stderr, "; the last good state (step %lld) is the last snapshot in %s", static_cast<long long>(s.last_good_step),
                   snapshots_->finish().c_str());
    std::fprintf(stderr, "\n");
    return 1;
  }
  // A run with no run record (one solve).
  int finish(nlohmann::json& j, const std::vector<std::string>& files) {
    j["files"] = files;
    io::write_json(opt_.out / "summary.json", j);
    if (checkpoints_) checkpoints_->finished();
    return 0;
  }

 private:
  // A new run into a folder that holds an earlier run's results: the files its summary.json listed (and
  // the summary) and unfinished HDF5 files (*.part, left by a killed run) go, so no stale file of
  // another case is read as this run's (plots read every CSV they find). Nothing else is touched.
  void remove_earlier_results() const {
    namespace fs = std::filesystem;
    std::vector<fs::path> stale;
    const fs::path summary = opt_.out / "summary.json";
    try {
      if (fs::exists(summary)) {
        std::ifstream in(summary);
        const auto j = nlohmann::json::parse(in);
        if (j.contains("files") && j["files"].is_array())
          for (const auto& f : j["files"])
            if (f.is_string()) {
              const fs::path name = f.get<std::string>();
              if (name.has_filename() && name == name.filename() && name != "." && name != "..") stale.push_back(opt_.out / name);
            }
        stale.push_back(summary);
      }
    } catch (const std::exception&) {
      // a damaged summary.json: the new run writes its own over it
    }
    for (const auto& e : fs::directory_iterator(opt_.out))
      if (e.is_regular_file() && e.path().extension() == ".part") stale.push_back(e.path());
    int removed = 0;
    for (const auto& f : stale) {
      std::error_code ec;
      if (fs::is_regular_file(f) && fs::remove(f, ec)) ++removed;
    }
    if (removed > 0 && !opt_.quiet)
      std::fprintf(stderr, "  removed %d file%s of an earlier run in %s\n", removed, removed == 1 ? "" : "s", opt_.out.c_str());
  }

  CaseSpec spec_;
  CommonOptions opt_;
  std::optional<Checkpoints> checkpoints_;
  std::unique_ptr<CaseSnapshots> snapshots_;
};

// The precision (and dimension) a scene runs in, as template arguments of `body`:
//   with_precision(p, [&](auto t) { using T = decltype(t); ... });
//   with_precision_and_dimension(p, dim, [&](auto t, auto d) { using T = decltype(t); constexpr int D = d; ... });
template <class Body>
int with_precision(const std::string& precision, Body&& body) {
  return precision == "float" ? body(float{}) : body(double{});
}
template <class Body>
int with_precision_and_dimension(const std::string& precision, int dim, Body&& body) {
  using Two = std::integral_constant<int, 2>;
  using Three = std::integral_constant<int, 3>;
  if (precision == "float") return dim == 3 ? body(float{}, Three{}) : body(float{}, Two{});
  return dim == 3 ? body(double{}, Three{}) : body(double{}, Two{});
}

}  // namespace polymech::apps
