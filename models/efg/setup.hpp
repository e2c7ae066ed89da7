// What io/ and the model share of the EFG set-up, free of Kokkos: the node lines, nodes, support radii,
// background-cell Gauss points, boundary points and crack segments of a configuration (host vectors),
// and the handbook stress intensity factors the static cases are checked against.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "efg/config.hpp"
#include "efg/effect_table.hpp"

namespace polymech::efg {

struct Layout {
  std::vector<double> xs, ys;       // node lines (sorted)
  std::vector<double> nodes;        // x, y per node
  std::vector<double> dm;           // support radius per node
  std::vector<double> quad;         // x, y, weight per background-cell Gauss point
  std::vector<double> traction;     // x, y, weight, tx, ty per boundary Gauss point
  std::vector<double> penalty;      // x, y, stiffness, component (0, 1), value per penalty point
  std::vector<double> crack;        // x0, y0, x1, y1 per crack segment
  double tip_x = 0.0, tip_y = 0.0;  // the tip the J-integral is taken at
  double face_offset = 0.0;         // crack-face nodes sit this far off the face (y = +- face_offset)
  std::size_t node_count() const { return dm.size(); }
  std::size_t quad_count() const { return quad.size() / 3; }
};

// Points lo = x_0 < ... < x_n = hi with spacing h_min at each focus, growing by `growth` per unit
// distance from the nearest focus, at most h_max; every focus inside (lo, hi) is a point.
std::vector<double> graded_line(double lo, double hi, const std::vector<double>& foci, double h_min, double h_max,
                                double growth);

// The number of intervals graded_line would make, without making them (the loader's size estimate).
double graded_line_intervals(double lo, double hi, const std::vector<double>& foci, double h_min, double h_max, double growth);

// Node lines only.
void node_lines(const Config& c, std::vector<double>& xs, std::vector<double>& ys);

Layout make_layout(const Config& c);

// The node count of make_layout(c), from the node lines only (the loader's cost estimate).
std::size_t count_nodes(const Config& c);

// The pairs the model's fixed-radius searches will find, from the node lines (the loader's memory
// estimate, issue 33 item 11: a fine h_min beside a coarse h_max made the searches, which use the largest
// support radius everywhere, allocate 9 GB that the node count did not announce): `candidates`, the
// Gauss points' nodes within the largest support radius R; `pattern`, the node pairs within 2 R.
struct SearchSize {
  double candidates = 0.0, pattern = 0.0;
};
SearchSize search_size(const Config& c, const std::vector<double>& xs, const std::vector<double>& ys);

// Estimated node-line counts of a configuration (x, y) without building them.
void estimate_lines(const Config& c, double& nx, double& ny);

// Handbook K_I / (stress sqrt(pi a)) of an infinitely long strip (Tada, Paris & Irwin): edge crack
// F(a/W) = 1.12 - 0.231 s + 10.55 s^2 - 21.72 s^3 + 30.39 s^4 (0.5 % for a/W <= 0.6); centre crack
// F(a/b) = (1 - 0.025 s^2 + 0.06 s^4) sqrt(sec(pi s / 2)) (0.1 %), b the half-width.
double handbook_factor(const Config& c);

// The radial band of the J-integral at radius r (Config::j_band): j_band x min(h_max, h_min + growth r),
// the node spacing of the layout's rule at distance r from the tip; 0 when j_band is 0.
double j_band_width(const Config& c, double r);

// Effective modulus of K = sqrt(J E'): E / (1 - nu^2) in plane strain, E in plane stress.
double effective_modulus(const Config& c);

}  // namespace polymech::efg
