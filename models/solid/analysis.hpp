// What the solid cases measure (issue 34), on the host in double, for every app, test and sweep alike:
// the displacement at a point (the element that holds it, its reference coordinates by Newton on the
// isoparametric map), the relative L2 error against a displacement field, and the stresses at the Gauss
// points. Element by element with the full tensor-product basis (set-up and post-processing cost only).
#pragma once

#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include "solid/linear_elastic.hpp"

namespace polymech::solid {

// The basis of one element at a reference point: values, physical gradients, position and det J.
template <int D>
struct PointBasis {
  std::vector<double> N, dN;  // [ND], [ND][D] (d/dx_j)
  std::array<double, D> x{};
  double det = 0.0;
};

template <int D>
class ElementEvaluator {
 public:
  explicit ElementEvaluator(const Discretization<D>& d) : d_(d), nodes_(fem::gauss_lobatto_nodes(d.n1d)) {}

  // Basis of storage element e at reference point xi.
  PointBasis<D> at(std::int64_t e, const std::array<double, D>& xi) const {
    const int n = d_.n1d, ND = d_.nodes_per_element();
    std::vector<double> l(static_cast<std::size_t>(D) * n), dl(l.size());
    for (int k = 0; k < D; ++k)
      for (int i = 0; i < n; ++i) {
        l[k * n + i] = fem::lagrange(nodes_, i, xi[k]);
        dl[k * n + i] = fem::lagrange_derivative(nodes_, i, xi[k]);
      }
    PointBasis<D> p;
    p.N.resize(ND);
    p.dN.resize(static_cast<std::size_t>(ND) * D);
    std::vector<double> g(static_cast<std::size_t>(ND) * D);
    double J[D][D] = {};
    const std::int64_t* en = &d_.element_nodes[static_cast<std::size_t>(e) * ND];
    for (int a = 0; a < ND; ++a) {
      int ai[3] = {a % n, (a / n) % n, a / (n * n)};
      double v = 1.0;
      for (int k = 0; k < D; ++k) v *= l[k * n + ai[k]];
      p.N[a] = v;
      for (int r = 0; r < D; ++r) {
        double s = 1.0;
        for (int k = 0; k < D; ++k) s *= (k == r ? dl : l)[k * n + ai[k]];
        g[static_cast<std::size_t>(a) * D + r] = s;
        for (int c = 0; c < D; ++c) J[c][r] += d_.coordinates[static_cast<std::size_t>(D * en[a] + c)] * s;
      }
      for (int c = 0; c < D; ++c) p.x[c] += d_.coordinates[static_cast<std::size_t>(D * en[a] + c)] * v;
    }
    double Ji[D][D];
    detail::jacobian_inverse<D>(J, Ji);
    p.det = detail::jacobian_det<D>(J);
    for (int a = 0; a < ND; ++a)
      for (int j = 0; j < D; ++j) {
        double s = 0.0;
        for (int r = 0; r < D; ++r) s += g[static_cast<std::size_t>(a) * D + r] * Ji[r][j];
        p.dN[static_cast<std::size_t>(a) * D + j] = s;
      }
    return p;
  }

  // Reference coordinates of the physical point x in element e (Newton); false if it lies outside.
  bool locate(std::int64_t e, const std::array<double, D>& x, std::array<double, D>& xi) const {
    xi.fill(0.0);
    for (int it = 0; it < 50; ++it) {
      const PointBasis<D> p = at(e, xi);
      // dx/dxi by forward differences of the interpolated position: the residual x - x(xi) is exact, so
      // Newton still converges to the point; the approximate Jacobian only makes it linear (rate ~1e-7)
      double J[D][D] = {}, Ji[D][D];
      const double h = 1e-7;
      for (int r = 0; r < D; ++r) {
        std::array<double, D> xp = xi;
        xp[r] += h;
        const PointBasis<D> q = at(e, xp);
        for (int c = 0; c < D; ++c) J[c][r] = (q.x[c] - p.x[c]) / h;
      }
      detail::jacobian_inverse<D>(J, Ji);
      double step = 0.0;
      for (int r = 0; r < D; ++r) {
        double s = 0.0;
        for (int c = 0; c < D; ++c) s += Ji[r][c] * (x[c] - p.x[c]);
        xi[r] += s;
        step = std::max(step, std::abs(s));
      }
      if (step < 1e-14) break;
    }
    for (int r = 0; r < D; ++r)
      if (!(std::abs(xi[r]) <= 1.0 + 1e-9)) return false;
    return true;
  }

