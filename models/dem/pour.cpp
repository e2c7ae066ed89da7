#include "dem/pour.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <unordered_map>

namespace polymech::dem {

namespace {

struct Lattice {
  double cell = 0.0;
  int nx = 0, ny = 0;
};

Lattice lattice_of(const PourSpec& s) {
  Lattice l;
  l.cell = 2.2 * s.radius_max;
  l.nx = static_cast<int>(std::floor(s.bin[0] / l.cell));
  l.ny = static_cast<int>(std::floor(s.bin[1] / l.cell));
  if (l.nx < 1 || l.ny < 1)
    throw std::invalid_argument("dem pour: the bin is smaller than one particle (2.2 x radius_max) across");
  return l;
}

}  // namespace

double pour_top(const PourSpec& s) {
  const Lattice l = lattice_of(s);
  const int layers = (s.count + l.nx * l.ny - 1) / (l.nx * l.ny);
  return l.cell * (layers - 0.5) + 0.1 * s.radius_max;
}

Config pour_config(const Config& base, const PourSpec& s) {
  if (s.count <= 0) throw std::invalid_argument("dem pour: count must be > 0");
  if (!(s.radius_min > 0) || s.radius_max < s.radius_min)
    throw std::invalid_argument("dem pour: 0 < radius_min <= radius_max is required");
  if (s.shapes.empty()) throw std::invalid_argument("dem pour: no shapes");
  Config c = base;
  c.spheres.clear();
  c.clumps.clear();
  c.clump_shapes.clear();
  std::vector<int> shape_index;  // -1: a sphere
  for (const auto& name : s.shapes) {
    if (name == "sphere") {
      shape_index.push_back(-1);
      continue;
    }
    const auto& all = gravel_shapes();
    const auto it = std::find_if(all.begin(), all.end(), [&](const ClumpShape& g) { return g.name == name; });
    if (it == all.end()) throw std::invalid_argument("dem pour: unknown shape '" + name + "'");
    int k = -1;
    for (std::size_t j = 0; j < c.clump_shapes.size(); ++j)
      if (c.clump_shapes[j].name == name) k = static_cast<int>(j);
    if (k < 0) {
      k = static_cast<int>(c.clump_shapes.size());
      c.clump_shapes.push_back(*it);
    }
    shape_index.push_back(k);
  }
  const Lattice l = lattice_of(s);
  std::mt19937_64 rng(s.seed);
  std::uniform_real_distribution<double> radius(s.radius_min, s.radius_max), jitter(-0.02, 0.02);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double x0 = 0.5 * (s.bin[0] - l.nx * l.cell), y0 = 0.5 * (s.bin[1] - l.ny * l.cell);
  for (int n = 0; n < s.count; ++n) {
    const int layer = n / (l.nx * l.ny), in = n % (l.nx * l.ny);
    const std::array<double, 3> p = {x0 + (in % l.nx + 0.5 + jitter(rng)) * l.cell,
                                     y0 + (in / l.nx + 0.5 + jitter(rng)) * l.cell, (layer + 0.5) * l.cell + 0.1 * s.radius_max};
    const double r = radius(rng);
    const int k = shape_index[static_cast<std::size_t>(n) % shape_index.size()];
    if (k < 0) {
      SphereInit sp;
      sp.radius = r;
      sp.position = p;
      c.spheres.push_back(sp);
    } else {
      ClumpInit cl;
      cl.shape = k;
      cl.scale = r;
      cl.position = p;
      std::array<double, 4> q = {gauss(rng), gauss(rng), gauss(rng), gauss(rng)};
      const double len = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
      for (auto& x : q) x /= len;
      cl.orientation = q;
      c.clumps.push_back(cl);
    }
  }
  c.planes = box_planes(s.bin[0], s.bin[1]);
  return c;
}

std::vector<PlaneInit> box_planes(double lx, double ly) {
  PlaneInit floor, w0, w1, w2, w3;
  floor.normal = {0, 0, 1};
  w0.normal = {1, 0, 0};
  w1.point = {lx, 0, 0};
  w1.normal = {-1, 0, 0};
  w2.normal = {0, 1, 0};
  w3.point = {0, ly, 0};
  w3.normal = {0, -1, 0};
  return {floor, w0, w1, w2, w3};
}

double packing_fraction(const std::vector<std::array<double, 4>>& spheres, const std::array<double, 3>& lo,
                        const std::array<double, 3>& hi, int samples) {
  if (samples < 2) throw std::invalid_argument("packing_fraction: at least 2 samples per axis");
  for (int k = 0; k < 3; ++k)
    if (!(hi[k] > lo[k])) return 0.0;
  double r_max = 0;
  for (const auto& s : spheres) r_max = std::max(r_max, s[3]);
  if (!(r_max > 0)) return 0.0;
  // bin the spheres by cells of 2 r_max
  const double cell = 2 * r_max;
  auto key = [&](long i, long j, long k) { return (i * 73856093L) ^ (j * 19349663L) ^ (k * 83492791L); };
  std::unordered_multimap<long, std::size_t> bins;
  for (std::size_t n = 0; n < spheres.size(); ++n)
    bins.emplace(key(std::lround(std::floor(spheres[n][0] / cell)), std::lround(std::floor(spheres[n][1] / cell)),
                     std::lround(std::floor(spheres[n][2] / cell))),
                 n);
  long inside = 0, total = 0;
  for (int a = 0; a < samples; ++a)
    for (int b = 0; b < samples; ++b)
      for (int d = 0; d < samples; ++d) {
        const double p[3] = {lo[0] + (a + 0.5) * (hi[0] - lo[0]) / samples, lo[1] + (b + 0.5) * (hi[1] - lo[1]) / samples,
                             lo[2] + (d + 0.5) * (hi[2] - lo[2]) / samples};
        const long ci = std::lround(std::floor(p[0] / cell)), cj = std::lround(std::floor(p[1] / cell)),
                   ck = std::lround(std::floor(p[2] / cell));
        bool hit = false;
        for (long i = ci - 1; i <= ci + 1 && !hit; ++i)
          for (long j = cj - 1; j <= cj + 1 && !hit; ++j)
            for (long k = ck - 1; k <= ck + 1 && !hit; ++k) {
              const auto range = bins.equal_range(key(i, j, k));
              for (auto it = range.first; it != range.second && !hit; ++it) {
                const auto& s = spheres[it->second];
                const double dx = p[0] - s[0], dy = p[1] - s[1], dz = p[2] - s[2];
                hit = dx * dx + dy * dy + dz * dz < s[3] * s[3];
              }
            }
        inside += hit ? 1 : 0;
        ++total;
      }
  return static_cast<double>(inside) / static_cast<double>(total);
}

void bed_box(const std::vector<std::array<double, 4>>& spheres, const PourSpec& spec, std::array<double, 3>& lo,
             std::array<double, 3>& hi) {
  std::vector<double> z;
  for (const auto& s : spheres) z.push_back(s[2]);
  std::sort(z.begin(), z.end());
  const double top = z.empty() ? 0.0 : z[static_cast<std::size_t>(0.9 * static_cast<double>(z.size() - 1))];
  const double m = spec.radius_max;
  lo = {m, m, m};
  hi = {spec.bin[0] - m, spec.bin[1] - m, top - m};
}

double repose_angle(const std::vector<std::array<double, 4>>& spheres, const PourSpec& spec,
                    std::vector<std::array<double, 2>>* profile) {
  const double w = 2 * spec.radius_max;
  double x_max = 0;
  for (const auto& s : spheres) x_max = std::max(x_max, s[0]);
  const int bins = std::max(1, static_cast<int>(std::ceil(x_max / w)));
  std::vector<double> h(static_cast<std::size_t>(bins), 0.0);
  for (const auto& s : spheres) {
    if (s[0] < 0 || s[1] < 0.25 * spec.bin[1] || s[1] > 0.75 * spec.bin[1]) continue;
    const auto b = static_cast<std::size_t>(std::min(bins - 1, static_cast<int>(s[0] / w)));
    h[b] = std::max(h[b], s[2] + s[3]);
  }
  const auto peak = static_cast<int>(std::max_element(h.begin(), h.end()) - h.begin());
  const double top = h[static_cast<std::size_t>(peak)];
  if (profile)
    for (int b = 0; b < bins; ++b) profile->push_back({(b + 0.5) * w, h[static_cast<std::size_t>(b)]});
  // the slope: from the first bin past the peak below 80 % of it to the first below 30 % (the toe); the
  // grains that ran out onto the floor beyond the toe (a layer one clump high, ~20 % of the heap) are not
  // part of it
  int b0 = peak;
  while (b0 < bins && h[static_cast<std::size_t>(b0)] > 0.8 * top) ++b0;
  int b1 = b0;
  while (b1 < bins && h[static_cast<std::size_t>(b1)] >= 0.3 * top) ++b1;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (int b = b0; b < b1; ++b) {
    const double x = (b + 0.5) * w, y = h[static_cast<std::size_t>(b)];
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (n < 3) return std::nan("");
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  return std::atan(-slope) * 180.0 / 3.14159265358979323846;
}

}  // namespace polymech::dem
