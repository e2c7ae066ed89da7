// A Helmholtz hexahedral mesh (mesh.hpp) from a neutral mesh as a file holds it (models/common/mesh.hpp):
// the hexahedra, checked for inversion, and the named boundary faces, each facet matched to a face of
// the mesh's exterior. Errors (std::invalid_argument) name the element's file and line.
#pragma once

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>

#include "common/mesh.hpp"
#include "helmholtz/mesh.hpp"

namespace polymech::helmholtz {

inline HexMesh hex_mesh_from(const mesh::Mesh& in) {
  auto fail = [&](const std::string& where, const std::string& what) {
    throw std::invalid_argument((where.empty() ? in.file : where) + ": " + what);
  };
  HexMesh m;
  m.vertices = in.nodes;
  for (const auto& h : in.hexahedra) {
    for (int k = 0; k < 8; ++k) m.hexes.push_back(h.nodes[k]);
    m.element_origin.push_back(h.origin + ", element " + std::to_string(h.tag));
    const double ratio = min_corner_jacobian_ratio(m, m.element_count() - 1);
    if (!(ratio > 0)) {
      char r[32];
      std::snprintf(r, sizeof r, "%.6g", ratio);
      fail(h.origin, "hexahedron " + std::to_string(h.tag) + " is inverted or degenerate (det J at a corner / mean = " + r +
                         "; allowed: > 0); its nodes must follow Gmsh's hexahedron order");
    }
  }
  if (m.element_count() == 0)
    fail("", "no 8-node hexahedra in volumes; allowed: hexahedral meshes (e.g. transfinite/recombined volumes, or "
             "Mesh.SubdivisionAlgorithm = 2)");
  // Boundary facets -> (element, local face) of the mesh exterior.
  std::int64_t overused = 0;
  const auto exterior = exterior_faces(m, &overused);
  if (overused > 0)
    fail("", std::to_string(overused) + " faces are shared by more than two hexahedra (overlapping or non-conforming mesh)");
  std::map<std::array<std::int64_t, 4>, std::size_t> face_of;
  for (std::size_t k = 0; k < exterior.size(); ++k) {
    const auto fv = hex_face_vertices(exterior[k].face);
    std::array<std::int64_t, 4> key;
    for (int c = 0; c < 4; ++c) key[c] = m.hexes[8 * exterior[k].element + fv[c]];
    std::sort(key.begin(), key.end());
    face_of[key] = k;
  }
  m.boundary_names = in.groups;
  std::vector<int> assigned(exterior.size(), -1);
  for (const auto& q : in.facets) {
    const std::string& name = in.groups.at(static_cast<std::size_t>(q.group));
    if (q.corners != 4)
      fail(q.origin, "3-node triangle elements on the physical surface '" + name +
                         "' are not supported; allowed on boundaries: 4-node quadrangles (type 3)");
    auto key = q.nodes;
    std::sort(key.begin(), key.end());
    const auto it = face_of.find(key);
    if (it == face_of.end())
      fail(q.origin, "quadrangle " + std::to_string(q.tag) + " of boundary '" + name +
                         "' is not a face on the boundary of the hexahedral mesh");
    int& a = assigned[it->second];
    if (a >= 0 && a != q.group)
      fail(q.origin, "quadrangle " + std::to_string(q.tag) + " is in two boundaries ('" + in.groups[a] + "' and '" + name + "')");
    if (a < 0) {
      a = q.group;
      BoundaryFace f = exterior[it->second];
      f.boundary = q.group;
      m.boundary_faces.push_back(f);
    }
  }
  return m;
}

}  // namespace polymech::helmholtz
