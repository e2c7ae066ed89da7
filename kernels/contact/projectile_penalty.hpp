// Penalty contact between a rigid projectile and particles (seed 003 §3(3), Fig. 3: a rigid
// cylindrical projectile perforating a plate). Each particle is a sphere of contact radius r_c; where
// it overlaps the projectile by d along the shortest way out n, it is pushed with k d n and the
// projectile with -k d n (frictionless). Shapes:
//  - blunt cylinder: axis along the last coordinate (z in 3D, y in 2D), flat nose face at
//    `position[D-1]`, body up to `position[D-1] + length`; radius `radius`;
//  - sphere (a disc in 2D): centre `position`, radius `radius`.
// One pass over all particles (O(N), no search); the reaction is summed in a thread-count
// independent order by the caller (particles::vector_sum over `force`).
#pragma once

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "particles/reductions.hpp"

namespace polymech::contact {

enum class ProjectileShape { blunt_cylinder, sphere };

template <class T, int D>
struct RigidProjectile {
  ProjectileShape shape = ProjectileShape::blunt_cylinder;
  T radius = T(0);
  T length = T(0);
  Vec<T, D> position = Vec<T, D>::zero();
};

template <class T, int D>
struct Overlap {
  T depth = T(0);          // > 0: in contact
  Vec<T, D> normal = Vec<T, D>::zero();  // unit vector out of the projectile
};

// Overlap of a particle (centre p, contact radius rc) with the projectile.
template <class T, int D>
KOKKOS_INLINE_FUNCTION Overlap<T, D> projectile_overlap(const RigidProjectile<T, D>& q, const Vec<T, D>& p, T rc) {
  Overlap<T, D> o;
  const Vec<T, D> d = p - q.position;
  if (q.shape == ProjectileShape::sphere) {
    const T r = norm(d);
    const T depth = q.radius + rc - r;
    if (depth > T(0) && r > T(0)) {
      o.depth = depth;
      o.normal = (T(1) / r) * d;
    }
    return o;
  }
  Vec<T, D> radial = d;
  radial[D - 1] = T(0);
  const T rho = norm(radial);
  const T zeta = d[D - 1];  // height above the nose face
  const T side = q.radius + rc - rho, face = zeta + rc, top = q.length + rc - zeta;
  if (side <= T(0) || face <= T(0) || top <= T(0)) return o;
  if (face <= side && face <= top) {
    o.depth = face;
    o.normal[D - 1] = T(-1);
  } else if (side <= top && rho > T(0)) {
    o.depth = side;
    o.normal = (T(1) / rho) * radial;
  } else {
    o.depth = top;
    o.normal[D - 1] = T(1);
  }
  return o;
}

// Kernel "polymech::contact::projectile_penalty": force[i] = k d n on every overlapping particle
// (zero elsewhere), and a[i] += force[i] / (rho V_i). Positions are x0 + u.
template <class T, int D>
void projectile_penalty(const RigidProjectile<T, D>& q, T stiffness, T contact_radius, const VecView<T, D>& x0,
                        const VecView<T, D>& u, const View1<T>& volume, T density, const VecView<T, D>& force,
                        const VecView<T, D>& a) {
  Kokkos::parallel_for(
      "polymech::contact::projectile_penalty", range(static_cast<std::int64_t>(x0.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        const Overlap<T, D> o = projectile_overlap(q, load<D>(x0, i) + load<D>(u, i), contact_radius);
        const Vec<T, D> fi = (stiffness * o.depth) * o.normal;
        store<D>(force, i, fi);
        if (o.depth > T(0)) {
          const T inv_m = T(1) / (density * volume(i));
          for (int k = 0; k < D; ++k) a(i, k) += inv_m * fi[k];
        }
      });
}

// sum_i |f_i|^2 / (2 k): energy stored in the penalty springs of the contact forces f_i.
template <class T, int D>
double penalty_energy(const VecView<T, D>& force, double stiffness) {
  const double inv2k = 0.5 / stiffness;
  const auto s = particles::ordered_sum<1>(
      "polymech::contact::penalty_energy", static_cast<std::int64_t>(force.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        double f2 = 0;
        for (int k = 0; k < D; ++k) f2 += double(force(i, k)) * double(force(i, k));
        acc[0] += f2 * inv2k;
      });
  return s[0];
}

}  // namespace polymech::contact
