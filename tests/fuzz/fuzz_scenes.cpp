// The scene fuzzer: mutates every shipped scene (scenes/**/*.toml) deterministically into variants and
// runs each through its loader in this process (what `--dry-run` does: load, validate, estimate the
// cost). Every variant must either load, with a finite cost estimate, or be refused with an
// io::SceneError whose message names "<file>:<line>" and a key or table. Anything else (another
// exception, an error without file:line or key, a crash) is listed and fails the run.
//
//   fuzz_scenes [--source DIR] [--work DIR] [--stride N] [--verbose]
//
// --source: the project (default $POLYMECH_SOURCE_DIR or .); --work: where variants are written
// (default: a folder under the temp directory, removed at the end); --stride N: run every N-th variant
// only (default 1: all); --verbose: one line per variant. A crash prints the variant it happened in.
//
// Mutations: per key line: delete, rename, retype, and for numbers -1, 0, negated, x10, +1, 1e300,
// 1e-300, -1e300, 1e15, nan, inf, -inf; for strings "", blanks, an unknown name; for arrays [], an
// element set to 1e300 / nan / a string / +10, one element fewer or more; profile_to = profile_from.
// Per scene: truncation at 7 points, garbage bytes at 4, a duplicated key and table, an unknown key and
// table, every effect name added and every listed effect removed, an unknown effect, no effects. Per
// Gmsh mesh a scene reads: truncation, deleted and corrupted lines, wrong counts and sections.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/kokkos_shim.hpp"
#include "io/cost.hpp"
#include "io/registry.hpp"
#include "io/scene.hpp"

namespace fs = std::filesystem;
namespace io = polymech::io;

namespace {

struct Variant {
  std::string name;      // "mps/point_source.toml: material.density = 1e300"
  std::string scene;     // the scene text
  std::string mesh;      // a replacement for the scene's mesh file ("" = the shipped one)
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  std::istringstream s(text);
  while (std::getline(s, line)) lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string s;
  for (const auto& l : lines) s += l + "\n";
  return s;
}

// One `key = value  # comment` line: where the value starts and ends.
struct KeyLine {
  std::size_t line = 0;
  std::string table;  // "domain", "probes" ([[probes]]), "" at the top
  std::string key;
  std::size_t value_begin = 0, value_end = 0;
  char type = 'n';  // n: number, s: string, a: array, b: boolean, ?: other
};

std::vector<KeyLine> key_lines(const std::vector<std::string>& lines) {
  static const std::regex key_re(R"(^\s*([A-Za-z_][A-Za-z0-9_]*)\s*=\s*)");
  static const std::regex table_re(R"(^\s*\[\[?\s*([A-Za-z0-9_.]+)\s*\]\]?)");
  std::vector<KeyLine> out;
  std::string table;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (std::regex_search(lines[i], m, table_re)) {
      table = m[1];
      continue;
    }
    if (!std::regex_search(lines[i], m, key_re)) continue;
    KeyLine k;
    k.line = i;
    k.table = table;
    k.key = m[1];
    const std::string& l = lines[i];
    k.value_begin = static_cast<std::size_t>(m.length(0));
    if (k.value_begin >= l.size()) continue;
    const char c0 = l[k.value_begin];
    std::size_t end = std::string::npos;
    if (c0 == '"') {
      k.type = 's';
      end = l.find('"', k.value_begin + 1);
      if (end != std::string::npos) ++end;
    } else if (c0 == '[') {
      k.type = 'a';
      end = l.find(']', k.value_begin);
      if (end != std::string::npos) ++end;
    } else {
      end = l.find_first_of(" \t#", k.value_begin);
      if (end == std::string::npos) end = l.size();
      const std::string v = l.substr(k.value_begin, end - k.value_begin);
      k.type = (v == "true" || v == "false") ? 'b' : (std::strtod(v.c_str(), nullptr) != 0.0 || v[0] == '0') ? 'n' : '?';
    }
    if (end == std::string::npos) continue;  // a value over several lines: only deleted / renamed
    k.value_end = end;
    out.push_back(k);
  }
  return out;
}

std::string with_value(const std::vector<std::string>& lines, const KeyLine& k, const std::string& value) {
  auto copy = lines;
  std::string& l = copy[k.line];
  l = l.substr(0, k.value_begin) + value + l.substr(k.value_end);
  return join_lines(copy);
}

std::vector<std::string> array_elements(const std::string& v) {
  std::vector<std::string> out;
  std::string inner = v.substr(1, v.size() - 2), tok;
  std::istringstream s(inner);
  while (std::getline(s, tok, ',')) {
    const auto a = tok.find_first_not_of(" \t"), b = tok.find_last_not_of(" \t");
    if (a != std::string::npos) out.push_back(tok.substr(a, b - a + 1));
  }
  return out;
}

