// Stabilized ISPH operators (seed 002 paper 4, eqs. (9)-(13)) with the IGCB wall contributions
// (eqs. (15)-(24)) as neighbour functors run by neighbors::for_each_row. Each operator is two passes:
// the fluid sum over the fluid-fluid list (into a scratch View), then the wall sum over the fluid ->
// wall integration point list, whose finish() writes the result. Wall values at the integration
// points come from ghost points mirrored into the fluid (eqs. (23)-(30)), computed over the ghost ->
// fluid list.
//
// Conventions: r_ij = x_i - x_j, grad W_ij = W'(r) r_ij / r = -F(r) r_ij with F = -W'/r >= 0
// (kernels/sph/kernel.hpp). Fluid particles share one mass m; a wall integration point carries the
// volume H_m |J_c,m| (`vol`). The pressure Poisson equation is solved for A p = b with A = -lap
// (positive on the diagonal); free-surface particles (flag 1) are Dirichlet rows p = 0.
#pragma once

#include <cstdint>

#include "neighbors/neighbor_loop.hpp"
#include "particles/particle_set.hpp"
#include "sph/kernel.hpp"

namespace polymech::sph {

using Flags = Kokkos::View<std::uint8_t*, MemSpace>;

// Fluid particles: the shared particle set (x0, u, v, a) and the fields of the fractional step.
template <class T, int D>
struct Fluid {
  particles::ParticleSet<T, D> p;
  VecView<T, D> x;      // current position x0 + u
  VecView<T, D> vstar;  // u* of eq. (3)
  VecView<T, D> work;   // scratch vector (the fluid part of a two-pass operator)
  View1<T> rho;         // summation density, eqs. (13) + (18)
  View1<T> pressure;    // p^{n+1}
  View1<T> rhs;         // right-hand side of the PPE (row-scaled)
  View1<T> inv_diag;    // Jacobi scaling of the PPE rows
  View1<T> scratch;     // scalar scratch (fluid part of the PPE operator, divergence)
  Flags surface;        // 1: free-surface particle (p = 0)
  View1<T> divr;        // divergence of position (Params::divergence_surface only)
  Index size() const { return p.size(); }
};

// Wall integration points of the IGCB cells (one Gauss point per cell, or more), with their ghosts.
template <class T, int D>
struct WallPoints {
  VecView<T, D> x;        // x_c,m
  View1<T> vol;           // H_m |J_c,m|
  VecView<T, D> normal;   // n: from the fluid into the wall, eq. (25)
  VecView<T, D> ghost;    // the ghost point mirrored into the fluid
  View1<T> dist;          // d = |x_c,m - ghost|, eq. (26)
  VecView<T, D> velocity; // v_Gamma of the wall at the point
  VecView<T, D> accel;    // a_Gamma
  View1<T> p;             // p_c,m, eq. (26)
  VecView<T, D> u;        // u_c,m, eqs. (27)-(30)
  View1<T> shepard;       // sum_j V_j W_gj at the ghost (0: no fluid near it)
  VecView<T, D + 1> interp;  // ghost interpolation weights: value_g = sum_j V_j W_gj (c0 + c . (x_j - x_g)) f_j
  Index size() const { return static_cast<Index>(x.extent(0)); }
};

template <class T, int D>
struct Params {
  Wendland<T, D> w;
  T mass = T(0);      // m of every fluid particle
  T rho0 = T(0);      // rho^0 (and rho_c of the walls, eq. (18))
  T nu = T(0);        // kinematic viscosity (0: effect off)
  T dt = T(0);
  T alpha = T(0);     // density relaxation, eq. (4) (0: effect off)
  T beta = T(0.9);    // free surface: rho_i < beta rho0
  Vec<T, D> g;
  bool slip = false;  // eqs. (27)-(28) instead of (29)-(30)
  bool difference_gradient = false;  // grad p by (p_j - p_i), (p_c - p_i) instead of eqs. (9), (19)
  bool divergence_surface = false;  // free surface by the divergence of position (< surface_divr), not the density
  T surface_divr = T(1.5);
  bool density_surface_too = false;  // with divergence_surface: also flag rho < beta rho0 (either test)
  bool linear_ghosts = true;  // ghost values by a linear fit (exact for a hydrostatic field); false: Shepard, eq. (23)
  bool surface_correction = true;  // free-surface particles: eq. (9) divided by rho_i / rho0 (the kernel's
                                   // share inside the fluid), see FluidPressureGradient
};

template <class T, int D>
KOKKOS_INLINE_FUNCTION T pair_distance(const VecView<T, D>& xa, Index i, const VecView<T, D>& xb, Index j,
                                       Vec<T, D>& rij) {
  rij = load<D>(xa, i) - load<D>(xb, j);
  return norm(rij);
}

// ---- density: eq. (13) over the fluid, then eq. (18) over the wall points, and the surface flag ----
template <class T, int D>
struct FluidDensity {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return c.mass * c.w.value(T(0)); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    acc += c.mass * c.w.value(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.rho(i) = acc; }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

template <class T, int D>
struct WallDensity {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    acc += c.w.value(pair_distance<T, D>(f.x, i, wp.x, k, r)) * wp.vol(k);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    const T rho = f.rho(i) + c.rho0 * acc;  // eq. (18)
    f.rho(i) = rho;
    if (!c.divergence_surface) f.surface(i) = rho < c.beta * c.rho0 ? 1 : 0;
  }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

// Divergence of position, div r_i = sum_j V_j (x_j - x_i) . grad_i W_ij = sum_j V_j F_ij |r_ij|^2 (F = -W'/r) over the
// fluid (V_j = m / rho_j, after the density passes) and then the wall points (V = H |J|); the wall pass
// flags the free surface, div r_i < surface_divr (Lee et al. 2008; Params::divergence_surface).
template <class T, int D>
struct FluidPositionDivergence {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T d = pair_distance<T, D>(f.x, i, f.x, j, r);
    acc += c.mass / f.rho(j) * c.w.f(d) * d * d;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.divr(i) = acc; }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};
template <class T, int D>
struct WallPositionDivergence {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T d = pair_distance<T, D>(f.x, i, wp.x, k, r);
    acc += wp.vol(k) * c.w.f(d) * d * d;
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    const T divr = f.divr(i) + acc;
    f.divr(i) = divr;
    const T rho = f.rho(i);
    f.surface(i) = ((divr < c.surface_divr && rho < c.rho0) || (c.density_surface_too && rho < c.beta * c.rho0)) ? 1 : 0;
  }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

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
  KOKKOS_INLINE_FUNCTION void join(const Moments& b) {
    s += b.s;
    sr += b.sr;
    srr += b.srr;
  }
  KOKKOS_INLINE_FUNCTION Vec<T, D> centroid() const { return (T(1) / s) * sr; }
  KOKKOS_INLINE_FUNCTION Mat<T, D> covariance(const Vec<T, D>& m) const { return (T(1) / s) * srr - outer(m, m); }
};

