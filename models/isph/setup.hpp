// What io/ needs of the ISPH model without compiling it (Kokkos-free): the particle and wall-point counts
// of a configuration, a time-step check, and the checks of a configuration.
#pragma once

#include <string>
#include <vector>

#include "isph/config.hpp"
#include "isph/effect_table.hpp"

namespace polymech::isph {

// Fluid particles and wall integration points the model will create.
Counts count(const Config& c);

// The initial fluid particles (n x dim, row-major): a lattice of spacing l0 filling the water block from
// the tank's lower corner, without the particles closer than l0 / 2 to the body (with `rigid_body`).
std::vector<double> fluid_positions(const Config& c);

// The body's IGCB cells (one Gauss point each): a polar mesh of the disk in rings of width ~l0, each
// ring cut into cells of arc length ~l0; point (r_mid, theta_mid), weight H |J| = r_mid dr dtheta (the
// cell's exact area). Positions relative to the centre.
struct BodyCells {
  std::vector<double> offset;  // n x 2
  std::vector<double> weight;  // H |J|
};
BodyCells body_cells(const Config& c);

// Area, centroid (relative to the centre) and polar moment of inertia of the body by quadrature over its
// cells, eqs. (33)-(35) (eq. (34) with the 1/A it is missing).
struct MassProperties {
  double area = 0.0, centroid[2] = {0.0, 0.0}, inertia = 0.0, mass = 0.0;
};
MassProperties mass_properties(const Config& c, const BodyCells& cells);

// The area of a disc of radius R below a line h above its lowest point (0 for h <= 0, pi R^2 for h >= 2R).
double segment_area(double R, double h);

// The equilibrium draft over the diameter of a floating cylinder of density ratio s (Archimedes: the
// submerged circular segment has the area s pi R^2).
double archimedes_draft_over_diameter(double density_ratio);

// The advective (CFL 0.4 at the dam-break speed 2 sqrt(g H)) and viscous (0.125 l0^2 / nu) limits.
struct TimeStepLimit {
  double cfl = 0.0, viscous = 0.0, limit = 0.0;
  std::string describe() const;
};
TimeStepLimit time_step_limit(const Config& c);

// The body's contact with the tank (effect `rigid_body`): the Hertz-Mindlin constants, the body's mass per
// unit thickness, and the duration of an undamped impact at the reference speed sqrt(2 g height) (a fall
// through the whole tank), which must span at least 10 steps (the scene's default spans 20).
struct BodyContact {
  double e_star = 0.0, beta = 0.0, mu = 0.0, mass = 0.0, reference_speed = 0.0, contact_time = 0.0;
};
BodyContact body_contact(const Config& c);

// Empty when the configuration can run; otherwise why not (rigid_body not implemented, fluid outside
// the tank, ...).
std::string check(const Config& c);

}  // namespace polymech::isph
