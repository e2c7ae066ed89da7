// The assembled matrices of the linear piezoelectric solid (issue 35; seed 002 paper 1 eqs. (4)-(6)), host,
// double. With E = -grad phi and the stress-charge law T = C S - e^T E, D = e S + eps E, the weak forms of
// Cauchy's law (eq. (4)) and of Gauss's law (eq. (5), quasi-static) are
//   int S(v) : (C S(u) + e^T grad phi) dV = f(v)                                  (mechanical)
//   int grad w . (e S(u) - eps grad phi) dV = -int w sigma_f dA                   (electrical)
// where sigma_f is the free surface charge on an electrode (D . n = -sigma_f with n the dielectric's outward
// normal). The electrical rows are negated so the coupled matrix is symmetric (and indefinite):
//   [ Kuu    Kuphi ] [u  ]   [ f  ]      Kuu   = int B^T C B,   Kuphi = int B^T e^T G,
//   [ Kuphi^T -Kpp ] [phi] = [ -Q ]      Kpp   = int G^T eps G  (G: the gradients of the shape functions)
// so that the sum of the electrical rows of an electrode's nodes is minus the charge Q on it. The consistent
// mass M = int rho N^T N acts on u only (the electrical equation is quasi-static).
//
// The element matrices are evaluated directly (full tensor-product basis at the Q = p + 1 Gauss points, the
// Jacobian formed point by point; kernels/solid/assembly.hpp does the same for the elastic matrix, whose
// (u, u) block this reproduces). The caller numbers the unknowns: dof_u[D node + c] and dof_phi[node] give the
// global index or -1 (a clamped component; a grounded or potential-free node). Several nodes may share one
// potential index: an electrode is an equipotential surface with one unknown, and the sum of its nodes' rows
// is what the shared index assembles. In 2D every integral is multiplied by the out-of-plane width.
// O(N^(3D)) per element: for the harvester's meshes (a few thousand elements), called once per model.
#pragma once

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/basis.hpp"
#include "solid/assembly.hpp"
#include "piezo/fe_law.hpp"

namespace polymech::piezo {

// Coordinate form of a sparse matrix: the solid layer's (kernels/solid/assembly.hpp).
using SparseTriplets = solid::Triplets;
inline void add_entry(SparseTriplets& t, std::int64_t r, std::int64_t c, double v) {
  t.rows.push_back(r);
  t.cols.push_back(c);
  t.values.push_back(v);
}

// A host CSR matrix (repeated entries summed) for the products the solvers need: y = A x.
struct HostCsr {
  std::int64_t n = 0;
  std::vector<std::int64_t> ptr, col;
  std::vector<double> val;

  explicit HostCsr(const SparseTriplets& t = {}) : n(t.n) {
    // bucket the entries by row (counting sort), then sort and merge each row's columns
    const auto rows_n = static_cast<std::size_t>(n);
    std::vector<std::size_t> start(rows_n + 1, 0);
    for (const auto r : t.rows) ++start[static_cast<std::size_t>(r) + 1];
    for (std::size_t r = 0; r < rows_n; ++r) start[r + 1] += start[r];
    std::vector<std::size_t> order(t.values.size()), fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < t.values.size(); ++k) order[fill[static_cast<std::size_t>(t.rows[k])]++] = k;
    ptr.assign(rows_n + 1, 0);
    col.reserve(t.values.size());
    val.reserve(t.values.size());
    for (std::size_t r = 0; r < rows_n; ++r) {
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(start[r]), order.begin() + static_cast<std::ptrdiff_t>(start[r + 1]),
                [&](std::size_t a, std::size_t b) { return t.cols[a] < t.cols[b]; });
      const std::size_t first = col.size();
      for (std::size_t k = start[r]; k < start[r + 1]; ++k) {
        const std::size_t i = order[k];
        if (col.size() > first && col.back() == t.cols[i]) {
          val.back() += t.values[i];
        } else {
          col.push_back(t.cols[i]);
          val.push_back(t.values[i]);
        }
      }
      ptr[r + 1] = static_cast<std::int64_t>(col.size());
    }
  }
  // The entries back as triplets, one per (row, column): what the factorisations copy (the element-by-element
  // triplets hold each entry up to 2^D times).
  SparseTriplets triplets() const {
    SparseTriplets t;
    t.n = n;
    t.rows.reserve(val.size());
    t.cols = col;
    t.values = val;
    for (std::int64_t r = 0; r < n; ++r)
      for (std::int64_t k = ptr[static_cast<std::size_t>(r)]; k < ptr[static_cast<std::size_t>(r) + 1]; ++k) t.rows.push_back(r);
    return t;
  }
  // y = A x (y resized)
  void apply(const std::vector<double>& x, std::vector<double>& y) const {
    y.assign(static_cast<std::size_t>(n), 0.0);
    for (std::int64_t r = 0; r < n; ++r) {
      double s = 0.0;
      for (std::int64_t k = ptr[static_cast<std::size_t>(r)]; k < ptr[static_cast<std::size_t>(r) + 1]; ++k)
        s += val[static_cast<std::size_t>(k)] * x[static_cast<std::size_t>(col[static_cast<std::size_t>(k)])];
      y[static_cast<std::size_t>(r)] = s;
    }
  }
  double dot(const std::vector<double>& x, const std::vector<double>& y) const {  // x^T A y
    std::vector<double> t;
    apply(y, t);
    return std::inner_product(x.begin(), x.end(), t.begin(), 0.0);
  }
};

