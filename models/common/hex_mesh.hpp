// Linear hexahedral meshes with named boundary faces: what the structured box generator and the Gmsh
// reader (io/gmsh_msh.hpp, through hex_mesh_from) produce, and what the order-p node numbering
// (common/hex_dofs.hpp) is built on. Shared by the Helmholtz model (models/helmholtz) and the solid models'
// unstructured discretization (models/solid/discretization.hpp); moved from models/helmholtz/mesh.hpp and
// mesh_import.hpp, whose names the Helmholtz headers bring into their namespace.
//
// Vertex order of a hexahedron: Gmsh's, which is also seed 002 paper 3's local numbering 1..8 (§3(1)):
// (-1,-1,-1), (1,-1,-1), (1,1,-1), (-1,1,-1), (-1,-1,1), (1,-1,1), (1,1,1), (-1,1,1) in (xi, eta, zeta).
// Local faces: 0: xi = -1, 1: xi = +1, 2: eta = -1, 3: eta = +1, 4: zeta = -1, 5: zeta = +1.
//
// hex_mesh_from: a hexahedral mesh from a neutral mesh as a file holds it (models/common/mesh.hpp): the
// hexahedra, checked for inversion, and the named boundary faces, each facet matched to a face of the mesh's
// exterior. Errors (std::invalid_argument) name the element's file and line.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/mesh.hpp"
#include "core/hash.hpp"

namespace polymech::mesh {

struct BoundaryFace {
  std::int64_t element = 0;
  int face = 0;      // local face 0..5
  int boundary = 0;  // index into HexMesh::boundary_names
};

struct HexMesh {
  std::vector<double> vertices;        // vertex_count x 3
  std::vector<std::int64_t> hexes;     // element_count x 8, Gmsh vertex order
  std::vector<std::string> boundary_names;
  std::vector<BoundaryFace> boundary_faces;
  std::vector<std::string> element_origin;  // optional, per element: where it was read ("duct.msh:57")
  std::string source;                       // the file it was read from ("" if generated), for messages

  std::int64_t vertex_count() const { return static_cast<std::int64_t>(vertices.size() / 3); }
  std::int64_t element_count() const { return static_cast<std::int64_t>(hexes.size() / 8); }
  int boundary_index(const std::string& name) const {
    for (std::size_t b = 0; b < boundary_names.size(); ++b)
      if (boundary_names[b] == name) return static_cast<int>(b);
    return -1;
  }
  std::string describe_element(std::int64_t e) const {
    std::string s = "element " + std::to_string(e);
    if (e >= 0 && e < static_cast<std::int64_t>(element_origin.size())) s += " (" + element_origin[e] + ")";
    return s;
  }
};

// Corner (i, j, k) in {0, 1}^3 of the reference cube -> Gmsh vertex index.
inline int hex_vertex(int i, int j, int k) {
  static const int v[2][2][2] = {{{0, 4}, {3, 7}}, {{1, 5}, {2, 6}}};  // v[i][j][k]
  return v[i][j][k];
}

// The four vertices (Gmsh indices) of local face f.
inline std::array<int, 4> hex_face_vertices(int f) {
  static const int fv[6][4] = {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}};
  return {fv[f][0], fv[f][1], fv[f][2], fv[f][3]};
}

// Faces that belong to one element only: the exterior of the mesh. Also reports faces shared by more
// than two elements (a non-conforming or overlapping mesh) through `overused` (count).
inline std::vector<BoundaryFace> exterior_faces(const HexMesh& m, std::int64_t* overused = nullptr) {
  std::map<std::array<std::int64_t, 4>, std::pair<int, BoundaryFace>> seen;
  for (std::int64_t e = 0; e < m.element_count(); ++e)
    for (int f = 0; f < 6; ++f) {
      const auto fv = hex_face_vertices(f);
      std::array<std::int64_t, 4> key;
      for (int c = 0; c < 4; ++c) key[c] = m.hexes[8 * e + fv[c]];
      std::sort(key.begin(), key.end());
      auto& s = seen[key];
      if (s.first++ == 0) s.second = {e, f, -1};
    }
  std::vector<BoundaryFace> out;
  std::int64_t over = 0;
  for (const auto& [key, s] : seen) {
    if (s.first == 1) out.push_back(s.second);
    if (s.first > 2) ++over;
  }
  if (overused) *overused = over;
  std::sort(out.begin(), out.end(), [](const BoundaryFace& a, const BoundaryFace& b) {
    return a.element != b.element ? a.element < b.element : a.face < b.face;
  });
  return out;
}

