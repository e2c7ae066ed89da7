// Planning a run from the accuracy it must reach (issue 38, `polymech plan`): for a scene whose case has a
// committed accuracy-cost sweep (docs/figures/*/ from bench/sweep_*), fit an error model per (order,
// precision) to the sweep's measured convergence and a time model to the scene loader's cost estimate
// refreshed by the sweep's measured CPU times, then choose the resolution, order and precision whose
// predicted error is at most the target at the least predicted time, or refuse when the data support no
// such choice. A thin layer: the sweeps' CSVs and the loaders' CostEstimate are read, never copied.
// Host-only, free of Kokkos (the loaders it calls check stability with the models' kernels: callers hold
// a Kokkos session, as `polymech` does).
#pragma once

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymech::io::plan {

// A scene, method or quantity the plan cannot serve (no sweep data, unknown quantity): exit code 2.
struct PlanError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A numeric CSV (header line, then rows; "nan" allowed), as the sweeps write them.
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  int column(const std::string& name) const;  // -1 if absent
};
Table read_csv(const std::filesystem::path& file);

// e = constant * h^rate by least squares on log e against log h (points with e > 0 and finite).
struct PowerLaw {
  double rate = 0.0, constant = 0.0;
  double log_rms = 0.0;  // rms of log(e / fit)
  int points = 0;
};
PowerLaw fit_power_law(const std::vector<double>& h, const std::vector<double>& e);

// Richardson extrapolation (issue 38: a quantity with no analytic reference): q(h) = q0 + C h^p through the
// three finest runs h1 > h2 > h3 of a group, p from (q1 - q2) / (q2 - q3) = (h1^p - h2^p) / (h2^p - h3^p)
// (any ratios of h), q0 = q3 - (q2 - q3) h3^p / (h2^p - h3^p). Not usable (ok false, with the reason) when
// fewer than three runs, the changes alternate in sign or do not shrink (no p > 0), the observed order is
// below min_order (the extrapolated correction would exceed what the sweep moved; the limit is a guess),
// or, with a fourth run, the order of the next coarser three differs by more than 30 % (not yet in the
// asymptotic range).
struct Richardson {
  bool ok = false;
  std::string reason;
  double limit = 0.0;        // q0
  double order = 0.0;        // p of the three finest runs
  double order_check = 0.0;  // p of the next coarser three (0: fewer than four runs)
  int points = 0;
};
constexpr double richardson_min_order = 0.5;
Richardson richardson(const std::vector<double>& h, const std::vector<double>& q);

// One measured run of a sweep.
struct SweepPoint {
  double resolution = 0.0;  // the sweep's knob (coarsening factor, elements along x)
  double h = 0.0;           // the length the error converges with (spacing, element size)
  double order = 0.0;       // element order or horizon ratio (0: the model has none)
  bool single = false;      // float
  double error = 0.0;       // |relative error| of the quantity
  double seconds = 0.0;     // measured CPU time, one thread
  double estimate = 0.0;    // the loader's cost estimate of the same run, one thread [s]
  std::int64_t steps = 0;   // the run's steps where the sweep sets them (0: the scene's)
};

// The error and time model of one (order, precision) group of a sweep.
struct GroupModel {
  double order = 0.0;
  bool single = false;
  PowerLaw fit;               // over the converging points (finest first is not assumed)
  double bound = 0.0;         // constant such that bound * h^rate >= every converging point's error
  bool converges = false;     // false: the error does not fall with h over the sweep (envelope model)
  double floor = 0.0;         // > 0: finer runs than the best one do not reduce the error below this
  // time: measured = time_factor * estimate^time_exponent, least squares in log-log over the group (one
  // point: the ratio, exponent 1); the exponent absorbs what the estimate leaves out (set-up, output)
  double time_factor = 1.0;
  double time_exponent = 1.0;
  double time_log_rms = 0.0;  // rms of log(measured / model)
  // > 0 where the sweep timed whole processes (start-up included: DEM): measured = time_offset +
  // time_factor * estimate, least squares on the relative residual (time_exponent 1)
  double time_offset = 0.0;
  int points = 0;
  // where the quantity has no analytic reference: the group's Richardson limit that its errors are
  // measured against (NaN: an analytic reference)
  double reference = NAN;
  double reference_order = 0.0;
};

