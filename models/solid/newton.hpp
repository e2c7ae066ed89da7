// The quasi-static Newton driver every nonlinear static solid model shares (issue 34): load paths with step
// cutting, Newton with a line search on the incremental potential, the force-based convergence test, reactions
// and the monitored displacement. solid::ElastoPlastic (elastoplastic.hpp: small strain, Hill plasticity) and
// solid::Hyperelastic (hyperelastic.hpp: finite strain, follower pressure) derive from it and supply what
// differs: how the residual is evaluated, how the tangent system is solved, what a converged step commits.
//
// Loading. A load factor lambda scales the external force and the Dirichlet values: f(lambda) = lambda f_ext,
// u_c = lambda g. The caller gives a path of load-factor points (0 -> 1 -> 0 = load, then unload), each segment
// in a number of equal increments. A step whose Newton iteration fails (no convergence in max_iterations, a
// failed evaluation, a line search that finds no decrease, a linear solve that fails) is restarted from the last
// converged state with half the increment, up to max_cuts halvings in a row; then std::runtime_error names the
// load factor reached. After a cut step has converged the next step tries the remaining distance to the planned
// point again in one increment.
//
// Newton. Residual r(u) = f_int(u) - f_load(u, lambda) on the free DoFs (zero on the constrained rows; u carries
// u_c = lambda g); K du = -r, du = 0 on the constrained DoFs; u += alpha du. Convergence: |r| <= tolerance F_ref,
// F_ref = max(|f_load| on the free DoFs, |reactions|, 1e-2 the largest F_ref of the analysis so far), the
// reactions being f_int on the constrained rows (under displacement control the load vanishes and the reactions
// are the force scale; the floor keeps a step that unloads to zero force from chasing round-off). A force
// criterion only: after a converged force residual du is of the order of the residual over the stiffness anyway.
//
// Line search (on the incremental potential, Matthies & Strang 1979): associative plasticity with the
// backward-Euler return mapping, and hyperelasticity under dead loads (or pressure on a closed or edge-fixed
// surface), have a potential Pi(u) whose gradient is r(u), so along the Newton direction g(alpha) = du . r(u +
// alpha du) is its slope, g(0) = -du . K du < 0. alpha = 1 is accepted when the evaluation succeeds and g(1) <=
// line_search_ratio |g(0)| (still descending, or past the minimum by little); otherwise alpha moves to the root
// of the secant of g through 0 and alpha, safeguarded to [0.1, 0.9] alpha (a failed evaluation halves alpha), at
// most max_line_search times. The residual norm |r| is not the merit: Newton's first step of a plastic increment
// often raises |r| and still converges. The last evaluation is the accepted one, so its trial state and tangent
// are what the next iteration uses. A step starts from the last converged state, or from the secant predictor
// (NewtonOptions::secant_predictor). Without the line search a failed evaluation still halves alpha.
//
// What a model supplies (CRTP: class M : public NewtonSolid<T, D, M>; the hooks public or the base a friend):
//   double evaluate(const View1<T>& u, double lambda, const View1<T>& r)
//       r = f_int(u) - f_load off the constrained rows, zero on them, f_int into this->f_int_ (every DoF: the
//       reactions on the constrained rows), the tangent for the next solve stored; returns |r|, or NaN when the
//       evaluation failed (a failed local return mapping, J <= 0);
//   double load_norm(double lambda) const     |f_load| on the free DoFs of the last evaluation;
//   double load_sum(int c, double lambda) const  the sum of f_load's component c (StepResult::applied);
//   bool solve_tangent(StepResult& res)       du_ = K^-1 r_ (r_ already negated; du_ on the constrained DoFs is
//                                             zeroed afterwards); false with last_failure_ set on failure;
//   void commit(StepResult& res)              a converged step: history committed, counts reported;
//   const char* failed_evaluation() const     what a failed evaluation means, for the failure message.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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
  double linear_tolerance = 1e-10;  // CG solvers: relative residual of CG
  double linear_accept = 1e-7;      // a CG stopped short (attainable accuracy) still serves if its true residual is below
  int linear_max_iterations = 1000;
  TwoLevelOptions two_level;        // two_level_pcg: the cycle's smoothing and coarse solver
  // > 0: inexact Newton (Eisenstat & Walker 1996): CG only to max(linear_tolerance, min(1e-2, forcing |r| / F_ref)),
  // loose while |r| is large, tight near convergence (superlinear; 0 keeps every solve at linear_tolerance and
  // Newton's quadratic rate, which tests/solid/test_solid_plasticity.cpp shows)
  double forcing = 0.0;
  // A step starts from the secant extrapolation of the last two converged states, u_n + (lambda - lambda_n) /
  // (lambda_n - lambda_n-1) (u_n - u_n-1) on the free DoFs, or from u_n when that fails to evaluate (an inverted
  // element). Measured on the finite-strain model: the elastica 113 -> 57 Newton iterations; off by default for
  // the elasto-plastic model (its curves are documented without it).
  bool secant_predictor = false;
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
  std::array<double, 3> applied{0.0, 0.0, 0.0};   // sum of the load vector per component
  double displacement = 0.0;                      // the monitor's value
  int newton_iterations = 0;
  std::vector<double> residuals;     // |r| at the start and after each iteration (absolute)
  std::vector<double> step_lengths;  // line-search alpha per iteration
  double reference_force = 0.0;      // F_ref of the convergence test
  int linear_iterations = 0;         // CG iterations of the step (CG solvers), solves (direct)
  Index plastic_points = 0;
  int cuts = 0;  // halvings before this step converged
  double seconds = 0.0;
};

