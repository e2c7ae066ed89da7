// The least-squares estimator's solver (issue 34; seed 002 paper 5 section 5): residuals, finite-difference
// sensitivities and the projected Levenberg-Marquardt iteration with its stopping tests. The covariance and
// identifiability analysis at the estimate (Estimator::analyse, Estimator::svd_analysis) is defined in
// identifiability.hpp; include least_squares.hpp, which holds both and the entry point fit().
//
// Sensitivities. Forward differences (u + h e_j; u - h e_j where the bound leaves no room or the model
// fails there) or central ones, with h = sqrt(acc) or acc^(1/3) in u, acc the forward model's relative
// accuracy (Options::model_accuracy; machine epsilon for a closed form, the solver tolerance for a
// finite-element model). Every forward run is counted; the callback is called serially.
//
// Levenberg-Marquardt. At each iterate the thin SVD J_f = U Sigma V^T of the free columns (parameters
// not held at a bound) gives the damped step for every damping lambda without a new factorisation,
//   delta = - sum_k sigma_k / (sigma_k^2 + lambda) (u_k . r) v_k,
// truncated to the singular values above sigma_max / max_condition: along a combination the data do not
// determine the estimator does not move, so it keeps the start's value there (the minimum-change
// solution) instead of wandering along a flat valley. The trial point is projected onto the box; a step
// is accepted when the cost falls, with Nielsen's damping update from the ratio of the actual to the
// predicted reduction (the prediction from the projected step). A parameter at a bound whose gradient
// pushes outward is held there for the iteration (active set).
//
// Stopping: gradient small (max_j |J_j . r| / (|J_j| |r|) <= gtol over the free columns: the cosine of the
// residual with each sensitivity), step small (|delta|_inf <= xtol in u), cost reduction small (actual
// and predicted relative reduction <= ftol), max iterations, or forward-model failure: a trial point
// where the model throws or returns a non-finite value is rejected and the damping raised; after
// max_failures consecutive failures, or a failure at the start or in both finite-difference directions,
// the fit stops naming the point and the model's message.
//
// The ill-conditioned stop. A problem whose Jacobian at the estimate (or, with
// Unidentifiable::Stop, at any iterate) has a singular value below the cutoff ends with
// StopReason::NotIdentifiable and a message naming the combination (e.g. "+0.707 log(a) -0.707 log(b)").
// With Unidentifiable::FitDetermined (default) the fit first converges in the determined subspace, so
// the determined combinations (here a*b) and the parameters outside the null space are estimated, with
// intervals, while the undetermined ones keep their start value and are flagged; with Stop it ends at
// the first iterate where the rank drops, saving forward runs. Either way no interval is given to an
// undetermined parameter.
//
// Host-only, double, Eigen.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "inverse/format.hpp"
#include "inverse/problem.hpp"

namespace polymech::estimation {

namespace detail {

class Estimator {
 public:
  Estimator(const Problem& pr, const Options& o) : pr_(pr), o_(o) {
    const auto np = pr_.parameters.size();
    if (np == 0) throw std::invalid_argument("least_squares: no parameters");
    if (pr_.datasets.empty()) throw std::invalid_argument("least_squares: no datasets");
    for (std::size_t i = 0; i < np; ++i) {
      const Parameter& q = pr_.parameters[i];
      if (!(q.lower <= q.initial && q.initial <= q.upper))
        throw std::invalid_argument("least_squares: the start of " + q.name + " lies outside its bounds");
      if (q.transform == Transform::Log && !(q.initial > 0.0 && q.lower >= 0.0))
        throw std::invalid_argument("least_squares: log parameter " + q.name + " must be positive");
      if (q.transform == Transform::Linear && !(q.scale > 0.0))
        throw std::invalid_argument("least_squares: the scale of " + q.name + " must be positive");
      if (!q.fixed) free_.push_back(i);
    }
    if (free_.empty()) throw std::invalid_argument("least_squares: every parameter is fixed");
    for (const Dataset& d : pr_.datasets) {
      if (!d.model) throw std::invalid_argument("least_squares: dataset " + d.name + " has no model");
      if (!d.sigma.empty() && d.sigma.size() != d.data.size())
        throw std::invalid_argument("least_squares: dataset " + d.name + ": sigma and data differ in length");
      for (double s : d.sigma)
        if (!(s > 0.0)) throw std::invalid_argument("least_squares: dataset " + d.name + ": sigma must be positive");
      if (!(d.weight > 0.0)) throw std::invalid_argument("least_squares: dataset " + d.name + ": weight must be positive");
      offsets_.push_back(m_);
      m_ += static_cast<int>(d.data.size());
    }
    offsets_.push_back(m_);
    n_ = static_cast<int>(free_.size());
    const double acc = o_.model_accuracy;
    const bool central = o_.differences == Differences::Central;
    h_ = o_.fd_step > 0.0 ? o_.fd_step : (central ? std::cbrt(acc) : std::sqrt(acc));
    const double jac_acc = central ? std::pow(acc, 2.0 / 3.0) : std::sqrt(acc);
    max_cond_ = o_.max_condition > 0.0 ? o_.max_condition : std::min(1e8, 0.01 / jac_acc);
    lo_.resize(n_);
    hi_.resize(n_);
    for (int j = 0; j < n_; ++j) {
      const Parameter& q = par(j);
      lo_(j) = to_u(q, q.lower);
      hi_(j) = to_u(q, q.upper);
      names_.push_back(q.transform == Transform::Log ? "log(" + q.name + ")" : q.name + "/" + fmt(q.scale, "%g"));
    }
  }

