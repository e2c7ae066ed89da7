// A sphere against a facet (quadrilateral or triangle) of a SurfaceMesh by the inside-outside algorithm
// (seed 002 paper 2, eqs. (1)-(10); Wang & Nakamachi 1997), in the corrected form of docs/METHODS.md:
//
//   E_i = N_{i+1} - N_i                     edge vectors, counter-clockwise seen from outside (E_0 = E_4)
//   n_i = E_{i-1} x E_i                     node normals                  (eq. (1) prints E_i x (-E_i) = 0)
//   n_s = sum n_i / |sum n_i|               segment normal                (eq. (2) prints a product)
//   phi_i = (E_i x (P - N_i)) . n_s         judgement values, eq. (3): > 0 on the inner side of edge i
//   PTF (every phi_i > 0):  Q = P - ((P - C) . n_s) n_s,  h = (P - Q) . n_s - r       eqs. (4)-(5)
//   PTE (phi_i <= 0):       t = (P - N_i) . E_i / |E_i|^2 in (0, 1), Q = N_i + t E_i,   eqs. (6)-(9)
//                           h = |P - Q| - r                                 (eq. (8) divides by |P - N_i|)
//   PTN (t clamped to 0 or 1 on every edge with phi_i <= 0): Q = N_i,  h = |P - N_i| - r       eq. (10)
//
// Q of PTF is the projection on the plane through the centroid C: for a planar facet it is eq. (4)'s
// point; for a warped quadrilateral the plane of the mean normal n_s. The contact normal is n_s for PTF
// (one-sided: a sphere whose centre has crossed the facet plane is still pushed out along n_s while the
// centre is less than r behind it, so a fast sphere does not tunnel through a thin surface) and
// (P - Q) / |P - Q| for PTE and PTN, which equals n_s on the boundary of the PTF region: the normal and
// the overlap are continuous as a sphere rolls across an edge or a node.
//
// One force, not two, where a sphere touches several facets at once (contact::keep_facet_contact): an
// edge contact is dropped when a facet holding that edge is in face contact or an earlier facet reported
// the same edge; a node contact when a facet holding the node is in face or edge contact or the node was
// reported already.
#pragma once

#include "contact/surface_mesh.hpp"
#include "core/small_math.hpp"

