// Reports of a least-squares fit (issue 34): the result as one JSON object (to_json; non-finite numbers as
// null) and a human-readable summary (describe). No I/O: both return strings. Host-only.
#pragma once

#include <cmath>
#include <string>

#include "inverse/format.hpp"
#include "inverse/problem.hpp"

namespace polymech::estimation {

namespace detail {

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
