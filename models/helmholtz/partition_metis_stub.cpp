// Builds without METIS (models/helmholtz/partition.hpp): the structured partition only.
#include "helmholtz/partition.hpp"

namespace polymech::helmholtz {

bool metis_available() { return false; }

std::vector<int> metis_partition(const HexMesh&, int) {
  throw std::invalid_argument("partition: this build has no METIS (install libmetis-dev and reconfigure)");
}

}  // namespace polymech::helmholtz
