// The quasi-static elasto-plastic solid model (issue 34): small strain, Hill (1948) plasticity with cubic
// symmetry and power-law hardening at every quadrature point (seed 002 paper 5 eqs. (1)-(4); J2 its isotropic
// case; kernels/materials/hill_plasticity.hpp), history stored per point (kernels/solid/plastic_law.hpp).
//
// Loading. A load factor lambda scales the external force (tractions, body forces) and the Dirichlet values:
// f(lambda) = lambda f_ext, u_c = lambda g. The caller gives a path of load-factor points (0 -> 1 -> 0 = load,
// then unload), each segment in a number of equal increments. A step whose Newton iteration fails (no
// convergence in max_iterations, a NaN, a failed local return mapping, a line search that finds no decrease,
// a linear solve that fails) is restarted from the last converged state with half the increment, up to
// max_cuts halvings in a row; then std::runtime_error names the load factor reached. After a cut step has
// converged the next step tries the remaining distance to the planned point again in one increment.
//
// Newton. Residual r(u) = f_int(u) - lambda f_ext on the free DoFs (zero on the constrained rows; u carries
// u_c = lambda g), f_int the sum-factorized element kernel with the plastic law (each point returns from a
// copy of its converged history). Every residual evaluation also stores the consistent tangent per point,
// so the Newton matrix is exact: K_t du = -r, du = 0 on the constrained DoFs; then u += alpha du.
// Convergence: |r| <= tolerance * F_ref, F_ref = max(|lambda f_ext|, |reactions|, 1e-2 * the largest F_ref
// of the analysis so far), the reactions being f_int on the constrained rows (under displacement control
// f_ext vanishes and the reactions are the force scale; the floor keeps a step that unloads to zero force
// from chasing round-off). A force criterion only: the displacement increment is not tested, because after
// a converged force residual du is of the order of the residual over the stiffness anyway.
//
// Line search (on the incremental potential, Matthies & Strang 1979): associative plasticity with the
// backward-Euler return mapping has an incremental potential Pi(u) whose gradient is r(u), so along the Newton
// direction g(alpha) = du . r(u + alpha du) is its slope, g(0) = -du . K_t du < 0. alpha = 1 is accepted when
// the evaluation is finite without local failures and g(1) <= 0.5 |g(0)| (still descending, or past the
// minimum by little); otherwise alpha moves to the root of the secant of g through 0 and alpha, safeguarded
// to [0.1, 0.9] alpha (a failed evaluation halves alpha), at most max_line_search times. The residual norm
// |r| is not the merit: Newton's first step of a plastic increment often raises |r| and still converges
// (measured: the large step of tests/solid/test_solid_plasticity.cpp). The last evaluation is the accepted
// one, so its trial history and tangent are what the next iteration uses.
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

#include "solid/plastic_law.hpp"
#include "solid/problem.hpp"
#include "solid/two_level.hpp"
#include "solvers/host_sparse_lu.hpp"
#include "solvers/krylov.hpp"

namespace polymech::solid {

enum class TangentSolver { direct, elastic_pcg, two_level_pcg };

struct NewtonOptions {
  double tolerance = 1e-8;   // |r| <= tolerance * F_ref
  int max_iterations = 25;   // per step
  bool line_search = true;
  int max_line_search = 10;  // backtracking steps per iteration
  double line_search_ratio = 0.5;  // accept alpha when du . r(u + alpha du) <= ratio |du . r(u)|
  int max_cuts = 10;         // successive halvings of a failing step
  TangentSolver solver = TangentSolver::elastic_pcg;
  double linear_tolerance = 1e-10;  // elastic_pcg: relative residual of CG
  double linear_accept = 1e-7;      // a CG stopped short (attainable accuracy) still serves if its true residual is below
  int linear_max_iterations = 1000;
  // > 0: inexact Newton (Eisenstat & Walker 1996): CG only to max(linear_tolerance, min(1e-2, forcing |r| / F_ref)),
  // loose while |r| is large, tight near convergence (superlinear; 0 keeps every solve at linear_tolerance and
  // Newton's quadratic rate, which tests/solid/test_solid_plasticity.cpp shows)
  double forcing = 0.0;
};

// Load-factor points (points[0] must be the model's current load factor) and increments per segment.
struct LoadPath {
  std::vector<double> points{0.0, 1.0};
  std::vector<int> increments{10};
};

// What each converged step reports.
struct Monitor {
  std::string reaction_boundary;  // reactions summed over the constrained DoFs of this side; empty: all of them
  std::function<double(const std::vector<double>& u)> displacement;  // of u on the host (D per node)
  std::int64_t dof = -1;  // or this DoF's displacement (used when `displacement` is empty)
};

struct StepResult {
  double load_factor = 0.0;
  std::array<double, 3> reaction{0.0, 0.0, 0.0};  // sum of f_int over the monitored constrained DoFs, per component
  std::array<double, 3> applied{0.0, 0.0, 0.0};   // lambda * sum of f_ext per component
  double displacement = 0.0;                      // the monitor's value
  int newton_iterations = 0;
  std::vector<double> residuals;     // |r| at the start and after each iteration (absolute)
  std::vector<double> step_lengths;  // line-search alpha per iteration
  double reference_force = 0.0;      // F_ref of the convergence test
  int linear_iterations = 0;         // CG iterations of the step (elastic_pcg), solves (direct)
  Index plastic_points = 0;
  int cuts = 0;  // halvings before this step converged
  double seconds = 0.0;
};

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

// z = K_e^-1 r with the host sparse LU of the constrained elastic stiffness.
template <class T>
struct HostLUPreconditioner {
  const solvers::HostSparseLU* lu = nullptr;
  void apply(const View1<T>& r, const View1<T>& z) const {
    // a separate host copy: on a host memory space create_mirror_view_and_copy would alias r
    Kokkos::View<T*, HostSpace> h("polymech::solid::lu_rhs", r.extent(0));
    Kokkos::deep_copy(h, r);
    std::vector<double> b(h.extent(0));
    for (std::size_t i = 0; i < b.size(); ++i) b[i] = static_cast<double>(h(i));
    lu->solve(b.data());
    for (std::size_t i = 0; i < b.size(); ++i) h(i) = static_cast<T>(b[i]);
    Kokkos::deep_copy(z, h);
  }
};

}  // namespace detail

