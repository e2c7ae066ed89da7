// The contact kernels of the DEM model: sphere-sphere (over a half neighbour list, each pair once, then
// a gather to the second members over the list's transpose), sphere against analytic planes, sphere
// against the facets of a SurfaceMesh (inside-outside, one force per touching feature). Each kernel
// runs over the spheres and adds to one sphere per thread (its acceleration and angular acceleration):
// no atomics, and the result does not depend on the thread count.
//
// History: the tangential spring xi of contact k sits in hist(k, 0..2) (contact::PairHistory::values,
// carried across list rebuilds); it is set to zero while the pair is listed but not touching, so a new
// contact starts unloaded. An empty hist (friction off) is never read.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>

#include "contact/facet_weights.hpp"
#include "contact/sphere_facet.hpp"
#include "dem/hertz_mindlin.hpp"
#include "dem/pair_batch.hpp"
#include "dem/spheres.hpp"
#include "neighbors/neighbor_list.hpp"
#include "neighbors/transpose.hpp"
#include "particles/reductions.hpp"

namespace polymech::dem {

template <class T>
using SpringView = Kokkos::View<T* [3], Kokkos::LayoutRight, MemSpace>;

// Analytic planes: a point and the unit normal of the side the spheres are on, (px, py, pz, nx, ny, nz).
template <class T>
using PlaneView = Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>;

namespace detail {

// Adds one contact's force (and torque about the centre, lever -l n: l = r for a wall, the distance to
// the middle of the overlap for two spheres) to sphere i.
template <class T>
KOKKOS_INLINE_FUNCTION void add_contact(const SphereSet<T>& s, Index i, const Vec3<T>& n, T r_i, T lever, const Vec3<T>& f) {
  const T m = s.mass(i);
  const T inv_inertia = T(2.5) / (m * r_i * r_i);
  const Vec3<T> torque = cross((-lever) * n, f);
  for (int k = 0; k < 3; ++k) {
    s.a(i, k) += f[k] / m;
    s.alpha(i, k) += inv_inertia * torque[k];
  }
}

template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> spring(const SpringView<T>& h, Offset k, bool friction) {
  return friction ? load<3>(h, k) : Vec3<T>::zero();
}

}  // namespace detail

// What a sphere-sphere pair gives its second member j (half list): the force on j is -f, its torque
// tj = -l_j (n x f) (rows: fx, fy, fz, tjx, tjy, tjz; zero for a listed pair not in contact).
template <class T>
using PairLoadView = Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>;

// The planes near each sphere, a bit per plane (at most max_planes): a Verlet list for the planes,
// rebuilt with the sphere list. An empty mask View: every plane is near every sphere.
using PlaneMask = Kokkos::View<std::uint32_t*, MemSpace>;
inline constexpr int max_planes = 32;

// Analytic planes in contact with the spheres: the planes, their springs hist(i * planes + q), the mask
// of the planes near each sphere (near_planes; empty: all) and the sphere-wall law. No planes: empty.
template <class T>
struct PlaneContacts {
  PlaneView<T> planes;
  SpringView<T> hist;
  PlaneMask near;
  HertzMindlin<T> law;
};

namespace detail {

// Sphere i (centre x, radius r, mass m, velocity v, spin w) against the planes near it, one-sided: a
// sphere whose centre is less than r behind a plane is pushed out along its normal (R* = r, m* = m, lever
// r); the forces and torques are added to f_sum, t_sum.
// root_ratio: contact::shear_root_ratio(pc.law), taken once by the caller.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION void plane_contacts(const PlaneContacts<T>& pc, Index i, const Vec3<T>& x, T r, T m, const Vec3<T>& v,
                                                const Vec3<T>& w, bool friction, T dt, T root_ratio, Vec3<T>& f_sum, Vec3<T>& t_sum) {
  const Index np = static_cast<Index>(pc.planes.extent(0));
  const std::uint32_t bits = pc.near.extent(0) == 0 ? ~std::uint32_t(0) : pc.near(i);
  if (bits == 0) return;
  const HertzMindlin<T> law = pc.law;  // a local: stores to hist cannot change it
  for (Index q = 0; q < np; ++q) {
    if (!((bits >> q) & 1u)) continue;
    const Offset k = static_cast<Offset>(i) * np + q;
    const Vec3<T> point{{pc.planes(q, 0), pc.planes(q, 1), pc.planes(q, 2)}};
    const Vec3<T> n{{pc.planes(q, 3), pc.planes(q, 4), pc.planes(q, 5)}};
    const T d = dot(x - point, n);
    const T delta = r - d;
    if (!(delta > T(0)) || !(d > -r)) {  // apart: a spring is dropped (read first: most are zero already)
      if (friction && (pc.hist(k, 0) != T(0) || pc.hist(k, 1) != T(0) || pc.hist(k, 2) != T(0))) store<3>(pc.hist, k, Vec3<T>::zero());
      continue;
    }
    const Vec3<T> v_rel = v + cross(w, (-r) * n);
    Vec3<T> xi = spring(pc.hist, k, friction);
    const auto c = hertz_mindlin_force(law, root_ratio, r, m, delta, n, v_rel, friction, dt, xi);
    if (friction) store<3>(pc.hist, k, xi);
    f_sum += c.force;
    t_sum -= r * cross(n, c.force);
  }
}

}  // namespace detail