  Result run() {
    const auto t0 = std::chrono::steady_clock::now();
    Result res;
    res.points = m_;
    res.max_condition = max_cond_;
    Eigen::VectorXd u(n_);
    for (int j = 0; j < n_; ++j) u(j) = to_u(par(j), par(j).initial);
    Eigen::VectorXd r;
    std::string err;
    bool done = false;
    if (!residual(u, r, err)) {
      finish_fail(res, "the forward model failed at the start point " + point_text(u) + ": " + err);
      done = true;
    }
    Eigen::MatrixXd J;
    bool jac_current = false;
    double lambda = -1.0, nu = 2.0;
    int failures = 0;
    StopReason reason = StopReason::MaxIterations;
    std::string why;
    while (!done) {
      if (!jacobian(u, r, J, err)) {
        finish_fail(res, err);
        done = true;
        break;
      }
      jac_current = true;
      const double rn = r.norm();
      const Eigen::VectorXd g = J.transpose() * r;
      // active set: at a bound with the descent direction -g pointing out
      std::vector<int> act;
      double gcos = 0.0;
      for (int j = 0; j < n_; ++j) {
        const bool held = (u(j) <= lo_(j) && g(j) > 0.0) || (u(j) >= hi_(j) && g(j) < 0.0);
        if (held) continue;
        act.push_back(j);
        const double cn = J.col(j).norm();
        if (cn > 0.0 && rn > 0.0) gcos = std::max(gcos, std::fabs(g(j)) / (cn * rn));
      }
      if (rn == 0.0 || gcos <= o_.gtol) {
        reason = StopReason::GradientSmall;
        why = "gradient small: max cosine(residual, sensitivity) = " + fmt(gcos) + " <= gtol " + fmt(o_.gtol);
        break;
      }
      Eigen::MatrixXd Jf(m_, static_cast<Eigen::Index>(act.size()));
      for (std::size_t k = 0; k < act.size(); ++k) Jf.col(static_cast<Eigen::Index>(k)) = J.col(act[k]);
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jf, Eigen::ComputeThinU | Eigen::ComputeThinV);
      const Eigen::VectorXd& sv = svd.singularValues();
      const double smax = sv.size() ? sv(0) : 0.0;
      int rank = 0;
      for (Eigen::Index k = 0; k < sv.size(); ++k)
        if (sv(k) > smax / max_cond_) ++rank;
      if (rank < static_cast<int>(act.size()) && o_.unidentifiable == Unidentifiable::Stop) {
        reason = StopReason::NotIdentifiable;
        why = "stopped at iteration " + std::to_string(res.iterations) + ": the Jacobian lost rank";
        break;
      }
      if (rank == 0) {
        reason = StopReason::GradientSmall;
        why = "no parameter has a resolvable sensitivity";
        break;
      }
      const Eigen::VectorXd c = svd.matrixU().leftCols(rank).transpose() * r;
      if (lambda < 0.0) lambda = o_.initial_damping * smax * smax;
      const double F = 0.5 * r.squaredNorm();
      bool accepted = false;
      while (!accepted) {
        Eigen::VectorXd coef(rank);
        for (int k = 0; k < rank; ++k) coef(k) = -sv(k) / (sv(k) * sv(k) + lambda) * c(k);
        const Eigen::VectorXd df = svd.matrixV().leftCols(rank) * coef;
        Eigen::VectorXd ut = u;
        for (std::size_t k = 0; k < act.size(); ++k) {
          const int j = act[k];
          ut(j) = std::clamp(u(j) + df(static_cast<Eigen::Index>(k)), lo_(j), hi_(j));
        }
        const Eigen::VectorXd step = ut - u;
        const double snorm = step.cwiseAbs().maxCoeff();
        if (snorm <= o_.xtol && failures > 0) {
          // the damping was raised by failures, not by a lack of decrease: no convergence
          finish_fail(res, "the forward model failed at every trial step from " + point_text(u) + " down to |du|_inf = " +
                               fmt(snorm) + " (" + std::to_string(failures) + " consecutive failures; last: " + err + ")");
          done = true;
          break;
        }
        if (snorm <= o_.xtol) {
          reason = StopReason::StepSmall;
          why = "step small: |du|_inf = " + fmt(snorm) + " <= xtol " + fmt(o_.xtol);
          done = true;
          break;
        }
        const double pred = 0.5 * (r.squaredNorm() - (r + J * step).squaredNorm());
        Eigen::VectorXd rt;
        if (!residual(ut, rt, err)) {
          ++res.forward_failures;
          if (++failures >= o_.max_failures) {
            finish_fail(res, "the forward model failed at " + std::to_string(failures) +
                                 " consecutive trial points (last " + point_text(ut) + ": " + err + ")");
            done = true;
            break;
          }
          lambda *= nu;
          nu *= 2.0;
          continue;
        }
        failures = 0;
        const double Ft = 0.5 * rt.squaredNorm();
        const double rho = pred > 0.0 ? (F - Ft) / pred : -1.0;
        if (Ft < F && rho > 0.0) {
          accepted = true;
          lambda *= std::max(1.0 / 3.0, 1.0 - std::pow(2.0 * rho - 1.0, 3));
          nu = 2.0;
          u = ut;
          r = rt;
          jac_current = false;
          ++res.iterations;
          if ((F - Ft) <= o_.ftol * F && pred <= o_.ftol * F) {
            reason = StopReason::CostReductionSmall;
            why = "cost reduction small: " + fmt((F - Ft) / F) + " <= ftol " + fmt(o_.ftol);
            done = true;
          }
        } else {
          lambda *= nu;
          nu *= 2.0;
          if (!std::isfinite(lambda) || lambda > 1e32 * smax * smax) {
            reason = StopReason::StepSmall;
            why = "no reduction of the cost along the damped steps (damping " + fmt(lambda) + ")";
            done = true;
            break;
          }
        }
      }
      if (failed_) break;
      if (!done && res.iterations >= o_.max_iterations) {
        reason = StopReason::MaxIterations;
        why = "max iterations " + std::to_string(o_.max_iterations) + " reached";
        break;
      }
      if (done) break;
    }
    if (!failed_) {
      res.reason = reason;
      res.converged = reason == StopReason::GradientSmall || reason == StopReason::StepSmall ||
                      reason == StopReason::CostReductionSmall;
      if (!jac_current && !jacobian(u, r, J, err)) {
        finish_fail(res, "at the estimate: " + err);
        res.converged = false;
      } else {
        analyse(res, u, r, J);
        if (!res.identifiable) {
          std::string undet;
          for (const Direction& d : res.combined.directions)
            if (!d.determined) undet += (undet.empty() ? "" : "; ") + d.text + " (relative singular value " + fmt(d.relative, "%.2g") + ")";
          const std::string conv = reason == StopReason::NotIdentifiable ? why
                                   : std::string("the fit ") + (res.converged ? "converged" : "stopped") +
                                         " in the determined directions (" + why + ")";
          res.reason = StopReason::NotIdentifiable;
          res.message = "not identifiable: the data cannot determine " + undet + " (condition number " +
                        fmt(res.combined.condition, "%.3g") + " > " + fmt(max_cond_, "%.3g") +
                        "); undetermined directions keep their start value; " + conv;
        } else {
          res.message = why;
        }
      }
    } else {
      fill_estimate(res, u);
    }
    res.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return res;
  }

