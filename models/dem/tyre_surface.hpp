// The members of dem::TyreDrive (models/dem/tyre_drive.hpp) that join the FE tyre's outer side to the DEM's
// surface: the surface's facets, its placement in the world each step, the spheres' node forces returned to the
// FE residual, their sum on the tyre, the tread's lowest point and the set-down.
#pragma once

#include <algorithm>
#include <cmath>

#include "dem/tyre_drive.hpp"

namespace polymech::dem {

// Kernel "polymech::dem::tyre_surface_loads": r(fe node of s) -= scale force(s) (the spheres' forces as external
// ones; scale: TyreDrive's substeps, 1 for one common step, 0 inside a subcycle).
template <class T>
void subtract_surface_loads(const Kokkos::View<Index*, MemSpace>& node, const VecView<T, 3>& force, double scale, const View1<double>& r) {
  Kokkos::parallel_for(
      "polymech::dem::tyre_surface_loads", range(static_cast<Index>(node.extent(0))), KOKKOS_LAMBDA(const Index s) {
        const Index i = node(s);
        for (int k = 0; k < 3; ++k) r(3 * i + k) -= scale * double(force(s, k));
      });
}

// The outer side's lattice (lattice[0] round, periodic; lattice[1] along the contour, bead to bead) at the
// last wall index: one surface node per lattice point, quadrilaterals between neighbours (the cells' order-p
// nodes make p x p facets per cell face). Orientation: the facets' normal points away from the inner surface.
template <class T>
void TyreDrive<T>::make_surface() {
  const auto& d = solid_->solid().discretization();
  const int n0 = d.lattice[0], n1 = d.lattice[1], top = d.lattice[2] - 1;
  std::vector<Index> fe(static_cast<std::size_t>(n0) * static_cast<std::size_t>(n1));
  surface_ = SurfaceInit();
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const std::int64_t v = d.node({i, j, top});
      fe[static_cast<std::size_t>(j) * static_cast<std::size_t>(n0) + static_cast<std::size_t>(i)] = static_cast<Index>(v);
      for (int k = 0; k < 3; ++k)
        surface_.nodes.push_back(d.coordinates[static_cast<std::size_t>(3 * v + k)] + spec_.parked[static_cast<std::size_t>(k)]);
    }
  auto sn = [n0](int i, int j) { return static_cast<std::int64_t>(j) * n0 + (i % n0); };
  // orientation from the first cell: (x1 - x0) x (x3 - x0) against the wall's direction (inner -> outer)
  const auto X = [&d](std::int64_t v, int k) { return d.coordinates[static_cast<std::size_t>(3 * v + k)]; };
  const std::int64_t a = d.node({0, 0, top}), b = d.node({1, 0, top}), c = d.node({0, 1, top}), in = d.node({0, 0, 0});
  double e1[3], e2[3], wall[3];
  for (int k = 0; k < 3; ++k) {
    e1[k] = X(b, k) - X(a, k);
    e2[k] = X(c, k) - X(a, k);
    wall[k] = X(a, k) - X(in, k);
  }
  const double nrm[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  const bool ccw = nrm[0] * wall[0] + nrm[1] * wall[1] + nrm[2] * wall[2] > 0.0;
  std::vector<Index> facet_nodes;
  for (int j = 0; j + 1 < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const std::int64_t q[4] = {sn(i, j), sn(i + 1, j), sn(i + 1, j + 1), sn(i, j + 1)};
      surface_.facet_sizes.push_back(4);
      for (int k = 0; k < 4; ++k) {
        const std::int64_t node = ccw ? q[k] : q[3 - k];
        surface_.facet_nodes.push_back(node);
        facet_nodes.push_back(static_cast<Index>(node));
      }
    }
  fe_node_ = models::to_device<Index>("polymech::dem::tyre_surface_nodes", fe);
  reference_ = models::to_device<double>("polymech::dem::tyre_reference", d.coordinates);
  const auto ns = fe.size();
  velocity_ = VecView<T, 3>("polymech::dem::tyre_surface_velocity", ns);
  force_ = VecView<T, 3>("polymech::dem::tyre_surface_force", ns);
  adjacency_ = surface_adjacency(static_cast<Index>(ns), surface_.facet_sizes, facet_nodes);
  // the spheres' forces on the surface nodes into the FE residual (r = f_int - f_ext: subtracted)
  const auto node = fe_node_;
  const auto force = force_;
  const auto scale = contact_scale_;
  solid_->set_external_force([node, force, scale](double, const View1<double>&, const View1<double>&, const View1<double>& r) {
    if (*scale != 0.0) subtract_surface_loads(node, force, *scale, r);
  });
}

// Kernel "polymech::dem::place_tyre_surface": surface node s at X + u + origin, its velocity v; then the facets'
// geometry (contact::update_geometry).
template <class T>
void TyreDrive<T>::place(const contact::SurfaceMesh<T>& mesh) const {
  const auto node = fe_node_;
  const auto X = reference_;
  const auto u = solid_->displacement(), v = solid_->velocity();
  const auto nodes = mesh.nodes;
  const auto vel = velocity_;
  const TyreRecord& r = record_(0);
  const double o0 = r.origin[0], o1 = r.origin[1], o2 = r.origin[2];
  Kokkos::parallel_for(
      "polymech::dem::place_tyre_surface", range(static_cast<Index>(node.extent(0))), KOKKOS_LAMBDA(const Index s) {
        const Index i = node(s);
        nodes(s, 0) = T(X(3 * i) + u(3 * i) + o0);
        nodes(s, 1) = T(X(3 * i + 1) + u(3 * i + 1) + o1);
        nodes(s, 2) = T(X(3 * i + 2) + u(3 * i + 2) + o2);
        for (int k = 0; k < 3; ++k) vel(s, k) = T(v(3 * i + k));
      });
  contact::update_geometry(mesh);
}

// The gravel's force on the tyre (the node forces) and its moment about the rim's centre, in node order.
template <class T>
void TyreDrive<T>::sum_contact() {
  const auto node = fe_node_;
  const auto X = reference_;
  const auto u = solid_->displacement();
  const auto force = force_;
  const auto& rim = solid_->ties()[0];
  const double c0 = rim.position[0], c1 = rim.position[1], c2 = rim.position[2];
  const auto sum = particles::ordered_sum<6>(
      "polymech::dem::tyre_reaction_sum", static_cast<std::int64_t>(node.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t s, double* acc) {
        const Index i = node(s);
        const double y[3] = {X(3 * i) + u(3 * i) - c0, X(3 * i + 1) + u(3 * i + 1) - c1, X(3 * i + 2) + u(3 * i + 2) - c2};
        const double f[3] = {double(force(s, 0)), double(force(s, 1)), double(force(s, 2))};
        for (int k = 0; k < 3; ++k) acc[k] += f[k];
        acc[3] += y[1] * f[2] - y[2] * f[1];
        acc[4] += y[2] * f[0] - y[0] * f[2];
        acc[5] += y[0] * f[1] - y[1] * f[0];
      },
      partials_);
  for (int k = 0; k < 6; ++k) contact_[static_cast<std::size_t>(k)] = sum[k];
}

// The lowest z of the outer surface in the world (host; at output times).
template <class T>
double TyreDrive<T>::lowest_tread() const {
  const auto node = fe_node_;
  const auto X = reference_;
  const auto u = solid_->displacement();
  double low = 0.0;
  Kokkos::parallel_reduce(
      "polymech::dem::tyre_lowest_point", range(static_cast<Index>(node.extent(0))),
      KOKKOS_LAMBDA(const Index s, double& m) {
        const Index i = node(s);
        const double z = X(3 * i + 2) + u(3 * i + 2);
        m = z < m ? z : m;
      },
      Kokkos::Min<double>(low));
  return low + record_(0).origin[2];
}

// Its lowest point on the highest sphere under its footprint (dem/wheel.hpp bed_level), at rest: the FE frame's
// origin there (the undeformed tyre's lowest point is R below its centre).
template <class T>
void TyreDrive<T>::set_down(double time, const SphereSet<T>& s) {
  const BedLevel level = bed_under(s, spec_);
  TyreRecord& r = record_(0);
  r.origin[0] = spec_.x_start;
  r.origin[1] = spec_.y_centre;
  r.origin[2] = level.highest + spec_.radius;
  r.placement.placed = 1.0;
  r.placement.time_placed = time;
  r.placement.bed_level = level.mean;
  r.placement.bed_highest = level.highest;
}

}  // namespace polymech::dem
