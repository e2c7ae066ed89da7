// The host mirror type of a View, spelled the same from Kokkos 3.4 to 5.x (a difference kept in
// kernels/core/ with kokkos_shim.hpp): what Kokkos::create_mirror_view returns is View::HostMirror in
// 3.x-4.x and View::host_mirror_type later (HostMirror deprecated in 5.0), so it is named through the call.
// Kept out of kokkos_shim.hpp so that only the units that hold a host mirror as a member include it.
#pragma once

#include <utility>

#include "core/kokkos_shim.hpp"

namespace polymech::kx {

template <class V>
using HostMirror = decltype(Kokkos::create_mirror_view(std::declval<V>()));

}  // namespace polymech::kx
