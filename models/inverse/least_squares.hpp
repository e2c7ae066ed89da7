// Gradient-based least-squares parameter estimation with an identifiability analysis (issue 34; seed 002
// paper 5 section 5). Paper 5 estimates six elasto-plastic constants of a cubic crystal (C11, C12, C44,
// sigma0, n, R12 of its eqs. (2)-(4)) from micro-cantilever load-displacement curves at six orientations,
// through a response surface of 30 forward runs and a genetic algorithm, and finds (its Fig. 4) that how
// reliably each constant is determined depends on the orientation. This estimator fits the forward model
// itself and says which parameters, or combinations of them, the data determine:
//
//   minimise  F(p) = 1/2 sum_k w_k sum_i ((m_k(p)_i - y_ki) / sigma_ki)^2     over lo <= p <= hi,
//
// over datasets k (e.g. one per orientation), each a forward-model callback m_k(p) -> predictions.
//
// Variables. Each parameter is estimated in an internal variable u: u = log p (Transform::Log, for
// positive parameters: moduli, yield stress) or u = p / scale (Transform::Linear). A unit step in u is
// then a relative change (log) or one typical magnitude (linear), so the Jacobian J = dr/du is the
// "scaled" Jacobian J S of relative sensitivities, the finite-difference step, the damping, the stopping
// tolerances and the condition number are all in these units, and confidence intervals of log
// parameters are asymmetric in p (and never cross zero).
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
// Identifiability, at the estimate (the Jacobian re-evaluated there). The SVD of J (all non-fixed
// parameters): singular values, the condition number sigma_max / sigma_min, and each right singular
// vector as a combination of the internal variables with its standard error s / sigma_k. A singular
// value below sigma_max / max_condition is a combination the data cannot determine. The default
// max_condition is min(1e8, 0.01 / e_J), e_J the finite-difference Jacobian's relative accuracy
// (sqrt(acc) forward, acc^(2/3) central): a smaller singular value cannot be told from the
// differencing error (forward differences with acc = eps: 6.7e5; central: 1e8). The same analysis is
// given per dataset (e.g. per orientation) from its rows of J, and for all datasets together.
//
// Covariance. cov(u) = s^2 V_r Sigma_r^-2 V_r^T over the determined directions (the pseudo-inverse of
// J^T J with the relative cutoff 1/max_condition), over the parameters not held at a bound; s^2 = 1 when
// the sigmas are the data's standard deviations (Noise::Known), s^2 = 2 F / (m - rank) otherwise
// (Noise::Estimated). A parameter with a coefficient above null_coefficient_tol in an undetermined
// direction is reported Undetermined: no standard error, no interval (a pseudo-inverse would give it a
// finite, meaningless one). Standard errors in p by the delta method (p se_u for log, scale se_u for
// linear). 95 % intervals u +- q se_u mapped to p: q the normal quantile 1.95996 when the noise is known,
// Student's t with m - rank degrees of freedom when it is estimated. These are linearised (asymptotic)
// intervals; weights w_k != 1 make them those of the weighted problem (exact only if the weights are the
// inverse variance factors).
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
// Host-only, double, Eigen; no I/O: to_json and describe return strings.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// (Namespace `estimation`, not `inverse`: polymech::inverse is the small-matrix inverse of kernels/core/small_math.hpp.)
namespace polymech::estimation {

enum class Transform { Linear, Log };

struct Parameter {
  std::string name;
  double initial = 0.0;
  double lower = -std::numeric_limits<double>::infinity();
  double upper = std::numeric_limits<double>::infinity();
  double scale = 1.0;  // Transform::Linear: typical magnitude (u = p / scale); unused for Log
  Transform transform = Transform::Linear;
  bool fixed = false;  // held at `initial`, not estimated
};

// One set of observations and the forward model that predicts them (e.g. one orientation's curve).
struct Dataset {
  std::string name;
  std::vector<double> data;   // observations y_i
  std::vector<double> sigma;  // standard deviation of each y_i; empty: 1 for all
  double weight = 1.0;        // w_k, multiplies the squared residuals
  // Predictions at the data points for the parameters p (all of them, in declaration order). May throw
  // or return non-finite values where the model fails; a wrong length is a programming error.
  std::function<std::vector<double>(const std::vector<double>& p)> model;
};

struct Problem {
  std::vector<Parameter> parameters;
  std::vector<Dataset> datasets;
};

enum class Differences { Forward, Central };
enum class Noise { Known, Estimated };
enum class Unidentifiable { FitDetermined, Stop };

struct Options {
  int max_iterations = 100;
  double gtol = 1e-8;  // gradient cosine
  double xtol = 1e-9;  // step, internal units
  double ftol = 1e-12; // relative cost reduction (actual and predicted)
  int max_failures = 8;  // consecutive forward-model failures before giving up
  Differences differences = Differences::Forward;
  double model_accuracy = std::numeric_limits<double>::epsilon();  // relative accuracy of the model
  double fd_step = 0.0;        // 0: sqrt(acc) forward, acc^(1/3) central (internal units)
  double max_condition = 0.0;  // 0: min(1e8, 0.01 / Jacobian accuracy)
  double null_coefficient_tol = 1e-2;
  double initial_damping = 1e-3;  // lambda_0 = this * sigma_max^2
  Noise noise = Noise::Known;
  Unidentifiable unidentifiable = Unidentifiable::FitDetermined;
  double confidence = 0.95;
};

enum class StopReason { GradientSmall, StepSmall, CostReductionSmall, MaxIterations, ModelFailure, NotIdentifiable };

inline const char* to_string(StopReason r) {
  switch (r) {
    case StopReason::GradientSmall: return "gradient_small";
    case StopReason::StepSmall: return "step_small";
    case StopReason::CostReductionSmall: return "cost_reduction_small";
    case StopReason::MaxIterations: return "max_iterations";
    case StopReason::ModelFailure: return "model_failure";
    case StopReason::NotIdentifiable: return "not_identifiable";
  }
  return "?";
}

enum class ParameterStatus { Determined, Undetermined, AtBound, Fixed };

inline const char* to_string(ParameterStatus s) {
  switch (s) {
    case ParameterStatus::Determined: return "determined";
    case ParameterStatus::Undetermined: return "undetermined";
    case ParameterStatus::AtBound: return "at_bound";
    case ParameterStatus::Fixed: return "fixed";
  }
  return "?";
}

struct ParameterEstimate {
  std::string name;
  std::string variable;  // "log(name)" or "name/scale"
  double value = 0.0;
  ParameterStatus status = ParameterStatus::Determined;
  double se = std::numeric_limits<double>::quiet_NaN();           // in p (delta method)
  double se_internal = std::numeric_limits<double>::quiet_NaN();  // in u
  double lower = std::numeric_limits<double>::quiet_NaN();        // confidence interval in p
  double upper = std::numeric_limits<double>::quiet_NaN();
};

// A right singular vector: a combination of the internal variables (sum_j coefficients[j] u_j).
struct Direction {
  double singular_value = 0.0;
  double relative = 0.0;  // singular_value / largest
  double se = std::numeric_limits<double>::quiet_NaN();  // s / singular_value (internal units)
  bool determined = true;
  std::vector<double> coefficients;  // one per estimated parameter (Identifiability::names)
  std::string text;                  // "+0.707 log(a) -0.707 log(b)"
};

struct Identifiability {
  std::string dataset;  // "all" for the stacked problem
  std::vector<std::string> names;  // internal variables, one per estimated parameter
  std::vector<Direction> directions;  // largest singular value first
  double condition = 0.0;             // sigma_max / sigma_min (inf when sigma_min = 0)
  int rank = 0;                       // singular values above the cutoff
};

struct Result {
  StopReason reason = StopReason::MaxIterations;
  std::string message;
  bool converged = false;     // a convergence test was met (in the determined subspace if not identifiable)
  bool identifiable = false;  // every estimated direction determined at the estimate
  bool ok() const { return converged && identifiable; }

