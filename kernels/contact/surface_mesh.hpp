// A surface mesh of triangles and quadrilaterals that no single model owns: the facets a DEM sphere
// touches (seed 002 paper 2: the FE surfaces of a wheel and a bin), the walls of a tank. Node positions
// live in a View, so a moving or deforming FE surface plugs in by writing them; update_geometry()
// refreshes the facets' centroids, unit normals and bounding radii, which the broad phase searches.
//
// Facet f has nodes facets(f, 0..3); a triangle has facets(f, 3) = -1. The normal of a quadrilateral
// is that of its diagonals, (x2 - x0) x (x3 - x1), the mean normal of a bilinear (possibly warped)
// quad; of a triangle, (x1 - x0) x (x2 - x0). Node order gives the outward side (counter-clockwise
// seen from outside).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "core/small_math.hpp"
#include "core/types.hpp"
#include "neighbors/neighbor_search.hpp"

namespace polymech::contact {

template <class T>
struct SurfaceMesh {
  VecView<T, 3> nodes;                                          // current node positions
  Kokkos::View<Index* [4], Kokkos::LayoutRight, MemSpace> facets;  // node indices; [3] = -1: triangle
  VecView<T, 3> centroid;                                       // per facet, from update_geometry()
  VecView<T, 3> normal;                                         // unit normal
  View1<T> radius;                                              // largest node distance from the centroid

  Index node_count() const { return static_cast<Index>(nodes.extent(0)); }
  Index facet_count() const { return static_cast<Index>(facets.extent(0)); }
  KOKKOS_INLINE_FUNCTION int corners(Index f) const { return facets(f, 3) < 0 ? 3 : 4; }
};

// Kernel "polymech::contact::facet_geometry": centroid, unit normal and bounding radius of every facet.
template <class T>
void update_geometry(const SurfaceMesh<T>& m) {
  Kokkos::parallel_for(
      "polymech::contact::facet_geometry", range(m.facet_count()), KOKKOS_LAMBDA(const Index f) {
        const int n = m.corners(f);
        Vec3<T> x[4];
        auto c = Vec3<T>::zero();
        for (int a = 0; a < n; ++a) {
          x[a] = load<3>(m.nodes, m.facets(f, a));
          c += x[a];
        }
        c *= T(1) / T(n);
        const Vec3<T> nrm = n == 3 ? cross(x[1] - x[0], x[2] - x[0]) : cross(x[2] - x[0], x[3] - x[1]);
        const T len = norm(nrm);
        T r = T(0);
        for (int a = 0; a < n; ++a) r = kx::max(r, norm(x[a] - c));
        store<3>(m.centroid, f, c);
        store<3>(m.normal, f, len > T(0) ? (T(1) / len) * nrm : nrm);
        m.radius(f) = r;
      });
}

// A surface mesh from host arrays: nodes (n x 3) and facets, each given by 3 or 4 node indices
// (facet_sizes[f] in {3, 4}, node indices concatenated). Throws std::invalid_argument for a facet of
// another size or an index outside the nodes.
template <class T>
SurfaceMesh<T> make_surface_mesh(const std::vector<double>& nodes, const std::vector<int>& facet_sizes,
                                 const std::vector<Index>& facet_nodes, const std::string& label) {
  SurfaceMesh<T> m;
  const std::size_t nn = nodes.size() / 3, nf = facet_sizes.size();
  m.nodes = VecView<T, 3>(label + "_nodes", nn);
  m.facets = Kokkos::View<Index* [4], Kokkos::LayoutRight, MemSpace>(label + "_facets", nf);
  m.centroid = VecView<T, 3>(label + "_centroid", nf);
  m.normal = VecView<T, 3>(label + "_normal", nf);
  m.radius = View1<T>(label + "_radius", nf);
  auto hn = Kokkos::create_mirror_view(m.nodes);
  for (std::size_t i = 0; i < nn; ++i)
    for (int k = 0; k < 3; ++k) hn(i, k) = static_cast<T>(nodes[3 * i + k]);
  auto hf = Kokkos::create_mirror_view(m.facets);
  std::size_t at = 0;
  for (std::size_t f = 0; f < nf; ++f) {
    const int size = facet_sizes[f];
    if (size != 3 && size != 4)
      throw std::invalid_argument("surface mesh '" + label + "': facet " + std::to_string(f) + " has " +
                                  std::to_string(size) + " nodes; allowed: 3 (triangle) or 4 (quadrilateral)");
    for (int a = 0; a < 4; ++a) {
      const Index node = a < size ? facet_nodes.at(at + a) : Index(-1);
      if (a < size && (node < 0 || static_cast<std::size_t>(node) >= nn))
        throw std::invalid_argument("surface mesh '" + label + "': facet " + std::to_string(f) + " refers to node " +
                                    std::to_string(node) + "; the mesh has " + std::to_string(nn) + " nodes");
      hf(f, a) = node;
    }
    at += static_cast<std::size_t>(size);
  }
  Kokkos::deep_copy(m.nodes, hn);
  Kokkos::deep_copy(m.facets, hf);
  update_geometry(m);
  return m;
}

// Kernel "polymech::contact::place_rigid_surface": a surface that moves as one rigid body, nodes =
// centre + R(q) reference (the reference nodes relative to the centre in the body frame, q the unit
// quaternion (w, x, y, z) body -> world), then its facet geometry (update_geometry).
template <class T>
void place_rigid(const SurfaceMesh<T>& m, const VecView<T, 3>& reference, const double (&centre)[3], const double (&q)[4]) {
  const auto nodes = m.nodes;
  const double c0 = centre[0], c1 = centre[1], c2 = centre[2], w = q[0], u0 = q[1], u1 = q[2], u2 = q[3];
  Kokkos::parallel_for(
      "polymech::contact::place_rigid_surface", range(m.node_count()), KOKKOS_LAMBDA(const Index n) {
        const double x0 = double(reference(n, 0)), x1 = double(reference(n, 1)), x2 = double(reference(n, 2));
        // y = x + w t + u x t, t = 2 u x x (the rotation of a unit quaternion)
        const double t0 = 2.0 * (u1 * x2 - u2 * x1), t1 = 2.0 * (u2 * x0 - u0 * x2), t2 = 2.0 * (u0 * x1 - u1 * x0);
        nodes(n, 0) = T(c0 + x0 + w * t0 + (u1 * t2 - u2 * t1));
        nodes(n, 1) = T(c1 + x1 + w * t1 + (u2 * t0 - u0 * t2));
        nodes(n, 2) = T(c2 + x2 + w * t2 + (u0 * t1 - u1 * t0));
      });
  update_geometry(m);
}

// The largest bounding radius of the facets (host): a point within distance d of a facet is within
// d + max_facet_radius of its centroid, the radius of a two-set broad phase of points against facets.
template <class T>
T max_facet_radius(const SurfaceMesh<T>& m) {
  T r = T(0);
  const auto radius = m.radius;
  Kokkos::parallel_reduce(
      "polymech::contact::max_facet_radius", range(m.facet_count()),
      KOKKOS_LAMBDA(const Index f, T& x) { x = radius(f) > x ? radius(f) : x; }, Kokkos::Max<T>(r));
  return r;
}

}  // namespace polymech::contact