namespace detail {

// The host's batched rows (sphere_sphere_rows on a CPU): a block of rows_block spheres per call; its touching
// pairs are gathered, in row order, into a PairBatch of contiguous arrays, the contact law runs over the batch
// as one vector loop (dem/pair_batch.cpp: eight laws per AVX-512 instruction, so the chain of square roots and
// divisions that sets a contact's latency overlaps across pairs), and the results are summed in row order as in
// the one-sphere body. The blocks, and so the batches, are fixed by the sphere indices, not by the threads: any
// thread count gives the same bits (the GPU's one-sphere body the same law, not necessarily the same bits).
inline constexpr Index rows_block = std::is_same<MemSpace, HostSpace>::value ? 16 : 1;

// Listed pair i-j (i at xi_pos, radius ri, in clump body_i, -1: none): d = x_i - x_j, |d|^2 and r_j; whether they
// touch (closer than r_i + r_j, apart from coincident, not in one clump).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION bool touching(const SphereSet<T>& s, const Vec3<T>& xi_pos, T ri, int body_i, Index j, Vec3<T>& d, T& dist2,
                                          T& rj) {
  d = xi_pos - load<3>(s.x, j);
  dist2 = norm2(d);
  rj = s.radius(j);
  const T reach = ri + rj;
  return dist2 < reach * reach && dist2 > T(0) && !(body_i >= 0 && s.body(j) == body_i);
}

// A listed pair that does not touch (apart, or both in one clump): its spring dropped (read first: most are zero
// already), its load zero.
template <class T>
KOKKOS_FORCEINLINE_FUNCTION void drop_pair(const SpringView<T>& hist, const PairLoadView<T>& pair_load, Offset k, bool friction) {
  if (friction && (hist(k, 0) != T(0) || hist(k, 1) != T(0) || hist(k, 2) != T(0))) store<3>(hist, k, Vec3<T>::zero());
  for (int c = 0; c < 6; ++c) pair_load(k, c) = T(0);
}

}  // namespace detail

