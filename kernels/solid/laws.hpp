// Small-strain laws as the solid element kernel sees them (issue 34): at each quadrature point the
// kernel forms the Voigt strain of the batch (kernels/materials/voigt.hpp: engineering shears; in 2D the
// (11, 22, 12) components) and asks the law for the stress. A law is a struct with
//   template <int D, int E, class P> KOKKOS_FORCEINLINE_FUNCTION Batch batch(Index e0, int count) const;
// returning what the law reads for the batch of elements e0 .. e0 + count - 1 (lanes of P), with
//   KOKKOS_FORCEINLINE_FUNCTION void stress(int q, const P (&eps)[S], P (&sig)[S]) const;   // S = 6 or 3
// So one kernel serves the linear operator (sigma = C_e eps), the tangent of a nonlinear law (a C per
// quadrature point, PointStiffness) and, later, a residual f_int(u) with history: a law that returns the
// stress of its return mapping from the strain and its stored state at point q.
#pragma once

#include "fem/helmholtz_operator.hpp"
#include "solid/elements.hpp"

namespace polymech::solid {

// Reduced Voigt index of the tensor pair (i, j) in D dimensions: 3D (11, 22, 33, 23, 13, 12), 2D (11, 22, 12).
template <int D>
KOKKOS_INLINE_FUNCTION constexpr int pair_index(int i, int j) {
  return i == j ? i : (D == 3 ? 6 - i - j : 2);
}

// The reduced Voigt strain (engineering shears) of a displacement gradient H[c][j] = du_c / dx_j.
template <int D, class V>
KOKKOS_FORCEINLINE_FUNCTION void voigt_strain(const V (&H)[D][D], V (&eps)[strain_components<D>]) {
  for (int i = 0; i < D; ++i) eps[i] = H[i][i];
  if constexpr (D == 3) {
    eps[3] = H[1][2] + H[2][1];
    eps[4] = H[0][2] + H[2][0];
    eps[5] = H[0][1] + H[1][0];
  } else {
    eps[2] = H[0][1] + H[1][0];
  }
}

// sigma = C eps with the dense reduced S x S block of C.
template <int S, class P>
struct DenseStiffnessBatch {
  P c[S][S];
  KOKKOS_FORCEINLINE_FUNCTION void stress(int, const P (&eps)[S], P (&sig)[S]) const {
    for (int i = 0; i < S; ++i) {
      P s = c[i][0] * eps[0];
      for (int j = 1; j < S; ++j) s += c[i][j] * eps[j];
      sig[i] = s;
    }
  }
};

// Linear elasticity with one Voigt stiffness per element (SolidElements::material).
template <class T>
struct ElementStiffness {
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> material;  // [elements][36]

  template <int D, int E, class P>
  KOKKOS_FORCEINLINE_FUNCTION DenseStiffnessBatch<strain_components<D>, P> batch(Index e0, int count) const {
    constexpr int S = strain_components<D>;
    DenseStiffnessBatch<S, P> b;
    for (int i = 0; i < S; ++i)
      for (int j = 0; j < S; ++j) {
        const int k = 6 * voigt_component<D>(i) + voigt_component<D>(j);
        b.c[i][j] = fem::detail::element_lanes<E, 1, P>(count, [&](int l) { return material(e0 + l, k); });
      }
    return b;
  }
};

// A tangent per quadrature point: c(e, q, 6 i + j) (a nonlinear law's consistent tangent, Newton's
// tangent apply).
template <int S, class P, class V>
struct PointStiffnessBatch {
  V c;
  Index e0;
  int count;
  KOKKOS_FORCEINLINE_FUNCTION void stress(int q, const P (&eps)[S], P (&sig)[S]) const {
    constexpr int E = P::size;
    for (int i = 0; i < S; ++i) {
      P s = P::broadcast(0);
      for (int j = 0; j < S; ++j) {
        const int k = 6 * (S == 6 ? i : (i == 2 ? 5 : i)) + (S == 6 ? j : (j == 2 ? 5 : j));
        s += fem::detail::element_lanes<E, 1, P>(count, [&](int l) { return c(e0 + l, q, k); }) * eps[j];
      }
      sig[i] = s;
    }
  }
};

template <class T>
struct PointStiffness {
  Kokkos::View<T***, Kokkos::LayoutRight, MemSpace> tangent;  // [elements][Q^D][36]

  template <int D, int E, class P>
  KOKKOS_FORCEINLINE_FUNCTION PointStiffnessBatch<strain_components<D>, P, Kokkos::View<T***, Kokkos::LayoutRight, MemSpace>>
  batch(Index e0, int count) const {
    return {tangent, e0, count};
  }
};

}  // namespace polymech::solid
