// What an app keeps while it runs and must get back on --restart: time series of named columns
// (Series) and the sums, counts and lists under way (Records). Both write themselves into every
// checkpoint and read themselves back, so an app names each value once instead of listing it again in
// a save and a load function that must stay in the same order.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/archive.hpp"
#include "io/output.hpp"

namespace polymech::apps {

// Named columns of equal length, one row per sample.
class Series {
 public:
  Series() = default;
  explicit Series(std::vector<std::string> names) : names_(std::move(names)), columns_(names_.size()) {}

  std::size_t columns() const { return names_.size(); }
  std::size_t rows() const { return columns_.empty() ? 0 : columns_[0].size(); }
  bool empty() const { return rows() == 0; }
  const std::vector<std::string>& names() const { return names_; }

  // One value per column, in the columns' order.
  void append(std::initializer_list<double> row) {
    if (row.size() != columns_.size())
      throw std::logic_error("Series::append: " + std::to_string(row.size()) + " values for " +
                             std::to_string(columns_.size()) + " columns");
    std::size_t k = 0;
    for (double x : row) columns_[k++].push_back(x);
  }
  void append(const std::vector<double>& row) {
    if (row.size() != columns_.size()) throw std::logic_error("Series::append: row and columns differ in length");
    for (std::size_t k = 0; k < row.size(); ++k) columns_[k].push_back(row[k]);
  }

  const std::vector<double>& operator[](const std::string& name) const { return columns_[index(name)]; }
  std::vector<double>& operator[](const std::string& name) { return columns_[index(name)]; }
  const std::vector<double>& column(std::size_t k) const { return columns_.at(k); }
  const io::Columns& all() const { return columns_; }

  // The named columns, in the order given (for a CSV file that holds some of them).
  io::Columns select(const std::vector<std::string>& names) const {
    io::Columns c;
    for (const auto& n : names) c.push_back((*this)[n]);
    return c;
  }
  void write_csv(const std::filesystem::path& file) const { io::write_csv(file, names_, columns_); }
  void write_csv(const std::filesystem::path& file, const std::vector<std::string>& names) const {
    io::write_csv(file, names, select(names));
  }

  void save(models::Archive& a, const std::string& key) const { a.put_columns(key, columns_); }
  void load(const models::Archive& a, const std::string& key) {
    auto c = a.get_columns<double>(key);
    if (c.size() != columns_.size())
      throw std::runtime_error("checkpoint: " + key + " has " + std::to_string(c.size()) + " columns, this run keeps " +
                               std::to_string(columns_.size()));
    columns_ = std::move(c);
  }

 private:
  std::size_t index(const std::string& name) const {
    for (std::size_t k = 0; k < names_.size(); ++k)
      if (names_[k] == name) return k;
    throw std::logic_error("Series: no column '" + name + "'");
  }
  std::vector<std::string> names_;
  io::Columns columns_;
};

// The app's values under way, each under a checkpoint key: saved into every checkpoint, read back
// when the run resumes from one. The referenced values must outlive the run.
class Records {
 public:
  void keep(const std::string& key, Series& s) {
    add([&s, key](models::Archive& a) { s.save(a, key); }, [&s, key](const models::Archive& a) { s.load(a, key); });
  }
  void keep(const std::string& key, std::vector<double>& v) {
    add([&v, key](models::Archive& a) { a.put_vector(key, v); },
        [&v, key](const models::Archive& a) { v = a.get_vector<double>(key); });
  }
  template <class T>
  void keep(const std::string& key, T& x) {
    static_assert(std::is_arithmetic_v<T>, "Records::keep: a number, a vector of doubles or a Series");
    add([&x, key](models::Archive& a) { a.put(key, x); }, [&x, key](const models::Archive& a) { x = a.get<T>(key); });
  }
  // Anything else: the app's own pair.
  void add(std::function<void(models::Archive&)> save, std::function<void(const models::Archive&)> load) {
    save_.push_back(std::move(save));
    load_.push_back(std::move(load));
  }

  void save(models::Archive& a) const {
    for (const auto& f : save_) f(a);
  }
  void load(const models::Archive& a) const {
    for (const auto& f : load_) f(a);
  }

 private:
  std::vector<std::function<void(models::Archive&)>> save_;
  std::vector<std::function<void(const models::Archive&)>> load_;
};

}  // namespace polymech::apps
