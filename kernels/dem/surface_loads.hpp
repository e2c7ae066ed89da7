// Spheres against a surface whose nodes move independently (issue 37: the outer surface of the FE tyre):
// the contact of kernels/dem/contact_forces.hpp's sphere_facet kernel (inside-outside, seed 002 paper 2 eqs.
// (1)-(10); Hertz-Mindlin eqs. (11)-(17)) with the surface's material velocity at the contact point
// interpolated from its nodes, and each contact's force returned to the facet's nodes (contact/facet_weights.hpp):
//
//   sphere_deforming_facet_forces   per sphere row: the contacts, the sphere's force and torque, and per
//                                    listed entry k the force on the surface with the corner weights
//                                    (entry_load(k) = fx fy fz w0 w1 w2 w3)
//   surface_node_loads               per surface node: the sum of w_a f over the entries of the facets it is a
//                                    corner of (facet -> entries: the list's transpose over the facets; node
//                                    -> facets: SurfaceAdjacency), in a fixed order
//
// No atomics: the node loads are the same for any thread count, and they add up to minus the spheres' facet
// forces to round-off (the momentum exchange is exact).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "dem/contact_forces.hpp"

namespace polymech::dem {

// For each surface node the facets it is a corner of, in increasing facet order, with the corner index.
struct SurfaceAdjacency {
  Kokkos::View<Offset*, MemSpace> offsets;  // nodes + 1
  Kokkos::View<Index*, MemSpace> facet;
  Kokkos::View<int*, MemSpace> corner;
};

// The adjacency of facets given as 3 or 4 node indices each (host arrays, as make_surface_mesh takes them).
inline SurfaceAdjacency surface_adjacency(Index nodes, const std::vector<int>& facet_sizes, const std::vector<Index>& facet_nodes) {
  std::vector<Offset> off(static_cast<std::size_t>(nodes) + 1, 0);
  std::size_t at = 0;
  for (const int size : facet_sizes) {
    for (int a = 0; a < size; ++a) {
      const Index n = facet_nodes.at(at + static_cast<std::size_t>(a));
      if (n < 0 || n >= nodes) throw std::invalid_argument("dem::surface_adjacency: node " + std::to_string(n) + " out of range");
      ++off[static_cast<std::size_t>(n) + 1];
    }
    at += static_cast<std::size_t>(size);
  }
  for (std::size_t i = 1; i < off.size(); ++i) off[i] += off[i - 1];
  std::vector<Index> facet(static_cast<std::size_t>(off.back()));
  std::vector<int> corner(facet.size());
  std::vector<Offset> fill(off.begin(), off.end() - 1);
  at = 0;
  for (std::size_t f = 0; f < facet_sizes.size(); ++f) {
    for (int a = 0; a < facet_sizes[f]; ++a) {
      const auto n = static_cast<std::size_t>(facet_nodes[at + static_cast<std::size_t>(a)]);
      const auto e = static_cast<std::size_t>(fill[n]++);
      facet[e] = static_cast<Index>(f);
      corner[e] = a;
    }
    at += static_cast<std::size_t>(facet_sizes[f]);
  }
  SurfaceAdjacency s;
  s.offsets = Kokkos::View<Offset*, MemSpace>("polymech::dem::surface_adjacency_offsets", off.size());
  s.facet = Kokkos::View<Index*, MemSpace>("polymech::dem::surface_adjacency_facet", facet.size());
  s.corner = Kokkos::View<int*, MemSpace>("polymech::dem::surface_adjacency_corner", corner.size());
  auto ho = Kokkos::create_mirror_view(s.offsets);
  auto hf = Kokkos::create_mirror_view(s.facet);
  auto hc = Kokkos::create_mirror_view(s.corner);
  for (std::size_t i = 0; i < off.size(); ++i) ho(i) = off[i];
  for (std::size_t i = 0; i < facet.size(); ++i) {
    hf(i) = facet[i];
    hc(i) = corner[i];
  }
  Kokkos::deep_copy(s.offsets, ho);
  Kokkos::deep_copy(s.facet, hf);
  Kokkos::deep_copy(s.corner, hc);
  return s;
}

// Kernel "polymech::dem::sphere_deforming_facet": sphere_facet_forces (dem/contact_forces.hpp) on a surface
// whose nodes move with `node_velocity`; entry_load(k) gets the force on the surface and the weights of entry k.
template <class T>
void sphere_deforming_facet_forces(const SphereSet<T>& s, const contact::SurfaceMesh<T>& mesh, const neighbors::NeighborList& list,
                                   const SpringView<T>& hist, const HertzMindlin<T>& p, bool friction, T dt,
                                   const VecView<T, 3>& node_velocity, const EntryLoadView<T>& entry_load) {
  sphere_facet_forces(s, mesh, list, hist, p, friction, dt, SurfaceMotion<T>(), WrenchView<T>(), DeformingSurface<T>{node_velocity, entry_load});
}

// Kernel "polymech::dem::surface_node_loads": node_force(n) = sum over the facets f of node n (adjacency
// order), over the entries e of f (`by_facet`, the sphere-facet list's transpose over the facets; increasing
// entry), of w_corner(e) f(e).
template <class T>
void surface_node_loads(const SurfaceAdjacency& adj, const neighbors::ListTranspose& by_facet, const EntryLoadView<T>& entry_load,
                        const VecView<T, 3>& node_force) {
  Kokkos::parallel_for(
      "polymech::dem::surface_node_loads", range(static_cast<Index>(node_force.extent(0))), KOKKOS_LAMBDA(const Index n) {
        Vec3<T> f = Vec3<T>::zero();
        for (Offset a = adj.offsets(n); a < adj.offsets(n + 1); ++a) {
          const Index facet = adj.facet(a);
          const int corner = adj.corner(a);
          for (Offset e = by_facet.begin(facet); e < by_facet.end(facet); ++e) {
            const Offset k = by_facet.entry(e);
            const T w = entry_load(k, 3 + corner);
            if (w == T(0)) continue;
            for (int q = 0; q < 3; ++q) f[q] += w * entry_load(k, q);
          }
        }
        store<3>(node_force, n, f);
      });
}

}  // namespace polymech::dem
