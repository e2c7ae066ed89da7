// Index types, free of Kokkos so that host-only code (io/, set-up) can name particles and bonds.
#pragma once

#include <cstdint>

namespace polymech {

// Particle and bond indices: 32 bits is enough for the sizes this project runs (2e6 particles,
// ~3e7 bonds) and halves the index traffic of neighbour lists compared with 64 bits.
using Index = std::int32_t;
// CSR offsets can exceed 2^31 for 3D lists of 1e7+ particles; keep them 64-bit.
using Offset = std::int64_t;

}  // namespace polymech
