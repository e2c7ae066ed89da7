// Small fixed-size vectors and matrices usable in device code (2D and 3D).
//
// Deliberately minimal: aggregates with element access, the arithmetic the kernels need, det and
// inverse for 2x2/3x3. No expression templates: the compiler sees plain loops over D <= 3 and
// unrolls them.
#pragma once

#include "core/kokkos_shim.hpp"

namespace polymech {

template <class T, int D>
struct Vec {
  static_assert(D == 2 || D == 3, "Vec is for 2D and 3D");
  T v[D];

  KOKKOS_INLINE_FUNCTION T& operator[](int i) { return v[i]; }
  KOKKOS_INLINE_FUNCTION const T& operator[](int i) const { return v[i]; }

  KOKKOS_INLINE_FUNCTION static Vec zero() {
    Vec r{};
    for (int i = 0; i < D; ++i) r.v[i] = T(0);
    return r;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator+=(const Vec& b) {
    for (int i = 0; i < D; ++i) v[i] += b.v[i];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator-=(const Vec& b) {
    for (int i = 0; i < D; ++i) v[i] -= b.v[i];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator*=(T s) {
    for (int i = 0; i < D; ++i) v[i] *= s;
    return *this;
  }
};

template <class T>
using Vec2 = Vec<T, 2>;
template <class T>
using Vec3 = Vec<T, 3>;

template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator+(Vec<T, D> a, const Vec<T, D>& b) {
  return a += b;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator-(Vec<T, D> a, const Vec<T, D>& b) {
  return a -= b;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator-(Vec<T, D> a) {
  for (int i = 0; i < D; ++i) a.v[i] = -a.v[i];
  return a;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator*(T s, Vec<T, D> a) {
  return a *= s;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator*(Vec<T, D> a, T s) {
  return a *= s;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION T dot(const Vec<T, D>& a, const Vec<T, D>& b) {
  T s = T(0);
  for (int i = 0; i < D; ++i) s += a.v[i] * b.v[i];
  return s;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION T norm2(const Vec<T, D>& a) {
  return dot(a, a);
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION T norm(const Vec<T, D>& a) {
  return kx::sqrt(dot(a, a));
}

// 2D cross product (the z component of a x b).
template <class T>
KOKKOS_INLINE_FUNCTION T cross(const Vec2<T>& a, const Vec2<T>& b) {
  return a.v[0] * b.v[1] - a.v[1] * b.v[0];
}
template <class T>
KOKKOS_INLINE_FUNCTION Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return Vec3<T>{{a.v[1] * b.v[2] - a.v[2] * b.v[1], a.v[2] * b.v[0] - a.v[0] * b.v[2],
                  a.v[0] * b.v[1] - a.v[1] * b.v[0]}};
}
// 2D: rotate by +90 degrees (J a), so that cross(a, b) == dot(perp(a), b).
template <class T>
KOKKOS_INLINE_FUNCTION Vec2<T> perp(const Vec2<T>& a) {
  return Vec2<T>{{-a.v[1], a.v[0]}};
}

// Row-major D x D matrix.
template <class T, int D>
struct Mat {
  static_assert(D == 2 || D == 3, "Mat is for 2D and 3D");
  T a[D][D];

  KOKKOS_INLINE_FUNCTION T& operator()(int i, int j) { return a[i][j]; }
  KOKKOS_INLINE_FUNCTION const T& operator()(int i, int j) const { return a[i][j]; }

  KOKKOS_INLINE_FUNCTION static Mat zero() {
    Mat m{};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) m.a[i][j] = T(0);
    return m;
  }
  KOKKOS_INLINE_FUNCTION static Mat identity() {
    Mat m = zero();
    for (int i = 0; i < D; ++i) m.a[i][i] = T(1);
    return m;
  }
  KOKKOS_INLINE_FUNCTION Mat& operator+=(const Mat& b) {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a[i][j] += b.a[i][j];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Mat& operator-=(const Mat& b) {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a[i][j] -= b.a[i][j];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Mat& operator*=(T s) {
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) a[i][j] *= s;
    return *this;
  }
};

template <class T>
using Mat2 = Mat<T, 2>;
template <class T>
using Mat3 = Mat<T, 3>;

template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> operator+(Mat<T, D> a, const Mat<T, D>& b) {
  return a += b;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> operator-(Mat<T, D> a, const Mat<T, D>& b) {
  return a -= b;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> operator*(T s, Mat<T, D> a) {
  return a *= s;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Vec<T, D> operator*(const Mat<T, D>& m, const Vec<T, D>& x) {
  Vec<T, D> y = Vec<T, D>::zero();
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) y.v[i] += m.a[i][j] * x.v[j];
  return y;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> operator*(const Mat<T, D>& A, const Mat<T, D>& B) {
  Mat<T, D> C = Mat<T, D>::zero();
  for (int i = 0; i < D; ++i)
    for (int k = 0; k < D; ++k)
      for (int j = 0; j < D; ++j) C.a[i][j] += A.a[i][k] * B.a[k][j];
  return C;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> transpose(const Mat<T, D>& m) {
  Mat<T, D> t;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) t.a[i][j] = m.a[j][i];
  return t;
}
// a (x) b: outer product.
template <class T, int D>
KOKKOS_INLINE_FUNCTION Mat<T, D> outer(const Vec<T, D>& x, const Vec<T, D>& y) {
  Mat<T, D> m;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) m.a[i][j] = x.v[i] * y.v[j];
  return m;
}
template <class T, int D>
KOKKOS_INLINE_FUNCTION T trace(const Mat<T, D>& m) {
  T s = T(0);
  for (int i = 0; i < D; ++i) s += m.a[i][i];
  return s;
}

template <class T>
KOKKOS_INLINE_FUNCTION T det(const Mat2<T>& m) {
  return m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0];
}
template <class T>
KOKKOS_INLINE_FUNCTION T det(const Mat3<T>& m) {
  return m.a[0][0] * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]) -
         m.a[0][1] * (m.a[1][0] * m.a[2][2] - m.a[1][2] * m.a[2][0]) +
         m.a[0][2] * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
}

// Inverse by the adjugate. The caller checks det != 0 (kernels cannot throw); a singular matrix
// gives inf/NaN entries, which the callers' finiteness checks report.
template <class T>
KOKKOS_INLINE_FUNCTION Mat2<T> inverse(const Mat2<T>& m) {
  const T s = T(1) / det(m);
  Mat2<T> r;
  r.a[0][0] = s * m.a[1][1];
  r.a[0][1] = -s * m.a[0][1];
  r.a[1][0] = -s * m.a[1][0];
  r.a[1][1] = s * m.a[0][0];
  return r;
}
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> inverse(const Mat3<T>& m) {
  const T s = T(1) / det(m);
  Mat3<T> r;
  r.a[0][0] = s * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]);
  r.a[0][1] = s * (m.a[0][2] * m.a[2][1] - m.a[0][1] * m.a[2][2]);
  r.a[0][2] = s * (m.a[0][1] * m.a[1][2] - m.a[0][2] * m.a[1][1]);
  r.a[1][0] = s * (m.a[1][2] * m.a[2][0] - m.a[1][0] * m.a[2][2]);
  r.a[1][1] = s * (m.a[0][0] * m.a[2][2] - m.a[0][2] * m.a[2][0]);
  r.a[1][2] = s * (m.a[0][2] * m.a[1][0] - m.a[0][0] * m.a[1][2]);
  r.a[2][0] = s * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
  r.a[2][1] = s * (m.a[0][1] * m.a[2][0] - m.a[0][0] * m.a[2][1]);
  r.a[2][2] = s * (m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0]);
  return r;
}

// 2D rotation matrix R(theta) (seed 000 eq. (7)).
template <class T>
KOKKOS_INLINE_FUNCTION Mat2<T> rotation(T theta) {
  const T c = kx::cos(theta), s = kx::sin(theta);
  Mat2<T> r;
  r.a[0][0] = c;
  r.a[0][1] = -s;
  r.a[1][0] = s;
  r.a[1][1] = c;
  return r;
}

// Load/store a Vec from a View with a trailing extent of D (e.g. View<T*[D]>).
template <int D, class ViewT>
KOKKOS_INLINE_FUNCTION Vec<typename ViewT::non_const_value_type, D> load(const ViewT& v, std::int64_t i) {
  Vec<typename ViewT::non_const_value_type, D> r;
  for (int k = 0; k < D; ++k) r.v[k] = v(i, k);
  return r;
}
template <int D, class ViewT, class T>
KOKKOS_INLINE_FUNCTION void store(const ViewT& v, std::int64_t i, const Vec<T, D>& x) {
  for (int k = 0; k < D; ++k) v(i, k) = x.v[k];
}

}  // namespace polymech
