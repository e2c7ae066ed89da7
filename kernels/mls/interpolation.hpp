// A 2D vector field and its gradient at points from nodal coefficients and MLS shape functions (seed 004,
// Hagihara et al., eq. (1): u_h(x) = sum_I phi_I(x) u_I, and its derivatives through d phi_I / dx_k).
#pragma once

#include "core/types.hpp"
#include "mls/mls.hpp"

namespace polymech::mls {

// Per point: (ux, uy, ux_x, ux_y, uy_x, uy_y).
template <class T>
using PointFields = Kokkos::View<T* [6], Kokkos::LayoutRight, MemSpace>;

// u and its gradient at the points of `sf`: out(i) = (ux, uy, ux_x, ux_y, uy_x, uy_y), u_h = sum_I phi_I u_I,
// from the coefficients u (ux, uy interleaved per node).
template <class T>
void interpolate(const ShapeFunctions<T>& sf, const View1<T>& u, const PointFields<T>& out) {
  const auto rows = sf.rows;
  const auto phi = sf.phi;
  const auto dphi = sf.dphi;
  Kokkos::parallel_for(
      "polymech::efg::interpolate", range(sf.points), KOKKOS_LAMBDA(const Index i) {
        T v[6] = {};
        for (Offset k = rows.offsets(i); k < rows.offsets(i + 1); ++k) {
          const Index n = rows.neighbors(k);
          const T ux = u(2 * n), uy = u(2 * n + 1);
          v[0] += phi(k) * ux;
          v[1] += phi(k) * uy;
          v[2] += dphi(k, 0) * ux;
          v[3] += dphi(k, 1) * ux;
          v[4] += dphi(k, 0) * uy;
          v[5] += dphi(k, 1) * uy;
        }
        for (int c = 0; c < 6; ++c) out(i, c) = v[c];
      });
}

}  // namespace polymech::mls
