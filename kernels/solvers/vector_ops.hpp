// Vector kernels of the Krylov solvers, for real (T) and complex (Kokkos::complex<T>) values. The
// bilinear form is the unconjugated x^T y (COCG's, and CG's for real vectors); norms are Hermitian.
// Reductions run over the owned entries [0, owned) only, so a distributed layout (owned DoFs first,
// ghost copies after them) gives each DoF once; updates run over owned + ghost.
#pragma once

#include <type_traits>

#include "core/types.hpp"

namespace polymech::solvers {

template <class V>
struct ScalarTraits {
  using real_type = V;
  static constexpr bool is_complex = false;
  KOKKOS_INLINE_FUNCTION static V re(const V& v) { return v; }
  KOKKOS_INLINE_FUNCTION static V im(const V&) { return V(0); }
  KOKKOS_INLINE_FUNCTION static V make(V re, V) { return re; }
};
template <class T>
struct ScalarTraits<Kokkos::complex<T>> {
  using real_type = T;
  static constexpr bool is_complex = true;
  KOKKOS_INLINE_FUNCTION static T re(const Kokkos::complex<T>& v) { return v.real(); }
  KOKKOS_INLINE_FUNCTION static T im(const Kokkos::complex<T>& v) { return v.imag(); }
  KOKKOS_INLINE_FUNCTION static Kokkos::complex<T> make(T re, T im) { return Kokkos::complex<T>(re, im); }
};

template <class V>
using real_of = typename ScalarTraits<V>::real_type;

template <class V>
KOKKOS_INLINE_FUNCTION real_of<V> abs2(const V& v) {
  using S = ScalarTraits<V>;
  return S::re(v) * S::re(v) + S::im(v) * S::im(v);
}

// A bilinear value with the two norms that judge it: x^T y, |x|^2, |y|^2.
template <class V>
struct DotNorms {
  V dot;
  double norm2_x = 0.0, norm2_y = 0.0;
};

// x^T y with |x|^2 and |y|^2 in one pass.
template <class V>
DotNorms<V> dot_with_norms(const char* label, Index owned, const View1<V>& x, const View1<V>& y) {
  using S = ScalarTraits<V>;
  using T = real_of<V>;
  T dr = 0, di = 0, nx = 0, ny = 0;
  Kokkos::parallel_reduce(
      label, range(owned),
      KOKKOS_LAMBDA(const Index i, T& a, T& b, T& c, T& d) {
        const V p = x(i) * y(i);
        a += S::re(p);
        b += S::im(p);
        c += abs2(x(i));
        d += abs2(y(i));
      },
      dr, di, nx, ny);
  return {S::make(dr, di), static_cast<double>(nx), static_cast<double>(ny)};
}

// |x|^2 over the owned entries.
template <class V>
double norm2(const char* label, Index owned, const View1<V>& x) {
  real_of<V> s = 0;
  Kokkos::parallel_reduce(
      label, range(owned), KOKKOS_LAMBDA(const Index i, real_of<V>& a) { a += abs2(x(i)); }, s);
  return static_cast<double>(s);
}

// r = b - Ax (Ax given in r on entry); returns |r|^2.
template <class V>
double residual_from_product(Index owned, Index local, const View1<V>& b, const View1<V>& r) {
  Kokkos::parallel_for(
      "polymech::solvers::residual", range(local), KOKKOS_LAMBDA(const Index i) { r(i) = b(i) - r(i); });
  return norm2("polymech::solvers::residual_norm", owned, r);
}

// x += alpha p; r -= alpha q; returns |r|^2 (owned).
template <class V>
double update_solution_and_residual(Index owned, Index local, V alpha, const View1<V>& p, const View1<V>& q,
                                    const View1<V>& x, const View1<V>& r) {
  using T = real_of<V>;
  T rr = 0;
  Kokkos::parallel_reduce(
      "polymech::solvers::update_x_r", range(local),
      KOKKOS_LAMBDA(const Index i, T& s) {
        x(i) += alpha * p(i);
        const V ri = r(i) - alpha * q(i);
        r(i) = ri;
        if (i < owned) s += abs2(ri);
      },
      rr);
  return static_cast<double>(rr);
}

// z = inv_diag .* r (identity when inv_diag is empty); returns r^T z with |r|^2 and |z|^2.
template <class V>
DotNorms<V> precondition_and_dot(Index owned, Index local, const View1<V>& inv_diag, const View1<V>& r,
                                 const View1<V>& z) {
  using S = ScalarTraits<V>;
  using T = real_of<V>;
  const bool jacobi = inv_diag.extent(0) > 0;
  T dr = 0, di = 0, nr = 0, nz = 0;
  Kokkos::parallel_reduce(
      "polymech::solvers::jacobi_dot", range(local),
      KOKKOS_LAMBDA(const Index i, T& a, T& b, T& c, T& d) {
        const V zi = jacobi ? inv_diag(i) * r(i) : r(i);
        z(i) = zi;
        if (i < owned) {
          const V p = r(i) * zi;
          a += S::re(p);
          b += S::im(p);
          c += abs2(r(i));
          d += abs2(zi);
        }
      },
      dr, di, nr, nz);
  return {S::make(dr, di), static_cast<double>(nr), static_cast<double>(nz)};
}

// The fused COCG / CG update with Jacobi (inv_diag non-empty): x += alpha p; r -= alpha q; with
// z = inv_diag .* r (not stored) returns r^T z, |r|^2 and |z|^2 (owned entries). One pass instead of
// the update and the preconditioning pass; z is formed again in update_direction_jacobi.
template <class V>
DotNorms<V> update_and_precondition(Index owned, Index local, V alpha, const View1<V>& p, const View1<V>& q,
                                    const View1<V>& x, const View1<V>& r, const View1<V>& inv_diag) {
  using S = ScalarTraits<V>;
  using T = real_of<V>;
  T dr = 0, di = 0, nr = 0, nz = 0;
  Kokkos::parallel_reduce(
      "polymech::solvers::update_jacobi_dot", range(local),
      KOKKOS_LAMBDA(const Index i, T& a, T& b, T& c, T& d) {
        x(i) += alpha * p(i);
        const V ri = r(i) - alpha * q(i);
        r(i) = ri;
        if (i < owned) {
          const V zi = inv_diag(i) * ri;
          const V rz = ri * zi;
          a += S::re(rz);
          b += S::im(rz);
          c += abs2(ri);
          d += abs2(zi);
        }
      },
      dr, di, nr, nz);
  return {S::make(dr, di), static_cast<double>(nr), static_cast<double>(nz)};
}

// p = inv_diag .* r + beta p (the Jacobi-preconditioned direction, z not stored).
template <class V>
void update_direction_jacobi(Index local, V beta, const View1<V>& inv_diag, const View1<V>& r, const View1<V>& p) {
  Kokkos::parallel_for(
      "polymech::solvers::update_p_jacobi", range(local),
      KOKKOS_LAMBDA(const Index i) { p(i) = inv_diag(i) * r(i) + beta * p(i); });
}

// y = s x (y may be x).
template <class V>
void scale(Index local, real_of<V> s, const View1<V>& x, const View1<V>& y) {
  Kokkos::parallel_for(
      "polymech::solvers::scale", range(local), KOKKOS_LAMBDA(const Index i) { y(i) = s * x(i); });
}

// p = z + beta p.
template <class V>
void update_direction(Index local, V beta, const View1<V>& z, const View1<V>& p) {
  Kokkos::parallel_for(
      "polymech::solvers::update_p", range(local), KOKKOS_LAMBDA(const Index i) { p(i) = z(i) + beta * p(i); });
}

// Jacobi preconditioner: inv = 1 / diag over the local entries. Reports the smallest and largest
// |diag| over the owned entries, where the smallest is, and how many entries are not finite, so the
// caller can refuse a diagonal that vanishes (an indefinite operator can have one).
struct DiagonalSummary {
  double min_abs = 0.0, max_abs = 0.0;
  Index argmin = -1;
  Index non_finite = 0;
};

template <class V>
DiagonalSummary jacobi_inverse(Index owned, Index local, const View1<V>& diag, const View1<V>& inv) {
  Kokkos::parallel_for(
      "polymech::solvers::jacobi_inverse", range(local), KOKKOS_LAMBDA(const Index i) { inv(i) = V(1) / diag(i); });
  using T = real_of<V>;
  using MinLoc = Kokkos::MinLoc<T, Index>;
  typename MinLoc::value_type lo;
  Kokkos::parallel_reduce(
      "polymech::solvers::jacobi_min", range(owned),
      KOKKOS_LAMBDA(const Index i, typename MinLoc::value_type& m) {
        const T a = kx::sqrt(abs2(diag(i)));
        if (kx::isfinite(a) && a < m.val) {
          m.val = a;
          m.loc = i;
        }
      },
      MinLoc(lo));
  T hi = 0, bad = 0;  // (Kokkos 3.4 cannot combine MinLoc with other reducers in one pass)
  Kokkos::parallel_reduce(
      "polymech::solvers::jacobi_max", range(owned),
      KOKKOS_LAMBDA(const Index i, T& h, T& nb) {
        const T a = kx::sqrt(abs2(diag(i)));
        if (!kx::isfinite(a))
          nb += T(1);
        else if (a > h)
          h = a;
      },
      Kokkos::Max<T>(hi), Kokkos::Sum<T>(bad));
  return {static_cast<double>(lo.val), static_cast<double>(hi), lo.loc, static_cast<Index>(bad)};
}

}  // namespace polymech::solvers