std::string array_of(const std::vector<std::string>& e) {
  std::string s = "[";
  for (std::size_t i = 0; i < e.size(); ++i) s += (i ? ", " : "") + e[i];
  return s + "]";
}

std::string number_text(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  std::string s = buf;
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // keep it a TOML float
  return s;
}

const std::vector<std::string>& effect_names() {
  static const std::vector<std::string> names = {
      "rotation", "crack_contact.open_close", "crack_contact.slip", "weighted_function", "velocity_viscosity", "damage",
      "contact",  "short_range",              "hourglass",          "dirichlet",         "impedance",          "vibrating"};
  return names;
}

// Every variant of one scene's text.
std::vector<Variant> scene_variants(const std::string& name, const std::string& text) {
  std::vector<Variant> out;
  auto add = [&](const std::string& what, const std::string& scene) { out.push_back({name + ": " + what, scene, ""}); };
  const auto lines = split_lines(text);
  const auto keys = key_lines(lines);
  std::map<std::string, std::string> values;  // "output.profile_from" -> its text
  for (const auto& k : keys)
    values[k.table + "." + k.key] = lines[k.line].substr(k.value_begin, k.value_end - k.value_begin);

  for (const auto& k : keys) {
    const std::string full = (k.table.empty() ? "" : k.table + ".") + k.key;
    const std::string v = lines[k.line].substr(k.value_begin, k.value_end - k.value_begin);
    {
      auto copy = lines;
      copy.erase(copy.begin() + static_cast<long>(k.line));
      add(full + " deleted", join_lines(copy));
      copy = lines;
      copy[k.line] = std::regex_replace(copy[k.line], std::regex("^(\\s*)" + k.key), "$1" + k.key + "_typo");
      add(full + " renamed", join_lines(copy));
      copy = lines;
      copy.insert(copy.begin() + static_cast<long>(k.line), lines[k.line]);
      add(full + " given twice", join_lines(copy));
    }
    auto set = [&](const std::string& value) { add(full + " = " + value, with_value(lines, k, value)); };
    if (k.type == 'n') {
      const double x = std::strtod(v.c_str(), nullptr);
      for (const char* r : {"-1", "0", "1e300", "1e-300", "-1e300", "1e15", "nan", "inf", "-inf", "\"text\"", "true"})
        set(r);
      set(number_text(-x));
      set(number_text(10 * x));
      set(number_text(x + 1));
    } else if (k.type == 's') {
      for (const char* r : {"\"\"", "\"   \"", "\"no_such_name\"", "1.5", "[\"a\"]"}) set(r);
    } else if (k.type == 'a') {
      auto e = array_elements(v);
      set("[]");
      set("\"text\"");
      if (!e.empty()) {
        for (const char* r : {"1e300", "nan", "-1", "\"x\""}) {
          auto f = e;
          f[0] = r;
          set(array_of(f));
        }
        auto f = e;
        f.pop_back();
        set(array_of(f));
        f = e;
        f.push_back(e.back());
        set(array_of(f));
        const double x = std::strtod(e[0].c_str(), nullptr);
        if (e[0][0] != '"') {
          f = e;
          f[0] = number_text(x + 10);
          set(array_of(f));
        }
      }
      if (k.key == "profile_to" && values.count(k.table + ".profile_from")) set(values[k.table + ".profile_from"]);
      if (k.key == "effects") {
        for (const auto& eff : effect_names()) {
          const std::string q = "\"" + eff + "\"";
          if (v.find(q) != std::string::npos) {
            auto g = e;
            g.erase(std::remove(g.begin(), g.end(), q), g.end());
            set(array_of(g));
          } else {
            auto g = e;
            g.push_back(q);
            set(array_of(g));
          }
        }
        set("[\"no_such_effect\"]");
        if (!e.empty()) {
          auto g = e;
          g.push_back(e[0]);
          set(array_of(g));
        }
      }
    } else if (k.type == 'b') {
      for (const char* r : {"1", "\"true\""}) set(r);
    }
  }

  // whole-file mutations
  for (int pct : {5, 20, 35, 50, 65, 80, 95}) add("truncated at " + std::to_string(pct) + " %", text.substr(0, text.size() * pct / 100));
  const std::string garbage[] = {std::string("\0\0", 2), "\xff\xfe\xfd", "=[[]] \x1b", "\x80\x81 key"};
  for (int g = 0; g < 4; ++g) {
    const std::size_t at = text.size() * static_cast<std::size_t>(g + 1) / 5;
    add("garbage bytes at " + std::to_string(at), text.substr(0, at) + garbage[g] + text.substr(at));
  }
  add("unknown key", "no_such_key = 1\n" + text);
  add("unknown table", text + "\n[no_such_table]\nx = 1\n");
  for (std::size_t i = 0; i < lines.size(); ++i)
    if (lines[i].rfind("[", 0) == 0 && lines[i].rfind("[[", 0) != 0) {
      add("table " + lines[i].substr(0, lines[i].find(']') + 1) + " twice", text + "\n" + lines[i] + "\n");
      break;
    }
  add("empty file", "");
  return out;
}