// A choice the plan can make: one sweep point with its predicted error and time.
struct Candidate {
  SweepPoint point;
  double predicted_error = 0.0;
  double predicted_seconds = 0.0;
  bool beyond_floor = false;  // finer than the group's best run: never chosen (dominated)
  double reference = NAN;     // the group's Richardson limit (NaN: analytic reference; the app reports the error)
};

// The fitted models of one scene's quantity.
struct Model {
  std::string method;       // "MPS point source", ...
  std::string app;          // the app that runs it
  std::string quantity;     // key (cp, l2, modulus)
  std::string quantity_text;
  std::string summary_key;  // the key of the achieved error in the app's summary.json (Richardson: of the value)
  std::string resolution_name, order_name;
  std::filesystem::path csv;  // the sweep data, relative to the source folder
  std::string sweep_command;  // how the CSV is made
  std::vector<GroupModel> groups;
  std::vector<Candidate> candidates;  // predicted_seconds include overhead_seconds
  // the app's fixed cost that the sweep's model-only times leave out (start-up, scene load, output),
  // measured by `polymech plan --measure-overhead` into overhead_csv(); 0 where none is committed
  double overhead_seconds = 0.0;
  std::string overhead_source;
  // where the quantity has no analytic reference: the sweep's errors are against a Richardson extrapolation
  std::string reference_note;
  bool richardson = false;
  // not empty: no group of the sweep gives an error estimate (Richardson not usable); every target is refused
  std::string unusable;
};

// Groups sweep points by (order, precision) and fits each (error model: power law over the points up to
// the group's smallest error, floor where finer points stop improving, monotone envelope where the error
// does not fall; time model: the estimate's ratio to the measured time). Candidates are the sweep's
// points with their predictions.
std::vector<GroupModel> fit_groups(const std::vector<SweepPoint>& points, bool affine_time = false);
std::vector<Candidate> predict(const std::vector<SweepPoint>& points, const std::vector<GroupModel>& groups);

struct Plan {
  bool refused = false;
  std::string reason;          // why refused
  double best_error = 0.0;     // the smallest predicted error any candidate reaches
  Candidate choice;            // when not refused
  std::vector<Candidate> pareto;  // the non-dominated candidates (predicted error, predicted time)
};
// The candidate of least predicted time with predicted error <= target; refused (with the best reachable
// error and what limits it) when none.
Plan choose(const Model& model, double target);

// The folder that holds docs/figures: $POLYMECH_SOURCE_DIR, else the first parent of the scene file (or of
// the working folder) that has docs/figures.
std::filesystem::path source_dir(const std::filesystem::path& scene);

// The names of the cases (and their scenes) with sweep data.
std::vector<std::string> planned_cases();

// The model of `scene`'s quantity (default: the case's first); PlanError if the scene's case has no
// sweep data or the quantity is unknown.
// with_overhead false: the sweep's times alone (what --measure-overhead compares a whole run with).
Model build_model(const std::filesystem::path& scene, const std::string& quantity = "", bool with_overhead = true);

// The committed app overheads (relative to the source folder) and one scene of every case (to measure them).
inline const char* overhead_csv() { return "docs/figures/plan/app_overhead.csv"; }
std::vector<std::filesystem::path> overhead_scenes(const std::filesystem::path& root);

// A table (markdown) of every case's fitted models: rate, constant, floor, time factor per group.
std::string fit_report(const std::filesystem::path& root);

// The run of a candidate: writes a copy of the scene set to the candidate's resolution, order and
// precision as `out/plan_scene.toml`, and returns the app's arguments (after the app's name).
std::vector<std::string> run_arguments(const Model& model, const std::filesystem::path& scene, const Candidate& c,
                                       const std::filesystem::path& out, int threads);

// Human-readable lines.
std::string describe_candidate(const Model& model, const Candidate& c);
std::string describe_plan(const Model& model, const Plan& plan, double target);

}  // namespace polymech::io::plan