namespace detail {

// z = A^-1 r with a host sparse LU (of the tangent, or of the elastic stiffness as a preconditioner).
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

template <class T, int D, class Model>
class NewtonSolid : public SolidProblem<T, D> {
  using Base = SolidProblem<T, D>;

 public:
  NewtonSolid(const Config<D>& c, const NewtonOptions& o, std::string name) : Base(c), options_(o), name_(std::move(name)) {
    const Index n = Base::dof_count();
    u_ = View1<T>("polymech::solid::displacement", n);
    trial_u_ = View1<T>("polymech::solid::trial_displacement", n);
    du_ = View1<T>("polymech::solid::newton_increment", n);
    r_ = View1<T>("polymech::solid::residual", n);
    f_int_ = View1<T>("polymech::solid::internal_force", n);
  }

  NewtonOptions& options() { return options_; }
  const NewtonOptions& options() const { return options_; }
  double load_factor() const { return lambda_; }
  // The largest reference force of the converged steps so far (the convergence test's floor is 1e-2 of it):
  // part of the driver's state a checkpoint keeps (models/fsi/turek_hron_fsi_transient.hpp).
  double reference_force_max() const { return f_ref_max_; }
  void set_reference_force_max(double f) { f_ref_max_ = f; }
  const View1<T>& displacement() const { return u_; }
  std::vector<double> displacement_host() const { return models::to_host(u_); }
  // f_int of the last evaluation (every DoF: on the constrained rows the reactions).
  const View1<T>& internal_force() const { return f_int_; }
  // The reason of the last failed Newton attempt (empty if none).
  const std::string& last_failure() const { return last_failure_; }

