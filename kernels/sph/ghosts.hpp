// The IGCB ghost values of the stabilized ISPH (seed 002 paper 4, eqs. (23)-(30)): each wall integration
// point takes its value from the ghost point mirrored into the fluid, interpolated from the ghost's fluid
// neighbours over the ghost -> fluid list: the interpolation weights (once per step), the ghost pressure
// with the Neumann condition (26), the ghost velocity (slip or no-slip), and the fluid pressure at a body's
// surface (kernels/sph/fluid.hpp has the conventions).
#pragma once

#include "sph/fluid.hpp"

namespace polymech::sph {

// ---- ghost interpolation weights (once per step, the fluid positions fixed) ----
// Shepard, eq. (23): value_g = sum_j w_j f_j / sum_j w_j, w_j = V_j W(x_g - x_j). Near a wall the
// ghost's support is cut by the wall and the weighted centroid of its neighbours lies a fraction of l0
// further into the fluid: in a hydrostatic field the ghost pressure is then too low above a wall and too
// high below one, which lifts an immersed body (+3-4 % buoyancy, docs/VALIDATION.md). The linear fit
// (moving least squares with the basis [1, x] and the same weights; not in the paper, docs/METHODS.md)
// is exact for linear fields: with the normalised weights w^_j = w_j / s, the centroid offset
// m = sum w^_j r_j (r_j = x_j - x_g) and the covariance C = sum w^_j r_j r_j^T - m m^T,
//   value_g = sum_j w_j [(1 + m^T C^-1 m) - (C^-1 m) . r_j] / s f_j,
// i.e. c0 = (1 + m^T C^-1 m)/s, c = -C^-1 m / s. Where the neighbours do not span the plane (det(C) below
// det_min = (1e-3 re^2)^D; a full support has about (0.05 re^2)^D) or the ghost lies far outside their
// cloud (m^T C^-1 m > 4: extrapolation over two of the cloud's standard deviations), the ghost falls back
// to Shepard (c0 = 1/s, c = 0).
// The weighted moments of a ghost's neighbours r_j = x_j - x_g: s = sum w_j, sum w_j r_j, sum w_j r_j r_j^T;
// their centroid offset m and covariance C (normalised by s).
template <class T, int D>
struct Moments {
  T s;
  Vec<T, D> sr;
  Mat<T, D> srr;
  KOKKOS_INLINE_FUNCTION static Moments zero() { return {T(0), Vec<T, D>::zero(), Mat<T, D>::zero()}; }
  KOKKOS_INLINE_FUNCTION void add(T w, const Vec<T, D>& r) {
    s += w;
    sr += w * r;
    srr += w * outer(r, r);
  }
  KOKKOS_INLINE_FUNCTION Moments& operator+=(const Moments& b) {
    s += b.s;
    sr += b.sr;
    srr += b.srr;
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec<T, D> centroid() const { return (T(1) / s) * sr; }
  KOKKOS_INLINE_FUNCTION Mat<T, D> covariance(const Vec<T, D>& m) const { return (T(1) / s) * srr - outer(m, m); }
};

// The weight of fluid particle j in the value at ghost k (r = x_g - x_j, as pair_distance gives it).
template <class T, int D>
KOKKOS_FORCEINLINE_FUNCTION T ghost_weight(const WallPoints<T, D>& wp, Index k, T wv, const Vec<T, D>& r) {
  T lin = wp.interp(k, 0);
  for (int d = 0; d < D; ++d) lin -= wp.interp(k, d + 1) * r[d];
  return wv * lin;
}

namespace pass {

template <class T, int D>
struct GhostWeights {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  T det_min;  // the smallest det(C) taken as regular
  using Accumulator = Moments<T, D>;
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index k, Index j, Offset) const {
    Vec<T, D> r;
    const T wv = c.w.value(pair_distance<T, D>(wp.ghost, k, f.x, j, r)) * c.mass / f.rho(j);
    if (c.linear_ghosts)
      acc.add(wv, -r);  // r_j = x_j - x_g
    else
      acc.s += wv;  // Shepard needs only the sum
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index k, Accumulator& acc) const {
    for (int d = 0; d <= D; ++d) wp.interp(k, d) = T(0);
    if (!(acc.s > T(0))) return;  // no fluid near the ghost: value 0 (pressure) / the wall's (velocity)
    const T inv_s = T(1) / acc.s;
    wp.interp(k, 0) = inv_s;
    if (!c.linear_ghosts) return;
    const Vec<T, D> m = acc.centroid();
    const Mat<T, D> C = acc.covariance(m);
    if (!(det(C) > det_min)) return;
    const Vec<T, D> cm = inverse(C) * m;
    const T q = dot(m, cm);
    if (!(q <= T(4))) return;
    wp.interp(k, 0) = (T(1) + q) * inv_s;
    for (int d = 0; d < D; ++d) wp.interp(k, d + 1) = -cm[d] * inv_s;
  }
};

// The fluid pressure at the wall's surface point q_k = (x_k + ghost_k) / 2 of wall points [begin, end) (the
// body's outer ring), by the weighted linear least-squares fit of the ghost's neighbours (weights as in
// GhostWeights) evaluated at q_k: p(q) = pbar + b . (q - x_g - m), b = C^-1 sum w^_j (r_j - m) p_j; the
// Shepard mean pbar where the fit is singular; 0 where no fluid is near (a dry point above the water).
// Used for the body's pressure force with the difference form (sph::body_surface_force).
template <class T, int D>
struct SurfacePressure {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  Index begin, end;
  T det_min;
  View1<T> out;  // [end - begin]
  struct Accumulator {
    Moments<T, D> mo;
    T sp;
    Vec<T, D> srp;
    KOKKOS_INLINE_FUNCTION Accumulator& operator+=(const Accumulator& b) {
      mo += b.mo;
      sp += b.sp;
      srp += b.srp;
      return *this;
    }
  };
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index k, Index j, Offset) const {
    if (k < begin || k >= end) return;
    Vec<T, D> r;
    const T wv = c.w.value(pair_distance<T, D>(wp.ghost, k, f.x, j, r)) * c.mass / f.rho(j);
    r = -r;  // x_j - x_g
    const T pj = f.surface(j) ? T(0) : f.pressure(j);
    acc.mo.add(wv, r);
    acc.sp += wv * pj;
    acc.srp += (wv * pj) * r;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index k, Accumulator& acc) const {
    if (k < begin || k >= end) return;
    T p = T(0);
    if (acc.mo.s > T(0)) {
      const T inv_s = T(1) / acc.mo.s;
      const T pbar = inv_s * acc.sp;
      p = pbar;
      const Vec<T, D> m = acc.mo.centroid();
      const Mat<T, D> C = acc.mo.covariance(m);
      if (det(C) > det_min) {
        const Vec<T, D> b = inverse(C) * (inv_s * acc.srp - pbar * m);
        const Vec<T, D> delta = T(0.5) * (load<D>(wp.x, k) - load<D>(wp.ghost, k)) - m;  // q - x_g - m
        p = pbar + dot(b, delta);
      }
    }
    out(k - begin) = p;
  }
};

// ---- ghost values at the ghost of each wall point, eqs. (23)-(24), by the weights above ----
// Pressure: p_c,m = p_g + d rho0 (g - a_Gamma) . n (eq. (26)); `affine` false drops the second term
// (the homogeneous part, for the PPE operator). Surface particles enter with p = 0.
template <class T, int D>
struct GhostPressure {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  View1<T> pin;  // fluid pressure (or the Krylov vector)
  bool affine;
  View1<T> stored = {};  // the pair weights of StorePairCoefficients (empty: computed here; no Shepard sum then)
  struct Accumulator {
    T s, sp;
    KOKKOS_INLINE_FUNCTION Accumulator& operator+=(const Accumulator& b) {
      s += b.s;
      sp += b.sp;
      return *this;
    }
  };
  // The weight of fluid particle j in the ghost value at k: V_j W_gj (c0 + c . (x_j - x_g)), eq. (23).
  KOKKOS_FORCEINLINE_FUNCTION T coefficient(Index k, Index j, Offset) const {
    Vec<T, D> r;
    const T wv = c.w.value(pair_distance<T, D>(wp.ghost, k, f.x, j, r)) * c.mass / f.rho(j);
    return ghost_weight<T, D>(wp, k, wv, r);
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index k, Index j, Offset o) const {
    if (stored.extent(0) > 0) {
      if (!f.surface(j)) acc.sp += stored(o) * pin(j);
      return;
    }
    Vec<T, D> r;
    const T wv = c.w.value(pair_distance<T, D>(wp.ghost, k, f.x, j, r)) * c.mass / f.rho(j);
    acc.s += wv;
    if (!f.surface(j)) acc.sp += ghost_weight<T, D>(wp, k, wv, r) * pin(j);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index k, Accumulator& acc) const {
    T p = acc.sp;
    if (affine) {
      const Vec<T, D> n = load<D>(wp.normal, k);
      const Vec<T, D> ga = c.g - load<D>(wp.accel, k);
      p += wp.dist(k) * c.rho0 * dot(ga, n);  // eq. (26)
    }
    wp.p(k) = p;
    if (stored.extent(0) == 0) wp.shepard(k) = acc.s;
  }
};

// Velocity: u_c,m - v_Gamma = M (u_g - v_Gamma), M = I - 2 n n (slip, eqs. (27)-(28)) or M = -I
// (no-slip, eqs. (29)-(30)). A ghost with no fluid around it takes u_g = v_Gamma.
template <class T, int D>
struct GhostVelocity {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  VecView<T, D> vin;
  struct Accumulator {
    T s;
    Vec<T, D> su;
    KOKKOS_INLINE_FUNCTION Accumulator& operator+=(const Accumulator& b) {
      s += b.s;
      su += b.su;
      return *this;
    }
  };
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index k, Index j, Offset) const {
    Vec<T, D> r;
    const T wv = c.w.value(pair_distance<T, D>(wp.ghost, k, f.x, j, r)) * c.mass / f.rho(j);
    acc.s += wv;
    acc.su += ghost_weight<T, D>(wp, k, wv, r) * load<D>(vin, j);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index k, Accumulator& acc) const {
    const Vec<T, D> vg = load<D>(wp.velocity, k);
    const Vec<T, D> rel = acc.s > T(0) ? acc.su - vg : Vec<T, D>::zero();
    Vec<T, D> out;
    if (c.slip) {
      const Vec<T, D> n = load<D>(wp.normal, k);
      out = rel - (T(2) * dot(n, rel)) * n;  // eq. (28)
    } else {
      out = -rel;  // eq. (30)
    }
    store<D>(wp.u, k, vg + out);
  }
};

}  // namespace pass

template <class T, int D>
using GhostWeights = AdditiveSum<pass::GhostWeights<T, D>>;
template <class T, int D>
using SurfacePressure = AdditiveSum<pass::SurfacePressure<T, D>>;
template <class T, int D>
using GhostPressure = AdditiveSum<pass::GhostPressure<T, D>>;
template <class T, int D>
using GhostVelocity = AdditiveSum<pass::GhostVelocity<T, D>>;

}  // namespace polymech::sph