struct PiezoAssemblyInput {
  int dim = 2, order = 1;
  double width = 1.0;                        // 2D: the out-of-plane width the integrals are multiplied by
  std::vector<std::int64_t> element_nodes;   // elements x N^D (a = i + N (j + N k))
  std::vector<double> coordinates;           // nodes x D
  std::vector<int> element_law;              // elements: index into laws
  std::vector<FeLaw> laws;
  std::vector<std::int64_t> dof_u;           // nodes x D: global index or -1
  std::vector<std::int64_t> dof_phi;         // nodes: global index or -1
  std::int64_t unknowns = 0;
};

struct PiezoMatrices {
  SparseTriplets K;  // the coupled symmetric matrix above
  SparseTriplets M;  // the consistent mass on the displacement unknowns
  SparseTriplets Kuu;  // the elastic (u, u) block alone (for stiffness-proportional damping)
};

inline PiezoMatrices assemble_piezo(const PiezoAssemblyInput& in) {
  const int D = in.dim, N = in.order + 1, Q = N;
  if (D != 2 && D != 3) throw std::invalid_argument("assemble_piezo: dimension " + std::to_string(D));
  const int ND = D == 3 ? N * N * N : N * N, QD = D == 3 ? Q * Q * Q : Q * Q, S = D == 3 ? 6 : 3;
  const fem::GaussTables tables = fem::gauss_tables(N);  // Q = N
  const std::int64_t ne = static_cast<std::int64_t>(in.element_law.size());
  if (static_cast<std::int64_t>(in.element_nodes.size()) != ne * ND)
    throw std::invalid_argument("assemble_piezo: element table and law list disagree");
  const double scale = D == 2 ? in.width : 1.0;
  PiezoMatrices out;
  out.K.n = out.M.n = out.Kuu.n = in.unknowns;
  {  // reserve the upper bounds of the entries (the reallocations cost a third of the assembly's time)
    const auto per = static_cast<std::size_t>(ne);
    const auto nl = static_cast<std::size_t>((D + 1) * ND), nu = static_cast<std::size_t>(D * ND);
    for (auto* t : {&out.K, &out.Kuu, &out.M}) {
      const std::size_t k = per * (t == &out.K ? nl * nl : t == &out.Kuu ? nu * nu : nu * static_cast<std::size_t>(ND));
      t->rows.reserve(k);
      t->cols.reserve(k);
      t->values.reserve(k);
    }
  }
  const int NL = (D + 1) * ND;  // local: u (a, c) -> a D + c, phi a -> D ND + a
  std::vector<double> Ke(static_cast<std::size_t>(NL) * NL), Me(static_cast<std::size_t>(ND) * ND);
  std::vector<double> grad(static_cast<std::size_t>(ND) * D), val(static_cast<std::size_t>(ND));
  std::vector<double> B(static_cast<std::size_t>(S) * ND * D);  // B[s][(a, c)]
  std::vector<std::int64_t> gl(static_cast<std::size_t>(NL));
  const int NU = ND * D;
  std::vector<double> CB(static_cast<std::size_t>(S) * NU), eB(static_cast<std::size_t>(D) * NU);
  for (std::int64_t e = 0; e < ne; ++e) {
    const std::int64_t* en = &in.element_nodes[static_cast<std::size_t>(e) * ND];
    const FeLaw& law = in.laws[static_cast<std::size_t>(in.element_law[static_cast<std::size_t>(e)])];
    std::fill(Ke.begin(), Ke.end(), 0.0);
    std::fill(Me.begin(), Me.end(), 0.0);
    for (int q = 0; q < QD; ++q) {
      double w;
      const double det = fem::tensor_point(tables, D, q, en, in.coordinates, val.data(), grad.data(), w);
      if (!(det > 0.0))
        throw std::invalid_argument("assemble_piezo: element " + std::to_string(e) + " is inverted (det J <= 0)");
      // strain-displacement: B[s][(a, c)] (Voigt of the element, engineering shears)
      std::fill(B.begin(), B.end(), 0.0);
      auto b = [&](int s, int a, int c) -> double& { return B[(static_cast<std::size_t>(s) * ND + a) * D + c]; };
      for (int a = 0; a < ND; ++a) {
        const double* g = &grad[static_cast<std::size_t>(a) * D];
        if (D == 2) {
          b(0, a, 0) = g[0];
          b(1, a, 1) = g[1];
          b(2, a, 0) = g[1];
          b(2, a, 1) = g[0];
        } else {
          b(0, a, 0) = g[0];
          b(1, a, 1) = g[1];
          b(2, a, 2) = g[2];
          b(3, a, 1) = g[2];
          b(3, a, 2) = g[1];
          b(4, a, 0) = g[2];
          b(4, a, 2) = g[0];
          b(5, a, 0) = g[1];
          b(5, a, 1) = g[0];
        }
      }
      const double wd = w * det * scale;
      // CB[s][(a, c)] = C B, eB[k][(a, c)] = e B
      std::fill(CB.begin(), CB.end(), 0.0);
      std::fill(eB.begin(), eB.end(), 0.0);
      for (int s = 0; s < S; ++s)
        for (int t = 0; t < S; ++t) {
          const double c = law.C[s][t];
          if (c == 0.0) continue;
          for (int i = 0; i < NU; ++i) CB[static_cast<std::size_t>(s) * NU + i] += c * B[static_cast<std::size_t>(t) * NU + i];
        }
      if (law.piezoelectric)
        for (int k = 0; k < D; ++k)
          for (int t = 0; t < S; ++t) {
            const double c = law.e[k][t];
            if (c == 0.0) continue;
            for (int i = 0; i < NU; ++i) eB[static_cast<std::size_t>(k) * NU + i] += c * B[static_cast<std::size_t>(t) * NU + i];
          }
      for (int i = 0; i < NU; ++i)
        for (int j = 0; j < NU; ++j) {
          double s = 0.0;
          for (int t = 0; t < S; ++t) s += B[static_cast<std::size_t>(t) * NU + i] * CB[static_cast<std::size_t>(t) * NU + j];
          Ke[static_cast<std::size_t>(i) * NL + j] += wd * s;
        }
      if (law.piezoelectric) {
        for (int i = 0; i < NU; ++i)
          for (int a = 0; a < ND; ++a) {  // Kuphi = int B^T e^T G: (e B)_k,i G_k,a
            double s = 0.0;
            for (int k = 0; k < D; ++k) s += eB[static_cast<std::size_t>(k) * NU + i] * grad[static_cast<std::size_t>(a) * D + k];
            Ke[static_cast<std::size_t>(i) * NL + NU + a] += wd * s;
            Ke[static_cast<std::size_t>(NU + a) * NL + i] += wd * s;
          }
        for (int a = 0; a < ND; ++a)
          for (int c = 0; c < ND; ++c) {
            double s = 0.0;
            for (int k = 0; k < D; ++k)
              for (int l = 0; l < D; ++l)
                s += grad[static_cast<std::size_t>(a) * D + k] * law.eps[k][l] * grad[static_cast<std::size_t>(c) * D + l];
            Ke[static_cast<std::size_t>(NU + a) * NL + NU + c] -= wd * s;
          }
      }
      for (int a = 0; a < ND; ++a)
        for (int c = 0; c < ND; ++c) Me[static_cast<std::size_t>(a) * ND + c] += wd * law.rho * val[a] * val[c];
    }
    for (int a = 0; a < ND; ++a) {
      for (int c = 0; c < D; ++c) gl[static_cast<std::size_t>(a * D + c)] = in.dof_u[static_cast<std::size_t>(D * en[a] + c)];
      gl[static_cast<std::size_t>(ND * D + a)] = law.piezoelectric ? in.dof_phi[static_cast<std::size_t>(en[a])] : -1;
    }
    for (int i = 0; i < NL; ++i) {
      if (gl[i] < 0) continue;
      for (int j = 0; j < NL; ++j) {
        const double v = Ke[static_cast<std::size_t>(i) * NL + j];
        if (gl[j] < 0 || v == 0.0) continue;
        add_entry(out.K, gl[i], gl[j], v);
        if (i < ND * D && j < ND * D) add_entry(out.Kuu, gl[i], gl[j], v);
      }
    }
    for (int a = 0; a < ND; ++a)
      for (int c = 0; c < ND; ++c)
        for (int d = 0; d < D; ++d) {
          const std::int64_t r = gl[static_cast<std::size_t>(a * D + d)], col = gl[static_cast<std::size_t>(c * D + d)];
          if (r >= 0 && col >= 0) add_entry(out.M, r, col, Me[static_cast<std::size_t>(a) * ND + c]);
        }
  }
  return out;
}

}  // namespace polymech::piezo
