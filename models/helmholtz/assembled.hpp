// Assembled sparse reference of the system matrix of seed 002 paper 3 eq. (16) (Eigen, host, double),
// for small meshes: element matrices A_e - k^2 M_e (eqs. (17)-(18)) and face matrices C_e (eq. (19))
// by direct evaluation of the full 3D basis at the Gauss points, with the Jacobian formed and inverted
// point by point; no sum factorization, no stored geometric factors. The matrix-free operator must
// equal it (tests/fem), and benchmarks compare time and memory with its CSR form.
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <complex>
#include <vector>

#include "fem/csr.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/helmholtz.hpp"

namespace polymech::helmholtz {

using SparseMatrix = Eigen::SparseMatrix<std::complex<double>, Eigen::RowMajor, int>;

// `faces`: face terms c_f int N^T N dGamma (impedance: c_f = j rho omega / Zn). Rows and columns of
// constrained DoFs are replaced by the identity, as the matrix-free operator does.
inline SparseMatrix assemble_reference(const HexMesh& mesh, const HexDofs& d, double mass_coefficient,
                                       const std::vector<FaceTerm>& faces, const std::vector<char>& constrained) {
  const int N = d.n1d, N3 = d.nodes_per_element(), Q = N;
  const std::vector<double> nodes = fem::gauss_lobatto_nodes(N);
  std::vector<double> xq, wq;
  fem::gauss_legendre(Q, xq, wq);
  using Triplet = Eigen::Triplet<std::complex<double>, int>;
  std::vector<Triplet> trip;
  auto add = [&](int r, int c, std::complex<double> v) {
    if (constrained[r] || constrained[c]) return;
    trip.emplace_back(r, c, v);
  };
  // full 3D basis (value and reference gradient) of node a at reference point p
  auto basis = [&](int a, const double p[3], double& phi, double g[3]) {
    const int ijk[3] = {a % N, (a / N) % N, a / (N * N)};
    double l[3], dl[3];
    for (int c = 0; c < 3; ++c) {
      l[c] = fem::lagrange(nodes, ijk[c], p[c]);
      dl[c] = fem::lagrange_derivative(nodes, ijk[c], p[c]);
    }
    phi = l[0] * l[1] * l[2];
    g[0] = dl[0] * l[1] * l[2];
    g[1] = l[0] * dl[1] * l[2];
    g[2] = l[0] * l[1] * dl[2];
  };
  std::vector<double> phi(N3), grad(3 * N3);
  std::vector<Eigen::Vector3d> X(N3);
  for (std::int64_t e = 0; e < mesh.element_count(); ++e) {
    const std::int32_t* dofs = &d.element_dofs[e * N3];
    for (int a = 0; a < N3; ++a) X[a] = Eigen::Vector3d(&d.coordinates[3 * static_cast<std::size_t>(dofs[a])]);
    Eigen::MatrixXd Ke = Eigen::MatrixXd::Zero(N3, N3);
    for (int qz = 0; qz < Q; ++qz)
      for (int qy = 0; qy < Q; ++qy)
        for (int qx = 0; qx < Q; ++qx) {
          const double p[3] = {xq[qx], xq[qy], xq[qz]};
          Eigen::Matrix3d J = Eigen::Matrix3d::Zero();  // J(c, r) = dx_c / dxi_r
          for (int a = 0; a < N3; ++a) {
            basis(a, p, phi[a], &grad[3 * a]);
            J += X[a] * Eigen::RowVector3d(grad[3 * a], grad[3 * a + 1], grad[3 * a + 2]);
          }
          const double det = J.determinant(), w = wq[qx] * wq[qy] * wq[qz] * det;
          const Eigen::Matrix3d JinvT = J.inverse().transpose();
          std::vector<Eigen::Vector3d> gx(N3);
          for (int a = 0; a < N3; ++a) gx[a] = JinvT * Eigen::Vector3d(grad[3 * a], grad[3 * a + 1], grad[3 * a + 2]);
          for (int a = 0; a < N3; ++a)
            for (int b = 0; b < N3; ++b) Ke(a, b) += w * (gx[a].dot(gx[b]) + mass_coefficient * phi[a] * phi[b]);
        }
    for (int a = 0; a < N3; ++a)
      for (int b = 0; b < N3; ++b) add(dofs[a], dofs[b], Ke(a, b));
  }
  for (const auto& term : faces)
    for (std::size_t k = 0; k < term.faces.size(); ++k) {
      const BoundaryFace& f = term.faces[k];
      const std::int32_t* dofs = &d.element_dofs[f.element * N3];
      for (int a = 0; a < N3; ++a) X[a] = Eigen::Vector3d(&d.coordinates[3 * static_cast<std::size_t>(dofs[a])]);
      const int dir = f.face / 2, t0 = dir == 0 ? 1 : 0, t1 = dir == 2 ? 1 : 2;
      Eigen::MatrixXd Ce = Eigen::MatrixXd::Zero(N3, N3);
      for (int qb = 0; qb < Q; ++qb)
        for (int qa = 0; qa < Q; ++qa) {
          double p[3];
          p[dir] = (f.face % 2) ? 1.0 : -1.0;
          p[t0] = xq[qa];
          p[t1] = xq[qb];
          Eigen::Vector3d xs = Eigen::Vector3d::Zero(), xt = Eigen::Vector3d::Zero();
          for (int a = 0; a < N3; ++a) {
            basis(a, p, phi[a], &grad[3 * a]);
            xs += X[a] * grad[3 * a + t0];
            xt += X[a] * grad[3 * a + t1];
          }
          const double w = wq[qa] * wq[qb] * xs.cross(xt).norm();
          for (int a = 0; a < N3; ++a)
            for (int b = 0; b < N3; ++b) Ce(a, b) += w * phi[a] * phi[b];
        }
      for (int a = 0; a < N3; ++a)
        for (int b = 0; b < N3; ++b)
          if (Ce(a, b) != 0.0) add(dofs[a], dofs[b], term.coefficient[k] * Ce(a, b));
    }
  for (std::int64_t i = 0; i < d.count; ++i)
    if (constrained[i]) trip.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
  SparseMatrix K(static_cast<int>(d.count), static_cast<int>(d.count));
  K.setFromTriplets(trip.begin(), trip.end());
  K.makeCompressed();
  return K;
}

// The reference of a model's operator (its mesh, DoFs, k, impedance faces and constraints).
template <class T>
SparseMatrix assemble_reference(const Helmholtz<T>& model) {
  const double k = model.config().wavenumber();
  std::vector<FaceTerm> faces;
  if (model.config().effects.has("impedance")) faces.push_back(model.face_term(BoundaryKind::impedance));
  return assemble_reference(model.config().mesh, model.dofs(), -k * k, faces, model.constrained_mask());
}

// CSR copy on the device in precision T (for the assembled-operator benchmarks and solves).
template <class T>
fem::CsrMatrix<Kokkos::complex<T>> to_csr(const SparseMatrix& K) {
  fem::CsrMatrix<Kokkos::complex<T>> A;
  const Index n = static_cast<Index>(K.rows());
  const Offset nnz = static_cast<Offset>(K.nonZeros());
  A.row_ptr = Kokkos::View<Offset*, MemSpace>("polymech::helmholtz::csr_row_ptr", n + 1);
  A.cols = View1<Index>("polymech::helmholtz::csr_cols", nnz);
  A.values = View1<Kokkos::complex<T>>("polymech::helmholtz::csr_values", nnz);
  auto r = Kokkos::create_mirror_view(A.row_ptr);
  auto c = Kokkos::create_mirror_view(A.cols);
  auto v = Kokkos::create_mirror_view(A.values);
  for (Index i = 0; i <= n; ++i) r(i) = K.outerIndexPtr()[i];
  for (Offset k = 0; k < nnz; ++k) {
    c(k) = K.innerIndexPtr()[k];
    const auto z = K.valuePtr()[k];
    v(k) = Kokkos::complex<T>(static_cast<T>(z.real()), static_cast<T>(z.imag()));
  }
  Kokkos::deep_copy(A.row_ptr, r);
  Kokkos::deep_copy(A.cols, c);
  Kokkos::deep_copy(A.values, v);
  return A;
}

}  // namespace polymech::helmholtz