// Kernel "polymech::dem::sphere_sphere": Hertz-Mindlin forces between listed spheres in contact, over a
// half list (j > i: each pair computed once), and each sphere's contacts with the analytic planes
// `planes` (if any; the same arithmetic as sphere_plane_forces, in the same pass over the spheres). A row
// is one sphere's: its pairs' force and torque go to its first member i (no atomics), what the second
// member gets to pair_load(k); sphere_sphere_gather then adds those to each j over the list's transpose,
// in increasing k. The sums are in a fixed order: any thread count gives the same bits. One tangential
// spring per pair, hist(k), from i's side (v_rel = i's contact point less j's).
// On a host the rows go by blocks of detail::rows_block spheres, the contact law vectorised over each
// block's touching pairs (detail::PairBatch); on a GPU a thread per sphere.
template <class T>
void sphere_sphere_rows(const SphereSet<T>& s, const neighbors::NeighborList& list, const SpringView<T>& hist,
                        const PairLoadView<T>& pair_load, const HertzMindlin<T>& p, bool friction, T dt,
                        const PlaneContacts<T>& planes = PlaneContacts<T>()) {
  const bool clumped = s.body.extent(0) > 0;
  const bool walls = planes.planes.extent(0) > 0;
  // sqrt(4 G* / E*) of both laws once, not per contact (contact::shear_root_ratio; the same bits)
  const T root_pp = contact::shear_root_ratio(p), root_pw = walls ? contact::shear_root_ratio(planes.law) : T(0);
  if constexpr (detail::rows_block > 1) {
    const Index n = list.num_particles, block = detail::rows_block;
    Kokkos::parallel_for(
        "polymech::dem::sphere_sphere", range((n + block - 1) / block), [=](const Index blk) {
          const HertzMindlin<T> law = p;  // locals: the stores below cannot change them
          const T h = dt, root_ratio = root_pp;
          const Index first = blk * block, last = first + block < n ? first + block : n;
          detail::PairBatch<T> b;
          Vec3<T> f_sum[detail::rows_block], t_sum[detail::rows_block];
          // the batch's law, then its results in row order (the one-sphere body's sums and stores)
          const auto flush = [&]() {
            if (friction)
              detail::batch_contacts<true>(b, law, root_ratio, h);
            else
              detail::batch_contacts<false>(b, law, root_ratio, h);
            for (int c = 0; c < b.count; ++c) {
              const Offset k = b.k[c];
              const int r = b.row[c];
              const Vec3<T> f{{b.f[0][c], b.f[1][c], b.f[2][c]}}, nxf{{b.nxf[0][c], b.nxf[1][c], b.nxf[2][c]}};
              if (friction) store<3>(hist, k, Vec3<T>{{b.xi[0][c], b.xi[1][c], b.xi[2][c]}});
              f_sum[r] += f;
              t_sum[r] -= b.li[c] * nxf;
              const T lj = b.lj[c];
              for (int q = 0; q < 3; ++q) {
                pair_load(k, q) = f[q];
                pair_load(k, 3 + q) = -lj * nxf[q];
              }
            }
            b.count = 0;
          };
          for (Index i = first; i < last; ++i) {
            const int r = static_cast<int>(i - first);
            f_sum[r] = Vec3<T>::zero();
            t_sum[r] = Vec3<T>::zero();
            const Vec3<T> xi_pos = load<3>(s.x, i);
            const T ri = s.radius(i), mi = s.mass(i);
            const int body_i = clumped ? s.body(i) : -1;
            // i's motion read once per row (locals: the batch's stores cannot change them)
            const Vec3<T> vi = load<3>(s.v, i), wi = load<3>(s.omega, i);
            for (Offset k = list.begin(i); k < list.end(i); ++k) {
              const Index j = list.neighbor(k);
              Vec3<T> d;
              T dist2, rj;
              if (!detail::touching(s, xi_pos, ri, body_i, j, d, dist2, rj)) {
                detail::drop_pair(hist, pair_load, k, friction);
                continue;
              }
              const int c = b.count++;
              b.k[c] = k;
              b.row[c] = r;
              b.dist2[c] = dist2;
              b.ri[c] = ri;
              b.rj[c] = rj;
              b.mi[c] = mi;
              b.mj[c] = s.mass(j);
              for (int q = 0; q < 3; ++q) {
                b.d[q][c] = d[q];
                b.vi[q][c] = vi[q];
                b.wi[q][c] = wi[q];
                b.vj[q][c] = s.v(j, q);
                b.wj[q][c] = s.omega(j, q);
                b.xi[q][c] = friction ? hist(k, q) : T(0);
              }
              if (b.count == detail::PairBatch<T>::capacity) flush();
            }
          }
          if (b.count > 0) flush();
          for (Index i = first; i < last; ++i) {
            const int r = static_cast<int>(i - first);
            const T ri = s.radius(i), mi = s.mass(i);
            if (walls)
              detail::plane_contacts(planes, i, load<3>(s.x, i), ri, mi, load<3>(s.v, i), load<3>(s.omega, i), friction, h, root_pw,
                                     f_sum[r], t_sum[r]);
            const T inv_inertia = T(2.5) / (mi * ri * ri);
            for (int q = 0; q < 3; ++q) {
              s.a(i, q) += f_sum[r][q] / mi;
              s.alpha(i, q) += inv_inertia * t_sum[r][q];
            }
          }
        });
  } else {
    Kokkos::parallel_for(
        "polymech::dem::sphere_sphere", range(list.num_particles), KOKKOS_LAMBDA(const Index i) {
          // the law and dt as locals: the captured copies are doubles in the closure, which the stores to
          // hist and pair_load may alias for the compiler (it would load them again after every store)
          const HertzMindlin<T> law = p;
          const T h = dt, root_ratio = root_pp;
          const Vec3<T> xi_pos = load<3>(s.x, i), vi = load<3>(s.v, i), wi = load<3>(s.omega, i);
          const T ri = s.radius(i), mi = s.mass(i);
          const int body_i = clumped ? s.body(i) : -1;
          Vec3<T> f_sum = Vec3<T>::zero(), t_sum = Vec3<T>::zero();
          for (Offset k = list.begin(i); k < list.end(i); ++k) {
            const Index j = list.neighbor(k);
            Vec3<T> d;
            T dist2, rj;
            if (!detail::touching(s, xi_pos, ri, body_i, j, d, dist2, rj)) {
              detail::drop_pair(hist, pair_load, k, friction);
              continue;
            }
            // (the same arithmetic as detail::batch_contacts, dem/pair_batch.cpp: change both together)
            const T reach = ri + rj;
            const T dist = kx::sqrt(dist2);
            const T delta = reach - dist;
            const Vec3<T> n = (T(1) / dist) * d;  // from j to i
            // Both ends act at one point, the middle of the overlap (levers r - delta / 2), so the pair's
            // forces and torques conserve angular momentum exactly (with the lever r each, a tangential
            // force would leave a couple delta n x f_t: what a clump's angular momentum then shows).
            const T li = ri - T(0.5) * delta, lj = rj - T(0.5) * delta;
            const Vec3<T> v_rel = vi + cross(wi, (-li) * n) - load<3>(s.v, j) - cross(load<3>(s.omega, j), lj * n);
            const T mj = s.mass(j);
            Vec3<T> xi = detail::spring(hist, k, friction);
            const auto c = hertz_mindlin_force(law, root_ratio, ri * rj / reach, mi * mj / (mi + mj), delta, n, v_rel, friction, h, xi);
            if (friction) store<3>(hist, k, xi);
            const Vec3<T> nxf = cross(n, c.force);
            f_sum += c.force;
            t_sum -= li * nxf;
            for (int q = 0; q < 3; ++q) {
              pair_load(k, q) = c.force[q];
              pair_load(k, 3 + q) = -lj * nxf[q];
            }
          }
          if (walls) detail::plane_contacts(planes, i, xi_pos, ri, mi, vi, wi, friction, h, root_pw, f_sum, t_sum);
          const T inv_inertia = T(2.5) / (mi * ri * ri);
          for (int q = 0; q < 3; ++q) {
            s.a(i, q) += f_sum[q] / mi;
            s.alpha(i, q) += inv_inertia * t_sum[q];
          }
        });
  }
}

