// A checkpoint's content in memory: named byte records, in the order they were put. Models put their
// state Views (host copies), run drivers their time series, apps what their writers have written;
// io/checkpoint.hpp stores an Archive in a file atomically and reads it back. Kokkos-free, so io/ and
// the apps' host code use it too.
//
// Values are stored as their bytes: a restart on the same build reproduces them bit for bit (a
// checkpoint is not a portable exchange format, and says so when read by another build: see
// io/checkpoint.hpp).
#pragma once

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace polymech::models {

class Archive {
 public:
  struct Record {
    std::string name;
    std::vector<char> bytes;
  };

  // Raw bytes under `name` (replaces an earlier record of that name).
  void put_bytes(const std::string& name, const void* data, std::size_t n) {
    Record* r = find(name);
    if (!r) {
      records_.push_back({name, {}});
      r = &records_.back();
    }
    r->bytes.assign(static_cast<const char*>(data), static_cast<const char*>(data) + n);
  }
  template <class T>
  void put(const std::string& name, const T& value) {
    static_assert(std::is_trivially_copyable_v<T>, "Archive::put stores plain values; use put_vector / put_string");
    put_bytes(name, &value, sizeof(T));
  }
  template <class T>
  void put_vector(const std::string& name, const std::vector<T>& v) {
    static_assert(std::is_trivially_copyable_v<T>, "Archive::put_vector stores vectors of plain values");
    put_bytes(name, v.data(), v.size() * sizeof(T));
  }
  void put_string(const std::string& name, const std::string& s) { put_bytes(name, s.data(), s.size()); }

  bool has(const std::string& name) const { return find(name) != nullptr; }
  const std::vector<char>& bytes(const std::string& name) const {
    const Record* r = find(name);
    if (!r) throw std::runtime_error("checkpoint: no record '" + name + "'");
    return r->bytes;
  }
  template <class T>
  T get(const std::string& name) const {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto& b = bytes(name);
    if (b.size() != sizeof(T))
      throw std::runtime_error("checkpoint: record '" + name + "' has " + std::to_string(b.size()) + " bytes, expected " +
                               std::to_string(sizeof(T)));
    T v;
    std::memcpy(&v, b.data(), sizeof(T));
    return v;
  }
  template <class T>
  std::vector<T> get_vector(const std::string& name) const {
    static_assert(std::is_trivially_copyable_v<T>);
    const auto& b = bytes(name);
    if (b.size() % sizeof(T) != 0)
      throw std::runtime_error("checkpoint: record '" + name + "' is not a whole number of " + std::to_string(sizeof(T)) +
                               "-byte values");
    std::vector<T> v(b.size() / sizeof(T));
    if (!v.empty()) std::memcpy(v.data(), b.data(), b.size());
    return v;
  }
  // get_vector with the size this model expects: a checkpoint of another model (another mesh or case) is refused
  // with both sizes named.
  template <class T>
  std::vector<T> get_vector_sized(const std::string& name, std::size_t expected) const {
    std::vector<T> v = get_vector<T>(name);
    if (v.size() != expected)
      throw std::runtime_error("checkpoint: " + name + " has " + std::to_string(v.size()) + " values, this model " + std::to_string(expected));
    return v;
  }
  std::string get_string(const std::string& name) const {
    const auto& b = bytes(name);
    return std::string(b.begin(), b.end());
  }

  // A vector of vectors (columns of a time series) under name/0, name/1, ... and name/count.
  template <class T>
  void put_columns(const std::string& name, const std::vector<std::vector<T>>& c) {
    put(name + "/count", static_cast<std::uint64_t>(c.size()));
    for (std::size_t k = 0; k < c.size(); ++k) put_vector(name + "/" + std::to_string(k), c[k]);
  }
  template <class T>
  std::vector<std::vector<T>> get_columns(const std::string& name) const {
    std::vector<std::vector<T>> c(get<std::uint64_t>(name + "/count"));
    for (std::size_t k = 0; k < c.size(); ++k) c[k] = get_vector<T>(name + "/" + std::to_string(k));
    return c;
  }

  const std::vector<Record>& records() const { return records_; }
  std::vector<Record>& records() { return records_; }
  std::size_t bytes_total() const {
    std::size_t n = 0;
    for (const auto& r : records_) n += r.bytes.size();
    return n;
  }

 private:
  Record* find(const std::string& name) {
    for (auto& r : records_)
      if (r.name == name) return &r;
    return nullptr;
  }
  const Record* find(const std::string& name) const {
    for (const auto& r : records_)
      if (r.name == name) return &r;
    return nullptr;
  }
  std::vector<Record> records_;
};

}  // namespace polymech::models
