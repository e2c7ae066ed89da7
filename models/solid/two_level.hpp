// A two-level p-multigrid preconditioner for the solid's constrained stiffness (issue 34): Chebyshev
// smoothing on the order-p operator (matrix-free, kernels/solvers/chebyshev.hpp on D^-1 K) and an exact
// coarse correction with the order-1 stiffness of the same mesh (assembled, host sparse LU, factorised
// once). One application is the symmetric V-cycle
//   z = S r,   z += P A1^-1 P^T (r - K z),   z += S (r - K z),
// with S the same Chebyshev polynomial before and after, so the cycle is symmetric positive definite and
// preconditions CG (the Helmholtz model's p-multigrid, models/helmholtz/preconditioners.hpp, is the same
// cycle on several orders; here the coarse level is solved directly).
//
// Why: Jacobi CG needs O(h^-1) iterations (700 at 1.6e4 DoFs on the 3D cantilever of
// bench/peer_solid_cantilever.cpp), and the 3D sparse LU of the order-p matrix fills in badly (5 s at
// 1.6e4 DoFs of order 2, 280 s at 1.1e5 of order 4). The order-1 matrix has about 1/p^3 of the DoFs and a
// 27-point stencil, so its LU stays cheap, and the smoother takes the high-order modes
// (docs/PERFORMANCE.md has the measured iteration counts and times).
//
// The prolongation P is the order-1 interpolant at the order-p GLL nodes of each cell (the multilinear
// weights of the node's position), built from the two discretizations' element tables matched by cell;
// constrained DoFs of either level take and give nothing. Any fine operator with the Krylov operator
// concept applies (the elastic stiffness, or a Newton tangent: the coarse level then stays elastic, which
// keeps it a preconditioner, not the tangent's inverse).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/host_copy.hpp"
#include "fem/transfer.hpp"
#include "solid/linear_elastic.hpp"
#include "solvers/chebyshev.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::solid {

// Defaults measured on the micro-cantilever's load-unload curve (docs/PERFORMANCE.md): degree 3 -> 5 and range
// 10 -> 30 take CG from 2 894 to 1 265 iterations for the same 54-60 Newton iterations at 152 661 DoFs; the
// float coarse factors solve in 15.7 ms instead of 23.2 (21 141 DoFs) with the same iteration count.
struct TwoLevelOptions {
  int smoothing_degree = 5;       // Chebyshev degree of each smoothing (applications of K)
  double smoothing_range = 30.0;  // the smoother acts on [hi / range, hi] of the spectrum of D^-1 K
  int lanczos_steps = 20;         // CG steps of the spectrum estimate
  bool coarse_single = true;      // the coarse LU factors in float (the cycle only preconditions; measured faster)
};

// The order-1 interpolant at the order-p nodes, fine DoFs x coarse DoFs (transpose: coarse x fine), both
// discretizations of the same mesh; constrained DoFs (per DoF flags) of either left out.
template <int D>
std::vector<std::vector<std::pair<Index, double>>> order_one_interpolation(const Discretization<D>& fine,
                                                                           const std::vector<char>& fine_constrained,
                                                                           const Discretization<D>& coarse,
                                                                           const std::vector<char>& coarse_constrained,
                                                                           bool transpose) {
  if (coarse.order != 1) throw std::invalid_argument("solid two-level: the coarse discretization must be of order 1");
  const int N = fine.n1d, p = fine.order, ND = fine.nodes_per_element(), NC = 1 << D;
  const std::vector<double> gll = fem::gauss_lobatto_nodes(N);
  // the coarse element of each cell
  std::int64_t cells = 0;
  for (const std::int64_t c : coarse.element_cells) cells = std::max(cells, c + 1);
  for (const std::int64_t c : fine.element_cells) cells = std::max(cells, c + 1);
  std::vector<std::int64_t> coarse_of_cell(static_cast<std::size_t>(cells), -1);
  for (std::size_t e = 0; e < coarse.element_cells.size(); ++e)
    coarse_of_cell[static_cast<std::size_t>(coarse.element_cells[e])] = static_cast<std::int64_t>(e);
  // weights of the 2^D corners at local node a
  std::vector<double> w(static_cast<std::size_t>(ND * NC));
  for (int a = 0; a < ND; ++a)
    for (int v = 0; v < NC; ++v) {
      double x = 1.0;
      for (int d = 0, r = a; d < D; ++d, r /= N) {
        const int i = r % N;
        const double t = i == 0 ? 0.0 : i == p ? 1.0 : 0.5 * (1.0 + gll[i]);
        x *= ((v >> d) & 1) ? t : 1.0 - t;
      }
      w[static_cast<std::size_t>(a * NC + v)] = x;
    }
  std::vector<std::vector<std::pair<Index, double>>> rows(
      static_cast<std::size_t>(D * (transpose ? coarse.nodes : fine.nodes)));
  std::vector<char> done(static_cast<std::size_t>(fine.nodes), 0);
  for (std::size_t e = 0; e < fine.element_cells.size(); ++e) {
    const std::int64_t ce = coarse_of_cell[static_cast<std::size_t>(fine.element_cells[e])];
    if (ce < 0) throw std::invalid_argument("solid two-level: a cell of the fine mesh is missing from the coarse one");
    for (int a = 0; a < ND; ++a) {
      const std::int64_t f = fine.element_nodes[e * ND + a];
      if (done[static_cast<std::size_t>(f)]) continue;
      done[static_cast<std::size_t>(f)] = 1;
      for (int v = 0; v < NC; ++v) {
        const double x = w[static_cast<std::size_t>(a * NC + v)];
        if (x == 0.0) continue;
        const std::int64_t g = coarse.element_nodes[static_cast<std::size_t>(ce) * NC + v];
        for (int c = 0; c < D; ++c) {
          const std::int64_t fd = D * f + c, gd = D * g + c;
          if (fine_constrained[static_cast<std::size_t>(fd)] || coarse_constrained[static_cast<std::size_t>(gd)]) continue;
          if (transpose)
            rows[static_cast<std::size_t>(gd)].push_back({static_cast<Index>(fd), x});
          else
            rows[static_cast<std::size_t>(fd)].push_back({static_cast<Index>(gd), x});
        }
      }
    }
  }
  return rows;
}