// Kernel "polymech::dem::sphere_sphere_gather": each sphere j adds what its pairs as second member give it
// (pair_load over the list's transpose, in increasing k). With h > 0 (kernel
// "polymech::dem::sphere_sphere_gather_kick") it then takes velocity Verlet's second half kick in the same
// pass, v += h a, omega += h alpha (kick's arithmetic): when nothing else adds to a after the gather.
template <class T>
void sphere_sphere_gather(const SphereSet<T>& s, const neighbors::ListTranspose& transposed, const PairLoadView<T>& pair_load, T h = T(0)) {
  const bool kick = h > T(0);
  Kokkos::parallel_for(
      kick ? "polymech::dem::sphere_sphere_gather_kick" : "polymech::dem::sphere_sphere_gather", range(s.size()),
      KOKKOS_LAMBDA(const Index j) {
        Vec3<T> f_sum = Vec3<T>::zero(), t_sum = Vec3<T>::zero();
        for (Offset e = transposed.begin(j); e < transposed.end(j); ++e) {
          const Offset k = transposed.entry(e);
          for (int q = 0; q < 3; ++q) {
            f_sum[q] -= pair_load(k, q);
            t_sum[q] += pair_load(k, 3 + q);
          }
        }
        const T mj = s.mass(j), rj = s.radius(j);
        const T inv_inertia = T(2.5) / (mj * rj * rj);
        Vec3<T> aj = load<3>(s.a, j), alphaj = load<3>(s.alpha, j);
        for (int q = 0; q < 3; ++q) {
          aj[q] += f_sum[q] / mj;
          alphaj[q] += inv_inertia * t_sum[q];
        }
        store<3>(s.a, j, aj);
        store<3>(s.alpha, j, alphaj);
        if (kick) {
          Vec3<T> vj = load<3>(s.v, j), wj = load<3>(s.omega, j);
          for (int q = 0; q < 3; ++q) {
            vj[q] += h * aj[q];
            wj[q] += h * alphaj[q];
          }
          store<3>(s.v, j, vj);
          store<3>(s.omega, j, wj);
        }
      });
}

