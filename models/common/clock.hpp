// The clock of a model stepped at a fixed dt (DEM, ISPH, MPS, NOSB PD, rigid bodies): the step index n and
// the time t = n dt, computed from n and never accumulated, so a run restarted at step n continues with the
// same bits of t as the run that was not interrupted. Checkpointed as "<prefix>step".
//
// The EFG model keeps its own time, accumulated (t += dt) and saved in its checkpoints as such: on this
// clock its time series would change in the last bits (n dt is not the sum of n dt's).
#pragma once

#include <cstdint>
#include <string>

namespace polymech::models {

class StepClock {
 public:
  std::int64_t index() const { return n_; }
  void set_index(std::int64_t n) { n_ = n; }
  void tick() { ++n_; }
  double time(double dt) const { return static_cast<double>(n_) * dt; }

  template <class Archive>
  void save(Archive& a, const std::string& prefix) const {
    a.put(prefix + "step", n_);
  }
  template <class Archive>
  void restore(const Archive& a, const std::string& prefix) {
    n_ = a.template get<std::int64_t>(prefix + "step");
  }

 private:
  std::int64_t n_ = 0;
};

}  // namespace polymech::models