  std::vector<double> estimate;  // all parameters, declaration order
  std::vector<ParameterEstimate> parameters;
  double cost = 0.0;  // F = 1/2 sum r^2
  int points = 0;     // m
  int dof = 0;        // m - rank
  double noise_scale = 1.0;  // s
  double reduced_chi2 = std::numeric_limits<double>::quiet_NaN();  // 2F / (m - rank)
  std::string interval_kind;  // "normal" or "student-t(dof)"
  double quantile = 0.0;
  std::vector<std::vector<double>> correlation;  // all parameters; NaN where undefined
  Identifiability combined;
  std::vector<Identifiability> per_dataset;

  int iterations = 0;
  int residual_evaluations = 0;  // evaluations of the whole residual (all datasets)
  int forward_runs = 0;          // calls of the dataset models
  int forward_failures = 0;
  double wall_seconds = 0.0;
  double max_condition = 0.0;  // the cutoff used
};

namespace detail {

// Regularised incomplete beta I_x(a, b) by its continued fraction (modified Lentz).
inline double incomplete_beta(double a, double b, double x) {
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  const double ln_front = std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b) + a * std::log(x) + b * std::log1p(-x);
  if (x > (a + 1.0) / (a + b + 2.0)) return 1.0 - incomplete_beta(b, a, 1.0 - x);
  const double tiny = 1e-300;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::fabs(d) < tiny) d = tiny;
  d = 1.0 / d;
  double f = d;
  for (int k = 1; k < 500; ++k) {
    for (int parity = 0; parity < 2; ++parity) {
      const double num = parity == 0 ? k * (b - k) * x / ((a + 2 * k - 1) * (a + 2 * k))
                                     : -(a + k) * (a + b + k) * x / ((a + 2 * k) * (a + 2 * k + 1));
      d = 1.0 + num * d;
      if (std::fabs(d) < tiny) d = tiny;
      c = 1.0 + num / c;
      if (std::fabs(c) < tiny) c = tiny;
      d = 1.0 / d;
      f *= c * d;
      if (parity == 1 && std::fabs(c * d - 1.0) < 1e-15) return std::exp(ln_front) * f / a;
    }
  }
  return std::exp(ln_front) * f / a;
}

}  // namespace detail

