// Relative L2 error of a finite-element field against an analytic one (seed 002 paper 3 eq. (28)):
//   eps = sqrt(int |Phi_h - Phi|^2 dOmega) / sqrt(int |Phi|^2 dOmega),
// integrated element by element with Qe Gauss points per direction on the isoparametric geometry. The
// paper uses 3 points for linear elements; order p needs more for the error to show its p + 1
// convergence, so the callers pass Qe = max(3, p + 2). Always in double, whatever precision solved.
#pragma once

#include "fem/hex_elements.hpp"

namespace polymech::fem {

struct ErrorIntegrals {
  double error2 = 0.0;      // int |Phi_h - Phi|^2
  double reference2 = 0.0;  // int |Phi|^2
  double volume = 0.0;      // int 1
  double relative() const { return reference2 > 0 ? std::sqrt(error2 / reference2) : std::sqrt(error2); }
};

namespace detail {

template <int N, int Qe, class F>
ErrorIntegrals l2_error(const Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>& dofs,
                        const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                        const View1<Kokkos::complex<double>>& u, const F& exact) {
  using C = Kokkos::complex<double>;
  constexpr int N3 = N * N * N, Q3 = Qe * Qe * Qe;
  const HexBasis<double, N, Qe> b = make_hex_basis<double, N, Qe>();
  ErrorIntegrals r;
  Kokkos::parallel_reduce(
      "polymech::fem::l2_error", range(static_cast<Index>(dofs.extent(0))),
      KOKKOS_LAMBDA(const Index e, double& err, double& ref, double& vol) {
        C U[N3], Uq[Q3], Ct1[Qe * Qe * N], Ct2[Qe * Qe * N];
        double X[N3], Xq[3][Q3], J[3][3][Q3], t1[Qe * Qe * N], t2[Qe * Qe * N];
        for (int a = 0; a < N3; ++a) U[a] = u(decode_dof(dofs(e, a)));
        interpolate<N, Qe>(b.B, U, Uq, Ct1, Ct2);
        for (int c = 0; c < 3; ++c) {
          for (int a = 0; a < N3; ++a) X[a] = x(decode_dof(dofs(e, a)), c);
          interpolate<N, Qe>(b.B, X, Xq[c], t1, t2);
          gradient_at_points<Qe>(b.Dq, Xq[c], J[c][0], J[c][1], J[c][2]);
        }
        for (int q = 0; q < Q3; ++q) {
          Mat3<double> m;
          for (int c = 0; c < 3; ++c)
            for (int d = 0; d < 3; ++d) m(c, d) = J[c][d][q];
          const double wq = b.w[q % Qe] * b.w[(q / Qe) % Qe] * b.w[q / (Qe * Qe)] * polymech::det(m);
          const C ex = exact(Xq[0][q], Xq[1][q], Xq[2][q]);
          const C diff = Uq[q] - ex;
          err += wq * (diff.real() * diff.real() + diff.imag() * diff.imag());
          ref += wq * (ex.real() * ex.real() + ex.imag() * ex.imag());
          vol += wq;
        }
      },
      r.error2, r.reference2, r.volume);
  return r;
}

}  // namespace detail

// eq. (28) for the field u (local DoFs, double) of an order-`order` mesh with element map `dofs` and
// DoF coordinates x; exact(x, y, z) -> Kokkos::complex<double> is a device-callable functor.
template <class F>
ErrorIntegrals l2_error(int order, const Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>& dofs,
                        const Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>& x,
                        const View1<Kokkos::complex<double>>& u, const F& exact) {
  ErrorIntegrals r;
  with_nodes(order, [&](auto n) {
    constexpr int N = decltype(n)::value;
    constexpr int Qe = N + 1 < 3 ? 3 : N + 1;  // max(3, p + 2)
    r = detail::l2_error<N, Qe>(dofs, x, u, exact);
  });
  return r;
}

}  // namespace polymech::fem
