#include "efg/setup.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fem/gauss_legendre.hpp"

namespace polymech::efg {

namespace {

constexpr double pi = 3.14159265358979323846;

// A small deterministic generator for the jitter (splitmix64).
double uniform(std::uint64_t& s) {
  s += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = s;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 9007199254740992.0;
}

}  // namespace

std::vector<double> graded_line(double lo, double hi, const std::vector<double>& foci, double h_min, double h_max,
                                double growth) {
  if (!(hi > lo) || !(h_min > 0) || !(h_max >= h_min)) throw std::invalid_argument("graded_line: bad interval or spacing");
  std::vector<double> breaks{lo};
  std::vector<double> inside;
  for (double f : foci)
    if (f > lo && f < hi) inside.push_back(f);
  std::sort(inside.begin(), inside.end());
  for (double f : inside) breaks.push_back(f);
  breaks.push_back(hi);
  auto spacing = [&](double s) {
    if (foci.empty()) return h_max;
    double d = 1e300;
    for (double f : foci) d = std::min(d, std::abs(s - f));
    return std::min(h_max, h_min + growth * d);
  };
  std::vector<double> out{lo};
  constexpr int samples = 4000;
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    const double p = breaks[b], q = breaks[b + 1];
    std::vector<double> cum(samples + 1, 0.0);
    const double ds = (q - p) / samples;
    for (int k = 0; k < samples; ++k) cum[static_cast<std::size_t>(k) + 1] = cum[static_cast<std::size_t>(k)] + ds / spacing(p + (k + 0.5) * ds);
    const double total = cum.back();
    const int n = std::max(1, static_cast<int>(std::lround(total)));
    std::size_t k = 0;
    for (int m = 1; m < n; ++m) {
      const double target = total * m / n;
      while (k + 1 < cum.size() && cum[k + 1] < target) ++k;
      const double f = (target - cum[k]) / (cum[k + 1] - cum[k]);
      out.push_back(p + (static_cast<double>(k) + f) * ds);
    }
    out.push_back(q);
  }
  return out;
}

double graded_line_intervals(double lo, double hi, const std::vector<double>& foci, double h_min, double h_max, double growth) {
  if (!(hi > lo) || !(h_min > 0) || !(h_max >= h_min)) return 0.0;
  constexpr int samples = 4000;
  const double ds = (hi - lo) / samples;
  double total = 0.0;
  for (int k = 0; k < samples; ++k) {
    const double s = lo + (k + 0.5) * ds;
    double h = h_max;
    if (!foci.empty()) {
      double d = 1e300;
      for (double f : foci) d = std::min(d, std::abs(s - f));
      h = std::min(h_max, h_min + growth * d);
    }
    total += ds / h;
  }
  return total + static_cast<double>(foci.size()) + 1.0;
}

void estimate_lines(const Config& c, double& nx, double& ny) {
  const double a = c.crack_length;
  const double f = a + c.tip_offset * c.h_min;
  if (c.crack == CrackKind::centre)
    nx = graded_line_intervals(-0.5 * c.width, 0.5 * c.width, {-f, f}, c.h_min, c.h_max, c.growth) + 1;
  else if (c.crack == CrackKind::edge)
    nx = graded_line_intervals(0.0, c.width, {f}, c.h_min, c.h_max, c.growth) + 1;
  else
    nx = graded_line_intervals(0.0, c.width, {}, c.h_max, c.h_max, c.growth) + 1;
  ny = graded_line_intervals(-0.5 * c.height, 0.5 * c.height,
                             c.crack == CrackKind::none ? std::vector<double>{} : std::vector<double>{0.0},
                             c.crack == CrackKind::none ? c.h_max : c.h_min, c.h_max, c.growth) + 1;
}

// On a tensor grid of lines the points of a square of half-width r around a point count separably, (lines
// within r in x) x (lines within r in y); a disc of radius r holds about pi / 4 of the square.
SearchSize search_size(const Config& c, const std::vector<double>& xs, const std::vector<double>& ys) {
  double widest = 0.0;
  for (const auto* v : {&xs, &ys})
    for (std::size_t i = 0; i + 1 < v->size(); ++i) widest = std::max(widest, (*v)[i + 1] - (*v)[i]);
  const double R = c.support_factor * widest;
  // sum over the positions p of the lines within r of p
  const auto within = [](const std::vector<double>& lines, const std::vector<double>& at, double r) {
    double sum = 0.0;
    for (double p : at) {
      const auto lo = std::lower_bound(lines.begin(), lines.end(), p - r);
      const auto hi = std::upper_bound(lines.begin(), lines.end(), p + r);
      sum += static_cast<double>(hi - lo);
    }
    return sum;
  };
  const auto centres = [](const std::vector<double>& v) {
    std::vector<double> m;
    for (std::size_t i = 0; i + 1 < v.size(); ++i) m.push_back(0.5 * (v[i] + v[i + 1]));
    return m;
  };
  constexpr double disc = 0.785398163397448;  // pi / 4
  const double g2 = static_cast<double>(c.gauss) * static_cast<double>(c.gauss);
  SearchSize s;
  s.candidates = disc * g2 * within(xs, centres(xs), R) * within(ys, centres(ys), R);
  s.pattern = disc * within(xs, xs, 2.0 * R) * within(ys, ys, 2.0 * R);
  return s;
}