// The preconditioner for an operator Op (krylov.hpp concept, value type T) on the DoFs of a model built
// from `config` (its discretization and constrained flags given); the coarse level is the order-1
// LinearElastic model of the same configuration.
template <class T, int D, class Op>
class TwoLevel {
 public:
  TwoLevel(const Op* op, const View1<T>& inv_diag, const Config<D>& config, const Discretization<D>& fine,
           const std::vector<char>& fine_constrained, const TwoLevelOptions& o = {})
      : op_(op) {
    Config<D> c1 = config;
    c1.order = 1;
    c1.plasticity.reset();  // the coarse level is the elastic stiffness (a preconditioner of the tangent too)
    const LinearElastic<double, D> coarse(c1);
    const Triplets a1 = coarse.assemble();
    lu_ = std::make_shared<solvers::HostSparseLU>();
    lu_->factor(a1.n, a1.rows, a1.cols, a1.values, o.coarse_single);
    P_ = fem::make_transfer<T>(order_one_interpolation(fine, fine_constrained, coarse.discretization(),
                                                       coarse.constrained_mask(), false));
    R_ = fem::make_transfer<T>(order_one_interpolation(fine, fine_constrained, coarse.discretization(),
                                                       coarse.constrained_mask(), true));
    coarse_dofs_ = static_cast<Index>(a1.n);
    spectrum_ = solvers::estimate_spectrum(*op, inv_diag, o.lanczos_steps);
    const double hi = 1.1 * spectrum_.hi;
    smoother_ = solvers::Chebyshev<Op, T>(op, inv_diag, hi / o.smoothing_range, hi, o.smoothing_degree);
    const Index n = op->local_size();
    res_ = View1<T>("polymech::solid::two_level_residual", n);
    kz_ = View1<T>("polymech::solid::two_level_kz", n);
    rc_ = View1<T>("polymech::solid::two_level_coarse", coarse_dofs_);
  }

  Index coarse_dofs() const { return coarse_dofs_; }
  const solvers::Spectrum& spectrum() const { return spectrum_; }
  std::string describe() const {
    return "two-level p-multigrid: Chebyshev degree " + std::to_string(smoother_.degree()) +
           " on D^-1 K, order-1 coarse level (" + std::to_string(coarse_dofs_) + " DoFs, sparse LU)";
  }

  // z = M r (the preconditioner concept of krylov.hpp).
  void apply(const View1<T>& r, const View1<T>& z) const {
    const Index n = op_->local_size();
    smoother_.apply(r, z);  // pre-smoothing from zero
    op_->apply(z, kz_);
    solvers::detail::subtract_from(n, r, kz_, res_);
    R_.template apply<false>(res_, rc_);
    std::vector<double> b = models::to_host(rc_);
    lu_->solve(b.data());
    auto h = Kokkos::create_mirror_view(rc_);
    for (std::size_t i = 0; i < b.size(); ++i) h(i) = static_cast<T>(b[i]);
    Kokkos::deep_copy(rc_, h);
    P_.template apply<true>(rc_, z);  // coarse correction
    smoother_.smooth(r, z);           // post-smoothing
  }

 private:
  const Op* op_ = nullptr;
  std::shared_ptr<solvers::HostSparseLU> lu_;
  fem::Transfer<T> P_, R_;
  Index coarse_dofs_ = 0;
  solvers::Spectrum spectrum_;
  solvers::Chebyshev<Op, T> smoother_;
  View1<T> res_, kz_, rc_;
};

}  // namespace polymech::solid
