// The deformable tyre of the DEM model's `fe_tyre` effect (seed 002 paper 2 §4, Figs. 6-10; issue 37): the FE
// tyre 37x12.5R16.5 of models/solid/tyre.hpp as an explicit finite-strain solid (solid::HyperelasticExplicit,
// central differences with the lumped mass) whose two beads are tied to one rigid rim, stepped with the spheres
// in one common step (the DEM's: the tyre's own limit is larger, docs/VALIDATION.md), its outer surface the
// DEM's FE surface.
//
// Schedule (WheelSpec, times from the set-down at WheelSpec::start): parked far above the bin until then; set
// down with its lowest point on the highest sphere under it (as the rigid wheel, dem/wheel_drive.hpp); inflated
// to TyreInit::pressure over [0, inflate_to] (a follower pressure on the inner surface; with TyreInit::deflate let
// down to zero over [deflate[0], deflate[1]], the hard case of a flat tyre); the rim carries the
// vertical load (free height, m z'' = F_z - load), its x velocity and spin are prescribed (speed and slip).
// The tyre carries no weight of its own (as the rigid wheel: the load is all of it).
//
// One step of the coupled system (velocity Verlet for both, dem/dem.hpp):
//   first_half: the tyre's kick and drift (solid::HyperelasticExplicit::first_half), then its outer surface
//               placed (nodes X + u + origin, velocities the half-step ones)
//   the DEM's contacts: spheres against the surface's facets with the material velocity interpolated at the
//               contact point; each contact's force to the facet's nodes (dem/surface_loads.hpp)
//   second_half: the tyre's forces at t + dt with those node forces as external forces, its second kick.
// The momentum the spheres lose is what the tyre's nodes gain (to round-off), and what reaches the rim through
// the tied beads is the rim's reaction: the rim's vertical and tractive forces are the gravel's through the tyre.
//
// Subcycling (TyreInit::substeps = k > 1, when the tyre's stable step is the smaller: a layered wall's is about a
// quarter of the smeared one's), as the impulse form of multiple time stepping (r-RESPA: Tuckerman, Berne &
// Martyna 1992, J. Chem. Phys. 97, 1990): the contact force is the slow force, applied as two half-kicks of
// dt / 2 at the DEM step's ends, the tyre's own forces are integrated by k velocity Verlet steps of dt / k between
// them. In the tyre's leapfrog this is the contact force scaled by k in the residual of the step's last inner
// step (its half-kick of h / 2 = dt / (2k) is the DEM step's closing half-kick, and the same acceleration opens
// the next DEM step) and zero in the k - 1 inner ones: the tyre's contact impulse per DEM step is
// dt / 2 (F_n + F_n+1), the spheres' exactly, so momentum is still exchanged to round-off. k = 1 is the common
// step, bit for bit.
// Damping (TyreInit::damping) acts on the nodes' velocity relative to the rim's rigid motion, its reaction on
// the rim, so it neither brakes the rolling nor changes the momentum.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/state.hpp"
#include "contact/surface_mesh.hpp"
#include "dem/config.hpp"
#include "dem/surface_loads.hpp"
#include "dem/tyre_spec.hpp"
#include "dem/wheel_drive.hpp"
#include "solid/finite_strain_explicit.hpp"
#include "solid/tyre.hpp"

namespace polymech::dem {

// The tyre's placement and the FE model's clock and rim state, for checkpoints: the bytes of the entry
// "tyre_info" (doubles only).
struct TyreRecord {
  WheelPlacement placement;
  double origin[3] = {0, 0, 0};  // the FE frame's origin (the undeformed tyre's centre) in the world
  double fe_time = 0.0, fe_steps = 0.0;
  solid::TieState<3> rim;
};

template <class T>
class TyreDrive {
 public:
  using Solid = solid::HyperelasticExplicit<double, 3>;
  TyreDrive() = default;  // no tyre: allocates nothing