// Two-sided quantile: P(|T| <= q) = level, T standard normal (dof <= 0) or Student's t with dof degrees of
// freedom; by bisection on the t distribution function (I_{dof/(dof+q^2)}(dof/2, 1/2) = 1 - level).
inline double two_sided_quantile(double level, int dof) {
  const double tail = 1.0 - level;
  auto tail_of = [&](double q) {
    if (dof <= 0) return std::erfc(q / std::sqrt(2.0));
    return detail::incomplete_beta(0.5 * dof, 0.5, dof / (dof + q * q));
  };
  double lo = 0.0, hi = 1.0;
  while (tail_of(hi) > tail) hi *= 2.0;
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (tail_of(mid) > tail ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

namespace detail {

inline std::string fmt(double v, const char* f = "%.6g") {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

inline std::string combination_text(const std::vector<std::string>& names, const Eigen::VectorXd& v, double tol) {
  // sign convention: the first coefficient within 10 % of the largest magnitude is positive (stable where
  // two are equal in size, as +-1/sqrt(2))
  const double vmax = v.cwiseAbs().maxCoeff();
  Eigen::Index lead = 0;
  while (lead + 1 < v.size() && std::fabs(v(lead)) < 0.9 * vmax) ++lead;
  const double sgn = v(lead) < 0 ? -1.0 : 1.0;
  std::string s;
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    const double c = sgn * v(j);
    if (std::fabs(c) < tol) continue;
    if (!s.empty()) s += " ";
    s += (c >= 0 ? "+" : "-") + fmt(std::fabs(c), "%.3f") + " " + names[static_cast<std::size_t>(j)];
  }
  return s;
}

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

  Identifiability svd_analysis(const std::string& name, const Eigen::MatrixXd& J, double s) const {
    Identifiability id;
    id.dataset = name;
    id.names = names_;
    // full V: a dataset with fewer points than parameters still gets its null directions (zero singular values)
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
    const Eigen::VectorXd& sv = svd.singularValues();
    const double smax = sv.size() ? sv(0) : 0.0;
    for (int k = 0; k < n_; ++k) {
      Direction d;
      d.singular_value = k < sv.size() ? sv(k) : 0.0;
      d.relative = smax > 0.0 ? d.singular_value / smax : 0.0;
      d.determined = smax > 0.0 && d.singular_value > smax / max_cond_;
      d.se = d.singular_value > 0.0 ? s / d.singular_value : std::numeric_limits<double>::infinity();
      const Eigen::VectorXd v = svd.matrixV().col(k);
      d.coefficients.assign(v.data(), v.data() + v.size());
      d.text = combination_text(names_, v, 0.01);
      if (d.determined) ++id.rank;
      id.directions.push_back(d);
    }
    const double smin = id.directions.back().singular_value;
    id.condition = smin > 0.0 ? smax / smin : std::numeric_limits<double>::infinity();
    return id;
  }

  void analyse(Result& res, const Eigen::VectorXd& u, const Eigen::VectorXd& r, const Eigen::MatrixXd& J) {
    fill_estimate(res, u);
    const double chi2 = r.squaredNorm();
    res.cost = 0.5 * chi2;
    // which parameters sit at a bound (held there: excluded from the covariance)
    const Eigen::VectorXd g = J.transpose() * r;
    std::vector<int> inner;
    std::vector<bool> at_bound(static_cast<std::size_t>(n_), false);
    for (int j = 0; j < n_; ++j) {
      const double tol = 1e-12 * std::max(1.0, std::fabs(u(j)));
      const bool b = (u(j) <= lo_(j) + tol && g(j) >= 0.0) || (u(j) >= hi_(j) - tol && g(j) <= 0.0);
      at_bound[static_cast<std::size_t>(j)] = b;
      if (!b) inner.push_back(j);
    }
    // identifiability of all estimated parameters (s filled in below)
    res.combined = svd_analysis("all", J, 1.0);
    res.identifiable = res.combined.rank == n_;
    // covariance over the parameters not at a bound
    const int ni = static_cast<int>(inner.size());
    Eigen::MatrixXd Ji(m_, ni);
    for (int k = 0; k < ni; ++k) Ji.col(k) = J.col(inner[static_cast<std::size_t>(k)]);
    int rank = 0;
    Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(ni, ni);
    std::vector<bool> undetermined(static_cast<std::size_t>(ni), false);
    if (ni > 0) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(Ji, Eigen::ComputeThinV);
      const Eigen::VectorXd& sv = svd.singularValues();
      const double smax = sv(0);
      for (Eigen::Index k = 0; k < sv.size(); ++k) {
        if (smax > 0.0 && sv(k) > smax / max_cond_) {
          ++rank;
          const Eigen::VectorXd v = svd.matrixV().col(k);
          cov += v * v.transpose() / (sv(k) * sv(k));
        }
      }
      // undetermined: a coefficient above tol in a direction outside the determined subspace
      const Eigen::MatrixXd Vr = svd.matrixV().leftCols(rank);
      for (int k = 0; k < ni; ++k) {
        const double in_range = Vr.row(k).squaredNorm();  // |P e_k|^2; 1 - it = |null component|^2
        const double null_c = std::sqrt(std::max(0.0, 1.0 - in_range));
        undetermined[static_cast<std::size_t>(k)] = null_c > o_.null_coefficient_tol;
      }
    }
    res.dof = m_ - rank;
    if (res.dof > 0) res.reduced_chi2 = chi2 / res.dof;
    if (o_.noise == Noise::Estimated) {
      if (res.dof <= 0) {
        res.noise_scale = std::numeric_limits<double>::quiet_NaN();
      } else {
        res.noise_scale = std::sqrt(res.reduced_chi2);
      }
      res.quantile = res.dof > 0 ? two_sided_quantile(o_.confidence, res.dof) : std::numeric_limits<double>::quiet_NaN();
      res.interval_kind = "student-t(" + std::to_string(res.dof) + ")";
    } else {
      res.noise_scale = 1.0;
      res.quantile = two_sided_quantile(o_.confidence, 0);
      res.interval_kind = "normal";
    }
    const double s = res.noise_scale;
    for (Direction& d : res.combined.directions) d.se = d.singular_value > 0.0 ? s / d.singular_value : std::numeric_limits<double>::infinity();
    cov *= s * s;
    for (std::size_t k = 0; k < pr_.datasets.size(); ++k) {
      const Eigen::MatrixXd Jk = J.middleRows(offsets_[k], offsets_[k + 1] - offsets_[k]);
      res.per_dataset.push_back(svd_analysis(pr_.datasets[k].name, Jk, s));
    }
    // parameters
    const auto np = pr_.parameters.size();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    res.correlation.assign(np, std::vector<double>(np, nan));
    std::vector<int> slot(np, -1);  // index into cov
    for (int j = 0; j < n_; ++j) {
      ParameterEstimate& e = res.parameters[free_[static_cast<std::size_t>(j)]];
      if (at_bound[static_cast<std::size_t>(j)]) e.status = ParameterStatus::AtBound;
    }
    for (int k = 0; k < ni; ++k) {
      const int j = inner[static_cast<std::size_t>(k)];
      const std::size_t i = free_[static_cast<std::size_t>(j)];
      ParameterEstimate& e = res.parameters[i];
      if (undetermined[static_cast<std::size_t>(k)]) {
        e.status = ParameterStatus::Undetermined;
        continue;
      }
      slot[i] = k;
      const Parameter& q = par(j);
      const double se_u = std::sqrt(std::max(0.0, cov(k, k)));
      e.se_internal = se_u;
      e.se = q.transform == Transform::Log ? e.value * se_u : q.scale * se_u;
      const double uq = res.quantile * se_u;
      e.lower = to_p(q, u(j) - uq);
      e.upper = to_p(q, u(j) + uq);
    }
    for (std::size_t a = 0; a < np; ++a)
      for (std::size_t b = 0; b < np; ++b)
        if (slot[a] >= 0 && slot[b] >= 0) {
          const double den = std::sqrt(cov(slot[a], slot[a]) * cov(slot[b], slot[b]));
          res.correlation[a][b] = den > 0.0 ? cov(slot[a], slot[b]) / den : nan;
        }
  }

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

inline std::string json_number(double v) { return std::isfinite(v) ? fmt(v, "%.17g") : "null"; }

inline std::string json_string(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      o += b;
    }
    else o += c;
  }
  return o + "\"";
}