 private:
  const Parameter& par(int j) const { return pr_.parameters[free_[static_cast<std::size_t>(j)]]; }
  static double to_u(const Parameter& q, double p) { return q.transform == Transform::Log ? std::log(p) : p / q.scale; }
  static double to_p(const Parameter& q, double u) { return q.transform == Transform::Log ? std::exp(u) : u * q.scale; }

  std::vector<double> physical(const Eigen::VectorXd& u) const {
    std::vector<double> p(pr_.parameters.size());
    for (std::size_t i = 0; i < p.size(); ++i) p[i] = pr_.parameters[i].initial;
    for (int j = 0; j < n_; ++j) {
      const Parameter& q = par(j);
      p[free_[static_cast<std::size_t>(j)]] = std::clamp(to_p(q, u(j)), q.lower, q.upper);
    }
    return p;
  }

  std::string point_text(const Eigen::VectorXd& u) const {
    const auto p = physical(u);
    std::string s = "(";
    for (std::size_t i = 0; i < p.size(); ++i) s += (i ? ", " : "") + pr_.parameters[i].name + " = " + fmt(p[i]);
    return s + ")";
  }

  // r = sqrt(w_k) (m_k(p) - y) / sigma; false (with the reason) where the model throws or is not finite.
  bool residual(const Eigen::VectorXd& u, Eigen::VectorXd& r, std::string& err) {
    const auto p = physical(u);
    r.resize(m_);
    ++res_evals_;
    for (std::size_t k = 0; k < pr_.datasets.size(); ++k) {
      const Dataset& d = pr_.datasets[k];
      std::vector<double> y;
      ++runs_;
      try {
        y = d.model(p);
      } catch (const std::exception& e) {
        err = "dataset " + d.name + ": " + e.what();
        return false;
      } catch (...) {
        err = "dataset " + d.name + ": unknown exception";
        return false;
      }
      if (y.size() != d.data.size())
        throw std::invalid_argument("least_squares: the model of dataset " + d.name + " returned " +
                                    std::to_string(y.size()) + " values for " + std::to_string(d.data.size()) + " data");
      const double sw = std::sqrt(d.weight);
      for (std::size_t i = 0; i < y.size(); ++i) {
        const double s = d.sigma.empty() ? 1.0 : d.sigma[i];
        const double v = sw * (y[i] - d.data[i]) / s;
        if (!std::isfinite(v)) {
          err = "dataset " + d.name + ": non-finite prediction at point " + std::to_string(i);
          return false;
        }
        r(offsets_[k] + static_cast<int>(i)) = v;
      }
    }
    return true;
  }

