// Stiffness and damping matrices of a periodic particle patch by central differences of the NOSB
// forces (host, Eigen): the zero-energy-mode analysis of seed 003 §3(2), for tests and docs.
//
// The patch is the central tile of a lattice box of 3 x 3 (x 3) tiles; every particle of the box is
// an image of a central-tile particle, and a displacement (or velocity) of a degree of freedom moves
// all its images, so the central tile sees complete families and the result is the stiffness of an
// infinite periodic lattice (a free patch hides the zero-energy modes: its surface particles pin them).
//
//   K_ab = -d f_a / d u_b,   C_ab = -d f_a / d v_b,   f_a = rho V a_a (force on DoF a [N]),
// at rest (u = v = 0), where St. Venant-Kirchhoff is linear to second order in eps. A periodic patch
// has D rigid-body zeros (translations); every further zero of M^-1 K is a zero-energy mode, e.g. the
// parity patterns u_i = (-1)^(ix + iy) c, for which F_i = I on every particle (eq. (1)).
#pragma once

// GCC 12 with -march=native reports maybe-uninitialized inside Eigen's AVX-512 intrinsics (Eigen's
// own code, inlined here); the state in force at the header's lines decides, so it is set around them.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

#include <cmath>
#include <map>
#include <vector>

#include "nosb_pd/nosb_pd.hpp"

