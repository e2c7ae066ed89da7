// The quasi-static elasto-plastic solid model (issue 34): small strain, Hill (1948) plasticity with cubic
// symmetry and power-law hardening at every quadrature point (seed 002 paper 5 eqs. (1)-(4); J2 its isotropic
// case; kernels/materials/hill_plasticity.hpp), history stored per point (kernels/solid/plastic_law.hpp).
//
// Loading, Newton, the convergence test and the line search on the incremental potential are the shared
// driver's (models/solid/newton.hpp: load paths with step cutting). Here: r(u) = f_int(u) - lambda f_ext, f_int
// the sum-factorized element kernel with the plastic law (each point returns from a copy of its converged
// history); every residual evaluation also stores the consistent tangent per point, so the Newton matrix is
// exact; a failed local return mapping is a failed evaluation; a converged step commits the history.
//
// Linear solver for K_t du = -r (NewtonOptions::solver):
//   direct:      the per-point tangent assembled on the host (solid/assembly.hpp with point_material) and the
//                host sparse LU, factorized every iteration;
//   elastic_pcg: matrix-free CG on the tangent (PointStiffness apply) preconditioned by the sparse LU of the
//                ELASTIC stiffness, factorized once per model: where the plastic zone is small, K_e^-1 K_t is
//                the identity plus a low-rank-ish perturbation and CG needs few iterations;
//   two_level_pcg: the same CG preconditioned by one two-level p-multigrid cycle of the ELASTIC stiffness
//                (models/solid/two_level.hpp: Chebyshev smoothing, the order-1 stiffness by sparse LU as the
//                coarse level), set up once per model. In 3D the order-p LU fills in badly (docs/PERFORMANCE.md:
//                5 s at 1.6e4 DoFs, minutes at 1e5) while the order-1 LU stays small, so this is the 3D choice
//                beyond a few thousand DoFs (the micro-cantilever: docs/PERFORMANCE.md).
// Both are exact enough (CG to a relative 1e-10) to keep Newton's quadratic convergence. Measured timings
// are in the header of bench/bench_solid_plastic.cpp and the notes; elastic_pcg is the default.
//
// Without a plastic law in the configuration the model is linear elastic and allocates no history; one
// Newton iteration per step then solves the linear problem (the same answer as LinearElastic).
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/newton.hpp"
#include "solid/plastic_law.hpp"
#include "solid/problem.hpp"
#include "solid/two_level.hpp"
#include "solvers/host_sparse_lu.hpp"
#include "solvers/krylov.hpp"

namespace polymech::solid {

namespace detail {

// The constrained tangent for CG: y = K_t x on the free DoFs, y = x on the constrained ones.
template <class T, int D, class Law>
struct TangentOperator {
  using value_type = T;
  SolidElements<T, D> el;
  Law law;
  View1<Index> constrained;
  Index local_size() const { return el.dof_count(); }
  Index owned_size() const { return el.dof_count(); }
  void apply(const View1<T>& x, const View1<T>& y) const {
    Kokkos::deep_copy(y, T(0));
    add_internal_force<true>("polymech::solid::tangent_apply", el, law, x, y);
    fem::copy_constrained_rows(constrained, x, y);
  }
};

}  // namespace detail

template <class T, int D = 3>
class ElastoPlastic : public NewtonSolid<T, D, ElastoPlastic<T, D>> {
  using Base = NewtonSolid<T, D, ElastoPlastic<T, D>>;
  friend Base;

 public:
  explicit ElastoPlastic(const Config<D>& c, const NewtonOptions& o = {}) : Base(c, o, "solid::ElastoPlastic") {
    if (c.plasticity) {
      if (D == 2 && c.plane == Plane::stress)
        throw std::invalid_argument("solid::ElastoPlastic: plane stress plasticity is not supported (plane strain and 3D are)");
      double diff = 0.0, scale = 0.0;
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) {
          diff = std::max(diff, std::fabs(c.plasticity->C.c[i][j] - c.stiffness.c[i][j]));
          scale = std::max(scale, std::fabs(c.stiffness.c[i][j]));
        }
      if (!(diff <= 1e-12 * scale))
        throw std::invalid_argument("solid::ElastoPlastic: the plastic law's elastic stiffness C differs from "
                                    "Config::stiffness (set stiffness = plasticity->C)");
      law_ = PlasticLaw<T>(cast_law<T>(*c.plasticity), Base::element_count(), points_per_element());
    }
    f_ext_free_norm_ = this->free_norm(this->f_ext_);
    const std::vector<double> fe = models::to_host(this->f_ext_);
    for (std::size_t i = 0; i < fe.size(); ++i) f_ext_sum_[i % D] += fe[i];
  }

  bool plastic() const { return law_.allocated(); }
  const PlasticLaw<T>& law() const { return law_; }  // empty Views when elastic
  int points_per_element() const { return power<D>(this->config_.order + 1); }

