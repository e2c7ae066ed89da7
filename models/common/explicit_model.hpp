// The phases of an explicit model's time step, so that one run driver steps every method and a coupled
// model interleaves two models and the forces between them.
//
// A model (MpsElastic, NosbPd, RigidBodyModel, CoupledModel) provides
//
//   void prepare();               forces of the initial state, where the integrator needs them (velocity
//                                 Verlet: a_0); called once before the first step, a no-op afterwards
//   void advance_first_half();    the integrator's part before the forces (Verlet: kick + drift;
//                                 symplectic Euler: nothing)
//   void compute_forces();        internal forces -> accelerations (overwrites them)
//   void observe();               records what is sampled at this state (probes); may do nothing
//   void add_contact_forces();    the model's own contact and loads (adds to the accelerations)
//   void advance_second_half();   the integrator's part after the forces; ends the step
//   double dt() const; double time() const; std::int64_t step_index() const;
//
// A coupled model adds its interaction's forces between compute_forces() and add_contact_forces() of
// its two models: internal forces first, then the coupling, then each model's own contact. Each model's
// step() is explicit_step(*this).
#pragma once

namespace polymech::models {

template <class Model>
void explicit_step(Model& m) {
  m.prepare();
  m.advance_first_half();
  m.compute_forces();
  m.observe();
  m.add_contact_forces();
  m.advance_second_half();
}

}  // namespace polymech::models