  // The tyre of `tyre` under the schedule `spec` (radius and width: the tyre's outer radius and section width),
  // stepped at dt (0: 0.9 x its critical step). Throws std::invalid_argument for a bad spec or a step above the
  // tyre's stable one.
  TyreDrive(const WheelSpec& spec, const TyreInit& tyre, double dt) : spec_(spec), init_(tyre) {
    if (!spec.enabled() || !(spec.mass > 0) || !(spec.slip >= 0 && spec.slip < 1) || !(spec.damping >= 0))
      throw std::invalid_argument("dem: the tyre's rim needs radius > 0, mass > 0, slip in [0, 1) and damping >= 0");
    if (!(tyre.pressure >= 0) || !(tyre.inflate_to > 0) || !(tyre.damping >= 0) || tyre.order < 1 || tyre.order > 4)
      throw std::invalid_argument("dem: the tyre needs pressure >= 0, inflate_to > 0, damping >= 0 and order 1-4");
    if (tyre.deflate[1] > 0 && !(tyre.deflate[0] >= tyre.inflate_to && tyre.deflate[1] > tyre.deflate[0]))
      throw std::invalid_argument("dem: the tyre's deflation [t0, t1] needs inflate_to <= t0 < t1");
    if (tyre.substeps < 0 || tyre.substeps > 1000)
      throw std::invalid_argument("dem: the tyre's substeps must be 0 (as its step needs) or 1-1000");
    contact_scale_ = std::make_shared<double>(1.0);
    const solid::TyreSpec ts = tyre_spec(spec, tyre);
    const solid::TyreLaw law = solid::tyre_equivalent_law(ts);
    solid::Config<3> c;
    c.mesh = solid::make_tyre(ts, tyre.around, tyre.across, tyre.through);
    c.order = tyre.order;
    solid::RigidTie<3> rim;
    rim.boundary = "ymin+ymax";  // both beads on the one rim
    rim.axis = {0.0, 1.0, 0.0};
    rim.mass = spec.mass;
    rim.inertia = 1.0;  // its spin is prescribed
    const WheelSpec w = spec;
    rim.velocity[0] = [w](double t) { return w.speed_at(t); };
    rim.velocity[1] = [](double) { return 0.0; };
    rim.velocity[3] = [w](double t) { return w.spin_at(t); };
    rim.load[2] = [w](double t) { return -w.load_at(t); };
    rim.damping[2] = spec.damping;  // the carriage's vertical damper (WheelSpec::damping; 0: none)
    solid::ExplicitFiniteStrainOptions o;
    o.density = law.density;
    o.dt = dt;
    o.damping = tyre.damping;
    o.damping_frame = 0;
    o.cell_scale = solid::tyre_cell_scale(ts, tyre.around, tyre.across, tyre.through);  // empty: the smeared law
    o.fibre_stiffness = solid::tyre_fibre_stiffness(ts, tyre.around, tyre.across, tyre.through);  // empty unless belt_rebar
    o.fibre_angle_deg = ts.belt_angle_deg;
    o.fibre_tension_only = ts.belt_tension_only;
    // the pressure's factor: up over [0, inflate_to], then (deflate[1] > 0) down to zero over [deflate[0], deflate[1]]
    const double ramp = tyre.inflate_to, d0 = tyre.deflate[0], d1 = tyre.deflate[1];
    o.load_factor = [ramp, d0, d1](double t) {
      if (t < ramp) return t / ramp;
      if (!(d1 > 0) || t <= d0) return 1.0;
      return t < d1 ? (d1 - t) / (d1 - d0) : 0.0;
    };
    solid_ = std::make_shared<Solid>(c, solid::HyperelasticLaw(law.law), o, std::vector<solid::FollowerPressure>{{"zmin", tyre.pressure}},
                                     std::vector<solid::RigidTie<3>>{rim});
    rim_reference_ = solid_->ties()[0].position;
    make_surface();
    record_ = Kokkos::View<TyreRecord*, HostSpace>("polymech::dem::tyre_info", 1);
    record_(0).rim = solid_->ties()[0];
    for (int k = 0; k < 3; ++k) record_(0).origin[k] = spec.parked[k];
  }

  bool enabled() const { return solid_ != nullptr; }
  void set_time_step(double dt) { solid_->set_time_step(dt); }
  // The tyre stepped `substeps` times per DEM step of dt (0: as many as its stable step needs, at least 1): its
  // step dt / k. Throws std::invalid_argument (solid::HyperelasticExplicit's message) when dt / k is above it.
  void subcycle(double dt, int substeps) {
    const double own = solid_->time_step();  // safety x its critical step
    substeps_ = substeps > 0 ? substeps : std::max(1, static_cast<int>(std::ceil(dt / own * (1.0 - 1e-12))));
    solid_->set_time_step(dt / substeps_);
  }
  int substeps() const { return substeps_; }
  bool placed() const { return record_(0).placement.placed > 0; }
  const Solid& solid() const { return *solid_; }
  // The outer surface as a DEM surface (nodes in the world, parked): quadrilaterals between neighbouring nodes
  // of the order-p lattice's outer side, counter-clockwise seen from outside.
  const SurfaceInit& surface() const { return surface_; }
  // Per surface node: its velocity (the half step's, after first_half) and the spheres' force on it.
  const VecView<T, 3>& node_velocity() const { return velocity_; }
  const VecView<T, 3>& node_force() const { return force_; }
  const SurfaceAdjacency& adjacency() const { return adjacency_; }
  // The gravel's total force on the tyre and its moment about the rim's centre (last step).
  const std::array<double, 6>& contact() const { return contact_; }

