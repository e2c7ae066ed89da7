// The channel of the flow-driven harvester (seed 002 paper 1, case 2, Fig. 5; issue 36): a rigid square cylinder
// of side D in a uniform stream, a thin flexible plate clamped to the middle of its rear face. The paper gives
// the plate (270 mm long, two 0.2 mm PZT-5A layers on a 0.2 mm brass host) and the air speed (0.85 m/s), not the
// cylinder nor the channel; models/fsi/flow_harvester.hpp chooses D, this file builds the mesh for any D.
//
// Geometry (lengths in D unless named): the inflow at x = 0, the cylinder's front face at x = upstream, the
// plate from its rear face (the root, x_r = upstream + 1) to the tip x_t = x_r + plate_length, the outflow
// downstream of the tip; the channel 0 <= y <= height, the cylinder and plate centred at y_c = height / 2.
//
// Blocks (make_harvester_channel): four columns (upstream | cylinder | plate | wake) by five rows (below the
// cylinder | the cylinder's lower half | the plate's thickness | the upper half | above), the cylinder's three
// middle cells and the plate's one left out; the upstream column's three middle rows are one block (the
// cylinder's front face). Each row and column is graded by a fixed map (the same at every level), fine at the
// cylinder and at the plate, so a level doubles every count and halves every cell. The plate row is one cell
// thick at every level (the tip face: three Q2 nodes, matched to the solid's nodes there). The plate column's
// cells are uniform: its Q2 nodes on the two faces are the nodes of an order-2 solid with the same cells.
//
// Tags: x = 0 kInflow, y = 0 and y = height kWall (models/fsi/flow_harvester.hpp moves them with the stream:
// a far-field condition), the outflow kOutflow, the cylinder's faces and the plate's faces kObstacle.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "flow/mesh.hpp"

namespace polymech::flow {

struct HarvesterGeometry {
  double side = 0.03;              // D [m]
  double plate_length = 0.27;      // [m]
  double plate_thickness = 0.6e-3; // [m]
  double upstream = 5.0, downstream = 8.0, height = 14.0;  // in D
  double x_root() const { return (upstream + 1.0) * side; }
  double x_tip() const { return x_root() + plate_length; }
  double y_centre() const { return 0.5 * height * side; }
  double length() const { return x_tip() + downstream * side; }
};

// Cells per block at level 0 (each doubles per level; the plate's row stays one cell thick).
struct HarvesterCells {
  int upstream = 4, cylinder = 2, plate = 12, wake = 6;   // along x
  int outer = 4, half = 2;                                 // along y: above/below the cylinder, its half minus the plate's
};

inline std::vector<double> reversed_planes(const std::vector<double>& p) {
  std::vector<double> r(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) r[k] = 1.0 - p[p.size() - 1 - k];
  return r;
}

inline QuadMesh make_harvester_channel(int level, const HarvesterGeometry& g, const HarvesterCells& n0 = {}) {
  if (level < 0 || level > 4) throw std::invalid_argument("harvester mesh: level " + std::to_string(level) + " outside 0..4");
  const double D = g.side, t = g.plate_thickness;
  if (!(D > 0.0) || !(g.plate_length > 0.0) || !(t > 0.0) || !(t < 0.5 * D))
    throw std::invalid_argument("harvester mesh: need D > 0, a plate length > 0 and 0 < thickness < D / 2");
  if (!(g.upstream >= 1.0) || !(g.downstream >= 1.0) || !(g.height >= 3.0))
    throw std::invalid_argument("harvester mesh: upstream and downstream >= 1 D, height >= 3 D");
  const int f = 1 << level;
  const int nu = n0.upstream * f, nc = n0.cylinder * f, np = n0.plate * f, nw = n0.wake * f, no = n0.outer * f, nh = n0.half * f;
  const double x0 = g.upstream * D, x1 = x0 + D, x2 = g.x_tip(), x3 = g.length();
  const double yc = g.y_centre(), H = g.height * D;
  const double y1 = yc - 0.5 * D, y2 = yc - 0.5 * t, y3 = yc + 0.5 * t, y4 = yc + 0.5 * D;
  // grading maps (fixed: the same at every level)
  const std::vector<double> up = reversed_planes(graded_planes(nu, 2.5));           // fine at the front face
  const std::vector<double> cyl = uniform_planes(nc), plate = uniform_planes(np);
  const std::vector<double> wake = geometric_planes(nw, (g.plate_length / np) / (x3 - x2));  // from the plate's cell size
  const std::vector<double> below = reversed_planes(graded_planes(no, 2.5)), above = graded_planes(no, 2.5);
  const std::vector<double> lower = reversed_planes(graded_planes(nh, 1.5)), upper = graded_planes(nh, 1.5);
  const std::vector<double> one = uniform_planes(1), face = uniform_planes(nc);
  MeshBuilder mb(x3);
  // upstream column: below, the front face, above
  mb.add(rect_block(0, x0, 0, y1, up, below, kWall, 0, kInflow, 0));
  mb.add(rect_block(0, x0, y1, y4, up, face, 0, 0, kInflow, kObstacle));
  mb.add(rect_block(0, x0, y4, H, up, above, 0, kWall, kInflow, 0));
  // the cylinder's column: below and above it
  mb.add(rect_block(x0, x1, 0, y1, cyl, below, kWall, kObstacle, 0, 0));
  mb.add(rect_block(x0, x1, y4, H, cyl, above, kObstacle, kWall, 0, 0));
  // the plate's column: below, the lower half (plate on top, cylinder on the left), the upper half, above
  mb.add(rect_block(x1, x2, 0, y1, plate, below, kWall, 0, 0, 0));
  mb.add(rect_block(x1, x2, y1, y2, plate, lower, 0, kObstacle, kObstacle, 0));
  mb.add(rect_block(x1, x2, y3, y4, plate, upper, kObstacle, 0, kObstacle, 0));
  mb.add(rect_block(x1, x2, y4, H, plate, above, 0, kWall, 0, 0));
  // the wake, the tip face on the plate row's left edge
  mb.add(rect_block(x2, x3, 0, y1, wake, below, kWall, 0, 0, kOutflow));
  mb.add(rect_block(x2, x3, y1, y2, wake, lower, 0, 0, 0, kOutflow));
  mb.add(rect_block(x2, x3, y2, y3, wake, one, 0, 0, kObstacle, kOutflow));
  mb.add(rect_block(x2, x3, y3, y4, wake, upper, 0, 0, 0, kOutflow));
  mb.add(rect_block(x2, x3, y4, H, wake, above, 0, kWall, 0, kOutflow));
  return mb.take();
}

}  // namespace polymech::flow
