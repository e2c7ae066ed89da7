// Particle state of non-ordinary state-based (NOSB, "correspondence") peridynamics (seed 003 §3):
// the shared particle set (kernels/particles: x0, u, v, a, volume, constraints) and what the pd
// kernels add to it, and the small parameter structs the kernels take.
//
// The bond vector is Y = xi + (u_j - u_i) with xi = x0_j - x0_i, so float keeps full relative precision
// of the deformation. Per-particle matrices (F, K^-1, P K^-1, Cauchy stress) are stored row-major in
// Views with a trailing extent D*D (or 6 for symmetric 3x3 tensors, Voigt order xx yy zz yz xz xy).
//
// Views of effects that are not enabled stay empty (extent 0): kernels test `extent(0) > 0` or a
// flag in their parameter struct, and never touch them.
#pragma once

#include <cstdint>

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/neighbor_loop.hpp"
#include "particles/particle_set.hpp"

namespace polymech::pd {

template <class T, int D>
using MatView = Kokkos::View<T* [D * D], Kokkos::LayoutRight, MemSpace>;
template <class T>
using SymView = Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>;

// Particle status flags (bits of Fields::status).
enum StatusBits : std::uint8_t {
  status_failed = 1,       // too few intact bonds for an invertible shape tensor: carries no stress
  status_shape_known = 2,  // kinv holds K^-1 of the current intact family
  status_crushed = 4,      // F left the admissible volume range (inverted or blown up): failed for good
};

using particles::constrain_all;

// x0, u, v, a (internal force density / rho + external force / m), volume V_i and the constraints
// come from the particle set.
template <class T, int D>
struct Fields : particles::ParticleSet<T, D> {
  // per particle, from the deformation-gradient pass
  MatView<T, D> kinv;  // K_i^-1, inverse shape tensor (eq. (1), right factor)
  MatView<T, D> F;     // deformation gradient F_i (eq. (1))
  MatView<T, D> Fdot;  // rate dF/dt (only with a rate-dependent law)
  MatView<T, D> A;     // P_i K_i^-1: the force state is T_i<xi> = omega A_i xi
  View1<T> damage;     // 1 - (intact bond weight) / (all bond weight)
  Kokkos::View<std::uint8_t*, MemSpace> status;
  // J2 / Johnson-Cook state (empty for the elastic law)
  SymView<T> sigma;     // Cauchy stress
  View1<T> eps_p;       // equivalent plastic strain
  View1<T> temperature;  // adiabatic temperature (thermal softening)
  View1<T> plastic_work;  // accumulated plastic work per reference volume [J/m^3]
  // per bond, aligned with family.neighbors
  View1<T> bond_weight;                               // W_ij (V_ij or W'_ij of eq. (2)), from the reference configuration
  Kokkos::View<std::uint8_t*, MemSpace> bond_intact;  // damage effect only
  // velocity_viscosity effect (eq. (3)); empty otherwise
  VecView<T, D> vbar;            // weighted mean velocity over the intact family
  View1<T> horizon_weight;       // V_H,i: sum of the intact bond weights of i
  VecView<T, D> vv_state;        // t_i, the zero-energy force state of eq. (3) (the same for every bond of i)
  View1<T> viscous_work;         // work done on particle i by the velocity-viscosity forces [J]
  VecView<T, D> vv_force;        // the velocity-viscosity force density of the last evaluation
  // hourglass effect; empty otherwise
  View1<T> hourglass_work;       // work done on particle i by the stabilisation forces [J]
  VecView<T, D> hg_force;        // the hourglass force density of the last evaluation
};

// Bond weights of eq. (1): V_ij (plain: the neighbour's volume V_j) or, with the weighted_function
// effect, W'_ij = beta V_j (1 - |xi|^2 / delta^2) (eq. (2)).
template <class T>
struct BondWeight {
  T delta2 = T(1);  // delta^2
  T beta = T(1);
  bool weighted = false;

