// Order-p nodes of a linear hexahedral mesh (host): numbering, coordinates, face node lists, colouring, chunks.
// Shared by the Helmholtz model and the solid models' unstructured discretization; moved from
// models/helmholtz/dofs.hpp (and chunk_order from models/helmholtz/element_data.hpp).
//
// Numbering without orientation cases: a GLL node of an element is a point of the trilinear map with
// weights on the element's vertices; a node on a vertex, edge or face has non-zero weights on 1, 2 or
// 4 vertices only, all of which the neighbours sharing it also have, with the same weights (the GLL
// nodes are exactly symmetric, basis.hpp). So the sorted list of (global vertex, weight) identifies a
// shared node from every side; interior nodes (8 weights) are the element's own. DoFs are numbered in
// order of first appearance over the elements, which keeps an element's DoFs close in memory.
//
// Node coordinates: the trilinear map of the vertices (isoparametric geometry of order p that
// represents the mesh as read; perturb_nodes() moves them to make genuinely curved elements).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "fem/basis.hpp"
#include "common/hex_mesh.hpp"

namespace polymech::mesh {

struct HexDofs {
  int order = 1;
  int n1d = 2;                                  // N = order + 1
  std::int64_t count = 0;                       // DoFs
  std::vector<std::int32_t> element_dofs;       // elements x N^3, element order of the mesh
  std::vector<double> coordinates;              // count x 3
  int nodes_per_element() const { return n1d * n1d * n1d; }
};

// Element-local node indices (i + N (j + N k)) of local face f in face-lexicographic order: the first
// tangential reference direction (the lower of the two) fastest.
inline std::vector<int> face_local_nodes(int n1d, int f) {
  const int dir = f / 2, side = (f % 2) ? n1d - 1 : 0;
  const int t0 = dir == 0 ? 1 : 0, t1 = dir == 2 ? 1 : 2;
  std::vector<int> out;
  out.reserve(static_cast<std::size_t>(n1d) * n1d);
  for (int b = 0; b < n1d; ++b)
    for (int a = 0; a < n1d; ++a) {
      int ijk[3];
      ijk[dir] = side;
      ijk[t0] = a;
      ijk[t1] = b;
      out.push_back(ijk[0] + n1d * (ijk[1] + n1d * ijk[2]));
    }
  return out;
}

// Elements in an order that keeps neighbours close: sorted by the Morton (Z-order) code of their
// centroids on a 2^10 grid over the mesh's bounding box. Chunks of consecutive elements in this order
// are compact blobs, and DoFs numbered in it are close in memory.
inline std::vector<std::int64_t> locality_order(const HexMesh& m) {
  const std::int64_t ne = m.element_count();
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::int64_t v = 0; v < m.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], m.vertices[3 * v + k]);
      hi[k] = std::max(hi[k], m.vertices[3 * v + k]);
    }
  auto spread = [](std::uint64_t x) {  // 10 bits -> every third bit of 30
    x &= 0x3ff;
    x = (x | (x << 16)) & 0x030000ff;
    x = (x | (x << 8)) & 0x0300f00f;
    x = (x | (x << 4)) & 0x030c30c3;
    x = (x | (x << 2)) & 0x09249249;
    return x;
  };
  std::vector<std::pair<std::uint64_t, std::int64_t>> keys(static_cast<std::size_t>(ne));
  for (std::int64_t e = 0; e < ne; ++e) {
    std::uint64_t code = 0;
    for (int k = 0; k < 3; ++k) {
      double c = 0;
      for (int v = 0; v < 8; ++v) c += m.vertices[3 * m.hexes[8 * e + v] + k] / 8.0;
      const double t = hi[k] > lo[k] ? (c - lo[k]) / (hi[k] - lo[k]) : 0.0;
      code |= spread(static_cast<std::uint64_t>(std::min(1023.0, std::max(0.0, t * 1024.0)))) << k;
    }
    keys[e] = {code, e};
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::int64_t> order(keys.size());
  for (std::size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
  return order;
}

// `traversal`: the element order in which DoFs are numbered (empty: the mesh's order).
inline HexDofs number_dofs(const HexMesh& m, int order, const std::vector<std::int64_t>& traversal = {}) {
  if (order < fem::min_order || order > fem::max_order)
    throw std::invalid_argument("order " + std::to_string(order) + " is not supported; allowed: 1..4");
  HexDofs d;
  d.order = order;
  d.n1d = order + 1;
  const int N = d.n1d, N3 = N * N * N;
  const std::vector<double> gll = fem::gauss_lobatto_nodes(N);
  const std::int64_t ne = m.element_count();
  d.element_dofs.assign(static_cast<std::size_t>(ne * N3), -1);
  // 1D linear weights (1 - x)/2, (1 + x)/2 at each GLL node; exact 0 / 1 at the ends
  std::vector<std::array<double, 2>> lw(N);
  for (int i = 0; i < N; ++i) lw[i] = {0.5 * (1.0 - gll[i]), 0.5 * (1.0 + gll[i])};
  lw[0] = {1.0, 0.0};
  lw[N - 1] = {0.0, 1.0};

  using Key = std::array<std::int64_t, 8>;  // up to 4 (vertex, quantized weight) pairs
  struct KeyHash {
    std::size_t operator()(const Key& k) const {
      std::uint64_t h = 1469598103934665603ull;
      for (auto v : k) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
      return static_cast<std::size_t>(h);
    }
  };
  std::unordered_map<Key, std::int32_t, KeyHash> shared;
  shared.reserve(static_cast<std::size_t>(ne) * (N3 - (N - 2) * (N - 2) * (N - 2)) / 2 + 16);
  std::int64_t next = 0;
  auto new_dof = [&](const double* w, const std::int64_t* verts) {
    if (next >= std::int64_t(1) << 31) throw std::invalid_argument("mesh too large for 32-bit DoF indices");
    double x[3] = {0, 0, 0};
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 3; ++k) x[k] += w[c] * m.vertices[3 * verts[c] + k];
    for (int k = 0; k < 3; ++k) d.coordinates.push_back(x[k]);
    return static_cast<std::int32_t>(next++);
  };
  for (std::int64_t t = 0; t < ne; ++t) {
    const std::int64_t e = traversal.empty() ? t : traversal[t];
    const std::int64_t* verts = &m.hexes[8 * e];
    for (int k = 0; k < N; ++k)
      for (int j = 0; j < N; ++j)
        for (int i = 0; i < N; ++i) {
          double w[8];
          std::array<std::pair<std::int64_t, std::int64_t>, 8> nz;
          int count = 0;
          for (int c = 0; c < 8; ++c) {
            const int ci = (c == 1 || c == 2 || c == 5 || c == 6) ? 1 : 0;
            const int cj = (c == 2 || c == 3 || c == 6 || c == 7) ? 1 : 0;
            const int ck = c >= 4 ? 1 : 0;
            w[c] = lw[i][ci] * lw[j][cj] * lw[k][ck];
            if (w[c] != 0.0) nz[count++] = {verts[c], std::llround(std::ldexp(w[c], 40))};
          }
          const int a = i + N * (j + N * k);
          std::int32_t id;
          if (count == 8) {
            id = new_dof(w, verts);  // interior: this element's own
          } else {
            std::sort(nz.begin(), nz.begin() + count);
            Key key;
            key.fill(-1);
            for (int c = 0; c < count; ++c) {
              key[2 * c] = nz[c].first;
              key[2 * c + 1] = nz[c].second;
            }
            auto it = shared.find(key);
            if (it == shared.end()) {
              id = new_dof(w, verts);
              shared.emplace(key, id);
            } else {
              id = it->second;
            }
          }
          d.element_dofs[static_cast<std::size_t>(e * N3 + a)] = id;
        }
  }
  d.count = next;
  return d;
}

