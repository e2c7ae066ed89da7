// Neighbour list with a skin distance: lists pairs within radius + skin and rebuilds only when some
// particle has moved more than skin / 2 since the last build (then no pair can have crossed from
// outside radius + skin to inside radius). Kernels using it must test the true distance.
#pragma once

#include "neighbors/neighbor_search.hpp"

namespace polymech::neighbors {

// Largest |x_i - x_ref_i| over all particles.
template <class T, int D>
T max_displacement(const VecView<T, D>& x, const VecView<T, D>& x_ref) {
  T m2 = T(0);
  Kokkos::parallel_reduce(
      "polymech::neighbors::max_displacement", range(static_cast<std::int64_t>(x.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t i, T& m) {
        T d2 = T(0);
        for (int k = 0; k < D; ++k) {
          const T d = x(i, k) - x_ref(i, k);
          d2 += d * d;
        }
        m = d2 > m ? d2 : m;
      },
      Kokkos::Max<T>(m2));
  return kx::sqrt(m2);
}

template <class T, int D>
class VerletList {
 public:
  VerletList(T radius, T skin, ListKind kind) : radius_(radius), skin_(skin), kind_(kind) {}

  // Rebuilds the list when needed; returns true when it did. The first call always builds.
  bool update(const VecView<T, D>& x) {
    const bool first = x_at_build_.extent(0) != x.extent(0);
    if (!first && max_displacement<T, D>(x, x_at_build_) <= skin_ / T(2)) return false;
    if (first) x_at_build_ = VecView<T, D>("polymech::neighbors::x_at_build", x.extent(0));
    Kokkos::deep_copy(x_at_build_, x);
    search_.build(x, radius_ + skin_, kind_, list_);
    ++builds_;
    return true;
  }

  // For a checkpoint: the positions of the last build and the build count; restore() rebuilds the
  // list from those positions, so a restarted run holds the list (and its pair order) it had.
  const VecView<T, D>& positions_at_build() const { return x_at_build_; }
  void restore(const VecView<T, D>& x_at_build, int builds) {
    if (x_at_build_.extent(0) != x_at_build.extent(0))
      x_at_build_ = VecView<T, D>("polymech::neighbors::x_at_build", x_at_build.extent(0));
    Kokkos::deep_copy(x_at_build_, x_at_build);
    search_.build(x_at_build_, radius_ + skin_, kind_, list_);
    builds_ = builds;
  }

  const NeighborList& list() const { return list_; }
  T radius() const { return radius_; }
  T skin() const { return skin_; }
  int builds() const { return builds_; }

 private:
  T radius_, skin_;
  ListKind kind_;
  NeighborSearch<T, D> search_;
  NeighborList list_;
  VecView<T, D> x_at_build_;
  int builds_ = 0;
};

}  // namespace polymech::neighbors