  // seed 003 eq. (2) for |xi| < delta (the family only holds such bonds); plain V_ij otherwise.
  KOKKOS_INLINE_FUNCTION T operator()(T volume_j, T xi2) const {
    if (!weighted) return volume_j;
    const T s = T(1) - xi2 / delta2;
    return s > T(0) ? beta * volume_j * s : T(0);
  }
};

// Kernel "polymech::pd::bond_weights": W_ij of every bond of the family, once (they depend on the
// reference configuration only; stored, the bond passes stream them instead of recomputing them).
template <class T, int D>
struct BondWeights {
  VecView<T, D> x0;
  View1<T> volume;
  BondWeight<T> weight;
  View1<T> out;
  struct Accumulator {
    Vec<T, D> xi0;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const { return {load<D>(x0, i)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    T xi2 = T(0);
    for (int d = 0; d < D; ++d) xi2 += (x0(j, d) - acc.xi0[d]) * (x0(j, d) - acc.xi0[d]);
    out(k) = weight(volume(j), xi2);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index, Accumulator&) const {}
  KOKKOS_INLINE_FUNCTION static void join(Accumulator&, const Accumulator&) {}
};

template <class T, int D>
void bond_weights(const neighbors::BondFamily& family, const VecView<T, D>& x0, const View1<T>& volume,
                  const BondWeight<T>& weight, const View1<T>& out) {
  neighbors::for_each_row("polymech::pd::bond_weights", family, BondWeights<T, D>{x0, volume, weight, out});
}

// Matrices in row-major Views with trailing extent D*D.
template <int D, class ViewT>
KOKKOS_INLINE_FUNCTION Mat<typename ViewT::non_const_value_type, D> load_mat(const ViewT& v, std::int64_t i) {
  Mat<typename ViewT::non_const_value_type, D> m;
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) m.a[r][c] = v(i, r * D + c);
  return m;
}
template <int D, class ViewT, class T>
KOKKOS_INLINE_FUNCTION void store_mat(const ViewT& v, std::int64_t i, const Mat<T, D>& m) {
  for (int r = 0; r < D; ++r)
    for (int c = 0; c < D; ++c) v(i, r * D + c) = m.a[r][c];
}

// Symmetric 3x3 in Voigt order (xx yy zz yz xz xy).
template <class ViewT>
KOKKOS_INLINE_FUNCTION Mat3<typename ViewT::non_const_value_type> load_sym(const ViewT& v, std::int64_t i) {
  Mat3<typename ViewT::non_const_value_type> m;
  m.a[0][0] = v(i, 0);
  m.a[1][1] = v(i, 1);
  m.a[2][2] = v(i, 2);
  m.a[1][2] = m.a[2][1] = v(i, 3);
  m.a[0][2] = m.a[2][0] = v(i, 4);
  m.a[0][1] = m.a[1][0] = v(i, 5);
  return m;
}
template <class ViewT, class T>
KOKKOS_INLINE_FUNCTION void store_sym(const ViewT& v, std::int64_t i, const Mat3<T>& m) {
  v(i, 0) = m.a[0][0];
  v(i, 1) = m.a[1][1];
  v(i, 2) = m.a[2][2];
  v(i, 3) = m.a[1][2];
  v(i, 4) = m.a[0][2];
  v(i, 5) = m.a[0][1];
}

// 2D plane strain <-> 3D: a 2x2 F is the in-plane block of a 3x3 with F33 = 1.
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat3<T> embed3(const Mat<T, D>& m) {
  if constexpr (D == 3) {
    return m;
  } else {
    Mat3<T> r = Mat3<T>::identity();
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) r.a[a][b] = m.a[a][b];
    return r;
  }
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> block(const Mat3<T>& m) {
  if constexpr (D == 3) {
    return m;
  } else {
    Mat2<T> r;
    for (int a = 0; a < 2; ++a)
      for (int b = 0; b < 2; ++b) r.a[a][b] = m.a[a][b];
    return r;
  }
}

}  // namespace polymech::pd
