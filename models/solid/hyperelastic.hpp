// The quasi-static finite-strain (total-Lagrangian) hyperelastic solid (issue 34: "St. Venant-Kirchhoff,
// neo-Hookean and Mooney-Rivlin for finite strain", "surface tractions (also follower pressure)").
//
// Laws (HyperelasticLaw): materials::StVenantKirchhoff (S = lambda tr(E) I + 2 mu E), materials::NeoHookean
// (W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2), materials::MooneyRivlin (decoupled:
// W = C10 (I1b - 3) + C01 (I2b - 3) + kappa/2 (J - 1)^2); kernels/materials/hyperelastic.hpp. 3D, and 2D plane
// strain (F_33 = 1); plane stress is refused (it would need the out-of-plane stretch as a local unknown).
//
// Loads, scaled by the load factor lambda: the dead loads of the Config (tractions per reference area and body
// forces per reference volume: the SolidProblem's f_ext), the Dirichlet values (u_c = lambda g) and follower
// pressures on named sides (FollowerPressure; kernels/solid/finite_strain.hpp: p times the current normal
// area). Residual r(u) = f_int(u) - lambda (f_ext + f_p(u)) on the free DoFs, zero on the constrained rows.
//
// Newton (the structure of models/solid/elastoplastic.hpp; its NewtonOptions, LoadPath, Monitor and StepResult
// are reused): the exact tangent K = dr/du = K_int(u) (material + geometric, from A = dP/dF) + lambda K_p(u)
// (the follower load stiffness, not symmetric) is assembled on the host from the element and face matrices
// the Kokkos kernels compute, and factorized by the host sparse LU every iteration (TangentSolver::direct;
// the only solver here). Line search on the potential as elastoplastic.hpp does: along du the slope of the
// potential Pi(u + alpha du) is g(alpha) = du . r(u + alpha du) (exact for dead loads and pressure on a closed
// or edge-fixed surface, where Pi = sum W - lambda f_ext . u - lambda p V; otherwise the same test on the
// Galerkin projection of r); alpha = 1 is taken when g(1) <= ratio |g(0)|, else the secant root of g,
// safeguarded to [0.1, 0.9] alpha. A failed evaluation (J <= 0 or a non-finite W or P at any point) halves
// alpha in the line search, and ends the iteration when it occurs at the start of a step. Convergence:
// |r| <= tolerance F_ref, F_ref = max(|lambda (f_ext + f_p)| on the free DoFs, |reactions|, 1e-2 the largest
// F_ref so far). Predictor: a step starts from the secant extrapolation of the last two converged states
// (u_n + (lambda - lambda_n)/(lambda_n - lambda_n-1) (u_n - u_n-1)), or from u_n when that state fails to
// evaluate or there is no previous step (set_extrapolation(false) turns it off; measured on the elastica of
// tests/solid/test_solid_finite_strain.cpp: 113 -> 57 Newton iterations over 8 steps). A failed step (no convergence, a failed evaluation, a singular tangent, no acceptable
// line-search step) is restarted from the last converged state with half the increment, up to max_cuts
// halvings, then std::runtime_error names the load factor reached and the reason.
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "materials/hyperelastic.hpp"
#include "solid/elastoplastic.hpp"
#include "solid/finite_strain.hpp"
#include "solid/problem.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::solid {

using HyperelasticLaw =
    std::variant<materials::StVenantKirchhoff<double>, materials::NeoHookean<double>, materials::MooneyRivlin<double>>;

// A follower pressure p (force per current area; positive pushes against the surface) on a side, times the
// load factor.
struct FollowerPressure {
  std::string boundary;
  double p = 0.0;
};

namespace detail {
template <class T>
materials::StVenantKirchhoff<T> cast_hyperelastic(const materials::StVenantKirchhoff<double>& l) {
  materials::StVenantKirchhoff<T> r;
  r.elastic.lambda = static_cast<T>(l.elastic.lambda);
  r.elastic.mu = static_cast<T>(l.elastic.mu);
  return r;
}
template <class T>
materials::NeoHookean<T> cast_hyperelastic(const materials::NeoHookean<double>& l) {
  materials::NeoHookean<T> r;
  r.elastic.lambda = static_cast<T>(l.elastic.lambda);
  r.elastic.mu = static_cast<T>(l.elastic.mu);
  return r;
}
template <class T>
materials::MooneyRivlin<T> cast_hyperelastic(const materials::MooneyRivlin<double>& l) {
  materials::MooneyRivlin<T> r;
  r.C10 = static_cast<T>(l.C10);
  r.C01 = static_cast<T>(l.C01);
  r.kappa = static_cast<T>(l.kappa);
  return r;
}
}  // namespace detail

