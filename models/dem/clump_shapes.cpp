#include "dem/clump_shapes.hpp"

#include "dem/setup.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace polymech::dem {

UnionMassProperties union_mass_properties(const ClumpShape& shape, int columns) {
  if (shape.spheres.empty()) throw std::invalid_argument("clump shape '" + shape.name + "' has no spheres");
  if (columns < 4) throw std::invalid_argument("union_mass_properties: at least 4 columns");
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = shape.spheres[0][k] - shape.spheres[0][3];
    hi[k] = shape.spheres[0][k] + shape.spheres[0][3];
  }
  for (const auto& s : shape.spheres) {
    if (!(s[3] > 0)) throw std::invalid_argument("clump shape '" + shape.name + "': a sphere radius must be > 0");
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], s[k] - s[3]);
      hi[k] = std::max(hi[k], s[k] + s[3]);
    }
  }
  const double h = std::max(hi[0] - lo[0], hi[1] - lo[1]) / columns;
  const int nx = static_cast<int>(std::ceil((hi[0] - lo[0]) / h)), ny = static_cast<int>(std::ceil((hi[1] - lo[1]) / h));
  // moments: 1, x, y, z, xx, yy, zz, xy, xz, yz
  double m[10] = {};
  std::vector<std::pair<double, double>> chords;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = lo[0] + (i + 0.5) * h, y = lo[1] + (j + 0.5) * h;
      chords.clear();
      for (const auto& s : shape.spheres) {
        const double rho2 = (x - s[0]) * (x - s[0]) + (y - s[1]) * (y - s[1]);
        if (rho2 >= s[3] * s[3]) continue;
        const double half = std::sqrt(s[3] * s[3] - rho2);
        chords.emplace_back(s[2] - half, s[2] + half);
      }
      if (chords.empty()) continue;
      std::sort(chords.begin(), chords.end());
      double z0 = 0, z1 = 0, z2 = 0;  // integrals of 1, z, z^2 over the union of the chords
      double a = chords[0].first, b = chords[0].second;
      auto close = [&] {
        z0 += b - a;
        z1 += 0.5 * (b * b - a * a);
        z2 += (b * b * b - a * a * a) / 3.0;
      };
      for (std::size_t c = 1; c < chords.size(); ++c) {
        if (chords[c].first > b) {
          close();
          a = chords[c].first;
          b = chords[c].second;
        } else {
          b = std::max(b, chords[c].second);
        }
      }
      close();
      const double w = h * h;
      m[0] += w * z0;
      m[1] += w * x * z0;
      m[2] += w * y * z0;
      m[3] += w * z1;
      m[4] += w * x * x * z0;
      m[5] += w * y * y * z0;
      m[6] += w * z2;
      m[7] += w * x * y * z0;
      m[8] += w * x * z1;
      m[9] += w * y * z1;
    }
  UnionMassProperties p;
  p.volume = m[0];
  for (int k = 0; k < 3; ++k) p.centre[k] = m[1 + k] / m[0];
  const auto& c = p.centre;
  // second moments about the centre
  const double xx = m[4] - m[0] * c[0] * c[0], yy = m[5] - m[0] * c[1] * c[1], zz = m[6] - m[0] * c[2] * c[2];
  const double xy = m[7] - m[0] * c[0] * c[1], xz = m[8] - m[0] * c[0] * c[2], yz = m[9] - m[0] * c[1] * c[2];
  p.inertia = {{{yy + zz, -xy, -xz}, {-xy, xx + zz, -yz}, {-xz, -yz, xx + yy}}};
  symmetric_eigen(p.inertia, p.principal, p.axes);
  return p;
}

