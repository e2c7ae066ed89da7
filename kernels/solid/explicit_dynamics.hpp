// Device kernels of the explicit finite-strain solid with nodes tied to rigid bodies (issue 34: "explicit central
// differences with a lumped mass", "nodes tied to a rigid body"; issue 37: the tyre's rim), used by
// solid::HyperelasticExplicit (models/solid/finite_strain_explicit.hpp), one function per kernel:
//   explicit_kick_drift   v_{n+1/2} = v_n + dt/2 a_n,  u_{n+1} = u_n + dt v_{n+1/2}   on the free DoFs (kind 0)
//   explicit_kick         v_{n+1} = v_{n+1/2} + dt/2 a_{n+1}                          on the free DoFs
//   explicit_accelerate   a = -r / m - alpha v on the free DoFs, 0 elsewhere (M_L^-1 r, mass-proportional damping)
//   explicit_kinetic_energy  sum 1/2 m v^2 over every DoF
//   explicit_place_tied   x_i = c + R_n(theta) (X_i - c_0), v_i = V + omega n x (x_i - c) for the tied nodes
//   explicit_gather_tied  -r at the tied nodes (the structure's force on the body, summed on the host)
//   explicit_power_*      the power iteration on M_L^-1 K_t of the critical step dt_crit = 2 / omega_max, K_t x by a
//                         directional difference of the residual: a hashed start vector, the perturbed state, the
//                         Rayleigh quotient's sums, the largest component, the normalised update.
// DoF kinds: 0 free, 1 Dirichlet, 2 tied. The kernels keep the model's labels ("polymech::solid::fse_*").
#pragma once

#include "core/types.hpp"
#include "particles/reductions.hpp"