template <class T, int D>
struct GhostWeights {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  T det_min;  // the smallest det(C) taken as regular
  using Accumulator = Moments<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Accumulator::zero(); }
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
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a.join(b); }
};

// The fluid pressure at the wall's surface point q_k = (x_k + ghost_k) / 2 of wall points [begin, end) (the
// body's outer ring), by the weighted linear least-squares fit of the ghost's neighbours (weights as in
// GhostWeights) evaluated at q_k: p(q) = pbar + b . (q - x_g - m), b = C^-1 sum w^_j (r_j - m) p_j; the
// Shepard mean pbar where the fit is singular; 0 where no fluid is near (a dry point above the water).
// Used for the body's pressure force with the difference form (Isph::body_surface_force).
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
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {Moments<T, D>::zero(), T(0), Vec<T, D>::zero()}; }
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
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) {
    a.mo.join(b.mo);
    a.sp += b.sp;
    a.srp += b.srp;
  }
};

// The weight of fluid particle j in the value at ghost k (r = x_g - x_j, as pair_distance gives it).
template <class T, int D>
KOKKOS_FORCEINLINE_FUNCTION T ghost_weight(const WallPoints<T, D>& wp, Index k, T wv, const Vec<T, D>& r) {
  T lin = wp.interp(k, 0);
  for (int d = 0; d < D; ++d) lin -= wp.interp(k, d + 1) * r[d];
  return wv * lin;
}

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
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {T(0), T(0)}; }
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
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) {
    a.s += b.s;
    a.sp += b.sp;
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
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {T(0), Vec<T, D>::zero()}; }
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
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) {
    a.s += b.s;
    a.su += b.su;
  }
};

