#include "io/scene.hpp"

#include "io/model_table.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace polymech::io {

namespace detail {
struct SceneDocument {
  std::filesystem::path file;
  toml::table root;
};
}  // namespace detail

namespace {

const toml::table& as_table(const void* t) { return *static_cast<const toml::table*>(t); }

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date/time";
    default: return "nothing";
  }
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

std::string quoted_list(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "\"" : ", \"") + i + "\"";
  return s;
}

}  // namespace

std::string format_number(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.6g", x);
  return buf;
}

bool Range::contains(double x) const {
  if (std::isnan(x)) return false;
  const bool lo_ok = lo_open ? x > lo : x >= lo;
  const bool hi_ok = hi_open ? x < hi : x <= hi;
  return lo_ok && hi_ok;
}

std::string Range::text() const {
  const bool has_lo = std::isfinite(lo), has_hi = std::isfinite(hi);
  std::string s = "any finite number";
  if (has_lo && has_hi)
    s = std::string("in ") + (lo_open ? "(" : "[") + format_number(lo) + ", " + format_number(hi) + (hi_open ? ")" : "]");
  else if (has_lo)
    s = std::string(lo_open ? "> " : ">= ") + format_number(lo);
  else if (has_hi)
    s = std::string(hi_open ? "< " : "<= ") + format_number(hi);
  return note.empty() ? s : s + " " + note;
}

Range positive() { return Range{0.0, std::numeric_limits<double>::infinity(), true, false}; }
Range non_negative() { return Range{0.0, std::numeric_limits<double>::infinity(), false, false}; }
Range at_least(double lo) { return Range{lo, std::numeric_limits<double>::infinity(), false, false}; }
Range above(double lo) { return Range{lo, std::numeric_limits<double>::infinity(), true, false}; }
Range between(double lo, double hi) { return Range{lo, hi, false, false}; }

// ---------------------------------------------------------------------------------------------------

SceneTable::SceneTable(std::shared_ptr<const detail::SceneDocument> doc, const void* table, std::string path)
    : doc_(std::move(doc)), table_(table), path_(std::move(path)), known_(std::make_shared<std::set<std::string>>()) {}

const std::filesystem::path& SceneTable::file() const { return doc_->file; }

std::string SceneTable::full_name(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string SceneTable::location(const std::string& key) const {
  const auto& t = as_table(table_);
  toml::source_position pos = t.source().begin;
  if (!key.empty()) {
    auto it = t.find(key);
    if (it != t.end()) pos = it->first.source().begin;
  }
  std::string s = doc_->file.string();
  if (pos.line > 0) s += ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column);
  return s;
}

void SceneTable::fail(const std::string& key, const std::string& message) const {
  throw SceneError(location(key) + ": key '" + full_name(key) + "' " + message);
}

void SceneTable::fail_table(const std::string& message) const {
  const std::string where = path_.empty() ? "the scene" : "[" + path_ + "]";
  throw SceneError(location("") + ": " + where + ": " + message);
}

bool SceneTable::has(const std::string& key) const {
  known(key);
  return as_table(table_).contains(key);
}

namespace {

const toml::node* lookup(const void* table, const std::string& key) { return as_table(table).get(key); }

double number_of(const SceneTable& t, const std::string& key, const toml::node& n) {
  if (auto v = n.value<double>(); v && (n.is_integer() || n.is_floating_point())) return *v;
  t.fail(key, "must be a number, got " + type_name(n));
}

}  // namespace

double SceneTable::real(const std::string& key, Range range) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) fail(key, "is missing; it is required (a number " + range.text() + ")");
  const double x = number_of(*this, key, *n);
  if (!std::isfinite(x) || !range.contains(x))
    fail(key, "= " + format_number(x) + " is out of range: must be " + range.text());
  return x;
}

double SceneTable::real(const std::string& key, double fallback, Range range) const {
  known(key);
  return lookup(table_, key) ? real(key, range) : fallback;
}

std::int64_t SceneTable::integer(const std::string& key, std::int64_t lo, std::int64_t hi) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  const std::string allowed = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!n) fail(key, "is missing; it is required (" + allowed + ")");
  if (!n->is_integer()) fail(key, "must be " + allowed + ", got " + type_name(*n));
  const std::int64_t v = n->as_integer()->get();
  if (v < lo || v > hi) fail(key, "= " + std::to_string(v) + " is out of range: must be " + allowed);
  return v;
}

std::int64_t SceneTable::integer(const std::string& key, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const {
  known(key);
  return lookup(table_, key) ? integer(key, lo, hi) : fallback;
}

bool SceneTable::boolean(const std::string& key, bool fallback) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) return fallback;
  if (!n->is_boolean()) fail(key, "must be true or false, got " + type_name(*n));
  return n->as_boolean()->get();
}

std::string SceneTable::string(const std::string& key) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) fail(key, "is missing; it is required (a string)");
  if (!n->is_string()) fail(key, "must be a string, got " + type_name(*n));
  const std::string v = n->as_string()->get();
  if (v.find_first_not_of(" \t") == std::string::npos) fail(key, "is empty; it is required (a name or path, not \"\")");
  return v;
}

std::string SceneTable::string(const std::string& key, const std::string& fallback) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) return fallback;
  if (!n->is_string()) fail(key, "must be a string, got " + type_name(*n));
  return n->as_string()->get();
}