namespace polymech::nosb_pd {

// The periodic images of a lattice box of 3 x tile cells per direction: for every particle the index
// of the central-tile particle it images, and the central-tile particles (the degrees of freedom).
struct PeriodicImages {
  std::vector<Index> original;
  std::vector<Index> owners;
};

template <int D>
PeriodicImages periodic_images(const NosbPd<double, D>& m, int tile) {
  auto x0 = Kokkos::create_mirror_view_and_copy(HostSpace(), m.fields().x0);
  const double h = m.config().spacing;
  auto cell = [&](Index i, int k) { return static_cast<long>(std::lround(x0(i, k) / h - 0.5)); };
  std::map<std::vector<long>, Index> central;
  PeriodicImages p;
  for (Index i = 0; i < m.particles(); ++i) {
    std::vector<long> c(D);
    bool in = true;
    for (int k = 0; k < D; ++k) {
      c[k] = cell(i, k);
      in = in && c[k] >= tile && c[k] < 2 * tile;
    }
    if (in) {
      central[c] = i;
      p.owners.push_back(i);
    }
  }
  p.original.resize(static_cast<std::size_t>(m.particles()));
  for (Index i = 0; i < m.particles(); ++i) {
    std::vector<long> c(D);
    for (int k = 0; k < D; ++k) c[k] = ((cell(i, k) % tile) + tile) % tile + tile;
    p.original[static_cast<std::size_t>(i)] = central.at(c);
  }
  return p;
}

// -d f / d u (or d v) over the owners' degrees of freedom, row/column a = D * (owner index) + k.
template <int D>
Eigen::MatrixXd periodic_force_jacobian(NosbPd<double, D>& m, const PeriodicImages& p, bool velocity, double eps) {
  const auto& f = m.fields();
  const auto n_own = static_cast<Eigen::Index>(p.owners.size());
  const Eigen::Index N = D * n_own;
  std::vector<Eigen::Index> slot(static_cast<std::size_t>(m.particles()), -1);
  for (Eigen::Index o = 0; o < n_own; ++o) slot[static_cast<std::size_t>(p.owners[static_cast<std::size_t>(o)])] = o;
  auto state = Kokkos::create_mirror_view(velocity ? f.v : f.u);
  auto V = Kokkos::create_mirror_view_and_copy(HostSpace(), f.volume);
  const double rho = m.config().material.density;
  Kokkos::deep_copy(f.u, 0.0);
  Kokkos::deep_copy(f.v, 0.0);
  Eigen::MatrixXd J(N, N);
  Eigen::VectorXd plus(N);
  for (Eigen::Index b = 0; b < N; ++b) {
    const Index owner = p.owners[static_cast<std::size_t>(b / D)];
    for (double sgn : {1.0, -1.0}) {
      Kokkos::deep_copy(state, 0.0);
      for (Index i = 0; i < m.particles(); ++i)
        if (p.original[static_cast<std::size_t>(i)] == owner) state(i, b % D) = sgn * eps;
      Kokkos::deep_copy(velocity ? f.v : f.u, state);
      m.compute_forces();
      auto a = Kokkos::create_mirror_view_and_copy(HostSpace(), f.a);
      for (Eigen::Index r = 0; r < N; ++r) {
        const Index i = p.owners[static_cast<std::size_t>(r / D)];
        const double force = rho * V(i) * a(i, r % D);
        if (sgn > 0) plus(r) = force;
        else J(r, b) = -(plus(r) - force) / (2 * eps);
      }
    }
  }
  Kokkos::deep_copy(f.u, 0.0);
  Kokkos::deep_copy(f.v, 0.0);
  return J;
}

struct PatchSpectrum {
  std::vector<double> omega2;  // eigenvalues of M^-1/2 K M^-1/2, ascending [1/s^2]
  int rigid_modes = 0;         // D translations
  int zero_modes = 0;          // eigenvalues below tol x the largest (translations included)
  double smallest_nonzero = 0;  // the first eigenvalue above the zeros, relative to the largest
  // the damping M^-1/2 C M^-1/2 restricted to the zero-energy modes (the null space of K without the
  // translations): its eigenvalues [1/s], ascending; all > 0 means every zero-energy mode is damped
  std::vector<double> spurious_damping;
};

// Spectrum of the periodic patch (a lattice box of 3 tile^D cells) and, with `with_damping`, the
// damping of its zero-energy modes.
template <int D>
PatchSpectrum periodic_patch_spectrum(NosbPd<double, D>& m, int tile, double tol, bool with_damping) {
  const PeriodicImages p = periodic_images(m, tile);
  const double eps = 1e-9 * m.config().spacing;
  const Eigen::MatrixXd K = periodic_force_jacobian(m, p, false, eps);
  auto V = Kokkos::create_mirror_view_and_copy(HostSpace(), m.fields().volume);
  const Eigen::Index N = K.rows();
  Eigen::VectorXd s(N);  // M^-1/2
  for (Eigen::Index r = 0; r < N; ++r) s(r) = 1.0 / std::sqrt(m.config().material.density * V(p.owners[static_cast<std::size_t>(r / D)]));
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(s.asDiagonal() * (0.5 * (K + K.transpose())) * s.asDiagonal());
  const Eigen::VectorXd ev = es.eigenvalues();
  PatchSpectrum out;
  out.omega2.assign(ev.data(), ev.data() + N);
  out.rigid_modes = D;
  const double top = ev(N - 1);
  for (Eigen::Index k = 0; k < N; ++k)
    if (ev(k) < tol * top) ++out.zero_modes;
  out.smallest_nonzero = out.zero_modes < N ? ev(out.zero_modes) / top : 0.0;
  if (with_damping && out.zero_modes > out.rigid_modes) {
    const Eigen::MatrixXd C = periodic_force_jacobian(m, p, true, 1e-6);
    // translations in the scaled coordinates M^1/2 q, orthonormalised
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(N, D);
    for (Eigen::Index r = 0; r < N; ++r) R(r, r % D) = 1.0 / s(r);
    const Eigen::MatrixXd Q = Eigen::HouseholderQR<Eigen::MatrixXd>(R).householderQ() * Eigen::MatrixXd::Identity(N, D);
    const Eigen::MatrixXd Z = es.eigenvectors().leftCols(out.zero_modes);
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(Z - Q * (Q.transpose() * Z), Eigen::ComputeThinU);
    const Eigen::MatrixXd S = svd.matrixU().leftCols(out.zero_modes - out.rigid_modes);
    const Eigen::MatrixXd Cs = s.asDiagonal() * (0.5 * (C + C.transpose())) * s.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> ds(S.transpose() * Cs * S);
    out.spurious_damping.assign(ds.eigenvalues().data(), ds.eigenvalues().data() + ds.eigenvalues().size());
  }
  return out;
}

}  // namespace polymech::nosb_pd
