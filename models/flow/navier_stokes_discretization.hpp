// The discretisation of flow::NavierStokes2D (models/flow/navier_stokes.hpp): the DoF numbering (Dirichlet
// velocities and a pinned pressure left out of the unknowns), the reference basis at the Gauss points, the
// physical gradients and weights from the node coordinates, the body force at the Gauss points, and the CSR
// pattern of the free-free Jacobian with each element entry's position in it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/basis.hpp"
#include "fem/gauss_legendre.hpp"
#include "fem/point_basis.hpp"
#include "flow/navier_stokes_model.hpp"

namespace polymech::flow {

inline void NavierStokes2D::number_dofs() {
  nn_ = mesh_.node_count();
  ne_ = mesh_.element_count();
  vertex_.assign(static_cast<std::size_t>(nn_), -1);
  nv_ = 0;
  for (std::int64_t e = 0; e < ne_; ++e)
    for (const int a : {0, 2, 6, 8}) {
      auto& v = vertex_[static_cast<std::size_t>(mesh_.elements[static_cast<std::size_t>(e) * 9 + a])];
      if (v < 0) v = nv_++;
    }
  ndof_ = 2 * nn_ + nv_;
  free_.assign(static_cast<std::size_t>(ndof_), 0);
  for (std::int64_t n = 0; n < nn_; ++n)
    if (mesh_.tags[static_cast<std::size_t>(n)] & cfg_.dirichlet_tags) free_[2 * n] = free_[2 * n + 1] = -1;
  if (cfg_.pin_pressure) {
    std::int64_t best = -1;
    double dmin = 1e300;
    for (std::int64_t n = 0; n < nn_; ++n) {
      if (vertex_[static_cast<std::size_t>(n)] < 0) continue;
      const double d = std::hypot(mesh_.x[2 * n] - cfg_.pin_point[0], mesh_.x[2 * n + 1] - cfg_.pin_point[1]);
      if (d < dmin) dmin = d, best = n;
    }
    pinned_ = 2 * nn_ + vertex_[static_cast<std::size_t>(best)];
    free_[static_cast<std::size_t>(pinned_)] = -1;
  }
  nfree_ = 0;
  for (auto& f : free_)
    if (f == 0) f = nfree_++;
  std::vector<std::int64_t> dh(static_cast<std::size_t>(ne_) * kElementDofs);
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
    std::int64_t* d = &dh[static_cast<std::size_t>(e) * kElementDofs];
    for (int a = 0; a < 9; ++a) {
      d[2 * a] = 2 * en[a];
      d[2 * a + 1] = 2 * en[a] + 1;
    }
    const int corner[4] = {0, 2, 6, 8};
    for (int c = 0; c < 4; ++c) d[18 + c] = 2 * nn_ + vertex_[static_cast<std::size_t>(en[corner[c]])];
  }
  elem_dofs_ = dh;
  in_.dofs = View2<std::int64_t>("polymech::flow::element_dofs", static_cast<std::size_t>(ne_), kElementDofs);
  auto h = Kokkos::create_mirror_view(in_.dofs);
  for (std::int64_t e = 0; e < ne_; ++e)
    for (int k = 0; k < kElementDofs; ++k) h(e, k) = dh[static_cast<std::size_t>(e) * kElementDofs + k];
  Kokkos::deep_copy(in_.dofs, h);
}

inline void NavierStokes2D::build_basis() {
  tables_ = fem::gauss_tables(3);  // Q2 on the GLL nodes -1, 0, 1 at the 3 Gauss points
  std::vector<double> xq, wq;
  fem::gauss_legendre(3, xq, wq);
  const std::vector<double> n1{-1.0, 1.0};
  for (int q = 0; q < kPoints; ++q) {
    const int qi = q % 3, qj = q / 3;
    for (int a = 0; a < 9; ++a)
      basis_.N[q][a] = tables_.value[static_cast<std::size_t>(qi) * 3 + a % 3] * tables_.value[static_cast<std::size_t>(qj) * 3 + a / 3];
    for (int c = 0; c < 4; ++c)
      basis_.M[q][c] = fem::lagrange(n1, c % 2, xq[static_cast<std::size_t>(qi)]) * fem::lagrange(n1, c / 2, xq[static_cast<std::size_t>(qj)]);
  }
}