  bool jacobian(const Eigen::VectorXd& u, const Eigen::VectorXd& r, Eigen::MatrixXd& J, std::string& err) {
    J.resize(m_, n_);
    const bool central = o_.differences == Differences::Central;
    for (int j = 0; j < n_; ++j) {
      Eigen::VectorXd rp, rm;
      Eigen::VectorXd up = u, um = u;
      up(j) += h_;
      um(j) -= h_;
      const bool room_p = up(j) <= hi_(j), room_m = um(j) >= lo_(j);
      std::string e1, e2;
      const bool okp = room_p && residual(up, rp, e1);
      if (!okp && room_p) ++fd_failures_;
      const bool okm = (central || !okp) && room_m && residual(um, rm, e2);
      if (!okm && room_m && (central || !okp)) ++fd_failures_;
      if (okp && okm) J.col(j) = (rp - rm) / (2.0 * h_);
      else if (okp) J.col(j) = (rp - r) / h_;
      else if (okm) J.col(j) = (r - rm) / h_;
      else {
        err = "the sensitivity to " + par(j).name + " could not be evaluated at " + point_text(u) +
              (e1.empty() && e2.empty() ? ": no room inside the bounds for the step" : ": " + (e1.empty() ? e2 : e1));
        return false;
      }
    }
    return true;
  }

  void finish_fail(Result& res, const std::string& msg) {
    failed_ = true;
    res.reason = StopReason::ModelFailure;
    res.message = msg;
    res.converged = false;
    res.identifiable = false;
  }

  void fill_counters(Result& res) const {
    res.residual_evaluations = res_evals_;
    res.forward_runs = runs_;
    res.forward_failures += fd_failures_;
  }

  void fill_estimate(Result& res, const Eigen::VectorXd& u) {
    res.estimate = physical(u);
    res.parameters.clear();
    for (std::size_t i = 0; i < pr_.parameters.size(); ++i) {
      const Parameter& q = pr_.parameters[i];
      ParameterEstimate e;
      e.name = q.name;
      e.variable = q.transform == Transform::Log ? "log(" + q.name + ")" : q.name + "/" + fmt(q.scale, "%g");
      e.value = res.estimate[i];
      e.status = q.fixed ? ParameterStatus::Fixed : ParameterStatus::Determined;
      res.parameters.push_back(e);
    }
    fill_counters(res);
  }

  // At the estimate: the SVD of a Jacobian's rows, and the covariance, intervals and identifiability of the
  // result (identifiability.hpp).
  Identifiability svd_analysis(const std::string& name, const Eigen::MatrixXd& J, double s) const;
  void analyse(Result& res, const Eigen::VectorXd& u, const Eigen::VectorXd& r, const Eigen::MatrixXd& J);

  const Problem& pr_;
  Options o_;
  std::vector<std::size_t> free_;
  std::vector<int> offsets_;
  std::vector<std::string> names_;
  int m_ = 0, n_ = 0;
  double h_ = 0.0, max_cond_ = 0.0;
  Eigen::VectorXd lo_, hi_;
  int res_evals_ = 0, runs_ = 0, fd_failures_ = 0;
  bool failed_ = false;
};

}  // namespace detail

}  // namespace polymech::estimation
