// GoogleTest main that brackets the whole test binary with Kokkos::initialize / finalize.
#include <gtest/gtest.h>

#include "core/kokkos_shim.hpp"

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  polymech::kx::initialize();
  int rc = RUN_ALL_TESTS();
  Kokkos::finalize();
  return rc;
}
