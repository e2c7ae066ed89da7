// A neutral unstructured mesh, as a mesh file holds it: nodes, volume cells and named surface facets,
// each element with the place it was read from. Readers (io/gmsh_msh.hpp) fill it and know nothing of
// the methods; each method converts it to what it discretises (a Helmholtz hexahedral mesh with named
// boundary faces, a DEM surface of quadrilaterals and triangles). Host data, free of Kokkos.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace polymech::mesh {

// An element as read: its nodes (indices into Mesh::nodes) and where it came from, for messages.
struct Hexahedron {
  std::array<std::int64_t, 8> nodes{};  // Gmsh / seed 002 paper 3 local order
  std::string origin;                  // "file:line" of its line in the mesh file
  long long tag = 0;                   // the file's element tag
};

struct Facet {
  std::array<std::int64_t, 4> nodes{};  // a triangle uses the first 3
  int corners = 4;                     // 3 (triangle) or 4 (quadrilateral)
  int group = -1;                      // index into Mesh::groups
  std::string origin;
  long long tag = 0;
};

struct Mesh {
  std::vector<double> nodes;           // node_count() x 3
  std::vector<Hexahedron> hexahedra;   // the volume cells
  std::vector<Facet> facets;           // surface elements of named groups
  std::vector<std::string> groups;     // the names of the surface groups
  std::string file;                    // where the mesh was read from ("" if generated)

  std::int64_t node_count() const { return static_cast<std::int64_t>(nodes.size() / 3); }
  int group_index(const std::string& name) const {
    for (std::size_t g = 0; g < groups.size(); ++g)
      if (groups[g] == name) return static_cast<int>(g);
    return -1;
  }
};

}  // namespace polymech::mesh