void symmetric_eigen(const std::array<std::array<double, 3>, 3>& a_in, std::array<double, 3>& values,
                     std::array<std::array<double, 3>, 3>& v) {
  auto a = a_in;
  v = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = std::abs(a[0][1]) + std::abs(a[0][2]) + std::abs(a[1][2]);
    const double scale = std::abs(a[0][0]) + std::abs(a[1][1]) + std::abs(a[2][2]);
    if (off <= 1e-15 * scale || off == 0.0) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double cs = 1.0 / std::sqrt(t * t + 1.0), sn = t * cs;
        for (int k = 0; k < 3; ++k) {  // a <- a J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = cs * akp - sn * akq;
          a[k][q] = sn * akp + cs * akq;
        }
        for (int k = 0; k < 3; ++k) {  // a <- J^T a
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = cs * apk - sn * aqk;
          a[q][k] = sn * apk + cs * aqk;
        }
        for (int k = 0; k < 3; ++k) {  // v <- v J
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = cs * vkp - sn * vkq;
          v[k][q] = sn * vkp + cs * vkq;
        }
      }
  }
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return a[i][i] < a[j][j]; });
  std::array<std::array<double, 3>, 3> sorted{};
  for (int c = 0; c < 3; ++c) {
    values[c] = a[order[c]][order[c]];
    for (int k = 0; k < 3; ++k) sorted[k][c] = v[k][order[c]];
  }
  // right-handed: third column = first x second
  const auto& s = sorted;
  const double cross[3] = {s[1][0] * s[2][1] - s[2][0] * s[1][1], s[2][0] * s[0][1] - s[0][0] * s[2][1],
                           s[0][0] * s[1][1] - s[1][0] * s[0][1]};
  const double dot = cross[0] * s[0][2] + cross[1] * s[1][2] + cross[2] * s[2][2];
  if (dot < 0)
    for (int k = 0; k < 3; ++k) sorted[k][2] = -sorted[k][2];
  v = sorted;
}

std::array<double, 4> quaternion_of(const std::array<std::array<double, 3>, 3>& r) {
  std::array<double, 4> q{};
  const double tr = r[0][0] + r[1][1] + r[2][2];
  if (tr > 0) {
    const double s = 2.0 * std::sqrt(tr + 1.0);
    q = {0.25 * s, (r[2][1] - r[1][2]) / s, (r[0][2] - r[2][0]) / s, (r[1][0] - r[0][1]) / s};
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]);
    q = {(r[2][1] - r[1][2]) / s, 0.25 * s, (r[0][1] + r[1][0]) / s, (r[0][2] + r[2][0]) / s};
  } else if (r[1][1] > r[2][2]) {
    const double s = 2.0 * std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]);
    q = {(r[0][2] - r[2][0]) / s, (r[0][1] + r[1][0]) / s, 0.25 * s, (r[1][2] + r[2][1]) / s};
  } else {
    const double s = 2.0 * std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]);
    q = {(r[1][0] - r[0][1]) / s, (r[0][2] + r[2][0]) / s, (r[1][2] + r[2][1]) / s, 0.25 * s};
  }
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  for (auto& x : q) x /= n;
  return q;
}

std::array<double, 4> quaternion_product(const std::array<double, 4>& a, const std::array<double, 4>& b) {
  return {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3], a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
          a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1], a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
}

namespace {
// Moves a shape's centre of mass to the origin and scales it to a unit bounding radius.
ClumpShape normalised(ClumpShape s) {
  const auto p = union_mass_properties(s, 100);
  double reach = 0;
  for (auto& sp : s.spheres) {
    for (int k = 0; k < 3; ++k) sp[k] -= p.centre[k];
    reach = std::max(reach, std::sqrt(sp[0] * sp[0] + sp[1] * sp[1] + sp[2] * sp[2]) + sp[3]);
  }
  for (auto& sp : s.spheres)
    for (auto& x : sp) x /= reach;
  return s;
}
}  // namespace

const std::vector<ClumpShape>& gravel_shapes() {
  static const std::vector<ClumpShape> shapes = [] {
    ClumpShape cylinder{"cylinder", {{0, 0, -1, 1}, {0, 0, 0, 1}, {0, 0, 1, 1}}};
    ClumpShape cone{"cone", {{0, 0, 0, 1}, {0, 0, 0.8, 0.8}, {0, 0, 1.45, 0.6}, {0, 0, 1.95, 0.4}}};
    ClumpShape cube{"cube", {}};
    for (int k = 0; k < 8; ++k) cube.spheres.push_back({(k & 1) ? 0.5 : -0.5, (k & 2) ? 0.5 : -0.5, (k & 4) ? 0.5 : -0.5, 0.6});
    return std::vector<ClumpShape>{normalised(cylinder), normalised(cone), normalised(cube)};
  }();
  return shapes;
}

