// A rigid wheel driven over the gravel bed (seed 002 paper 2, sec. 4, Figs. 6-10): the tyre's surface
// as an FE quadrilateral mesh (radius 445 mm, width 310 mm), carried by one rigid body whose x velocity
// and spin follow the paper's schedule while its height is free under the vertical load. Kokkos-free:
// the mesh, the schedule and the measures; the model (dem.hpp) moves the mesh and sums the reaction.
//
// Schedule (times from `start`, the moment the wheel is set on the bed; the paper's steps b)-c)):
//   vertical load  F(t) = load * ramp(t; load_from, load_to)       10 163 N over 10-12 ms
//   speed          v(t) = speed * ramp(t; speed_from, speed_to)     over 12-15 ms
//   spin           omega(t) = v(t) / ((1 - slip) R)                 slip s = 1 - v / (omega R) = 20 %
//   vertical damper  F_d = -damping * z'                            none by default (WheelSpec::damping)
// The paper's step a) (inflation over 0-10 ms) belongs to the deformable tyre; a rigid wheel just
// waits on the bed during it, unloaded. The wheel runs along +x, its axis along y; a positive spin
// about +y rolls it forward, so with slip > 0 the tread pushes the gravel backwards (a driven wheel).
#pragma once

#include <array>
#include <string>
#include <vector>

namespace polymech::dem {

struct SurfaceInit;  // dem/config.hpp (which holds a WheelSpec)

struct WheelSpec {
  double radius = 0.0;         // R (m); 0: no wheel
  double width = 0.0;          // along y (m)
  int around = 0;              // facets around the tread (0: about the gravel's radius_max each)
  int across = 0;              // facets across the width
  double side_depth = 0.0;     // the side walls: annuli from R down to R - side_depth (keep gravel out)
  double mass = 0.0;           // of the wheel's vertical motion (kg)
  double damping = 0.0;        // N s/m: a dashpot on the rim's vertical velocity, reacted by the carriage (a test
                               // rig's or a suspension's damper; issue 37); 0: none, the paper's reading
  double load = 0.0;           // vertical load (N), downwards
  double load_from = 0.0, load_to = 0.0;    // its ramp (s after start)
  double speed = 0.0;          // forward speed (m/s)
  double speed_from = 0.0, speed_to = 0.0;  // its ramp (s after start)
  double slip = 0.0;           // s in [0, 1)
  double start = 0.0;          // simulated time at which the wheel is set on the bed (s)
  double x_start = 0.0, y_centre = 0.0;     // where (the axis' x; the middle of the tread in y)
  std::array<double, 3> parked{};           // the centre before start (far above the bin)

  bool enabled() const { return radius > 0; }
  double load_at(double t_from_start) const;   // F(t) (N), 0 before the ramp
  double speed_at(double t_from_start) const;  // v(t)
  double spin_at(double t_from_start) const;   // omega(t) about +y
  // The damper is explicit (on the half-step velocity): per step of `step` seconds it scales the rim's vertical
  // velocity by 1 - damping step / mass, so it must stay below 1 (at 1 it stops the rim in one step, above it
  // reverses it, and at 2 it diverges). Empty when damping < mass / step, else what is wrong, the limit named.
  std::string damping_problem(double step) const;
};

// The wheel's surface, nodes relative to its centre (axis along y): the tread, `around` x `across`
// quadrilaterals, and two side annuli (`side_depth` deep, rings of quadrilaterals about as long as
// the tread's), all counter-clockwise seen from outside. Throws std::invalid_argument for a bad spec.
SurfaceInit wheel_surface(const WheelSpec& w);

// The bed under the wheel at x_start: `highest`, the height of the wheel's lowest point when, lowered,
// it first touches a sphere (the circle of radius R in x-z against the spheres with |y - y_centre| <
// width/2), where the wheel is set down; `mean`, the mean of the highest sphere tops in columns of
// 2 r_max over |x - x_start| < R/2 and |y - y_centre| < width/2: the bed's level, from which the rim
// sinkage is measured.
struct BedLevel {
  double highest = 0.0, mean = 0.0;
};
BedLevel bed_level(const std::vector<std::array<double, 4>>& spheres, const WheelSpec& w, double r_max);

}  // namespace polymech::dem
