// Ordered reductions over particles: sums whose result does not depend on the thread count, and the
// check of the run driver's watchdog (the first particle that is not finite or has left its range).
//
// ordered_sum cuts the range into fixed chunks, sums each chunk in index order (in parallel over
// chunks), and adds the chunk sums in chunk order on the host. A Kokkos reducer would combine partial
// sums in an order that depends on the number of threads, so energies and reaction forces would
// differ by round-off between a 1-thread and a 2-thread run; these do not.
#pragma once

#include <string>

#include "particles/particle_set.hpp"

namespace polymech::particles {

inline constexpr std::int64_t sum_chunk = 2048;

// The chunk table of ordered_sum: a caller that sums every step keeps one and passes it in (no allocation
// per call once it is large enough).
using SumPartials = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>;

// Sums N doubles over i in [0, n): term(i, acc) adds item i's contributions to acc[0..N). `partial` is
// (re)allocated when it has fewer than ceil(n / sum_chunk) x N entries.
template <int N, class Term>
Kokkos::Array<double, N> ordered_sum(const char* label, std::int64_t n, const Term& term, SumPartials& partial) {
  const std::int64_t chunks = (n + sum_chunk - 1) / sum_chunk;
  if (static_cast<std::int64_t>(partial.extent(0)) < chunks || partial.extent(1) != static_cast<std::size_t>(N))
    partial = SumPartials(
        Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string("polymech::particles::ordered_sum_partials")), chunks, N);
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

// The same with a chunk table of its own (diagnostics: energies, reactions, power iterations).
template <int N, class Term>
Kokkos::Array<double, N> ordered_sum(const char* label, std::int64_t n, const Term& term) {
  SumPartials partial;
  return ordered_sum<N>(label, n, term, partial);
}

// sum_i v_i of a vector field (thread-count independent), e.g. a contact reaction.
template <class T, int D>
Kokkos::Array<double, D> vector_sum(const char* label, const VecView<T, D>& v) {
  return ordered_sum<D>(label, static_cast<std::int64_t>(v.extent(0)), KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
    for (int k = 0; k < D; ++k) acc[k] += double(v(i, k));
  });
}

// sum_i e_i of a scalar field (thread-count independent).
template <class T>
double scalar_sum(const char* label, const View1<T>& e) {
  return ordered_sum<1>(label, static_cast<std::int64_t>(e.extent(0)),
                        KOKKOS_LAMBDA(const std::int64_t i, double* acc) { acc[0] += double(e(i)); })[0];
}

// The lowest index whose displacement or velocity is NaN or infinite or, with max_u > 0, whose
// displacement is longer than max_u; -1 when there is none (kernel "polymech::particles::first_bad";
// a minimum is exact, so any thread count finds the same particle).
template <class T, int D>
Index first_bad_particle(const ParticleSet<T, D>& p, T max_u = T(0)) {
  const auto u = p.u, v = p.v;
  const T max_u2 = max_u * max_u;
  const bool bounded = max_u > T(0);
  const Index n = p.size();
  Index first = n;
  Kokkos::parallel_reduce(
      "polymech::particles::first_bad", range(n),
      KOKKOS_LAMBDA(const Index i, Index& m) {
        bool ok = true;
        T u2 = T(0);
        for (int k = 0; k < D; ++k) {
          ok = ok && kx::isfinite(u(i, k)) && kx::isfinite(v(i, k));
          u2 += u(i, k) * u(i, k);
        }
        if (bounded && !(u2 <= max_u2)) ok = false;
        if (!ok && i < m) m = i;
      },
      Kokkos::Min<Index>(first));
  return first < n ? first : Index(-1);
}

}  // namespace polymech::particles