 private:
  const Discretization<D>& d_;
  std::vector<double> nodes_;
};

// Displacement at the physical point x (the first element that holds it).
template <class T, int D>
std::array<double, D> displacement_at(const LinearElastic<T, D>& m, const std::array<double, D>& x) {
  const auto& d = m.discretization();
  const ElementEvaluator<D> ev(d);
  const std::vector<double> u = m.displacement_host();
  const int ND = d.nodes_per_element();
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    const std::int64_t* en = &d.element_nodes[e * ND];
    bool inside = true;  // bounding box of the element's nodes, with a margin
    for (int c = 0; c < D && inside; ++c) {
      double lo = 1e300, hi = -1e300;
      for (int a = 0; a < ND; ++a) {
        lo = std::min(lo, d.coordinates[static_cast<std::size_t>(D * en[a] + c)]);
        hi = std::max(hi, d.coordinates[static_cast<std::size_t>(D * en[a] + c)]);
      }
      const double margin = 1e-9 * (hi - lo);
      inside = x[c] >= lo - margin && x[c] <= hi + margin;
    }
    std::array<double, D> xi;
    if (!inside || !ev.locate(static_cast<std::int64_t>(e), x, xi)) continue;
    const PointBasis<D> p = ev.at(static_cast<std::int64_t>(e), xi);
    std::array<double, D> out{};
    for (int a = 0; a < ND; ++a)
      for (int c = 0; c < D; ++c) out[c] += p.N[a] * u[static_cast<std::size_t>(D * en[a] + c)];
    return out;
  }
  throw std::invalid_argument("solid: the point lies outside the mesh");
}

struct L2Error {
  double error = 0.0, reference = 0.0;  // sqrt(int |u_h - u|^2), sqrt(int |u|^2)
  double relative() const { return reference > 0 ? error / reference : error; }
};

// Relative L2 error of the displacement against exact(x, u) with N + 1 Gauss points per direction.
template <class T, int D>
L2Error l2_error(const LinearElastic<T, D>& m, const PointFunction& exact) {
  const auto& d = m.discretization();
  const ElementEvaluator<D> ev(d);
  const std::vector<double> u = m.displacement_host();
  const int ND = d.nodes_per_element(), Qe = d.n1d + 1, QD = D == 3 ? Qe * Qe * Qe : Qe * Qe;
  std::vector<double> xq, wq;
  fem::gauss_legendre(Qe, xq, wq);
  double err = 0.0, ref = 0.0;
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    const std::int64_t* en = &d.element_nodes[e * ND];
    for (int q = 0; q < QD; ++q) {
      const int qi[3] = {q % Qe, (q / Qe) % Qe, q / (Qe * Qe)};
      std::array<double, D> xi;
      double w = 1.0;
      for (int k = 0; k < D; ++k) {
        xi[k] = xq[qi[k]];
        w *= wq[qi[k]];
      }
      const PointBasis<D> p = ev.at(static_cast<std::int64_t>(e), xi);
      double ex[3] = {0, 0, 0}, pos[3] = {p.x[0], p.x[1], D == 3 ? p.x[D - 1] : 0.0};
      exact(pos, ex);
      for (int c = 0; c < D; ++c) {
        double uh = 0.0;
        for (int a = 0; a < ND; ++a) uh += p.N[a] * u[static_cast<std::size_t>(D * en[a] + c)];
        err += w * p.det * (uh - ex[c]) * (uh - ex[c]);
        ref += w * p.det * ex[c] * ex[c];
      }
    }
  }
  return {std::sqrt(err), std::sqrt(ref)};
}

// Stresses at the operator's Gauss points (N per direction): [elements in storage order][Q^D][S] with the
// reduced Voigt components (3D: 11, 22, 33, 23, 13, 12; 2D: 11, 22, 12), from the element stiffness.
template <class T, int D>
std::vector<double> quadrature_stresses(const LinearElastic<T, D>& m) {
  constexpr int S = strain_components<D>;
  const auto& d = m.discretization();
  const ElementEvaluator<D> ev(d);
  const std::vector<double> u = m.displacement_host();
  const auto mat = Kokkos::create_mirror_view_and_copy(HostSpace(), m.elements().material);
  const int ND = d.nodes_per_element(), Q = d.n1d, QD = D == 3 ? Q * Q * Q : Q * Q;
  std::vector<double> xq, wq;
  fem::gauss_legendre(Q, xq, wq);
  std::vector<double> out;
  out.reserve(d.element_cells.size() * QD * S);
  for (std::size_t e = 0; e < d.element_cells.size(); ++e) {
    const std::int64_t* en = &d.element_nodes[e * ND];
    for (int q = 0; q < QD; ++q) {
      const int qi[3] = {q % Q, (q / Q) % Q, q / (Q * Q)};
      std::array<double, D> xi;
      for (int k = 0; k < D; ++k) xi[k] = xq[qi[k]];
      const PointBasis<D> p = ev.at(static_cast<std::int64_t>(e), xi);
      double H[D][D] = {};
      for (int a = 0; a < ND; ++a)
        for (int c = 0; c < D; ++c)
          for (int j = 0; j < D; ++j)
            H[c][j] += u[static_cast<std::size_t>(D * en[a] + c)] * p.dN[static_cast<std::size_t>(a) * D + j];
      double eps[S];
      voigt_strain<D>(H, eps);
      for (int i = 0; i < S; ++i) {
        double s = 0.0;
        for (int j = 0; j < S; ++j)
          s += static_cast<double>(mat(e, 6 * voigt_component<D>(i) + voigt_component<D>(j))) * eps[j];
        out.push_back(s);
      }
    }
  }
  return out;
}

}  // namespace polymech::solid
