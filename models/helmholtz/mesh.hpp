// Linear hexahedral meshes with named boundary faces: the shared ones of models/common/hex_mesh.hpp (moved
// there so that the solid models read Gmsh meshes with the same code), under the Helmholtz model's names.
#pragma once

#include "common/hex_mesh.hpp"

namespace polymech::helmholtz {

using mesh::BoundaryFace;
using mesh::box_hash;
using mesh::BoxSpec;
using mesh::exterior_faces;
using mesh::hex_face_vertices;
using mesh::hex_vertex;
using mesh::HexMesh;
using mesh::make_box_mesh;
using mesh::min_corner_jacobian_ratio;

}  // namespace polymech::helmholtz