inline std::string json_identifiability(const Identifiability& id) {
  std::string s = "{\"dataset\": " + json_string(id.dataset) + ", \"condition\": " + json_number(id.condition) +
                  ", \"rank\": " + std::to_string(id.rank) + ", \"variables\": [";
  for (std::size_t j = 0; j < id.names.size(); ++j) s += (j ? ", " : "") + json_string(id.names[j]);
  s += "], \"directions\": [";
  for (std::size_t k = 0; k < id.directions.size(); ++k) {
    const Direction& d = id.directions[k];
    s += std::string(k ? ", " : "") + "{\"singular_value\": " + json_number(d.singular_value) +
         ", \"relative\": " + json_number(d.relative) + ", \"se\": " + json_number(d.se) +
         ", \"determined\": " + (d.determined ? "true" : "false") + ", \"combination\": " + json_string(d.text) +
         ", \"coefficients\": [";
    for (std::size_t j = 0; j < d.coefficients.size(); ++j) s += (j ? ", " : "") + json_number(d.coefficients[j]);
    s += "]}";
  }
  return s + "]}";
}

}  // namespace detail

// Fit the problem. Throws std::invalid_argument for an ill-posed call (no parameters, a start outside its
// bounds, a non-positive log parameter, sigma of the wrong length, a model returning the wrong length);
// every outcome of the fit itself, forward-model failures included, is in the Result.
inline Result fit(const Problem& problem, const Options& options = {}) {
  return detail::Estimator(problem, options).run();
}

