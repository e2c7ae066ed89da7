// Where on a facet a contact acts, as weights of the facet's corner nodes (issue 37: a sphere against the
// deforming surface of an FE tyre). A contact point Q of contact/sphere_facet.hpp is written as Q = sum w_a x_a
// with sum w_a = 1, so that
//   - the surface's material velocity at Q is sum w_a v_a (the relative velocity of seed 002 paper 2 eqs.
//     (12)-(15) on a surface whose nodes move independently), and
//   - the contact's force f on the surface goes to the nodes as w_a f: their forces add up to f exactly (the
//     momentum exchanged between the spheres and the structure is exact), and on a planar facet their moment
//     about any point is that of f at Q (sum w_a x_a = Q).
// Face contact (PTF, eqs. (4)-(5)): a quadrilateral's bilinear coordinates of Q (xi, eta in [0, 1]^2; the
// inverse of x(xi, eta) = sum N_a x_a, by Newton on its in-plane part, which converges in a few iterations from
// the centre for a convex facet; a warped facet's Q is projected on the plane of its mean normal, so there
// sum w_a x_a differs from Q by the warp), a triangle's barycentric ones. Edge contact (PTE, eqs. (6)-(9)): the
// linear weights (1 - t, t) of its two nodes. Node contact (PTN, eq. (10)): 1 on the node.
#pragma once

#include "contact/sphere_facet.hpp"

namespace polymech::contact {

// The corners' weights of contact `c` on facet f (w[a] for corner a; the unused corner of a triangle 0).
template <class T>
KOKKOS_INLINE_FUNCTION void facet_weights(const SurfaceMesh<T>& m, Index f, const FacetContact<T>& c, T (&w)[4]) {
  const int nc = m.corners(f);
  Vec3<T> x[4];
  for (int a = 0; a < 4; ++a) {
    w[a] = T(0);
    if (a < nc) x[a] = load<3>(m.nodes, m.facets(f, a));
  }
  if (c.region == FacetRegion::node) {
    for (int a = 0; a < nc; ++a)
      if (m.facets(f, a) == c.node_a) w[a] = T(1);
    return;
  }
  if (c.region == FacetRegion::edge) {
    int ia = 0, ib = 0;
    for (int a = 0; a < nc; ++a) {
      if (m.facets(f, a) == c.node_a) ia = a;
      if (m.facets(f, a) == c.node_b) ib = a;
    }
    const Vec3<T> e = x[ib] - x[ia];
    const T e2 = norm2(e);
    T t = e2 > T(0) ? dot(c.point - x[ia], e) / e2 : T(0);
    t = t < T(0) ? T(0) : (t > T(1) ? T(1) : t);
    w[ia] = T(1) - t;
    w[ib] = t;
    return;
  }
  if (nc == 3) {  // barycentric coordinates of Q
    const Vec3<T> e1 = x[1] - x[0], e2 = x[2] - x[0], q = c.point - x[0];
    const Vec3<T> n = cross(e1, e2);
    const T nn = norm2(n);
    if (!(nn > T(0))) {
      w[0] = w[1] = w[2] = T(1) / T(3);
      return;
    }
    const T b1 = dot(cross(q, e2), n) / nn, b2 = dot(cross(e1, q), n) / nn;
    w[1] = b1;
    w[2] = b2;
    w[0] = T(1) - b1 - b2;
    return;
  }
  // bilinear: x(s, t) = (1-s)(1-t) x0 + s(1-t) x1 + s t x2 + (1-s) t x3; solve the 2x2 in-plane Newton system
  // (the normal equations of the 3x2 Jacobian) for Q
  T s = T(0.5), t = T(0.5);
  for (int it = 0; it < 8; ++it) {
    const Vec3<T> p = ((T(1) - s) * (T(1) - t)) * x[0] + (s * (T(1) - t)) * x[1] + (s * t) * x[2] + ((T(1) - s) * t) * x[3];
    const Vec3<T> ds = (T(1) - t) * (x[1] - x[0]) + t * (x[2] - x[3]);
    const Vec3<T> dt = (T(1) - s) * (x[3] - x[0]) + s * (x[2] - x[1]);
    const Vec3<T> rres = c.point - p;
    const T a11 = dot(ds, ds), a12 = dot(ds, dt), a22 = dot(dt, dt);
    const T b1 = dot(ds, rres), b2 = dot(dt, rres);
    const T det = a11 * a22 - a12 * a12;
    if (!(det > T(0))) break;
    const T us = (a22 * b1 - a12 * b2) / det, ut = (a11 * b2 - a12 * b1) / det;
    s += us;
    t += ut;
    if (kx::fabs(us) + kx::fabs(ut) < (sizeof(T) == 4 ? T(1e-6) : T(1e-13))) break;
  }
  s = s < T(0) ? T(0) : (s > T(1) ? T(1) : s);
  t = t < T(0) ? T(0) : (t > T(1) ? T(1) : t);
  w[0] = (T(1) - s) * (T(1) - t);
  w[1] = s * (T(1) - t);
  w[2] = s * t;
  w[3] = (T(1) - s) * t;
}

}  // namespace polymech::contact
