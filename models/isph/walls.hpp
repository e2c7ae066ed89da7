// The walls of the ISPH model (seed 002 paper 4): improved ghost cell boundary (IGCB) walls, the tank as
// square (cubic) cells of the particle spacing, one Gauss point each (the paper's choice), ghost points
// mirrored into the fluid; with `rigid_body`, the floating body's cells after them (floating_body.hpp).
// A general cell mesh of IGCB (arbitrary walls) is not built (docs/METHODS.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "isph/config.hpp"
#include "isph/floating_body.hpp"
#include "isph/setup.hpp"
#include "sph/fluid.hpp"
#include "sph/safety_net.hpp"

namespace polymech::isph {

// The number of whole cells of l0 in `length` (a tank size rounded to a multiple of the spacing).
inline long long whole_cells(double length, double l0) { return static_cast<long long>(std::llround(length / l0)); }

// Tank walls: cells of size l0 in ceil(re/l0) layers below and beside the tank (open top), one Gauss
// point at each centre (weight H |J| = l0^D). The ghost of a point is its mirror through the nearest
// point q of the tank box (a face, an edge or a corner): ghost = 2 q - x, n = (x - q)/|x - q|, d = 2|x - q|.
// With `with_body` (2D), the body's cells follow the tank's points (body.build); its points are placed by
// body.place once the walls are on the device. `box` gets the tank as built: whole cells of l0, which
// the walls, the safety net and the body's contact all use. Returns the number of the tank's points.
template <class T, int D>
Index build_walls(const Config& cfg, bool with_body, bool difference_gradient, sph::WallPoints<T, D>& wp,
                 double (&box)[3], FloatingBody<T>& body) {
  const double l0 = cfg.spacing;
  const long long layers = static_cast<long long>(std::ceil(cfg.radius_factor - 1e-9));
  const long long nx = whole_cells(cfg.tank[0], l0), ny = whole_cells(cfg.tank[1], l0),
                  nz = D == 3 ? whole_cells(cfg.tank[2], l0) : 1;
  box[0] = nx * l0;
  box[1] = ny * l0;
  box[2] = nz * l0;
  std::vector<double> pts;
  const long long z0 = D == 3 ? -layers : 0, z1 = D == 3 ? nz + layers : 1;
  for (long long c = z0; c < z1; ++c)
    for (long long b = -layers; b < ny; ++b)
      for (long long a = -layers; a < nx + layers; ++a) {
        const bool inside = a >= 0 && a < nx && b >= 0 && (D == 2 || (c >= 0 && c < nz));
        if (inside) continue;
        pts.push_back((a + 0.5) * l0);
        pts.push_back((b + 0.5) * l0);
        if (D == 3) pts.push_back((c + 0.5) * l0);
      }
  const std::size_t tank_points = pts.size() / D;
  BodyCells cells_b;
  if constexpr (D == 2) {
    if (with_body) cells_b = body_cells(cfg);
  }
  const std::size_t m = tank_points + cells_b.weight.size();
  const std::string pre = "polymech::isph::wall_";
  wp.x = VecView<T, D>(pre + "x", m);
  wp.vol = View1<T>(pre + "vol", m);
  wp.normal = VecView<T, D>(pre + "normal", m);
  wp.ghost = VecView<T, D>(pre + "ghost", m);
  wp.dist = View1<T>(pre + "dist", m);
  wp.velocity = VecView<T, D>(pre + "velocity", m);
  wp.accel = VecView<T, D>(pre + "accel", m);
  wp.p = View1<T>(pre + "p", m);
  wp.u = VecView<T, D>(pre + "u", m);
  wp.shepard = View1<T>(pre + "shepard", m);
  wp.interp = VecView<T, D + 1>(pre + "interp", m);
  auto hx = Kokkos::create_mirror_view(wp.x);
  auto hv = Kokkos::create_mirror_view(wp.vol);
  auto hn = Kokkos::create_mirror_view(wp.normal);
  auto hg = Kokkos::create_mirror_view(wp.ghost);
  auto hd = Kokkos::create_mirror_view(wp.dist);
  for (std::size_t k = 0; k < tank_points; ++k) {
    double q[3], r2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double x = pts[k * D + d];
      q[d] = std::min(std::max(x, 0.0), box[d]);
      r2 += (x - q[d]) * (x - q[d]);
    }
    const double r = std::sqrt(r2);
    for (int d = 0; d < D; ++d) {
      const double x = pts[k * D + d];
      hx(k, d) = T(x);
      hn(k, d) = T((x - q[d]) / r);
      hg(k, d) = T(2 * q[d] - x);
    }
    hv(k) = T(std::pow(l0, D));
    hd(k) = T(2 * r);
  }
  if constexpr (D == 2) {
    // effect `rigid_body` only: nothing allocated without it
    if (!cells_b.weight.empty()) body.build(cfg, cells_b, static_cast<Index>(tank_points), box, difference_gradient, hv);
  }
  Kokkos::deep_copy(wp.x, hx);
  Kokkos::deep_copy(wp.vol, hv);
  Kokkos::deep_copy(wp.normal, hn);
  Kokkos::deep_copy(wp.ghost, hg);
  Kokkos::deep_copy(wp.dist, hd);
  return static_cast<Index>(tank_points);
}

// The safety net: particles that left the tank (a quarter spacing inside its walls; the top is open) are
// put back (sph::keep_inside); returns how many.
template <class T, int D>
long long keep_inside_tank(const sph::Fluid<T, D>& f, const double (&box)[3], double spacing) {
  Vec<T, D> lo, hi;
  const T margin = T(0.25 * spacing);
  for (int k = 0; k < D; ++k) {
    lo[k] = margin;
    hi[k] = T(box[k]) - margin;
  }
  hi[1] = T(1e30);  // open top
  return sph::keep_inside(f, lo, hi);
}

}  // namespace polymech::isph