// Both sphere-sphere kernels: sphere_sphere_rows (without planes), then sphere_sphere_gather.
template <class T>
void sphere_sphere_forces(const SphereSet<T>& s, const neighbors::NeighborList& list, const neighbors::ListTranspose& transposed,
                          const SpringView<T>& hist, const PairLoadView<T>& pair_load, const HertzMindlin<T>& p, bool friction, T dt) {
  sphere_sphere_rows(s, list, hist, pair_load, p, friction, dt);
  sphere_sphere_gather(s, transposed, pair_load);
}

// Kernel "polymech::dem::near_planes": bit q of mask(i) is set when sphere i is within r_i + reach of
// plane q's front (-r_i - reach < d < r_i + reach): with reach = the Verlet skin, no sphere can touch a
// plane whose bit is clear before the next rebuild (a rebuild comes when a sphere has moved skin / 2).
// The springs of the planes whose bit is clear are zeroed (a contact that starts later starts unloaded).
template <class T>
void near_planes(const SphereSet<T>& s, const PlaneView<T>& planes, T reach, const PlaneMask& mask, const SpringView<T>& hist, bool friction) {
  const Index np = static_cast<Index>(planes.extent(0));
  Kokkos::parallel_for(
      "polymech::dem::near_planes", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        const Vec3<T> x = load<3>(s.x, i);
        const T r = s.radius(i) + reach;
        std::uint32_t bits = 0;
        for (Index q = 0; q < np; ++q) {
          const Vec3<T> point{{planes(q, 0), planes(q, 1), planes(q, 2)}};
          const Vec3<T> n{{planes(q, 3), planes(q, 4), planes(q, 5)}};
          const T d = dot(x - point, n);
          if (d < r && d > -r)
            bits |= std::uint32_t(1) << q;
          else if (friction)
            store<3>(hist, static_cast<Offset>(i) * np + q, Vec3<T>::zero());
        }
        mask(i) = bits;
      });
}

// Kernel "polymech::dem::sphere_plane": every sphere against the planes near it (`near`, near_planes;
// empty: all planes), one-sided: a sphere whose centre is less than r behind a plane is pushed out
// along its normal. hist(i * planes + q). (The DEM model does this in sphere_sphere_rows' pass.)
template <class T>
void sphere_plane_forces(const SphereSet<T>& s, const PlaneView<T>& planes, const SpringView<T>& hist,
                         const HertzMindlin<T>& p, bool friction, T dt, const PlaneMask& near = PlaneMask()) {
  const PlaneContacts<T> pc{planes, hist, near, p};
  const T root_ratio = contact::shear_root_ratio(p);
  Kokkos::parallel_for(
      "polymech::dem::sphere_plane", range(s.size()), KOKKOS_LAMBDA(const Index i) {
        const T ri = s.radius(i), mi = s.mass(i);
        Vec3<T> f_sum = Vec3<T>::zero(), t_sum = Vec3<T>::zero();
        detail::plane_contacts(pc, i, load<3>(s.x, i), ri, mi, load<3>(s.v, i), load<3>(s.omega, i), friction, dt, root_ratio, f_sum, t_sum);
        const T inv_inertia = T(2.5) / (mi * ri * ri);
        for (int q = 0; q < 3; ++q) {
          s.a(i, q) += f_sum[q] / mi;
          s.alpha(i, q) += inv_inertia * t_sum[q];
        }
      });
}