void node_lines(const Config& c, std::vector<double>& xs, std::vector<double>& ys) {
  const double a = c.crack_length;
  const double f = a + c.tip_offset * c.h_min;
  if (c.crack == CrackKind::centre) {
    xs = graded_line(-0.5 * c.width, 0.5 * c.width, {-f, f}, c.h_min, c.h_max, c.growth);
  } else if (c.crack == CrackKind::edge) {
    xs = graded_line(0.0, c.width, {f}, c.h_min, c.h_max, c.growth);
  } else {
    xs = graded_line(0.0, c.width, {}, c.h_max, c.h_max, c.growth);
  }
  ys = graded_line(-0.5 * c.height, 0.5 * c.height, c.crack == CrackKind::none ? std::vector<double>{} : std::vector<double>{0.0},
                   c.crack == CrackKind::none ? c.h_max : c.h_min, c.h_max, c.growth);
}

namespace {
double smallest_interval(const std::vector<double>& xs, const std::vector<double>& ys) {
  double h = 1e300;
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) h = std::min(h, xs[i + 1] - xs[i]);
  for (std::size_t j = 0; j + 1 < ys.size(); ++j) h = std::min(h, ys[j + 1] - ys[j]);
  return h;
}
// The nodes make_layout puts where the node lines x and y = 0 cross: none on the path of a growing crack
// (a node there would be seen from both faces once the crack has passed it) unless Config::path_nodes
// (then one, split by the model when the tip passes it), two on the crack (one on each face), one
// elsewhere.
int crack_line_nodes(const Config& c, double hmin_all, double x) {
  const double a = c.crack_length;
  const bool growing = c.growth_speed > 0 && c.final_crack_length > a;
  const double ax = c.crack == CrackKind::centre ? std::abs(x) : x;
  if (c.crack == CrackKind::none) return 1;
  if (growing && ax > a - 1e-9 * hmin_all && ax < c.final_crack_length - 1e-9 * hmin_all) return c.path_nodes ? 1 : 0;
  if (c.crack == CrackKind::edge && x < a - 1e-9 * hmin_all) return 2;
  if (c.crack == CrackKind::centre && std::abs(x) < a - 1e-9 * hmin_all) return 2;
  return 1;
}
}  // namespace

std::size_t count_nodes(const Config& c) {
  std::vector<double> xs, ys;
  node_lines(c, xs, ys);
  const double hmin_all = smallest_interval(xs, ys);
  std::size_t n = 0;
  for (double y : ys)
    if (c.crack != CrackKind::none && y == 0.0)
      for (double x : xs) n += static_cast<std::size_t>(crack_line_nodes(c, hmin_all, x));
    else
      n += xs.size();
  return n;
}

