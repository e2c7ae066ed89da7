// The micro-cantilever case of seed 002 paper 5 (issue 34): the load-unload curve of one beam of cubic 8YSZ
// (Hill plasticity with power-law hardening, eqs. (1)-(4)) at a crystal orientation, and the inverse
// estimation of the paper's six parameters from such curves (its section 5), on the geometry of
// models/solid/micro_cantilever.hpp, the elasto-plastic model of models/solid/elastoplastic.hpp and the
// estimator of models/inverse/least_squares.hpp.
//
// A curve: the end-face load F = lambda F_peak goes 0 -> F_peak -> 0 in load_increments + unload_increments
// equal steps (load control, as the nanoindenter's load-unload); at every planned step the work-conjugate tip
// deflection delta = f_ext . u / F_peak (micro_cantilever.hpp), so F delta is the work of the load. Steps
// that Newton had to cut are computed but not reported, so a curve has the same points for every parameter
// set (what a least-squares fit needs).
//
// The synthetic experiment (the paper has no published curves): a parameter set hidden from the estimator,
// curves on a finer mesh than the estimator's, plus Gaussian noise of a stated standard deviation on every
// deflection (a seeded generator, so a study is reproducible). The estimator fits all six orientations at
// once (one dataset each) in log variables (every parameter is positive), with forward differences whose
// step matches the forward model's accuracy (Newton tolerance), and reports the identifiability per
// orientation and combined.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "inverse/least_squares.hpp"
#include "materials/hill_plasticity.hpp"
#include "solid/elastoplastic.hpp"
#include "solid/micro_cantilever.hpp"

namespace polymech::solid {

// The paper's six angles of the beam axis from [001] in the (110) plane, in degrees (54.7: [1-11]).
inline const std::vector<double>& paper_angles() {
  static const std::vector<double> a = {0.0, 5.0, 10.0, 20.0, 30.0, 54.7356103172453};
  return a;
}

// The beam's Newton defaults: the tangent solved by CG with the elastic two-level p-multigrid and the inexact
// forcing term (elastoplastic.hpp): 3.4x faster than the elastic-LU preconditioner on a 3.6e4-DoF beam
// (188 s -> 55 s with exact solves -> 28.6 s inexact, one thread, shared machine; the same curve to 5 digits).
// Each step starts from the secant extrapolation of the last two (newton.hpp), and the cycle smooths with
// degree 5 over [hi / 30, hi] on float coarse factors (two_level.hpp): the paper-resolution curve (152 661
// DoFs, two threads) 123.4 s -> 57.1 s, the same curve to 7 digits (docs/PERFORMANCE.md).
inline NewtonOptions beam_newton_options() {
  NewtonOptions o;
  o.solver = TangentSolver::two_level_pcg;
  o.forcing = 0.1;
  o.secant_predictor = true;
  return o;
}

struct CurveSpec {
  MicroCantileverSpec beam;  // geometry, mesh, theta; beam.force is the peak force F_peak (mN)
  int load_increments = 8, unload_increments = 4;
  NewtonOptions newton = beam_newton_options();
};

struct LoadUnloadCurve {
  std::vector<double> force, deflection;  // mN, um, at the planned steps (the start excluded)
  int newton_iterations = 0, cuts = 0;
  std::int64_t linear_iterations = 0;
  Index dofs = 0, max_plastic_points = 0, points = 0;
  double seconds = 0.0;
  double residual_deflection() const { return deflection.empty() ? 0.0 : deflection.back(); }
  double peak_force() const { return force.empty() ? 0.0 : *std::max_element(force.begin(), force.end()); }
  double peak_deflection() const { return deflection.empty() ? 0.0 : *std::max_element(deflection.begin(), deflection.end()); }
};

// The Hill law of 8YSZ-like parameters for a beam at theta_degrees (crystal -> specimen axes).
inline materials::HillPlasticity<double> cantilever_law(const materials::CubicHillParameters<double>& p, double theta_degrees) {
  const double theta = theta_degrees * 3.14159265358979323846 / 180.0;
  return materials::make_cubic_hill(p, materials::cantilever_rotation(theta));
}

// The run's monitor of the work-conjugate tip deflection delta = f_ext . u / F_peak (F_peak the end load's
// total, from the external force vector f, which must outlive the monitor).
inline Monitor tip_deflection_monitor(const std::vector<double>& f) {
  double F = 0.0;
  for (std::size_t i = 2; i < f.size(); i += 3) F -= f[i];
  Monitor mon;
  mon.displacement = [&f, F](const std::vector<double>& u) {
    double w = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) w += f[i] * u[i];
    return w / F;
  };
  return mon;
}