// The result as one JSON object (non-finite numbers as null).
inline std::string to_json(const Result& r) {
  using detail::json_number;
  using detail::json_string;
  std::string s = "{\"reason\": " + json_string(to_string(r.reason)) + ", \"message\": " + json_string(r.message) +
                  ", \"converged\": " + (r.converged ? "true" : "false") +
                  ", \"identifiable\": " + (r.identifiable ? "true" : "false") + ", \"cost\": " + json_number(r.cost) +
                  ", \"points\": " + std::to_string(r.points) + ", \"dof\": " + std::to_string(r.dof) +
                  ", \"noise_scale\": " + json_number(r.noise_scale) + ", \"reduced_chi2\": " + json_number(r.reduced_chi2) +
                  ", \"interval\": " + json_string(r.interval_kind) + ", \"quantile\": " + json_number(r.quantile) +
                  ", \"iterations\": " + std::to_string(r.iterations) +
                  ", \"residual_evaluations\": " + std::to_string(r.residual_evaluations) +
                  ", \"forward_runs\": " + std::to_string(r.forward_runs) +
                  ", \"forward_failures\": " + std::to_string(r.forward_failures) +
                  ", \"wall_seconds\": " + json_number(r.wall_seconds) + ", \"max_condition\": " + json_number(r.max_condition) +
                  ", \"parameters\": [";
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const ParameterEstimate& e = r.parameters[i];
    s += std::string(i ? ", " : "") + "{\"name\": " + json_string(e.name) + ", \"variable\": " + json_string(e.variable) +
         ", \"value\": " + json_number(e.value) + ", \"status\": " + json_string(to_string(e.status)) +
         ", \"se\": " + json_number(e.se) + ", \"lower\": " + json_number(e.lower) + ", \"upper\": " + json_number(e.upper) + "}";
  }
  s += "], \"correlation\": [";
  for (std::size_t i = 0; i < r.correlation.size(); ++i) {
    s += std::string(i ? ", " : "") + "[";
    for (std::size_t j = 0; j < r.correlation[i].size(); ++j) s += (j ? ", " : "") + json_number(r.correlation[i][j]);
    s += "]";
  }
  s += "], \"identifiability\": " + detail::json_identifiability(r.combined) + ", \"per_dataset\": [";
  for (std::size_t k = 0; k < r.per_dataset.size(); ++k) s += (k ? ", " : "") + detail::json_identifiability(r.per_dataset[k]);
  return s + "]}";
}