Layout make_layout(const Config& c) {
  Layout L;
  node_lines(c, L.xs, L.ys);
  const auto& xs = L.xs;
  const auto& ys = L.ys;
  const std::size_t nx = xs.size(), ny = ys.size();
  const double a = c.crack_length;
  const double hmin_all = smallest_interval(xs, ys);
  const double eps = 1e-7 * hmin_all;  // crack-face nodes sit this far off the face, on their side
  L.face_offset = eps;
  auto local = [](const std::vector<double>& v, std::size_t i) {
    double h = 0.0;
    if (i > 0) h = std::max(h, v[i] - v[i - 1]);
    if (i + 1 < v.size()) h = std::max(h, v[i + 1] - v[i]);
    return h;
  };
  std::uint64_t rng = c.seed;
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double hx = local(xs, i), hy = local(ys, j);
      const double d = c.support_factor * std::max(hx, hy);
      double x = xs[i], y = ys[j];
      const bool crack_line = c.crack != CrackKind::none && y == 0.0;
      const int here = crack_line ? crack_line_nodes(c, hmin_all, x) : 1;
      if (here == 0) continue;
      if (here == 2) {
        L.nodes.insert(L.nodes.end(), {x, -eps, x, eps});
        L.dm.insert(L.dm.end(), {d, d});
        continue;
      }
      const bool interior = i > 0 && i + 1 < nx && j > 0 && j + 1 < ny && !crack_line;
      if (interior && c.jitter > 0) {
        const double h = std::min({xs[i] - xs[i - 1], xs[i + 1] - xs[i], ys[j] - ys[j - 1], ys[j + 1] - ys[j]});
        x += c.jitter * h * (2.0 * uniform(rng) - 1.0);
        y += c.jitter * h * (2.0 * uniform(rng) - 1.0);
        // keep off the crack line
        if (c.crack != CrackKind::none && std::abs(y) < 0.05 * h) y = ys[j];
      }
      L.nodes.insert(L.nodes.end(), {x, y});
      L.dm.push_back(d);
    }
  if (c.crack == CrackKind::edge) {
    L.crack = {0.0 - 1e-3 * hmin_all, 0.0, a, 0.0};
    L.tip_x = a;
  } else if (c.crack == CrackKind::centre) {
    L.crack = {-a, 0.0, a, 0.0};
    L.tip_x = a;
  }
  // the background cells' c.gauss x c.gauss points and the boundary points, ascending in each direction
  if (c.gauss < 1) throw std::invalid_argument("efg: gauss must be >= 1");
  std::vector<double> gx, gw;
  fem::gauss_legendre(c.gauss, gx, gw);
  const std::size_t g = gx.size();
  L.quad.reserve((nx - 1) * (ny - 1) * g * g * 3);
  for (std::size_t j = 0; j + 1 < ny; ++j)
    for (std::size_t i = 0; i + 1 < nx; ++i) {
      const double hx = xs[i + 1] - xs[i], hy = ys[j + 1] - ys[j];
      for (std::size_t q = 0; q < g; ++q)
        for (std::size_t p = 0; p < g; ++p)
          L.quad.insert(L.quad.end(), {xs[i] + 0.5 * hx * (1 + gx[p]), ys[j] + 0.5 * hy * (1 + gx[q]), 0.25 * hx * hy * gw[p] * gw[q]});
    }
  // boundary Gauss points of an edge along the node lines v at fixed coordinate `at`
  auto edge_points = [&](const std::vector<double>& v, bool along_x, double at, auto&& emit) {
    for (std::size_t i = 0; i + 1 < v.size(); ++i) {
      const double h = v[i + 1] - v[i];
      for (std::size_t p = 0; p < g; ++p) {
        const double s = v[i] + 0.5 * h * (1 + gx[p]);
        emit(along_x ? s : at, along_x ? at : s, 0.5 * h * gw[p]);
      }
    }
  };
  const double x0 = xs.front(), x1 = xs.back(), y0 = ys.front(), y1 = ys.back();
  const double k = c.penalty * c.young;
  if (c.loading == Loading::tension) {
    edge_points(xs, true, y1, [&](double x, double y, double w) { L.traction.insert(L.traction.end(), {x, y, w, 0.0, c.stress}); });
    edge_points(xs, true, y0, [&](double x, double y, double w) { L.traction.insert(L.traction.end(), {x, y, w, 0.0, -c.stress}); });
    if (c.crack == CrackKind::centre || c.crack == CrackKind::none) {
      const double xm = c.crack == CrackKind::centre ? 0.0 : 0.5 * (x0 + x1);
      const double ym = c.crack == CrackKind::centre ? 0.0 : 0.5 * (y0 + y1);
      // u_x = 0 on the vertical symmetry line, u_y = 0 on the horizontal one
      L.penalty.insert(L.penalty.end(), {xm, y0, k, 0.0, 0.0, xm, y1, k, 0.0, 0.0, x0, ym, k, 1.0, 0.0, x1, ym, k, 1.0, 0.0});
    } else {
      // edge crack: u_y = 0 on the ligament (symmetry), u_x held at its far end (translation)
      const double xl = 0.5 * (a + x1);
      L.penalty.insert(L.penalty.end(), {x1, 0.0, k, 1.0, 0.0, xl, 0.0, k, 1.0, 0.0, x1, 0.0, k, 0.0, 0.0});
    }
  } else {
    auto imposed = [&](double x, double y, double w) {
      const auto& p = c.patch;
      L.penalty.insert(L.penalty.end(), {x, y, k * w, 0.0, p[0] + p[1] * x + p[2] * y});
      L.penalty.insert(L.penalty.end(), {x, y, k * w, 1.0, p[3] + p[4] * x + p[5] * y});
    };
    edge_points(xs, true, y0, imposed);
    edge_points(xs, true, y1, imposed);
    edge_points(ys, false, x0, imposed);
    edge_points(ys, false, x1, imposed);
  }
  return L;
}

double handbook_factor(const Config& c) {
  if (c.crack == CrackKind::edge) {
    const double s = c.crack_length / c.width;
    return 1.12 - 0.231 * s + 10.55 * s * s - 21.72 * s * s * s + 30.39 * s * s * s * s;
  }
  if (c.crack == CrackKind::centre) {
    const double s = c.crack_length / (0.5 * c.width);
    return (1 - 0.025 * s * s + 0.06 * s * s * s * s) * std::sqrt(1.0 / std::cos(pi * s / 2));
  }
  return 0.0;
}

double j_band_width(const Config& c, double r) {
  if (!(c.j_band > 0)) return 0.0;
  return c.j_band * std::min(c.h_max, c.h_min + c.growth * r);
}

double effective_modulus(const Config& c) {
  return c.plane_strain ? c.young / (1 - c.poisson * c.poisson) : c.young;
}

}  // namespace polymech::efg
