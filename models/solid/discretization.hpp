// Order-p Lagrange nodes on a structured solid mesh (host): the node lattice (p n_d + 1 nodes per direction,
// GLL positions inside each cell, so a node shared by cells is one lattice point and needs no orientation
// matching), node coordinates from each cell's multilinear map, the element node tables in storage order
// (chunks of neighbouring cells, coloured by the parity of the chunk's block index: chunks of one colour
// never share a node, so fem::parallel_for_batches scatters without atomics), and the nodes and faces of
// the named sides.
//
// A masked lattice (StructuredMesh::active) makes elements of its active cells only; the lattice points that
// no active cell touches are dropped and the others numbered compactly in lattice order (`node_ids`,
// `lattice_points`), chunks without an active cell are left out, and the sides list the existing nodes and
// the faces of active cells on them. Without a mask every table is what it was (node = lattice point).
//
// A periodic direction (StructuredMesh::periodic) has p n_d lattice points (the last plane is the first one):
// node() wraps the index, its two sides do not exist, and the chunk colouring gives the last block of an odd
// number of blocks a third colour digit (it touches the first block through the seam). A mapped lattice
// (StructuredMesh::map) places each node at the map of its multilinear position.
//
// Unstructured hexahedral meshes (3D; mesh::HexMesh, e.g. a Gmsh file through mesh::hex_mesh_from): the same
// tables from the machinery the Helmholtz model uses (models/common/hex_dofs.hpp): order-p nodes numbered by
// the sorted (vertex, weight) lists of their multilinear positions, so that the nodes on a shared edge or face
// match whatever the elements' vertex orders; elements in the locality (Morton) order cut into chunks of
// neighbours, the chunks coloured greedily by shared vertices (one colour's chunks share no node); the named
// boundaries are the mesh's physical surface groups, each a list of faces in the face-lexicographic order of
// its element's local face. `unstructured` is set and the lattice fields (cells, lattice, periodic, node_ids,
// lattice_points, active) are empty; element_cells holds the mesh element of each stored element.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/hex_dofs.hpp"
#include "common/hex_mesh.hpp"
#include "fem/basis.hpp"
#include "solid/mesh.hpp"

namespace polymech::solid {

template <int D>
struct Discretization {
  int order = 1, n1d = 2;
  std::array<int, D> cells{}, lattice{};  // cells and nodes per direction
  std::array<bool, D> periodic{};         // closed directions (lattice[d] = order cells[d])
  std::int64_t nodes = 0;
  std::vector<double> coordinates;            // nodes x D
  std::vector<std::int64_t> element_cells;    // storage index -> cell (lattice order)
  std::vector<std::int64_t> element_nodes;    // storage order, elements x N^D (a = i + N (j + N k))
  std::vector<std::int64_t> chunk_start;      // first element of each chunk, and the end
  std::vector<std::int64_t> color_offsets;    // first chunk of each colour, and the end
  // masked lattices only (empty: every lattice point is a node, node = lattice point, every cell active)
  std::vector<char> active;                   // the mesh's cell mask
  std::vector<std::int64_t> node_ids;         // lattice point -> node, -1 where no active cell touches it
  std::vector<std::int64_t> lattice_points;   // node -> lattice point
  // unstructured meshes only (discretize(const mesh::HexMesh&, ...)): element_cells holds mesh elements
  bool unstructured = false;
  std::vector<std::string> boundary_names;                // the mesh's named boundaries
  std::vector<std::vector<std::int64_t>> boundary_faces;  // per name: faces x N^(D-1) nodes (as side_faces)
  std::string mesh_source;                                // the file the mesh was read from, for messages