// det J of the trilinear map at the 8 corners, divided by (volume estimate / 8); <= 0 means an
// inverted or folded element. Cheap host check for meshes as read (the kernels check the order-p
// geometry at every node and quadrature point).
inline double min_corner_jacobian_ratio(const HexMesh& m, std::int64_t e) {
  auto X = [&](int i, int j, int k, int c) { return m.vertices[3 * m.hexes[8 * e + hex_vertex(i, j, k)] + c]; };
  double lo = 1e300, sum = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      for (int k = 0; k < 2; ++k) {
        double a[3], b[3], c[3];
        for (int d = 0; d < 3; ++d) {
          a[d] = X(1, j, k, d) - X(0, j, k, d);
          b[d] = X(i, 1, k, d) - X(i, 0, k, d);
          c[d] = X(i, j, 1, d) - X(i, j, 0, d);
        }
        const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                           a[2] * (b[0] * c[1] - b[1] * c[0]);
        lo = std::min(lo, det);
        sum += std::abs(det);
      }
  const double mean = sum / 8.0;
  return mean > 0 ? lo / mean : -1.0;
}

// A structured box [origin, origin + lengths] split into elements[0] x elements[1] x elements[2]
// hexahedra; faces named xmin, xmax, ymin, ymax, zmin, zmax. perturbation > 0 moves every vertex by
// up to perturbation x (element size) per direction (pseudo-random, reproducible from seed), keeping
// boundary vertices on their boundary planes: distorted, non-affine elements in the same box.
struct BoxSpec {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  std::array<double, 3> lengths{1.0, 1.0, 1.0};
  std::array<int, 3> elements{4, 4, 4};
  double perturbation = 0.0;
  std::uint32_t seed = 1;
};

inline double box_hash(std::uint32_t x) { return hash_symmetric(x); }  // in [-1, 1] (kernels/core/hash.hpp)

inline HexMesh make_box_mesh(const BoxSpec& s) {
  for (int d = 0; d < 3; ++d) {
    if (s.elements[d] < 1) throw std::invalid_argument("box mesh: element counts must be >= 1");
    if (!(s.lengths[d] > 0)) throw std::invalid_argument("box mesh: lengths must be > 0");
  }
  if (!(s.perturbation >= 0)) throw std::invalid_argument("box mesh: perturbation must be >= 0");
  const int nx = s.elements[0], ny = s.elements[1], nz = s.elements[2];
  const std::int64_t vx = nx + 1, vy = ny + 1, vz = nz + 1;
  HexMesh m;
  m.vertices.resize(static_cast<std::size_t>(3 * vx * vy * vz));
  const int n[3] = {nx, ny, nz};
  for (std::int64_t k = 0; k < vz; ++k)
    for (std::int64_t j = 0; j < vy; ++j)
      for (std::int64_t i = 0; i < vx; ++i) {
        const std::int64_t v = i + vx * (j + vy * k);
        const std::int64_t idx[3] = {i, j, k};
        for (int d = 0; d < 3; ++d) {
          const double h = s.lengths[d] / n[d];
          double x = s.origin[d] + h * static_cast<double>(idx[d]);
          const bool on_boundary = idx[d] == 0 || idx[d] == n[d];
          if (s.perturbation > 0 && !on_boundary)
            x += s.perturbation * h * box_hash(static_cast<std::uint32_t>(3 * v + d) * 2654435761u + s.seed);
          m.vertices[3 * v + d] = x;
        }
      }
  m.hexes.reserve(static_cast<std::size_t>(8) * nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        for (int c = 0; c < 8; ++c) {
          // Gmsh vertex c -> corner offsets
          static const int off[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                        {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
          m.hexes.push_back((i + off[c][0]) + vx * ((j + off[c][1]) + vy * (k + off[c][2])));
        }
  m.boundary_names = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const std::int64_t e = i + static_cast<std::int64_t>(nx) * (j + static_cast<std::int64_t>(ny) * k);
        if (i == 0) m.boundary_faces.push_back({e, 0, 0});
        if (i == nx - 1) m.boundary_faces.push_back({e, 1, 1});
        if (j == 0) m.boundary_faces.push_back({e, 2, 2});
        if (j == ny - 1) m.boundary_faces.push_back({e, 3, 3});
        if (k == 0) m.boundary_faces.push_back({e, 4, 4});
        if (k == nz - 1) m.boundary_faces.push_back({e, 5, 5});
      }
  return m;
}

// ---- from a neutral mesh (was models/helmholtz/mesh_import.hpp)

inline HexMesh hex_mesh_from(const Mesh& in) {
  auto fail = [&](const std::string& where, const std::string& what) {
    throw std::invalid_argument((where.empty() ? in.file : where) + ": " + what);
  };
  HexMesh m;
  m.source = in.file;
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

}  // namespace polymech::mesh
