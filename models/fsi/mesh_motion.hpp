// Mesh motion for the ALE fluid (issue 36; seed 002 paper 1, "pseudo-elastic mesh smoothing"): the displacement
// of the wet interface is extended into the fluid mesh by solving linear elasticity on the reference mesh,
//   div sigma(d) = 0,  sigma = lambda_m tr(eps) I + 2 mu_m eps,  eps = (grad d + grad d^T) / 2,
// with d = the interface displacement on the interface nodes and d = 0 on every other boundary node (the channel
// walls, the inflow and outflow lines, the rigid cylinder). The pseudo-material is stiffened where the cells are
// small, E(x) = (Jbar / det J(x))^chi at each Gauss point (Jbar the mean det J; Stein, Tezduyar & Benney 2003,
// "Mesh moving techniques for fluid-structure interactions with large displacements", J. Appl. Mech. 70, the
// Jacobian-based stiffening with chi = 1 by default), with a Poisson ratio nu_m (0.3 by default): the small cells
// near the flag and the cylinder then move almost rigidly and the large cells far away absorb the strain.
//
// Discretisation: the flow mesh's own Q2 (nine-node, isoparametric) elements and 3 x 3 Gauss points, so the
// moved mesh x = X + d is again a Q2 mesh whose curved cells stay curved. The operator is linear and depends on
// the reference mesh only, so the free-free stiffness is assembled and factorised once (host sparse LU); every
// motion is then a right-hand side -K_fi d_i and two triangular solves.
//
// Why not the solid layer's elastic operator (issue 36 asks to reuse it): solid::SolidProblem and its kernels
// work on one logically Cartesian lattice (solid::StructuredMesh: one block, every interior vertex of valence 4),
// while the Turek-Hron fluid mesh is 20 Coons blocks merged at their edges, with vertices of valence 3 and 5 where
// the ring around the cylinder meets the channel's columns; it cannot be written as one lattice. The element
// integrals here are the same plane-strain isotropic ones (lambda, mu), written for the flow's node order.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/basis.hpp"
#include "fem/point_basis.hpp"
#include "flow/mesh.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::fsi {

struct MeshMotionOptions {
  double poisson = 0.3;  // nu_m of the pseudo-material (< 0.5)
  double chi = 1.0;      // stiffening exponent: E = (Jbar / det J)^chi (0: uniform)
};