// A human-readable summary: the outcome, the parameter table, the directions of the stacked problem and
// the undetermined directions of each dataset.
inline std::string describe(const Result& r) {
  using detail::fmt;
  std::string s = std::string("least squares: ") + to_string(r.reason) + ": " + r.message + "\n";
  s += "  cost " + fmt(r.cost) + ", " + std::to_string(r.points) + " points, " + std::to_string(r.iterations) +
       " iterations, " + std::to_string(r.forward_runs) + " forward runs (" + std::to_string(r.forward_failures) +
       " failed), " + fmt(r.wall_seconds, "%.3g") + " s; intervals " + fmt(r.quantile, "%.4g") + " se (" +
       r.interval_kind + "), noise scale " + fmt(r.noise_scale) + "\n";
  for (const ParameterEstimate& e : r.parameters) {
    s += "  " + e.name + " = " + fmt(e.value) + "  [" + to_string(e.status) + "]";
    if (std::isfinite(e.se)) s += "  se " + fmt(e.se, "%.3g") + "  interval [" + fmt(e.lower) + ", " + fmt(e.upper) + "]";
    s += "\n";
  }
  auto dirs = [&](const Identifiability& id, bool only_undetermined) {
    std::string t = "  " + id.dataset + ": condition " + fmt(id.condition, "%.3g") + ", rank " + std::to_string(id.rank) + "/" +
                    std::to_string(id.names.size()) + "\n";
    for (const Direction& d : id.directions)
      if (!only_undetermined || !d.determined)
        t += std::string("    ") + (d.determined ? "determined   " : "UNDETERMINED ") + "s.v. rel " + fmt(d.relative, "%.3g") +
             "  se " + fmt(d.se, "%.3g") + "  " + d.text + "\n";
    return t;
  };
  s += dirs(r.combined, false);
  for (const Identifiability& id : r.per_dataset) s += dirs(id, true);
  return s;
}

}  // namespace polymech::estimation
