// The floating body of the ISPH model (seed 002 paper 4, 2D, effect `rigid_body`): a disc of IGCB cells
// (setup.hpp's body_cells) among the wall points, a rigid::RigidBody<2> moved by the fluid's force and
// moment, eqs. (31)-(37), and by its contact with the tank (kernels/contact/hertz_mindlin.hpp).
// Conventional serial staggered coupling (CSS), explicit Euler as the paper: the fluid step just taken
// saw the body at its old pose; the body now moves with the fluid force of that step, and the next fluid
// step sees the new pose.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "contact/hertz_mindlin.hpp"
#include "isph/config.hpp"
#include "isph/setup.hpp"
#include "neighbors/neighbor_list.hpp"
#include "rigid/rigid_body.hpp"
#include "sph/body.hpp"
#include "sph/ghosts.hpp"

namespace polymech::isph {

// The rigid body's state as apps and tests read it (Isph::body()), and as checkpoints store it: centre of
// the disc, angle, velocities, the fluid force and moment of the last step (eqs. (36)-(37)), and the
// acceleration used by the next step's Neumann condition (25).
struct BodyState {
  double centre[2] = {0, 0}, theta = 0, v[2] = {0, 0}, omega = 0, a[2] = {0, 0}, alpha = 0, force[2] = {0, 0},
         moment = 0;
  // contact with the tank (bottom, left, right wall): the force and moment of the last step and the
  // tangential spring of each wall (kernels/contact/hertz_mindlin.hpp)
  double contact_force[2] = {0, 0}, contact_moment = 0, spring[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
};

template <class T>
class FloatingBody {
 public:
  // The body's cells as wall points [begin, begin + cells): their weights into `vol` (a host mirror of
  // the wall points' volumes), their offsets from the centre kept here; the pose from the configuration.
  template <class HostVol>
  void build(const Config& c, const BodyCells& cells, Index begin, const double (&box)[3], bool difference_gradient,
             const HostVol& vol) {
    props_ = mass_properties(c, cells);
    bc_ = body_contact(c);
    begin_ = begin;
    diameter_ = c.body.diameter;
    spacing_ = c.spacing;
    dt_ = c.dt;
    release_time_ = c.body.release_time;
    added_mass_ = c.body.added_mass;
    density_ = c.density;
    gravity_ = c.gravity;
    width_ = box[0];
    offset_ = VecView<T, 2>("polymech::isph::body_offset", cells.weight.size());
    auto ho = Kokkos::create_mirror_view(offset_);
    for (std::size_t k = 0; k < cells.weight.size(); ++k) {
      for (int d = 0; d < 2; ++d) ho(k, d) = T(cells.offset[2 * k + d]);
      vol(static_cast<std::size_t>(begin) + k) = T(cells.weight[k]);
    }
    Kokkos::deep_copy(offset_, ho);
    // the outer ring (body_cells builds the rings from the outside in): the points at the first radius
    const double r0 = std::hypot(cells.offset[0], cells.offset[1]);
    outer_ = 0;
    while (static_cast<std::size_t>(outer_) < cells.weight.size() &&
           std::fabs(std::hypot(cells.offset[2 * outer_], cells.offset[2 * outer_ + 1]) - r0) < 1e-9 * r0)
      ++outer_;
    if (difference_gradient) surface_p_ = View1<T>("polymech::isph::body_surface_pressure", outer_);
    rigid_ = rigid::RigidBody<2>();
    rigid_.mass = props_.mass;
    rigid_.inertia[0] = props_.inertia;
    rigid_.position[0] = c.body.centre[0];
    rigid_.position[1] = c.body.centre[1];
    read_out();
  }

  Index begin() const { return begin_; }
  const MassProperties& properties() const { return props_; }
  const BodyState& state() const { return state_; }
  const rigid::RigidBody<2>& rigid() const { return rigid_; }

