// The least-squares estimator's interface (issue 34; seed 002 paper 5 section 5): the problem (parameters,
// datasets with their forward models), the options and the result. The estimator (estimator.hpp) fits
//
//   minimise  F(p) = 1/2 sum_k w_k sum_i ((m_k(p)_i - y_ki) / sigma_ki)^2     over lo <= p <= hi,
//
// over datasets k (e.g. one per orientation of paper 5's micro-cantilever), each a forward-model callback
// m_k(p) -> predictions. The overview of the method is in least_squares.hpp.
//
// Variables. Each parameter is estimated in an internal variable u: u = log p (Transform::Log, for
// positive parameters: moduli, yield stress) or u = p / scale (Transform::Linear). A unit step in u is
// then a relative change (log) or one typical magnitude (linear), so the Jacobian J = dr/du is the
// "scaled" Jacobian J S of relative sensitivities, the finite-difference step, the damping, the stopping
// tolerances and the condition number are all in these units, and confidence intervals of log
// parameters are asymmetric in p (and never cross zero).
//
// Host-only, double; no Eigen here.
#pragma once

#include <functional>
#include <limits>
#include <string>
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

}  // namespace polymech::estimation