// Variants of a Gmsh mesh (the scene that reads it is kept as it is).
std::vector<Variant> mesh_variants(const std::string& name, const std::string& scene, const std::string& mesh) {
  std::vector<Variant> out;
  auto add = [&](const std::string& what, const std::string& m) { out.push_back({name + ": mesh " + what, scene, m}); };
  const auto lines = split_lines(mesh);
  for (int pct : {1, 10, 30, 50, 70, 90, 99}) add("truncated at " + std::to_string(pct) + " %", mesh.substr(0, mesh.size() * pct / 100));
  auto find = [&](const std::string& s) {
    for (std::size_t i = 0; i < lines.size(); ++i)
      if (lines[i].rfind(s, 0) == 0) return i;
    return lines.size();
  };
  auto edit = [&](const std::string& what, std::size_t line, const std::string& replacement) {
    if (line >= lines.size()) return;
    auto copy = lines;
    copy[line] = replacement;
    add(what, join_lines(copy));
  };
  auto erase = [&](const std::string& what, std::size_t line) {
    if (line >= lines.size()) return;
    auto copy = lines;
    copy.erase(copy.begin() + static_cast<long>(line));
    add(what, join_lines(copy));
  };
  const std::size_t fmt = find("$MeshFormat"), nodes = find("$Nodes"), elems = find("$Elements"), ent = find("$Entities");
  edit("version 2.2", fmt + 1, "2.2 0 8");
  edit("binary", fmt + 1, "4.1 1 8");
  erase("no $MeshFormat", fmt);
  erase("no $EndNodes", find("$EndNodes"));
  erase("no $EndElements", find("$EndElements"));
  edit("node count -5", nodes + 1, "1 -5 1 5");
  edit("node count 1e18", nodes + 1, "1 1000000000000000000 1 5");
  edit("entity counts garbage", ent + 1, "x y z w");
  edit("element header garbage", elems + 1, "1 2");
  edit("element count huge", elems + 1, "99999999 99999999 1 99999999");
  add("$Nodes twice", mesh + "$Nodes\n0 0 0 0\n$EndNodes\n");
  add("unclosed section", mesh + "$Comments\nnever closed\n");
  add("text before the format", "hello\n" + mesh);
  // corrupted lines at ten places through the file
  for (int k = 1; k <= 10; ++k) {
    const std::size_t at = lines.size() * static_cast<std::size_t>(k) / 11;
    erase("line " + std::to_string(at + 1) + " deleted", at);
    edit("line " + std::to_string(at + 1) + " = nan", at, "nan nan nan");
    edit("line " + std::to_string(at + 1) + " = garbage", at, "1 2 x 4 \xff");
    edit("line " + std::to_string(at + 1) + " = -7", at, "-7");
  }
  return out;
}