// At most this many facets in one sphere's row take part in its contacts (a row is the facets whose
// centroid lies within r + the largest facet radius + skin: a few for a mesh finer than the sphere).
inline constexpr int max_facets_per_sphere = 24;

// The rigid motion of a surface mesh (all of it one body, e.g. a wheel): a material point at q moves
// with velocity + omega x (q - centre). Zero for a fixed surface.
template <class T>
struct SurfaceMotion {
  Vec3<T> centre = Vec3<T>::zero(), velocity = Vec3<T>::zero(), omega = Vec3<T>::zero();
  KOKKOS_INLINE_FUNCTION Vec3<T> at(const Vec3<T>& q) const { return velocity + cross(omega, q - centre); }
};

// What sphere i gives the surface: the force -f of its facet contacts and its moment (q - centre) x (-f)
// about SurfaceMotion::centre, (fx, fy, fz, mx, my, mz); summed over the spheres (ordered_sum) it is
// the surface's load, minus the spheres' to round-off (the momentum exchange is exact).
template <class T>
using WrenchView = Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>;

// Per listed sphere-facet entry of a deforming surface: the force on the surface (3) and the four corner
// weights of the contact point (contact/facet_weights.hpp); row 7 unused.
template <class T>
using EntryLoadView = Kokkos::View<T* [8], Kokkos::LayoutRight, MemSpace>;

// A surface whose nodes move independently (the FE tyre's, dem/surface_loads.hpp): the nodes' velocities, and
// where each contact's force and weights go. Empty: a rigid surface.
template <class T>
struct DeformingSurface {
  VecView<T, 3> node_velocity;
  EntryLoadView<T> entry_load;
};

