// Evaluation of the discrete solution of flow::NavierStokes2D (models/flow/navier_stokes.hpp): velocity, its
// gradient and the pressure at a point of an element, integrals over the domain (the divergence's L2 norm),
// and the flux through a tagged boundary line.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "fem/basis.hpp"
#include "fem/gauss_legendre.hpp"
#include "flow/navier_stokes_model.hpp"

namespace polymech::flow {

// Evaluation of the discrete solution: velocity, its gradient and the pressure at reference point (xi, eta)
// of element e, with the physical point x and det J.
inline NavierStokes2D::PointValue NavierStokes2D::evaluate(std::int64_t e, double xi, double eta) const {
  static const std::vector<double> n2{-1.0, 0.0, 1.0}, n1{-1.0, 1.0};
  double l[2][3], dl[2][3], m[2][2];
  const double r[2] = {xi, eta};
  for (int d = 0; d < 2; ++d) {
    for (int i = 0; i < 3; ++i) {
      l[d][i] = fem::lagrange(n2, i, r[d]);
      dl[d][i] = fem::lagrange_derivative(n2, i, r[d]);
    }
    for (int i = 0; i < 2; ++i) m[d][i] = fem::lagrange(n1, i, r[d]);
  }
  PointValue v;
  double J[2][2] = {{0, 0}, {0, 0}}, gref[9][2];
  const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
  for (int a = 0; a < 9; ++a) {
    const int i = a % 3, j = a / 3;
    const double N = l[0][i] * l[1][j];
    gref[a][0] = dl[0][i] * l[1][j];
    gref[a][1] = l[0][i] * dl[1][j];
    for (int c = 0; c < 2; ++c) {
      const double xc = mesh_.x[2 * static_cast<std::size_t>(en[a]) + c];
      v.x[c] += N * xc;
      v.u[c] += N * u_host_[2 * static_cast<std::size_t>(en[a]) + c];
      J[c][0] += xc * gref[a][0];
      J[c][1] += xc * gref[a][1];
    }
  }
  v.det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const double Ji[2][2] = {{J[1][1] / v.det, -J[0][1] / v.det}, {-J[1][0] / v.det, J[0][0] / v.det}};
  for (int a = 0; a < 9; ++a) {
    const double gx = gref[a][0] * Ji[0][0] + gref[a][1] * Ji[1][0], gy = gref[a][0] * Ji[0][1] + gref[a][1] * Ji[1][1];
    for (int c = 0; c < 2; ++c) {
      const double uc = u_host_[2 * static_cast<std::size_t>(en[a]) + c];
      v.grad[c][0] += uc * gx;
      v.grad[c][1] += uc * gy;
    }
  }
  const int corner[4] = {0, 2, 6, 8};
  for (int c = 0; c < 4; ++c)
    v.p += m[0][c % 2] * m[1][c / 2] * u_host_[static_cast<std::size_t>(2 * nn_ + vertex_[static_cast<std::size_t>(en[corner[c]])])];
  return v;
}

// Integrates g(point value) over the domain with a Gauss rule of `points` per direction.
template <class F>
inline double NavierStokes2D::integrate(F&& g, int points) const {
  std::vector<double> xq, wq;
  fem::gauss_legendre(points, xq, wq);
  double s = 0.0;
  for (std::int64_t e = 0; e < ne_; ++e)
    for (int j = 0; j < points; ++j)
      for (int i = 0; i < points; ++i) {
        const PointValue v = evaluate(e, xq[static_cast<std::size_t>(i)], xq[static_cast<std::size_t>(j)]);
        s += wq[static_cast<std::size_t>(i)] * wq[static_cast<std::size_t>(j)] * v.det * g(v);
      }
  return s;
}

// || div u ||_L2 over the domain.
inline double NavierStokes2D::divergence_l2() const {
  return std::sqrt(integrate([](const PointValue& v) { const double d = v.grad[0][0] + v.grad[1][1]; return d * d; }));
}

// The flux int u . n over the boundary nodes' edges on x = const (the inflow or outflow line), by Gauss on
// the element edges whose three nodes carry `tag`.
inline double NavierStokes2D::flux_through(unsigned tag) const {
  std::vector<double> xq, wq;
  fem::gauss_legendre(4, xq, wq);
  const int sides[4][3] = {{0, 1, 2}, {6, 7, 8}, {0, 3, 6}, {2, 5, 8}};
  double flux = 0.0;
  for (std::int64_t e = 0; e < ne_; ++e) {
    const std::int64_t* en = &mesh_.elements[static_cast<std::size_t>(e) * 9];
    for (int s = 0; s < 4; ++s) {
      bool on = true;
      for (int k = 0; k < 3; ++k) on = on && (mesh_.tags[static_cast<std::size_t>(en[sides[s][k]])] & tag) != 0;
      if (!on) continue;
      for (std::size_t q = 0; q < xq.size(); ++q) {
        const double xi = s < 2 ? xq[q] : (s == 2 ? -1.0 : 1.0), eta = s < 2 ? (s == 0 ? -1.0 : 1.0) : xq[q];
        const PointValue v = evaluate(e, xi, eta);
        // the edge's tangent from the reference derivative along it: n dl = (dy, -dx) up to orientation
        double dx = 0.0, dy = 0.0;
        static const std::vector<double> n2{-1.0, 0.0, 1.0};
        const double t = xq[q];
        for (int k = 0; k < 3; ++k) {
          const double dk = fem::lagrange_derivative(n2, k, t);
          dx += dk * mesh_.x[2 * static_cast<std::size_t>(en[sides[s][k]])];
          dy += dk * mesh_.x[2 * static_cast<std::size_t>(en[sides[s][k]]) + 1];
        }
        flux += wq[q] * std::abs(v.u[0] * dy - v.u[1] * dx);  // |u . n| dl (the lines are crossed one way)
      }
    }
  }
  return flux;
}

}  // namespace polymech::flow
