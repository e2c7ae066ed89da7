// Contact pairs in a checkpoint: the positions of the pair list's last build (from which the list is
// rebuilt on restart, same pairs in the same order), the build count and the history of every pair in
// use (tangential springs, stick/slip states). A restarted run then continues bit for bit: the springs
// of the contacts that were open are where they were, and the next rebuild happens at the same step.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/archive.hpp"
#include "common/state.hpp"
#include "contact/contact_pairs.hpp"

namespace polymech::models {

template <class T, int D, int N>
void save_contact_pairs(Archive& a, const std::string& prefix, const contact::ContactPairs<T, D, N>& pairs) {
  a.put(prefix + "builds", pairs.builds());
  if (pairs.builds() == 0) return;
  const auto pairs_in_use = static_cast<std::size_t>(pairs.list().num_pairs);
  a.put(prefix + "between", static_cast<int>(pairs.between_sets()));
  a.put(prefix + "queries", static_cast<std::uint64_t>(pairs.queries_at_build().extent(0)));
  a.put(prefix + "points", static_cast<std::uint64_t>(pairs.points_at_build().extent(0)));
  a.put(prefix + "pairs", static_cast<std::uint64_t>(pairs_in_use));
  StateRegistry r;
  r.add("queries_at_build", pairs.queries_at_build());
  if (pairs.between_sets()) r.add("points_at_build", pairs.points_at_build());
  const auto& h = pairs.history();
  if (h.values.extent(0) > 0 && pairs_in_use > 0) {
    const std::pair<std::size_t, std::size_t> used(0, pairs_in_use);
    r.add("history_values", Kokkos::subview(h.values, used, Kokkos::ALL()));
    r.add("history_state", Kokkos::subview(h.state, used));
  }
  r.save(a, prefix);
}

// Restores `pairs` (constructed as the saved ones were) from a checkpoint written by save_contact_pairs.
template <class T, int D, int N>
void load_contact_pairs(const Archive& a, const std::string& prefix, contact::ContactPairs<T, D, N>& pairs) {
  const int builds = a.get<int>(prefix + "builds");
  if (builds == 0) return;
  const bool between = a.get<int>(prefix + "between") != 0;
  VecView<T, D> queries(prefix + "queries_at_build", a.get<std::uint64_t>(prefix + "queries"));
  VecView<T, D> points = queries;
  StateRegistry r;
  r.add("queries_at_build", queries);
  if (between) {
    points = VecView<T, D>(prefix + "points_at_build", a.get<std::uint64_t>(prefix + "points"));
    r.add("points_at_build", points);
  }
  r.load(a, prefix);
  pairs.restore(queries, points, between, builds);
  const auto saved_pairs = a.get<std::uint64_t>(prefix + "pairs");
  if (static_cast<std::uint64_t>(pairs.list().num_pairs) != saved_pairs)
    throw std::runtime_error("checkpoint: the contact list '" + prefix + "' rebuilt with " +
                             std::to_string(pairs.list().num_pairs) + " pairs, it had " + std::to_string(saved_pairs));
  const auto& h = pairs.history();
  if (h.values.extent(0) > 0 && saved_pairs > 0) {
    const std::pair<std::size_t, std::size_t> used(0, static_cast<std::size_t>(saved_pairs));
    StateRegistry hr;
    hr.add("history_values", Kokkos::subview(h.values, used, Kokkos::ALL()));
    hr.add("history_state", Kokkos::subview(h.state, used));
    hr.load(a, prefix);
  }
}

}  // namespace polymech::models