// ---- predictor, eq. (3) with the viscous term eqs. (11) + (21) ----
template <class T, int D>
struct FluidViscosity {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Vec<T, D>::zero(); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    acc -= (T(2) * c.mass * F) * (load<D>(f.p.v, i) - load<D>(f.p.v, j));  // eq. (11) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { store<D>(f.work, i, (T(1) / f.rho(i)) * acc); }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a += b; }
};

template <class T, int D>
struct WallViscosityPredict {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Vec<T, D>::zero(); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    acc -= (T(2) * F * wp.vol(k)) * (load<D>(f.p.v, i) - load<D>(wp.u, k));  // eq. (21)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const Vec<T, D> lap = load<D>(f.work, i) + acc;
    store<D>(f.vstar, i, load<D>(f.p.v, i) + c.dt * (c.nu * lap + c.g));  // eq. (3)
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a += b; }
};

// ---- PPE right-hand side: eq. (4) with the divergence eqs. (12) + (22) of u* ----
template <class T, int D>
struct FluidDivergence {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    acc -= c.mass * F * dot(load<D>(f.vstar, j) - load<D>(f.vstar, i), r);  // eq. (12) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.scratch(i) = acc / f.rho(i); }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

// Finishes b_i = -(rho0/dt div u*_i + alpha (rho0 - rho_i)/dt^2) + 2 sum V F c_ip (the affine part
// of the Neumann wall pressure, eq. (26), moved to the right), row-scaled by inv_diag; stores the
// Jacobi scaling 1 / A_ii with A_ii = 2/rho_i sum m F + 2 sum V F (fluid diagonal from the fluid pass).
template <class T, int D>
struct WallDivergenceRhs {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  View1<T> fluid_diag;
  struct Accumulator {
    T div, diag, affine;
  };
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {T(0), T(0), T(0)}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    const T V = wp.vol(k);
    acc.div -= V * F * dot(load<D>(wp.u, k) - load<D>(f.vstar, i), r);  // eq. (22)
    acc.diag += T(2) * V * F;
    const Vec<T, D> ga = c.g - load<D>(wp.accel, k);
    acc.affine += T(2) * V * F * wp.dist(k) * c.rho0 * dot(ga, load<D>(wp.normal, k));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    if (f.surface(i)) {
      f.inv_diag(i) = T(1);
      f.rhs(i) = T(0);
      return;
    }
    const T div = f.scratch(i) + acc.div;
    const T diag = fluid_diag(i) + acc.diag;
    const T inv = diag > T(0) ? T(1) / diag : T(1);
    const T b = -(c.rho0 / c.dt * div + c.alpha * (c.rho0 - f.rho(i)) / (c.dt * c.dt)) + acc.affine;  // eq. (4)
    f.inv_diag(i) = inv;
    f.rhs(i) = inv * b;
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) {
    a.div += b.div;
    a.diag += b.diag;
    a.affine += b.affine;
  }
};