namespace polymech::contact {

enum class FacetRegion : int { none = 0, facet = 1, edge = 2, node = 3 };

template <class T>
struct FacetContact {
  FacetRegion region = FacetRegion::none;
  Index node_a = -1, node_b = -1;  // edge: its two nodes (a < b); node: the node in node_a
  Vec3<T> point;                   // Q, the closest point of the facet
  Vec3<T> normal;                  // unit normal from Q towards the sphere centre
  T overlap = T(0);                // -h: > 0 in contact
};

// The closest feature of facet f to a sphere (centre p, radius r), eqs. (1)-(10). region = none when
// the sphere is behind the facet by more than r or farther than r from it.
template <class T>
KOKKOS_INLINE_FUNCTION FacetContact<T> sphere_facet_contact(const SurfaceMesh<T>& m, Index f, const Vec3<T>& p, T r) {
  FacetContact<T> c;
  const int nc = m.corners(f);
  Vec3<T> x[4];
  Index id[4];
  for (int a = 0; a < nc; ++a) {
    id[a] = m.facets(f, a);
    x[a] = load<3>(m.nodes, id[a]);
  }
  // eqs. (1)-(2): node normals from adjacent edges, the segment normal their normalised sum
  auto ns = Vec3<T>::zero();
  for (int a = 0; a < nc; ++a) ns += cross(x[a] - x[(a + nc - 1) % nc], x[(a + 1) % nc] - x[a]);
  const T len = norm(ns);
  if (!(len > T(0))) return c;
  ns = (T(1) / len) * ns;
  // eq. (3): judgement values
  bool inside = true;
  T phi[4];
  for (int a = 0; a < nc; ++a) {
    phi[a] = dot(cross(x[(a + 1) % nc] - x[a], p - x[a]), ns);
    inside = inside && phi[a] > T(0);
  }
  if (inside) {  // PTF, eqs. (4)-(5)
    auto centre = Vec3<T>::zero();
    for (int a = 0; a < nc; ++a) centre += x[a];
    centre = (T(1) / T(nc)) * centre;
    const T d = dot(p - centre, ns);
    if (d <= -r || d >= r) return c;
    c.region = FacetRegion::facet;
    c.point = p - d * ns;
    c.normal = ns;
    c.overlap = r - d;
    return c;
  }
  // PTE / PTN, eqs. (6)-(10): the nearest point over the edges whose outer side holds P
  T best = T(-1);
  for (int a = 0; a < nc; ++a) {
    if (phi[a] > T(0)) continue;
    const Vec3<T> e = x[(a + 1) % nc] - x[a];
    const T e2 = norm2(e);
    T t = e2 > T(0) ? dot(p - x[a], e) / e2 : T(0);  // eq. (8), divided by |E|^2
    FacetRegion region = FacetRegion::edge;
    Index na = id[a], nb = id[(a + 1) % nc];
    if (t <= T(0)) {
      t = T(0);
      region = FacetRegion::node;
      nb = -1;
    } else if (t >= T(1)) {
      t = T(1);
      region = FacetRegion::node;
      na = id[(a + 1) % nc];
      nb = -1;
    }
    const Vec3<T> q = x[a] + t * e;  // eq. (7)
    const T d2 = norm2(p - q);
    if (best < T(0) || d2 < best) {
      best = d2;
      c.region = region;
      c.node_a = nb >= 0 && nb < na ? nb : na;
      c.node_b = nb >= 0 && nb < na ? na : nb;
      c.point = q;
    }
  }
  const T d = kx::sqrt(best);
  if (c.region == FacetRegion::none || !(d < r) || !(d > T(0))) {
    c.region = FacetRegion::none;
    return c;
  }
  c.normal = (T(1) / d) * (p - c.point);
  c.overlap = r - d;  // eqs. (9), (10)
  if (dot(c.normal, ns) < T(0)) c.region = FacetRegion::none;  // behind the surface: its other side's business
  return c;
}

template <class T>
KOKKOS_INLINE_FUNCTION bool facet_has_node(const SurfaceMesh<T>& m, Index f, Index node) {
  for (int a = 0; a < m.corners(f); ++a)
    if (m.facets(f, a) == node) return true;
  return false;
}

// Whether contact k of the facets `facet[0..count)` a sphere touches (contacts c[0..count)) adds a
// force: the rule of one force per touching feature (header comment).
template <class T>
KOKKOS_INLINE_FUNCTION bool keep_facet_contact(const SurfaceMesh<T>& m, const Index* facet, const FacetContact<T>* c,
                                               int count, int k) {
  const FacetContact<T>& ck = c[k];
  if (ck.region == FacetRegion::none) return false;
  if (ck.region == FacetRegion::facet) return true;
  for (int g = 0; g < count; ++g) {
    if (g == k || c[g].region == FacetRegion::none) continue;
    if (ck.region == FacetRegion::edge) {
      if (c[g].region == FacetRegion::facet && facet_has_node(m, facet[g], ck.node_a) &&
          facet_has_node(m, facet[g], ck.node_b))
        return false;
      if (g < k && c[g].region == FacetRegion::edge && c[g].node_a == ck.node_a && c[g].node_b == ck.node_b)
        return false;
    } else {  // node
      if (c[g].region == FacetRegion::facet && facet_has_node(m, facet[g], ck.node_a)) return false;
      if (c[g].region == FacetRegion::edge && (c[g].node_a == ck.node_a || c[g].node_b == ck.node_a)) return false;
      if (g < k && c[g].region == FacetRegion::node && c[g].node_a == ck.node_a) return false;
    }
  }
  return true;
}

}  // namespace polymech::contact