// NewtonOptions with the direct solver (the one this model has).
inline NewtonOptions finite_strain_newton_options() {
  NewtonOptions o;
  o.solver = TangentSolver::direct;
  return o;
}

template <class T, int D = 3>
class Hyperelastic : public SolidProblem<T, D> {
  using Base = SolidProblem<T, D>;

 public:
  Hyperelastic(const Config<D>& c, const HyperelasticLaw& law, const std::vector<FollowerPressure>& pressures = {},
               const NewtonOptions& o = finite_strain_newton_options())
      : Base(c), law_(law), options_(o) {
    if (c.plasticity) throw std::invalid_argument("solid::Hyperelastic: the configuration carries a plastic law");
    if (D == 2 && c.plane == Plane::stress)
      throw std::invalid_argument("solid::Hyperelastic: plane stress is not supported at finite strain (plane strain and 3D are)");
    if (o.solver != TangentSolver::direct)
      throw std::invalid_argument("solid::Hyperelastic: only TangentSolver::direct (the assembled tangent and the host "
                                  "sparse LU) is implemented");
    const Index n = Base::dof_count();
    u_ = View1<T>("polymech::solid::fs_displacement", n);
    u_previous_ = View1<T>("polymech::solid::fs_previous_displacement", n);
    trial_u_ = View1<T>("polymech::solid::fs_trial_displacement", n);
    du_ = View1<T>("polymech::solid::fs_newton_increment", n);
    r_ = View1<T>("polymech::solid::fs_residual", n);
    f_int_ = View1<T>("polymech::solid::fs_internal_force", n);
    f_load_ = View1<T>("polymech::solid::fs_load", n);
    set_up_pressure(pressures);
  }

  NewtonOptions& options() { return options_; }
  // The secant predictor (on by default): a step starts from the linear extrapolation of the last two
  // converged states (falling back to the last one when the extrapolated state fails to evaluate).
  void set_extrapolation(bool on) { extrapolate_ = on; }
  double load_factor() const { return lambda_; }
  const View1<T>& displacement() const { return u_; }
  std::vector<double> displacement_host() const { return models::to_host(u_); }
  const std::string& last_failure() const { return last_failure_; }
  const PressureFaces<D>& pressure_faces() const { return pressure_; }
  // Strain energy of the last evaluation.
  double strain_energy() const { return energy_; }
  // f_int of the last evaluation (every DoF: on the constrained rows the reactions).
  const View1<T>& internal_force() const { return f_int_; }

  // r = f_int(u) - lambda (f_ext + f_p(u)) off the constrained rows (zero on them); returns |r|, or NaN when
  // the evaluation failed (J <= 0 or a non-finite value at a point). With tangent, also the element and face
  // matrices for assemble_tangent(). u must carry its Dirichlet values.
  double residual(const View1<T>& u, double lambda, const View1<T>& r, bool tangent = false) {
    Kokkos::deep_copy(f_int_, T(0));
    FiniteStrainEvaluation ev;
    std::visit(
        [&](const auto& l) {
          const auto lt = detail::cast_hyperelastic<T>(l);
          ev = tangent ? finite_strain_internal_force<true>(this->op_.el, lt, u, f_int_, elements_)
                       : finite_strain_internal_force<false>(this->op_.el, lt, u, f_int_, elements_);
        },
        law_);
    energy_ = ev.energy;
    Kokkos::deep_copy(f_load_, this->f_ext_);
    solvers::scale(Base::dof_count(), static_cast<T>(lambda), f_load_, f_load_);
    if (pressure_.faces() > 0) {
      if (tangent)
        follower_pressure<true>(pressure_, this->x_, u, lambda, face_force_, face_stiffness_);
      else
        follower_pressure<false>(pressure_, this->x_, u, lambda, face_force_, face_stiffness_);
      scatter_pressure(pressure_, face_force_, f_load_);
    }
    const auto fi = f_int_, fl = f_load_;
    Kokkos::parallel_for(
        "polymech::solid::fs_residual", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { r(i) = fi(i) - fl(i); });
    fem::fill_constrained(this->op_.constrained, T(0), r);
    if (ev.failed_elements > 0) return std::numeric_limits<double>::quiet_NaN();
    return std::sqrt(solvers::norm2("polymech::solid::fs_residual_norm", Base::dof_count(), r));
  }

