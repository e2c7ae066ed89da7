// The driven rigid wheel of the DEM model's `rigid_wheel` effect (seed 002 paper 2, sec. 4, Figs. 6-10):
// one rigid body carrying the FE surface of dem/wheel.hpp. Before WheelSpec::start it is parked; at
// start it is set on the bed (its lowest point on the highest sphere under its footprint, at rest); then
// each step its x velocity and spin follow the schedule (prescribed at mid-step) while its height is free:
// m z'' = F_z, the spheres' reaction (summed in index order, kernels/dem/contact_forces.hpp wrench_sum)
// less the schedule's vertical load (the wheel carries no weight of its own: the load is all of it).
//
// Host-side: the body and its placement live in HostSpace Views (the model's registered state, so the
// watchdog and checkpoints keep them); the device work is the mesh's placement (contact::place_rigid)
// and the reaction's sum.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "common/state.hpp"
#include "contact/surface_mesh.hpp"
#include "dem/config.hpp"
#include "dem/contact_forces.hpp"
#include "dem/spheres.hpp"
#include "dem/wheel.hpp"
#include "rigid/rigid_body.hpp"

namespace polymech::dem {

// The wheel of the `rigid_wheel` effect after a step (host), in SI units.
struct WheelState {
  bool placed = false;           // set on the bed yet (time >= WheelSpec::start)
  double time = 0.0;             // since it was set down
  double centre[3] = {};
  double sinkage = 0.0;          // rim sinkage: the bed's level under it less its lowest point (R below the centre)
  double vertical_force = 0.0;   // the gravel's force on it, +z
  double tractive_force = 0.0;   // the gravel's force on it along the travel, +x (net traction)
  double driving_torque = 0.0;   // what turns it against the gravel (minus the gravel's moment about +y)
  double load = 0.0, speed = 0.0, spin = 0.0;  // the schedule's values now
  double bed_level = 0.0, bed_highest = 0.0;   // under the footprint when it was set down
  double tread_low = 0.0;        // the tread's lowest point (rigid wheel: R below the centre; a tyre: its surface)
};

// Where the wheel was set down. Four doubles in this order: the bytes of the checkpoint entry
// "wheel_info" (`placed` is a double, 1 once set down, so that older checkpoints read back).
struct WheelPlacement {
  double placed = 0.0;       // 1 once set on the bed
  double time_placed = 0.0;  // the simulated time it was set down (s)
  double bed_level = 0.0;    // the bed's mean level under its footprint then (BedLevel::mean)
  double bed_highest = 0.0;  // the highest sphere under it then (BedLevel::highest)
};

// A set-down wheel's (or tyre's) rim sinkage (the bed's level less its centre's height less R), the spheres' force
// and moment on it (contact: force, moment about its centre) and the schedule's values at w.time.
inline void set_down_state(WheelState& w, const WheelSpec& spec, const std::array<double, 6>& contact) {
  w.sinkage = w.bed_level - (w.centre[2] - spec.radius);
  w.vertical_force = contact[2];
  w.tractive_force = contact[0];
  w.driving_torque = -contact[4];
  w.load = spec.load_at(w.time);
  w.speed = spec.speed_at(w.time);
  w.spin = spec.spin_at(w.time);
}

// The bed under a wheel of `spec` at its x_start (dem/wheel.hpp bed_level) from the spheres' current positions.
template <class T>
BedLevel bed_under(const SphereSet<T>& s, const WheelSpec& spec) {
  auto x0 = Kokkos::create_mirror_view_and_copy(HostSpace(), s.x0);
  auto u = Kokkos::create_mirror_view_and_copy(HostSpace(), s.u);
  auto r = Kokkos::create_mirror_view_and_copy(HostSpace(), s.radius);
  std::vector<std::array<double, 4>> rows(static_cast<std::size_t>(s.size()));
  double r_max = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i] = {double(x0(i, 0) + u(i, 0)), double(x0(i, 1) + u(i, 1)), double(x0(i, 2) + u(i, 2)), double(r(i))};
    r_max = std::max(r_max, rows[i][3]);
  }
  return bed_level(rows, spec, r_max);
}

template <class T>
class WheelDrive {
 public:
  WheelDrive() = default;  // no wheel: allocates nothing
  // The wheel of `spec` carrying `mesh` (its nodes relative to the centre, as the scene gives them),
  // parked at spec.parked, over `spheres` spheres. Throws std::invalid_argument for a bad spec.
  WheelDrive(const WheelSpec& spec, const contact::SurfaceMesh<T>& mesh, Index spheres) : spec_(spec) {
    if (!spec.enabled() || !(spec.mass > 0) || !(spec.slip >= 0 && spec.slip < 1) || !(spec.damping >= 0))
      throw std::invalid_argument("dem: the wheel needs radius > 0, mass > 0, slip in [0, 1) and damping >= 0");
    body_ = decltype(body_)("polymech::dem::wheel", 1);
    placement_ = decltype(placement_)("polymech::dem::wheel_info", 1);
    auto& b = body_(0);
    b.mass = spec.mass;
    for (int k = 0; k < 3; ++k) {
      b.inertia[k] = 1.0;  // the spin is prescribed: with unit inertia the angular momentum is the angular velocity
      b.position[k] = spec.parked[k];
    }
    reference_ = VecView<T, 3>("polymech::dem::wheel_reference", mesh.node_count());
    Kokkos::deep_copy(reference_, mesh.nodes);
    reaction_ = WrenchView<T>("polymech::dem::wheel_reaction", spheres);
    place(mesh);
  }

