// Reader of unstructured meshes in Gmsh's MSH 4.1 ASCII format (host-only), into the neutral mesh of
// models/common/mesh.hpp; each method converts that to what it needs (helmholtz::hex_mesh_from).
//
// What is read: the nodes; the 8-node hexahedra (element type 5) of the volume entities; the 4-node
// quadrangles (type 3) and 3-node triangles (type 2) of surface entities that belong to a named
// physical group (the names a scene's [[boundary]] tables refer to). Points and lines are skipped, as
// are $NodeData-like sections. What no method here can use is an error naming the file, the line and
// what is allowed: another version or the binary format, tetrahedra, prisms, high-order elements, a
// partitioned mesh, an unknown node tag, a hexahedron that repeats a node, a surface in two groups.
//
// Write meshes with   gmsh -3 -format msh41 model.geo   (ASCII is Gmsh's default for .msh).
#pragma once

#include <filesystem>

#include "common/mesh.hpp"
#include "io/scene.hpp"

namespace polymech::io {

// A malformed or unusable mesh file: one message "<file>:<line>: <what>; <what is allowed>". Derives
// from SceneError so apps treat it as bad input.
class MeshError : public SceneError {
 public:
  using SceneError::SceneError;
};

mesh::Mesh read_gmsh_mesh(const std::filesystem::path& file);

}  // namespace polymech::io