  // Moves the body's wall points to the pose and motion of the body (sph::place_body).
  void place(const sph::WallPoints<T, 2>& wp) const {
    const auto& b = state_;
    const sph::BodyMotion<T> m{T(b.centre[0]), T(b.centre[1]), T(b.theta), T(b.v[0]), T(b.v[1]), T(b.omega),
                               T(b.a[0]),      T(b.a[1]),      T(b.alpha)};
    sph::place_body(wp, offset_, begin_, T(0.5 * diameter_), m);
  }

  // One step of the body after the fluid's step at `time` (its start): the fluid force and moment of that
  // step on the body's points (fw: fluid -> wall points, gf: ghosts -> fluid), and, once released, the
  // body's update and its points moved. Returns the fluid particles pushed out of the body.
  long long advance(const neighbors::NeighborList& fw, const neighbors::NeighborList& gf, const sph::Fluid<T, 2>& f,
                    const sph::WallPoints<T, 2>& wp, const sph::Params<T, 2>& par, double time, T ghost_det_min) {
    auto& b = state_;
    double out[3];
    sph::body_force(fw, f, wp, par, begin_, T(b.centre[0]), T(b.centre[1]), out);
    if (par.difference_gradient) {
      neighbors::for_each_row("polymech::sph::surface_pressure", gf,
                              sph::SurfacePressure<T, 2>{f, wp, par, begin_, begin_ + outer_, ghost_det_min, surface_p_});
      const double arc = 3.14159265358979323846 * diameter_ / double(outer_);
      sph::body_surface_force(wp, surface_p_, begin_, outer_, arc, out);
    }
    b.force[0] = out[0];
    b.force[1] = out[1];
    b.moment = out[2];
    const double dt = dt_, m = props_.mass, R = 0.5 * diameter_;
    if (time + dt < release_time_) return 0;  // held fixed: the force is recorded only
    const double v0[2] = {rigid_.velocity[0], rigid_.velocity[1]}, w0 = rigid_.spin[0];
    // eq. (31) by explicit Euler, with an added-mass term: the fluid force of a body accelerating at a
    // contains -m_a a (m_a = C_a rho0 pi R^2 for a cylinder); explicit staggered coupling then updates
    // a_{n+1} = (F_rest - m_a a_n) / m, which diverges when m_a >= m (density ratio <= 1 at C_a = 1).
    // Moving m_a a to the left, (m + m_a) a_{n+1} = F + m_a a_n - m g, has the same fixed point and is
    // stable (not in the paper; added_mass = 0 gives the paper's plain CSS). (The Neumann pressure of
    // eq. (26) alone carries little of m_a: -dF/da through it is 1.0-1.4 kg/m against m_a = 7.9 kg/m for
    // D = 0.1 m at l0 = D/5 and D/10, measured; the rest acts through the PPE's wall velocities.)
    const double pi = 3.14159265358979323846;
    const double ma = added_mass_ * density_ * pi * R * R;
    tank_contact(R);
    const double fx = out[0] + b.contact_force[0], fy = out[1] + b.contact_force[1];
    rigid_.clear_loads();
    rigid_.force[0] = fx + ma * b.a[0];
    rigid_.force[1] = fy + ma * b.a[1] - m * gravity_;
    rigid_.torque[0] = out[2] + b.contact_moment;  // eq. (32)
    rigid_.kick_added_mass(dt, ma);
    rigid_.drift(dt);
    b.a[0] = (rigid_.velocity[0] - v0[0]) / dt;
    b.a[1] = (rigid_.velocity[1] - v0[1]) / dt;
    b.alpha = (rigid_.spin[0] - w0) / dt;
    read_out();
    place(wp);
    return sph::push_out_of_body(f, T(b.centre[0]), T(b.centre[1]), T(R + 0.25 * spacing_));
  }