  // r = f_int(u) - lambda f_ext off the constrained rows (zero on them), the plastic law returning from the
  // converged history (and storing trial history and tangent); returns |r|. u must carry its Dirichlet values.
  double residual(const View1<T>& u, double lambda, const View1<T>& r) {
    Kokkos::deep_copy(this->f_int_, T(0));
    if (plastic())
      add_internal_force<false>("polymech::solid::plastic_internal_force", this->op_.el, law_, u, this->f_int_);
    else
      add_internal_force<false>("polymech::solid::internal_force", this->op_.el, ElementStiffness<T>{this->op_.el.material},
                                u, this->f_int_);
    const auto fi = this->f_int_, fe = this->f_ext_;
    const T l = static_cast<T>(lambda);
    Kokkos::parallel_for(
        "polymech::solid::plastic_residual", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { r(i) = fi(i) - l * fe(i); });
    fem::fill_constrained(this->op_.constrained, T(0), r);
    return std::sqrt(solvers::norm2("polymech::solid::residual_norm", Base::dof_count(), r));
  }

  // y = K_t x on the free DoFs (identity on the constrained ones) with the tangent of the last residual
  // evaluation (the elastic stiffness when elastic).
  void tangent_apply(const View1<T>& x, const View1<T>& y) const {
    if (plastic())
      detail::TangentOperator<T, D, PointStiffness<T>>{this->op_.el, law_.point_stiffness(), this->op_.constrained}.apply(x, y);
    else
      this->op_.apply(x, y);
  }

  // The driver's hooks (models/solid/newton.hpp).
  double evaluate(const View1<T>& u, double lambda, const View1<T>& r) {
    const double rn = residual(u, lambda, r);
    if (plastic() && law_.counts().failed > 0) return std::numeric_limits<double>::quiet_NaN();
    return rn;
  }
  double load_norm(double lambda) const { return std::fabs(lambda) * f_ext_free_norm_; }
  double load_sum(int c, double lambda) const { return lambda * f_ext_sum_[static_cast<std::size_t>(c)]; }
  const char* failed_evaluation() const { return "a non-finite residual or a failed local return mapping"; }
  void commit(StepResult& res) {
    if (plastic()) {
      law_.commit();
      res.plastic_points = law_.counts().plastic;
    }
  }

 private:
  using Base::du_;
  using Base::last_failure_;
  using Base::options_;
  using Base::r_;

  // Solve K_t du = -r (r_ holds -r; the driver zeroes du on the constrained DoFs); false with last_failure_ set
  // on failure.
  bool solve_tangent(StepResult& res) {
    bool ok = true;
    if (options_.solver == TangentSolver::direct) {
      if (plastic() || !elastic_lu_) {
        AssemblyInput in = this->assembly_input();
        Triplets t;
        if (plastic()) {
          const auto tg = Kokkos::create_mirror_view_and_copy(HostSpace(), law_.tangent);
          in.point_material.assign(tg.data(), tg.data() + tg.size());
          t = assemble_stiffness(in);
        } else {
          t = this->assemble_elastic();
        }
        tangent_lu_.factor(t.n, t.rows, t.cols, t.values);
        if (!plastic()) elastic_lu_ = true;
      }
      detail::HostLUPreconditioner<T>{&tangent_lu_}.apply(r_, du_);
      res.linear_iterations += 1;
    } else {
      if (options_.solver == TangentSolver::two_level_pcg && !two_level_) {
        elastic_inv_diag_ = this->op_.inverse_diagonal();
        two_level_ = std::make_unique<TwoLevel<T, D, ElasticOperator<T, D>>>(
            &this->op_, elastic_inv_diag_, this->config_, this->disc_, this->constrained_, options_.two_level);
      } else if (options_.solver == TangentSolver::elastic_pcg && !elastic_lu_pcg_) {
        const Triplets t = this->assemble_elastic();
        elastic_lu_k_.factor(t.n, t.rows, t.cols, t.values);
        elastic_lu_pcg_ = true;
      }
      Kokkos::deep_copy(du_, T(0));
      solvers::SolverOptions so;
      so.tolerance = this->linear_tolerance();
      so.max_iterations = options_.linear_max_iterations;
      solvers::SolveResult s;
      const auto solve = [&](const auto& P) {
        if (plastic())
          return solvers::cg_preconditioned(
              detail::TangentOperator<T, D, PointStiffness<T>>{this->op_.el, law_.point_stiffness(), this->op_.constrained},
              P, r_, du_, so);
        return solvers::cg_preconditioned(this->op_, P, r_, du_, so);
      };
      if (options_.solver == TangentSolver::two_level_pcg)
        s = solve(*two_level_);
      else
        s = solve(detail::HostLUPreconditioner<T>{&elastic_lu_k_});
      res.linear_iterations += s.iterations;
      if (!s.converged() && !(s.true_relative_residual <= std::max(options_.linear_accept, this->linear_tolerance()))) {
        last_failure_ = std::string("the tangent CG did not converge: ") + s.reason;
        ok = false;
      }
    }
    return ok;
  }

  PlasticLaw<T> law_;
  double f_ext_free_norm_ = 0.0;
  std::array<double, 3> f_ext_sum_{0.0, 0.0, 0.0};
  solvers::HostSparseLU tangent_lu_, elastic_lu_k_;
  bool elastic_lu_ = false, elastic_lu_pcg_ = false;
  std::unique_ptr<TwoLevel<T, D, ElasticOperator<T, D>>> two_level_;  // points to this->op_: built at the first solve
  View1<T> elastic_inv_diag_;
};

}  // namespace polymech::solid
