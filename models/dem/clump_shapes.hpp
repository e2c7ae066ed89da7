// Multi-sphere clumps (seed 002 paper 2, sec. 2: a gravel particle is a rigid union of elemental
// spheres, after Favier et al.), Kokkos-free: shapes, their mass properties computed numerically over
// the union of the spheres (overlaps counted once), and the expansion of a configuration's clumps into
// member spheres and rigid bodies, which the model (models/dem/dem.hpp) and io/ (the time-step limit,
// the cost estimate) share.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace polymech::dem {

// A clump's shape: spheres (centre x, y, z and radius) in the shape's own frame and units.
struct ClumpShape {
  std::string name;
  std::vector<std::array<double, 4>> spheres;
};

// Mass properties of a shape per unit density: volume, centre, inertia tensor about the centre (shape
// axes), its principal moments (ascending) and axes (columns; a right-handed rotation, principal ->
// shape frame).
struct UnionMassProperties {
  double volume = 0.0;
  std::array<double, 3> centre{};
  std::array<std::array<double, 3>, 3> inertia{};
  std::array<double, 3> principal{};
  std::array<std::array<double, 3>, 3> axes{};
};

// The union of the shape's spheres integrated on a grid of columns (`columns` across the larger side of
// the bounding box, midpoint rule in x, y), each column exactly in z: the union of the spheres' chords
// (overlaps once) and the moments z^0..z^2 of each merged interval in closed form. Converges as
// columns^-1.5 (the chord length has an infinite slope at the silhouette): docs/VALIDATION.md.
UnionMassProperties union_mass_properties(const ClumpShape& shape, int columns = 200);

// The paper's three gravel particle models (Fig. 2 draws them; the text gives no coordinates: the
// reading taken is in docs/METHODS.md), scaled to a unit bounding radius about their centre of mass:
//   "cylinder": three equal spheres in a row; "cone": four spheres along an axis, radii falling 1 ->
//   0.4; "cube": eight equal spheres at the corners of a cube.
const std::vector<ClumpShape>& gravel_shapes();

// The 3 x 3 symmetric eigenproblem (Jacobi rotations): eigenvalues ascending, eigenvectors as columns
// of a right-handed rotation.
void symmetric_eigen(const std::array<std::array<double, 3>, 3>& a, std::array<double, 3>& values,
                     std::array<std::array<double, 3>, 3>& vectors);

// Quaternion (w, x, y, z) of a rotation matrix, and the product a b.
std::array<double, 4> quaternion_of(const std::array<std::array<double, 3>, 3>& r);
std::array<double, 4> quaternion_product(const std::array<double, 4>& a, const std::array<double, 4>& b);

}  // namespace polymech::dem