// The fluid diagonal 2/rho_i sum m F (for the Jacobi scaling).
template <class T, int D>
struct FluidDiagonal {
  Fluid<T, D> f;
  Params<T, D> c;
  View1<T> out;
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    acc += T(2) * c.mass * c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { out(i) = acc / f.rho(i); }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

// ---- the PPE operator y = D^-1 A x, A = -(eq. (10) + eq. (20)), matrix-free ----
template <class T, int D>
struct FluidLaplacian {
  Fluid<T, D> f;
  Params<T, D> c;
  View1<T> xin;
  View1<T> stored = {};  // the pair coefficients of StorePairCoefficients (empty: computed here)
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION T coefficient(Index i, Index j, Offset) const {
    Vec<T, D> r;
    return T(2) * c.mass * c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index j, Offset o) const {
    const T a = stored.extent(0) > 0 ? stored(o) : coefficient(i, j, o);
    const T xj = f.surface(j) ? T(0) : xin(j);  // Dirichlet p = 0 at the free surface
    acc += a * (xin(i) - xj);                   // -eq. (10) times rho_i
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const { f.scratch(i) = acc / f.rho(i); }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

template <class T, int D>
struct WallLaplacian {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  View1<T> xin, yout;
  View1<T> stored = {};  // the pair coefficients of StorePairCoefficients (empty: computed here)
  using Accumulator = T;
  KOKKOS_INLINE_FUNCTION T start(Index) const { return T(0); }
  KOKKOS_FORCEINLINE_FUNCTION T coefficient(Index i, Index k, Offset) const {
    Vec<T, D> r;
    return T(2) * wp.vol(k) * c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
  }
  KOKKOS_FORCEINLINE_FUNCTION void pair(T& acc, Index i, Index k, Offset o) const {
    const T a = stored.extent(0) > 0 ? stored(o) : coefficient(i, k, o);
    acc += a * (xin(i) - wp.p(k));  // -eq. (20), p_c,m from the ghost (homogeneous part)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, T& acc) const {
    yout(i) = f.surface(i) ? xin(i) : f.inv_diag(i) * (f.scratch(i) + acc);
  }
  KOKKOS_INLINE_FUNCTION static void join(T& a, const T& b) { a += b; }
};

// The PPE operator's pair coefficients, stored once per step (`ppe_operator = "stored"`, the default):
// positions, densities and ghost weights do not change within a solve, so each of its applies reduces to
// three sparse products over the neighbour lists instead of three kernel evaluations per pair. `Pass` is
// GhostPressure, FluidLaplacian or WallLaplacian; out(o) = pass.coefficient(i, j, o) for the pair o of
// row i, formed as the matrix-free pass forms it, so both give the same result to the bit.
template <class T, class Pass>
struct StorePairCoefficients {
  Pass pass;
  View1<T> out;  // one per pair of the pass's list
  struct Accumulator {};
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return {}; }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator&, Index i, Index j, Offset o) const { out(o) = pass.coefficient(i, j, o); }
  KOKKOS_INLINE_FUNCTION void finish(Index, Accumulator&) const {}
  KOKKOS_INLINE_FUNCTION static void join(Accumulator&, const Accumulator&) {}
};

// ---- projection, eq. (5), with the pressure gradient eqs. (9) + (19); then the drift ----
template <class T, int D>
struct FluidPressureGradient {
  Fluid<T, D> f;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Vec<T, D>::zero(); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index j, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, f.x, j, r));
    const T ri = f.rho(i), rj = f.rho(j);
    if (c.difference_gradient)
      acc -= (c.mass * (f.pressure(j) - f.pressure(i)) / (rj * ri) * F) * r;
    else
      acc -= (c.mass * (f.pressure(j) / (rj * rj) + f.pressure(i) / (ri * ri)) * F) * r;  // eq. (9) / rho_i
  }
  // At a free-surface particle (p_i = 0) the sum of eq. (9) covers only the part of the kernel inside
  // the water, sum_j V_j p_j grad W_ij ~ (rho_i / rho0) grad p: it gives about half the hydrostatic
  // support and the surface layer sinks onto the one below. With surface_correction the sum is divided
  // by that share (a Shepard renormalisation; not in the paper, docs/METHODS.md).
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const T s = (c.surface_correction && f.surface(i)) ? c.rho0 : f.rho(i);
    store<D>(f.work, i, s * acc);
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a += b; }
};