// Greedy colouring of items (elements or faces) given their vertices: items sharing a vertex get
// different colours, so they share no DoF. Returns one colour per item; colours are 0..max.
// Items with any number of vertices each: item i has item_vertices[item_offsets[i] .. item_offsets[i + 1]).
inline std::vector<int> color_by_shared_vertices(const std::vector<std::int64_t>& item_offsets,
                                                 const std::vector<std::int64_t>& item_vertices,
                                                 std::int64_t vertex_count) {
  const std::int64_t n = static_cast<std::int64_t>(item_offsets.size()) - 1;
  std::vector<std::int64_t> offsets(static_cast<std::size_t>(vertex_count + 1), 0), items;
  for (auto v : item_vertices) ++offsets[v + 1];
  for (std::int64_t v = 0; v < vertex_count; ++v) offsets[v + 1] += offsets[v];
  items.resize(item_vertices.size());
  std::vector<std::int64_t> fill(offsets.begin(), offsets.end() - 1);
  for (std::int64_t e = 0; e < n; ++e)
    for (std::int64_t c = item_offsets[e]; c < item_offsets[e + 1]; ++c) items[fill[item_vertices[c]]++] = e;
  std::vector<int> color(static_cast<std::size_t>(n), -1);
  std::vector<std::int64_t> seen;  // seen[c] == e + 1: colour c is used by a neighbour of e
  for (std::int64_t e = 0; e < n; ++e) {
    for (std::int64_t c = item_offsets[e]; c < item_offsets[e + 1]; ++c) {
      const std::int64_t v = item_vertices[c];
      for (std::int64_t k = offsets[v]; k < offsets[v + 1]; ++k) {
        const int col = color[items[k]];
        if (col < 0) continue;
        if (col >= static_cast<int>(seen.size())) seen.resize(col + 1, 0);
        seen[col] = e + 1;
      }
    }
    int col = 0;
    while (col < static_cast<int>(seen.size()) && seen[col] == e + 1) ++col;
    color[e] = col;
  }
  return color;
}

