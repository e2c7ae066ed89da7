// Configuration of the stabilized ISPH model (seed 002 paper 4) as plain data (Kokkos-free): filled by
// io/isph_scene.cpp or directly by tests.
#pragma once

#include <string>

#include "effects.hpp"

namespace polymech::isph {

enum class WallCondition { no_slip, slip };  // eqs. (29)-(30) / (27)-(28)
// Values at the ghost points: the paper's Shepard interpolation, eq. (23) (default; biased near a wall by a
// fraction of l0), or a linear least-squares fit over the ghost's neighbours (exact for a linear field).
enum class GhostInterpolation { linear, shepard };
// The pressure gradient of the projection: the paper's symmetric form, eqs. (9) and (19), with (p_j + p_i)
// and (p_c + p_i) (default): momentum exchanged pair by pair, the body's force the sum of its points'
// reactions (eqs. (38)-(43)), but not zero for a constant pressure on an irregular particle set (a force
// error growing with the absolute pressure and with dt / l0: +0.9 to +4.4 % buoyancy on an immersed
// cylinder); or the difference form with (p_j - p_i) and (p_c - p_i): exact for a constant pressure, the
// body's pressure force then the integral of the fluid pressure over its surface, but unstable in the
// floating runs (docs/VALIDATION.md, ISPH stage 4).
enum class PressureGradient { difference, symmetric };
// Free-surface particles (p = 0): where the summation density (fluid + walls, eqs. (13), (18)) is below
// surface_threshold x rho0; or where the divergence of position, sum_j V_j (x_j - x_i) . grad W_ij over
// fluid and wall points (d inside the water, about d/2 at a flat surface), is below surface_divergence
// and the density below rho0 (Lee et al. 2008's test, with the density cap so that a surface layer
// pressed onto the one below gets a pressure and is pushed off it; the paper does not say how it detects
// the surface). The density test alone is fooled when the top layer compacts onto the one below (its
// density rises back over the threshold although nothing lies above it: the surface loses its p = 0
// there, docs/VALIDATION.md); the position divergence measures the missing part of the support.
// divergence_or_density flags a particle when either test does: the divergence keeps the top layer
// flagged, the density also sets p = 0 at water torn apart inside the tank (the jet squeezed out under a
// dense body landing on the bottom, which the divergence test alone let blow up: docs/VALIDATION.md).
enum class SurfaceDetection { density, divergence, divergence_or_density };

// A floating circular cylinder (2D) of IGCB cells (effect `rigid_body`, eqs. (31)-(43)).
struct Body {
  double centre[2] = {0.0, 0.0};  // initial centre [m]
  double diameter = 0.0;          // [m] (0: no body)
  double density_ratio = 0.8;     // rho_r / rho0
  double added_mass = 1.0;         // C_a: the coupling treats C_a rho0 pi R^2 implicitly (0: the paper's plain CSS)
  // The water's initial particles around the body (docs/METHODS.md, "The water around an immersed body"):
  // the lattice without its points closer than R + clearance l0 to the centre (default 0: the gap to the
  // body's outer cells averages one spacing, as in the lattice; 0.5 was the layout before 2026-11-24, half
  // a spacing more, ~7 % of the density missing beside the body), or, with rings K > 0, K rings of
  // particles at R + (k + 1/2) l0 (round(2 pi r / l0) each, concentric with the body's cells) and the
  // lattice from R + (K + clearance) l0.
  int fluid_rings = 0;
  double fluid_clearance = 0.0;   // [l0]
  double release_time = 0.0;      // [s] held fixed (force still computed) until then: the pressure of the
                                  // water started from rest needs a few hundred steps to become hydrostatic
  // Contact with the tank's bottom and sides: the shared Hertz-Mindlin law (kernels/contact/hertz_mindlin.hpp)
  // of a disc of unit thickness against a rigid plane.
  double contact_modulus = 0.0;   // E* [Pa] (0: the modulus whose impact at the tank's free-fall speed lasts 20 steps)
  double restitution = 0.5;       // of an impact in the contact law alone (the water damps it further)
  double friction = 0.3;          // Coulomb coefficient against the walls
};

struct Config {
  int dim = 2;                      // 2 (the paper's cases) or 3 (the hydrostatic tank)
  double spacing = 5e-3;            // l0 [m] (Table 1)
  double radius_factor = 3.3;       // re / l0 (Table 1)
  double density = 1000.0;          // rho^0 [kg/m^3]
  double viscosity = 1e-6;          // nu [m^2/s] (Table 1 prints 1e-3, 1000x water: a scene option)
  double gravity = 9.8;             // along -y [m/s^2]
  double alpha = 5e-3;              // density relaxation, eq. (4) (used when `stabilization` is on)
  double dt = 5e-4;                 // [s]
  double surface_threshold = 0.9;   // beta: free surface where rho_i < beta rho^0
  SurfaceDetection surface_detection = SurfaceDetection::density;
  double surface_divergence = 0.0;  // divergence test: free surface where div r < this (0: 1.5 in 2D, 2.4 in 3D)
  double tank[3] = {0.2, 0.2, 0.2};   // inner size of the tank: x, y (height), z (3D); walls below and on the sides
  double fluid[3] = {0.2, 0.1, 0.2};  // the initial water block, from the tank's lower corner (x = 0, y = 0)
  bool surface_correction = true;   // renormalised eq. (9) at free-surface particles (false: as printed)
  WallCondition wall = WallCondition::no_slip;
  GhostInterpolation ghost_interpolation = GhostInterpolation::shepard;
  PressureGradient pressure_gradient = PressureGradient::symmetric;
  Body body;                        // used with the effect `rigid_body`
  double tolerance = 1e-8;          // PPE: relative residual
  int max_iterations = 2000;        // PPE: BiCGSTAB iterations per step
  // PPE operator: its pair coefficients stored once per step (true: three sparse products per apply, one
  // value per pair of the three lists in memory) or recomputed in every apply (false: matrix-free, no
  // per-pair memory). Both give the same pressure to the bit (docs/PERFORMANCE.md, ISPH).
  bool ppe_stored = true;
  // PPE preconditioner: Jacobi (the rows scaled by their diagonal: ~1.75 sqrt(N) BiCGSTAB iterations) or
  // two-level (Jacobi smoothing plus a coarse correction on aggregates of ppe_coarse_cell x ... spacings,
  // models/isph/ppe_two_level.hpp; needs the stored operator; not in the paper).
  enum class Preconditioner { jacobi, two_level } ppe_preconditioner = Preconditioner::jacobi;
  double ppe_coarse_cell = 4.0;     // [l0] side of an aggregate of the two-level preconditioner
  EffectSet effects;
};

// Counts of a configuration (host, no allocation): fluid particles and wall integration points.
struct Counts {
  long long fluid = 0, wall_points = 0;
};

}  // namespace polymech::isph
