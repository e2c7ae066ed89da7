// External loads of the solid weak form (issue 34): f_ext = int_Omega N^T b dOmega + int_Gamma_t N^T t dGamma.
//  - body force b: values at the elements' Gauss points (the caller evaluates its field at the points
//    quadrature_points() returns), integrated with w det J and scattered colour by colour;
//  - surface traction t (constant on each face): the face weights w_a (w_b) |x_s (x x_t)| of the
//    isoparametric face (3D: a quadrilateral face of N x N nodes, 2D: an edge of N nodes) integrate N_a,
//    as fem::boundary_faces.hpp does for the scalar load of eq. (20).
// Set-up kernels, in double where they touch the geometry; the load vectors are in T.
#pragma once

#include <vector>

#include "solid/elements.hpp"

namespace polymech::solid {

namespace detail {

template <class T, int D, int N>
void quadrature_points(const SolidElements<T, D>& el, const NodeCoordinates<D>& x,
                       const Kokkos::View<double***, Kokkos::LayoutRight, MemSpace>& out) {
  constexpr int QD = power<D>(N);
  const fem::HexBasis<double, N, N> b = fem::make_hex_basis<double, N, N>();
  const auto dofs = el.cells.dofs;
  Kokkos::parallel_for(
      "polymech::solid::quadrature_points", range(el.elements()), KOKKOS_LAMBDA(const Index e) {
        ElementJacobians<D, N, N> j;
        element_jacobians<D, N, N>(b, dofs, e, x, j);
        for (int q = 0; q < QD; ++q)
          for (int c = 0; c < D; ++c) out(e, q, c) = j.Xq[c][q];
      });
}

}  // namespace detail

// Coordinates of the Q^D Gauss points of every element: [elements][Q^D][D] (the points of the operator).
template <class T, int D>
Kokkos::View<double***, Kokkos::LayoutRight, MemSpace> quadrature_points(const SolidElements<T, D>& el,
                                                                         const NodeCoordinates<D>& x) {
  Kokkos::View<double***, Kokkos::LayoutRight, MemSpace> out;
  fem::with_nodes(el.order(), [&](auto n) {
    constexpr int N = decltype(n)::value;
    out = Kokkos::View<double***, Kokkos::LayoutRight, MemSpace>("polymech::solid::quadrature_points", el.elements(),
                                                                 power<D>(N), D);
    detail::quadrature_points<T, D, N>(el, x, out);
  });
  return out;
}

namespace detail {

// Nodal values from the weighted values at the points (B^T along every direction; Q = N).
template <int D, int N, class B, class V>
KOKKOS_INLINE_FUNCTION void integrate_element(const B& basis, const V* vq, V* r, V* t1, V* t2) {
  if constexpr (D == 3)
    fem::integrate<N, N, false>(basis, vq, r, t1, t2);
  else
    fem::integrate_2d<N, N>(basis, vq, r, t1);
}

template <class T, int D, int N>
void add_body_force(const SolidElements<T, D>& el, const Kokkos::View<double***, Kokkos::LayoutRight, MemSpace>& body,
                    const View1<T>& f) {
  constexpr int Q = N, ND = power<D>(N);
  const fem::HexBasis<T, N, Q> b = fem::make_hex_basis<T, N, Q>();
  const auto dofs = el.cells.dofs;
  const GeometryViews<T, D> geo(el);
  fem::parallel_for_batches("polymech::solid::body_force", el.cells, KOKKOS_LAMBDA(const Index e0, const int count, int) {
    const Index row = geo.slot(e0);
    for (int l = 0; l < count; ++l) {
      const Index e = e0 + l;
      for (int c = 0; c < D; ++c) {
        T v[ND], r[ND], t1[ND], t2[ND], Ji[D][D];
        for (int q = 0; q < ND; ++q) v[q] = geo.template at<Q>(row, e0, l, q, b.w, Ji) * static_cast<T>(body(e, q, c));
        integrate_element<D, N>(b.B, v, r, t1, t2);
        for (int a = 0; a < ND; ++a) f(D * fem::decode_dof(dofs(e, a)) + c) += r[a];
      }
    }
  });
}

}  // namespace detail

// f += int N^T b dOmega for body-force values b(e, q, c) at the points of quadrature_points(), every DoF
// (the model overwrites the constrained rows).
template <class T, int D>
void add_body_force(const SolidElements<T, D>& el, const Kokkos::View<double***, Kokkos::LayoutRight, MemSpace>& body,
                    const View1<T>& f) {
  fem::with_nodes(el.order(), [&](auto n) { detail::add_body_force<T, D, decltype(n)::value>(el, body, f); });
}

// Boundary faces carrying a traction: their nodes (face-lexicographic, fem::HexFaces' order), surface
// weights at the Q^(D-1) points, and the traction vector of each face.
template <class T, int D>
struct TractionFaces {
  int order = 1;
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> nodes;     // [faces][N^(D-1)], decode with fem::decode_dof
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> weights;  // [faces][Q^(D-1)]
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> traction;  // [faces][D]
  Index faces() const { return static_cast<Index>(nodes.extent(0)); }
};

namespace detail {

// Surface weight w_a (w_b) |x_s (x x_t)| at the Q^(D-1) points of a face from its node coordinates X[D][N^(D-1)].
template <int D, int N>
KOKKOS_INLINE_FUNCTION void face_weights(const fem::HexBasis<double, N, N>& b, const double (&X)[D][D == 3 ? N * N : N],
                                         double* w) {
  constexpr int Q = N, NF = D == 3 ? N * N : N;
  double xs[D][NF], xt[D][NF], tmp[NF];
  for (int c = 0; c < D; ++c) {
    if constexpr (D == 3) {
      fem::contract<0, N, Q, N, N, 1, false, false>(b.D, X[c], tmp);  // d/ds
      fem::contract<1, N, Q, Q, N, 1, false, false>(b.B, tmp, xs[c]);
      fem::contract<0, N, Q, N, N, 1, false, false>(b.B, X[c], tmp);  // d/dt
      fem::contract<1, N, Q, Q, N, 1, false, false>(b.D, tmp, xt[c]);
    } else {
      fem::contract<0, N, Q, N, 1, 1, false, false>(b.D, X[c], xs[c]);
    }
  }
  for (int q = 0; q < NF; ++q) {
    if constexpr (D == 3) {
      const double c0 = xs[1][q] * xt[2][q] - xs[2][q] * xt[1][q];
      const double c1 = xs[2][q] * xt[0][q] - xs[0][q] * xt[2][q];
      const double c2 = xs[0][q] * xt[1][q] - xs[1][q] * xt[0][q];
      w[q] = kx::sqrt(c0 * c0 + c1 * c1 + c2 * c2) * b.w[q % Q] * b.w[q / Q];
    } else {
      w[q] = kx::sqrt(xs[0][q] * xs[0][q] + xs[1][q] * xs[1][q]) * b.w[q];
    }
  }
}

// int_face N_a dGamma from the weights at the points (B^T along the face's directions).
template <int D, int N>
KOKKOS_INLINE_FUNCTION void face_integral(const fem::HexBasis<double, N, N>& b, const double* wq, double* v) {
  constexpr int NF = D == 3 ? N * N : N;
  double tmp[NF];
  if constexpr (D == 3)
    fem::integrate_2d<N, N>(b.B, wq, v, tmp);
  else
    fem::contract<0, N, N, N, 1, 1, true, false>(b.B, wq, v);
}

template <class T, int D, int N>
double compute_face_weights(TractionFaces<T, D>& f, const NodeCoordinates<D>& x) {
  constexpr int NF = D == 3 ? N * N : N;
  f.weights = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::face_weights", f.faces(), NF);
  const fem::HexBasis<double, N, N> b = fem::make_hex_basis<double, N, N>();
  const auto nodes = f.nodes;
  const auto w = f.weights;
  double total = 0.0;
  Kokkos::parallel_reduce(
      "polymech::solid::face_weights", range(f.faces()),
      KOKKOS_LAMBDA(const Index face, double& sum) {
        double X[D][NF], wq[NF];
        for (int c = 0; c < D; ++c)
          for (int a = 0; a < NF; ++a) X[c][a] = x(fem::decode_dof(nodes(face, a)), c);
        face_weights<D, N>(b, X, wq);
        for (int q = 0; q < NF; ++q) {
          w(face, q) = wq[q];
          sum += wq[q];
        }
      },
      total);
  return total;
}

template <class T, int D, int N>
void add_face_tractions(const TractionFaces<T, D>& f, const View1<T>& load) {
  constexpr int NF = D == 3 ? N * N : N;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> nodal("polymech::solid::face_loads", f.faces(), NF);
  const fem::HexBasis<double, N, N> b = fem::make_hex_basis<double, N, N>();
  const auto w = f.weights;
  Kokkos::parallel_for(
      "polymech::solid::face_tractions", range(f.faces()), KOKKOS_LAMBDA(const Index face) {
        double wq[NF], v[NF];
        for (int q = 0; q < NF; ++q) wq[q] = w(face, q);
        face_integral<D, N>(b, wq, v);
        for (int a = 0; a < NF; ++a) nodal(face, a) = v[a];
      });
  const auto nh = Kokkos::create_mirror_view_and_copy(HostSpace(), nodal);
  const auto node_h = Kokkos::create_mirror_view_and_copy(HostSpace(), f.nodes);
  const auto t_h = Kokkos::create_mirror_view_and_copy(HostSpace(), f.traction);
  auto lh = Kokkos::create_mirror_view_and_copy(HostSpace(), load);
  for (Index face = 0; face < f.faces(); ++face)
    for (int a = 0; a < NF; ++a)
      for (int c = 0; c < D; ++c)
        lh(D * fem::decode_dof(node_h(face, a)) + c) += static_cast<T>(t_h(face, c) * nh(face, a));
  Kokkos::deep_copy(load, lh);
}

}  // namespace detail

// Surface weights of every face from the node coordinates; returns the total measure (area or length).
template <class T, int D>
double compute_face_weights(TractionFaces<T, D>& f, const NodeCoordinates<D>& x) {
  double total = 0.0;
  fem::with_nodes(f.order, [&](auto n) { total = detail::compute_face_weights<T, D, decltype(n)::value>(f, x); });
  return total;
}

// f += int_face N^T t dGamma over the faces, every DoF. Each face's nodal loads are computed in parallel and
// summed on the host in face order, so the result does not depend on the thread count (set-up only).
template <class T, int D>
void add_face_tractions(const TractionFaces<T, D>& f, const View1<T>& load) {
  if (f.faces() == 0) return;
  fem::with_nodes(f.order, [&](auto n) { detail::add_face_tractions<T, D, decltype(n)::value>(f, load); });
}

}  // namespace polymech::solid