  bool placed() const { return placement_(0).placed > 0; }
  const rigid::RigidBody<3>& body() const { return body_(0); }
  const WheelPlacement& placement() const { return placement_(0); }
  // Per sphere: what it gives the wheel (sphere_facet_forces fills it).
  const WrenchView<T>& reaction() const { return reaction_; }
  // The spheres' total force on the wheel and its moment about its centre (last step).
  const std::array<double, 6>& contact() const { return contact_; }

  // The wheel's motion over step `step` (from time step dt) for the sphere-facet contact: zero until
  // set down.
  SurfaceMotion<T> motion(std::int64_t step, double dt) const {
    SurfaceMotion<T> m;
    if (!placed()) return m;
    const auto& b = body_(0);
    const double t = time_of(step, dt) + dt - placement_(0).time_placed;  // the forces are those at the end of the step
    for (int k = 0; k < 3; ++k) m.centre[k] = T(b.position[k]);
    m.velocity[0] = T(spec_.speed_at(t));
    m.velocity[2] = T(b.velocity[2]);  // the half-step velocity, as the spheres' in velocity Verlet
    m.omega[1] = T(spec_.spin_at(t));
    return m;
  }

  // The first half of step `step`: set down at WheelSpec::start (then at rest), then the
  // kick of its height, the schedule's x velocity and spin at mid-step (the drift is exact for a ramp),
  // the drift, and the mesh moved with it.
  // The model's step and dt by reference (read again after set_down, as the model's own time() was:
  // then t = step dt - time_placed is one fused multiply-add, as it was before this class; bitwise).
  void first_half(const std::int64_t& step, const double& dt, const SphereSet<T>& s, const contact::SurfaceMesh<T>& mesh) {
    auto& b = body_(0);
    auto& at = placement_(0);
    if (!placed()) {
      if (time_of(step, dt) + 0.5 * dt < spec_.start) return;
      set_down(time_of(step, dt), s);
    }
    const double h = 0.5 * dt, t = time_of(step, dt) - at.time_placed;
    b.velocity[2] += h * b.force[2] / b.mass;
    b.velocity[0] = spec_.speed_at(t + h);
    b.velocity[1] = 0.0;
    b.spin[0] = b.spin[2] = 0.0;
    b.spin[1] = spec_.spin_at(t + h);
    b.drift(dt);
    place(mesh);
  }
  // The wheel's loads after the contact forces of step `step`: the spheres' reaction summed
  // in index order (thread-count independent) and the schedule's vertical load.
  void add_loads(std::int64_t step, double dt) {
    const auto sum = wrench_sum(reaction_, partials_);
    for (int k = 0; k < 6; ++k) contact_[static_cast<std::size_t>(k)] = sum[k];
    auto& b = body_(0);
    const double load = placed() ? spec_.load_at(time_of(step, dt) + dt - placement_(0).time_placed) : 0.0;
    for (int k = 0; k < 3; ++k) {
      b.force[k] = contact_[static_cast<std::size_t>(k)];
      b.torque[k] = contact_[static_cast<std::size_t>(3 + k)];
    }
    b.force[2] -= load + spec_.damping * b.velocity[2];  // the damper on the half-step velocity (WheelSpec::damping)
  }
  // The second half of the step: the kick of its height, m z'' = F_z (gravel + load).
  void second_half(double dt) {
    if (!placed()) return;
    auto& b = body_(0);
    b.velocity[2] += 0.5 * dt * b.force[2] / b.mass;
  }

  // The wheel after `step` steps of dt, as WheelState.
  WheelState state(std::int64_t step, double dt) const {
    WheelState w;
    const auto& b = body_(0);
    const auto& at = placement_(0);
    w.placed = placed();
    w.time = w.placed ? time_of(step, dt) - at.time_placed : 0.0;
    for (int k = 0; k < 3; ++k) w.centre[k] = b.position[k];
    w.bed_level = at.bed_level;
    w.bed_highest = at.bed_highest;
    w.tread_low = b.position[2] - spec_.radius;
    if (w.placed) set_down_state(w, spec_, contact_);
    return w;
  }

  // The body and its placement, under the checkpoint names "wheel" and "wheel_info".
  void register_state(models::StateRegistry& r) const {
    r.add("wheel", body_);
    r.add("wheel_info", placement_);
  }

 private:
  // The time after `step` steps, as the model's time() forms it: the times above are formed inline from
  // it, as the model formed them before this class (so that the compiler contracts them alike: bitwise).
  static double time_of(std::int64_t step, double dt) { return static_cast<double>(step) * dt; }
  // Its lowest point on the highest sphere under its footprint (dem/wheel.hpp bed_level), at rest.
  void set_down(double time, const SphereSet<T>& s) {
    const BedLevel level = bed_under(s, spec_);
    auto& b = body_(0);
    b = rigid::RigidBody<3>();
    b.mass = spec_.mass;
    for (int k = 0; k < 3; ++k) b.inertia[k] = 1.0;
    b.position[0] = spec_.x_start;
    b.position[1] = spec_.y_centre;
    b.position[2] = level.highest + spec_.radius;
    auto& at = placement_(0);
    at.placed = 1.0;
    at.time_placed = time;
    at.bed_level = level.mean;
    at.bed_highest = level.highest;
  }
  void place(const contact::SurfaceMesh<T>& mesh) const {
    const auto& b = body_(0);
    contact::place_rigid(mesh, reference_, b.position, b.orientation);
  }

  WheelSpec spec_;
  Kokkos::View<rigid::RigidBody<3>*, HostSpace> body_;  // one body
  Kokkos::View<WheelPlacement*, HostSpace> placement_;  // one placement
  VecView<T, 3> reference_;                             // its nodes relative to its centre
  WrenchView<T> reaction_;                              // per sphere: what it gives the wheel
  particles::SumPartials partials_;                     // the chunk table of its sum (kept across steps)
  std::array<double, 6> contact_{};                     // their sum (last step)
};

}  // namespace polymech::dem