template <class T, int D>
struct WallPressureCorrect {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  using Accumulator = Vec<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Vec<T, D>::zero(); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    Vec<T, D> r;
    const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
    const T pi = c.difference_gradient ? -f.pressure(i) : f.pressure(i);
    acc -= ((wp.p(k) + pi) * F * wp.vol(k)) * r;  // eq. (19)
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const {
    const Vec<T, D> grad = load<D>(f.work, i) + acc;
    const Vec<T, D> vnew = load<D>(f.vstar, i) - (c.dt / f.rho(i)) * grad;  // eq. (5)
    store<D>(f.p.a, i, (T(1) / c.dt) * (vnew - load<D>(f.p.v, i)));
    store<D>(f.p.v, i, vnew);
    store<D>(f.p.u, i, load<D>(f.p.u, i) + c.dt * vnew);  // x^{n+1} = x^n + dt u^{n+1}
  }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a += b; }
};

// Wall reaction of pair (i, (c,m)), eqs. (39)-(41): the force the point gives particle i, its pressure
// part (eq. (40)) and its viscous part (eq. (41)).
template <class T, int D>
KOKKOS_INLINE_FUNCTION void wall_pair_force_parts(const Fluid<T, D>& f, const WallPoints<T, D>& wp, const Params<T, D>& c,
                                                  Index i, Index k, Vec<T, D>& pressure, Vec<T, D>& viscous) {
  Vec<T, D> r;
  const T F = c.w.f(pair_distance<T, D>(f.x, i, wp.x, k, r));
  const T pi = c.difference_gradient ? -f.pressure(i) : f.pressure(i);
  const Vec<T, D> gradp = (-(wp.p(k) + pi) * F * wp.vol(k)) * r;                         // eq. (40)
  const Vec<T, D> lapu = (-T(2) * F * wp.vol(k)) * (load<D>(f.p.v, i) - load<D>(wp.u, k));  // eq. (41)
  pressure = (-c.mass / c.rho0) * gradp;                                                 // eq. (39)
  viscous = (c.mass * c.nu) * lapu;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> wall_pair_force(const Fluid<T, D>& f, const WallPoints<T, D>& wp, const Params<T, D>& c,
                                                 Index i, Index k) {
  Vec<T, D> fp, fv;
  wall_pair_force_parts<T, D>(f, wp, c, i, k, fp, fv);
  return fp + fv;
}

// The wall force on each fluid particle, f_i^wall = sum over its wall points, eq. (38).
template <class T, int D>
struct WallForceOnFluid {
  Fluid<T, D> f;
  WallPoints<T, D> wp;
  Params<T, D> c;
  VecView<T, D> out;
  using Accumulator = Vec<T, D>;
  KOKKOS_INLINE_FUNCTION Accumulator start(Index) const { return Vec<T, D>::zero(); }
  KOKKOS_FORCEINLINE_FUNCTION void pair(Accumulator& acc, Index i, Index k, Offset) const {
    acc += wall_pair_force<T, D>(f, wp, c, i, k);
  }
  KOKKOS_FORCEINLINE_FUNCTION void finish(Index i, Accumulator& acc) const { store<D>(out, i, acc); }
  KOKKOS_INLINE_FUNCTION static void join(Accumulator& a, const Accumulator& b) { a += b; }
};

// Position update helper: x = x0 + u.
template <class T, int D>
void current_positions(const Fluid<T, D>& f) {
  auto x = f.x;
  auto p = f.p;
  Kokkos::parallel_for(
      "polymech::sph::positions", range(f.size()), KOKKOS_LAMBDA(const Index i) { store<D>(x, i, p.position(i)); });
}

}  // namespace polymech::sph
