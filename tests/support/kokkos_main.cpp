// GoogleTest main that brackets the whole test binary with Kokkos::initialize / finalize.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>

#include "core/kokkos_shim.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  try {
    polymech::kx::initialize();  // subnormals flushed unless POLYMECH_SUBNORMALS=keep
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], e.what());
    return 2;
  }
  int rc = RUN_ALL_TESTS();
  Kokkos::finalize();
  return rc;
}