  // The first half of step `step`: set down at WheelSpec::start (at rest), then the tyre's kick and drift and
  // its surface placed in `mesh`.
  void first_half(std::int64_t step, double dt, const SphereSet<T>& s, const contact::SurfaceMesh<T>& mesh) {
    if (!placed()) {
      if (static_cast<double>(step) * dt + 0.5 * dt < spec_.start) return;
      set_down(static_cast<double>(step) * dt, s);
    }
    if (!failure_.empty()) return;
    solid_->first_half();
    *contact_scale_ = 0.0;  // the inner steps of a subcycle: the tyre's own forces only
    for (int j = 1; j < substeps_; ++j) {
      if (!evaluate()) return;
      solid_->first_half();
    }
    place(mesh);
  }
  // After the contact forces: the tyre's forces at t + dt (the spheres' node forces external) and its second
  // kick; the gravel's force and moment on the tyre summed in node order.
  // A tyre whose state stops evaluating (an inverted element) is not stepped again: failure() says why, and
  // the model's health check turns it into a diverged run (exit 1, the reason in summary.json).
  void second_half() {
    if (!placed() || !failure_.empty()) return;
    *contact_scale_ = static_cast<double>(substeps_);  // the DEM step's closing half-kick (1: the common step)
    if (!evaluate()) return;
    sum_contact();
    keep_record();
  }
  const std::string& failure() const { return failure_; }

  // The tyre after `step` steps of dt, as WheelState (its rim's centre and the tread's lowest point).
  WheelState state(std::int64_t step, double dt) const {
    WheelState w;
    const TyreRecord& r = record_(0);
    w.placed = placed();
    w.time = w.placed ? static_cast<double>(step) * dt - r.placement.time_placed : 0.0;
    const auto& rim = solid_->ties()[0];
    for (int k = 0; k < 3; ++k) w.centre[k] = r.origin[k] + rim.position[static_cast<std::size_t>(k)] - rim_reference_[static_cast<std::size_t>(k)];
    w.bed_level = r.placement.bed_level;
    w.bed_highest = r.placement.bed_highest;
    w.tread_low = lowest_tread();
    if (w.placed) set_down_state(w, spec_, contact_);
    return w;
  }

  // The tyre's displacement, velocity and acceleration and the record, under "tyre_u", "tyre_v", "tyre_a",
  // "tyre_info" (nothing without the tyre).
  void register_state(models::StateRegistry& r) const {
    if (!solid_) return;
    r.add("tyre_u", solid_->displacement());
    r.add("tyre_v", solid_->velocity());
    r.add("tyre_a", solid_->acceleration_view());
    r.add("tyre_info", record_);
  }
  // After a checkpoint (or the watchdog's last good state) was loaded: the FE model's clock and rim from the
  // record, the surface placed again.
  void restored(const contact::SurfaceMesh<T>& mesh) {
    if (!solid_) return;
    const TyreRecord& r = record_(0);
    solid_->restore(r.fe_time, static_cast<std::int64_t>(r.fe_steps), {r.rim});
    place(mesh);
  }

 public:  // (public: nvcc's extended lambdas)
  bool evaluate() {  // the tyre's forces at the end of its step and its second half-kick; false if it failed
    try {
      solid_->second_half();
    } catch (const std::runtime_error& e) {
      failure_ = e.what();
      return false;
    }
    return true;
  }
  void make_surface();
  void place(const contact::SurfaceMesh<T>& mesh) const;
  void sum_contact();
  double lowest_tread() const;
  void set_down(double time, const SphereSet<T>& s);
  void keep_record() {
    TyreRecord& r = record_(0);
    r.fe_time = solid_->time();
    r.fe_steps = static_cast<double>(solid_->steps());
    r.rim = solid_->ties()[0];
  }

 private:
  WheelSpec spec_;
  TyreInit init_;
  std::shared_ptr<Solid> solid_;
  std::array<double, 3> rim_reference_{};
  SurfaceInit surface_;
  Kokkos::View<Index*, MemSpace> fe_node_;  // per surface node: the FE node
  View1<double> reference_;                 // the FE nodes' coordinates X (FE frame)
  VecView<T, 3> velocity_, force_;
  SurfaceAdjacency adjacency_;
  Kokkos::View<TyreRecord*, HostSpace> record_;
  particles::SumPartials partials_;
  std::array<double, 6> contact_{};
  std::string failure_;
  int substeps_ = 1;
  std::shared_ptr<double> contact_scale_;  // the contact forces' factor in the residual, read by the solid's external force
};

}  // namespace polymech::dem

#include "dem/tyre_surface.hpp"  // the members declared above
