#include "io/cost.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace polymech::io {

namespace {

std::string bytes_text(double b) {
  const char* units[] = {"B", "KB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (b >= 1000.0 && u < 5) {
    b /= 1000.0;
    ++u;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g %s", b, units[u]);
  return buf;
}

std::string seconds_text(double s) {
  char buf[48];
  if (!std::isfinite(s)) return "unknown";
  if (s < 120.0)
    std::snprintf(buf, sizeof buf, "%.2g s", s);
  else if (s < 7200.0)
    std::snprintf(buf, sizeof buf, "%.3g min", s / 60.0);
  else if (s < 3.0 * 86400.0)
    std::snprintf(buf, sizeof buf, "%.3g h", s / 3600.0);
  else
    std::snprintf(buf, sizeof buf, "%.3g days", s / 86400.0);
  return buf;
}

std::string count_text(double x) {
  char buf[48];
  if (x < 1e7)
    std::snprintf(buf, sizeof buf, "%.0f", x);
  else
    std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

// "512M" -> 512e6; a plain number is bytes.
double parse_size(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  std::string suffix = end ? std::string(end) : std::string();
  double scale = 1.0;
  if (suffix == "K" || suffix == "k") scale = 1e3;
  else if (suffix == "M") scale = 1e6;
  else if (suffix == "G") scale = 1e9;
  else if (suffix == "T") scale = 1e12;
  else if (!suffix.empty()) scale = -1.0;
  if (end == text.c_str() || scale < 0 || !(v > 0) || !std::isfinite(v))
    throw std::invalid_argument("POLYMECH_MEMORY_LIMIT = '" + text +
                                "' is not a memory size; allowed: a number of bytes > 0, optionally with K, M, G or T");
  return v * scale;
}

double meminfo_available() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0.0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  return std::numeric_limits<double>::infinity();
}

// What a process holds before the problem: the binary, the Kokkos and OpenMP runtimes, HDF5 (measured:
// 18 MB resident for the smallest run, pd_tension at draft accuracy).
constexpr double process_bytes = 20e6;

}  // namespace

std::string describe(const CostEstimate& c) {
  std::ostringstream s;
  s << "  " << c.method << ": " << count_text(c.items) << " " << c.item_name;
  if (c.pairs > 0) s << ", " << count_text(c.pairs) << " bonds";
  s << ", " << count_text(c.steps) << " " << c.step_name << "\n";
  s << "  memory about " << bytes_text(c.bytes) << " (available " << bytes_text(available_memory()) << ", "
    << memory_source() << ")\n";
  s << "  predicted wall time about " << seconds_text(c.seconds) << " (" << c.rate << ")\n";
  if (!c.size_keys.empty()) {
    s << "  size set by:";
    for (std::size_t i = 0; i < c.size_keys.size(); ++i) s << (i ? ", " : " ") << c.size_keys[i];
    s << "\n";
  }
  return s.str();
}

double available_memory() {
  if (const char* limit = std::getenv("POLYMECH_MEMORY_LIMIT"); limit && *limit) return parse_size(limit);
  return meminfo_available();
}

std::string memory_source() {
  if (const char* limit = std::getenv("POLYMECH_MEMORY_LIMIT"); limit && *limit) return "POLYMECH_MEMORY_LIMIT";
  return "MemAvailable of /proc/meminfo; POLYMECH_MEMORY_LIMIT overrides";
}

void check_size(const CostEstimate& c, const SceneTable& at) {
  std::string keys;
  for (const auto& k : c.size_keys) keys += (keys.empty() ? "" : ", ") + k;
  if (c.max_items > 0 && !(c.items <= c.max_items))
    at.fail_table("the run would have " + count_text(c.items) + " " + c.item_name + ", more than the " +
                  count_text(c.max_items) + " the model can index; its size is set by " + keys +
                  "; allowed: a coarser spacing or a smaller domain");
  const double available = available_memory();
  if (!(c.bytes <= available))
    at.fail_table("the run needs about " + bytes_text(c.bytes) + " of memory (" + count_text(c.items) + " " + c.item_name +
                  (c.pairs > 0 ? ", " + count_text(c.pairs) + " bonds" : std::string()) + ") but " + bytes_text(available) +
                  " is available (" + memory_source() + "); its size is set by " + keys +
                  "; allowed: a run that fits in the available memory");
}

double lattice_neighbours(int dim, double ratio) {
  const auto m = static_cast<int>(std::floor(ratio));
  const double r2 = ratio * ratio * (1.0 + 1e-9);
  double n = 0.0;
  for (int a = -m; a <= m; ++a)
    for (int b = -m; b <= m; ++b)
      for (int c = (dim == 3 ? -m : 0); c <= (dim == 3 ? m : 0); ++c) {
        const double d2 = static_cast<double>(a * a + b * b + c * c);
        if (d2 > 0 && d2 <= r2) n += 1.0;
      }
  return n;
}

// Rates and bytes from docs/PERFORMANCE.md:
// - MPS: the apps' draft runs (section "Cost estimate against measured time"; MpsStep of "MPS elastic force
//   kernels" gives the float / double ratio), and the "Memory" paragraph (14 reals per particle with
//   rotation, 4 B index + one real per bond, an 8 B offset; the paper-size run measured 7 % above that).
CostEstimate mps_cost(double particles, double influence_radius, bool rotation, bool single, double steps, int runs) {
  CostEstimate c;
  c.method = "MPS elastic (2D)";
  c.item_name = "particles";
  c.items = particles;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  const double per = lattice_neighbours(2, influence_radius);
  c.pairs = particles * per;
  c.steps = steps * runs;
  c.step_name = runs > 1 ? "steps (" + std::to_string(runs) + " runs)" : "steps";
  const double real = single ? 4.0 : 8.0;
  const double reals = 9.0 + (rotation ? 5.0 : 0.0);
  // plus the host copies written to snapshots (about 10 doubles per particle); a draft run of
  // mps_point_source (125 000 particles) holds 71 MB resident
  c.bytes = process_bytes + 1.1 * particles * (reals * real + per * (4.0 + real) + 8.0 + 10.0 * 8.0);
  // one thread: the draft runs of the five MPS scenes (2026-11-27, Intel Xeon) measured 6.2-6.3 M particle-steps/s
  // for the whole app in double; float at MpsStep's float / double ratio (9.10 / 7.46), not measured in an app
  const double rate = single ? 7.6e6 : 6.25e6;
  c.seconds = particles * c.steps / rate;
  c.rate = std::string(single ? "7.6" : "6.25") +
           " M particle-steps/s, docs/PERFORMANCE.md 'Cost estimate against measured time' (the apps' draft runs, 1 thread)";
  c.rate_threads = 1;
  return c;
}

// - PD, one thread, the draft runs of docs/PERFORMANCE.md "Cost estimate against measured time" (2026-11-27):
//   5.2e7 bond-steps/s for the whole app with damage, contact and the velocity viscosity (the penetration
//   scenes: 5.27e7; the full-size penetration run of "Peridynamic bond forces", 103e6 on 2 threads, agrees), 1.0e8
//   for the elastic bond pass alone (the tension plates: 0.86-1.09e8). Memory: per bond a 4 B index, the
//   reference bond vector and influence weight (4 reals) and a damage flag; per particle about 80 reals
//   (positions, velocities, F, K^-1, stresses, plastic state, forces).
CostEstimate pd_cost(double particles, double bonds_per_particle, bool single, double steps, bool elastic_only) {
  CostEstimate c;
  c.method = "NOSB peridynamics";
  c.item_name = "particles";
  c.items = particles;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  c.pairs = particles * bonds_per_particle;
  c.steps = steps;
  c.step_name = "steps";
  const double real = single ? 4.0 : 8.0;
  c.bytes = process_bytes + 1.2 * (particles * 80.0 * real + c.pairs * (5.0 + 4.0 * real));
  const double rate = elastic_only ? 1.0e8 : 5.2e7;
  c.seconds = c.pairs * steps / rate;
  c.rate = std::string(elastic_only ? "1.0e8 bond-steps/s (the elastic bond pass)" : "5.2e7 bond-steps/s (damage, contact, viscosity)") +
           ", docs/PERFORMANCE.md 'Cost estimate against measured time', 1 thread";
  c.rate_threads = 1;
  return c;
}

// - Helmholtz: section "Matrix-free Helmholtz operator": operator storage per DoF and order ("Operator
//   apply throughput per order"), COCG DoF-iterations/s for p = 1 and p = 4 ("COCG"; p = 2, 3 between
//   them) and the iterations to 1e-10, which grow like the DoFs per direction (about 2.5 (p = 1) to
//   4.9 (p = 4) times cbrt(DoFs) in the table there), capped by the solver's limit.
CostEstimate helmholtz_cost(double dofs, double elements, int order, bool single, int max_iterations) {
  CostEstimate c;
  c.method = "Helmholtz FEM (order " + std::to_string(order) + ")";
  c.item_name = "DoFs";
  c.items = dofs;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  const int p = std::clamp(order, 1, 4) - 1;
  const double storage_double[] = {466, 197, 138, 114}, storage_float[] = {249, 105, 74, 61};
  const double rate_double[] = {8.4e6, 11.3e6, 14.2e6, 17.1e6}, rate_float[] = {9.2e6, 15.1e6, 21.0e6, 26.9e6};
  const double real = single ? 4.0 : 8.0;
  // operator storage, 7 complex solver vectors, the mesh (8 node ids and 3 coordinates per element)
  c.bytes = process_bytes + dofs * ((single ? storage_float : storage_double)[p] + 7 * 2 * real) + elements * (8 * 8 + 3 * 8);
  c.steps = std::min(static_cast<double>(max_iterations), (2.5 + 0.8 * p) * std::cbrt(dofs));
  c.step_name = "COCG iterations (estimate)";
  const double rate = (single ? rate_float : rate_double)[p];
  c.seconds = dofs * c.steps / rate;
  char buf[160];
  std::snprintf(buf, sizeof buf, "%.3g M DoF-iterations/s, docs/PERFORMANCE.md 'Matrix-free Helmholtz operator', COCG",
                rate / 1e6);
  c.rate = buf;
  return c;
}

// - DEM, 1 thread: the Chung & Ooi impacts of dem_benchmark (one or two spheres, a host copy per step for the
//   measurement) at 1.5e5 steps/s; pours and beds at 9.5e6 sphere-steps/s up to 1 000 spheres (the draft pours
//   measured 8.5-10.9e6 on 2026-11-27, docs/PERFORMANCE.md "Cost estimate against measured time"), x (spheres /
//   1 000)^-0.35 above. The fall is steeper than the caches alone give (bench_dem's dense block: 5.4-5.8e6 from
//   6.4e4 to 1e6 spheres) because the shipped beds deepen with their size: the coarse wheel bed measured 6.2e6 at
//   draft (6 750 spheres, a bed one grain deep), 3.9e6 at standard (13 500, 8 cm) and 2.1e6 at paper (27 000,
//   15.5 cm; an older run on a loaded machine), more contacts per sphere as the bed deepens. Not below 2.0e6: a
//   bed several grains deep has the bulk's contacts per sphere (the paper-depth coarse bed's 2.1e6).
//   Memory: about 40 reals per sphere.
CostEstimate dem_cost(double spheres, double steps) {
  CostEstimate c;
  c.method = "DEM (Hertz-Mindlin spheres)";
  c.item_name = "spheres";
  c.items = spheres;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  c.steps = steps;
  c.step_name = "steps";
  c.bytes = process_bytes + 1.2 * spheres * 40.0 * 8.0;
  const double rate = std::max(2.0e6, 9.5e6 * std::pow(std::max(1.0, spheres / 1000.0), -0.35));
  c.seconds = steps * std::max(1.0 / 1.5e5, spheres / rate);
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "1.5e5 steps/s (a few spheres) or %.2g sphere-steps/s at this size, docs/PERFORMANCE.md 'Cost estimate "
                "against measured time', 1 thread",
                rate);
  c.rate = buf;
  return c;
}

}  // namespace polymech::io
