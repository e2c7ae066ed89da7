// The second bond pass of a NOSB step: internal force density from the force states (the hot loop
// of the method), with the optional zero-energy controls folded into the same gather.
//
//   L_i = sum_j omega W_ij (T_i<xi_ij> - T_j<xi_ji>),  T_i<xi> = A_i xi,  A_i = P_i K_i^-1
//       = A_i (sum_j W_ij xi) + sum_j W_ij A_j xi       (omega = 1 on intact bonds)
//
// hourglass (Silling 2017, "Stability of peridynamic correspondence material models and their
// particle discretizations", CMAME 322): a stabilising force state proportional to the part of the
// bond that the affine map F_i does not explain, z_i<xi> = Y - F_i xi,
//   T^s_i<xi> = G_s c (z_i<xi> / |xi|),   c = 18 K / sum_j |xi| W_ij (the bond-based micromodulus),
// so L^s_i = G_s c sum_j W_ij (2 Y - (F_i + F_j) xi) / |xi|; it vanishes for every affine field.
//
// velocity_viscosity (seed 003 eq. (3)): T^ZE_i<xi> = t_i for every intact bond of i (pd/viscosity.hpp),
// so L^ZE_i = sum_j W_ij (t_i - t_j): equal and opposite pair terms (momentum is conserved).
//
// Gather over the full family in a fixed order: bitwise the same with any number of threads.
#pragma once

#include "pd/fields.hpp"

namespace polymech::pd {

template <class T>
struct ForceParams {
  T density = T(1);
  bool damage = false;         // skip broken bonds
  T hourglass_c = T(0);        // G_s c (hourglass effect)
  T work_dt = T(0);            // > 0: accumulate the work of the control forces over this step
};

// Work of a control force over one velocity-Verlet step, trapezoidal in time: the force f_n+1 found
// at x_n+1 and the one of the previous evaluation f_n both act over the step's velocity v_n+1/2,
//   W += dt/2 (f_n + f_n+1) . v_n+1/2 V_i,
// which sums to dt f_n . v_n over a run (v_n = the full-step velocity), the pairing under which a
// conservative force's work equals minus its potential change to second order; the rectangle rule
// dt f_n+1 . v_n+1/2 drifts by -k v^2 dt^2 / 2 per step for a spring of stiffness k.

namespace detail {
template <bool Hourglass, bool Viscosity>
constexpr const char* bond_forces_label() {
  if constexpr (Hourglass && Viscosity) return "polymech::pd::bond_forces_with_hourglass_velocity_viscosity";
  if constexpr (Hourglass) return "polymech::pd::bond_forces_with_hourglass";
  if constexpr (Viscosity) return "polymech::pd::bond_forces_with_velocity_viscosity";
  return "polymech::pd::bond_forces";
}
}  // namespace detail

// Writes a_i = L_i / rho (external forces are added afterwards).
template <class T, int D, bool Hourglass, bool Viscosity>
struct BondForces {
  Fields<T, D> f;
  bool damage;
  T inv_rho, hg_c, work_dt;
  struct Accumulator {
    Vec<T, D> xi0, ui;
    Vec<T, D> wxi;    // sum W xi
    Vec<T, D> fj;     // sum W A_j xi
    Vec<T, D> hg_y;   // sum W Y / |xi|
    Vec<T, D> hg_xi;  // sum W xi / |xi|
    Vec<T, D> hg_fj;  // sum W F_j xi / |xi|
    T wsum;
    Vec<T, D> tj;     // sum W t_j
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index i) const {
    const auto z = Vec<T, D>::zero();
    Accumulator acc{load<D>(f.x0, i), z, z, z, z, z, z, T(0), z};
    if (Hourglass) acc.ui = load<D>(f.u, i);
    return acc;
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index, Index j, Offset k) const {
    if (damage && !f.bond_intact(k)) return;
    const Vec<T, D> xi = load<D>(f.x0, j) - acc.xi0;
    const T w = f.bond_weight(k);
    acc.wxi += w * xi;
    acc.fj += w * (load_mat<D>(f.A, j) * xi);
    if (Hourglass) {
      const T wl = w / kx::sqrt(norm2(xi));
      acc.hg_y += wl * (xi + (load<D>(f.u, j) - acc.ui));
      acc.hg_xi += wl * xi;
      acc.hg_fj += wl * (load_mat<D>(f.F, j) * xi);
    }
    if (Viscosity) {
      acc.wsum += w;
      acc.tj += w * load<D>(f.vv_state, j);
    }
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    Vec<T, D> force = load_mat<D>(f.A, i) * acc.wxi + acc.fj;
    if (Hourglass) {
      const Vec<T, D> fs = hg_c * (T(2) * acc.hg_y - load_mat<D>(f.F, i) * acc.hg_xi - acc.hg_fj);
      force += fs;
      if (work_dt > T(0))
        f.hourglass_work(i) += T(0.5) * work_dt * f.volume(i) * dot(fs + load<D>(f.hg_force, i), load<D>(f.v, i));
      store<D>(f.hg_force, i, fs);
    }
    if (Viscosity) {
      const Vec<T, D> fv = acc.wsum * load<D>(f.vv_state, i) - acc.tj;
      force += fv;
      if (work_dt > T(0))
        f.viscous_work(i) += T(0.5) * work_dt * f.volume(i) * dot(fv + load<D>(f.vv_force, i), load<D>(f.v, i));
      store<D>(f.vv_force, i, fv);
    }
    store<D>(f.a, i, inv_rho * force);
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& into, const Accumulator& from) {
    into.wxi += from.wxi;
    into.fj += from.fj;
    into.hg_y += from.hg_y;
    into.hg_xi += from.hg_xi;
    into.hg_fj += from.hg_fj;
    into.wsum += from.wsum;
    into.tj += from.tj;
  }
};

template <class T, int D, bool Hourglass, bool Viscosity, class Strategy = neighbors::SerialNeighbors>
void bond_forces(const neighbors::BondFamily& family, const Fields<T, D>& f, const ForceParams<T>& p, Strategy strategy = {}) {
  neighbors::for_each_row(detail::bond_forces_label<Hourglass, Viscosity>(), family,
                          BondForces<T, D, Hourglass, Viscosity>{f, p.damage, T(1) / p.density, p.hourglass_c, p.work_dt},
                          strategy);
}

// Runtime dispatch on the enabled controls.
template <class T, int D, class Strategy = neighbors::SerialNeighbors>
void bond_forces(const neighbors::BondFamily& family, const Fields<T, D>& f, const ForceParams<T>& p, bool hourglass,
                 bool viscosity, Strategy strategy = {}) {
  if (hourglass && viscosity) bond_forces<T, D, true, true>(family, f, p, strategy);
  else if (hourglass) bond_forces<T, D, true, false>(family, f, p, strategy);
  else if (viscosity) bond_forces<T, D, false, true>(family, f, p, strategy);
  else bond_forces<T, D, false, false>(family, f, p, strategy);
}

}  // namespace polymech::pd
