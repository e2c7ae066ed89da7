// The static linear solid model (issue 34): small-strain linear elasticity on a structured mesh of order-p
// quadrilaterals (D = 2, plane strain or plane stress) or hexahedra (D = 3), continuous vector-valued
// Lagrange DoFs (D per node, interleaved), strong Dirichlet conditions, tractions and body forces. It builds
// the constrained system
//   K_ff u_f = f_f - K_fc g,   u_c = g
// (identity rows on the constrained DoFs: symmetric positive definite), and solves it either matrix-free
// with Jacobi-preconditioned CG (kernels/solvers/krylov.hpp) or assembled with the host sparse LU
// (kernels/solvers/host_sparse_lu.hpp). Templated on the precision T of the operator and the solution.
// The set-up (elements, constraints, loads) is solid::SolidProblem (problem.hpp), shared with ElastoPlastic.
#pragma once

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/problem.hpp"
#include "solvers/host_sparse_lu.hpp"
#include "solvers/krylov.hpp"

namespace polymech::solid {

// Wall time and outcome of a direct solve.
struct DirectSolveResult {
  double assembly_seconds = 0.0, factor_seconds = 0.0, solve_seconds = 0.0;
  std::int64_t nonzeros = 0;
};

template <class T, int D>
class LinearElastic : public SolidProblem<T, D> {
  using Base = SolidProblem<T, D>;

 public:
  explicit LinearElastic(const Config<D>& c) : Base(c), u_("polymech::solid::displacement", Base::dof_count()) {
    if (c.plasticity)
      throw std::invalid_argument("solid::LinearElastic: the configuration carries a plastic law; use solid::ElastoPlastic");
  }

  const View1<T>& displacement() const { return u_; }

  // Matrix-free CG with Jacobi from u = g on the constrained DoFs, 0 elsewhere.
  solvers::SolveResult solve_cg(const solvers::SolverOptions& o = {}) {
    if (inv_diag_.extent(0) == 0) inv_diag_ = this->op_.inverse_diagonal();
    Kokkos::deep_copy(u_, T(0));
    fem::set_constrained_values(this->op_.constrained, this->g_, u_);
    return solvers::cg(this->op_, inv_diag_, this->rhs_, u_, o);
  }

  // r = f_int(u) - f_ext off the constrained rows, zero on them: the residual a Newton driver drives to zero
  // (for this linear law f_int(u) = K u; u carries the Dirichlet values on the constrained DoFs).
  void residual(const View1<T>& u, const View1<T>& r) const {
    solvers::scale(this->dof_count(), T(-1), this->f_ext_, r);
    add_internal_force<false>("polymech::solid::internal_force", this->op_.el, ElementStiffness<T>{this->op_.el.material},
                              u, r);
    fem::fill_constrained(this->op_.constrained, T(0), r);
  }

  // The assembled constrained matrix, in double on the host (rows and columns of constrained DoFs: identity).
  Triplets assemble() const { return this->assemble_elastic(); }

  // Sparse LU of the assembled system on the host (double), the solution stored in T.
  DirectSolveResult solve_direct() {
    using clock = std::chrono::steady_clock;
    DirectSolveResult r;
    auto t0 = clock::now();
    const Triplets t = assemble();
    auto t1 = clock::now();
    solvers::HostSparseLU lu;
    lu.factor(t.n, t.rows, t.cols, t.values);
    auto t2 = clock::now();
    std::vector<double> b = models::to_host(this->rhs_);
    lu.solve(b.data());
    auto uh = Kokkos::create_mirror_view(u_);
    for (std::size_t i = 0; i < b.size(); ++i) uh(i) = static_cast<T>(b[i]);
    Kokkos::deep_copy(u_, uh);
    auto t3 = clock::now();
    r.assembly_seconds = std::chrono::duration<double>(t1 - t0).count();
    r.factor_seconds = std::chrono::duration<double>(t2 - t1).count();
    r.solve_seconds = std::chrono::duration<double>(t3 - t2).count();
    r.nonzeros = static_cast<std::int64_t>(t.values.size());
    return r;
  }

  // The solution on the host, double, nodes x D.
  std::vector<double> displacement_host() const { return models::to_host(u_); }

 private:
  View1<T> u_, inv_diag_;
};

}  // namespace polymech::solid