  // Checkpoints: the BodyState (its bytes as before the body was a RigidBody).
  void save(models::Archive& a, const std::string& name) const { a.put(name, state_); }
  void load(const models::Archive& a, const std::string& name) {
    state_ = a.get<BodyState>(name);
    rigid_.position[0] = state_.centre[0];
    rigid_.position[1] = state_.centre[1];
    rigid_.orientation[0] = state_.theta;
    rigid_.velocity[0] = state_.v[0];
    rigid_.velocity[1] = state_.v[1];
    rigid_.spin[0] = state_.omega;
  }

 private:
  // The body against the tank's bottom (y = 0) and sides (x = 0, x = width): the shared Hertz-Mindlin law
  // (kernels/contact/hertz_mindlin.hpp) of a disc of unit thickness on a rigid plane, with damping and
  // Coulomb friction, explicit like the fluid coupling; its force and moment join the fluid's in eqs.
  // (31)-(32). (It replaces a kinematic stop: a body that reaches a wall must not pass through it.)
  void tank_contact(double R) {
    auto& b = state_;
    // a rigid body and a rigid wall: the law's moduli are the contact's (nu = 0: G* = G / 2 = E* / 4)
    const contact::HertzMindlin<double> law{bc_.e_star, 0.25 * bc_.e_star, bc_.beta, bc_.mu};
    const double planes[3][3] = {{0.0, 1.0, 0.0}, {1.0, 0.0, 0.0}, {-1.0, 0.0, width_}};  // n . x + d >= 0 inside
    const double* x = rigid_.position;
    const double* v = rigid_.velocity;
    const double omega = rigid_.spin[0];
    b.contact_force[0] = b.contact_force[1] = b.contact_moment = 0.0;
    for (int w = 0; w < 3; ++w) {
      const double nx = planes[w][0], ny = planes[w][1];
      const double gap = nx * x[0] + ny * x[1] + planes[w][2] - R;  // < 0: overlap
      Vec3<double> xi{{b.spring[w][0], b.spring[w][1], b.spring[w][2]}};
      if (gap >= 0.0) {
        b.spring[w][0] = b.spring[w][1] = b.spring[w][2] = 0.0;
        continue;
      }
      const Vec3<double> n{{nx, ny, 0.0}};
      // the body's velocity at the contact point c - R n: v + omega x (-R n)
      const Vec3<double> vc{{v[0] + omega * R * ny, v[1] - omega * R * nx, 0.0}};
      const auto f = contact::hertz_mindlin_force(law, R, bc_.mass, -gap, n, vc, bc_.mu > 0.0, dt_, xi);
      b.contact_force[0] += f.force[0];
      b.contact_force[1] += f.force[1];
      b.contact_moment += -R * (nx * f.force[1] - ny * f.force[0]);  // lever -R n
      for (int k = 0; k < 3; ++k) b.spring[w][k] = xi[k];
    }
  }
  // The read-out of the RigidBody's pose and velocities.
  void read_out() {
    state_.centre[0] = rigid_.position[0];
    state_.centre[1] = rigid_.position[1];
    state_.theta = rigid_.orientation[0];
    state_.v[0] = rigid_.velocity[0];
    state_.v[1] = rigid_.velocity[1];
    state_.omega = rigid_.spin[0];
  }

  rigid::RigidBody<2> rigid_;  // pose and velocities (mass and inertia from the cells, eqs. (33)-(35))
  BodyState state_;            // the read-out, with the coupling's accelerations, loads and contact springs
  MassProperties props_;
  BodyContact bc_;
  Index begin_ = 0, outer_ = 0;  // the body's points: wall points [begin, ...); its outer ring: the first `outer`
  VecView<T, 2> offset_;         // each point's offset from the centre at theta = 0
  View1<T> surface_p_;           // the fluid pressure at the body's surface points (difference form only)
  double diameter_ = 0.0, spacing_ = 0.0, dt_ = 0.0, release_time_ = 0.0, added_mass_ = 0.0, density_ = 0.0,
         gravity_ = 0.0, width_ = 0.0;  // the configuration's, and the tank's width as built
};

}  // namespace polymech::isph
