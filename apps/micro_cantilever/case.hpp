// The cases of apps/micro_cantilever (issue 34; seed 002 paper 5): the scene's beam and crystal as the model's
// specs, the load-unload curves per angle and the synthetic inverse study, each writing its part of
// summary.json and the rows of curves.csv (the curves themselves and the study: models/solid/
// micro_cantilever_case.hpp).
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/common/case.hpp"
#include "io/solid_scene.hpp"
#include "solid/micro_cantilever_case.hpp"

namespace polymech::apps::cantilever {

constexpr int kPaperRunsPerSpecimen = 30;  // the paper's response surface: 30 forward runs per specimen (section 5)

inline materials::CubicHillParameters<double> parameters(const io::SolidCrystal& c) {
  materials::CubicHillParameters<double> p;
  p.elastic.C11 = c.C11;
  p.elastic.C12 = c.C12;
  p.elastic.C44 = c.C44;
  p.yield_stress = c.yield_stress;
  p.hardening_exponent = c.hardening_exponent;
  p.R12 = c.R12;
  p.form = c.hill_form == "as_printed" ? materials::HillForm::as_printed : materials::HillForm::yield_stress_ratio;
  return p;
}

inline solid::CurveSpec curve_spec(const io::SolidScene& s, double h_root) {
  solid::CurveSpec c;
  solid::MicroCantileverSpec& b = c.beam;
  b.length = s.beam.length;
  b.width = s.beam.width;
  b.height = s.beam.height;
  b.wall = s.beam.wall;
  b.support_length = s.beam.support_length;
  b.support_width = s.beam.support_width;
  b.support_depth = s.beam.support_depth;
  b.order = s.mesh.order;
  b.h_root = h_root;
  b.growth = s.mesh.growth;
  b.h_beam_max = std::max(s.mesh.h_beam_max, h_root);
  b.support_growth = s.mesh.support_growth;
  b.h_support_max = std::max(s.mesh.h_support_max, h_root);
  b.force = s.beam.peak_force;
  c.load_increments = s.load_increments;
  c.unload_increments = s.unload_increments;
  c.newton.tolerance = s.newton.tolerance;
  c.newton.max_iterations = s.newton.max_iterations;
  c.newton.line_search = s.newton.line_search;
  c.newton.max_cuts = s.newton.max_cuts;
  c.newton.solver = s.newton.solver == "direct"        ? solid::TangentSolver::direct
                    : s.newton.solver == "elastic_pcg" ? solid::TangentSolver::elastic_pcg
                                                       : solid::TangentSolver::two_level_pcg;
  c.newton.forcing = s.newton.solver == "direct" ? 0.0 : s.newton.forcing;
  return c;
}

// One angle's summary entry.
inline nlohmann::json curve_json(const io::SolidScene& s, double theta, const solid::LoadUnloadCurve& c) {
  solid::MicroCantileverSpec b;
  b.length = s.beam.length;
  b.width = s.beam.width;
  b.height = s.beam.height;
  b.wall = s.beam.wall;
  const solid::BeamTheory bt = solid::beam_theory(b, {s.crystal.C11, s.crystal.C12, s.crystal.C44}, theta);
  nlohmann::json j;
  j["angle"] = theta;
  j["uniaxial_modulus"] = bt.modulus;
  j["beam_theory_compliance"] = bt.compliance;  // Euler-Bernoulli, clamped root
  j["compliance"] = c.force.empty() ? 0.0 : c.deflection.front() / c.force.front();
  j["peak_force"] = c.peak_force();
  j["peak_deflection"] = c.peak_deflection();
  j["residual_deflection"] = s.unload_increments > 0 ? c.residual_deflection() : std::numeric_limits<double>::quiet_NaN();
  j["max_plastic_points"] = c.max_plastic_points;
  j["quadrature_points"] = c.points;
  j["newton_iterations"] = c.newton_iterations;
  j["linear_iterations"] = c.linear_iterations;
  j["step_cuts"] = c.cuts;
  j["wall_seconds"] = c.seconds;
  return j;
}

// The columns of curves.csv (angle, step, force, deflection), a row per planned step of every curve.
struct CurveRows {
  std::vector<double> angle, step, force, deflection;
  void add(double theta, const solid::LoadUnloadCurve& c) {
    for (std::size_t i = 0; i < c.force.size(); ++i) {
      angle.push_back(theta);
      step.push_back(static_cast<double>(i + 1));
      force.push_back(c.force[i]);
      deflection.push_back(c.deflection[i]);
    }
  }
};

// The curves of the scene's beam at `angles` into j["curves"] and `rows`. A curve whose Newton iteration fails
// (the step cut max_cuts times: std::runtime_error naming the load factor reached) ends the run as "diverged"
// in `stats`, with the reason and the angle; the curves finished before it are kept.
template <class T>
void run_curves(const io::SolidScene& scene, const Case& cs, const std::vector<double>& angles, nlohmann::json& j, CurveRows& rows,
                models::RunStats& stats) {
  const auto p = parameters(scene.crystal);
  const solid::CurveSpec base = curve_spec(scene, scene.mesh.h_root);
  nlohmann::json per = nlohmann::json::array();
  for (std::size_t k = 0; k < angles.size(); ++k) {
    solid::CurveSpec c = base;
    c.beam.theta_degrees = angles[k];
    solid::LoadUnloadCurve curve;
    try {
      curve = scene.plasticity ? solid::load_unload_curve<T>(c, p) : solid::elastic_load_unload_curve<T>(c, p);
    } catch (const std::runtime_error& e) {
      stats.diverged = true;
      stats.bad_step = static_cast<std::int64_t>(k);
      stats.last_good_step = static_cast<std::int64_t>(k) - 1;
      stats.reason = "the curve at theta = " + io::format_number(angles[k]) + " deg failed: " + e.what();
      j["failed_angle"] = angles[k];
      break;
    }
    if (!cs.quiet())
      std::fprintf(stderr, "  [%zu/%zu] theta = %.4g deg: peak deflection %.4g um, residual %.4g um, %lld plastic points, "
                   "%d Newton iterations (%d cuts), %.1f s\n",
                   k + 1, angles.size(), angles[k], curve.peak_deflection(), curve.residual_deflection(),
                   static_cast<long long>(curve.max_plastic_points), curve.newton_iterations, curve.cuts, curve.seconds);
    if (k == 0) j["dofs"] = curve.dofs;
    per.push_back(curve_json(scene, angles[k], curve));
    rows.add(angles[k], curve);
  }
  j["curves"] = per;
}

// The synthetic inverse study of the scene's [inverse] table: its keys into j, the experiment's curves into
// `rows`, fitted.csv (measured, noise-free experiment and fitted deflection per step) into the output folder.
// A forward model that failed during the fit ends the run as "diverged" in `stats`.
template <class T>
void run_inverse(const io::SolidScene& scene, const Case& cs, const std::vector<double>& angles, nlohmann::json& j, CurveRows& rows,
                 models::RunStats& stats, std::vector<std::string>& files) {
  namespace est = estimation;
  solid::InverseStudySpec st;
  st.truth = parameters(scene.crystal);
  st.start = parameters(scene.inverse->start);
  st.experiment = curve_spec(scene, scene.inverse->experiment_h_root);
  st.estimator = curve_spec(scene, scene.mesh.h_root);
  st.angles = angles;
  st.noise = scene.inverse->noise;
  st.seed = scene.inverse->seed;
  st.options.max_iterations = scene.inverse->max_iterations;
  st.options.model_accuracy = scene.inverse->model_accuracy;
  std::fprintf(stderr, "  inverse study: experiment h_root %.3g um, estimator h_root %.3g um, noise %.3g um, seed %u\n",
               scene.inverse->experiment_h_root, scene.mesh.h_root, st.noise, st.seed);
  const solid::InverseStudy r = solid::run_inverse_study<T>(st, [&](const std::string& line) {
    if (!cs.quiet()) std::fprintf(stderr, "  %s\n", line.c_str());
  });
  if (!cs.quiet()) std::fprintf(stderr, "  fit: %d forward runs, %.1f s\n", r.result.forward_runs, r.result.wall_seconds);
  std::printf("%s", est::describe(r.result).c_str());
  nlohmann::json per = nlohmann::json::array();
  std::vector<double> fa, fs, ff, fm, fe, fv;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    nlohmann::json e = curve_json(scene, angles[k], r.experiments[k]);
    e["fitted_peak_deflection"] = r.fitted[k].peak_deflection();
    e["fitted_residual_deflection"] = r.fitted[k].residual_deflection();
    per.push_back(e);
    rows.add(angles[k], r.experiments[k]);
    for (std::size_t i = 0; i < r.fitted[k].force.size(); ++i) {
      fa.push_back(angles[k]);
      fs.push_back(static_cast<double>(i + 1));
      ff.push_back(r.fitted[k].force[i]);
      fm.push_back(r.measured[k][i]);
      fe.push_back(r.experiments[k].deflection[i]);
      fv.push_back(r.fitted[k].deflection[i]);
    }
  }
  j["dofs"] = r.fitted.empty() ? 0 : r.fitted.front().dofs;
  j["experiment_dofs"] = r.experiments.empty() ? 0 : r.experiments.front().dofs;
  j["experiment_h_root"] = scene.inverse->experiment_h_root;
  j["curves"] = per;  // the experiment's (noise-free) curves of the hidden truth
  j["noise"] = st.noise;
  j["seed"] = st.seed;
  j["truth"] = solid::to_vector(st.truth);
  j["start"] = solid::to_vector(st.start);
  j["parameter_names"] = solid::hill_parameter_names();
  j["inverse"] = nlohmann::json::parse(est::to_json(r.result));
  j["experiment_seconds"] = r.experiment_seconds;
  j["fit_seconds"] = r.result.wall_seconds;
  j["forward_runs"] = r.result.forward_runs;
  j["forward_runs_per_specimen"] = static_cast<double>(r.result.forward_runs) / static_cast<double>(angles.size());
  j["paper_forward_runs_per_specimen"] = kPaperRunsPerSpecimen;
  io::write_csv(cs.out() / "fitted.csv", {"angle", "step", "force", "measured", "experiment", "fitted"}, {fa, fs, ff, fm, fe, fv});
  files.push_back("fitted.csv");
  std::printf("cost: %d forward runs (%.1f per orientation; the paper's response surface: %d per specimen), fit %.1f s, "
              "experiment %.1f s\n",
              r.result.forward_runs, static_cast<double>(r.result.forward_runs) / angles.size(), kPaperRunsPerSpecimen,
              r.result.wall_seconds, r.experiment_seconds);
  if (r.result.reason == est::StopReason::ModelFailure) {
    stats.diverged = true;
    stats.reason = "the fit stopped: the forward model failed (" + r.result.message + ")";
  }
}

}  // namespace polymech::apps::cantilever
