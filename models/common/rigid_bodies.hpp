// Rigid bodies as an explicit model (models/common/explicit_model.hpp), to be coupled with a particle
// model through an interaction that loads them: a projectile, a floating body, a clump. The bodies live
// in a host View (few bodies; DEM keeps many in a device View of the same type); their loads are
// cleared at each force evaluation and accumulated by the interaction.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "common/clock.hpp"
#include "common/explicit_model.hpp"
#include "common/run.hpp"
#include "rigid/rigid_body.hpp"

namespace polymech::models {

template <int D>
class RigidBodies {
 public:
  static constexpr int dimension = D;
  using Body = rigid::RigidBody<D>;
  using HostBodies = Kokkos::View<Body*, HostSpace>;

  RigidBodies(const std::vector<Body>& bodies, double dt) : bodies_("polymech::rigid::bodies", bodies.size()), dt_(dt) {
    for (std::size_t b = 0; b < bodies.size(); ++b) bodies_(b) = bodies[b];
    state_.add("rigid_bodies", bodies_);
  }

  std::size_t count() const { return bodies_.extent(0); }
  Body& body(std::size_t b) { return bodies_(b); }
  const Body& body(std::size_t b) const { return bodies_(b); }

  // The explicit-model phases: velocity Verlet on every body.
  void prepare() { prepared_ = true; }
  void mark_prepared() { prepared_ = true; }
  void advance_first_half() {
    for (std::size_t b = 0; b < count(); ++b) {
      bodies_(b).kick(0.5 * dt_);
      bodies_(b).drift(dt_);
    }
  }
  void compute_forces() {
    for (std::size_t b = 0; b < count(); ++b) bodies_(b).clear_loads();
  }
  void observe() {}
  void add_contact_forces() {}
  void advance_second_half() {
    for (std::size_t b = 0; b < count(); ++b) bodies_(b).kick(0.5 * dt_);
    clock_.tick();
  }
  void step() { explicit_step(*this); }

  double dt() const { return dt_; }
  double time() const { return clock_.time(dt_); }
  std::int64_t step_index() const { return clock_.index(); }
  void set_step_index(std::int64_t k) { clock_.set_index(k); }
  const StateRegistry& state() const { return state_; }
  void save(Archive& a, const std::string& prefix) const {
    state_.save(a, prefix + "state/");
    clock_.save(a, prefix);
  }
  void load(const Archive& a, const std::string& prefix) {
    state_.load(a, prefix + "state/");
    clock_.restore(a, prefix);
    prepared_ = true;
  }

  Health health() const {
    Health h;
    for (std::size_t b = 0; b < count(); ++b) {
      bool ok = true;
      for (int k = 0; k < D; ++k) ok = ok && std::isfinite(bodies_(b).position[k]) && std::isfinite(bodies_(b).velocity[k]);
      if (!ok && h.finite) {
        h.finite = false;
        h.first_bad = static_cast<std::int64_t>(b);
        h.what = "rigid body";
      }
    }
    return h;
  }

  double kinetic_energy() const {
    double e = 0.0;
    for (std::size_t b = 0; b < count(); ++b) e += bodies_(b).kinetic_energy();
    return e;
  }

 private:
  HostBodies bodies_;
  double dt_;
  StepClock clock_;  // step index and time (models/common/clock.hpp)
  bool prepared_ = false;
  StateRegistry state_;
};

}  // namespace polymech::models
