// A rigid body in 2D or 3D: a peridynamic projectile (seed 003), the floating cylinder of ISPH (seed 002
// paper 4) and every multi-sphere DEM clump (seed 002 paper 2) are this one type. State in double (a
// body's pose must not lose the small motions of the particles around it); usable on the host for one
// body and inside kernels for many (a View of bodies).
//
//   mass m, principal moments of inertia I (body frame; 2D: one about z), centre x, orientation
//   (2D: angle theta; 3D: unit quaternion q, body -> world), velocity v, angular velocity
//   (2D: omega; 3D: from the angular momentum L, world frame), and the force and torque accumulated
//   since the last clear_loads().
//
// Half-step updates, the rigid part of velocity Verlet (kick - drift - forces - kick):
//   kick(h):   v += h F / m;   2D: omega += h tau / I;   3D: L += h tau
//   drift(dt): x += dt v;      2D: theta += dt omega;    3D: q <- exp(dt/2 w) q, w = R I^-1 R^T L
//   kick_added_mass(h, m_a): kick with the mass m + m_a, the increment rounded as (h F) / m (ISPH)
// The 3D drift rotates by the exact rotation of the angular velocity at the start of the drift (a unit
// quaternion stays unit; renormalised against round-off). A body may be translation-only
// (`rotation_locked`): its orientation stays and torques are ignored.
#pragma once

#include "core/small_math.hpp"

namespace polymech::rigid {

template <int D>
struct RigidBody {
  static_assert(D == 2 || D == 3, "RigidBody is 2D or 3D");
  static constexpr int rotational = D == 3 ? 3 : 1;  // rotational degrees of freedom

  double mass = 0.0;
  double inertia[rotational] = {};   // principal moments, body frame
  double position[D] = {};
  double velocity[D] = {};
  double orientation[D == 3 ? 4 : 1] = {};  // 2D: angle; 3D: quaternion (w, x, y, z), set by the constructor
  double spin[rotational] = {};      // 2D: angular velocity omega; 3D: angular momentum L (world frame)
  double force[D] = {};
  double torque[rotational] = {};
  bool rotation_locked = false;

  KOKKOS_INLINE_FUNCTION RigidBody() {
    if constexpr (D == 3) orientation[0] = 1.0;
  }

  KOKKOS_INLINE_FUNCTION void clear_loads() {
    for (int k = 0; k < D; ++k) force[k] = 0.0;
    for (int k = 0; k < rotational; ++k) torque[k] = 0.0;
  }

  // Force F acting at world point p: F and (p - x) x F.
  KOKKOS_INLINE_FUNCTION void add_force_at(const double (&f)[D], const double (&p)[D]) {
    for (int k = 0; k < D; ++k) force[k] += f[k];
    const double r0 = p[0] - position[0], r1 = p[1] - position[1];
    if constexpr (D == 2) {
      torque[0] += r0 * f[1] - r1 * f[0];
    } else {
      const double r2 = p[2] - position[2];
      torque[0] += r1 * f[2] - r2 * f[1];
      torque[1] += r2 * f[0] - r0 * f[2];
      torque[2] += r0 * f[1] - r1 * f[0];
    }
  }

  KOKKOS_INLINE_FUNCTION void kick(double h) {
    for (int k = 0; k < D; ++k) {
      const double acceleration = force[k] / mass;
      velocity[k] += h * acceleration;
    }
    if (rotation_locked) return;
    if constexpr (D == 2)
      spin[0] += h * (torque[0] / inertia[0]);
    else
      for (int k = 0; k < 3; ++k) spin[k] += h * torque[k];
  }

  // The kick of an explicit staggered coupling with an added mass m_a (the ISPH floating body, seed 002
  // paper 4 eqs. (31)-(32)): v += h F / (m + m_a); 2D: omega += h tau / I; 3D: L += h tau. Each increment
  // is formed as (h F) / m, as the ISPH model's Euler update always formed it (kick's h (F / m) can differ
  // in the last bit). The caller's F holds the explicit part m_a a_n of the added-mass term (added_mass 0:
  // the paper's plain update; m_a stays out of `mass`, so kinetic_energy() is the body's own).
  KOKKOS_INLINE_FUNCTION void kick_added_mass(double h, double added_mass) {
    for (int k = 0; k < D; ++k) velocity[k] += h * force[k] / (mass + added_mass);
    if (rotation_locked) return;
    if constexpr (D == 2)
      spin[0] += h * torque[0] / inertia[0];
    else
      for (int k = 0; k < 3; ++k) spin[k] += h * torque[k];
  }

  KOKKOS_INLINE_FUNCTION void drift(double dt) {
    for (int k = 0; k < D; ++k) position[k] += dt * velocity[k];
    if (rotation_locked) return;
    if constexpr (D == 2) {
      orientation[0] += dt * spin[0];
    } else {
      double w[3];
      angular_velocity(w);
      const double angle = dt * kx::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      if (angle == 0.0) return;
      const double s = kx::sin(0.5 * angle) / (angle / dt), c = kx::cos(0.5 * angle);
      const double r[4] = {c, s * w[0], s * w[1], s * w[2]};  // exp(dt/2 w)
      double q[4];
      quaternion_product(r, orientation, q);
      const double inv = 1.0 / kx::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for (int k = 0; k < 4; ++k) orientation[k] = inv * q[k];
    }
  }

