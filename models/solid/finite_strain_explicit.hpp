// Explicit dynamics at finite strain with nodes tied to a rigid body (issue 34: "explicit central differences
// with a lumped mass", "nodes tied to a rigid body"; issue 37: the tyre is stepped explicitly with the DEM and its
// rim is a rigid body carrying the load, the speed and the slip).
//
// The pieces, by job:
//   rigid_tie.hpp              RigidTie, TieState: the tie's description and the body's state
//   hyperelastic_explicit.hpp  the options and solid::HyperelasticExplicit: velocity Verlet with a lumped mass
//   explicit_ties.hpp          the bodies: set-up, the tied nodes' placement, the forces on and of the drivers
//   explicit_stability.hpp     the critical step by power iteration on M_L^-1 K_t
// Their device kernels (kick, drift, accelerations, the tied nodes, the power iteration) are in
// kernels/solid/explicit_dynamics.hpp.
// This header includes them all.
#pragma once

#include "solid/explicit_stability.hpp"
#include "solid/explicit_ties.hpp"
#include "solid/hyperelastic_explicit.hpp"
#include "solid/rigid_tie.hpp"