inline std::vector<int> color_by_shared_vertices(const std::vector<std::int64_t>& item_vertices, int per_item,
                                                 std::int64_t vertex_count) {
  std::vector<std::int64_t> offsets(item_vertices.size() / per_item + 1);
  for (std::size_t i = 0; i < offsets.size(); ++i) offsets[i] = static_cast<std::int64_t>(i) * per_item;
  return color_by_shared_vertices(offsets, item_vertices, vertex_count);
}

// Order of items sorted by colour (stable) and the colour offsets.
inline void sort_by_color(const std::vector<int>& color, std::vector<std::int64_t>& order,
                          std::vector<std::int32_t>& offsets) {
  const int colors = color.empty() ? 0 : *std::max_element(color.begin(), color.end()) + 1;
  offsets.assign(static_cast<std::size_t>(colors) + 1, 0);
  for (int c : color) ++offsets[c + 1];
  for (int c = 0; c < colors; ++c) offsets[c + 1] += offsets[c];
  order.resize(color.size());
  std::vector<std::int32_t> fill(offsets.begin(), offsets.end() - 1);
  for (std::size_t i = 0; i < color.size(); ++i) order[fill[color[i]]++] = static_cast<std::int64_t>(i);
}

// Moves every DoF node that is not on the mesh boundary by up to amplitude x h (pseudo-random, fixed
// seed): curved isoparametric elements of order p (for p = 1 the same as moving vertices).
inline void perturb_nodes(HexDofs& d, const std::vector<char>& on_boundary, double amplitude, double h,
                          std::uint32_t seed = 7) {
  for (std::int64_t i = 0; i < d.count; ++i) {
    if (on_boundary[i]) continue;
    for (int c = 0; c < 3; ++c)
      d.coordinates[3 * i + c] +=
          amplitude * h * box_hash(static_cast<std::uint32_t>(3 * i + c) * 2246822519u + seed);
  }
}

// DoFs on the faces in `faces` (true) and the rest (false).
inline std::vector<char> dofs_on_faces(const HexDofs& d, const std::vector<BoundaryFace>& faces) {
  std::vector<char> mark(static_cast<std::size_t>(d.count), 0);
  const int N3 = d.nodes_per_element();
  for (const auto& f : faces)
    for (int a : face_local_nodes(d.n1d, f.face)) mark[d.element_dofs[f.element * N3 + a]] = 1;
  return mark;
}