  // 2D: omega; 3D: w = R I^-1 R^T L.
  KOKKOS_INLINE_FUNCTION void angular_velocity(double (&w)[rotational]) const {
    if constexpr (D == 2) {
      w[0] = spin[0];
    } else {
      double b[3];
      to_body(spin, b);
      for (int k = 0; k < 3; ++k) b[k] = inertia[k] > 0.0 ? b[k] / inertia[k] : 0.0;
      to_world(b, w);
    }
  }

  // Rotation of a vector from the body frame to the world frame, and back.
  KOKKOS_INLINE_FUNCTION void to_world(const double (&b)[D], double (&w)[D]) const { rotate(b, w, false); }
  KOKKOS_INLINE_FUNCTION void to_body(const double (&w)[D], double (&b)[D]) const { rotate(w, b, true); }

  // Velocity of the body's material point at world position p: v + omega x (p - x).
  KOKKOS_INLINE_FUNCTION void velocity_at(const double (&p)[D], double (&out)[D]) const {
    double w[rotational];
    angular_velocity(w);
    const double r0 = p[0] - position[0], r1 = p[1] - position[1];
    if constexpr (D == 2) {
      out[0] = velocity[0] - w[0] * r1;
      out[1] = velocity[1] + w[0] * r0;
    } else {
      const double r2 = p[2] - position[2];
      out[0] = velocity[0] + w[1] * r2 - w[2] * r1;
      out[1] = velocity[1] + w[2] * r0 - w[0] * r2;
      out[2] = velocity[2] + w[0] * r1 - w[1] * r0;
    }
  }

  KOKKOS_INLINE_FUNCTION double kinetic_energy() const {
    double e = 0.0;
    for (int k = 0; k < D; ++k) e += 0.5 * mass * velocity[k] * velocity[k];
    if (!rotation_locked) {
      double w[rotational];
      angular_velocity(w);
      if constexpr (D == 2)
        e += 0.5 * inertia[0] * w[0] * w[0];
      else
        for (int k = 0; k < 3; ++k) e += 0.5 * w[k] * spin[k];  // 1/2 w . L
    }
    return e;
  }

 private:
  KOKKOS_INLINE_FUNCTION void rotate(const double (&x)[D], double (&y)[D], bool inverse) const {
    if constexpr (D == 2) {
      const double c = kx::cos(orientation[0]), s = inverse ? -kx::sin(orientation[0]) : kx::sin(orientation[0]);
      y[0] = c * x[0] - s * x[1];
      y[1] = s * x[0] + c * x[1];
    } else {
      // y = q x q* (inverse: q* x q)
      const double w = orientation[0], sgn = inverse ? -1.0 : 1.0;
      const double u[3] = {sgn * orientation[1], sgn * orientation[2], sgn * orientation[3]};
      // t = 2 u x x;  y = x + w t + u x t
      const double t[3] = {2.0 * (u[1] * x[2] - u[2] * x[1]), 2.0 * (u[2] * x[0] - u[0] * x[2]),
                           2.0 * (u[0] * x[1] - u[1] * x[0])};
      y[0] = x[0] + w * t[0] + (u[1] * t[2] - u[2] * t[1]);
      y[1] = x[1] + w * t[1] + (u[2] * t[0] - u[0] * t[2]);
      y[2] = x[2] + w * t[2] + (u[0] * t[1] - u[1] * t[0]);
    }
  }
  KOKKOS_INLINE_FUNCTION static void quaternion_product(const double (&a)[4], const double (&b)[4], double (&c)[4]) {
    c[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
    c[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
    c[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
    c[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
  }
};

// Mass, centre and principal inertia of a body from weighted sample points (quadrature points of a
// meshed body, or the cells of a voxelised union of spheres): host, in double. Principal axes other
// than the coordinate axes are not diagonalised here: the caller sets the orientation from them.
struct MassProperties {
  double mass = 0.0;
  double centre[3] = {0, 0, 0};
  double inertia[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};  // about the centre, world axes
};

// points: n x D coordinates; masses: n.
template <int D, class Points, class Masses>
MassProperties mass_properties(const Points& points, const Masses& masses, std::int64_t n) {
  MassProperties p;
  for (std::int64_t i = 0; i < n; ++i) {
    p.mass += masses[i];
    for (int k = 0; k < D; ++k) p.centre[k] += masses[i] * points[i * D + k];
  }
  if (!(p.mass > 0.0)) return p;
  for (int k = 0; k < D; ++k) p.centre[k] /= p.mass;
  for (std::int64_t i = 0; i < n; ++i) {
    double r[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) r[k] = points[i * D + k] - p.centre[k];
    const double r2 = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) p.inertia[a][b] += masses[i] * ((a == b ? r2 : 0.0) - r[a] * r[b]);
  }
  return p;
}

}  // namespace polymech::rigid
