// Probe records of any model: a model samples its probes by a kernel into one slot of a device buffer;
// the buffer is copied to the host in chunks (not every step) and appended to a ProbeHistory.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "core/types.hpp"

namespace polymech::models {

// Probe time series on the host: values[p][f][s] for probe p, field f, sample s.
struct ProbeHistory {
  std::vector<std::string> names;   // probes
  std::vector<std::string> fields;  // what each probe records
  std::vector<double> times;
  std::vector<std::vector<std::vector<double>>> values;
};

template <class T>
class ProbeBuffer {
 public:
  ProbeBuffer() = default;
  ProbeBuffer(const std::string& label, std::vector<std::string> probes, std::vector<std::string> fields,
              std::int64_t capacity = 2048)
      : capacity_(capacity) {
    history_.names = std::move(probes);
    history_.fields = std::move(fields);
    history_.values.assign(history_.names.size(), std::vector<std::vector<double>>(history_.fields.size()));
    if (!history_.names.empty())
      record_ = View2<T>(label, capacity_, history_.names.size() * history_.fields.size());
  }

  int probes() const { return static_cast<int>(history_.names.size()); }
  int fields() const { return static_cast<int>(history_.fields.size()); }

  // The record to write the next sample into and its slot (row): record(slot, probe * fields() + field).
  const View2<T>& record() const { return record_; }
  std::int64_t next_slot() {
    if (pending_ == capacity_) flush();
    return pending_;
  }
  // The sample written into next_slot() is the state at time t.
  void commit(double t) {
    pending_times_.push_back(t);
    ++pending_;
  }

  // Everything recorded so far (copies pending samples from the device first).
  const ProbeHistory& history() {
    flush();
    return history_;
  }

  // The record so far into a checkpoint, and back (a buffer built for the same probes).
  void save(Archive& a, const std::string& prefix) {
    flush();
    a.put_vector(prefix + "times", history_.times);
    for (std::size_t p = 0; p < history_.values.size(); ++p) a.put_columns(prefix + std::to_string(p), history_.values[p]);
  }
  void load(const Archive& a, const std::string& prefix) {
    pending_ = 0;
    pending_times_.clear();
    history_.times = a.get_vector<double>(prefix + "times");
    for (std::size_t p = 0; p < history_.values.size(); ++p) history_.values[p] = a.get_columns<double>(prefix + std::to_string(p));
  }

 private:
  void flush() {
    if (pending_ == 0) return;
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), record_);
    const int nf = fields();
    for (std::int64_t s = 0; s < pending_; ++s) {
      history_.times.push_back(pending_times_[static_cast<std::size_t>(s)]);
      for (int p = 0; p < probes(); ++p)
        for (int f = 0; f < nf; ++f) history_.values[p][f].push_back(static_cast<double>(h(s, p * nf + f)));
    }
    pending_ = 0;
    pending_times_.clear();
  }

  View2<T> record_;
  std::int64_t capacity_ = 2048;
  std::int64_t pending_ = 0;
  std::vector<double> pending_times_;
  ProbeHistory history_;
};

}  // namespace polymech::models
