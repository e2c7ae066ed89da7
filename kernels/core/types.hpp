// Execution/memory spaces and View aliases shared by every kernel.
#pragma once

#include "core/index.hpp"
#include "core/kokkos_shim.hpp"

#include <cstdint>

namespace polymech {

// Default floating type; kernels and models take the precision as a template parameter where it
// matters (double by default, float allowed) so precision is one axis of the accuracy-cost study.
using Real = double;

using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;
using HostSpace = Kokkos::HostSpace;
using HostExec = Kokkos::DefaultHostExecutionSpace;


template <class T>
using View1 = Kokkos::View<T*, MemSpace>;
template <class T>
using View2 = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>;

template <class T, int D>
using VecView = Kokkos::View<T* [D], Kokkos::LayoutRight, MemSpace>;

// A RangePolicy over [0, n) on the default execution space.
inline Kokkos::RangePolicy<ExecSpace> range(std::int64_t n) { return Kokkos::RangePolicy<ExecSpace>(0, n); }

}  // namespace polymech