std::string SceneTable::choice(const std::string& key, const std::vector<std::string>& allowed) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) fail(key, "is missing; it is required (one of " + quoted_list(allowed) + ")");
  if (!n->is_string()) fail(key, "must be one of " + quoted_list(allowed) + ", got " + type_name(*n));
  const std::string v = n->as_string()->get();
  if (std::find(allowed.begin(), allowed.end(), v) == allowed.end())
    fail(key, "= \"" + v + "\" is not allowed; allowed: " + quoted_list(allowed));
  return v;
}

std::string SceneTable::choice(const std::string& key, const std::vector<std::string>& allowed,
                               const std::string& fallback) const {
  known(key);
  return lookup(table_, key) ? choice(key, allowed) : fallback;
}

std::vector<std::string> SceneTable::strings(const std::string& key, const std::vector<std::string>& fallback) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) return fallback;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "must be an array of strings, got " + type_name(*n));
  std::vector<std::string> out;
  for (const auto& e : *a) {
    if (!e.is_string()) fail(key, "must be an array of strings, but an element is " + type_name(e));
    out.push_back(e.as_string()->get());
  }
  return out;
}

std::vector<double> SceneTable::reals(const std::string& key, Range range) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) fail(key, "is missing; it is required (an array of numbers " + range.text() + ")");
  const toml::array* a = n->as_array();
  if (!a) fail(key, "must be an array of numbers, got " + type_name(*n));
  std::vector<double> out;
  for (const auto& e : *a) {
    const double x = number_of(*this, key, e);
    if (!std::isfinite(x) || !range.contains(x))
      fail(key, "has the element " + format_number(x) + ", out of range: elements must be " + range.text());
    out.push_back(x);
  }
  return out;
}

SceneTable SceneTable::table(const std::string& key) const {
  known(key);
  auto t = optional_table(key);
  if (!t) fail_table("the table [" + full_name(key) + "] is missing; it is required");
  return *t;
}

std::optional<SceneTable> SceneTable::optional_table(const std::string& key) const {
  known(key);
  const toml::node* n = lookup(table_, key);
  if (!n) return std::nullopt;
  if (!n->is_table()) fail(key, "must be a table ([" + full_name(key) + "]), got " + type_name(*n));
  return SceneTable(doc_, n->as_table(), full_name(key));
}

std::vector<SceneTable> SceneTable::tables(const std::string& key) const {
  known(key);
  std::vector<SceneTable> out;
  const toml::node* n = lookup(table_, key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    fail(key, "must be an array of tables ([[" + full_name(key) + "]]), got " + type_name(*n));
  std::size_t i = 0;
  for (const toml::node& e : *a)
    out.push_back(SceneTable(doc_, e.as_table(), full_name(key) + "[" + std::to_string(i++) + "]"));
  return out;
}

void SceneTable::finish() const {
  std::vector<std::string> known_keys(known_->begin(), known_->end());
  for (auto&& [k, v] : as_table(table_)) {
    (void)v;
    const std::string key(k.str());
    if (known_->count(key)) continue;
    const std::string where = path_.empty() ? "at the top level" : "in [" + path_ + "]";
    throw SceneError(location(key) + ": unknown key '" + full_name(key) + "'; allowed " + where + ": " +
                     (known_keys.empty() ? std::string("(none)") : join(known_keys)));
  }
}

// ---------------------------------------------------------------------------------------------------

Scene Scene::load(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw SceneError(file.string() + ": scene file not found (give an existing .toml file, e.g. scenes/mps/point_source.toml)");
  if (std::filesystem::is_directory(file, ec)) throw SceneError(file.string() + ": is a directory, not a scene file");
  auto doc = std::make_shared<detail::SceneDocument>();
  doc->file = file;
  try {
    doc->root = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    const auto& pos = e.source().begin;
    throw SceneError(file.string() + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  Scene s;
  s.doc_ = std::move(doc);
  return s;
}

SceneTable Scene::root() const { return SceneTable(doc_, &doc_->root, ""); }

const std::filesystem::path& Scene::file() const { return doc_->file; }

const std::vector<std::string>& accuracy_presets() {
  static const std::vector<std::string> names = {"draft", "standard", "paper"};
  return names;
}

AccuracyChoice read_accuracy(const SceneTable& root, const std::string& requested, double requested_coarsening,
                             const std::string& default_preset) {
  std::map<std::string, double> factors = {{"draft", 4.0}, {"standard", 2.0}, {"paper", 1.0}};
  AccuracyChoice out;
  out.preset = default_preset;
  if (auto acc = root.optional_table("accuracy")) {
    out.preset = acc->choice("default", accuracy_presets(), out.preset);
    for (auto& [name, f] : factors) f = acc->real(name, f, between(1.0, 64.0));
    acc->finish();
  }
  if (!requested.empty()) {
    if (!factors.count(requested)) {
      std::string allowed;
      for (const auto& n : accuracy_presets()) allowed += (allowed.empty() ? "" : ", ") + n;
      throw SceneError(root.file().string() + ": accuracy '" + requested + "' is unknown; allowed: " + allowed);
    }
    out.preset = requested;
  }
  out.coarsening = requested_coarsening > 0 ? requested_coarsening : factors.at(out.preset);
  return out;
}

OpenScene open_scene(const std::filesystem::path& file, const std::string& kind, const std::vector<EffectSpec>& declared,
                     const std::string& precision) {
  Scene scene = Scene::load(file);
  SceneTable root = scene.root();
  SceneTable model = root.table("model");
  SceneHeader h;
  h.file = file;
  h.title = root.string("title", file.stem().string());
  h.kind = model.choice("kind", {kind});
  h.effects = read_effects(model, declared);
  h.precision = read_precision(model, precision);
  return OpenScene{std::move(scene), root, model, std::move(h)};
}

}  // namespace polymech::io
