// Galerkin assembly over MLS shape functions (seed 004, Hagihara et al., eqs. (7), (8)): the stiffness
// and consistent mass of 2D linear elasticity, summed over integration points into a node pattern of
// 2x2 blocks (block CSR: row_ptr / cols, the nodes whose supports overlap). The model (models/efg)
// builds the pattern and turns the blocks into a sparse matrix.
//
// One node (pattern row) per thread with no atomics: each node reads the entries of the shape-function
// rows that belong to it (node_entries, in increasing point order), so the sums are in a fixed order
// whatever the thread count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "mls/mls.hpp"

namespace polymech::mls {

// Index of `col` in the sorted cols[b, e) (the pattern contains it by construction).
KOKKOS_INLINE_FUNCTION Offset find_col(const View1<Index>& cols, Offset b, Offset e, Index col) {
  while (b < e) {
    const Offset m = b + (e - b) / 2;
    if (cols(m) < col)
      b = m + 1;
    else
      e = m;
  }
  return b;
}

// The entries of the shape-function rows that belong to each node, in increasing point order: node I's
// entries are node_entry(node_ptr(I)) .. node_entry(node_ptr(I + 1) - 1), at the points node_point(..).
struct NodeEntries {
  Kokkos::View<Offset*, MemSpace> node_ptr;
  View1<Offset> node_entry;
  View1<Index> node_point;
};

// Built on the host (a counting sort of the rows' node indices).
template <class T>
NodeEntries node_entries(const ShapeFunctions<T>& sf, Index nodes) {
  auto off = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.offsets);
  auto nb = Kokkos::create_mirror_view_and_copy(HostSpace(), sf.rows.neighbors);
  NodeEntries e;
  e.node_ptr = Kokkos::View<Offset*, MemSpace>("polymech::efg::node_ptr", static_cast<std::size_t>(nodes) + 1);
  const auto total = static_cast<std::size_t>(sf.rows.num_pairs);
  e.node_entry = View1<Offset>("polymech::efg::node_entry", total + 1);
  e.node_point = View1<Index>("polymech::efg::node_point", total + 1);
  auto hp = Kokkos::create_mirror_view(e.node_ptr);
  auto he = Kokkos::create_mirror_view(e.node_entry);
  auto hq = Kokkos::create_mirror_view(e.node_point);
  std::vector<Offset> count(static_cast<std::size_t>(nodes) + 1, 0);
  for (std::size_t k = 0; k < total; ++k) ++count[static_cast<std::size_t>(nb(k)) + 1];
  for (std::size_t i = 0; i < static_cast<std::size_t>(nodes); ++i) count[i + 1] += count[i];
  for (std::size_t i = 0; i <= static_cast<std::size_t>(nodes); ++i) hp(i) = count[i];
  for (Index q = 0; q < sf.points; ++q)
    for (Offset k = off(q); k < off(q + 1); ++k) {
      const auto slot = static_cast<std::size_t>(count[static_cast<std::size_t>(nb(k))]++);
      he(slot) = k;
      hq(slot) = q;
    }
  Kokkos::deep_copy(e.node_ptr, hp);
  Kokkos::deep_copy(e.node_entry, he);
  Kokkos::deep_copy(e.node_point, hq);
  return e;
}

// seed 004 eqs. (7), (8): K_IJ += w_q B_I^T D B_J and M_IJ += w_q rho phi_I phi_J at every Gauss point q
// of node I's support, for every node J of q's row, into the 2x2 blocks (4 values per pattern entry,
// row-major) and the mass values (1 per entry) of the node pattern. lam, mu: the Lame constants of D
// (plane strain, or the plane-stress lambda). One node (pattern row) per thread.
template <class T>
void assemble_stiffness_mass(const ShapeFunctions<T>& sf, const NodeEntries& ne, const View1<T>& weight,
                             const Kokkos::View<Offset*, MemSpace>& row_ptr, const View1<Index>& cols, const View1<T>& values,
                             const View1<T>& mass, T lam, T mu, T rho) {
  const auto rows = sf.rows;
  const auto phi = sf.phi;
  const auto dphi = sf.dphi;
  const T c11 = lam + T(2) * mu;
  const auto n = static_cast<std::int64_t>(ne.node_ptr.extent(0)) - 1;
  Kokkos::parallel_for(
      "polymech::efg::stiffness_mass", range(n), KOKKOS_LAMBDA(const std::int64_t ia) {
        const Offset rb = row_ptr(ia), re = row_ptr(ia + 1);
        for (Offset t = ne.node_ptr(ia); t < ne.node_ptr(ia + 1); ++t) {
          const Offset ka = ne.node_entry(t);
          const Index q = ne.node_point(t);
          const T w = weight(q);
          const T ax = dphi(ka, 0) * w, ay = dphi(ka, 1) * w, pa = phi(ka) * w * rho;
          for (Offset kb = rows.offsets(q); kb < rows.offsets(q + 1); ++kb) {
            const T bx = dphi(kb, 0), by = dphi(kb, 1);
            const Offset s = find_col(cols, rb, re, rows.neighbors(kb));
            values(4 * s + 0) += ax * c11 * bx + ay * mu * by;
            values(4 * s + 1) += ax * lam * by + ay * mu * bx;
            values(4 * s + 2) += ay * lam * bx + ax * mu * by;
            values(4 * s + 3) += ay * c11 * by + ax * mu * bx;
            mass(s) += pa * phi(kb);
          }
        }
      });
}

}  // namespace polymech::mls