class PseudoElasticMeshMotion {
 public:
  // reference: the fluid mesh at rest; interface: the nodes whose displacement is given (a subset of the
  // boundary nodes); every other node with a boundary tag is held at zero, the nodes without one move.
  PseudoElasticMeshMotion(const flow::QuadMesh& reference, const std::vector<std::int64_t>& interface,
                          const MeshMotionOptions& o = {})
      : X_(reference.x), elements_(reference.elements), interface_(interface), o_(o) {
    if (!(o.poisson >= 0.0 && o.poisson < 0.5)) throw std::invalid_argument("mesh motion: the Poisson ratio must be in [0, 0.5)");
    if (!(o.chi >= 0.0)) throw std::invalid_argument("mesh motion: the stiffening exponent chi must be >= 0");
    nn_ = reference.node_count();
    ne_ = reference.element_count();
    std::vector<std::int64_t> iface_of(static_cast<std::size_t>(nn_), -1);
    for (std::size_t k = 0; k < interface.size(); ++k) {
      const std::int64_t n = interface[k];
      if (n < 0 || n >= nn_) throw std::invalid_argument("mesh motion: interface node " + std::to_string(n) + " is not a node");
      if (reference.tags[static_cast<std::size_t>(n)] == 0)
        throw std::invalid_argument("mesh motion: interface node " + std::to_string(n) + " is not on the boundary");
      iface_of[static_cast<std::size_t>(n)] = static_cast<std::int64_t>(k);
    }
    free_.assign(static_cast<std::size_t>(2 * nn_), -1);
    nfree_ = 0;
    for (std::int64_t n = 0; n < nn_; ++n)
      if (reference.tags[static_cast<std::size_t>(n)] == 0) {
        free_[static_cast<std::size_t>(2 * n)] = nfree_++;
        free_[static_cast<std::size_t>(2 * n + 1)] = nfree_++;
      }
    if (nfree_ == 0) throw std::invalid_argument("mesh motion: the mesh has no interior node");
    // element stiffness at 3 x 3 Gauss points (the flow's rule), scattered into K_ff and K_fi
    const fem::GaussTables tables = fem::gauss_tables(3);
    std::vector<double> grad(18), detq(static_cast<std::size_t>(ne_) * 9), wq(detq.size());
    std::vector<double> gq(static_cast<std::size_t>(ne_) * 9 * 18);
    double jsum = 0.0, wsum = 0.0;
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &elements_[static_cast<std::size_t>(e) * 9];
      for (int q = 0; q < 9; ++q) {
        double w;
        const double det = fem::tensor_point(tables, 2, q, en, X_, nullptr, grad.data(), w);
        if (!(det > 0.0)) throw std::invalid_argument("mesh motion: element " + std::to_string(e) + " is inverted");
        const std::size_t k = static_cast<std::size_t>(e) * 9 + static_cast<std::size_t>(q);
        detq[k] = det;
        wq[k] = w;
        std::copy(grad.begin(), grad.end(), gq.begin() + static_cast<std::ptrdiff_t>(k * 18));
        jsum += w * det;  // the mean det J, weighted by the reference area
        wsum += w;
      }
    }
    const double jbar = jsum / wsum, nu = o.poisson;
    std::vector<std::int64_t> rows, cols;
    std::vector<double> vals;
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &elements_[static_cast<std::size_t>(e) * 9];
      double Ke[18][18] = {};
      for (int q = 0; q < 9; ++q) {
        const std::size_t k = static_cast<std::size_t>(e) * 9 + static_cast<std::size_t>(q);
        const double E = std::pow(jbar / detq[k], o.chi);
        const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu)), dv = wq[k] * detq[k];
        const double* g = &gq[k * 18];
        // K_(a i)(b j) = int lambda dN_a/dx_i dN_b/dx_j + mu (dN_a/dx_j dN_b/dx_i + delta_ij grad N_a . grad N_b)
        for (int a = 0; a < 9; ++a)
          for (int b = 0; b < 9; ++b) {
            const double gg = g[2 * a] * g[2 * b] + g[2 * a + 1] * g[2 * b + 1];
            for (int i = 0; i < 2; ++i)
              for (int j = 0; j < 2; ++j)
                Ke[2 * a + i][2 * b + j] +=
                    dv * (lam * g[2 * a + i] * g[2 * b + j] + mu * g[2 * a + j] * g[2 * b + i] + (i == j ? mu * gg : 0.0));
          }
      }
      for (int r = 0; r < 18; ++r) {
        const std::int64_t gr = 2 * en[r / 2] + r % 2, fr = free_[static_cast<std::size_t>(gr)];
        if (fr < 0) continue;
        for (int c = 0; c < 18; ++c) {
          const std::int64_t node = en[c / 2], gc = 2 * node + c % 2, fc = free_[static_cast<std::size_t>(gc)];
          if (fc >= 0) {
            rows.push_back(fr);
            cols.push_back(fc);
            vals.push_back(Ke[r][c]);
          } else if (iface_of[static_cast<std::size_t>(node)] >= 0) {
            ki_rows_.push_back(fr);
            ki_cols_.push_back(2 * iface_of[static_cast<std::size_t>(node)] + c % 2);
            ki_vals_.push_back(Ke[r][c]);
          }
        }
      }
    }
    lu_.factor(nfree_, rows, cols, vals);
  }

  std::int64_t unknowns() const { return nfree_; }
  const std::vector<std::int64_t>& interface_nodes() const { return interface_; }

  // The mesh displacement (node_count x 2) for the interface displacement d_i (2 per interface node, in the
  // order of `interface`): d = d_i on the interface, 0 on the other boundary nodes, the elastic extension inside.
  std::vector<double> displacement(const std::vector<double>& di) const {
    if (di.size() != 2 * interface_.size())
      throw std::invalid_argument("mesh motion: " + std::to_string(di.size()) + " interface values for " +
                                  std::to_string(interface_.size()) + " nodes");
    std::vector<double> rhs(static_cast<std::size_t>(nfree_), 0.0);
    for (std::size_t k = 0; k < ki_vals_.size(); ++k)
      rhs[static_cast<std::size_t>(ki_rows_[k])] -= ki_vals_[k] * di[static_cast<std::size_t>(ki_cols_[k])];
    lu_.solve(rhs.data());
    std::vector<double> d(static_cast<std::size_t>(2 * nn_), 0.0);
    for (std::int64_t g = 0; g < 2 * nn_; ++g)
      if (free_[static_cast<std::size_t>(g)] >= 0) d[static_cast<std::size_t>(g)] = rhs[static_cast<std::size_t>(free_[static_cast<std::size_t>(g)])];
    for (std::size_t k = 0; k < interface_.size(); ++k)
      for (int c = 0; c < 2; ++c) d[static_cast<std::size_t>(2 * interface_[k] + c)] = di[2 * k + static_cast<std::size_t>(c)];
    return d;
  }

  // The moved node coordinates x = X + d.
  std::vector<double> coordinates(const std::vector<double>& d) const {
    std::vector<double> x(X_);
    for (std::size_t k = 0; k < x.size(); ++k) x[k] += d[k];
    return x;
  }

  // min over the elements and the 3 x 3 Gauss points of det J(X + d) / det J(X): > 0 keeps every cell valid,
  // 1 is a rigid motion of every cell.
  double min_jacobian_ratio(const std::vector<double>& d) const {
    const fem::GaussTables tables = fem::gauss_tables(3);
    const std::vector<double> x = coordinates(d);
    std::vector<double> grad(18);
    double m = 1e300;
    for (std::int64_t e = 0; e < ne_; ++e) {
      const std::int64_t* en = &elements_[static_cast<std::size_t>(e) * 9];
      for (int q = 0; q < 9; ++q) {
        double w;
        const double d0 = fem::tensor_point(tables, 2, q, en, X_, nullptr, grad.data(), w);
        const double d1 = fem::tensor_point(tables, 2, q, en, x, nullptr, grad.data(), w);
        m = std::min(m, d1 / d0);
      }
    }
    return m;
  }

  // The mesh velocity of a BDF step from the displacements d^(n+1), d^n, d^(n-1) (second order when bdf2, the
  // flow's time rule; backward Euler otherwise), for NavierStokes2D::set_mesh_velocity on unsteady runs.
  static std::vector<double> mesh_velocity(const std::vector<double>& d1, const std::vector<double>& d0,
                                           const std::vector<double>& dm, double dt, bool bdf2) {
    std::vector<double> w(d1.size());
    for (std::size_t k = 0; k < w.size(); ++k)
      w[k] = bdf2 ? (1.5 * d1[k] - 2.0 * d0[k] + 0.5 * dm[k]) / dt : (d1[k] - d0[k]) / dt;
    return w;
  }

 private:
  std::vector<double> X_;
  std::vector<std::int64_t> elements_, interface_;
  MeshMotionOptions o_;
  std::int64_t nn_ = 0, ne_ = 0, nfree_ = 0;
  std::vector<std::int64_t> free_, ki_rows_, ki_cols_;
  std::vector<double> ki_vals_;
  solvers::HostSparseLU lu_;
};

}  // namespace polymech::fsi
