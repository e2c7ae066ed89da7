// The kernels of a rigid body in the ISPH fluid (seed 002 paper 4, 2D): its IGCB points moved with the
// body, the fluid force and moment on it, eqs. (36)-(37) with (42)-(43), the pressure force by the surface
// integral (difference form of the gradient), and the safety net that keeps fluid particles out of it.
// The body is a disc whose wall points are [begin, begin + offset.extent(0)) of the WallPoints.
#pragma once

#include "sph/gradient.hpp"

namespace polymech::sph {

// The body's pose and motion as the kernels read it (precision T): centre, angle, velocity, angular
// velocity, acceleration and angular acceleration.
template <class T>
struct BodyMotion {
  T cx, cy, theta, vx, vy, omega, ax, ay, alpha;
};

// Moves the body's points rigidly: x = c + Rot(theta) r0, the ghost mirrored through the circle
// (q = c + R (x - c)/|x - c|, ghost = 2q - x, n = -(x - c)/|x - c|, d = 2 (R - |x - c|)), the wall
// velocity v + omega x r and acceleration a + alpha x r - omega^2 r (eq. (25)).
template <class T, int D>
void place_body(const WallPoints<T, D>& wp, const VecView<T, D>& offset, Index begin, T R, const BodyMotion<T>& m) {
  const T cx = m.cx, cy = m.cy, vx = m.vx, vy = m.vy, om = m.omega, ax = m.ax, ay = m.ay, al = m.alpha;
  const T cs = kx::cos(m.theta), sn = kx::sin(m.theta);
  Kokkos::parallel_for(
      "polymech::sph::place_body", range(static_cast<Index>(offset.extent(0))), KOKKOS_LAMBDA(const Index k) {
        const Index w = begin + k;
        const T rx = cs * offset(k, 0) - sn * offset(k, 1), ry = sn * offset(k, 0) + cs * offset(k, 1);
        const T r = kx::sqrt(rx * rx + ry * ry);
        const T ex = rx / r, ey = ry / r;
        wp.x(w, 0) = cx + rx;
        wp.x(w, 1) = cy + ry;
        const T qx = cx + R * ex, qy = cy + R * ey;
        wp.ghost(w, 0) = T(2) * qx - (cx + rx);
        wp.ghost(w, 1) = T(2) * qy - (cy + ry);
        wp.normal(w, 0) = -ex;
        wp.normal(w, 1) = -ey;
        wp.dist(w) = T(2) * (R - r);
        wp.velocity(w, 0) = vx - om * ry;
        wp.velocity(w, 1) = vy + om * rx;
        wp.accel(w, 0) = ax - al * ry - om * om * rx;
        wp.accel(w, 1) = ay + al * rx - om * om * ry;
      });
}

// The fluid force and moment on the body, eqs. (36)-(37) with (42)-(43): minus the wall force of each
// (particle, body point) pair, summed. out = {Fx, Fy, M about the centre (cx, cy)}.
template <class T, int D>
void body_force(const neighbors::NeighborList& list, const Fluid<T, D>& f, const WallPoints<T, D>& wp,
                const Params<T, D>& c, Index begin, T cx, T cy, double* out) {
  double fx = 0, fy = 0, mz = 0;
  Kokkos::parallel_reduce(
      "polymech::sph::body_force", range(list.num_particles),
      KOKKOS_LAMBDA(const Index i, double& ax, double& ay, double& am) {
        for (Offset k = list.begin(i); k < list.end(i); ++k) {
          const Index w = list.neighbor(k);
          if (w < begin) continue;
          Vec<T, D> fw, fv;
          wall_pair_force_parts<T, D>(f, wp, c, i, w, fw, fv);
          if (c.difference_gradient) fw = Vec<T, D>::zero();  // the pressure from body_surface_force
          fw += fv;
          const double gx = -double(fw[0]), gy = -double(fw[1]);  // eq. (42)
          ax += gx;
          ay += gy;
          am += (double(wp.x(w, 0)) - double(cx)) * gy - (double(wp.x(w, 1)) - double(cy)) * gx;  // eq. (37)
        }
      },
      fx, fy, mz);
  out[0] = fx;
  out[1] = fy;
  out[2] = mz;
}

// With the difference form of the pressure gradient the pair terms of eq. (40) are not the force between
// a particle and the wall (they need not sum to it: the form does not conserve momentum pair by pair), so
// the body's pressure force is the surface integral -oint p n_out ds over its circle, with p the fluid's
// pressure at the surface point of each outer-ring point (sph::SurfacePressure: the linear fit of the
// ghost's neighbours, 0 above the water), each point carrying the arc R dtheta of its cell. Adds to
// out[0..1]; a circle's pressure has no moment about its centre.
template <class T, int D>
void body_surface_force(const WallPoints<T, D>& wp, const View1<T>& ps, Index begin, Index count, double arc,
                        double* out) {
  double fx = 0, fy = 0;
  Kokkos::parallel_reduce(
      "polymech::sph::body_surface_force", range(count),
      KOKKOS_LAMBDA(const Index k, double& ax, double& ay) {
        const Index w = begin + k;
        ax += double(ps(k)) * double(wp.normal(w, 0)) * arc;
        ay += double(ps(k)) * double(wp.normal(w, 1)) * arc;
      },
      fx, fy);
  out[0] += fx;
  out[1] += fy;
}

// Puts every fluid particle closer than rmin to the centre (cx, cy) back at rmin, radially (a safety net
// for the explicit coupling); returns how many it moved.
template <class T, int D>
long long push_out_of_body(const Fluid<T, D>& f, T cx, T cy, T rmin) {
  long long n = 0;
  Kokkos::parallel_reduce(
      "polymech::sph::push_out_of_body", range(f.size()),
      KOKKOS_LAMBDA(const Index i, long long& count) {
        const Vec<T, D> x = f.p.position(i);
        const T dx = x[0] - cx, dy = x[1] - cy, r = kx::sqrt(dx * dx + dy * dy);
        if (r >= rmin || r <= T(0)) return;
        f.p.u(i, 0) += (rmin - r) * dx / r;
        f.p.u(i, 1) += (rmin - r) * dy / r;
        ++count;
      },
      n);
  return n;
}

}  // namespace polymech::sph