  // The tangent dr/du of the last residual(..., tangent = true) evaluation, assembled (identity on the
  // constrained rows and columns).
  Triplets assemble_tangent() const {
    Triplets t;
    t.n = Base::dof_count();
    const int ND = this->disc_.nodes_per_element();
    const auto& en = this->disc_.element_nodes;
    append_matrices<D>(elements_.matrices, ND,
                       [&](std::size_t e, int a) { return en[e * static_cast<std::size_t>(ND) + static_cast<std::size_t>(a)]; },
                       this->constrained_, t);
    if (pressure_.faces() > 0) {
      const auto nh = Kokkos::create_mirror_view_and_copy(HostSpace(), pressure_.nodes);
      append_matrices<D>(face_stiffness_, static_cast<int>(nh.extent(1)),
                         [&](std::size_t f, int a) { return static_cast<std::int64_t>(nh(f, a)); }, this->constrained_, t);
    }
    for (std::int64_t i = 0; i < t.n; ++i)
      if (this->constrained_[static_cast<std::size_t>(i)]) {
        t.rows.push_back(i);
        t.cols.push_back(i);
        t.values.push_back(1.0);
      }
    return t;
  }

  // Follow the load path from the current state (the loop and step cutting of ElastoPlastic::run).
  std::vector<StepResult> run(const LoadPath& path, const Monitor& monitor = {}) {
    if (path.points.size() < 2 || path.increments.size() + 1 != path.points.size())
      throw std::invalid_argument("solid::Hyperelastic: a load path needs n >= 2 points and n - 1 increment counts");
    if (std::fabs(path.points[0] - lambda_) > 1e-14 * std::max(1.0, std::fabs(lambda_)))
      throw std::invalid_argument("solid::Hyperelastic: the load path starts at " + models::format_g(path.points[0]) +
                                  ", the model is at load factor " + models::format_g(lambda_));
    monitor_ = monitor;
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
            cuts = 0;
          } else if (++cuts > options_.max_cuts) {
            throw std::runtime_error("solid::Hyperelastic: the load step to load factor " + models::format_g(next) +
                                     " failed after " + std::to_string(options_.max_cuts) +
                                     " halvings; load factor reached " + models::format_g(lambda_) +
                                     " (last failure: " + last_failure_ + ")");
          }
        }
      }
    }
    return out;
  }

  // (Public only because nvcc's extended lambdas may not live in private member functions.)
  double dot(const View1<T>& a, const View1<T>& b) const {
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::fs_dot", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i, double& acc) { acc += static_cast<double>(a(i)) * static_cast<double>(b(i)); }, s);
    return s;
  }
  double free_load_norm() const {
    const auto fl = f_load_;
    View1<T> w("polymech::solid::fs_free_load", Base::dof_count());
    Kokkos::deep_copy(w, fl);
    fem::fill_constrained(this->op_.constrained, T(0), w);
    return std::sqrt(solvers::norm2("polymech::solid::fs_free_norm", Base::dof_count(), w));
  }
  double reaction_norm() const {
    const auto fi = f_int_;
    const auto list = this->op_.constrained;
    double s = 0.0;
    Kokkos::parallel_reduce(
        "polymech::solid::fs_reaction_norm", Kokkos::RangePolicy<ExecSpace>(0, static_cast<Index>(list.extent(0))),
        KOKKOS_LAMBDA(const Index k, double& acc) {
          const double v = static_cast<double>(fi(list(k)));
          acc += v * v;
        },
        s);
    return std::sqrt(s);
  }
  // du = u_n - u_n-1 on the free DoFs (the secant predictor's direction).
  void secant_direction() {
    const auto d = du_, a = u_, b = u_previous_;
    Kokkos::parallel_for(
        "polymech::solid::fs_secant", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { d(i) = a(i) - b(i); });
    fem::fill_constrained(this->op_.constrained, T(0), du_);
  }
  // trial_u = u + alpha du and its residual (and tangent) into r_.
  double try_point(const View1<T>& u, double alpha, double lambda, bool tangent) {
    const auto d = du_, x = u, t = trial_u_;
    const T a = static_cast<T>(alpha);
    Kokkos::parallel_for(
        "polymech::solid::fs_update", Kokkos::RangePolicy<ExecSpace>(0, Base::dof_count()),
        KOKKOS_LAMBDA(const Index i) { t(i) = x(i) + a * d(i); });
    return residual(trial_u_, lambda, r_, tangent);
  }

 private:
  void set_up_pressure(const std::vector<FollowerPressure>& pressures) {
    pressure_.order = this->config_.order;
    const int NF = D == 3 ? this->disc_.n1d * this->disc_.n1d : this->disc_.n1d;
    std::vector<std::int64_t> nodes;
    std::vector<double> sign, p;
    for (const auto& fp : pressures) {
      const auto ds = side_of<D>(fp.boundary);
      if (ds[0] < 0) throw std::invalid_argument("solid::Hyperelastic: unknown boundary '" + fp.boundary + "'");
      const auto f = side_faces(this->disc_, fp.boundary);
      nodes.insert(nodes.end(), f.begin(), f.end());
      for (std::size_t k = 0; k < f.size() / static_cast<std::size_t>(NF); ++k) {
        sign.push_back(outward_sign(ds[0], ds[1] != 0));
        p.push_back(fp.p);
      }
    }
    const std::size_t nf = sign.size();
    pressure_.nodes = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::solid::pressure_nodes", nf, NF);
    auto nh = Kokkos::create_mirror_view(pressure_.nodes);
    for (std::size_t f = 0; f < nf; ++f)
      for (int a = 0; a < NF; ++a) nh(f, a) = static_cast<Index>(nodes[f * NF + a]);
    Kokkos::deep_copy(pressure_.nodes, nh);
    pressure_.sign = models::to_device<double>("polymech::solid::pressure_sign", sign);
    pressure_.pressure = models::to_device<double>("polymech::solid::pressure_values", p);
  }

  bool solve_tangent(StepResult& res) {
    solvers::scale(Base::dof_count(), T(-1), r_, r_);
    try {
      const Triplets t = assemble_tangent();
      lu_.factor(t.n, t.rows, t.cols, t.values);
    } catch (const std::runtime_error& e) {
      last_failure_ = std::string("the tangent factorization failed: ") + e.what();
      return false;
    }
    detail::HostLUPreconditioner<T>{&lu_}.apply(r_, du_);
    res.linear_iterations += 1;
    fem::fill_constrained(this->op_.constrained, T(0), du_);
    return true;
  }

  bool step(double lambda, StepResult& res) {
    const auto t0 = std::chrono::steady_clock::now();
    res = StepResult{};
    res.load_factor = lambda;
    View1<T> u("polymech::solid::fs_newton_iterate", Base::dof_count());
    View1<T> g_lambda("polymech::solid::fs_scaled_dirichlet", this->g_.extent(0));
    solvers::scale(static_cast<Index>(g_lambda.extent(0)), static_cast<T>(lambda), this->g_, g_lambda);
    Kokkos::deep_copy(u, u_);
    fem::set_constrained_values(this->op_.constrained, g_lambda, u);
    double rn = std::numeric_limits<double>::quiet_NaN();
    if (extrapolate_ && have_previous_ && lambda_ != lambda_previous_) {
      // secant predictor: u_n + (lambda - lambda_n) / (lambda_n - lambda_n-1) (u_n - u_n-1) (free DoFs)
      secant_direction();
      rn = try_point(u, (lambda - lambda_) / (lambda_ - lambda_previous_), lambda, true);
    }
    if (!std::isfinite(rn)) {  // no predictor, or it inverted an element: start from the converged state
      Kokkos::deep_copy(du_, T(0));
      rn = try_point(u, 0.0, lambda, true);
    }
    res.residuals.push_back(rn);
    for (int it = 0;; ++it) {
      if (!std::isfinite(rn)) {
        last_failure_ = "a failed evaluation (J <= 0 or a non-finite stress) at iteration " + std::to_string(it);
        return false;
      }
      Kokkos::deep_copy(u, trial_u_);
      double ref = std::max({free_load_norm(), reaction_norm(), 1e-2 * f_ref_max_});
      if (!(ref > 0.0)) ref = 1.0;
      res.reference_force = ref;
      if (rn <= options_.tolerance * ref) break;
      if (it == options_.max_iterations) {
        last_failure_ = "no convergence in " + std::to_string(options_.max_iterations) + " iterations (|r|/F_ref = " +
                        models::format_g(rn / ref) + ")";
        return false;
      }
      if (!solve_tangent(res)) return false;
      const double g0 = -dot(du_, r_);  // r_ holds -r after the solve
      double alpha = 1.0, r_try = try_point(u, alpha, lambda, true);
      if (options_.line_search && g0 < 0.0) {
        for (int ls = 0;; ++ls) {
          const bool finite = std::isfinite(r_try);
          const double g = finite ? dot(du_, r_) : 0.0;
          if (finite && (g <= 0.0 || g <= options_.line_search_ratio * -g0)) break;
          if (ls == options_.max_line_search) {
            last_failure_ = "the line search found no acceptable step at iteration " + std::to_string(it + 1);
            return false;
          }
          const double next = finite ? alpha * -g0 / (g - g0) : 0.5 * alpha;
          alpha = std::min(0.9 * alpha, std::max(0.1 * alpha, next));
          r_try = try_point(u, alpha, lambda, true);
        }
      } else if (!std::isfinite(r_try)) {  // no line search: halve on failed evaluations only
        for (int ls = 0; ls < options_.max_line_search && !std::isfinite(r_try); ++ls) {
          alpha *= 0.5;
          r_try = try_point(u, alpha, lambda, true);
        }
      }
      res.step_lengths.push_back(alpha);
      rn = r_try;
      res.residuals.push_back(rn);
      res.newton_iterations = it + 1;
    }
    Kokkos::deep_copy(u_previous_, u_);
    lambda_previous_ = lambda_;
    have_previous_ = true;
    Kokkos::deep_copy(u_, u);
    lambda_ = lambda;
    f_ref_max_ = std::max(f_ref_max_, res.reference_force);
    finish_step(res);
    res.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    last_failure_.clear();
    return true;
  }

  // Reactions (f_int summed over the monitored constrained DoFs), applied load and the monitored displacement.
  void finish_step(StepResult& res) const {
    const std::vector<double> fi = models::to_host(f_int_), fl = models::to_host(f_load_);
    std::vector<std::int64_t> dofs;
    const auto& mask = this->constrained_;
    if (monitor_.reaction_boundary.empty()) {
      for (std::size_t i = 0; i < mask.size(); ++i)
        if (mask[i]) dofs.push_back(static_cast<std::int64_t>(i));
    } else {
      for (const std::int64_t v : side_nodes(this->disc_, monitor_.reaction_boundary))
        for (int c = 0; c < D; ++c)
          if (mask[static_cast<std::size_t>(D * v + c)]) dofs.push_back(D * v + c);
    }
    for (const std::int64_t i : dofs) res.reaction[static_cast<std::size_t>(i % D)] += fi[static_cast<std::size_t>(i)];
    for (std::size_t i = 0; i < fl.size(); ++i) res.applied[i % D] += fl[i];
    if (monitor_.displacement)
      res.displacement = monitor_.displacement(displacement_host());
    else if (monitor_.dof >= 0)
      res.displacement = displacement_host()[static_cast<std::size_t>(monitor_.dof)];
  }

  HyperelasticLaw law_;
  NewtonOptions options_;
  PressureFaces<D> pressure_;
  FiniteStrainElementData<T> elements_;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> face_force_, face_stiffness_;
  View1<T> u_, u_previous_, trial_u_, du_, r_, f_int_, f_load_;
  bool extrapolate_ = true, have_previous_ = false;
  double lambda_previous_ = 0.0;
  double lambda_ = 0.0, f_ref_max_ = 0.0, energy_ = 0.0;
  solvers::HostSparseLU lu_;
  Monitor monitor_;
  std::string last_failure_;
};

}  // namespace polymech::solid
