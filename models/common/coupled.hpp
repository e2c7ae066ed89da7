// Two explicit models advanced with one time step, and an interaction that adds forces to both: a
// peridynamic plate and a rigid projectile (seed 003), fluid particles and a floating body (ISPH), DEM
// clumps and a deformable FE surface. The interaction computes each pair force once and adds it to both
// sides with opposite signs, so the momentum it exchanges is exact.
//
// An interaction provides
//   void add_forces(A& a, B& b);   // called after both models' internal forces, before their own contact
//   double energy() const;         // energy stored in it (penalty springs), 0 if none
#pragma once

#include <stdexcept>
#include <string>

#include "common/explicit_model.hpp"
#include "common/run.hpp"

namespace polymech::models {

template <class A, class B, class Interaction>
class CoupledModel {
 public:
  static constexpr int dimension = A::dimension;

  // The models must use the same time step.
  CoupledModel(A& a, B& b, Interaction& interaction) : a_(a), b_(b), interaction_(interaction) {
    if (a.dt() != b.dt())
      throw std::invalid_argument("coupled model: the two models' time steps differ (" + std::to_string(a.dt()) + " s and " +
                                  std::to_string(b.dt()) + " s); give both the same dt");
  }

  void prepare() {
    if (prepared_) return;
    a_.compute_forces();
    b_.compute_forces();
    interaction_.add_forces(a_, b_);
    a_.add_contact_forces();
    b_.add_contact_forces();
    a_.mark_prepared();
    b_.mark_prepared();
    prepared_ = true;
  }
  void advance_first_half() {
    a_.advance_first_half();
    b_.advance_first_half();
  }
  void compute_forces() {
    a_.compute_forces();
    b_.compute_forces();
    interaction_.add_forces(a_, b_);
  }
  void observe() {
    a_.observe();
    b_.observe();
  }
  void add_contact_forces() {
    a_.add_contact_forces();
    b_.add_contact_forces();
  }
  void advance_second_half() {
    a_.advance_second_half();
    b_.advance_second_half();
  }
  void step() { explicit_step(*this); }
  void mark_prepared() { prepared_ = true; }

  double dt() const { return a_.dt(); }
  double time() const { return a_.time(); }
  std::int64_t step_index() const { return a_.step_index(); }
  void set_step_index(std::int64_t k) {
    a_.set_step_index(k);
    b_.set_step_index(k);
  }
  // The first model's health first, then the second's.
  Health health() const {
    const Health h = a_.health();
    return h.finite ? b_.health() : h;
  }
  const StateRegistry& state() {
    state_ = StateRegistry();
    state_.append(a_.state());
    state_.append(b_.state());
    return state_;
  }

  // Both models' complete states (the interaction holds none between steps: it recomputes its
  // forces from the models' state).
  void save(Archive& a, const std::string& prefix) {
    a_.save(a, prefix + "first/");
    b_.save(a, prefix + "second/");
  }
  void load(const Archive& a, const std::string& prefix) {
    a_.load(a, prefix + "first/");
    b_.load(a, prefix + "second/");
    prepared_ = true;
  }

  A& first() { return a_; }
  B& second() { return b_; }
  Interaction& interaction() { return interaction_; }
  const A& first() const { return a_; }
  const B& second() const { return b_; }
  const Interaction& interaction() const { return interaction_; }

 private:
  A& a_;
  B& b_;
  Interaction& interaction_;
  StateRegistry state_;
  bool prepared_ = false;
};

}  // namespace polymech::models
