// Contact pairs that keep their history across neighbour-list rebuilds: the tangential spring of a
// Hertz-Mindlin contact and its stick/slip state must survive when the broad phase rebuilds its list
// (seed 002 paper 2, eqs. (14)-(17)), or friction forgets every contact at each rebuild.
//
// The pairs are the entries of a NeighborList (one set: particle pairs; two sets: spheres against
// facets), the history is per entry (N reals and one int state, aligned with list.neighbors). After a
// rebuild, carry_history() gives every pair (i, j) of the new list the history it had in the old list
// (found in i's old row), and zero to pairs that are new; pairs that left the list are forgotten.
//
// ContactPairs does the whole cycle: a list within radius + skin rebuilt only when a point has moved
// more than skin / 2 (kernels/neighbors/verlet_list.hpp's rule), with the history carried over.
#pragma once

#include <string>

#include "neighbors/neighbor_search.hpp"
#include "neighbors/verlet_list.hpp"

namespace polymech::contact {

template <class T, int N>
struct PairHistory {
  Kokkos::View<T* [N], Kokkos::LayoutRight, MemSpace> values;  // e.g. the tangential spring (N = 3)
  Kokkos::View<int*, MemSpace> state;                          // e.g. stick / slip, 0 when new

  void resize(std::size_t pairs, const std::string& label) {
    if (values.extent(0) >= pairs) return;
    const std::size_t n = pairs + pairs / 8 + 16;
    values = Kokkos::View<T* [N], Kokkos::LayoutRight, MemSpace>(label + "_values", n);
    state = Kokkos::View<int*, MemSpace>(label + "_state", n);
  }
};

// Kernel "polymech::contact::carry_history": history of the pairs of `now` from those of `before`.
template <class T, int N>
void carry_history(const neighbors::NeighborList& before, const PairHistory<T, N>& old_history,
                   const neighbors::NeighborList& now, const PairHistory<T, N>& new_history) {
  const auto old_values = old_history.values, new_values = new_history.values;
  const auto old_state = old_history.state, new_state = new_history.state;
  const Index rows_before = before.num_particles;
  Kokkos::parallel_for(
      "polymech::contact::carry_history", range(now.num_particles), KOKKOS_LAMBDA(const Index i) {
        for (Offset k = now.begin(i); k < now.end(i); ++k) {
          const Index j = now.neighbor(k);
          Offset found = -1;
          if (i < rows_before)
            for (Offset m = before.begin(i); m < before.end(i) && found < 0; ++m)
              if (before.neighbor(m) == j) found = m;
          for (int c = 0; c < N; ++c) new_values(k, c) = found >= 0 ? old_values(found, c) : T(0);
          new_state(k) = found >= 0 ? old_state(found) : 0;
        }
      });
}

template <class T, int D, int N>
class ContactPairs {
 public:
  // radius: the contact range of the narrow phase (a sphere's radius plus a facet's extent, say);
  // skin: the Verlet skin. keep_history = false: the list alone (history() stays empty: a model whose
  // contacts have no history, e.g. DEM without friction, allocates none).
  ContactPairs(T radius, T skin, neighbors::ListKind kind, std::string label = "polymech::contact::pairs",
               bool keep_history = true)
      : radius_(radius), skin_(skin), kind_(kind), label_(std::move(label)), keep_history_(keep_history) {}

  // One set, points of different sizes (sphere radii): a pair is listed within sizes_i + sizes_j + skin
  // (each <= radius / 2) rather than radius + skin: fewer pairs to test each step, the same contacts.
  void set_sizes(const View1<T>& sizes) { sizes_ = sizes; }
  // Rows of at most `capacity` pairs are found in one search pass (NeighborSearch::set_row_capacity).
  void set_row_capacity(int capacity) { search_.set_row_capacity(capacity); }

