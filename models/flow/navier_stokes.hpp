// Incompressible Navier-Stokes in 2D on a quadrilateral mesh (issue 36; seed 002 paper 1 eqs. (1)-(3) with the
// mesh at rest: the ALE mesh velocity w enters the convective term and is zero until the mesh moves).
//
// Discretisation: Taylor-Hood Q2/Q1 (velocity biquadratic, pressure bilinear and continuous). The pair
// satisfies the discrete inf-sup (LBB) condition uniformly in h on quadrilateral meshes (Brezzi-Fortin; for
// Q2/Q1 Stenberg's macro-element argument), so it needs no pressure stabilisation and converges with
// velocity order 3 in L2 and pressure order 2. Geometry is isoparametric Q2 (the nodes of a curved boundary on
// the curve). The element residual and exact Newton Jacobian come from one Kokkos kernel over the elements
// (models/flow/kernels.hpp, "polymech::flow::element_residual_jacobian"); the host scatters them into a CSR
// pattern built once and factorises the Jacobian with the sparse direct solver (kernels/solvers/
// host_sparse_lu.hpp), Dirichlet velocities eliminated (their rows and columns left out).
//
// Time: BDF2 with the first step backward Euler, Newton to convergence in every step. BDF2 rather than
// Crank-Nicolson: it is L-stable (CN keeps the stiff viscous and pressure modes undamped and needs the pressure
// at half steps), it costs one nonlinear solve per step like CN, and its form c_t (u - u*) leaves the kernel
// identical to the steady one apart from c_t. Its price: a slight damping of resolved oscillations,
// O((omega dt)^4) per step.
//
// Forces on the obstacle (Babuska-Miller; the "volume" or reaction form): with the discrete solution, the
// residual of the weak momentum equation tested with v = e_k on the obstacle's velocity nodes (zero elsewhere)
// is the integral of the traction over the obstacle, so the force the fluid exerts on it is
//   F_k = - sum_(obstacle nodes a) R_(a,k)(u_h, p_h)
// (Turek & Hron 2006 eq. for F_D, F_L, written as a domain integral over the elements that touch the body).
// It converges at the rate of the energy norm squared, against the rate of the stress for a line integral.
//
// The pieces, by job:
//   navier_stokes_model.hpp           FlowConfig, the reports, the class NavierStokes2D (state, accessors)
//   navier_stokes_discretization.hpp  DoF numbering, basis, geometry, body force, the CSR pattern
//   navier_stokes_solve.hpp           assembly (element kernel, scatter, forces), Newton, steady solve, BDF2 step
//   navier_stokes_motion.hpp          Dirichlet values, per-node velocities, ALE mesh, the time state
//   navier_stokes_evaluate.hpp        point values, integrals, the divergence, boundary fluxes
// The element kernel is in models/flow/kernels.hpp. This header includes them all.
#pragma once

#include "flow/navier_stokes_discretization.hpp"
#include "flow/navier_stokes_evaluate.hpp"
#include "flow/navier_stokes_model.hpp"
#include "flow/navier_stokes_motion.hpp"
#include "flow/navier_stokes_solve.hpp"
