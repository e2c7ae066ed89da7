// Efg<T>, part: MLS shape functions at points (seed 004 eqs. (2)-(5), kernels/mls/mls.hpp), the field
// and its gradient interpolated from them (eq. (1), kernels/mls/interpolation.hpp), the crack opening,
// and the node positions and support radii on the device. Included by efg/efg.hpp.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "efg/efg.hpp"
#include "efg/host_copy.hpp"
#include "mls/interpolation.hpp"
#include "mls/mls.hpp"
#include "neighbors/neighbor_search.hpp"

namespace polymech::efg {

template <class T>
inline mls::ShapeFunctions<T> Efg<T>::shape_functions(const std::vector<double>& flat, int stride, const std::string& what) const {
  const auto pts = detail::to_points<T>(flat, stride, "polymech::efg::points");
  return shape_functions(pts, what);
}

// The nodes of each point from the two-set search (points against nodes, largest support radius), kept
// where the node's own support covers the point and the crack does not hide it; then eqs. (2)-(5).
template <class T>
inline mls::ShapeFunctions<T> Efg<T>::shape_functions(const VecView<T, 2>& pts, const std::string& what) const {
  neighbors::NeighborSearch<T, 2> search;
  neighbors::NeighborList candidates;
  search.build_between(pts, nodes_, static_cast<T>(max_dm_), candidates);
  mls::ShapeFunctions<T> sf;
  sf.rows = mls::support_rows(candidates, pts, nodes_, dm_, crack_);
  mls::evaluate(pts, nodes_, dm_, static_cast<T>(config_.min_moment_ratio), sf);
  Index count = 0;
  const Index first = mls::first_flagged(sf.status, sf.points, count);
  if (first >= 0) {
    auto hp = Kokkos::create_mirror_view_and_copy(HostSpace(), pts);
    auto hr = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.ratio);
    auto ho = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.offsets);
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "EFG: nearly singular MLS moment matrix at %s point %d (x = %.9g, y = %.9g): det(A)/(A00 A11 A22) = "
                  "%.3g < min_moment_ratio %.3g, %lld nodes in its support (%d such points; too few or nearly collinear "
                  "nodes: raise support_factor or move the nodes)",
                  what.c_str(), static_cast<int>(first), static_cast<double>(hp(first, 0)), static_cast<double>(hp(first, 1)),
                  static_cast<double>(hr(first)), config_.min_moment_ratio,
                  static_cast<long long>(ho(first + 1) - ho(first)), static_cast<int>(count));
    throw std::runtime_error(buf);
  }
  return sf;
}

// (ux, uy, ux_x, ux_y, uy_x, uy_y) of the coefficients `coeff` at the points of sf, 6 per point.
template <class T>
inline std::vector<double> Efg<T>::probe(const mls::ShapeFunctions<T>& sf, const View1<T>& coeff) const {
  mls::PointFields<T> out("polymech::efg::fields", static_cast<std::size_t>(sf.points));
  mls::interpolate(sf, coeff, out);
  auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), out);
  std::vector<double> r(static_cast<std::size_t>(sf.points) * 6);
  for (Index i = 0; i < sf.points; ++i)
    for (int c = 0; c < 6; ++c) r[static_cast<std::size_t>(i) * 6 + static_cast<std::size_t>(c)] = static_cast<double>(h(i, c));
  return r;
}

template <class T>
inline std::vector<double> Efg<T>::fields_at(const std::vector<double>& xy, const std::string& what) const {
  return probe(shape_functions(xy, 2, what), u_);
}

template <class T>
inline double Efg<T>::opening_at(double x) const {
  const double e = 1e-6 * config_.h_min;
  const auto v = fields_at({x, e, x, -e}, "crack-opening");
  return v[1] - v[6 + 1];
}

// As opening_at, the shape functions kept while x stays the same.
template <class T>
inline double Efg<T>::dynamic_opening_at(double x) {
  if (!cod_ready_ || cod_x_ != x) {
    const double e = 1e-6 * config_.h_min;
    cod_sf_ = shape_functions(std::vector<double>{x, e, x, -e}, 2, "crack-opening");
    cod_ready_ = true;
    cod_x_ = x;
  }
  const auto v = probe(cod_sf_, u_);
  return v[1] - v[6 + 1];
}

// The layout's node positions and support radii to the device.
template <class T>
inline void Efg<T>::upload_nodes() {
  nodes_ = detail::to_points<T>(layout_.nodes, 2, "polymech::efg::nodes");
  dm_ = detail::to_device<T>(layout_.dm, "polymech::efg::support_radius");
}

}  // namespace polymech::efg