const char* current_variant = "(none)";
void on_crash(int sig) {
  std::fprintf(stderr, "\nfuzz_scenes: CRASH (signal %d) in variant: %s\n", sig, current_variant);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

enum class Outcome { loaded, refused, bad };

struct Result {
  Outcome outcome;
  std::string detail;
};

std::string escape_regex(const std::string& s) { return std::regex_replace(s, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"); }

Result run_variant(const fs::path& scene_file) {
  try {
    const io::SceneKind& kind = io::scene_kind_of(scene_file);
    const io::CostEstimate cost = kind.estimate(scene_file);
    const std::string text = io::describe(cost);
    if (!(std::isfinite(cost.items) && cost.items > 0 && std::isfinite(cost.bytes) && cost.bytes > 0 &&
          std::isfinite(cost.seconds) && cost.seconds >= 0 && std::isfinite(cost.steps)))
      return {Outcome::bad, "loaded with a cost estimate that is not finite:\n" + text};
    return {Outcome::loaded, ""};
  } catch (const io::SceneError& e) {
    const std::string msg = e.what();
    static const std::regex names_key(R"(key '[^']+'|\[[A-Za-z_][A-Za-z0-9_.\[\]]*\]|TOML syntax error)");
    const bool located = std::regex_search(msg, std::regex(escape_regex(scene_file.string()) + ":[0-9]+"));
    if (!located) return {Outcome::bad, "message without " + scene_file.string() + ":<line>: " + msg};
    if (!std::regex_search(msg, names_key)) return {Outcome::bad, "message naming no key or table: " + msg};
    return {Outcome::refused, msg};
  } catch (const std::exception& e) {
    return {Outcome::bad, std::string("threw something else than a SceneError: ") + e.what()};
  } catch (...) {
    return {Outcome::bad, "threw a non-exception"};
  }
}

}  // namespace

int main(int argc, char** argv) {
  fs::path source = std::getenv("POLYMECH_SOURCE_DIR") ? fs::path(std::getenv("POLYMECH_SOURCE_DIR")) : fs::path(".");
  fs::path work;
  std::size_t stride = 1;
  bool verbose = false;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--source" && k + 1 < argc) source = argv[++k];
    else if (a == "--work" && k + 1 < argc) work = argv[++k];
    else if (a == "--stride" && k + 1 < argc) stride = std::max(1, std::atoi(argv[++k]));
    else if (a == "--verbose") verbose = true;
    else {
      std::fprintf(stderr, "usage: fuzz_scenes [--source DIR] [--work DIR] [--stride N] [--verbose]\n");
      return 2;
    }
  }
  const bool own_work = work.empty();
  if (own_work) work = fs::temp_directory_path() / ("polymech_fuzz_scenes_" + std::to_string(::getpid()));
  fs::remove_all(work);
  for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL}) std::signal(sig, on_crash);

  // variants that grow a run are refused by its memory estimate long before they would take seconds to
  // check; the shipped scenes at their default accuracy need far less than this
  ::setenv("POLYMECH_MEMORY_LIMIT", "256M", 0);
  polymech::kx::initialize(1);  // the loaders compute stability limits with the models' kernels
  std::vector<fs::path> scenes;
  for (const auto& e : fs::recursive_directory_iterator(source / "scenes"))
    if (e.is_regular_file() && e.path().extension() == ".toml") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());

  std::size_t total = 0, run = 0, loaded = 0, refused = 0;
  std::vector<std::string> bad;
  std::map<std::string, std::size_t> per_scene;
  for (const auto& scene : scenes) {
    const fs::path rel = fs::relative(scene, source / "scenes");
    const fs::path dir = work / rel.parent_path();
    fs::create_directories(dir);
    // the scene's folder's meshes, so that relative mesh paths resolve
    if (fs::exists(scene.parent_path() / "meshes") && !fs::exists(dir / "meshes"))
      fs::copy(scene.parent_path() / "meshes", dir / "meshes", fs::copy_options::recursive);
    const std::string text = read_text(scene);
    std::vector<Variant> variants = scene_variants(rel.string(), text);
    std::smatch m;
    if (std::regex_search(text, m, std::regex(R"(\nfile\s*=\s*"([^"]+)\")"))) {
      const auto more = mesh_variants(rel.string(), text, read_text(scene.parent_path() / m[1].str()));
      variants.insert(variants.end(), more.begin(), more.end());
    }
    std::size_t index = 0;
    for (const auto& v : variants) {
      const std::size_t n = total++;
      if (n % stride != 0) continue;
      ++run;
      ++per_scene[rel.string()];
      const fs::path file = dir / (rel.stem().string() + "_v" + std::to_string(index++) + ".toml");
      std::string scene_text = v.scene;
      if (!v.mesh.empty()) {
        const std::string mesh_name = "fuzz_" + std::to_string(n) + ".msh";
        write_text(dir / "meshes" / mesh_name, v.mesh);
        scene_text = std::regex_replace(scene_text, std::regex(R"(\nfile\s*=\s*"[^"]+\")"), "\nfile = \"meshes/" + mesh_name + "\"");
      }
      write_text(file, scene_text);
      current_variant = v.name.c_str();
      const Result r = run_variant(file);
      if (r.outcome == Outcome::loaded) ++loaded;
      if (r.outcome == Outcome::refused) ++refused;
      if (r.outcome == Outcome::bad) bad.push_back(v.name + " (" + file.string() + "): " + r.detail);
      if (verbose)
        std::printf("%-8s %s%s%s\n", r.outcome == Outcome::loaded ? "loaded" : r.outcome == Outcome::refused ? "refused" : "BAD",
                    v.name.c_str(), r.detail.empty() ? "" : "\n         ", r.detail.c_str());
      if (r.outcome != Outcome::bad) fs::remove(file);
    }
  }
  Kokkos::finalize();
  for (const auto& b : bad) std::printf("BAD %s\n", b.c_str());
  std::printf("fuzz_scenes: %zu scenes, %zu variants generated, %zu run: %zu loaded, %zu refused with file:line and key, "
              "%zu other\n",
              scenes.size(), total, run, loaded, refused, bad.size());
  for (const auto& [s, n] : per_scene) std::printf("  %-40s %zu variants\n", s.c_str(), n);
  if (own_work && bad.empty()) fs::remove_all(work);
  return bad.empty() ? 0 : 1;
}