  // Follow the load path from the current state; one StepResult per converged step (history committed).
  std::vector<StepResult> run(const LoadPath& path, const Monitor& monitor = {}) {
    if (path.points.size() < 2 || path.increments.size() + 1 != path.points.size())
      throw std::invalid_argument(name_ + ": a load path needs n >= 2 points and n - 1 increment counts");
    if (std::fabs(path.points[0] - lambda_) > 1e-14 * std::max(1.0, std::fabs(lambda_)))
      throw std::invalid_argument(name_ + ": the load path starts at " + models::format_g(path.points[0]) +
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
            throw std::runtime_error(name_ + ": the load step to load factor " + models::format_g(next) + " failed after " +
                                     std::to_string(options_.max_cuts) + " halvings; load factor reached " +
                                     models::format_g(lambda_) + " (last failure: " + last_failure_ + ")");
          }
        }
      }
    }
    return out;
  }

  // One Newton solve from the converged state to load factor lambda, which may equal the current one (a time
  // step of the implicit dynamics, models/solid/finite_strain_dynamics.hpp, which sets the inertia first). On
  // success the state is committed; false: nothing changed, the reason in last_failure().
  bool solve_step(double lambda, StepResult& result) { return step(lambda, result); }

  // (Public only because nvcc's extended lambdas may not live in private member functions.)
  double dot(const View1<T>& a, const View1<T>& b) const {
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::newton_dot", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i, double& acc) { acc += static_cast<double>(a(i)) * static_cast<double>(b(i)); }, s);
    return s;
  }

  // |f_int| on the constrained rows (the reactions) after an evaluation.
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

  // trial_u = u + alpha du, its residual into r_; returns |r| (NaN on a failed evaluation).
  double try_point(const View1<T>& u, double alpha, double lambda) {
    const auto d = du_, x = u, t = trial_u_;
    const T a = static_cast<T>(alpha);
    Kokkos::parallel_for(
        "polymech::solid::newton_update", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { t(i) = x(i) + a * d(i); });
    return model().evaluate(trial_u_, lambda, r_);
  }

  // du = u_n - u_n-1 on the free DoFs (the secant predictor's direction).
  void secant_direction() {
    const auto d = du_, a = u_, b = u_previous_;
    Kokkos::parallel_for(
        "polymech::solid::secant_direction", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { d(i) = a(i) - b(i); });
    fem::fill_constrained(this->op_.constrained, T(0), du_);
  }

  // |v| over the free DoFs.
  double free_norm(const View1<T>& v) const {
    View1<T> w("polymech::solid::free_copy", Base::dof_count());
    Kokkos::deep_copy(w, v);
    fem::fill_constrained(this->op_.constrained, T(0), w);
    return std::sqrt(solvers::norm2("polymech::solid::free_norm", Base::dof_count(), w));
  }

 protected:
  Model& model() { return static_cast<Model&>(*this); }
  const Model& model() const { return static_cast<const Model&>(*this); }

  // The tolerance of the current tangent solve (NewtonOptions::forcing), for CG solvers.
  double linear_tolerance() const { return linear_tolerance_; }

  View1<T> u_, trial_u_, du_, r_, f_int_;
  NewtonOptions options_;
  std::string last_failure_;

 private:
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
    double rn = std::numeric_limits<double>::quiet_NaN();
    if (options_.secant_predictor && have_previous_ && lambda_ != lambda_previous_) {
      secant_direction();
      rn = try_point(u, (lambda - lambda_) / (lambda_ - lambda_previous_), lambda);
    }
    if (!std::isfinite(rn)) {  // no predictor, or it failed to evaluate: start from the converged state
      Kokkos::deep_copy(du_, T(0));
      rn = try_point(u, 0.0, lambda);
    }
    auto reference = [&] {
      const double f = std::max({model().load_norm(lambda), reaction_norm(), 1e-2 * f_ref_max_});
      return f > 0.0 ? f : 1.0;
    };
    res.residuals.push_back(rn);
    for (int it = 0;; ++it) {
      if (!std::isfinite(rn)) {
        last_failure_ = std::string(model().failed_evaluation()) + " at iteration " + std::to_string(it);
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
      solvers::scale(Base::dof_count(), T(-1), r_, r_);
      const bool solved = model().solve_tangent(res);
      fem::fill_constrained(this->op_.constrained, T(0), du_);
      if (!solved) return false;
      const double g0 = -dot(du_, r_);  // r_ holds -r: g0 = du . r(u) = -du . K du < 0
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
      } else if (!std::isfinite(r_try)) {  // no line search: halve on failed evaluations only
        for (int ls = 0; ls < options_.max_line_search && !std::isfinite(r_try); ++ls) {
          alpha *= 0.5;
          r_try = try_point(u, alpha, lambda);
        }
      }
      res.step_lengths.push_back(alpha);
      rn = r_try;
      res.residuals.push_back(rn);
      res.newton_iterations = it + 1;
    }
    // converged: commit
    if (options_.secant_predictor) {
      if (u_previous_.extent(0) != u_.extent(0)) u_previous_ = View1<T>("polymech::solid::previous_displacement", u_.extent(0));
      Kokkos::deep_copy(u_previous_, u_);
      lambda_previous_ = lambda_;
      have_previous_ = true;
    }
    Kokkos::deep_copy(u_, u);
    lambda_ = lambda;
    f_ref_max_ = std::max(f_ref_max_, res.reference_force);
    model().commit(res);
    const std::vector<double> fi = models::to_host(f_int_);
    for (const std::int64_t i : reaction_dofs_) res.reaction[static_cast<std::size_t>(i % D)] += fi[static_cast<std::size_t>(i)];
    for (int c = 0; c < D; ++c) res.applied[c] = model().load_sum(c, lambda);
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

  std::string name_;
  double lambda_ = 0.0, f_ref_max_ = 0.0;
  View1<T> u_previous_;  // the converged state before the last one (secant_predictor only)
  double lambda_previous_ = 0.0;
  bool have_previous_ = false;
  double linear_tolerance_ = 1e-10;
  Monitor monitor_;
  std::vector<std::int64_t> reaction_dofs_;
};

}  // namespace polymech::solid