template <class T, int D = 3>
class ElastoPlastic : public SolidProblem<T, D> {
  using Base = SolidProblem<T, D>;

 public:
  explicit ElastoPlastic(const Config<D>& c, const NewtonOptions& o = {}) : Base(c), options_(o) {
    const Index n = Base::dof_count();
    u_ = View1<T>("polymech::solid::displacement", n);
    trial_u_ = View1<T>("polymech::solid::trial_displacement", n);
    du_ = View1<T>("polymech::solid::newton_increment", n);
    r_ = View1<T>("polymech::solid::residual", n);
    f_int_ = View1<T>("polymech::solid::internal_force", n);
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
    f_ext_free_norm_ = free_norm(this->f_ext_);
  }

  NewtonOptions& options() { return options_; }
  const NewtonOptions& options() const { return options_; }
  bool plastic() const { return law_.allocated(); }
  const PlasticLaw<T>& law() const { return law_; }  // empty Views when elastic
  double load_factor() const { return lambda_; }
  const View1<T>& displacement() const { return u_; }
  std::vector<double> displacement_host() const { return models::to_host(u_); }
  int points_per_element() const { return power<D>(this->config_.order + 1); }

  // r = f_int(u) - lambda f_ext off the constrained rows (zero on them), the plastic law returning from the
  // converged history (and storing trial history and tangent); returns |r|. u must carry its Dirichlet values.
  double residual(const View1<T>& u, double lambda, const View1<T>& r) {
    Kokkos::deep_copy(f_int_, T(0));
    if (plastic())
      add_internal_force<false>("polymech::solid::plastic_internal_force", this->op_.el, law_, u, f_int_);
    else
      add_internal_force<false>("polymech::solid::internal_force", this->op_.el, ElementStiffness<T>{this->op_.el.material},
                                u, f_int_);
    const auto fi = f_int_, fe = this->f_ext_;
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

  // Follow the load path from the current state; one StepResult per converged step (history committed).
  std::vector<StepResult> run(const LoadPath& path, const Monitor& monitor = {}) {
    if (path.points.size() < 2 || path.increments.size() + 1 != path.points.size())
      throw std::invalid_argument("solid::ElastoPlastic: a load path needs n >= 2 points and n - 1 increment counts");
    if (std::fabs(path.points[0] - lambda_) > 1e-14 * std::max(1.0, std::fabs(lambda_)))
      throw std::invalid_argument("solid::ElastoPlastic: the load path starts at " + models::format_g(path.points[0]) +
                                  ", the model is at load factor " + models::format_g(lambda_));
    set_monitor(monitor);
    std::vector<StepResult> out;
    for (std::size_t s = 0; s + 1 < path.points.size(); ++s) {
      const int n = std::max(path.increments[s], 1);
      const double a = path.points[s], b = path.points[s + 1];
      for (int k = 1; k <= n; ++k) {
        const double target = k == n ? b : a + (b - a) * k / n;
        int cuts = 0;
        while (lambda_ != target) {
          double next = target;
          for (int c = 0; c < cuts; ++c) next = 0.5 * (lambda_ + next);
          StepResult r;
          if (step(next, r)) {
            r.cuts = cuts;
            out.push_back(std::move(r));
            cuts = 0;  // the rest of the planned increment in one step again
          } else if (++cuts > options_.max_cuts) {
            throw std::runtime_error("solid::ElastoPlastic: the load step to load factor " + models::format_g(next) +
                                     " failed after " + std::to_string(options_.max_cuts) +
                                     " halvings; load factor reached " + models::format_g(lambda_) + " (last failure: " +
                                     last_failure_ + ")");
          }
        }
      }
    }
    return out;
  }

  // The reason of the last failed Newton attempt (empty if none).
  const std::string& last_failure() const { return last_failure_; }

  // (Public only because nvcc's extended lambdas may not live in private member functions.)
  double dot(const View1<T>& a, const View1<T>& b) const {
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::newton_dot", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i, double& acc) { acc += static_cast<double>(a(i)) * static_cast<double>(b(i)); }, s);
    return s;
  }

  // |f_int| on the constrained rows (the reactions) after a residual evaluation.
  double reaction_norm() const {
    const auto fi = f_int_;
    const auto list = this->op_.constrained;
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::reaction_norm", Kokkos::RangePolicy<ExecSpace>(0, static_cast<Index>(list.extent(0))),
        KOKKOS_LAMBDA(const Index k, double& acc) {
          const double v = static_cast<double>(fi(list(k)));
          acc += v * v;
        },
        s);
    return std::sqrt(s);
  }