// The physical gradients and weights at the Gauss points from the current node coordinates (again after the
// mesh moves). Throws for an inverted element.
inline void NavierStokes2D::update_geometry() {
  if (in_.grad.extent(0) != static_cast<std::size_t>(ne_)) {
    in_.grad = decltype(in_.grad)("polymech::flow::basis_gradients", static_cast<std::size_t>(ne_), kPoints);
    in_.wdet = View2<double>("polymech::flow::weights", static_cast<std::size_t>(ne_), kPoints);
  }
  auto gh = Kokkos::create_mirror_view(in_.grad);
  auto wh = Kokkos::create_mirror_view(in_.wdet);
  std::vector<double> grad(18);
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
    for (int q = 0; q < kPoints; ++q) {
      double w;
      const double det = fem::tensor_point(tables_, 2, q, en, mesh_.x, nullptr, grad.data(), w);
      if (!(det > 0.0)) throw std::invalid_argument("flow: element " + std::to_string(e) + " is inverted (det J <= 0)");
      wh(e, q) = w * det;
      for (int a = 0; a < 9; ++a)
        for (int d = 0; d < 2; ++d) gh(e, q, a, d) = grad[static_cast<std::size_t>(2 * a + d)];
    }
  }
  Kokkos::deep_copy(in_.grad, gh);
  Kokkos::deep_copy(in_.wdet, wh);
}

inline void NavierStokes2D::set_body_force() {
  in_.force = View2<double>("polymech::flow::body_force", static_cast<std::size_t>(ne_), 2 * kPoints);
  auto fh = Kokkos::create_mirror_view(in_.force);
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
    for (int q = 0; q < kPoints; ++q) {
      double x = 0.0, y = 0.0;
      for (int a = 0; a < 9; ++a) {
        x += basis_.N[q][a] * mesh_.x[2 * static_cast<std::size_t>(en[a])];
        y += basis_.N[q][a] * mesh_.x[2 * static_cast<std::size_t>(en[a]) + 1];
      }
      const Vec2 f = cfg_.body_force(x, y);
      fh(e, 2 * q) = f[0];
      fh(e, 2 * q + 1) = f[1];
    }
  }
  Kokkos::deep_copy(in_.force, fh);
}

// The CSR pattern of the free-free Jacobian and, per element entry, its position in the value array.
inline void NavierStokes2D::build_pattern() {
  std::vector<std::vector<std::int64_t>> cols(static_cast<std::size_t>(nfree_));
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* d = &elem_dofs_[static_cast<std::size_t>(e) * kElementDofs];
    for (int k = 0; k < kElementDofs; ++k) {
      const std::int64_t r = free_[static_cast<std::size_t>(d[k])];
      if (r < 0) continue;
      for (int l = 0; l < kElementDofs; ++l) {
        const std::int64_t c = free_[static_cast<std::size_t>(d[l])];
        if (c >= 0) cols[static_cast<std::size_t>(r)].push_back(c);
      }
    }
  }
  rows_.clear();
  cols_.clear();
  std::vector<std::int64_t> start(static_cast<std::size_t>(nfree_) + 1, 0);
  for (std::int64_t r = 0; r < nfree_; ++r) {
    auto& c = cols[static_cast<std::size_t>(r)];
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    start[static_cast<std::size_t>(r) + 1] = start[static_cast<std::size_t>(r)] + static_cast<std::int64_t>(c.size());
    for (const auto cc : c) {
      rows_.push_back(r);
      cols_.push_back(cc);
    }
  }
  values_.assign(cols_.size(), 0.0);
  position_.assign(static_cast<std::size_t>(ne_) * kElementDofs * kElementDofs, -1);
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* d = &elem_dofs_[static_cast<std::size_t>(e) * kElementDofs];
    for (int k = 0; k < kElementDofs; ++k) {
      const std::int64_t r = free_[static_cast<std::size_t>(d[k])];
      if (r < 0) continue;
      const auto& c = cols[static_cast<std::size_t>(r)];
      for (int l = 0; l < kElementDofs; ++l) {
        const std::int64_t cc = free_[static_cast<std::size_t>(d[l])];
        if (cc < 0) continue;
        const auto it = std::lower_bound(c.begin(), c.end(), cc);
        position_[(static_cast<std::size_t>(e) * kElementDofs + k) * kElementDofs + l] =
            start[static_cast<std::size_t>(r)] + (it - c.begin());
      }
    }
  }
}

}  // namespace polymech::flow
