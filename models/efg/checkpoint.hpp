// Efg<T>, part: the checkpoint of a dynamic run (models::run's protocol): the nodal coefficients of u, v,
// a, the time, the step and the crack (half-)length and tip speed, and the ties of a gradual release; the
// matrices are rebuilt from the configuration and that crack, the factorisation from dt on load.
// Included by efg/efg.hpp.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "efg/efg.hpp"

namespace polymech::efg {

template <class T>
inline void Efg<T>::save(models::Archive& ar, const std::string& prefix) const {
  auto vec = [](const Eigen::VectorXd& x) { return std::vector<double>(x.data(), x.data() + x.size()); };
  ar.put_vector(prefix + "u", vec(ud_));
  ar.put_vector(prefix + "v", vec(vd_));
  ar.put_vector(prefix + "a", vec(ad_));
  ar.put(prefix + "time", time_);
  ar.put(prefix + "dt", dt_);
  ar.put(prefix + "step", step_);
  ar.put(prefix + "crack_length", config_.crack_length);
  ar.put(prefix + "tip_speed", speed_);
  if (!ties_.empty()) {  // gradual release: each tie's state and released force
    std::vector<double> t;
    for (const auto& x : ties_) t.insert(t.end(), {static_cast<double>(x.state), x.f0[0], x.f0[1]});
    ar.put_vector(prefix + "ties", t);
  }
}

// Restarts from a checkpoint: start_dynamic(dt) at the configured crack, then the crack moved to the saved
// length (splitting the path nodes it passed), the coefficients, the ties and the clock as saved.
template <class T>
inline void Efg<T>::load(const models::Archive& ar, const std::string& prefix) {
  const double dt = ar.get<double>(prefix + "dt");
  start_dynamic(dt);
  const double a = ar.get<double>(prefix + "crack_length"), speed = ar.get<double>(prefix + "tip_speed");
  if (a != config_.crack_length) set_crack_length(a, speed);
  speed_ = speed;
  auto vec = [&](const std::string& k, Eigen::VectorXd& x) {
    const auto v = ar.get_vector<double>(prefix + k);
    if (v.size() != static_cast<std::size_t>(x.size())) throw std::runtime_error("EFG checkpoint: '" + prefix + k + "' has the wrong size");
    for (std::size_t i = 0; i < v.size(); ++i) x(static_cast<Eigen::Index>(i)) = v[i];
  };
  vec("u", ud_);
  vec("v", vd_);
  vec("a", ad_);
  if (!ties_.empty()) {  // the ties as they were (set_crack_length above made them fresh): reassemble
    const auto t = ar.get_vector<double>(prefix + "ties");
    if (t.size() != 3 * ties_.size()) throw std::runtime_error("EFG checkpoint: '" + prefix + "ties' has the wrong size");
    for (std::size_t k = 0; k < ties_.size(); ++k) {
      ties_[k].state = static_cast<typename Tie::State>(static_cast<int>(t[3 * k]));
      ties_[k].f0[0] = t[3 * k + 1];
      ties_[k].f0[1] = t[3 * k + 2];
    }
    restore_ties_ = true;
    assemble();
    restore_ties_ = false;
    factor_effective_stiffness();
  }
  time_ = ar.get<double>(prefix + "time");
  step_ = ar.get<std::int64_t>(prefix + "step");
  sync_dynamic();
}

}  // namespace polymech::efg
