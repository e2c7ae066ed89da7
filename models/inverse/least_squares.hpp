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
// The pieces, by job (each file's header says the method of its part):
//   problem.hpp          the interface: parameters, datasets (forward models), options, result
//   estimator.hpp        residuals, finite-difference sensitivities, Levenberg-Marquardt, stopping
//   identifiability.hpp  at the estimate: SVD identifiability, covariance, standard errors, intervals
//   statistics.hpp       incomplete beta, normal and Student's t quantiles
//   format.hpp           number and JSON formatting
//   report.hpp           to_json and describe
// This header includes them all and holds the entry point fit().
//
// Host-only, double, Eigen; no I/O: to_json and describe return strings.
#pragma once

#include "inverse/estimator.hpp"
#include "inverse/format.hpp"
#include "inverse/identifiability.hpp"
#include "inverse/problem.hpp"
#include "inverse/report.hpp"
#include "inverse/statistics.hpp"

// (Namespace `estimation`, not `inverse`: polymech::inverse is the small-matrix inverse of kernels/core/small_math.hpp.)
namespace polymech::estimation {

// Fit the problem. Throws std::invalid_argument for an ill-posed call (no parameters, a start outside its
// bounds, a non-positive log parameter, sigma of the wrong length, a model returning the wrong length);
// every outcome of the fit itself, forward-model failures included, is in the Result.
inline Result fit(const Problem& problem, const Options& options = {}) {
  return detail::Estimator(problem, options).run();
}

}  // namespace polymech::estimation
