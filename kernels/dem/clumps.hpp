// Multi-sphere clumps on the device (seed 002 paper 2, sec. 2-3): each clump is a rigid::RigidBody<3>
// (the type of every rigid body in polymech) and its member spheres are ordinary spheres of the
// SphereSet, so the contact kernels treat them like any sphere (pairs within one clump are skipped).
// A member's mass is its clump's mass: the contact law's effective mass (the damping) is the clump's,
// and a contact kernel's a += F / m, alpha += tau / (2/5 m r^2) give back F and tau exactly as
// m (a - g) and 2/5 m r^2 alpha.
//
// One velocity-Verlet step of the clumps, inside the DEM step:
//   clump_kick(h), clump_drift(dt), clump_members(positions) -> contacts ->
//   clump_loads (sum of the members' forces and torques, in member order) -> clump_kick(h),
//   clump_members(velocities).
#pragma once

#include "core/small_math.hpp"
#include "dem/spheres.hpp"
#include "rigid/rigid_body.hpp"

namespace polymech::dem {

template <class T>
struct ClumpSet {
  Kokkos::View<rigid::RigidBody<3>*, MemSpace> bodies;
  Kokkos::View<Offset*, MemSpace> first_member;  // bodies + 1 entries: members of b are
  Kokkos::View<Index*, MemSpace> members;         // members(first_member(b)) .. members(first_member(b+1)-1)
  VecView<T, 3> offset;                           // per sphere: centre in the body frame (members only)
  Index size() const { return static_cast<Index>(bodies.extent(0)); }
};

// Kernel "polymech::dem::clump_kick": v += h F / M, L += h tau.
template <class T>
void clump_kick(const ClumpSet<T>& c, double h) {
  const auto bodies = c.bodies;
  Kokkos::parallel_for(
      "polymech::dem::clump_kick", range(c.size()), KOKKOS_LAMBDA(const Index b) { bodies(b).kick(h); });
}

// Kernel "polymech::dem::clump_drift": x += dt v, q <- exp(dt/2 w) q.
template <class T>
void clump_drift(const ClumpSet<T>& c, double dt) {
  const auto bodies = c.bodies;
  Kokkos::parallel_for(
      "polymech::dem::clump_drift", range(c.size()), KOKKOS_LAMBDA(const Index b) { bodies(b).drift(dt); });
}

// Kernel "polymech::dem::clump_members": every member sphere follows its body: velocity v + w x r and
// spin w; with `positions`, also its centre X + R offset (as u = x - x0).
template <class T>
void clump_members(const SphereSet<T>& s, const ClumpSet<T>& c, bool positions) {
  // one View per declaration: nvcc 11.8 rejects an `auto` list whose types differ (docs/DEVELOPING.md)
  const auto bodies = c.bodies;
  const auto offset = c.offset;
  const auto body = s.body;
  const auto x0 = s.x0, u = s.u, v = s.v, omega = s.omega;
  Kokkos::parallel_for(
      "polymech::dem::clump_members", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        const int b = body(i);
        if (b < 0) return;
        const auto& rb = bodies(b);
        const double local[3] = {double(offset(i, 0)), double(offset(i, 1)), double(offset(i, 2))};
        double arm[3], p[3], vel[3], w[3];
        rb.to_world(local, arm);
        for (int k = 0; k < 3; ++k) p[k] = rb.position[k] + arm[k];
        rb.velocity_at(p, vel);
        rb.angular_velocity(w);
        for (int k = 0; k < 3; ++k) {
          if (positions) u(i, k) = T(p[k] - double(x0(i, k)));
          v(i, k) = T(vel[k]);
          omega(i, k) = T(w[k]);
        }
      });
}

// Kernel "polymech::dem::clump_loads": F = M g + sum m (a_i - g), tau = sum (x_i - X) x m (a_i - g) +
// 2/5 m r_i^2 alpha_i over the members in their order (no atomics: the sums do not depend on the
// thread count).
template <class T>
void clump_loads(const SphereSet<T>& s, const ClumpSet<T>& c, const Vec3<T>& g) {
  const auto bodies = c.bodies;
  const auto first = c.first_member;
  const auto members = c.members;
  Kokkos::parallel_for(
      "polymech::dem::clump_loads", range(c.size()), KOKKOS_LAMBDA(const Index b) {
        auto& rb = bodies(b);
        rb.clear_loads();
        for (int k = 0; k < 3; ++k) rb.force[k] = rb.mass * double(g[k]);
        for (Offset m = first(b); m < first(b + 1); ++m) {
          const Index i = members(m);
          const double mass = double(s.mass(i)), r = double(s.radius(i));
          double f[3], p[3];
          for (int k = 0; k < 3; ++k) {
            f[k] = mass * (double(s.a(i, k)) - double(g[k]));
            p[k] = double(s.x0(i, k)) + double(s.u(i, k));
          }
          rb.add_force_at(f, p);
          for (int k = 0; k < 3; ++k) rb.torque[k] += 0.4 * mass * r * r * double(s.alpha(i, k));
        }
      });
}

}  // namespace polymech::dem