// Output mesh: each order-p element split into p^3 linear hexahedra through its GLL nodes (XDMF / VTK
// hexahedron vertex order), on the DoFs as points. Returns elements x p^3 x 8 DoF indices.
inline std::vector<std::int64_t> linear_subcells(const HexDofs& d) {
  const int N = d.n1d, p = d.order, N3 = d.nodes_per_element();
  const std::int64_t ne = static_cast<std::int64_t>(d.element_dofs.size()) / N3;
  static const int off[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<std::int64_t> cells;
  cells.reserve(static_cast<std::size_t>(ne) * p * p * p * 8);
  for (std::int64_t e = 0; e < ne; ++e)
    for (int k = 0; k < p; ++k)
      for (int j = 0; j < p; ++j)
        for (int i = 0; i < p; ++i)
          for (const auto& o : off)
            cells.push_back(d.element_dofs[e * N3 + (i + o[0]) + N * ((j + o[1]) + N * (k + o[2]))]);
  return cells;
}

// DoFs within `tolerance` of the segment [a, b], sorted along it: (parameter s in [0, 1], DoF).
inline std::vector<std::pair<double, std::int64_t>> dofs_on_segment(const HexDofs& d, const std::array<double, 3>& a,
                                                                    const std::array<double, 3>& b, double tolerance) {
  double ab[3], len2 = 0;
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    len2 += ab[k] * ab[k];
  }
  std::vector<std::pair<double, std::int64_t>> out;
  for (std::int64_t i = 0; i < d.count; ++i) {
    const double* x = &d.coordinates[3 * i];
    double s = 0;
    for (int k = 0; k < 3; ++k) s += (x[k] - a[k]) * ab[k];
    s = len2 > 0 ? s / len2 : 0.0;
    if (s < -1e-12 || s > 1 + 1e-12) continue;
    double dist2 = 0;
    for (int k = 0; k < 3; ++k) dist2 += (x[k] - a[k] - s * ab[k]) * (x[k] - a[k] - s * ab[k]);
    if (dist2 <= tolerance * tolerance) out.push_back({s, i});
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The part's elements in chunks of `per_chunk` neighbours (the locality order of layout.elements), the
// chunks coloured by shared vertices and sorted by colour: the storage order (mesh elements), the first
// storage index of each chunk (and the end), the first chunk of each colour (and the end).
struct ChunkOrder {
  std::vector<std::int64_t> elements;
  std::vector<std::int64_t> chunk_start;
  std::vector<std::int32_t> color_offsets;
};
inline ChunkOrder chunk_order(const HexMesh& mesh, const std::vector<std::int64_t>& elements, std::int64_t per_chunk) {
  const std::int64_t ne = static_cast<std::int64_t>(elements.size());
  const std::int64_t nchunks = (ne + per_chunk - 1) / per_chunk;
  std::vector<std::int64_t> chunk_vertex_offsets(1, 0), chunk_vertices;
  for (std::int64_t k = 0; k < nchunks; ++k) {
    const std::size_t first = chunk_vertices.size();
    for (std::int64_t t = k * per_chunk; t < std::min(ne, (k + 1) * per_chunk); ++t)
      for (int v = 0; v < 8; ++v) chunk_vertices.push_back(mesh.hexes[8 * elements[t] + v]);
    std::sort(chunk_vertices.begin() + static_cast<std::ptrdiff_t>(first), chunk_vertices.end());
    chunk_vertices.erase(std::unique(chunk_vertices.begin() + static_cast<std::ptrdiff_t>(first), chunk_vertices.end()),
                         chunk_vertices.end());
    chunk_vertex_offsets.push_back(static_cast<std::int64_t>(chunk_vertices.size()));
  }
  ChunkOrder out;
  std::vector<std::int64_t> chunks;
  sort_by_color(color_by_shared_vertices(chunk_vertex_offsets, chunk_vertices, mesh.vertex_count()), chunks,
                out.color_offsets);
  out.chunk_start.push_back(0);
  for (const std::int64_t k : chunks) {
    for (std::int64_t t = k * per_chunk; t < std::min(ne, (k + 1) * per_chunk); ++t) out.elements.push_back(elements[t]);
    out.chunk_start.push_back(static_cast<std::int64_t>(out.elements.size()));
  }
  return out;
}

}  // namespace polymech::mesh
