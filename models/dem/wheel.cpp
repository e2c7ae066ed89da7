#include "dem/wheel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <utility>

#include "dem/config.hpp"

namespace polymech::dem {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

double ramp(double t, double from, double to) {
  if (t <= from) return 0.0;
  if (t >= to) return 1.0;
  return (t - from) / (to - from);
}

}  // namespace

double WheelSpec::load_at(double t) const { return load * ramp(t, load_from, load_to); }
double WheelSpec::speed_at(double t) const { return speed * ramp(t, speed_from, speed_to); }
double WheelSpec::spin_at(double t) const { return speed_at(t) / ((1.0 - slip) * radius); }

std::string WheelSpec::damping_problem(double step) const {
  if (!(damping > 0) || !(step > 0) || damping * step < mass) return {};
  char text[320];
  std::snprintf(text, sizeof text,
                "= %.6g N s/m is too strong for the explicit damper: with the rim's mass %.6g kg and its step %.6g s, "
                "damping x dt / mass = %.3g, which must stay below 1 (damping < %.6g N s/m)",
                damping, mass, step, damping * step / mass, mass / step);
  return text;
}

SurfaceInit wheel_surface(const WheelSpec& w) {
  if (!(w.radius > 0) || !(w.width > 0)) throw std::invalid_argument("wheel: radius and width must be > 0");
  if (w.around < 8 || w.across < 1) throw std::invalid_argument("wheel: at least 8 facets around and 1 across");
  if (w.side_depth < 0 || w.side_depth >= w.radius) throw std::invalid_argument("wheel: side_depth must be in [0, radius)");
  SurfaceInit s;
  auto node = [&s](double x, double y, double z) {
    s.nodes.insert(s.nodes.end(), {x, y, z});
    return static_cast<std::int64_t>(s.nodes.size() / 3 - 1);
  };
  auto quad = [&s](std::int64_t a, std::int64_t b, std::int64_t c, std::int64_t d) {
    s.facet_sizes.push_back(4);
    s.facet_nodes.insert(s.facet_nodes.end(), {a, b, c, d});
  };
  const int na = w.around, nw = w.across;
  // the tread: node (k, j) at angle theta_k about y, y_j across; x = R sin theta, z = -R cos theta
  // (theta = 0 at the bottom). Outward normal (sin, 0, -cos): order (k, j), (k, j+1), (k+1, j+1), (k+1, j).
  const int rings = w.side_depth > 0 ? std::max(1, static_cast<int>(std::lround(w.side_depth / (kTwoPi * w.radius / na)))) : 0;
  std::vector<std::int64_t> id((static_cast<std::size_t>(nw) + 1) * na);
  for (int j = 0; j <= nw; ++j)
    for (int k = 0; k < na; ++k) {
      const double th = kTwoPi * k / na, y = -0.5 * w.width + w.width * j / nw;
      id[static_cast<std::size_t>(j) * na + k] = node(w.radius * std::sin(th), y, -w.radius * std::cos(th));
    }
  auto at = [&](int j, int k) { return id[static_cast<std::size_t>(j) * na + (k % na)]; };
  for (int j = 0; j < nw; ++j)
    for (int k = 0; k < na; ++k) quad(at(j, k), at(j + 1, k), at(j + 1, k + 1), at(j, k + 1));
  // the sides: rings from R (the tread's edge nodes) inwards; the side y = +w/2 faces +y, y = -w/2 faces -y
  for (int side = 0; side < 2; ++side) {
    const int j = side == 0 ? 0 : nw;
    const double y = side == 0 ? -0.5 * w.width : 0.5 * w.width;
    std::vector<std::int64_t> outer(static_cast<std::size_t>(na)), inner(static_cast<std::size_t>(na));
    for (int k = 0; k < na; ++k) outer[static_cast<std::size_t>(k)] = at(j, k);
    for (int r = 1; r <= rings; ++r) {
      const double rad = w.radius - w.side_depth * r / rings;
      for (int k = 0; k < na; ++k) {
        const double th = kTwoPi * k / na;
        inner[static_cast<std::size_t>(k)] = node(rad * std::sin(th), y, -rad * std::cos(th));
      }
      for (int k = 0; k < na; ++k) {
        const auto o0 = outer[static_cast<std::size_t>(k)], o1 = outer[static_cast<std::size_t>((k + 1) % na)];
        const auto i0 = inner[static_cast<std::size_t>(k)], i1 = inner[static_cast<std::size_t>((k + 1) % na)];
        // (o1 - o0) x (i0 - o0) points along -y for the increasing angle: the -y side takes that order
        if (side == 0)
          quad(o0, o1, i1, i0);
        else
          quad(o0, i0, i1, o1);
      }
      outer = inner;
    }
  }
  return s;
}

BedLevel bed_level(const std::vector<std::array<double, 4>>& spheres, const WheelSpec& w, double r_max) {
  BedLevel out;
  std::map<std::pair<long, long>, double> top;
  const double cell = 2 * r_max;
  for (const auto& s : spheres) {
    if (std::abs(s[0] - w.x_start) >= 0.5 * w.radius || std::abs(s[1] - w.y_centre) >= 0.5 * w.width) continue;
    const auto key = std::make_pair(std::lround(std::floor(s[0] / cell)), std::lround(std::floor(s[1] / cell)));
    const double h = s[2] + s[3];
    auto it = top.find(key);
    if (it == top.end())
      top.emplace(key, h);
    else
      it->second = std::max(it->second, h);
  }
  for (const auto& s : spheres) {  // the height of the wheel's lowest point when it first touches a sphere
    const double dx = s[0] - w.x_start, reach = w.radius + s[3];
    if (std::abs(dx) >= reach || std::abs(s[1] - w.y_centre) >= 0.5 * w.width) continue;
    out.highest = std::max(out.highest, s[2] + std::sqrt(reach * reach - dx * dx) - w.radius);
  }
  for (const auto& [k, h] : top) out.mean += h;
  if (!top.empty()) out.mean /= static_cast<double>(top.size());
  return out;
}

}  // namespace polymech::dem
