// The spheres of a DEM model: the shared particle set (x0, u, v, a) with what a rotating sphere adds
// (radius, mass, angular velocity and acceleration) and the current positions the broad phase bins.
// The integrator is the shared velocity Verlet (particles::kick / drift) plus kick_rotation for the
// spin; a sphere's orientation is not tracked (its contacts do not depend on it); a clump's is, in its rigid
// body (kernels/dem/clumps.hpp).
#pragma once

#include <string>
#include <type_traits>

#include "particles/particle_set.hpp"

namespace polymech::dem {

template <class T>
struct SphereSet : particles::ParticleSet<T, 3> {
  View1<T> radius, mass;
  VecView<T, 3> omega;  // angular velocity
  VecView<T, 3> alpha;  // angular acceleration (torque / I, I = 2/5 m r^2)
  VecView<T, 3> x;      // current positions x0 + u (current_positions())
  View1<int> body;      // the clump of a member sphere, -1 for a free sphere (empty without clumps)
};

template <class T>
void allocate(SphereSet<T>& s, Index n, const std::string& prefix) {
  particles::allocate<T, 3>(s, n, prefix);
  const auto size = static_cast<std::size_t>(n);
  s.radius = View1<T>(prefix + "radius", size);
  s.mass = View1<T>(prefix + "mass", size);
  s.omega = VecView<T, 3>(prefix + "omega", size);
  s.alpha = VecView<T, 3>(prefix + "alpha", size);
  s.x = VecView<T, 3>(prefix + "x", size);
}

// Kernel "polymech::dem::current_positions": x = x0 + u.
template <class T>
void current_positions(const SphereSet<T>& s) {
  const auto x = s.x, x0 = s.x0, u = s.u;
  Kokkos::parallel_for(
      "polymech::dem::current_positions", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) x(i, k) = x0(i, k) + u(i, k);
      });
}

// Kernel "polymech::dem::body_forces": a = g, alpha = 0 (the contact kernels add to both).
template <class T>
void body_forces(const SphereSet<T>& s, const Vec3<T>& g) {
  const auto a = s.a, alpha = s.alpha;
  Kokkos::parallel_for(
      "polymech::dem::body_forces", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) {
          a(i, k) = g[k];
          alpha(i, k) = T(0);
        }
      });
}

// Kernel "polymech::dem::kick_rotation": omega += h alpha (velocity Verlet's half kick of the spin).
template <class T>
void kick_rotation(const SphereSet<T>& s, T h) {
  const auto omega = s.omega, alpha = s.alpha;
  Kokkos::parallel_for(
      "polymech::dem::kick_rotation", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) omega(i, k) += h * alpha(i, k);
      });
}

// The DEM step's integrator passes, fused (one pass over the spheres each, the same arithmetic as
// particles::kick / drift and kick_rotation):
// kernel "polymech::dem::kick_drift": v += h a, omega += h alpha, u += dt v (velocity Verlet's first half);
template <class T>
void kick_drift(const SphereSet<T>& s, T h, T dt) {
  const auto u = s.u, v = s.v, a = s.a, omega = s.omega, alpha = s.alpha;
  Kokkos::parallel_for(
      "polymech::dem::kick_drift", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) {
          v(i, k) += h * a(i, k);
          omega(i, k) += h * alpha(i, k);
          u(i, k) += dt * v(i, k);
        }
      });
}
// kernel "polymech::dem::kick_drift" (a reduction here): the first half and start_forces below in one pass
// over the spheres (a step of spheres without clumps: nothing moves them between the two): v += h a,
// omega += h alpha, u += dt v, x = x0 + u, a = g, alpha = 0; returns the largest |x - x_build| (the Verlet
// list's displacement check, neighbors::max_displacement's value bit for bit; 0 for an empty x_build).
// On a host, each call of kick_drift_start's body takes a block of spheres and keeps its running maximum
// in a register (one sphere per call kept it in memory: a store and a load each sphere); on a GPU, one.
inline constexpr Index kick_drift_block = std::is_same<MemSpace, HostSpace>::value ? 16 : 1;
template <class T>
T kick_drift_start(const SphereSet<T>& s, T h, T dt, const Vec3<T>& g, const VecView<T, 3>& x_build) {
  const auto u = s.u, v = s.v, a = s.a, omega = s.omega, alpha = s.alpha, x = s.x, x0 = s.x0;
  const bool check = x_build.extent(0) == static_cast<std::size_t>(s.size());
  const Index n = s.size();
  const Index block = kick_drift_block;
  T m2 = T(0);
  Kokkos::parallel_reduce(
      "polymech::dem::kick_drift", range((n + block - 1) / block),
      KOKKOS_LAMBDA(const Index b, T& m) {
        T mb = m;
        const Index end = (b + 1) * block < n ? (b + 1) * block : n;
        for (Index i = b * block; i < end; ++i) {
          // whole spheres in registers: every View is read once and written once (the Views may alias for
          // the compiler, so a component written and read again would be loaded again)
          Vec3<T> vi = load<3>(v, i), wi = load<3>(omega, i), ui = load<3>(u, i), xi;
          const Vec3<T> ai = load<3>(a, i), alphai = load<3>(alpha, i), x0i = load<3>(x0, i);
          for (int k = 0; k < 3; ++k) {
            vi[k] += h * ai[k];
            wi[k] += h * alphai[k];
            ui[k] += dt * vi[k];
            xi[k] = x0i[k] + ui[k];
          }
          store<3>(v, i, vi);
          store<3>(omega, i, wi);
          store<3>(u, i, ui);
          store<3>(x, i, xi);
          store<3>(a, i, g);
          store<3>(alpha, i, Vec3<T>::zero());
          if (check) {
            const Vec3<T> xb = load<3>(x_build, i);
            T d2 = T(0);
            for (int k = 0; k < 3; ++k) {
              const T d = xi[k] - xb[k];
              d2 += d * d;
            }
            mb = d2 > mb ? d2 : mb;
          }
        }
        m = mb;
      },
      Kokkos::Max<T>(m2));
  return kx::sqrt(m2);
}
// kernel "polymech::dem::kick": v += h a, omega += h alpha (its second half);
template <class T>
void kick(const SphereSet<T>& s, T h) {
  const auto v = s.v, a = s.a, omega = s.omega, alpha = s.alpha;
  Kokkos::parallel_for(
      "polymech::dem::kick", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) {
          v(i, k) += h * a(i, k);
          omega(i, k) += h * alpha(i, k);
        }
      });
}
// kernel "polymech::dem::start_forces": x = x0 + u, a = g, alpha = 0 (current_positions + body_forces).
template <class T>
void start_forces(const SphereSet<T>& s, const Vec3<T>& g) {
  const auto x = s.x, x0 = s.x0, u = s.u, a = s.a, alpha = s.alpha;
  Kokkos::parallel_for(
      "polymech::dem::start_forces", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        for (int k = 0; k < 3; ++k) {
          x(i, k) = x0(i, k) + u(i, k);
          a(i, k) = g[k];
          alpha(i, k) = T(0);
        }
      });
}

}  // namespace polymech::dem
