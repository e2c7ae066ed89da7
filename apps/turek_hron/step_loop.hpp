// The time loop that apps/turek_hron's strongly coupled transient apps share: FSI2, FSI3 and the flap
// (apps/turek_hron/fsi_transient.cpp) and the flow-driven harvester (apps/turek_hron/harvester.cpp). Each app keeps
// its model, its row (what Model::step() returns), series.csv's columns, its report line and its own summary keys;
// the loop does the rest the same way for both:
//   - every step's row in `rows` (the statistics need them all) and the coupling evaluations (their sum and the
//     most in one step), into every checkpoint with the next report's time: the records PREFIX/rows,
//     PREFIX/evaluations, PREFIX/max_evaluations, the app's own (`more`), PREFIX/next_report;
//   - series.csv written as the run goes, every sample_every-th step, flushed every 20 steps (a restarted run
//     writes the rows of the steps before it again: the file is the same as an uninterrupted run's);
//   - a step that throws (the coupling stopped, or a fluid, solid or circuit solve inside it) or whose row is not
//     finite ends the run: `failed` and `reason` ("step K: ..."), summary.json's converged false and reason, and
//     exit code 1 (exit_code);
//   - io::Progress's lines, and a report line every report_every seconds of simulated time;
//   - checkpoints and --restart (apps/turek_hron/loop_checkpoints.hpp): the model's state under "model/";
//   - the summary keys both apps write (put_summary).
//
//   CoupledStepLoop<Row> loop(cs, "prefix", steps, s, 0.5, [&](Records& r) { r.keep("prefix/extra", extra); });
//   Model model(...);   // the checkpoint's records are loaded by now; run() loads the model's state
//   loop.run(model, opt.quiet, "t,a,b\n", write, invalid, account, report);
//   auto j = cs.summary(); loop.put_summary(j, model); ...; return loop.exit_code(cs.finish(j, {...}));
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "apps/common/case.hpp"
#include "apps/turek_hron/cases.hpp"
#include "apps/turek_hron/loop_checkpoints.hpp"
#include "common/host_copy.hpp"
#include "io/flow_scene.hpp"
#include "io/progress.hpp"

namespace polymech::apps {

// Mean = (max + min) / 2 and amplitude = (max - min) / 2 of a field over the rows with t >= t0, its frequency from
// the upward crossings of that mean (linear interpolation between rows; 0 with fewer than two crossings).
struct WindowStats {
  double mean = 0.0, amplitude = 0.0, frequency = 0.0;
};
template <class Row>
WindowStats window_stats(const std::vector<Row>& rows, double Row::*field, double t0) {
  WindowStats w;
  double lo = 1e300, hi = -1e300;
  for (const auto& r : rows)
    if (r.t >= t0) lo = std::min(lo, r.*field), hi = std::max(hi, r.*field);
  if (!(hi >= lo)) return w;
  w.mean = 0.5 * (hi + lo);
  w.amplitude = 0.5 * (hi - lo);
  double first = 0.0, last = 0.0;
  int up = 0;
  for (std::size_t k = 1; k < rows.size(); ++k) {
    const double a = rows[k - 1].*field, b = rows[k].*field;
    if (rows[k - 1].t >= t0 && a < w.mean && b >= w.mean) {
      const double t = rows[k - 1].t + (w.mean - a) / (b - a) * (rows[k].t - rows[k - 1].t);
      if (up == 0) first = t;
      last = t;
      ++up;
    }
  }
  if (up >= 2) w.frequency = static_cast<double>(up - 1) / (last - first);
  return w;
}

// NAME_mean, NAME_amplitude (and NAME_frequency) of WindowStats or flow::PeriodicStats.
template <class Stats>
void put_window(nlohmann::json& j, const std::string& name, const Stats& w, bool frequency = false) {
  j[name + "_mean"] = w.mean;
  j[name + "_amplitude"] = w.amplitude;
  if (frequency) j[name + "_frequency"] = w.frequency;
}

template <class Row>
class CoupledStepLoop {
 public:
  std::vector<Row> rows;    // every step's row, the run so far (a restarted run's from its checkpoint)
  long evaluations = 0;     // the coupling evaluations of the steps in rows
  int max_evaluations = 0;  // the most in one step
  bool failed = false;      // a step stopped the run: `reason` says which and why
  std::string reason;

  // Keeps the loop's records (and the app's, by `more`) in cs's checkpoints under `prefix`; with --restart they are
  // the checkpoint's when this returns.
  CoupledStepLoop(Case& cs, const std::string& prefix, std::int64_t steps, const io::FlowSetup& s, double report_every,
                  const std::function<void(Records&)>& more = {})
      : cs_(cs), s_(s), steps_(steps), report_every_(report_every), next_report_(report_every) {
    rows.reserve(static_cast<std::size_t>(steps));
    cs.records.add([this, prefix](models::Archive& a) { a.put_vector(prefix + "/rows", rows); },
                   [this, prefix](const models::Archive& a) { rows = a.get_vector<Row>(prefix + "/rows"); });
    cs.records.keep(prefix + "/evaluations", evaluations);
    cs.records.keep(prefix + "/max_evaluations", max_evaluations);
    if (more) more(cs.records);
    cs.records.keep(prefix + "/next_report", next_report_);
    ck_.emplace(cs);
  }
  CoupledStepLoop(const CoupledStepLoop&) = delete;  // the records point into this object
  CoupledStepLoop& operator=(const CoupledStepLoop&) = delete;

