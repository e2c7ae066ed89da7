// Strict reading of scene files (TOML): every value is read through a SceneTable that checks its
// type and range, remembers which keys the model knows, and reports unknown keys when the table is
// finished. Every error is one SceneError whose message names the file, the line, the key and what
// is allowed, e.g.
//
//   scenes/mps/point_source.toml:12:1: key 'domain.spacing' = -5e-05 is out of range: must be > 0
//   scenes/mps/point_source.toml:14:1: unknown key 'domain.spacng'; allowed in [domain]: width, height, ...
//
// Host-only (toml++ does not compile under nvcc); models never see this header.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "effects.hpp"

namespace polymech::io {

class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An interval for a number; text() says it in words for error messages ("> 0", "in [1, 10]"), followed
// by `note` when there is one (a unit, what the bounds mean: see io/ranges.hpp).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  std::string note;

  Range() = default;
  Range(double lo_, double hi_, bool lo_open_ = false, bool hi_open_ = false, std::string note_ = {})
      : lo(lo_), hi(hi_), lo_open(lo_open_), hi_open(hi_open_), note(std::move(note_)) {}

  bool contains(double x) const;
  std::string text() const;
};
Range positive();                      // > 0
Range non_negative();                  // >= 0
Range at_least(double lo);             // >= lo
Range above(double lo);                // > lo
Range between(double lo, double hi);   // [lo, hi]

namespace detail {
struct SceneDocument;
}

// One table of a scene (the root, [section], or one entry of [[array]]).
class SceneTable {
 public:
  // Required and optional numbers; integers in the file are accepted as reals.
  double real(const std::string& key, Range range) const;
  double real(const std::string& key, double fallback, Range range) const;
  std::int64_t integer(const std::string& key, std::int64_t lo, std::int64_t hi) const;
  std::int64_t integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const;
  bool boolean(const std::string& key, bool fallback) const;
  // A required string may not be empty (a name or a path); the optional form returns what is written.
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  // A string from a fixed set; the error lists the set.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string choice(const std::string& key, const std::vector<std::string>& allowed, const std::string& fallback) const;
  std::vector<std::string> strings(const std::string& key, const std::vector<std::string>& fallback) const;
  std::vector<double> reals(const std::string& key, Range range) const;

  bool has(const std::string& key) const;
  SceneTable table(const std::string& key) const;                    // required [key]
  std::optional<SceneTable> optional_table(const std::string& key) const;
  std::vector<SceneTable> tables(const std::string& key) const;      // [[key]], may be empty

  // Fails on any key of this table that no accessor above asked for, listing the known ones.
  void finish() const;

  // Errors located at a key of this table (or at the table itself when the key is absent).
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  [[noreturn]] void fail_table(const std::string& message) const;

  // "domain.spacing", "probes[2].x1": the key's full name, as errors print it.
  std::string full_name(const std::string& key) const;
  const std::filesystem::path& file() const;
  std::string location(const std::string& key) const;  // "file:line:column"

 private:
  friend class Scene;
  // table is a const toml::table*, kept opaque so toml++ stays inside scene.cpp
  SceneTable(std::shared_ptr<const detail::SceneDocument> doc, const void* table, std::string path);
  void known(const std::string& key) const { known_->insert(key); }

  std::shared_ptr<const detail::SceneDocument> doc_;
  const void* table_;
  std::string path_;  // "" for the root
  std::shared_ptr<std::set<std::string>> known_;
};

// A parsed scene file. Missing or unreadable files and TOML syntax errors are SceneErrors.
class Scene {
 public:
  static Scene load(const std::filesystem::path& file);
  SceneTable root() const;
  const std::filesystem::path& file() const;

 private:
  std::shared_ptr<const detail::SceneDocument> doc_;
};

// "%.6g" of a number, the form error messages print values in.
std::string format_number(double x);

// Accuracy presets shared by every scene kind: [accuracy] names the default preset and may change the
// spacing factor of each (draft x4, standard x2, paper x1 by default, each in [1, 64]).
const std::vector<std::string>& accuracy_presets();

struct AccuracyChoice {
  std::string preset;       // the preset in effect
  double coarsening = 1.0;  // spacing factor relative to the paper's
};

// Reads the optional [accuracy] table of `root`; `requested` (a command-line preset, "" = the scene's
// default) and `requested_coarsening` (> 0: an explicit factor, e.g. from a sweep) override it.
AccuracyChoice read_accuracy(const SceneTable& root, const std::string& requested, double requested_coarsening,
                             const std::string& default_preset = "draft");

// What a user chooses when a scene is loaded, the same fields for every loader (load_<kind>_scene(file,
// options)); empty: the scene's own. Loaders with more choices have their own struct with these two
// fields (MpsSceneOptions, NosbPdSceneOptions, HelmholtzSceneOptions).
struct SceneOptions {
  std::string accuracy;   // "" -> the scene's [accuracy].default
  std::string precision;  // "" -> the scene's [model].precision
};

// What every scene says about itself, whatever its model: the file, its title, the model kind, the
// effects it asks for (resolved against the model's), the precision and the accuracy preset.
struct SceneHeader {
  std::filesystem::path file;
  std::string title;
  std::string kind;
  std::string precision;     // "double" or "float"
  EffectSet effects;
  std::string accuracy;      // preset name
  double coarsening = 1.0;   // the preset's resolution factor

  void set_accuracy(const AccuracyChoice& a) {
    accuracy = a.preset;
    coarsening = a.coarsening;
  }
};

// A scene opened by its model's loader: the parsed file, its root table, its [model] table (with kind,
// effects and precision read; the loader reads any further keys and calls model.finish()) and header.
struct OpenScene {
  Scene scene;
  SceneTable root;
  SceneTable model;
  SceneHeader header;
};

// The first lines of every loader: load the file, read the title, check [model].kind == kind, resolve
// [model].effects against `declared` and read [model].precision (`precision` overrides it when not
// empty).
OpenScene open_scene(const std::filesystem::path& file, const std::string& kind, const std::vector<EffectSpec>& declared,
                     const std::string& precision = "");

// The same, filling a loader's result: out.header and out.config.effects.
template <class SceneT>
OpenScene open_scene(const std::filesystem::path& file, const std::string& kind, const std::vector<EffectSpec>& declared,
                     const std::string& precision, SceneT& out) {
  OpenScene s = open_scene(file, kind, declared, precision);
  out.header = s.header;
  out.config.effects = s.header.effects;
  return s;
}

}  // namespace polymech::io
