// METIS partition of a hexahedral mesh (models/helmholtz/partition.hpp): the dual graph of elements
// sharing a face (METIS_PartMeshDual with ncommon = 4), k-way, default options (deterministic: every
// rank gets the same parts). Compiled where the build found METIS; partition_metis_stub.cpp otherwise.
#include <metis.h>

#include "helmholtz/partition.hpp"

namespace polymech::helmholtz {

bool metis_available() { return true; }

std::vector<int> metis_partition(const HexMesh& m, int parts) {
  idx_t ne = static_cast<idx_t>(m.element_count()), nn = static_cast<idx_t>(m.vertex_count());
  std::vector<idx_t> eptr(static_cast<std::size_t>(ne) + 1), eind(m.hexes.size());
  for (idx_t e = 0; e <= ne; ++e) eptr[e] = 8 * e;
  for (std::size_t k = 0; k < m.hexes.size(); ++k) eind[k] = static_cast<idx_t>(m.hexes[k]);
  idx_t ncommon = 4, nparts = parts, objval = 0;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = 1;
  std::vector<idx_t> epart(static_cast<std::size_t>(ne)), npart(static_cast<std::size_t>(nn));
  const int status = METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                                        nullptr, options, &objval, epart.data(), npart.data());
  if (status != METIS_OK)
    throw std::runtime_error("partition: METIS_PartMeshDual failed (status " + std::to_string(status) + ") for " +
                             std::to_string(parts) + " parts");
  return std::vector<int>(epart.begin(), epart.end());
}

}  // namespace polymech::helmholtz
