// The element-free Galerkin model of a cracked plate (seed 004, Hagihara et al.), as plain data: what
// io/ fills from a scene and tests fill directly. Lengths in m, stresses in Pa, unit thickness.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "effects.hpp"

namespace polymech::efg {

enum class CrackKind { none, edge, centre };
// tension: traction +-stress on the top and bottom edges, the rigid-body modes held at points where
// symmetry makes the held components zero; patch: the linear field `patch` imposed on the whole
// boundary (the patch test).
enum class Loading { tension, patch };

struct Config {
  CrackKind crack = CrackKind::edge;
  Loading loading = Loading::tension;
  // The plate [0, width] x [-height/2, height/2] (edge crack from (0, 0) to (crack_length, 0)) or
  // [-width/2, width/2] x [-height/2, height/2] (centre crack from (-crack_length, 0) to (crack_length, 0):
  // crack_length is the half-length a).
  double width = 1.0;
  double height = 3.0;
  double crack_length = 0.5;
  // Node lines: spacing h_min at the crack tip(s) (x) and the crack line (y), growing by `growth` per
  // unit distance (dh/ds) up to h_max. Background cells are the rectangles between the node lines.
  double h_max = 0.05;
  double h_min = 0.05;
  double growth = 0.3;
  // The node lines are refined about x = tip + tip_offset x h_min: 0 puts a node on the tip, 0.5 puts
  // the tip half-way between two nodes (a hard case of the issue).
  double tip_offset = 0.0;
  // Interior nodes off the crack line moved by up to jitter x the local spacing (0: none).
  double jitter = 0.0;
  std::uint64_t seed = 1;
  // Support radius of node I: support_factor x the largest spacing of the node lines through it.
  double support_factor = 1.5;
  int gauss = 10;  // Gauss points per cell and direction (the paper: 10 x 10)
  // Material (seed 004 §3.1: E = 7562 MPa, nu = 0.394, rho = 1191 kg/m^3).
  double young = 7.562e9;
  double poisson = 0.394;
  double density = 1191.0;
  bool plane_strain = true;
  double stress = 1e7;              // applied traction [Pa]
  double penalty = 1e6;             // penalty stiffness / young (essential conditions by penalty)
  double min_moment_ratio = 1e-8;   // det(A) / (A00 A11 A22) below this: an error naming the point
  std::array<double, 6> patch{};    // ux = c0 + c1 x + c2 y, uy = c3 + c4 x + c5 y (Loading::patch)
  // J-integral: circular contours around the (right) tip, radii in m; arcs x Gauss points per arc.
  std::vector<double> j_radii{0.2, 0.25, 0.3, 0.35, 0.4};
  int j_arcs = 20;
  int j_gauss = 4;
  // J-integral band: > 0 replaces the contour value at radius r by its mean over the radii
  // [r - d/2, r + d/2], d = j_band x the local node spacing h(r) = min(h_max, h_min + growth r), taken at
  // 4 radial Gauss points (a smoothed, equivalent-domain form of eq. (13)); 0: the single contour of the
  // paper. The single contour carries an error that oscillates with r at the period of the node lines
  // (docs/METHODS.md, 'J-integral band').
  double j_band = 0.0;
  // Crack growth at a prescribed speed (seed 004 §3.3): from t = growth_start [s] both tips run at
  // growth_speed [m/s] up to final_crack_length (the half-length for a centre crack). growth_speed = 0: a
  // stationary crack. path_nodes = false: the crack line carries no node along the path (a node on it
  // would be seen from both faces once the crack passed; the background cells keep their edges on the
  // line). path_nodes = true (the paper's Model 4, whose nodes follow the physical shape, §3.3): a node
  // on every node line along the path, split in two (one on each face, the same coefficients) when the
  // tip passes it.
  // Newmark's gamma: 0.5 with beta = 1/4 is the paper's average acceleration (no numerical damping);
  // gamma > 0.5 with beta = (gamma + 1/2)^2 / 4 damps the highest frequencies (not in the paper: a test of
  // how much of the running crack's noisy K is undamped high-frequency response, docs/VALIDATION.md).
  double newmark_gamma = 0.5;
  double growth_start = 0.0;
  double growth_speed = 0.0;
  double final_crack_length = 0.0;
  bool path_nodes = false;
  // How a split path node lets go: false (sudden, the default), its twins free at once; true (gradual),
  // tied by a spring whose stiffness falls linearly from penalty x E to 0 while the tip runs the next node
  // spacing (not in the paper: the finite-element node-release remedy, docs/VALIDATION.md).
  bool path_release_gradual = false;
  EffectSet effects;
};

}  // namespace polymech::efg
