// Splitting a hexahedral mesh into parts (seed 002 paper 3 §4, Fig. 8: domain decomposition):
//  - structured: recursive coordinate bisection of the element centroids (each cut across the longest
//    extent, at the element count that keeps the parts' sizes proportional to their numbers of parts):
//    slabs, columns and blocks of a box, for any number of parts;
//  - metis: METIS_PartMeshDual (graph of elements sharing a face), for unstructured (Gmsh) meshes;
//    available where the build found METIS (POLYMECH_WITH_METIS, the MPI preset).
// Host code; every rank computes the same partition from the same (replicated) mesh.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "helmholtz/mesh.hpp"

namespace polymech::helmholtz {

enum class PartitionMethod {
  automatic,   // structured for box meshes, metis for meshes read from a file (structured without METIS)
  structured,  // recursive coordinate bisection
  metis,       // graph partitioning by METIS
};

inline const char* to_string(PartitionMethod m) {
  switch (m) {
    case PartitionMethod::automatic: return "automatic";
    case PartitionMethod::structured: return "structured";
    case PartitionMethod::metis: return "metis";
  }
  return "?";
}

// Whether this build has METIS, and the METIS partition (defined in partition_metis.cpp when it has).
bool metis_available();
std::vector<int> metis_partition(const HexMesh& m, int parts);

namespace detail {

inline void bisect(const std::vector<std::array<double, 3>>& centre, std::vector<std::int64_t>::iterator begin,
                   std::vector<std::int64_t>::iterator end, int first_part, int parts, std::vector<int>& out) {
  if (parts == 1) {
    for (auto it = begin; it != end; ++it) out[*it] = first_part;
    return;
  }
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (auto it = begin; it != end; ++it)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], centre[*it][k]);
      hi[k] = std::max(hi[k], centre[*it][k]);
    }
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (hi[k] - lo[k] > hi[axis] - lo[axis]) axis = k;
  const int left = parts / 2;
  const auto count = end - begin;
  const auto cut = begin + static_cast<std::ptrdiff_t>(static_cast<double>(count) * left / parts + 0.5);
  // by coordinate, then by index: the same result on every rank
  std::nth_element(begin, cut, end, [&](std::int64_t a, std::int64_t b) {
    return centre[a][axis] != centre[b][axis] ? centre[a][axis] < centre[b][axis] : a < b;
  });
  bisect(centre, begin, cut, first_part, left, out);
  bisect(centre, cut, end, first_part + left, parts - left, out);
}

}  // namespace detail

// Part of every element by recursive coordinate bisection of the centroids.
inline std::vector<int> structured_partition(const HexMesh& m, int parts) {
  const std::int64_t ne = m.element_count();
  std::vector<std::array<double, 3>> centre(static_cast<std::size_t>(ne));
  for (std::int64_t e = 0; e < ne; ++e)
    for (int k = 0; k < 3; ++k) {
      double c = 0;
      for (int v = 0; v < 8; ++v) c += m.vertices[3 * m.hexes[8 * e + v] + k];
      centre[e][k] = c / 8.0;
    }
  std::vector<std::int64_t> ids(static_cast<std::size_t>(ne));
  std::iota(ids.begin(), ids.end(), 0);
  std::vector<int> out(static_cast<std::size_t>(ne), 0);
  detail::bisect(centre, ids.begin(), ids.end(), 0, parts, out);
  return out;
}

// The part of every element; `used` receives the method that was applied.
inline std::vector<int> partition_elements(const HexMesh& m, int parts, PartitionMethod method, std::string* used) {
  if (parts < 1) throw std::invalid_argument("partition: " + std::to_string(parts) + " parts; allowed: >= 1");
  if (parts > m.element_count())
    throw std::invalid_argument("partition: " + std::to_string(parts) + " parts for " + std::to_string(m.element_count()) +
                                " elements; allowed: at most one part per element");
  if (method == PartitionMethod::automatic)
    method = !m.element_origin.empty() && metis_available() ? PartitionMethod::metis : PartitionMethod::structured;
  if (method == PartitionMethod::metis && !metis_available())
    throw std::invalid_argument("partition: method 'metis' is not available in this build (METIS was not found); "
                                "allowed here: structured, automatic");
  if (used) *used = to_string(method);
  if (parts == 1) return std::vector<int>(static_cast<std::size_t>(m.element_count()), 0);
  return method == PartitionMethod::metis ? metis_partition(m, parts) : structured_partition(m, parts);
}

}  // namespace polymech::helmholtz