  int nodes_per_element() const { return D == 3 ? n1d * n1d * n1d : n1d * n1d; }
  // The lattice point of index I (a periodic direction's index taken modulo its lattice).
  std::int64_t lattice_point(const std::array<int, D>& I) const {
    std::int64_t v = 0;
    for (int d = D - 1; d >= 0; --d) v = v * lattice[d] + (periodic[d] && I[d] >= lattice[d] ? I[d] - lattice[d] : I[d]);
    return v;
  }
  // The node at lattice point I (-1 on a masked lattice where the point has no node).
  std::int64_t node(const std::array<int, D>& I) const {
    const std::int64_t v = lattice_point(I);
    return node_ids.empty() ? v : node_ids[static_cast<std::size_t>(v)];
  }
  bool cell_active(std::int64_t cell) const { return active.empty() || active[static_cast<std::size_t>(cell)] != 0; }
  // The lattice index of node v.
  std::array<int, D> lattice_index(std::int64_t v) const {
    if (!lattice_points.empty()) v = lattice_points[static_cast<std::size_t>(v)];
    std::array<int, D> I;
    for (int d = 0; d < D; ++d) {
      I[d] = static_cast<int>(v % lattice[d]);
      v /= lattice[d];
    }
    return I;
  }
};

// Chunk edge (cells per direction of a chunk's block): about 8000 element nodes per chunk on the host (the
// scalar operator's choice, models/helmholtz/element_data.hpp), but at least 32 chunks per thread when the
// mesh allows; one cell per chunk on a device.
template <int D>
int default_chunk_edge(const StructuredMesh<D>& m, int order, int threads, bool device) {
  if (device) return 1;
  const double n = order + 1, per_element = D == 3 ? n * n * n : n * n;
  int b = std::max(1, static_cast<int>(std::pow(8000.0 / per_element, 1.0 / D)));
  auto chunks = [&](int e) {
    std::int64_t c = 1;
    for (int d = 0; d < D; ++d) c *= (m.cells[d] + e - 1) / e;
    return c;
  };
  while (b > 1 && chunks(b) < 32 * threads) --b;
  return b;
}

template <int D>
Discretization<D> discretize(const StructuredMesh<D>& m, int order, int chunk_edge) {
  if (order < fem::min_order || order > fem::max_order)
    throw std::invalid_argument("solid: order " + std::to_string(order) + " is not supported; allowed: 1..4");
  Discretization<D> s;
  s.order = order;
  s.n1d = order + 1;
  s.cells = m.cells;
  s.periodic = m.periodic;
  std::int64_t points = 1;
  for (int d = 0; d < D; ++d) {
    if (m.periodic[d] && m.cells[d] < 3)
      throw std::invalid_argument("solid: a periodic lattice direction needs at least 3 cells (it has " +
                                  std::to_string(m.cells[d]) + ")");
    s.lattice[d] = order * m.cells[d] + (m.periodic[d] ? 0 : 1);
    points *= s.lattice[d];
  }
  s.nodes = points;
  if (m.masked()) {
    if (static_cast<std::int64_t>(m.active.size()) != m.cell_count())
      throw std::invalid_argument("solid: the active-cell mask has " + std::to_string(m.active.size()) +
                                  " entries for " + std::to_string(m.cell_count()) + " cells");
    s.active = m.active;
    // keep the lattice points of active cells, numbered in lattice order
    std::vector<char> used(static_cast<std::size_t>(points), 0);
    for (std::int64_t c = 0; c < m.cell_count(); ++c) {
      if (!m.is_active(c)) continue;
      std::array<int, D> ci;
      std::int64_t r = c;
      for (int d = 0; d < D; ++d) {
        ci[d] = static_cast<int>(r % m.cells[d]);
        r /= m.cells[d];
      }
      const int ND = D == 3 ? s.n1d * s.n1d * s.n1d : s.n1d * s.n1d;
      for (int a = 0; a < ND; ++a) {
        std::array<int, D> I;
        int r2 = a;
        for (int d = 0; d < D; ++d) {
          I[d] = order * ci[d] + r2 % s.n1d;
          r2 /= s.n1d;
        }
        used[static_cast<std::size_t>(s.lattice_point(I))] = 1;
      }
    }
    s.node_ids.assign(static_cast<std::size_t>(points), -1);
    for (std::int64_t v = 0; v < points; ++v)
      if (used[static_cast<std::size_t>(v)]) {
        s.node_ids[static_cast<std::size_t>(v)] = static_cast<std::int64_t>(s.lattice_points.size());
        s.lattice_points.push_back(v);
      }
    s.nodes = static_cast<std::int64_t>(s.lattice_points.size());
    if (s.nodes == 0) throw std::invalid_argument("solid: the active-cell mask leaves no cell");
  }
  // node coordinates: the multilinear map of the cell that holds the node (the lowest one), at GLL positions
  const std::vector<double> gll = fem::gauss_lobatto_nodes(s.n1d);
  s.coordinates.assign(static_cast<std::size_t>(s.nodes) * D, 0.0);
  for (std::int64_t v = 0; v < s.nodes; ++v) {
    const auto I = s.lattice_index(v);
    std::array<int, D> cell;
    std::array<double, D> t;  // position in [0, 1] inside the cell, exact at the ends
    double xi[D] = {};        // the multilinear position
    for (int d = 0; d < D; ++d) {
      cell[d] = std::min(I[d] / order, m.cells[d] - 1);
      const int a = I[d] - order * cell[d];
      t[d] = a == 0 ? 0.0 : a == order ? 1.0 : 0.5 * (1.0 + gll[a]);
    }
    for (int corner = 0; corner < (1 << D); ++corner) {
      std::array<int, D> vi;
      double w = 1.0;
      for (int d = 0; d < D; ++d) {
        const int hi = (corner >> d) & 1;
        vi[d] = cell[d] + hi;
        w *= hi ? t[d] : 1.0 - t[d];
      }
      if (w == 0.0) continue;
      const std::int64_t vert = m.vertex(vi);
      for (int d = 0; d < D; ++d) xi[d] += w * m.vertices[static_cast<std::size_t>(D * vert + d)];
    }
    double* x = s.coordinates.data() + static_cast<std::size_t>(D * v);
    if (m.map)
      m.map(xi, x);
    else
      for (int d = 0; d < D; ++d) x[d] = xi[d];
  }
  // chunks: blocks of chunk_edge^D cells, coloured by the parity of the block index (a digit 0/1 per
  // direction; 2 for the last block of a periodic direction with an odd number of blocks > 1)
  const int b = std::max(1, chunk_edge);
  std::array<int, D> blocks;
  for (int d = 0; d < D; ++d) blocks[d] = (m.cells[d] + b - 1) / b;
  std::int64_t nblocks = 1;
  for (int d = 0; d < D; ++d) nblocks *= blocks[d];
  const int N = s.n1d, ND = s.nodes_per_element();
  int colors = 1;
  for (int d = 0; d < D; ++d) colors *= 3;
  for (int color = 0; color < colors; ++color) {
    // a colour without chunks adds no (empty) range
    if (s.color_offsets.empty() || s.color_offsets.back() != static_cast<std::int64_t>(s.chunk_start.size()))
      s.color_offsets.push_back(static_cast<std::int64_t>(s.chunk_start.size()));
    for (std::int64_t k = 0; k < nblocks; ++k) {
      std::array<int, D> B;
      std::int64_t r = k;
      int c = 0, radix = 1;
      for (int d = 0; d < D; ++d) {
        B[d] = static_cast<int>(r % blocks[d]);
        r /= blocks[d];
        const bool seam = m.periodic[d] && blocks[d] > 1 && blocks[d] % 2 == 1 && B[d] == blocks[d] - 1;
        c += (seam ? 2 : B[d] % 2) * radix;
        radix *= 3;
      }
      if (c != color) continue;
      const std::size_t first = s.element_cells.size();
      std::array<int, D> lo, hi;
      for (int d = 0; d < D; ++d) {
        lo[d] = B[d] * b;
        hi[d] = std::min(m.cells[d], lo[d] + b);
      }
      std::array<int, 3> i{0, 0, 0};
      for (i[2] = D == 3 ? lo[D - 1] : 0; i[2] < (D == 3 ? hi[D - 1] : 1); ++i[2])
        for (i[1] = lo[1]; i[1] < hi[1]; ++i[1])
          for (i[0] = lo[0]; i[0] < hi[0]; ++i[0]) {
            std::array<int, D> ci;
            for (int d = 0; d < D; ++d) ci[d] = i[d];
            std::int64_t cellid = 0;
            for (int d = D - 1; d >= 0; --d) cellid = cellid * m.cells[d] + ci[d];
            if (!m.is_active(cellid)) continue;
            s.element_cells.push_back(cellid);
            for (int a = 0; a < ND; ++a) {
              std::array<int, D> I;
              int r2 = a;
              for (int d = 0; d < D; ++d) {
                I[d] = order * ci[d] + r2 % N;
                r2 /= N;
              }
              s.element_nodes.push_back(s.node(I));
            }
          }
      if (s.element_cells.size() > first) s.chunk_start.push_back(static_cast<std::int64_t>(first));  // else: no active cell
    }
  }
  s.chunk_start.push_back(static_cast<std::int64_t>(s.element_cells.size()));
  const std::int64_t chunks = static_cast<std::int64_t>(s.chunk_start.size()) - 1;
  if (s.color_offsets.back() != chunks || s.color_offsets.size() == 1) s.color_offsets.push_back(chunks);
  return s;
}

// Elements per chunk of an unstructured mesh: about 8000 element nodes on the host (as default_chunk_edge),
// at least 32 chunks per thread when the mesh allows; one element per chunk on a device.
inline std::int64_t default_chunk_elements(std::int64_t elements, int order, int threads, bool device) {
  if (device) return 1;
  const std::int64_t n = order + 1;
  return std::max<std::int64_t>(1, std::min<std::int64_t>(8000 / (n * n * n), elements / (32 * std::max(1, threads))));
}

// The order-p discretization of an unstructured hexahedral mesh (see the header): chunks of `chunk_elements`
// neighbouring elements.
inline Discretization<3> discretize(const mesh::HexMesh& m, int order, std::int64_t chunk_elements) {
  if (order < fem::min_order || order > fem::max_order)
    throw std::invalid_argument("solid: order " + std::to_string(order) + " is not supported; allowed: 1..4");
  const std::string from = m.source.empty() ? std::string("a generated mesh") : m.source;
  if (m.element_count() == 0) throw std::invalid_argument("solid: the hexahedral mesh (" + from + ") has no elements");
  Discretization<3> s;
  s.order = order;
  s.n1d = order + 1;
  s.unstructured = true;
  s.mesh_source = m.source;
  const std::vector<std::int64_t> traversal = mesh::locality_order(m);
  const mesh::HexDofs dofs = mesh::number_dofs(m, order, traversal);
  s.nodes = dofs.count;
  s.coordinates = dofs.coordinates;
  const mesh::ChunkOrder chunks = mesh::chunk_order(m, traversal, std::max<std::int64_t>(1, chunk_elements));
  const int ND = s.nodes_per_element();
  s.element_cells = chunks.elements;
  s.element_nodes.reserve(chunks.elements.size() * static_cast<std::size_t>(ND));
  for (const std::int64_t e : chunks.elements)
    for (int a = 0; a < ND; ++a) s.element_nodes.push_back(dofs.element_dofs[static_cast<std::size_t>(e * ND + a)]);
  s.chunk_start = chunks.chunk_start;
  s.color_offsets.assign(chunks.color_offsets.begin(), chunks.color_offsets.end());
  s.boundary_names = m.boundary_names;
  s.boundary_faces.resize(m.boundary_names.size());
  for (const auto& f : m.boundary_faces) {
    auto& out = s.boundary_faces[static_cast<std::size_t>(f.boundary)];
    for (const int a : mesh::face_local_nodes(s.n1d, f.face))
      out.push_back(dofs.element_dofs[static_cast<std::size_t>(f.element * ND + a)]);
  }
  return s;
}

namespace detail {
// The faces of the named boundary of an unstructured discretization; an unknown name is an error that names
// it, the mesh's file and the boundaries it has.
template <int D>
const std::vector<std::int64_t>& named_boundary(const Discretization<D>& s, const std::string& name) {
  for (std::size_t b = 0; b < s.boundary_names.size(); ++b)
    if (s.boundary_names[b] == name) return s.boundary_faces[b];
  std::string have;
  for (const auto& n : s.boundary_names) have += (have.empty() ? "'" : ", '") + n + "'";
  const std::string of = s.mesh_source.empty() ? std::string("the mesh") : "the mesh " + s.mesh_source;
  if (have.empty()) have = "none (the mesh names no boundary)";
  throw std::invalid_argument("solid: boundary '" + name + "' is not a named boundary (physical surface group) of " +
                              of + "; allowed: " + have);
}
}  // namespace detail

// Nodes of a named side (every node with lattice index 0 or the last along the side's direction; on a
// masked lattice the existing ones; on an unstructured mesh the nodes of the named boundary's faces, ascending).
template <int D>
std::vector<std::int64_t> side_nodes(const Discretization<D>& s, const std::string& side) {
  if (s.unstructured) {
    std::vector<std::int64_t> out = detail::named_boundary(s, side);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }
  const auto ds = side_of<D>(side);
  if (ds[0] < 0) throw std::invalid_argument("solid: unknown boundary '" + side + "'");
  if (s.periodic[ds[0]]) throw std::invalid_argument("solid: boundary '" + side + "' does not exist (its direction is periodic)");
  std::vector<std::int64_t> out;
  for (std::int64_t v = 0; v < s.nodes; ++v) {
    const auto I = s.lattice_index(v);
    if (I[ds[0]] == (ds[1] ? s.lattice[ds[0]] - 1 : 0)) out.push_back(v);
  }
  return out;
}

// Faces of a named side: faces x N^(D-1) nodes, the other directions in increasing order, lower fastest
// (the face-lexicographic order of fem::HexFaces); on a masked lattice the faces of active cells only; on an
// unstructured mesh the faces of the named boundary, each in the face-lexicographic order of its element's
// local face (mesh::face_local_nodes).
template <int D>
std::vector<std::int64_t> side_faces(const Discretization<D>& s, const std::string& side) {
  if (s.unstructured) return detail::named_boundary(s, side);
  const auto ds = side_of<D>(side);
  if (ds[0] < 0) throw std::invalid_argument("solid: unknown boundary '" + side + "'");
  if (s.periodic[ds[0]]) throw std::invalid_argument("solid: boundary '" + side + "' does not exist (its direction is periodic)");
  const int dir = ds[0], p = s.order, N = s.n1d;
  const int t0 = dir == 0 ? 1 : 0, t1 = D == 3 ? (dir == 2 ? 1 : 2) : -1;
  std::vector<std::int64_t> out;
  const int fixed = ds[1] ? s.lattice[dir] - 1 : 0;
  const int n0 = s.cells[t0], n1 = D == 3 ? s.cells[t1] : 1;
  for (int c1 = 0; c1 < n1; ++c1)
    for (int c0 = 0; c0 < n0; ++c0) {
      if (!s.active.empty()) {  // the cell behind the face
        std::array<int, D> ci;
        ci[dir] = ds[1] ? s.cells[dir] - 1 : 0;
        ci[t0] = c0;
        if constexpr (D == 3) ci[t1] = c1;
        std::int64_t cell = 0;
        for (int d = D - 1; d >= 0; --d) cell = cell * s.cells[d] + ci[d];
        if (!s.cell_active(cell)) continue;
      }
      for (int b = 0; b < (D == 3 ? N : 1); ++b)
        for (int a = 0; a < N; ++a) {
          std::array<int, D> I;
          I[dir] = fixed;
          I[t0] = p * c0 + a;
          if constexpr (D == 3) I[t1] = p * c1 + b;
          out.push_back(s.node(I));
        }
    }
  return out;
}

}  // namespace polymech::solid
