// Order-p DoFs of a linear hexahedral mesh: the shared numbering, coloring and chunking of
// models/common/hex_dofs.hpp (moved there so that the solid models' unstructured discretization uses the same
// code), under the Helmholtz model's names.
#pragma once

#include "common/hex_dofs.hpp"
#include "helmholtz/mesh.hpp"

namespace polymech::helmholtz {

using mesh::color_by_shared_vertices;
using mesh::dofs_on_faces;
using mesh::dofs_on_segment;
using mesh::face_local_nodes;
using mesh::HexDofs;
using mesh::linear_subcells;
using mesh::locality_order;
using mesh::number_dofs;
using mesh::perturb_nodes;
using mesh::sort_by_color;

}  // namespace polymech::helmholtz