  // trial_u = u + alpha du, its residual into r_; returns |r| (NaN on a local failure).
  double try_point(const View1<T>& u, double alpha, double lambda) {
    const auto d = du_, x = u, t = trial_u_;
    const T a = static_cast<T>(alpha);
    Kokkos::parallel_for(
        "polymech::solid::newton_update", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { t(i) = x(i) + a * d(i); });
    const double rn = residual(trial_u_, lambda, r_);
    if (plastic() && law_.counts().failed > 0) return std::numeric_limits<double>::quiet_NaN();
    return rn;
  }

 private:
  double free_norm(const View1<T>& v) const {
    View1<T> w("polymech::solid::free_copy", Base::dof_count());
    Kokkos::deep_copy(w, v);
    fem::fill_constrained(this->op_.constrained, T(0), w);
    return std::sqrt(solvers::norm2("polymech::solid::free_norm", Base::dof_count(), w));
  }

  void set_monitor(const Monitor& m) {
    monitor_ = m;
    reaction_dofs_.clear();
    const auto& mask = this->constrained_;
    if (m.reaction_boundary.empty()) {
      for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) reaction_dofs_.push_back(static_cast<std::int64_t>(i));
    } else {
      for (const std::int64_t v : side_nodes(this->disc_, m.reaction_boundary))
        for (int c = 0; c < D; ++c)
          if (mask[static_cast<std::size_t>(D * v + c)]) reaction_dofs_.push_back(D * v + c);
    }
    f_ext_sum_ = {0.0, 0.0, 0.0};
    const std::vector<double> fe = models::to_host(this->f_ext_);
    for (std::size_t i = 0; i < fe.size(); ++i) f_ext_sum_[i % D] += fe[i];
  }

  // Solve K_t du = -r (du = 0 on the constrained DoFs); returns false with last_failure_ set on failure.
  bool solve_tangent(StepResult& res) {
    solvers::scale(Base::dof_count(), T(-1), r_, r_);
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
            &this->op_, elastic_inv_diag_, this->config_, this->disc_, this->constrained_);
      } else if (options_.solver == TangentSolver::elastic_pcg && !elastic_lu_pcg_) {
        const Triplets t = this->assemble_elastic();
        elastic_lu_k_.factor(t.n, t.rows, t.cols, t.values);
        elastic_lu_pcg_ = true;
      }
      Kokkos::deep_copy(du_, T(0));
      solvers::SolverOptions so;
      so.tolerance = linear_tolerance_;
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
      if (!s.converged() && !(s.true_relative_residual <= std::max(options_.linear_accept, linear_tolerance_))) {
        last_failure_ = std::string("the tangent CG did not converge: ") + s.reason;
        ok = false;
      }
    }
    fem::fill_constrained(this->op_.constrained, T(0), du_);
    return ok;
  }

  // One load step from the converged state (u_, history, lambda_) to load factor `lambda`; on success commits.
  bool step(double lambda, StepResult& res) {
    const auto t0 = std::chrono::steady_clock::now();
    res = StepResult{};
    res.load_factor = lambda;
    View1<T> u("polymech::solid::newton_iterate", Base::dof_count());
    Kokkos::deep_copy(u, u_);
    {  // u_c = lambda g
      View1<T> g("polymech::solid::scaled_dirichlet", this->g_.extent(0));
      solvers::scale(static_cast<Index>(g.extent(0)), static_cast<T>(lambda), this->g_, g);
      fem::set_constrained_values(this->op_.constrained, g, u);
    }
    Kokkos::deep_copy(du_, T(0));
    double rn = try_point(u, 0.0, lambda);
    auto reference = [&] {
      const double f = std::max({std::fabs(lambda) * f_ext_free_norm_, reaction_norm(), 1e-2 * f_ref_max_});
      return f > 0.0 ? f : 1.0;
    };
    res.residuals.push_back(rn);
    for (int it = 0;; ++it) {
      if (!std::isfinite(rn)) {
        last_failure_ = "a non-finite residual or a failed local return mapping at iteration " + std::to_string(it);
        return false;
      }
      Kokkos::deep_copy(u, trial_u_);
      const double ref = reference();
      res.reference_force = ref;
      if (rn <= options_.tolerance * ref) break;
      if (it == options_.max_iterations) {
        last_failure_ = "no convergence in " + std::to_string(options_.max_iterations) + " iterations (|r|/F_ref = " +
                        models::format_g(rn / ref) + ")";
        return false;
      }
      linear_tolerance_ = options_.forcing > 0.0
                              ? std::max(options_.linear_tolerance, std::min(1e-2, options_.forcing * rn / ref))
                              : options_.linear_tolerance;
      if (!solve_tangent(res)) return false;
      const double g0 = -dot(du_, r_);  // r_ holds -r after the solve: g0 = du . r(u) = -du . K_t du < 0
      double alpha = 1.0, r_try = try_point(u, alpha, lambda);
      if (options_.line_search && g0 < 0.0) {
        for (int ls = 0;; ++ls) {
          const bool finite = std::isfinite(r_try);
          const double g = finite ? dot(du_, r_) : 0.0;  // the potential's slope at alpha
          if (finite && (g <= 0.0 || g <= options_.line_search_ratio * -g0)) break;
          if (ls == options_.max_line_search) {
            last_failure_ = "the line search found no acceptable step at iteration " + std::to_string(it + 1);
            return false;
          }
          // overshoot past the minimum of the potential along du: the root of the slope's secant through
          // (0, g0) and (alpha, g), safeguarded to [0.1, 0.9] alpha; a failed evaluation halves alpha
          const double next = finite ? alpha * -g0 / (g - g0) : 0.5 * alpha;
          alpha = std::min(0.9 * alpha, std::max(0.1 * alpha, next));
          r_try = try_point(u, alpha, lambda);
        }
      }
      res.step_lengths.push_back(alpha);
      rn = r_try;
      res.residuals.push_back(rn);
      res.newton_iterations = it + 1;
    }
    // converged: commit
    Kokkos::deep_copy(u_, u);
    lambda_ = lambda;
    f_ref_max_ = std::max(f_ref_max_, res.reference_force);
    if (plastic()) {
      law_.commit();
      res.plastic_points = law_.counts().plastic;
    }
    const std::vector<double> fi = models::to_host(f_int_);
    for (const std::int64_t i : reaction_dofs_) res.reaction[static_cast<std::size_t>(i % D)] += fi[static_cast<std::size_t>(i)];
    for (int c = 0; c < 3; ++c) res.applied[c] = lambda * f_ext_sum_[c];
    if (monitor_.displacement)
      res.displacement = monitor_.displacement(displacement_host());
    else if (monitor_.dof >= 0) {
      auto sub = Kokkos::subview(u_, std::make_pair(static_cast<Index>(monitor_.dof), static_cast<Index>(monitor_.dof + 1)));
      auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), sub);
      res.displacement = static_cast<double>(h(0));
    }
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    last_failure_.clear();
    return true;
  }

  NewtonOptions options_;
  PlasticLaw<T> law_;
  View1<T> u_, trial_u_, du_, r_, f_int_;
  double lambda_ = 0.0, f_ext_free_norm_ = 0.0, f_ref_max_ = 0.0;
  solvers::HostSparseLU tangent_lu_, elastic_lu_k_;
  bool elastic_lu_ = false, elastic_lu_pcg_ = false;
  std::unique_ptr<TwoLevel<T, D, ElasticOperator<T, D>>> two_level_;  // points to this->op_: built at the first solve
  View1<T> elastic_inv_diag_;
  double linear_tolerance_ = 1e-10;  // of the current tangent solve (NewtonOptions::forcing)
  Monitor monitor_;
  std::vector<std::int64_t> reaction_dofs_;
  std::array<double, 3> f_ext_sum_{0.0, 0.0, 0.0};
  std::string last_failure_;
};

}  // namespace polymech::solid
