// Checkpoints and --restart for the time loops of apps/turek_hron (CFD3, FSI2, FSI3), which run their own loop
// (a step that fails ends the run with its reason; the rows, CSV and progress are the loop's) rather than the
// shared driver's models::run: the same store, key, options and files (apps/common/restart.hpp through
// apps::Case), the same records ("driver/step", "driver/restarts", "driver/wall_seconds"), written after a step
// every --checkpoint-every wall seconds or --checkpoint-steps steps, never after the last one.
//
//   LoopCheckpoints ck(cs);                  // after cs.records.keep(...) of the loop's values
//   if (ck.resume()) model.load(*ck.resume(), "model/");  // the records are loaded here
//   for (k = ck.first_step() + 1; k <= steps; ++k) { ...; ck.after_step(k, steps, [&](auto& a) { model.save(a, "model/"); }); }
#pragma once

#include <chrono>
#include <cstdint>
#include <ctime>
#include <functional>

#include "apps/common/case.hpp"

namespace polymech::apps {

class LoopCheckpoints {
 public:
  explicit LoopCheckpoints(Case& cs) : cs_(cs), t0_(std::chrono::steady_clock::now()), c0_(std::clock()) {
    cs_.attach(hooks_, [this](models::Archive& a) { cs_.records.save(a); });
    if (const models::Archive* r = hooks_.resume) {
      cs_.records.load(*r);
      restarts_ = r->get<std::int64_t>("driver/restarts") + 1;
      earlier_wall_ = r->get<double>("driver/wall_seconds");
      earlier_cpu_ = r->get<double>("driver/cpu_seconds");
    }
  }

  const models::Archive* resume() const { return hooks_.resume; }
  std::int64_t first_step() const { return cs_.resume_step(); }  // the steps done before this process
  std::int64_t restarts() const { return restarts_; }
  // Wall and CPU seconds of the whole run, the interrupted processes' included.
  double wall_seconds() const { return earlier_wall_ + std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }
  double cpu_seconds() const { return earlier_cpu_ + static_cast<double>(std::clock() - c0_) / CLOCKS_PER_SEC; }

  // After step k of `end`: a checkpoint when one is due (the model's state by `save`, the case's records).
  void after_step(std::int64_t k, std::int64_t end, const std::function<void(models::Archive&)>& save) {
    const auto& ck = hooks_.checkpoint;
    if (!ck.write || k >= end) return;
    const double now = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (!((ck.every_steps > 0 && k % ck.every_steps == 0) || (ck.every_seconds > 0 && now - last_ >= ck.every_seconds))) return;
    models::Archive a;
    a.put("driver/step", k);
    a.put("driver/restarts", restarts_);
    a.put("driver/wall_seconds", wall_seconds());
    a.put("driver/cpu_seconds", cpu_seconds());
    save(a);
    ck.write(k, a);
    last_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
  }

 private:
  Case& cs_;
  models::RunHooks hooks_;
  std::chrono::steady_clock::time_point t0_;
  std::clock_t c0_;
  std::int64_t restarts_ = 0;
  double earlier_wall_ = 0.0, earlier_cpu_ = 0.0, last_ = 0.0;
};

}  // namespace polymech::apps