  // Steps `model` (Row step(); save and load of its state) from the checkpoint's step, or 0, to the end:
  //   header        series.csv's first line ("t,...\n");
  //   write(fp, r)  one row of series.csv;
  //   invalid(r)    nullptr, or what in r is not finite ("a non-finite force ..."): the run stops there;
  //   account(r)    the app's own sums over the steps;
  //   report(r)     the report line's start to stderr ("  t = ... s: ..."; the loop adds the evaluations and CPU).
  template <class Model, class Write, class Invalid, class Account, class Report>
  void run(Model& model, bool quiet, const char* header, const Write& write, const Invalid& invalid, const Account& account,
           const Report& report) {
    LoopCheckpoints& ck = *ck_;
    if (ck.resume()) model.load(*ck.resume(), "model/");
    const auto csv = cs_.out() / "series.csv";
    FILE* fp = std::fopen(csv.c_str(), "w");
    if (!fp) throw std::runtime_error("cannot write " + csv.string());
    std::fputs(header, fp);
    const auto write_row = [&](std::int64_t k, const Row& r) {
      if (k % s_.sample_every == 0) write(fp, r);
    };
    for (std::size_t i = 0; i < rows.size(); ++i) write_row(static_cast<std::int64_t>(i) + 1, rows[i]);
    io::Progress progress("turek_hron", steps_, s_.dt, !quiet, 10.0);
    progress.resume_at(ck.first_step());
    for (std::int64_t k = ck.first_step() + 1; k <= steps_; ++k) {
      Row r;
      try {
        r = model.step();
      } catch (const std::runtime_error& e) {  // the coupling stopped, or a solve inside it
        failed = true;
        reason = "step " + std::to_string(k) + ": " + e.what();
        break;
      }
      if (const char* what = invalid(r)) {
        failed = true;
        reason = "step " + std::to_string(k) + " (t = " + models::format_g(r.t) + " s): " + what;
        break;
      }
      rows.push_back(r);
      evaluations += r.evaluations;
      max_evaluations = std::max(max_evaluations, r.evaluations);
      account(r);
      write_row(k, r);
      if (k % 20 == 0) std::fflush(fp);
      progress.update(k);
      if (!quiet && r.t >= next_report_ - 1e-9) {
        report(r);
        const double cpu = ck.cpu_seconds();
        std::fprintf(stderr, "; %.2f evaluations per step; CPU %.0f s (%.3f s per step)\n",
                     static_cast<double>(evaluations) / static_cast<double>(k), cpu, cpu / static_cast<double>(k));
        next_report_ += report_every_;
      }
      ck.after_step(k, steps_, [&](models::Archive& a) { model.save(a, "model/"); });
    }
    std::fclose(fp);
    progress.done(done());
    cpu_ = ck.cpu_seconds();  // the interrupted processes' included
    wall_ = ck.wall_seconds();
  }

  std::int64_t done() const { return static_cast<std::int64_t>(rows.size()); }
  double end_time() const { return rows.empty() ? 0.0 : rows.back().t; }
  double evaluations_per_step() const { return done() > 0 ? static_cast<double>(evaluations) / static_cast<double>(done()) : 0.0; }
  double cpu_seconds() const { return cpu_; }  // the whole run's, after run()
  const LoopCheckpoints& checkpoints() const { return *ck_; }

  // The summary keys both apps write: the time step, the steps done, converged (and reason), the coupling's
  // settings and evaluations, the fluid's Newton iterations, CPU and wall seconds, the fluid's CPU split, restarts.
  template <class Model>
  void put_summary(nlohmann::json& j, const Model& model) const {
    const auto& t = model.timings();
    const std::int64_t n = done();
    const double per_step = evaluations_per_step();
    j["analysis"] = "transient";
    j["dt"] = s_.dt;
    j["dt_paper"] = s_.scene_dt;
    j["ramp_time"] = s_.ramp_time;
    j["steps"] = n;
    j["end_time"] = end_time();
    j["converged"] = !failed;
    if (failed) j["reason"] = reason;
    j["coupling"] = {{"method", s_.coupling_method}, {"tolerance", s_.coupling_tolerance}, {"scale", 1e-3},
                     {"max_iterations", s_.coupling_max_iterations}, {"evaluations", evaluations},
                     {"evaluations_per_step", per_step}, {"max_evaluations_per_step", max_evaluations}};
    j["coupling_evaluations"] = t.evaluations;  // every evaluation of G, a failed step's included
    j["coupling_evaluations_per_step"] = per_step;
    j["fluid_newton_iterations"] = t.fluid_newton;
    j["cpu_seconds"] = cpu_;
    j["cpu_seconds_per_step"] = n > 0 ? cpu_ / static_cast<double>(n) : 0.0;
    j["wall_seconds"] = wall_;
    j["fluid_split"] = flow_cpu_split(model.fluid().timings());  // this process's (a restarted run: since the restart)
    j["restarts"] = ck_->restarts();
  }

  // cs.finish's code, or 1 (the reason to stderr) when a step stopped the run.
  int exit_code(int rc) const {
    if (!failed) return rc;
    std::fprintf(stderr, "turek_hron: %s\n", reason.c_str());
    return 1;
  }

 private:
  Case& cs_;
  const io::FlowSetup& s_;
  std::int64_t steps_;
  double report_every_, next_report_;
  double cpu_ = 0.0, wall_ = 0.0;
  std::optional<LoopCheckpoints> ck_;
};

}  // namespace polymech::apps
