// A Helmholtz hexahedral mesh from a neutral mesh as a file holds it: mesh::hex_mesh_from
// (models/common/hex_mesh.hpp, shared with the solid models).
#pragma once

#include "common/hex_mesh.hpp"
#include "helmholtz/mesh.hpp"

namespace polymech::helmholtz {

using mesh::hex_mesh_from;

}  // namespace polymech::helmholtz
