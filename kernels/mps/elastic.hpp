// Elastic-wave MPS in 2D plane strain (seed 000 §2.3 and §3): relative displacement with particle
// rotation, volumetric strain, the translational equation (11), the rotational equation (12) and
// the rotation part of symplectic Euler (15)-(16) (eqs. (13)-(14): particles::symplectic_euler).
//
// State is the displacement u from the reference lattice x0, not the position: with nanometre waves
// in a 0.1 m plate, positions in float would lose the signal entirely, while u keeps full relative
// precision in either type. The pair vector is r_ij = r0_ij + (u_j - u_i).
//
// The template flag Rotation selects the `rotation` effect: with it, u_ij subtracts the particles'
// mean rotation (eq. (6)) and the force kernel also returns the angular acceleration (eq. (12));
// without it, theta/omega/alpha are never read, written or allocated.
#pragma once

#include "mps/weight.hpp"
#include "neighbors/neighbor_loop.hpp"
#include "particles/particle_set.hpp"

namespace polymech::mps {

// Material and discretisation constants of eq. (11)-(12), in the kernel's precision.
template <class T>
struct ElasticParams {
  T re;       // influence radius r_e
  T n0;       // reference number density
  T rho;      // density
  T c13;      // C13 (= Lame lambda)
  T c55;      // C55 (= shear modulus mu)
  T mass;     // particle mass m = rho l0^2 (per unit thickness)
  T inertia;  // particle moment of inertia I
};

// The particle set (x0: reference positions r0_i, u, v, a = dv/dt; no per-particle volume: every
// particle stands for one l0 x l0 cell) and the MPS state beside it.
template <class T>
struct ElasticFields : particles::ParticleSet<T, 2> {
  View1<T> inv_r0;   // 1 / |r0_ij| per bond of the family (aligned with family.neighbors)
  View1<T> e;        // volumetric strain <div u>_i
  // rotation effect only (empty Views otherwise)
  View1<T> theta;     // particle rotation angle
  View1<T> omega;     // angular velocity
  View1<T> alpha;     // angular acceleration
  View1<T> sin_theta;  // sin(theta), kept with theta so pair loops need no trigonometry
  View1<T> half_omc;   // (1 - cos theta) / 2 = sin^2(theta / 2)
};

// seed 000 eq. (6)-(7): u_ij = r_ij - 1/2 (R_i + R_j) r0_ij, written as
// (u_j - u_i) + (I - 1/2 (R_i + R_j)) r0_ij so nothing cancels catastrophically. I - R(theta) has
// entries 1 - cos theta = 2 sin^2(theta/2) and +-sin theta; both come precomputed per particle.
template <class T>
KOKKOS_INLINE_FUNCTION Vec2<T> relative_displacement(const Vec2<T>& du, const Vec2<T>& r0, T sin_i, T sin_j,
                                                     T half_omc_i, T half_omc_j) {
  const T one_minus_cos = half_omc_i + half_omc_j;  // 1/2 [(1 - cos ti) + (1 - cos tj)]
  const T sin_mean = T(0.5) * (sin_i + sin_j);
  return Vec2<T>{{du[0] + one_minus_cos * r0[0] + sin_mean * r0[1], du[1] - sin_mean * r0[0] + one_minus_cos * r0[1]}};
}

// What a pair needs of one particle: reference position, displacement and, with rotation, the
// precomputed sin(theta) and (1 - cos theta)/2. Loaded once per particle i, once per neighbour j.
template <class T, bool Rotation>
struct ParticleState {
  Vec2<T> x0, u;
  T sin_theta = T(0), half_omc = T(0);

  KOKKOS_INLINE_FUNCTION ParticleState(const ElasticFields<T>& f, Index i) : x0(load<2>(f.x0, i)), u(load<2>(f.u, i)) {
    if constexpr (Rotation) {
      sin_theta = f.sin_theta(i);
      half_omc = f.half_omc(i);
    }
  }
};

// Everything one pair (bond k = (i, j) of the family) needs, from the reference and current
// configurations. One square root and one division per pair: 1/|r0| comes per bond from set-up and
// w = re/r - 1 reuses 1/r.
template <class T, bool Rotation>
struct ElasticPair {
  Vec2<T> r;     // r_ij (current)
  Vec2<T> uij;   // relative displacement u_ij, eq. (6)
  T inv_r;       // 1 / |r_ij|
  T inv_r0;      // 1 / |r0_ij|
  T w;           // w(|r_ij|), eq. (1)