// The load path of a curve: 0 -> 1 in load_increments steps, then back to 0 in unload_increments (if any).
inline LoadPath load_unload_path(const CurveSpec& s) {
  LoadPath path;
  path.points = {0.0, 1.0};
  path.increments = {s.load_increments};
  if (s.unload_increments > 0) {
    path.points.push_back(0.0);
    path.increments.push_back(s.unload_increments);
  }
  return path;
}

template <class T>
LoadUnloadCurve load_unload_curve(const CurveSpec& s, const materials::CubicHillParameters<double>& p) {
  if (s.load_increments < 1 || s.unload_increments < 0)
    throw std::invalid_argument("micro-cantilever curve: load_increments >= 1 and unload_increments >= 0 needed");
  const auto t0 = std::chrono::steady_clock::now();
  const materials::HillPlasticity<double> law = cantilever_law(p, s.beam.theta_degrees);
  Config<3> c = micro_cantilever(s.beam, law.C);
  c.plasticity = law;
  ElastoPlastic<T, 3> m(c, s.newton);
  const std::vector<double> f = models::to_host(m.external_force());
  const Monitor mon = tip_deflection_monitor(f);
  const LoadPath path = load_unload_path(s);
  // the planned load factors, in order
  std::vector<double> planned;
  for (std::size_t k = 0; k + 1 < path.points.size(); ++k)
    for (int i = 1; i <= path.increments[k]; ++i) {
      const double a = path.points[k], b = path.points[k + 1];
      planned.push_back(i == path.increments[k] ? b : a + (b - a) * i / path.increments[k]);
    }
  const std::vector<StepResult> steps = m.run(path, mon);
  LoadUnloadCurve out;
  out.dofs = m.dof_count();
  out.points = m.element_count() * m.points_per_element();
  std::size_t next = 0;
  for (const StepResult& r : steps) {
    out.newton_iterations += r.newton_iterations;
    out.linear_iterations += r.linear_iterations;
    out.cuts += r.cuts;
    out.max_plastic_points = std::max(out.max_plastic_points, r.plastic_points);
    if (next < planned.size() && r.load_factor == planned[next]) {
      out.force.push_back(r.load_factor * s.beam.force);
      out.deflection.push_back(r.displacement);
      ++next;
    }
  }
  if (next != planned.size())
    throw std::runtime_error("micro-cantilever curve: " + std::to_string(next) + " of " + std::to_string(planned.size()) +
                             " planned load steps were reported");
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// The curve of a linear elastic beam (no effect "plasticity": Config::plasticity left empty, no history): the
// same load path and tip measure as load_unload_curve, one Newton iteration per step.
template <class T>
LoadUnloadCurve elastic_load_unload_curve(const CurveSpec& s, const materials::CubicHillParameters<double>& p) {
  const auto t0 = std::chrono::steady_clock::now();
  const Config<3> c = micro_cantilever(s.beam, cantilever_law(p, s.beam.theta_degrees).C);
  ElastoPlastic<T, 3> m(c, s.newton);
  const std::vector<double> f = models::to_host(m.external_force());
  const Monitor mon = tip_deflection_monitor(f);
  LoadUnloadCurve out;
  out.dofs = m.dof_count();
  out.points = m.element_count() * m.points_per_element();
  for (const StepResult& r : m.run(load_unload_path(s), mon)) {  // an elastic step never cuts: every step is a planned one
    out.newton_iterations += r.newton_iterations;
    out.linear_iterations += r.linear_iterations;
    out.force.push_back(r.load_factor * s.beam.force);
    out.deflection.push_back(r.displacement);
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

// The closed-form references of a beam at theta_degrees: the uniaxial modulus of the cubic crystal along the
// beam axis and the Euler-Bernoulli compliance L^3 / (3 E I) of the beam clamped at its root (I of the pentagon).
struct BeamTheory {
  double modulus = 0.0, compliance = 0.0;
};
inline BeamTheory beam_theory(const MicroCantileverSpec& b, const materials::CubicConstants<double>& k, double theta_degrees) {
  BeamTheory t;
  t.modulus = materials::cubic_uniaxial_modulus(k, materials::cantilever_axis(theta_degrees * 3.14159265358979323846 / 180.0));
  t.compliance = std::pow(b.length, 3) / (3.0 * t.modulus * pentagon_section(b).second_moment);
  return t;
}

// The six parameters in the estimator's order, and back.
inline const std::vector<std::string>& hill_parameter_names() {
  static const std::vector<std::string> n = {"C11", "C12", "C44", "sigma_y", "n", "R12"};
  return n;
}
inline std::vector<double> to_vector(const materials::CubicHillParameters<double>& p) {
  return {p.elastic.C11, p.elastic.C12, p.elastic.C44, p.yield_stress, p.hardening_exponent, p.R12};
}
inline materials::CubicHillParameters<double> to_parameters(const std::vector<double>& v,
                                                            materials::HillForm form = materials::HillForm::yield_stress_ratio) {
  materials::CubicHillParameters<double> p;
  p.elastic.C11 = v.at(0);
  p.elastic.C12 = v.at(1);
  p.elastic.C44 = v.at(2);
  p.yield_stress = v.at(3);
  p.hardening_exponent = v.at(4);
  p.R12 = v.at(5);
  p.form = form;
  return p;
}

struct InverseStudySpec {
  materials::CubicHillParameters<double> truth;  // hidden from the estimator
  materials::CubicHillParameters<double> start;  // the estimator's first guess
  CurveSpec experiment;                          // the synthetic experiment's mesh and load (beam.theta ignored)
  CurveSpec estimator;                           // the estimator's (coarser) mesh, same load
  std::vector<double> angles = paper_angles();
  double noise = 0.005;  // standard deviation of the measured deflection (um)
  std::uint32_t seed = 1;
  estimation::Options options;
};

struct InverseStudy {
  std::vector<LoadUnloadCurve> experiments;  // per angle, noise-free, on the experiment's mesh
  std::vector<std::vector<double>> measured;  // per angle, with noise
  std::vector<LoadUnloadCurve> fitted;        // per angle, the estimator's mesh at the estimate
  estimation::Result result;
  double experiment_seconds = 0.0;
};

// Curves of the hidden parameters (experiment mesh), noise, the six-parameter fit (estimator mesh), the
// identifiability per orientation and combined, and the fitted curves.
template <class T>
InverseStudy run_inverse_study(const InverseStudySpec& s, const std::function<void(const std::string&)>& progress = {}) {
  InverseStudy out;
  std::mt19937_64 rng(s.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const auto t0 = std::chrono::steady_clock::now();
  estimation::Problem problem;
  for (double theta : s.angles) {
    CurveSpec e = s.experiment;
    e.beam.theta_degrees = theta;
    out.experiments.push_back(load_unload_curve<T>(e, s.truth));
    std::vector<double> y = out.experiments.back().deflection;
    for (double& v : y) v += s.noise * gauss(rng);
    out.measured.push_back(y);
    if (progress) {
      char line[160];
      std::snprintf(line, sizeof line, "experiment theta = %.4g deg: %zu points, peak deflection %.4g um, %.2f s", theta,
                    y.size(), *std::max_element(y.begin(), y.end()), out.experiments.back().seconds);
      progress(line);
    }
    estimation::Dataset d;
    char name[32];
    std::snprintf(name, sizeof name, "theta=%.4g", theta);
    d.name = name;
    d.data = y;
    d.sigma.assign(y.size(), s.noise);
    CurveSpec est = s.estimator;
    est.beam.theta_degrees = theta;
    d.model = [est](const std::vector<double>& p) { return load_unload_curve<T>(est, to_parameters(p)).deflection; };
    problem.datasets.push_back(std::move(d));
  }
  out.experiment_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::vector<double> start = to_vector(s.start);
  const std::vector<std::pair<double, double>> bounds = {{50.0, 2000.0}, {1.0, 1000.0}, {5.0, 500.0},
                                                         {0.05, 50.0},  {1e-3, 0.9},   {0.2, 5.0}};
  for (std::size_t j = 0; j < start.size(); ++j) {
    estimation::Parameter q;
    q.name = hill_parameter_names()[j];
    q.initial = start[j];
    q.lower = bounds[j].first;
    q.upper = bounds[j].second;
    q.transform = estimation::Transform::Log;
    problem.parameters.push_back(q);
  }
  out.result = estimation::fit(problem, s.options);
  for (double theta : s.angles) {
    CurveSpec est = s.estimator;
    est.beam.theta_degrees = theta;
    out.fitted.push_back(load_unload_curve<T>(est, to_parameters(out.result.estimate)));
  }
  return out;
}

}  // namespace polymech::solid
