// Configuration of the static linear solid model (issue 34), plain data: the mesh, the element order, the
// law, and loads and constraints as small objects, each acting on a named side of the structured mesh
// (xmin, xmax, ymin, ymax, zmin, zmax; models/solid/mesh.hpp), or, in 3D, on a named boundary (physical surface
// group) of an unstructured hexahedral mesh (`hex_mesh`, e.g. a Gmsh file).
#pragma once

#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "materials/hill_plasticity.hpp"
#include "common/hex_mesh.hpp"
#include "materials/voigt.hpp"
#include "solid/mesh.hpp"

namespace polymech::solid {

// A displacement field or a force density given as a function of the position (host, set-up only).
using PointFunction = std::function<void(const double* x, double* value)>;

// u_c = value(x)_c (zero when value is empty) for the components c in `components` (bit c) on a side.
struct Dirichlet {
  std::string boundary;
  unsigned components = 7u;  // all
  PointFunction value;       // empty: fixed (u = 0)
};

// A constant traction vector t (force per area in 3D, per length and unit thickness in 2D) on a side.
struct Traction {
  std::string boundary;
  std::array<double, 3> t{0.0, 0.0, 0.0};
};

// A body force per volume b(x).
struct BodyForce {
  PointFunction b;
};

// 2D: plane strain (eps_33 = 0: the 3D law's (11, 22, 12) block) or plane stress (sigma_33 = 0: the law
// condensed by materials::plane_stress_condensed).
enum class Plane { strain, stress };

template <int D>
struct Config {
  StructuredMesh<D> mesh;
  // 3D only: an unstructured mesh of 8-node hexahedra with named boundaries, e.g.
  // mesh::hex_mesh_from(io::read_gmsh_mesh(file)); when it has elements it replaces `mesh`, and the boundaries
  // the loads and constraints name are its groups (models/solid/discretization.hpp).
  ::polymech::mesh::HexMesh hex_mesh;
  int order = 2;
  materials::Stiffness6<double> stiffness = materials::isotropic_stiffness(1.0, 0.3);  // 3D Voigt C, every element
  // Elasto-plasticity (models/solid/elastoplastic.hpp): absent = elastic with `stiffness` (no history is
  // allocated); present = this return mapping at every quadrature point. Its elastic stiffness law.C should
  // equal `stiffness` (the elastic preconditioner and the linear model read `stiffness`; ElastoPlastic checks).
  std::optional<materials::HillPlasticity<double>> plasticity;
  Plane plane = Plane::strain;  // 2D only
  std::vector<Dirichlet> dirichlet;
  std::vector<Traction> tractions;
  std::vector<BodyForce> body_forces;
  bool affine_geometry = true;  // one Jacobian per affine element (false: factors at every point)
  int chunk_edge = 0;           // cells per chunk direction (hex_mesh: chunk_edge^3 elements per chunk); 0: default
};

}  // namespace polymech::solid
