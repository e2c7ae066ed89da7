// Boundary terms of the Helmholtz system on element faces (seed 002 paper 3):
//  - face mass with a complex coefficient, y += c (int N^T N dGamma) x: the impedance term
//    j rho omega C of eq. (16) with C_e = (1/Zn) int N^T N dGamma, eq. (19), c = j rho omega / Zn;
//  - face load, q += c int N^T dGamma: the vibrating-boundary source of eq. (20), c = v.
// A face is the N x N GLL nodes of one element side, listed face-lexicographically (first tangential
// reference direction fastest); Q x Q Gauss points carry the surface weight w_a w_b |x_s x x_t| of the
// isoparametric face. Faces are grouped by colour (faces of one colour share no DoF).
#pragma once

#include "fem/hex_elements.hpp"

namespace polymech::fem {

template <class T, class V>
struct HexFaces {
  int order = 1;
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> dofs;  // [faces][N^2], encoded as HexElements::dofs
  Kokkos::View<T**, Kokkos::LayoutRight, MemSpace> weights;   // [faces][Q^2]
  View1<V> coefficient;                                       // [faces]
  std::vector<Index> color_offsets;                           // host

  Index faces() const { return static_cast<Index>(dofs.extent(0)); }
  int colors() const { return color_offsets.empty() ? 0 : static_cast<int>(color_offsets.size()) - 1; }
};

namespace detail {

template <class T, int N, int Q>
struct FaceMatrix {  // a Q x N matrix captured by value into a kernel
  T M[Q][N];
};

template <class T, class V, int N>
double compute_face_weights(HexFaces<T, V>& f, const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x) {
  constexpr int Q = N, N2 = N * N, Q2 = Q * Q;
  const HexBasis<double, N, Q> b = make_hex_basis<double, N, Q>();
  const auto dofs = f.dofs;
  const auto w = f.weights;
  double min_area = 0.0;
  Kokkos::parallel_reduce(
      "polymech::fem::face_geometry", range(f.faces()),
      KOKKOS_LAMBDA(const Index face, double& lo) {
        double X[N2], xs[3][Q2], xt[3][Q2], tmp[Q * N];
        for (int c = 0; c < 3; ++c) {
          for (int a = 0; a < N2; ++a) X[a] = x(decode_dof(dofs(face, a)), c);
          contract<0, N, Q, N, N, 1, false, false>(b.D, X, tmp);  // d/ds
          contract<1, N, Q, Q, N, 1, false, false>(b.B, tmp, xs[c]);
          contract<0, N, Q, N, N, 1, false, false>(b.B, X, tmp);  // d/dt
          contract<1, N, Q, Q, N, 1, false, false>(b.D, tmp, xt[c]);
        }
        double area = 0.0, smallest = 1e300;
        for (int q = 0; q < Q2; ++q) {
          const Vec3<double> s{{xs[0][q], xs[1][q], xs[2][q]}}, t{{xt[0][q], xt[1][q], xt[2][q]}};
          const double js = norm(cross(s, t));
          const double wq = b.w[q % Q] * b.w[q / Q] * js;
          w(face, q) = static_cast<T>(wq);
          area += wq;
          if (js < smallest) smallest = js;
        }
        const double ratio = area > 0 ? smallest / (area / 4.0) : 0.0;
        if (ratio < lo) lo = ratio;
      },
      Kokkos::Min<double>(min_area));
  return min_area;
}

template <class T, class V, int N, bool Constrained>
void apply_face_mass(const char* label, const HexFaces<T, V>& f, const View1<V>& x, const View1<V>& y) {
  constexpr int Q = N, N2 = N * N, Q2 = Q * Q;
  const HexBasis<T, N, Q> b = make_hex_basis<T, N, Q>();
  const auto dofs = f.dofs;
  const auto w = f.weights;
  const auto coef = f.coefficient;
  parallel_for_colors(label, f.color_offsets, KOKKOS_LAMBDA(const Index face) {
    V u[N2], uq[Q2], tmp[Q * N];
    gather<Constrained, N2>(dofs, face, x, u);
    interpolate_2d<N, Q>(b.B, u, uq, tmp);
    const V cf = coef(face);
    for (int q = 0; q < Q2; ++q) uq[q] = (cf * w(face, q)) * uq[q];
    integrate_2d<N, Q>(b.B, uq, u, tmp);
    scatter_add<Constrained, N2>(dofs, face, u, y);
  });
}

// out += c_f int M(s) M(t) w dGamma per face node: with M = B the load int N dGamma (eq. (20)), with
// M = B^2 the diagonal of the face mass (eq. (19)).
template <class T, class V, int N>
void integrate_face_weights(const char* label, const HexFaces<T, V>& f, const T (&M)[N][N], const View1<V>& out) {
  constexpr int Q = N, N2 = N * N, Q2 = Q * Q;
  FaceMatrix<T, N, Q> m{};
  for (int q = 0; q < Q; ++q)
    for (int i = 0; i < N; ++i) m.M[q][i] = M[q][i];
  const auto dofs = f.dofs;
  const auto w = f.weights;
  const auto coef = f.coefficient;
  parallel_for_colors(label, f.color_offsets, KOKKOS_LAMBDA(const Index face) {
    T wq[Q2], v[N2], tmp[Q * N];
    for (int q = 0; q < Q2; ++q) wq[q] = w(face, q);
    integrate_2d<N, Q>(m.M, wq, v, tmp);
    const V cf = coef(face);
    V cv[N2];
    for (int a = 0; a < N2; ++a) cv[a] = cf * v[a];
    scatter_add<true, N2>(dofs, face, cv, out);
  });
}

template <class T, class V, int N>
void add_face_mass_diagonal(const HexFaces<T, V>& f, const View1<V>& diag) {
  const HexBasis<T, N, N> b = make_hex_basis<T, N, N>();
  T BB[N][N];
  for (int q = 0; q < N; ++q)
    for (int i = 0; i < N; ++i) BB[q][i] = b.B[q][i] * b.B[q][i];
  integrate_face_weights<T, V, N>("polymech::fem::impedance_diagonal", f, BB, diag);
}

template <class T, class V, int N>
void add_face_load(const HexFaces<T, V>& f, const View1<V>& rhs) {
  const HexBasis<T, N, N> b = make_hex_basis<T, N, N>();
  integrate_face_weights<T, V, N>("polymech::fem::boundary_load", f, b.B, rhs);
}

}  // namespace detail

// Surface weights of every face from the DoF coordinates; returns the smallest |x_s x x_t| relative
// to the mean over its face (0 for a degenerate face).
// `label` names the allocation (the owning effect's name in it, for the kernel census).
template <class T, class V>
double compute_face_weights(HexFaces<T, V>& f, const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                            const std::string& label) {
  double r = 0.0;
  with_nodes(f.order, [&](auto n) {
    constexpr int Q = decltype(n)::value;
    f.weights = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>(label, f.faces(), Q * Q);
    r = detail::compute_face_weights<T, V, decltype(n)::value>(f, x);
  });
  return r;
}

// y += c_f (int N^T N dGamma) x over the faces (eq. (19) with c_f = j rho omega / Zn), on the free DoFs.
template <class T, class V>
void apply_face_mass(const HexFaces<T, V>& f, const View1<V>& x, const View1<V>& y) {
  with_nodes(f.order, [&](auto n) {
    detail::apply_face_mass<T, V, decltype(n)::value, true>("polymech::fem::impedance_apply", f, x, y);
  });
}

// The same over every DoF, constrained ones included (Dirichlet lifting next to an impedance face).
template <class T, class V>
void apply_face_mass_unconstrained(const HexFaces<T, V>& f, const View1<V>& x, const View1<V>& y) {
  with_nodes(f.order, [&](auto n) {
    detail::apply_face_mass<T, V, decltype(n)::value, false>("polymech::fem::impedance_lift", f, x, y);
  });
}

template <class T, class V>
void add_face_mass_diagonal(const HexFaces<T, V>& f, const View1<V>& diag) {
  with_nodes(f.order, [&](auto n) { detail::add_face_mass_diagonal<T, V, decltype(n)::value>(f, diag); });
}

// rhs += c_f int N^T dGamma over the faces (eq. (20) with c_f = v).
template <class T, class V>
void add_face_load(const HexFaces<T, V>& f, const View1<V>& rhs) {
  with_nodes(f.order, [&](auto n) { detail::add_face_load<T, V, decltype(n)::value>(f, rhs); });
}

}  // namespace polymech::fem
