// Crack-face contact by penalty (seed 000 §4): pairs (i in the upper face S+, j in the lower face S-)
// whose bond the crack cut interact only through contact.
//  - open/close model, eqs. (17)-(19): stick (in contact) while the pair is closer than its initial
//    distance, with the repulsion f_i = -kn (d0 - |r_ij|) r_ij / |r_ij|; separation otherwise;
//  - slip model, eqs. (20)-(21): Coulomb friction along the crack tangent s: in stick a spring
//    f_i = ks (dr_ij . s) s on the relative displacement since the last slip -> stick transition; in
//    slip the kinetic force mu_d |f'_n| along the sliding direction; stick -> slip when
//    |f_s| >= mu_s |f'_n|, slip -> stick when the relative tangential velocity reaches zero.
//
// The pair kernels compute each pair's force and state once (state is per pair); crack_apply_forces
// then gathers the pair forces per particle, so results do not depend on the thread count and no
// atomics are needed. Displacements, not positions, enter every difference: nanometre overlaps of
// 50 um spacings keep full precision in float.
#pragma once

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::contact {

enum CrackPairState : int { pair_separation = 0, pair_stick = 1, pair_slip = 2, pair_state_count = 3 };

// Geometry of the contact pairs, fixed at set-up (the crack particles never change, seed 000 §4).
template <class T>
struct CrackPairs {
  View1<Index> plus, minus;          // i in S+, j in S-
  VecView<T, 2> r0;                  // x0_j - x0_i
  View1<T> d0;                       // |r0|: the pair's contact distance (l0 for lattice neighbours)
  // gather: the crack-face particles and, per particle, its pairs (CSR)
  View1<Index> face_particles;
  Kokkos::View<Offset*, MemSpace> face_offsets;
  View1<Index> face_pairs;
  Index count() const { return static_cast<Index>(plus.extent(0)); }
};

// Per-pair contact state. Views of an effect that is off stay empty (never allocated).
template <class T>
struct CrackContactState {
  Kokkos::View<int*, MemSpace> state;   // CrackPairState
  VecView<T, 2> force;                  // force on i (S+) from the pair; j receives -force
  // open_close and slip together: the open/close normal force, read by the slip kernel
  View1<T> normal_force;
  // slip only
  VecView<T, 2> du_anchor;  // u_j - u_i at the last slip -> stick transition (r^c of eq. (21))
  View1<T> preload;         // fixed normal reaction |f'_n| of eq. (20) (seed 000 §5.2.2)
  Kokkos::View<int*, MemSpace> slip_sign;  // +1 / -1: direction of the kinetic force along s while slipping
};

template <class T>
struct CrackContactParams {
  T kn = T(0);    // normal penalty stiffness, eq. (19): k' m / dt^2
  T ks = T(0);    // tangential stiffness (seed 000: ks = kn)
  T mu_s = T(0);  // static friction coefficient
  T mu_d = T(0);  // kinetic friction coefficient
  Vec2<T> s{};    // unit tangent of the crack (the shear direction s_i of eq. (20)-(21))
};

// seed 000 eqs. (17)-(19). With Slip, a pair that comes back into contact restarts in stick with its
// tangential anchor at the current relative displacement, and the normal force is kept for the slip
// model's friction limit.
template <class T, bool Slip>
void crack_open_close(const CrackPairs<T>& pairs, const CrackContactState<T>& st, const VecView<T, 2>& u,
                      const CrackContactParams<T>& p) {
  const T kn = p.kn;
  Kokkos::parallel_for(
      "polymech::contact::crack_open_close", range(pairs.count()), KOKKOS_LAMBDA(const Index k) {
        const Index i = pairs.plus(k), j = pairs.minus(k);
        const Vec2<T> r0 = load<2>(pairs.r0, k);
        const Vec2<T> du = load<2>(u, j) - load<2>(u, i);
        const Vec2<T> r = r0 + du;
        const T len = kx::sqrt(norm2(r));
        // d0 - |r0 + du| without cancellation: -(2 r0.du + |du|^2) / (|r| + d0)
        const T overlap = -(T(2) * dot(r0, du) + norm2(du)) / (len + pairs.d0(k));
        // eq. (17); overlaps below 1e-12 d0 (round-off of double positions) do not count as contact, so
        // the exponentially small precursors an explicit particle scheme sends ahead of every wave (r_e
        // per step) do not flip the state of a crack the wave has not reached
        const bool contact = overlap > T(1e-12) * pairs.d0(k);
        Vec2<T> f = Vec2<T>::zero();
        if (contact) f = (-kn * overlap / len) * r;  // eq. (18), on i
        store<2>(st.force, k, f);
        if (Slip) {
          st.normal_force(k) = contact ? kn * overlap : T(0);
          if (!contact) {
            st.state(k) = pair_separation;
          } else if (st.state(k) == pair_separation) {  // separation -> stick: a fresh anchor
            st.state(k) = pair_stick;
            store<2>(st.du_anchor, k, du);
          }
        } else {
          st.state(k) = contact ? pair_stick : pair_separation;
        }
      });
}

// seed 000 eqs. (20)-(21). NormalContact: the open/close kernel ran this step (its force is in
// st.force and its normal force adds to the preload); otherwise the faces are held together by the
// fixed normal reaction alone, as in the paper's S-wave case, and the state is stick or slip.
template <class T, bool NormalContact>
void crack_slip(const CrackPairs<T>& pairs, const CrackContactState<T>& st, const VecView<T, 2>& u,
                const VecView<T, 2>& v, const CrackContactParams<T>& p) {
  const T ks = p.ks, mu_s = p.mu_s, mu_d = p.mu_d;
  const Vec2<T> s = p.s;
  Kokkos::parallel_for(
      "polymech::contact::crack_slip", range(pairs.count()), KOKKOS_LAMBDA(const Index k) {
        const Index i = pairs.plus(k), j = pairs.minus(k);
        Vec2<T> f = NormalContact ? load<2>(st.force, k) : Vec2<T>::zero();
        int state = st.state(k);
        if (NormalContact && state == pair_separation) {
          store<2>(st.force, k, f);
          return;
        }
        const T normal = st.preload(k) + (NormalContact ? st.normal_force(k) : T(0));
        const Vec2<T> du = load<2>(u, j) - load<2>(u, i);
        T ft = T(0);  // tangential force on i along s
        if (state == pair_slip) {
          const T vt = dot(load<2>(v, j) - load<2>(v, i), s);
          if (vt * T(st.slip_sign(k)) <= T(0)) {  // eq. (20): relative sliding stopped -> stick, new anchor
            state = pair_stick;
            store<2>(st.du_anchor, k, du);
          } else {
            ft = T(st.slip_sign(k)) * mu_d * normal;  // eq. (21), slip
          }
        }
        if (state == pair_stick) {
          ft = ks * dot(du - load<2>(st.du_anchor, k), s);  // eq. (21), stick
          if (kx::fabs(ft) >= mu_s * normal) {               // eq. (20): stick -> slip
            state = pair_slip;
            st.slip_sign(k) = ft >= T(0) ? 1 : -1;
            ft = T(st.slip_sign(k)) * mu_d * normal;
          }
        }
        st.state(k) = state;
        store<2>(st.force, k, f + ft * s);
      });
}

// a_i += f_k / m for the pairs k of every crack-face particle (+ for S+, - for S-).
template <class T>
void crack_apply_forces(const CrackPairs<T>& pairs, const CrackContactState<T>& st, const VecView<T, 2>& a, T mass) {
  const T inv_m = T(1) / mass;
  Kokkos::parallel_for(
      "polymech::contact::crack_apply_forces", range(static_cast<std::int64_t>(pairs.face_particles.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t q) {
        const Index i = pairs.face_particles(q);
        Vec2<T> sum = Vec2<T>::zero();
        for (Offset m = pairs.face_offsets(q); m < pairs.face_offsets(q + 1); ++m) {
          const Index k = pairs.face_pairs(m);
          const Vec2<T> f = load<2>(st.force, k);
          if (pairs.plus(k) == i)
            sum += f;
          else
            sum -= f;
        }
        for (int c = 0; c < 2; ++c) a(i, c) += inv_m * sum[c];
      });
}

// Number of pairs in separation, stick and slip (host values).
struct CrackStateCounts {
  std::int64_t separation = 0, stick = 0, slip = 0;
};

template <class T>
CrackStateCounts crack_state_counts(const CrackPairs<T>& pairs, const CrackContactState<T>& st) {
  std::int64_t sep = 0, stick = 0, slip = 0;
  const auto state = st.state;
  Kokkos::parallel_reduce(
      "polymech::contact::crack_state_census", range(pairs.count()),
      KOKKOS_LAMBDA(const Index k, std::int64_t& a, std::int64_t& b, std::int64_t& c) {
        const int s = state(k);
        a += s == pair_separation ? 1 : 0;
        b += s == pair_stick ? 1 : 0;
        c += s == pair_slip ? 1 : 0;
      },
      sep, stick, slip);
  return {sep, stick, slip};
}

}  // namespace polymech::contact