// Kernel "polymech::dem::sphere_facet": spheres against the facets of a surface mesh listed in `list`
// (two-set: sphere i -> facet j), by the inside-outside algorithm with one force per touching feature
// (contact/sphere_facet.hpp). R* = r and m* = m; the relative velocity of eqs. (12)-(15) is the sphere's
// surface point's less the facet's material point's: a rigid surface, fixed or moving with `motion`, or
// (kernel "polymech::dem::sphere_deforming_facet", `deforming` given) sum_a w_a v_a from its nodes' velocities
// with the contact point's corner weights, and then entry_load(k) gets the force on the surface and the weights
// of listed entry k (zero for an entry not in contact). With a non-empty `reaction`, row i gets what sphere i
// gives the (rigid) surface (WrenchView).
template <class T>
void sphere_facet_forces(const SphereSet<T>& s, const contact::SurfaceMesh<T>& mesh, const neighbors::NeighborList& list,
                         const SpringView<T>& hist, const HertzMindlin<T>& p, bool friction, T dt,
                         const SurfaceMotion<T>& motion = SurfaceMotion<T>(), const WrenchView<T>& reaction = WrenchView<T>(),
                         const DeformingSurface<T>& deforming = DeformingSurface<T>()) {
  const bool react = reaction.extent(0) > 0;
  const bool nodal = deforming.node_velocity.extent(0) > 0;
  const auto node_velocity = deforming.node_velocity;
  const auto entry_load = deforming.entry_load;
  Kokkos::parallel_for(
      nodal ? "polymech::dem::sphere_deforming_facet" : "polymech::dem::sphere_facet", range(list.num_particles), KOKKOS_LAMBDA(const Index i) {
        const Vec3<T> xi_pos = load<3>(s.x, i), vi = load<3>(s.v, i), wi = load<3>(s.omega, i);
        const T ri = s.radius(i), mi = s.mass(i);
        Vec3<T> f_sum = Vec3<T>::zero(), m_sum = Vec3<T>::zero();
        contact::FacetContact<T> c[max_facets_per_sphere];
        Index facet[max_facets_per_sphere];
        const Offset begin = list.begin(i);
        const Offset listed = list.end(i) - begin;
        const int count = static_cast<int>(kx::min<Offset>(listed, Offset(max_facets_per_sphere)));
        for (int m = 0; m < count; ++m) {
          facet[m] = list.neighbor(begin + m);
          c[m] = contact::sphere_facet_contact(mesh, facet[m], xi_pos, ri);
        }
        if (nodal)  // beyond the row's capacity: no load
          for (Offset k = begin + count; k < begin + listed; ++k)
            for (int q = 0; q < 8; ++q) entry_load(k, q) = T(0);
        bool keep[max_facets_per_sphere];
        for (int m = 0; m < count; ++m) keep[m] = contact::keep_facet_contact(mesh, facet, c, count, m);
        // A touching feature dropped as a duplicate is the same contact as a kept one: its spring goes to
        // the kept contact that has none yet, so a sphere sliding from one facet onto the next keeps it.
        Vec3<T> carried = Vec3<T>::zero();
        if (friction)
          for (int m = 0; m < count; ++m)
            if (!keep[m] && c[m].region != contact::FacetRegion::none) {
              const Vec3<T> x = load<3>(hist, begin + m);
              if (norm2(x) > norm2(carried)) carried = x;
            }
        for (int m = 0; m < count; ++m) {
          const Offset k = begin + m;
          if (!keep[m]) {
            if (friction) store<3>(hist, k, Vec3<T>::zero());
            if (nodal)
              for (int q = 0; q < 8; ++q) entry_load(k, q) = T(0);
            continue;
          }
          T w[4] = {T(0), T(0), T(0), T(0)};
          Vec3<T> v_surface;
          if (nodal) {
            contact::facet_weights(mesh, facet[m], c[m], w);
            v_surface = Vec3<T>::zero();
            for (int a = 0; a < mesh.corners(facet[m]); ++a) v_surface += w[a] * load<3>(node_velocity, mesh.facets(facet[m], a));
          } else {
            v_surface = motion.at(c[m].point);
          }
          const Vec3<T> n = c[m].normal;
          const Vec3<T> v_rel = vi + cross(wi, (-ri) * n) - v_surface;
          Vec3<T> xi = detail::spring(hist, k, friction);
          if (friction && norm2(xi) == T(0)) {
            xi = carried;
            carried = Vec3<T>::zero();
          }
          const auto f = hertz_mindlin_force(p, ri, mi, c[m].overlap, n, v_rel, friction, dt, xi);
          if (friction) store<3>(hist, k, xi);
          detail::add_contact(s, i, n, ri, ri, f.force);
          f_sum -= f.force;
          m_sum -= cross(c[m].point - motion.centre, f.force);
          if (nodal) {
            for (int q = 0; q < 3; ++q) entry_load(k, q) = -f.force[q];
            for (int a = 0; a < 4; ++a) entry_load(k, 3 + a) = w[a];
            entry_load(k, 7) = T(0);
          }
        }
        if (react)
          for (int k = 0; k < 3; ++k) {
            reaction(i, k) = f_sum[k];
            reaction(i, 3 + k) = m_sum[k];
          }
      });
}

// Kernel "polymech::dem::wheel_reaction_sum": the rows of a WrenchView summed in index order (the
// surface's total load; the same for any thread count). `partial`: the sum's chunk table, kept by the caller.
template <class T>
std::array<double, 6> wrench_sum(const WrenchView<T>& w, particles::SumPartials& partial) {
  const auto sum = particles::ordered_sum<6>(
      "polymech::dem::wheel_reaction_sum", static_cast<std::int64_t>(w.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        for (int k = 0; k < 6; ++k) acc[k] += double(w(i, k));
      },
      partial);
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) out[static_cast<std::size_t>(k)] = sum[k];
  return out;
}

}  // namespace polymech::dem
