// The state of a model as a list of named Views: everything a step reads that it did not compute in
// the same step (displacements, velocities, accelerations of velocity Verlet, bond and contact states,
// material history). A model registers its Views once, after allocating them; the run driver's
// watchdog keeps a copy of the last good state with it, and checkpoints (Archive, io/checkpoint.hpp)
// write it and read it back.
//
// Views of effects that are off are empty and are not registered: a disabled effect costs nothing
// here either.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "common/archive.hpp"
#include "core/types.hpp"

namespace polymech::models {

// How many of a floating-point View's values are subnormal (0 < |x| < the type's smallest normal).
struct SubnormalCount {
  std::string name;
  std::int64_t subnormal = 0, values = 0;
};

class StateRegistry {
 public:
  // A copy of every registered View, in the same memory space (the watchdog's last good state).
  class Backup {
   public:
    bool empty() const { return restore_.empty(); }

   private:
    friend class StateRegistry;
    std::vector<std::function<void()>> save_, restore_;
  };

  template <class View>
  void add(const std::string& name, const View& v) {
    if (v.size() == 0) return;
    Entry e;
    e.name = name;
    e.bytes = v.span() * sizeof(typename View::value_type);
    e.make_backup = [v](std::vector<std::function<void()>>& save, std::vector<std::function<void()>>& restore) {
      auto copy = Kokkos::create_mirror(typename View::memory_space(), v);
      save.push_back([v, copy] { Kokkos::deep_copy(copy, v); });
      restore.push_back([v, copy] { Kokkos::deep_copy(v, copy); });
    };
    e.to_archive = [v](Archive& a, const std::string& key) {
      auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
      a.put_bytes(key, h.data(), h.span() * sizeof(typename View::value_type));
    };
    e.from_archive = [v](const Archive& a, const std::string& key) {
      const auto& b = a.bytes(key);
      auto h = Kokkos::create_mirror_view(v);
      if (b.size() != h.span() * sizeof(typename View::value_type))
        throw std::runtime_error("checkpoint: '" + key + "' has " + std::to_string(b.size()) + " bytes, this run needs " +
                                 std::to_string(h.span() * sizeof(typename View::value_type)) +
                                 " (written for another scene or size?)");
      std::memcpy(static_cast<void*>(h.data()), b.data(), b.size());
      Kokkos::deep_copy(v, h);
    };
    using value_type = typename View::non_const_value_type;
    if constexpr (std::is_floating_point_v<value_type>) {
      e.count_subnormals = [v] {
        auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), v);
        const value_type* p = h.data();
        std::int64_t n = 0;
        for (std::size_t i = 0; i < h.span(); ++i)
          n += (p[i] != value_type(0) && std::abs(p[i]) < std::numeric_limits<value_type>::min()) ? 1 : 0;
        return std::make_pair(n, static_cast<std::int64_t>(h.span()));
      };
    }
    entries_.push_back(std::move(e));
  }

  // Everything `other` holds, after what this one holds (a coupled model's two models).
  void append(const StateRegistry& other) { entries_.insert(entries_.end(), other.entries_.begin(), other.entries_.end()); }

  std::size_t size() const { return entries_.size(); }
  std::size_t bytes() const {
    std::size_t b = 0;
    for (const auto& e : entries_) b += e.bytes;
    return b;
  }
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& e : entries_) n.push_back(e.name);
    return n;
  }

  // The subnormal values of every floating-point View (issue 39: where a model meets them when they are
  // kept); copies each View to the host, so it is a diagnostic (RunHooks::census_every), not a hot path.
  std::vector<SubnormalCount> subnormal_census() const {
    std::vector<SubnormalCount> c;
    for (const auto& e : entries_) {
      if (!e.count_subnormals) continue;
      const auto [n, size] = e.count_subnormals();
      c.push_back({e.name, n, size});
    }
    return c;
  }

  // Allocates backup storage for every View (once) and copies the state into it.
  void save(Backup& b) const {
    if (b.save_.empty())
      for (const auto& e : entries_) e.make_backup(b.save_, b.restore_);
    for (auto& s : b.save_) s();
    Kokkos::fence();
  }
  void restore(const Backup& b) const {
    for (auto& r : b.restore_) r();
    Kokkos::fence();
  }

  // Every View's bytes under "<prefix><name>" (a checkpoint), and back. Reading checks that every
  // View is there with the size this model has.
  void save(Archive& a, const std::string& prefix = "state/") const {
    for (const auto& e : entries_) e.to_archive(a, prefix + e.name);
  }
  void load(const Archive& a, const std::string& prefix = "state/") const {
    for (const auto& e : entries_) e.from_archive(a, prefix + e.name);
    Kokkos::fence();
  }

 private:
  struct Entry {
    std::string name;
    std::size_t bytes = 0;
    std::function<void(std::vector<std::function<void()>>&, std::vector<std::function<void()>>&)> make_backup;
    std::function<void(Archive&, const std::string&)> to_archive;
    std::function<void(const Archive&, const std::string&)> from_archive;
    std::function<std::pair<std::int64_t, std::int64_t>()> count_subnormals;  // floating-point Views only
  };
  std::vector<Entry> entries_;
};

}  // namespace polymech::models
