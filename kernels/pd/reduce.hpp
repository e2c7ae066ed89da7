// Sums over particles whose result does not depend on the thread count: the range is cut into
// fixed chunks, each chunk is summed in index order (in parallel over chunks), and the chunk sums
// are added in chunk order on the host. A Kokkos reducer would combine partial sums in an order
// that depends on the number of threads, so energies and reaction forces would differ by round-off
// between a 1-thread and a 2-thread run; these do not.
#pragma once

#include <string>

#include "core/types.hpp"

namespace polymech::pd {

inline constexpr std::int64_t sum_chunk = 2048;

// Sums N doubles over i in [0, n): term(i, acc) adds particle i's contributions to acc[0..N).
// Diagnostics only (energies, reactions): it allocates its chunk table.
template <int N, class Term>
Kokkos::Array<double, N> ordered_sum(const char* label, std::int64_t n, const Term& term) {
  const std::int64_t chunks = (n + sum_chunk - 1) / sum_chunk;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> partial(
      Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::pd::ordered_sum_partials")), chunks, N);
  Kokkos::parallel_for(
      label, Kokkos::RangePolicy<ExecSpace>(0, chunks), KOKKOS_LAMBDA(const std::int64_t c) {
        double acc[N];
        for (int k = 0; k < N; ++k) acc[k] = 0.0;
        const std::int64_t end = (c + 1) * sum_chunk < n ? (c + 1) * sum_chunk : n;
        for (std::int64_t i = c * sum_chunk; i < end; ++i) term(i, acc);
        for (int k = 0; k < N; ++k) partial(c, k) = acc[k];
      });
  auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), partial);
  Kokkos::Array<double, N> out;
  for (int k = 0; k < N; ++k) out[k] = 0.0;
  for (std::int64_t c = 0; c < chunks; ++c)
    for (int k = 0; k < N; ++k) out[k] += h(c, k);
  return out;
}

}  // namespace polymech::pd
