// The element kernel of the incompressible Navier-Stokes model (issue 36; seed 002 paper 1 eqs. (1)-(3) on a
// fixed mesh, the ALE convective velocity u - w an argument): one Kokkos pass over the elements computes each
// Taylor-Hood Q2/Q1 element's residual and, optionally, its Newton Jacobian, which the host scatters into the
// global sparse matrix (models/flow/navier_stokes.hpp).
//
// The weak form (rho the density, mu = rho nu the dynamic viscosity, the Laplacian ("gradient") form of the
// viscous term, so that the natural condition mu du/dn - p n = 0 is the do-nothing outflow that Poiseuille flow
// satisfies), for velocity test functions N_a e_i and pressure test functions M_c:
//   R_(a,i) = int [ rho c_t (u - u*)_i N_a + rho ((u - w) . grad u_i) N_a + mu grad u_i . grad N_a
//                   - p dN_a/dx_i - f_i N_a ] dx
//   R_c     = - int M_c div u dx
// with the time derivative written c_t (u - u*): BDF2 c_t = 3 / (2 dt), u* = (4 u^n - u^(n-1)) / 3; backward
// Euler c_t = 1 / dt, u* = u^n; steady c_t = 0. The Jacobian is exact (Newton); `picard` drops the term
// rho N_b du_i/dx_j (the Oseen linearisation).
#pragma once

#include "core/kokkos_shim.hpp"
#include "core/types.hpp"