  // One set: pairs among the points x. Returns true when the list was rebuilt.
  bool update(const VecView<T, D>& x) { return update_impl(x, x, false); }
  // The same, with the largest displacement since the last build computed by the caller (fused into
  // another pass over the points, e.g. dem::kick_drift_start); ignored at the first build.
  bool update(const VecView<T, D>& x, T moved) { return update_impl(x, x, false, moved); }
  // Two sets: pairs (query i, point j). Rebuilds when a query or a point moved more than skin / 2.
  bool update(const VecView<T, D>& queries, const VecView<T, D>& points) { return update_impl(queries, points, true); }

  const neighbors::NeighborList& list() const { return lists_[current_]; }
  const PairHistory<T, N>& history() const { return history_[current_]; }
  int builds() const { return builds_; }

  // For a checkpoint (models/common/contact_pairs_archive.hpp): the positions of the last build, and
  // restore(), which rebuilds the list from them (the same pairs in the same order, as the search is
  // deterministic) and leaves the history of its entries to be filled by the caller.
  const VecView<T, D>& queries_at_build() const { return queries_at_build_; }
  const VecView<T, D>& points_at_build() const { return points_at_build_; }
  bool between_sets() const { return between_; }
  void restore(const VecView<T, D>& queries, const VecView<T, D>& points, bool between, int builds) {
    queries_at_build_ = VecView<T, D>(label_ + "_queries_at_build", queries.extent(0));
    points_at_build_ = VecView<T, D>(label_ + "_points_at_build", points.extent(0));
    Kokkos::deep_copy(queries_at_build_, queries);
    Kokkos::deep_copy(points_at_build_, points);
    between_ = between;
    if (between)
      search_.build_between(queries_at_build_, points_at_build_, radius_ + skin_, lists_[current_]);
    else
      search_.build(queries_at_build_, radius_ + skin_, kind_, lists_[current_], sizes_, skin_);
    if (keep_history_) history_[current_].resize(static_cast<std::size_t>(lists_[current_].num_pairs), label_ + "_history");
    builds_ = builds;
  }

 private:
  bool update_impl(const VecView<T, D>& queries, const VecView<T, D>& points, bool between, T known = T(-1)) {
    const bool first = queries_at_build_.extent(0) != queries.extent(0) || points_at_build_.extent(0) != points.extent(0);
    if (!first) {
      T moved = known >= T(0) ? known : neighbors::max_displacement<T, D>(queries, queries_at_build_);
      if (between) moved = kx::max(moved, neighbors::max_displacement<T, D>(points, points_at_build_));
      if (moved <= skin_ / T(2)) return false;
    }
    if (first) {
      queries_at_build_ = VecView<T, D>(label_ + "_queries_at_build", queries.extent(0));
      points_at_build_ = VecView<T, D>(label_ + "_points_at_build", points.extent(0));
    }
    Kokkos::deep_copy(queries_at_build_, queries);
    Kokkos::deep_copy(points_at_build_, points);
    const int next = 1 - current_;
    between_ = between;
    if (between)
      search_.build_between(queries, points, radius_ + skin_, lists_[next]);
    else
      search_.build(queries, radius_ + skin_, kind_, lists_[next], sizes_, skin_);
    if (keep_history_) history_[next].resize(static_cast<std::size_t>(lists_[next].num_pairs), label_ + "_history");
    if (keep_history_ && builds_ > 0) carry_history(lists_[current_], history_[current_], lists_[next], history_[next]);
    current_ = next;
    ++builds_;
    return true;
  }

  T radius_, skin_;
  neighbors::ListKind kind_;
  std::string label_;
  bool keep_history_ = true;
  bool between_ = false;
  neighbors::NeighborSearch<T, D> search_;
  neighbors::NeighborList lists_[2];
  PairHistory<T, N> history_[2];
  int current_ = 0;
  int builds_ = 0;
  VecView<T, D> queries_at_build_, points_at_build_;
  View1<T> sizes_;  // set_sizes (empty: every pair within radius + skin)
};

}  // namespace polymech::contact