namespace {
using Mat3 = std::array<std::array<double, 3>, 3>;
Mat3 rotation_of(const std::array<double, 4>& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
           {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
           {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
}
std::array<double, 3> rotate_by(const Mat3& r, const std::array<double, 3>& v) {
  std::array<double, 3> out{};
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) out[a] += r[a][b] * v[b];
  return out;
}
}  // namespace

ClumpBodies expand_clumps(const Config& c) {
  ClumpBodies out;
  std::vector<UnionMassProperties> props(c.clump_shapes.size());
  std::vector<bool> done(c.clump_shapes.size(), false);
  for (const auto& k : c.clumps) {
    if (k.shape < 0 || static_cast<std::size_t>(k.shape) >= c.clump_shapes.size())
      throw std::invalid_argument("dem: clump shape " + std::to_string(k.shape) + " does not exist (" +
                                  std::to_string(c.clump_shapes.size()) + " shapes)");
    if (!(k.scale > 0) || !std::isfinite(k.scale)) throw std::invalid_argument("dem: a clump scale must be > 0");
    const auto sh = static_cast<std::size_t>(k.shape);
    if (!done[sh]) {
      props[sh] = union_mass_properties(c.clump_shapes[sh], c.mass_columns);
      done[sh] = true;
    }
    const auto& p = props[sh];
    const double s = k.scale, rho = c.particle.density;
    double qn = 0;
    for (double x : k.orientation) qn += x * x;
    if (!(qn > 0)) throw std::invalid_argument("dem: a clump orientation must be a non-zero quaternion");
    std::array<double, 4> q0 = k.orientation;
    for (auto& x : q0) x /= std::sqrt(qn);
    const Mat3 r0 = rotation_of(q0);
    ClumpBodies::Body b;
    b.mass = rho * p.volume * s * s * s;
    for (int a = 0; a < 3; ++a) b.inertia[a] = rho * p.principal[a] * s * s * s * s * s;
    b.position = k.position;
    b.velocity = k.velocity;
    b.orientation = quaternion_product(q0, quaternion_of(p.axes));
    // L = R diag(I) R^T omega, R the body's rotation
    const Mat3 r = rotation_of(b.orientation);
    std::array<double, 3> wb{};
    for (int a = 0; a < 3; ++a)
      for (int m = 0; m < 3; ++m) wb[a] += r[m][a] * k.omega[m];
    for (int a = 0; a < 3; ++a) wb[a] *= b.inertia[a];
    b.angular_momentum = rotate_by(r, wb);
    const int body = static_cast<int>(out.bodies.size());
    out.bodies.push_back(b);
    for (const auto& sp : c.clump_shapes[sh].spheres) {
      const std::array<double, 3> local = {s * (sp[0] - p.centre[0]), s * (sp[1] - p.centre[1]), s * (sp[2] - p.centre[2])};
      const std::array<double, 3> arm = rotate_by(r0, local);  // world
      std::array<double, 3> offset{};                      // body frame: A^T local
      for (int a = 0; a < 3; ++a)
        for (int m = 0; m < 3; ++m) offset[a] += p.axes[m][a] * local[m];
      SphereInit m;
      m.radius = s * sp[3];
      for (int a = 0; a < 3; ++a) m.position[a] = k.position[a] + arm[a];
      m.velocity = {k.velocity[0] + k.omega[1] * arm[2] - k.omega[2] * arm[1],
                    k.velocity[1] + k.omega[2] * arm[0] - k.omega[0] * arm[2],
                    k.velocity[2] + k.omega[0] * arm[1] - k.omega[1] * arm[0]};
      m.omega = k.omega;
      out.members.push_back(m);
      out.member_body.push_back(body);
      out.member_offset.push_back(offset);
    }
  }
  return out;
}

}  // namespace polymech::dem
