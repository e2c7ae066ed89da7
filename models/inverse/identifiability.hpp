// The least-squares estimator's analysis at the estimate (issue 34; seed 002 paper 5 section 5, whose Fig. 4
// finds that how reliably each constant is determined depends on the orientation): the identifiability (SVD
// of the Jacobian) and the covariance, standard errors and confidence intervals. Defines the members
// Estimator::svd_analysis and Estimator::analyse declared in estimator.hpp.
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
// Host-only, double, Eigen.
#pragma once

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "inverse/estimator.hpp"
#include "inverse/format.hpp"
#include "inverse/problem.hpp"
#include "inverse/statistics.hpp"

namespace polymech::estimation {

namespace detail {

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

inline Identifiability Estimator::svd_analysis(const std::string& name, const Eigen::MatrixXd& J, double s) const {
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

inline void Estimator::analyse(Result& res, const Eigen::VectorXd& u, const Eigen::VectorXd& r, const Eigen::MatrixXd& J) {
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

}  // namespace detail

}  // namespace polymech::estimation