namespace polymech::solid {

// v += dt/2 a, then u += dt v, on the free DoFs.
template <class T>
void explicit_kick_drift(Index n, const View1<char>& kind, const View1<T>& u, const View1<T>& v, const View1<T>& a, T th,
                         T tdt) {
  Kokkos::parallel_for(
      "polymech::solid::fse_kick_drift", range(n), KOKKOS_LAMBDA(const Index i) {
        if (kind(i) != 0) return;
        v(i) += th * a(i);
        u(i) += tdt * v(i);
      });
}

// v += dt/2 a on the free DoFs.
template <class T>
void explicit_kick(Index n, const View1<char>& kind, const View1<T>& v, const View1<T>& a, T th) {
  Kokkos::parallel_for(
      "polymech::solid::fse_kick", range(n), KOKKOS_LAMBDA(const Index i) {
        if (kind(i) == 0) v(i) += th * a(i);
      });
}

// a = -r / m - alpha v on the free DoFs, 0 elsewhere.
template <class T>
void explicit_accelerate(Index n, const View1<char>& kind, const View1<T>& r, const View1<T>& m, const View1<T>& v, T alpha,
                         const View1<T>& a) {
  Kokkos::parallel_for(
      "polymech::solid::fse_accelerate", range(n), KOKKOS_LAMBDA(const Index i) {
        a(i) = kind(i) == 0 ? -r(i) / m(i) - alpha * v(i) : T(0);
      });
}

// sum_i 1/2 m_i v_i^2 (in double).
template <class T>
double explicit_kinetic_energy(Index n, const View1<T>& m, const View1<T>& v) {
  double e = 0.0;
  Kokkos::parallel_reduce(
      "polymech::solid::fse_kinetic", range(n),
      KOKKOS_LAMBDA(const Index i, double& s) { s += 0.5 * double(m(i)) * double(v(i)) * double(v(i)); }, e);
  return e;
}

// A rigid body's pose for explicit_place_tied: its reference point c (c0 at the start), cos and sin of the
// rotation, the unit axis n, the velocity V of c and the angular velocity w (3 components; 2D uses 2).
struct TiedPose {
  double c[3] = {0, 0, 0}, c0[3] = {0, 0, 0}, V[3] = {0, 0, 0};
  double ct = 1.0, st = 0.0, n0 = 0.0, n1 = 0.0, n2 = 1.0, w = 0.0;
};

// The tied nodes' displacement u = c + R (X - c0) - X (and with velocities, velocity V + w n x R (X - c0)) from
// the body's pose; off(j, d) = X_j - c0, nodes(j) the node of tied node j.
template <class T, int D>
void explicit_place_tied(const Kokkos::View<Index*, MemSpace>& nodes, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& off,
                         const TiedPose& pose, bool velocities, const View1<T>& u, const View1<T>& v) {
  const double ct = pose.ct, st = pose.st, n0 = pose.n0, n1 = pose.n1, n2 = pose.n2, w = pose.w;
  double c[3], c0[3], V[3];
  for (int d = 0; d < 3; ++d) {
    c[d] = pose.c[d];
    c0[d] = pose.c0[d];
    V[d] = pose.V[d];
  }
  Kokkos::parallel_for(
      "polymech::solid::fse_place_tied", range(static_cast<Index>(nodes.extent(0))), KOKKOS_LAMBDA(const Index j) {
        const Index i = nodes(j);
        double x[3] = {0, 0, 0}, y[3] = {0, 0, 0};
        for (int d = 0; d < D; ++d) x[d] = off(j, d);
        if (D == 2) {
          y[0] = ct * x[0] - st * x[1];
          y[1] = st * x[0] + ct * x[1];
        } else {
          const double nx = n0 * x[0] + n1 * x[1] + n2 * x[2];
          const double cr[3] = {n1 * x[2] - n2 * x[1], n2 * x[0] - n0 * x[2], n0 * x[1] - n1 * x[0]};
          const double nn[3] = {n0, n1, n2};
          for (int d = 0; d < 3; ++d) y[d] = ct * x[d] + st * cr[d] + (1.0 - ct) * nx * nn[d];
        }
        for (int d = 0; d < D; ++d) u(D * i + d) = static_cast<T>(c[d] + y[d] - (c0[d] + x[d]));
        if (velocities) {  // V + omega n x y
          double wy[3];
          if (D == 2) {
            wy[0] = -w * y[1];
            wy[1] = w * y[0];
          } else {
            wy[0] = w * (n1 * y[2] - n2 * y[1]);
            wy[1] = w * (n2 * y[0] - n0 * y[2]);
            wy[2] = w * (n0 * y[1] - n1 * y[0]);
          }
          for (int d = 0; d < D; ++d) v(D * i + d) = static_cast<T>(V[d] + wy[d]);
        }
      });
}

// gath(j, d) = -r at component d of tied node j.
template <class T, int D>
void explicit_gather_tied(const Kokkos::View<Index*, MemSpace>& nodes, const View1<T>& r,
                          const Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>& gath) {
  Kokkos::parallel_for(
      "polymech::solid::fse_gather_tied", range(static_cast<Index>(nodes.extent(0))), KOKKOS_LAMBDA(const Index j) {
        for (int d = 0; d < D; ++d) gath(j, d) = -r(D * nodes(j) + d);
      });
}

// The power iteration's start: a hashed vector in [-1, 1] on the free DoFs, 0 elsewhere.
template <class T>
void explicit_power_start(Index n, const View1<char>& kind, const View1<T>& x) {
  Kokkos::parallel_for(
      "polymech::solid::fse_power_start", range(n), KOKKOS_LAMBDA(const Index i) {
        const unsigned long long hsh = (static_cast<unsigned long long>(i) + 1ull) * 0x9E3779B97F4A7C15ull;
        const T q = T(static_cast<double>((hsh >> 11) & 0xFFFFFull) / double(0xFFFFF)) * T(2) - T(1);
        x(i) = kind(i) == 0 ? q : T(0);
      });
}

// up = u + eps x.
template <class T>
void explicit_power_perturb(Index n, const View1<T>& u, const View1<T>& xx, T te, const View1<T>& upp) {
  Kokkos::parallel_for(
      "polymech::solid::fse_power_perturb", range(n), KOKKOS_LAMBDA(const Index i) { upp(i) = u(i) + te * xx(i); });
}

// On the free DoFs: K x = (r(u + eps x) - r(u)) / eps from w = r(u + eps x) and rr = r(u); xkx = sum x K x,
// xmx = sum m x^2, and w becomes M_L^-1 K x.
template <class T>
void explicit_power_quotient(Index n, const View1<char>& kind, const View1<T>& w, const View1<T>& rr, const View1<T>& xx,
                             const View1<T>& m, T inv, double& xkx, double& xmx) {
  Kokkos::parallel_reduce(
      "polymech::solid::fse_power_quotient", range(n),
      KOKKOS_LAMBDA(const Index i, double& s1, double& s2) {
        if (kind(i) != 0) return;
        const T kx = (w(i) - rr(i)) * inv;
        s1 += double(xx(i)) * double(kx);
        s2 += double(m(i)) * double(xx(i)) * double(xx(i));
        w(i) = kx / m(i);  // M_L^-1 K x
      },
      xkx, xmx);
}

// max |w| over the free DoFs.
template <class T>
void explicit_power_norm(Index n, const View1<char>& kind, const View1<T>& w, double& amax) {
  Kokkos::parallel_reduce(
      "polymech::solid::fse_power_norm", range(n),
      KOKKOS_LAMBDA(const Index i, double& mx) {
        const double wi = double(w(i)) < 0.0 ? -double(w(i)) : double(w(i));
        if (kind(i) == 0 && wi > mx) mx = wi;
      },
      Kokkos::Max<double>(amax));
}

// x = sc w on the free DoFs, 0 elsewhere.
template <class T>
void explicit_power_update(Index n, const View1<char>& kind, const View1<T>& w, T sc, const View1<T>& xx) {
  Kokkos::parallel_for(
      "polymech::solid::fse_power_update", range(n), KOKKOS_LAMBDA(const Index i) { xx(i) = kind(i) == 0 ? sc * w(i) : T(0); });
}

// Mass-proportional damping relative to a rigid motion (issue 37: a rolling tyre's damping must not brake its
// rigid rotation with the rim): on the free DoFs r += alpha m (v - v_f), v_f = V + w x (x - c) the frame's
// velocity at the node's current position x = X + u (3D; w the angular velocity vector), so that with a = -r / m
// the node is damped towards the frame's motion. Returns what the dashpots give the frame's body, sum of the
// added r and its moment about c along the unit axis n (fx, fy, fz, m_n), summed in node order (ordered_sum: any
// thread count gives the same bits); the caller adds it to the body, so the damping conserves momentum.
struct DampingFrame {
  double c[3] = {0, 0, 0}, V[3] = {0, 0, 0}, w[3] = {0, 0, 0}, n[3] = {0, 0, 1};
};

template <class T>
Kokkos::Array<double, 4> explicit_frame_damping(Index nodes, const View1<char>& kind, const View1<double>& X, const View1<T>& u,
                                                const View1<T>& v, const View1<T>& m, double alpha, const DampingFrame& f,
                                                const View1<T>& r, particles::SumPartials& partials) {
  const double c0 = f.c[0], c1 = f.c[1], c2 = f.c[2], V0 = f.V[0], V1 = f.V[1], V2 = f.V[2];
  const double w0 = f.w[0], w1 = f.w[1], w2 = f.w[2], n0 = f.n[0], n1 = f.n[1], n2 = f.n[2];
  return particles::ordered_sum<4>(
      "polymech::solid::fse_frame_damping", static_cast<std::int64_t>(nodes),
      KOKKOS_LAMBDA(const std::int64_t j, double* acc) {
        const Index i = static_cast<Index>(3 * j);
        const double y0 = X(i) + double(u(i)) - c0, y1 = X(i + 1) + double(u(i + 1)) - c1, y2 = X(i + 2) + double(u(i + 2)) - c2;
        const double vf[3] = {V0 + w1 * y2 - w2 * y1, V1 + w2 * y0 - w0 * y2, V2 + w0 * y1 - w1 * y0};
        double g[3] = {0, 0, 0};
        for (int d = 0; d < 3; ++d) {
          if (kind(i + d) != 0) continue;
          g[d] = alpha * double(m(i + d)) * (double(v(i + d)) - vf[d]);
          r(i + d) += static_cast<T>(g[d]);
          acc[d] += g[d];
        }
        acc[3] += n0 * (y1 * g[2] - y2 * g[1]) + n1 * (y2 * g[0] - y0 * g[2]) + n2 * (y0 * g[1] - y1 * g[0]);
      },
      partials);
}

}  // namespace polymech::solid
