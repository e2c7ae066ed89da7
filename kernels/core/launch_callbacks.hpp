// Installs (or, with nullptr, removes) Kokkos Tools callbacks on every kernel launch: the begin callback
// on parallel_for / reduce / scan, and optionally the matching end callback. Shared by the tests' kernel
// census and the benchmarks' kernel timers; the Tools API lives in Kokkos::Tools::Experimental (3.4 to
// 5.x), so a change of its spelling is made here once.
#pragma once

#include <cstdint>

#include "core/kokkos_shim.hpp"

namespace polymech::kx {

using LaunchBegin = void (*)(const char* name, const std::uint32_t device, std::uint64_t* id);
using LaunchEnd = void (*)(const std::uint64_t id);

inline void set_launch_callbacks(LaunchBegin begin, LaunchEnd end = nullptr) {
  namespace kt = Kokkos::Tools::Experimental;
  kt::set_begin_parallel_for_callback(begin);
  kt::set_begin_parallel_reduce_callback(begin);
  kt::set_begin_parallel_scan_callback(begin);
  kt::set_end_parallel_for_callback(end);
  kt::set_end_parallel_reduce_callback(end);
  kt::set_end_parallel_scan_callback(end);
}

}  // namespace polymech::kx