namespace polymech::flow {

constexpr int kVelocityNodes = 9, kPressureNodes = 4, kPoints = 9;
constexpr int kElementDofs = 2 * kVelocityNodes + kPressureNodes;  // local: (a, i) -> 2 a + i, c -> 18 + c

// The reference values shared by every element (isoparametric Q2 geometry): N[q][a] the biquadratic basis,
// M[q][c] the bilinear pressure basis at the 3 x 3 Gauss points q = qi + 3 qj.
struct ElementBasis {
  double N[kPoints][kVelocityNodes];
  double M[kPoints][kPressureNodes];
};

// What the kernel reads: per element and point the physical gradients of the nine velocity basis functions and
// the weight w_q det J (host-computed from the node coordinates; recomputed when the mesh moves), the element's
// 22 global DoF indices, the state U, the time-derivative history u* (same indexing), the mesh velocity W
// (indexed like U's velocity part; zero on a fixed mesh) and an optional body force per point.
struct ElementInput {
  Kokkos::View<double** [kVelocityNodes][2], Kokkos::LayoutRight, MemSpace> grad;  // (e, q, a, d)
  View2<double> wdet;                                                              // (e, q)
  View2<std::int64_t> dofs;                                                        // (e, 22)
  View2<double> force;                                                             // (e, 2 q + i) or empty
  View2<double> eddy;  // (e, q) the eddy viscosity nu_t [m^2/s] (FlowConfig::smagorinsky) or empty: none
};

struct ElementCoefficients {
  double rho = 1.0, mu = 1.0;
  double ct = 0.0;  // the time derivative's coefficient (0: steady)
};

// Re(e, k) the element residual, Ke(e, k 22 + l) its Jacobian (when `jacobian`).
inline void element_residual_jacobian(const ElementInput& in, const ElementBasis& basis, const ElementCoefficients& co,
                                      const View1<double>& U, const View1<double>& Ustar, const View1<double>& W,
                                      const View2<double>& Re, const View2<double>& Ke, bool jacobian, bool picard) {
  const auto grad = in.grad;
  const auto wdet = in.wdet;
  const auto dofs = in.dofs;
  const auto force = in.force;
  const auto eddy = in.eddy;
  const bool has_force = force.extent(0) > 0;
  const bool has_eddy = eddy.extent(0) > 0;
  const bool has_mesh_velocity = W.extent(0) > 0;
  const double rho = co.rho, mu0 = co.mu, ct = co.ct;
  const ElementBasis B = basis;
  const std::int64_t ne = static_cast<std::int64_t>(dofs.extent(0));
  Kokkos::parallel_for(
      "polymech::flow::element_residual_jacobian", range(ne), KOKKOS_LAMBDA(const std::int64_t e) {
        double u[kVelocityNodes][2], us[kVelocityNodes][2], w[kVelocityNodes][2], p[kPressureNodes];
        for (int a = 0; a < kVelocityNodes; ++a)
          for (int i = 0; i < 2; ++i) {
            const std::int64_t g = dofs(e, 2 * a + i);
            u[a][i] = U(g);
            us[a][i] = Ustar(g);
            w[a][i] = has_mesh_velocity ? W(g) : 0.0;
          }
        for (int c = 0; c < kPressureNodes; ++c) p[c] = U(dofs(e, 2 * kVelocityNodes + c));
        double R[kElementDofs];
        double K[kElementDofs][kElementDofs];
        for (int k = 0; k < kElementDofs; ++k) {
          R[k] = 0.0;
          if (jacobian)
            for (int l = 0; l < kElementDofs; ++l) K[k][l] = 0.0;
        }
        for (int q = 0; q < kPoints; ++q) {
          const double wd = wdet(e, q);
          const double mu = has_eddy ? mu0 + rho * eddy(e, q) : mu0;  // the eddy viscosity is data of the step
          double g[kVelocityNodes][2];
          double uq[2] = {0, 0}, usq[2] = {0, 0}, wq[2] = {0, 0}, gu[2][2] = {{0, 0}, {0, 0}}, pq = 0.0;
          for (int a = 0; a < kVelocityNodes; ++a) {
            g[a][0] = grad(e, q, a, 0);
            g[a][1] = grad(e, q, a, 1);
            const double Na = B.N[q][a];
            for (int i = 0; i < 2; ++i) {
              uq[i] += Na * u[a][i];
              usq[i] += Na * us[a][i];
              wq[i] += Na * w[a][i];
              gu[i][0] += u[a][i] * g[a][0];  // gu[i][j] = du_i/dx_j
              gu[i][1] += u[a][i] * g[a][1];
            }
          }
          for (int c = 0; c < kPressureNodes; ++c) pq += B.M[q][c] * p[c];
          const double conv[2] = {uq[0] - wq[0], uq[1] - wq[1]};  // the ALE convective velocity
          const double divu = gu[0][0] + gu[1][1];
          double f[2] = {0, 0};
          if (has_force) {
            f[0] = force(e, 2 * q);
            f[1] = force(e, 2 * q + 1);
          }
          double adv[2];  // rho (c . grad) u_i + rho c_t (u - u*)_i - f_i
          for (int i = 0; i < 2; ++i)
            adv[i] = rho * (conv[0] * gu[i][0] + conv[1] * gu[i][1]) + rho * ct * (uq[i] - usq[i]) - f[i];
          for (int a = 0; a < kVelocityNodes; ++a) {
            const double Na = B.N[q][a];
            for (int i = 0; i < 2; ++i)
              R[2 * a + i] += wd * (adv[i] * Na + mu * (gu[i][0] * g[a][0] + gu[i][1] * g[a][1]) - pq * g[a][i]);
          }
          for (int c = 0; c < kPressureNodes; ++c) R[2 * kVelocityNodes + c] -= wd * B.M[q][c] * divu;
          if (!jacobian) continue;
          for (int b = 0; b < kVelocityNodes; ++b) {
            const double Nb = B.N[q][b];
            const double cgb = conv[0] * g[b][0] + conv[1] * g[b][1];
            for (int a = 0; a < kVelocityNodes; ++a) {
              const double Na = B.N[q][a];
              const double diag = wd * (rho * ct * Na * Nb + rho * cgb * Na + mu * (g[a][0] * g[b][0] + g[a][1] * g[b][1]));
              K[2 * a][2 * b] += diag;
              K[2 * a + 1][2 * b + 1] += diag;
              if (!picard) {
                const double s = wd * rho * Na * Nb;
                K[2 * a][2 * b] += s * gu[0][0];
                K[2 * a][2 * b + 1] += s * gu[0][1];
                K[2 * a + 1][2 * b] += s * gu[1][0];
                K[2 * a + 1][2 * b + 1] += s * gu[1][1];
              }
            }
            for (int c = 0; c < kPressureNodes; ++c) {
              const double m = wd * B.M[q][c];
              for (int i = 0; i < 2; ++i) {
                K[2 * b + i][2 * kVelocityNodes + c] -= m * g[b][i];
                K[2 * kVelocityNodes + c][2 * b + i] -= m * g[b][i];
              }
            }
          }
        }
        for (int k = 0; k < kElementDofs; ++k) {
          Re(e, k) = R[k];
          if (jacobian)
            for (int l = 0; l < kElementDofs; ++l) Ke(e, k * kElementDofs + l) = K[k][l];
        }
      });
}

// The Smagorinsky eddy viscosity at the Gauss points, nu_t = (C_s Delta)^2 |S|, |S| = sqrt(2 S:S), S the strain
// rate of the velocity V (the step's extrapolation 2 u^n - u^(n-1), models/flow/navier_stokes_solve.hpp), Delta
// = sqrt(|element|) / 2 (the Q2 node spacing). Into in.eddy (e, q).
inline void smagorinsky_viscosity(const ElementInput& in, const View1<double>& V, double cs) {
  const auto grad = in.grad;
  const auto wdet = in.wdet;
  const auto dofs = in.dofs;
  const auto eddy = in.eddy;
  const std::int64_t ne = static_cast<std::int64_t>(dofs.extent(0));
  Kokkos::parallel_for(
      "polymech::flow::smagorinsky_viscosity", range(ne), KOKKOS_LAMBDA(const std::int64_t e) {
        double area = 0.0;
        for (int q = 0; q < kPoints; ++q) area += wdet(e, q);
        const double delta = 0.5 * kx::sqrt(area), l2 = cs * cs * delta * delta;
        for (int q = 0; q < kPoints; ++q) {
          double gu[2][2] = {{0, 0}, {0, 0}};
          for (int a = 0; a < kVelocityNodes; ++a)
            for (int i = 0; i < 2; ++i) {
              const double ua = V(dofs(e, 2 * a + i));
              gu[i][0] += ua * grad(e, q, a, 0);
              gu[i][1] += ua * grad(e, q, a, 1);
            }
          const double s01 = 0.5 * (gu[0][1] + gu[1][0]);
          eddy(e, q) = l2 * kx::sqrt(2.0 * (gu[0][0] * gu[0][0] + gu[1][1] * gu[1][1] + 2.0 * s01 * s01));
        }
      });
}

}  // namespace polymech::flow