  KOKKOS_INLINE_FUNCTION ElasticPair(const ParticleState<T, Rotation>& pi, const ParticleState<T, Rotation>& pj,
                                     T inv_r0_ij, T re)
      : inv_r0(inv_r0_ij) {
    const Vec2<T> r0 = pj.x0 - pi.x0;
    const Vec2<T> du = pj.u - pi.u;
    r = r0 + du;
    inv_r = T(1) / kx::sqrt(norm2(r));
    w = re * inv_r > T(1) ? re * inv_r - T(1) : T(0);  // eq. (1) for r > 0
    if constexpr (Rotation)
      uij = relative_displacement(du, r0, pi.sin_theta, pj.sin_theta, pi.half_omc, pj.half_omc);
    else
      uij = du;
  }
  KOKKOS_INLINE_FUNCTION ElasticPair(const ElasticFields<T>& f, Index i, Index j, Offset k, T re)
      : ElasticPair(ParticleState<T, Rotation>(f, i), ParticleState<T, Rotation>(f, j), f.inv_r0(k), re) {}
};

// 1/|r0_ij| for every bond of the reference family (set-up, once).
template <class T>
struct ReferenceBondLengths {
  ElasticFields<T> f;
  struct Accumulator {
    Vec2<T> xi;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {load<2>(f.x0, i)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    f.inv_r0(k) = T(1) / norm(load<2>(f.x0, j) - acc.xi);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index, Accumulator&) const {}
  KOKKOS_INLINE_FUNCTION static void join(Accumulator&, const Accumulator&) {}
};

template <class T>
void reference_bond_lengths(const neighbors::BondFamily& family, const ElasticFields<T>& f) {
  neighbors::for_each_row("polymech::mps::reference_bond_lengths", family, ReferenceBondLengths<T>{f});
}

// The shape every MPS pair sum shares: i's state loaded once, a scalar summed over its pairs, the term
// of one pair computed by Derived::term from the ElasticPair (CRTP: no virtual calls in kernels).
template <class T, bool Rotation, class Derived>
struct ElasticPairSum {
  ElasticFields<T> f;
  T re;
  struct Accumulator {
    ParticleState<T, Rotation> pi;
    T s;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {ParticleState<T, Rotation>(f, i), T(0)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    const ElasticPair<T, Rotation> q(acc.pi, ParticleState<T, Rotation>(f, j), f.inv_r0(k), re);
    acc.s += Derived::term(q);
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) { into.s += from.s; }
};

// <div u>_i = d/n0 sum u_ij . r_ij / (|r0_ij| |r_ij|) w  (eq. (4), difference form, with eq. (6)).
template <class T, bool Rotation>
struct VolumetricStrain : ElasticPairSum<T, Rotation, VolumetricStrain<T, Rotation>> {
  T c;
  KOKKOS_INLINE_FUNCTION static T term(const ElasticPair<T, Rotation>& q) { return dot(q.uij, q.r) * q.w * q.inv_r0 * q.inv_r; }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, typename VolumetricStrain::Accumulator& acc) const { this->f.e(i) = c * acc.s; }
};

template <class T, bool Rotation, class Strategy = neighbors::SerialNeighbors>
void volumetric_strain(const neighbors::BondFamily& family, const ElasticFields<T>& f, const ElasticParams<T>& p,
                       Strategy strategy = {}) {
  VolumetricStrain<T, Rotation> physics;
  physics.f = f;
  physics.re = p.re;
  physics.c = T(2) / p.n0;
  neighbors::for_each_row(Rotation ? "polymech::mps::volumetric_strain_with_rotation" : "polymech::mps::volumetric_strain",
                          family, physics, strategy);
}

// seed 000 eq. (11): rho dv/dt = C13 div((div u) I) + 2 C55 lap u, with the symmetric divergence
// (eq. (4), psi_j + psi_i) and the Laplacian (eq. (5)) applied to u_ij. With Rotation, also
// eq. (12): each pair's shear force F_ij = m (2 C55 / rho) (2d/n0) u_ij w / |r0|^2 is not central;
// its moment M = (r_i - r_j) x F_ij is returned to the two particles' spins, I dw_i/dt = -M/2 each,
// so the total (orbital + spin) angular momentum is conserved.
template <class T, bool Rotation>
struct ElasticAcceleration {
  ElasticFields<T> f;
  T re, c_vol, c_lap, c_rot;
  struct Accumulator {
    ParticleState<T, Rotation> pi;
    T ei;
    Vec2<T> vol, lap;
    T moment;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const {
    return {ParticleState<T, Rotation>(f, i), f.e(i), Vec2<T>::zero(), Vec2<T>::zero(), T(0)};
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    const ElasticPair<T, Rotation> q(acc.pi, ParticleState<T, Rotation>(f, j), f.inv_r0(k), re);
    acc.vol += ((acc.ei + f.e(j)) * q.w * q.inv_r0 * q.inv_r) * q.r;
    const Vec2<T> shear = (q.w * q.inv_r0 * q.inv_r0) * q.uij;
    acc.lap += shear;
    if constexpr (Rotation) acc.moment += cross(q.r, shear);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    store<2>(f.a, i, c_vol * acc.vol + c_lap * acc.lap);
    if constexpr (Rotation) f.alpha(i) = c_rot * acc.moment;
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) {
    into.vol += from.vol;
    into.lap += from.lap;
    into.moment += from.moment;
  }
};

template <class T, bool Rotation, class Strategy = neighbors::SerialNeighbors>
void elastic_acceleration(const neighbors::BondFamily& family, const ElasticFields<T>& f, const ElasticParams<T>& p,
                          Strategy strategy = {}) {
  const T c_vol = p.c13 * T(2) / (p.n0 * p.rho);         // C13 d / (n0 rho)
  const T c_lap = T(2) * p.c55 * T(4) / (p.n0 * p.rho);  // 2 C55 2d / (n0 rho)
  const T c_rot = T(0.5) * p.mass / p.inertia * c_lap;  // (m / I) * 1/2
  neighbors::for_each_row(
      Rotation ? "polymech::mps::elastic_acceleration_with_rotation" : "polymech::mps::elastic_acceleration", family,
      ElasticAcceleration<T, Rotation>{f, p.re, c_vol, c_lap, c_rot}, strategy);
}

// seed 000 eqs. (15)-(16): omega^{k+1} = omega^k + dt (dw/dt)_sum;  theta^{k+1} = theta^k + dt omega^{k+1}.
template <class T>
void rotation_update(const ElasticFields<T>& f, T dt) {
  Kokkos::parallel_for(
      "polymech::mps::rotation_update", range(static_cast<std::int64_t>(f.theta.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        f.omega(i) += dt * f.alpha(i);
        const T theta = f.theta(i) + dt * f.omega(i);
        const T h = kx::sin(theta / T(2));
        f.theta(i) = theta;
        f.sin_theta(i) = kx::sin(theta);
        f.half_omc(i) = h * h;
      });
}

// Refresh sin(theta) and (1 - cos theta)/2 after theta was set directly (initial states, tests).
template <class T>
void rotation_trigonometry(const ElasticFields<T>& f) {
  Kokkos::parallel_for(
      "polymech::mps::rotation_trigonometry", range(static_cast<std::int64_t>(f.theta.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i) {
        const T h = kx::sin(f.theta(i) / T(2));
        f.sin_theta(i) = kx::sin(f.theta(i));
        f.half_omc(i) = h * h;
      });
}

// Energies of the discrete system (host values). The strain energy is the one whose gradient gives
// the forces above for small displacements: sum_i 1/2 V C13 e_i^2 + sum_pairs 1/2 k_ij |u_ij|^2 with
// k_ij = m (2 C55 / rho)(2d / n0) w / |r0_ij|^2 (each pair appears twice in a full list, hence 1/4).
struct ElasticEnergy {
  double kinetic = 0.0;  // translational + rotational
  double strain = 0.0;
  double total() const { return kinetic + strain; }
};

// sum_j w / |r0_ij|^2 |u_ij|^2 over the row of i.
template <class T, bool Rotation>
struct PairStrainEnergy : ElasticPairSum<T, Rotation, PairStrainEnergy<T, Rotation>> {
  KOKKOS_INLINE_FUNCTION static T term(const ElasticPair<T, Rotation>& q) { return q.w * q.inv_r0 * q.inv_r0 * norm2(q.uij); }
};

template <class T, bool Rotation>
ElasticEnergy elastic_energy(const neighbors::BondFamily& family, const ElasticFields<T>& f,
                             const ElasticParams<T>& p) {
  ElasticEnergy out;
  const T m = p.mass, inertia = p.inertia;
  T kinetic = T(0);
  Kokkos::parallel_reduce(
      "polymech::mps::kinetic_energy", range(family.num_particles),
      KOKKOS_LAMBDA(const Index i, T& s) {
        s += T(0.5) * m * (f.v(i, 0) * f.v(i, 0) + f.v(i, 1) * f.v(i, 1));
        // plain if: nvcc forbids an extended lambda's first capture (inertia) inside if constexpr
        if (Rotation) s += T(0.5) * inertia * f.omega(i) * f.omega(i);
      },
      kinetic);
  const T k_vol = T(0.5) * m * p.c13 / p.rho;
  const T k_lap = T(0.25) * m * T(2) * p.c55 * T(4) / (p.rho * p.n0);
  PairStrainEnergy<T, Rotation> pairs;
  pairs.f = f;
  pairs.re = p.re;
  T strain = T(0);
  Kokkos::parallel_reduce(
      "polymech::mps::strain_energy", range(family.num_particles),
      KOKKOS_LAMBDA(const Index i, T& s) {
        auto acc = pairs.start(i);
        neighbors::gather_row(family, i, pairs, acc);
        s += k_vol * f.e(i) * f.e(i) + k_lap * acc.s;
      },
      strain);
  out.kinetic = static_cast<double>(kinetic);
  out.strain = static_cast<double>(strain);
  return out;
}

}  // namespace polymech::mps
