// The command line of every app (issue 33): one parse that turns every mistake into one line on stderr,
// "<app>: error: <option> <value>: <what is allowed>", and exit code 2 (--help and --version: exit 0), and
// the checks the options share: numbers in plain ranges, a thread count Kokkos can run, a scene file that
// exists and an output folder that can be written (also for --dry-run, without creating it).
#pragma once

#include <CLI/CLI.hpp>
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace polymech::apps {

// The build the apps come from (apps/common/version.cpp, generated at configure time): the project()
// version of CMakeLists.txt and `git describe --always --dirty`, "unknown" outside a git checkout.
const char* version();
const char* commit();
inline std::string version_line(const std::string& app) {
  return app + " polymech " + version() + " (" + commit() + ")";
}

// --threads at most: Kokkos 3.4's OpenMP back end keeps its thread records in a fixed array of 512
// (OpenMPExec::m_pool) and overruns it, a segmentation fault, for more threads.
inline constexpr int max_threads = 256;

// Cores this process may run on (its CPU affinity), else std::thread::hardware_concurrency().
inline int machine_cores() {
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

namespace cli {

// A value as messages show it: at most about `max` bytes, the middle left out (not inside a UTF-8
// character); quoted when empty.
inline std::string shown(const std::string& v, std::size_t max = 80) {
  if (v.empty()) return "''";
  if (v.size() <= max) return v;
  auto lead = [&](std::size_t n) {  // n moved back to the start of a character
    while (n > 0 && n < v.size() && (static_cast<unsigned char>(v[n]) & 0xC0) == 0x80) --n;
    return n;
  };
  const std::size_t head = lead(max / 2 - 2), tail = lead(v.size() - (max / 2 - 1));
  return v.substr(0, head) + "..." + v.substr(tail);
}

inline std::string plain(long double x) {
  char b[64];
  if (x == std::floor(x) && std::fabs(x) < 1e18L)
    std::snprintf(b, sizeof b, "%.0Lf", x);
  else
    std::snprintf(b, sizeof b, "%.10Lg", x);
  return b;
}

// A whole decimal or floating-point number, nothing else (no hex, inf, nan or spaces).
inline bool read_number(const std::string& s, long double& x) {
  if (s.empty() || s.find_first_of("xXpP \t\n") != std::string::npos) return false;
  char* end = nullptr;
  errno = 0;
  x = std::strtold(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(x);
}

inline std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

// The app's option closest to `given` ("--thread" -> "--threads"), or "" when none is close.
inline std::string closest_option(const CLI::App& app, const std::string& given) {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& l : o->get_lnames()) {
      const std::string name = "--" + l;
      std::size_t d = edit_distance(given, name);
      if (given.size() >= 5 && name.rfind(given, 0) == 0) d = std::min<std::size_t>(d, 1);  // a prefix
      if (d < best_d) best_d = d, best = name;
    }
  }
  return best_d <= std::max<std::size_t>(2, given.size() / 4) ? best : "";
}

// Numbers in [lo, hi] (integer: whole numbers; 1e6 is read as 1000000); lo_open: x > lo.
inline CLI::Validator number_check(const std::string& name, long double lo, long double hi, bool integer, bool lo_open,
                                   long double type_max, std::string note) {
  const bool open_top = hi == HUGE_VALL;
  const std::string kind = integer ? "a whole number" : "a number";
  const std::string range = open_top ? (lo_open ? "> " : ">= ") + plain(lo) : plain(lo) + " to " + plain(hi);
  const std::string allowed = open_top ? kind + " " + range : range;         // "a number > 0", "1 to 256"
  const std::string typed = open_top ? allowed : kind + ", " + range;        // for a value that is no number
  if (!note.empty()) note = " (" + note + ")";
  return CLI::Validator(
      [=](std::string& v) -> std::string {
        long double x = 0;
        const std::string head = name + " " + shown(v) + ": must be ";
        if (!read_number(v, x) || (integer && x != std::floor(x))) return head + typed + note;
        if (x < lo || (lo_open && x == lo) || x > hi) return head + allowed + note;
        if (x > type_max) return head + "at most " + plain(type_max);
        if (integer) v = plain(x);
        return "";
      },
      open_top ? (lo_open ? ">" : ">=") + plain(lo) : plain(lo) + ".." + plain(hi));
}

template <class T>
long double type_max() {
  return static_cast<long double>(std::numeric_limits<T>::max());
}

}  // namespace cli

// Checks on an option's value, with messages like "--threads 0: must be 1 to 256"; `note` is added in
// parentheses. within: lo <= x <= hi; positive: x > 0; non_negative: x >= 0. Integral T: whole numbers.
template <class T>
CLI::Option* within(CLI::Option* o, T lo, T hi, const std::string& note = "") {
  return o->transform(cli::number_check(o->get_name(), lo, hi, std::is_integral_v<T>, false, cli::type_max<T>(), note));
}
template <class T>
CLI::Option* positive(CLI::Option* o, const std::string& note = "") {
  return o->transform(cli::number_check(o->get_name(), 0, HUGE_VALL, std::is_integral_v<T>, true, cli::type_max<T>(), note));
}
template <class T>
CLI::Option* non_negative(CLI::Option* o, const std::string& note = "") {
  return o->transform(cli::number_check(o->get_name(), 0, HUGE_VALL, std::is_integral_v<T>, false, cli::type_max<T>(), note));
}
// One of `names`: "--accuracy bogus: must be draft, standard or paper".
inline CLI::Option* one_of(CLI::Option* o, const std::vector<std::string>& names) {
  std::string allowed;
  for (std::size_t k = 0; k < names.size(); ++k)
    allowed += (k == 0 ? "" : k + 1 == names.size() ? " or " : ", ") + names[k];
  std::string desc;
  for (const auto& n : names) desc += (desc.empty() ? "" : "|") + n;
  const std::string name = o->get_name();
  return o->check(CLI::Validator(
      [=](std::string& v) -> std::string {
        if (std::find(names.begin(), names.end(), v) != names.end()) return "";
        return name + " " + cli::shown(v) + ": must be " + allowed;
      },
      desc));
}

// Why output folder `dir` cannot be used, or "" when it can: an existing folder this process can write
// into, or (unless must_exist) a path whose nearest existing ancestor is one. Probed by creating and
// removing an empty folder in it (root passes permission checks, /proc does not take folders); `dir`
// itself is never created.
inline std::string unusable_folder(const std::filesystem::path& dir, bool must_exist) {
  namespace fs = std::filesystem;
  if (dir.empty()) return "give a folder";
  for (const auto& part : dir)
    if (part.native().size() > 255) return "a name in the path is longer than 255 bytes";
  if (dir.native().size() > 4000) return "the path is longer than 4000 bytes";
  std::error_code ec;
  fs::path at = dir;
  while (true) {  // up to the nearest existing ancestor
    const fs::file_status st = fs::status(at, ec);
    if (st.type() == fs::file_type::not_found) {
      if (must_exist) return "no such folder";
      if (at == "." || at == at.root_path()) return cli::shown(at.string()) + " does not exist";
      at = at.parent_path();
      if (at.empty()) at = ".";
      continue;
    }
    if (ec) return cli::shown(at.string()) + ": " + ec.message();
    if (st.type() != fs::file_type::directory)
      return at == dir ? std::string("exists and is not a folder") : cli::shown(at.string()) + " is not a folder";
    break;
  }
  const std::string where = at == dir ? std::string("") : " in " + cli::shown(at.string());
  if (access(at.c_str(), W_OK | X_OK) != 0)
    return (at == dir ? std::string("cannot write into it") : "cannot create a folder" + where) + " (" + std::strerror(errno) + ")";
  std::string probe = (at / ".polymech-probe-XXXXXX").string();
  if (mkdtemp(probe.data()) == nullptr)
    return (at == dir ? std::string("cannot write into it") : "cannot create a folder" + where) + " (" + std::strerror(errno) + ")";
  fs::remove(probe, ec);
  return "";
}

namespace cli {

// The one-line text of a CLI11 parse error.
inline std::string describe(const CLI::App& app, const CLI::ParseError& e) {
  const std::string what = e.what();
  const auto colon = what.find(": ");
  const std::string head = colon == std::string::npos ? std::string() : what.substr(0, colon);
  const std::string rest = colon == std::string::npos ? what : what.substr(colon + 2);
  if (dynamic_cast<const CLI::ExtrasError*>(&e) != nullptr) {
    const auto left = app.remaining();
    std::string extra = left.empty() ? std::string() : left.front();
    for (const auto& a : left)
      if (a.size() > 1 && a[0] == '-' && a != "--") {
        extra = a;
        break;
      }
    if (extra.size() < 2 || extra[0] != '-' || extra == "--")
      return "unexpected argument " + shown(extra) + " (every input is an option; " + app.get_name() + " --help lists them)";
    const std::string name = extra.substr(0, extra.find('='));
    const std::string near = closest_option(app, name);
    return shown(name) + ": unknown option" +
           (near.empty() ? " (" + app.get_name() + " --help lists the options)" : "; did you mean " + near + "?");
  }
  if (dynamic_cast<const CLI::ValidationError*>(&e) != nullptr)
    return rest.rfind(head + " ", 0) == 0 ? rest : head + " " + rest;  // our checks name the option
  const bool mismatch = dynamic_cast<const CLI::ArgumentMismatch*>(&e) != nullptr;
  if (mismatch && rest.find("missing") != std::string::npos) return head + ": needs a value";
  if (mismatch && rest.find("At Most") != std::string::npos) return head + ": given more than once";
  if (dynamic_cast<const CLI::ConversionError*>(&e) != nullptr) {  // "Could not convert: --flag = value"
    const auto eq = what.find(" = ");
    const std::string pre = "Could not convert: ";
    if (what.rfind(pre, 0) == 0 && eq != std::string::npos)
      return what.substr(pre.size(), eq - pre.size()) + " " + shown(what.substr(eq + 3)) + ": not a valid value";
  }
  return what.substr(0, what.find('\n'));
}

inline std::optional<long long> integer_from(const char* s) {
  if (s == nullptr || *s == '\0') return std::nullopt;
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(s, &end, 10);
  if (errno != 0 || end == s) return std::nullopt;
  return v;
}

}  // namespace cli

// Parses the command line of app `name`; returns the exit code when the app must stop here (--help,
// --version: 0, printed on stdout; any mistake: 2, one line "<name>: error: ..." on stderr, nothing
// written), nullopt to run. Besides CLI11's parse it checks what involves the machine or the file
// system: --threads against the cores (more: a warning unless --quiet) and OMP_NUM_THREADS, that --scene
// is a file and that the output folder (--out, or --restart's) can be written. Run by the polymech app, it
// then prints that app's notice (POLYMECH_DISPATCH_NOTICE) on stderr.
// The command line as typed, recorded by parse_command_line (summary "command" of every app).
inline std::string& invocation() {
  static std::string command;
  return command;
}
inline std::string command_line(int argc, const char* const* argv) {
  std::string command;
  for (int k = 0; k < argc; ++k) command += (k ? " " : "") + std::string(argv[k]);
  return command;
}

inline std::optional<int> parse_command_line(CLI::App& app, const std::string& name, int argc, const char* const* argv) {
  invocation() = command_line(argc, argv);
  if (app.get_option_no_throw("--version") == nullptr)
    app.set_version_flag("--version", version_line(name), "print the app, the polymech version and git commit, and exit");
  app.name(name);
  auto fail = [&](std::string m) {
    if (m.size() > 280) m = cli::shown(m, 280);  // a long CLI11 text
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), m.c_str());
    return 2;
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return fail(cli::describe(app, e));
  }
  auto given = [&](const char* opt) -> const CLI::Option* {
    const CLI::Option* o = app.get_option_no_throw(opt);
    return o != nullptr && o->count() > 0 ? o : nullptr;
  };
  const int cores = machine_cores();
  const std::string machine = "this machine has " + std::to_string(cores) + (cores == 1 ? " core" : " cores");
  if (const CLI::Option* t = given("--threads")) {
    const int n = t->as<int>();
    const CLI::Option* q = given("--quiet");
    if (n > cores && q == nullptr)
      std::fprintf(stderr, "%s: warning: --threads %d is more than the %d cores of this machine; the run will be slower\n",
                   name.c_str(), n, cores);
  } else if (app.get_option_no_throw("--threads") != nullptr) {
    const char* env = std::getenv("OMP_NUM_THREADS");  // the default thread count (first of a list)
    const auto n = cli::integer_from(env);
    if (n && (*n < 1 || *n > max_threads))
      return fail("OMP_NUM_THREADS=" + cli::shown(env) + ": must be 1 to " + std::to_string(max_threads) + " (" + machine +
                  "; --threads N overrides it)");
  }
  if (const CLI::Option* s = given("--scene")) {
    const std::string file = s->as<std::string>();
    std::error_code ec;
    const auto st = std::filesystem::status(file, ec);
    if (st.type() == std::filesystem::file_type::directory)
      return fail("--scene " + cli::shown(file) + ": is a folder, not a scene file");
    if (!std::filesystem::exists(st))
      return fail("--scene " + cli::shown(file) + ": scene file not found (give an existing .toml file; scenes/ has one folder per model)");
  }
  if (const CLI::Option* r = given("--restart")) {
    const std::string dir = r->as<std::string>();
    const std::string why = unusable_folder(dir, true);
    if (!why.empty()) return fail("--restart " + cli::shown(dir) + ": " + why + " (give the output folder of an interrupted run)");
  } else if (const CLI::Option* o = app.get_option_no_throw("--out")) {
    const std::string dir = o->count() > 0 ? o->as<std::string>() : o->get_default_str();
    const std::string why = unusable_folder(dir, false);
    if (!why.empty()) return fail("--out " + cli::shown(dir) + ": " + why);
  }
  if (const char* notice = std::getenv("POLYMECH_DISPATCH_NOTICE")) {  // run by the polymech app
    std::fprintf(stderr, "%s\n", notice);
    unsetenv("POLYMECH_DISPATCH_NOTICE");
  }
  return std::nullopt;
}

}  // namespace polymech::apps
