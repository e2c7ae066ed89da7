// The part of the mesh one rank works on (seed 002 paper 3 §4; layout in parallel.hpp): its elements,
// its local DoFs (owned first, then ghosts) and the halo lists, computed from the replicated mesh and
// global DoF numbering by every rank alike, so that no message is needed to agree on them.
//
// Ownership: a DoF belongs to the lowest part among the elements that contain it. A part keeps its
// own elements and every other element that contains one of its owned DoFs (the overlap layer), so
// the rows of its owned DoFs are complete. Send and receive lists are in increasing global index on
// both sides.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "core/types.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/partition.hpp"

namespace polymech::helmholtz {

struct PartLayout {
  int rank = 0, parts = 1;
  std::string method;                          // partitioner used ("" with one part)
  std::vector<int> element_part;               // per mesh element (empty with one part)
  std::vector<std::int64_t> elements;          // this part's elements (own + overlap), traversal order
  std::vector<std::int32_t> local_of_global;   // per global DoF: local index or -1
  std::vector<std::int32_t> global_of_local;   // per local DoF
  Index owned = 0;                             // local DoFs [0, owned) are owned
  std::vector<int> neighbours;                 // ranks this part exchanges with
  std::vector<std::vector<Index>> send, recv;  // per neighbour: owned local indices sent, ghost ones received
  // elements counted once over all parts (element_part == rank), for integrals such as eq. (28)
  bool counts(std::int64_t element) const { return parts == 1 || element_part[element] == rank; }
};

inline PartLayout make_part_layout(const HexMesh& mesh, const HexDofs& dofs, const std::vector<std::int64_t>& traversal,
                                   int rank, int parts, PartitionMethod method) {
  PartLayout L;
  L.rank = rank;
  L.parts = parts;
  const std::int64_t ne = mesh.element_count(), nd = dofs.count;
  const int N3 = dofs.nodes_per_element();
  if (parts == 1) {
    L.elements = traversal;
    L.local_of_global.resize(static_cast<std::size_t>(nd));
    L.global_of_local.resize(static_cast<std::size_t>(nd));
    for (std::int64_t d = 0; d < nd; ++d) L.local_of_global[d] = L.global_of_local[d] = static_cast<std::int32_t>(d);
    L.owned = static_cast<Index>(nd);
    return L;
  }
  L.element_part = partition_elements(mesh, parts, method, &L.method);
  const auto& part = L.element_part;
  std::vector<int> owner(static_cast<std::size_t>(nd), parts);
  for (std::int64_t e = 0; e < ne; ++e)
    for (int a = 0; a < N3; ++a) {
      const auto d = dofs.element_dofs[static_cast<std::size_t>(e * N3 + a)];
      owner[d] = std::min(owner[d], part[e]);
    }
  // ghosts of every part q (DoFs of q's elements that q does not own), as marks per part
  std::vector<std::vector<char>> ghost_of(static_cast<std::size_t>(parts), std::vector<char>(static_cast<std::size_t>(nd), 0));
  std::vector<char> mine(static_cast<std::size_t>(ne), 0);
  std::vector<int> with;
  for (std::int64_t e = 0; e < ne; ++e) {
    with.assign(1, part[e]);  // the parts that keep element e
    for (int a = 0; a < N3; ++a) with.push_back(owner[dofs.element_dofs[static_cast<std::size_t>(e * N3 + a)]]);
    std::sort(with.begin(), with.end());
    with.erase(std::unique(with.begin(), with.end()), with.end());
    for (int q : with) {
      if (q == rank) mine[e] = 1;
      for (int a = 0; a < N3; ++a) {
        const auto d = dofs.element_dofs[static_cast<std::size_t>(e * N3 + a)];
        if (owner[d] != q) ghost_of[q][d] = 1;
      }
    }
  }
  for (const std::int64_t e : traversal)
    if (mine[e]) L.elements.push_back(e);
  L.local_of_global.assign(static_cast<std::size_t>(nd), -1);
  for (std::int64_t d = 0; d < nd; ++d)
    if (owner[d] == rank) {
      L.local_of_global[d] = static_cast<std::int32_t>(L.global_of_local.size());
      L.global_of_local.push_back(static_cast<std::int32_t>(d));
    }
  L.owned = static_cast<Index>(L.global_of_local.size());
  for (std::int64_t d = 0; d < nd; ++d)
    if (ghost_of[rank][d]) {
      L.local_of_global[d] = static_cast<std::int32_t>(L.global_of_local.size());
      L.global_of_local.push_back(static_cast<std::int32_t>(d));
    }
  for (int q = 0; q < parts; ++q) {
    if (q == rank) continue;
    std::vector<Index> s, r;
    for (std::int64_t d = 0; d < nd; ++d) {
      if (owner[d] == rank && ghost_of[q][d]) s.push_back(L.local_of_global[d]);
      if (owner[d] == q && ghost_of[rank][d]) r.push_back(L.local_of_global[d]);
    }
    if (s.empty() && r.empty()) continue;
    L.neighbours.push_back(q);
    L.send.push_back(std::move(s));
    L.recv.push_back(std::move(r));
  }
  return L;
}

}  // namespace polymech::helmholtz
