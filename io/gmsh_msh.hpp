// Reader of unstructured hexahedral meshes in Gmsh's MSH 4.1 ASCII format (host-only).
//
// What is read: the nodes; the 8-node hexahedra (element type 5) of the volume entities; the 4-node
// quadrangles (type 3) of surface entities that belong to a named physical group, which become named
// boundary faces (the names a scene's [[boundary]] tables refer to). Points and lines are skipped, as
// are $NodeData-like sections. Everything else that a hexahedral solver cannot use is an error naming
// the file, the line and what is allowed: another version or the binary format, tetrahedra, prisms,
// high-order hexahedra, a partitioned mesh, an unknown node tag, a quadrangle that is not a face of
// the mesh's boundary, an inverted or degenerate hexahedron, a face shared by three elements.
//
// Write meshes with   gmsh -3 -format msh41 model.geo   (ASCII is Gmsh's default for .msh).
#pragma once

#include <filesystem>

#include "helmholtz/mesh.hpp"
#include "io/scene.hpp"

namespace polymech::io {

// A malformed or unusable mesh file: one message "<file>:<line>: <what>; <what is allowed>". Derives
// from SceneError so apps treat it as bad input.
class MeshError : public SceneError {
 public:
  using SceneError::SceneError;
};

helmholtz::HexMesh read_gmsh_hex_mesh(const std::filesystem::path& file);

}  // namespace polymech::io
