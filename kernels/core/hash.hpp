// Reproducible pseudo-random numbers from an index, the same on the host and on a device: a 32-bit integer
// mixer (xor-shift / multiply rounds with well-avalanching odd constants) and its value mapped to [-1, 1].
// Used for mesh perturbations (models/common/hex_mesh.hpp, hex_dofs.hpp, models/solid/mesh.hpp), random
// start vectors (kernels/particles/power_iteration.hpp) and shuffled test meshes.
#pragma once

#include <cstdint>

// No Kokkos here: the scene readers (io/, which starts no Kokkos) number and perturb meshes with it too. Device
// code gets the functions from nvcc, which compiles every translation unit with __CUDACC__ defined.
#if defined(__CUDACC__) || defined(__HIPCC__)
#define POLYMECH_HASH_FUNCTION __host__ __device__ inline
#else
#define POLYMECH_HASH_FUNCTION inline
#endif

namespace polymech {

POLYMECH_HASH_FUNCTION std::uint32_t mix32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

// mix32(x) mapped to [-1, 1].
POLYMECH_HASH_FUNCTION double hash_symmetric(std::uint32_t x) {
  return 2.0 * (static_cast<double>(mix32(x)) / 4294967295.0) - 1.0;
}

}  // namespace polymech
