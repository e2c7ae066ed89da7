#include "io/plan.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <unistd.h>

#include "io/dem_scene.hpp"
#include "io/efg_scene.hpp"
#include "io/helmholtz_scene.hpp"
#include "io/isph_scene.hpp"
#include "io/mps_elastic_scene.hpp"
#include "io/nosb_pd_scene.hpp"
#include "io/scene.hpp"

namespace polymech::io::plan {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------- CSV

int Table::column(const std::string& name) const {
  for (std::size_t k = 0; k < columns.size(); ++k)
    if (columns[k] == name) return static_cast<int>(k);
  return -1;
}

Table read_csv(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw PlanError(file.string() + ": cannot read the sweep data");
  Table t;
  std::string line;
  auto split = [](const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string cell;
    while (std::getline(ss, cell, ',')) out.push_back(cell);
    return out;
  };
  auto chomp = [](std::string& l) {  // the CSVs of Python's csv module end lines in \r\n
    if (!l.empty() && l.back() == '\r') l.pop_back();
  };
  if (!std::getline(in, line)) throw PlanError(file.string() + ": empty");
  chomp(line);
  t.columns = split(line);
  int n = 1;
  while (std::getline(in, line)) {
    ++n;
    chomp(line);
    if (line.empty()) continue;
    const auto cells = split(line);
    if (cells.size() != t.columns.size())
      throw PlanError(file.string() + ":" + std::to_string(n) + ": " + std::to_string(cells.size()) + " cells, the header has " +
                      std::to_string(t.columns.size()));
    std::vector<double> row;
    for (const auto& c : cells) {
      char* end = nullptr;
      const double v = std::strtod(c.c_str(), &end);
      row.push_back(end == c.c_str() ? std::nan("") : v);
    }
    t.rows.push_back(row);
  }
  return t;
}

// ---------------------------------------------------------------------------------------------- fits

PowerLaw fit_power_law(const std::vector<double>& h, const std::vector<double>& e) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < h.size() && k < e.size(); ++k)
    if (h[k] > 0 && e[k] > 0 && std::isfinite(h[k]) && std::isfinite(e[k])) {
      x.push_back(std::log(h[k]));
      y.push_back(std::log(e[k]));
    }
  PowerLaw p;
  p.points = static_cast<int>(x.size());
  if (x.empty()) return p;
  double mx = 0, my = 0;
  for (std::size_t k = 0; k < x.size(); ++k) mx += x[k], my += y[k];
  mx /= x.size();
  my /= y.size();
  double sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < x.size(); ++k) sxx += (x[k] - mx) * (x[k] - mx), sxy += (x[k] - mx) * (y[k] - my);
  p.rate = sxx > 0 ? sxy / sxx : 0.0;
  p.constant = std::exp(my - p.rate * mx);
  double r2 = 0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double r = y[k] - (my + p.rate * (x[k] - mx));
    r2 += r * r;
  }
  p.log_rms = std::sqrt(r2 / x.size());
  return p;
}

namespace {

// (h1^p - h2^p) / (h2^p - h3^p), increasing in p from log(h1/h2) / log(h2/h3) at p -> 0
double richardson_ratio(double h1, double h2, double h3, double p) {
  return (std::pow(h1, p) - std::pow(h2, p)) / (std::pow(h2, p) - std::pow(h3, p));
}

// The observed order of three runs h1 > h2 > h3 (0: none, with the reason).
double observed_order(double h1, double h2, double h3, double q1, double q2, double q3, std::string& why) {
  const double d1 = q1 - q2, d2 = q2 - q3;
  if (d2 == 0.0 || d1 == 0.0 || (d1 > 0) != (d2 > 0)) {
    why = "the changes between successive runs alternate in sign or vanish (no monotone convergence)";
    return 0.0;
  }
  const double r = d1 / d2;
  if (r <= std::log(h1 / h2) / std::log(h2 / h3)) {
    why = "the changes between successive runs do not shrink with h (no convergence at any order p > 0)";
    return 0.0;
  }
  double lo = 1e-6, hi = 1.0;
  while (richardson_ratio(h1, h2, h3, hi) < r && hi < 64) hi *= 2;
  if (richardson_ratio(h1, h2, h3, hi) < r) {
    why = "the observed order is above 64 (the changes collapse: round-off or a floor, not convergence)";
    return 0.0;
  }
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (richardson_ratio(h1, h2, h3, mid) < r ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

bool same_group(const SweepPoint& p, const GroupModel& g) { return p.order == g.order && p.single == g.single; }

// The points of one group, coarsest first.
std::vector<SweepPoint> group_points(const std::vector<SweepPoint>& points, double order, bool single) {
  std::vector<SweepPoint> g;
  for (const auto& p : points)
    if (p.order == order && p.single == single && std::isfinite(p.error)) g.push_back(p);
  std::sort(g.begin(), g.end(), [](const SweepPoint& a, const SweepPoint& b) { return a.h > b.h; });
  return g;
}

// Index of the smallest error (the first one on ties: the coarsest run that reached it; finer runs with
// the same error, as float's rounding of the DEM force gives, are a floor).
std::size_t best_index(const std::vector<SweepPoint>& g) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < g.size(); ++i)
    if (g[i].error < g[k].error) k = i;
  return k;
}

// A rate below this is no convergence over the sweep's range.
constexpr double min_rate = 0.2;

std::string num3(double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace

Richardson richardson(const std::vector<double>& h_in, const std::vector<double>& q_in) {
  Richardson r;
  std::vector<std::pair<double, double>> pts;
  for (std::size_t i = 0; i < h_in.size() && i < q_in.size(); ++i)
    if (h_in[i] > 0 && std::isfinite(q_in[i])) pts.emplace_back(h_in[i], q_in[i]);
  std::sort(pts.begin(), pts.end(), [](const auto& a, const auto& b) { return a.first > b.first; });  // coarsest first
  r.points = static_cast<int>(pts.size());
  if (pts.size() < 3) {
    r.reason = std::to_string(pts.size()) + " run(s), Richardson needs three resolutions";
    return r;
  }
  const std::size_t n = pts.size();
  const auto& [h1, q1] = pts[n - 3];
  const auto& [h2, q2] = pts[n - 2];
  const auto& [h3, q3] = pts[n - 1];
  if (!(h1 > h2 && h2 > h3)) {
    r.reason = "two runs share a resolution";
    return r;
  }
  std::string why;
  r.order = observed_order(h1, h2, h3, q1, q2, q3, why);
  if (r.order <= 0) {
    r.reason = why + " (values " + num3(q1) + ", " + num3(q2) + ", " + num3(q3) + " at h " + num3(h1) + ", " + num3(h2) +
               ", " + num3(h3) + ")";
    return r;
  }
  const double p = r.order;
  r.limit = q3 - (q2 - q3) * std::pow(h3, p) / (std::pow(h2, p) - std::pow(h3, p));
  if (p < richardson_min_order) {
    r.reason = "observed order " + num3(p) + " below " + num3(richardson_min_order) + " (values " + num3(q1) + ", " +
               num3(q2) + ", " + num3(q3) + " at h " + num3(h1) + ", " + num3(h2) + ", " + num3(h3) +
               "): the extrapolated limit " + num3(r.limit) + " would lie further from the finest run than the sweep moved";
    return r;
  }
  if (n >= 4) {
    const auto& [h0, q0] = pts[n - 4];
    std::string why0;
    r.order_check = observed_order(h0, h1, h2, q0, q1, q2, why0);
    if (!(std::abs(r.order_check - p) <= 0.3 * std::max(r.order_check, p))) {
      r.reason = "the observed order of the three finest runs, " + num3(p) + ", and of the next coarser three, " +
                 (r.order_check > 0 ? num3(r.order_check) : "none (" + why0 + ")") +
                 ", differ by more than 30 % (not in the asymptotic range)";
      return r;
    }
  }
  if (r.limit == 0.0 || !std::isfinite(r.limit)) {
    r.reason = "the extrapolated limit is zero: no relative error";
    return r;
  }
  r.ok = true;
  return r;
}

// time = offset + factor * estimate, least squares on the relative residual (offset >= 0).
void fit_affine_time(const std::vector<double>& est, const std::vector<double>& sec, GroupModel& g) {
  // minimise sum ((t0 + a e_i - t_i) / t_i)^2: normal equations in (t0, a) with weights 1 / t_i^2
  double s00 = 0, s01 = 0, s11 = 0, r0 = 0, r1 = 0;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const double w = 1.0 / (sec[i] * sec[i]);
    s00 += w, s01 += w * est[i], s11 += w * est[i] * est[i], r0 += w * sec[i], r1 += w * est[i] * sec[i];
  }
  const double det = s00 * s11 - s01 * s01;
  double t0 = det != 0 ? (r0 * s11 - r1 * s01) / det : 0.0;
  double a = det != 0 ? (s00 * r1 - s01 * r0) / det : r1 / s11;
  if (!(t0 >= 0) || !(a > 0)) {  // fall back to a pure ratio (or a pure offset)
    t0 = 0.0;
    a = r1 / s11;
  }
  g.time_offset = t0;
  g.time_factor = a;
  g.time_exponent = 1.0;
  double r2 = 0;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const double r = std::log((t0 + a * est[i]) / sec[i]);
    r2 += r * r;
  }
  g.time_log_rms = std::sqrt(r2 / est.size());
}

std::vector<GroupModel> fit_groups(const std::vector<SweepPoint>& points, bool affine_time) {
  std::vector<GroupModel> groups;
  for (const auto& p : points) {
    bool seen = false;
    for (const auto& g : groups) seen = seen || same_group(p, g);
    if (seen) continue;
    GroupModel g;
    g.order = p.order;
    g.single = p.single;
    const auto pts = group_points(points, p.order, p.single);
    g.points = static_cast<int>(pts.size());
    if (pts.empty()) continue;
    const std::size_t k = best_index(pts);
    // the converging part: the coarsest run to the one of least error; finer runs that do not improve on
    // it mark a floor (float round-off, a solver tolerance, a discretisation limit)
    std::vector<double> h, e;
    for (std::size_t i = 0; i <= k; ++i) h.push_back(pts[i].h), e.push_back(pts[i].error);
    g.fit = fit_power_law(h, e);
    g.converges = k >= 1 && g.fit.rate > min_rate;
    if (g.converges) {
      g.floor = k + 1 < pts.size() ? pts[k].error : 0.0;
      for (std::size_t i = 0; i <= k; ++i) g.bound = std::max(g.bound, pts[i].error / std::pow(pts[i].h, g.fit.rate));
    } else {
      g.fit = fit_power_law([&] { std::vector<double> v; for (auto& q : pts) v.push_back(q.h); return v; }(),
                            [&] { std::vector<double> v; for (auto& q : pts) v.push_back(q.error); return v; }());
    }
    // time: the loader's estimate refreshed by the measured CPU times, t = a * estimate^b
    std::vector<double> est, sec;
    for (const auto& q : pts)
      if (q.seconds > 0 && q.estimate > 0) est.push_back(q.estimate), sec.push_back(q.seconds);
    if (affine_time && est.size() >= 2) {
      fit_affine_time(est, sec, g);
    } else if (est.size() >= 2) {
      const PowerLaw t = fit_power_law(est, sec);
      g.time_factor = t.constant;
      g.time_exponent = t.rate;
      g.time_log_rms = t.log_rms;
    } else if (est.size() == 1) {
      g.time_factor = sec[0] / est[0];
    }
    groups.push_back(g);
  }
  std::sort(groups.begin(), groups.end(),
            [](const GroupModel& a, const GroupModel& b) { return a.single != b.single ? !a.single : a.order < b.order; });
  return groups;
}

std::vector<Candidate> predict(const std::vector<SweepPoint>& points, const std::vector<GroupModel>& groups) {
  std::vector<Candidate> out;
  for (const auto& g : groups) {
    const auto pts = group_points(points, g.order, g.single);
    if (pts.empty()) continue;
    const std::size_t k = best_index(pts);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      Candidate c;
      c.point = pts[i];
      c.reference = g.reference;
      if (g.converges) {
        c.predicted_error = std::max(g.bound * std::pow(pts[i].h, g.fit.rate), g.floor);
        c.beyond_floor = i > k;
        if (c.beyond_floor) c.predicted_error = std::max(c.predicted_error, pts[i].error);  // never chosen
      } else {
        // no convergence: at most the largest error measured at this resolution or finer
        double env = 0;
        for (std::size_t j = i; j < pts.size(); ++j) env = std::max(env, pts[j].error);
        c.predicted_error = env;
      }
      c.predicted_seconds =
          pts[i].estimate > 0 ? g.time_offset + g.time_factor * std::pow(pts[i].estimate, g.time_exponent) : pts[i].seconds;
      out.push_back(c);
    }
  }
  return out;
}

Plan choose(const Model& model, double target) {
  Plan plan;
  std::vector<Candidate> usable;
  for (const auto& c : model.candidates)
    if (!c.beyond_floor) usable.push_back(c);
  plan.best_error = INFINITY;
  const Candidate* best = nullptr;
  const Candidate* pick = nullptr;
  for (const auto& c : usable) {
    if (!best || c.predicted_error < best->predicted_error ||
        (c.predicted_error == best->predicted_error && c.predicted_seconds < best->predicted_seconds))
      best = &c;
    if (c.predicted_error <= target && (!pick || c.predicted_seconds < pick->predicted_seconds)) pick = &c;
  }
  if (best) plan.best_error = best->predicted_error;
  // the Pareto front: no other candidate is both as accurate and as fast (and better in one)
  for (const auto& c : usable) {
    bool dominated = false;
    for (const auto& d : usable)
      dominated = dominated || (d.predicted_error <= c.predicted_error && d.predicted_seconds <= c.predicted_seconds &&
                                (d.predicted_error < c.predicted_error || d.predicted_seconds < c.predicted_seconds));
    if (!dominated) plan.pareto.push_back(c);
  }
  std::sort(plan.pareto.begin(), plan.pareto.end(),
            [](const Candidate& a, const Candidate& b) { return a.predicted_seconds < b.predicted_seconds; });
  if (pick) {
    plan.choice = *pick;
    return plan;
  }
  plan.refused = true;
  if (usable.empty() && !model.unusable.empty()) {  // nothing to choose from: say why, not "below"
    plan.reason = "the sweep (" + model.csv.string() + ") gives no error estimate for " + model.quantity_text + ": " +
                  model.unusable;
    return plan;
  }
  std::ostringstream why;
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g", target);
  why << "target " << buf << " is below what the sweep supports for " << model.quantity_text << ": ";
  if (best) {
    std::snprintf(buf, sizeof buf, "%.3g", plan.best_error);
    why << "the best reachable predicted error is " << buf << " (" << describe_candidate(model, *best) << ")";
  } else {
    why << "no usable sweep point";
  }
  std::vector<std::string> limits;
  for (const auto& g : model.groups) {
    std::string name = (g.single ? "float" : "double");
    if (!model.order_name.empty()) {
      std::snprintf(buf, sizeof buf, "%s %g ", model.order_name.c_str(), g.order);
      name = buf + name;
    }
    if (!g.converges) {
      limits.push_back(name + ": the error does not fall with the resolution over the sweep");
    } else if (g.floor > 0) {
      std::snprintf(buf, sizeof buf, "%.3g", g.floor);
      limits.push_back(name + ": stops converging at " + buf + (g.single ? " (float round-off)" : ""));
    }
  }
  if (!limits.empty()) {
    why << "; ";
    for (std::size_t k = 0; k < limits.size(); ++k) why << (k ? "; " : "") << limits[k];
  }
  why << "; finer runs than the sweep's finest are not predicted (no data)";
  plan.reason = why.str();
  return plan;
}

// ---------------------------------------------------------------------------------------------- cases

namespace {

struct QuantitySpec {
  std::string key, column, summary_key, text;
  // the column (and the summary key) is the quantity's value, with no analytic reference: errors against
  // each group's Richardson limit
  bool richardson = false;
};

struct Level {
  double resolution, order;
  bool single;
  std::int64_t steps;
};

// What the plan needs of one case with a committed sweep.
struct Case {
  std::string name, kind, app;
  std::vector<std::string> scenes;  // scene file stems the sweep ran
  std::string csv, sweep_command;
  std::string resolution_column, h_column, order_column, precision_column, time_column, steps_column;
  std::string resolution_name, order_name;
  std::vector<QuantitySpec> quantities;
  // the loader's cost estimate of one run, one thread [s]
  std::function<double(const fs::path& scene, const Level&)> estimate;
  // sets a parsed scene to the level; returns the accuracy preset to run it with
  std::function<std::string(toml::table&, const Level&)> edit;
  std::string dir;  // scenes/<dir>/<stem>.toml
  std::vector<std::pair<std::string, double>> where;  // keep only the sweep rows with these column values
  bool affine_time = false;  // the sweep timed whole processes (start-up included): t = t0 + a * estimate
  std::string reference_note;  // where the error is not against an analytic reference
};

double one_thread(const CostEstimate& c) { return c.seconds * c.rate_threads; }

std::string precision(bool single) { return single ? "float" : "double"; }

void set_accuracy(toml::table& t, const std::string& preset, double factor) {
  if (!t["accuracy"].is_table()) t.insert_or_assign("accuracy", toml::table{});
  t["accuracy"].as_table()->insert_or_assign(preset, factor);
}

// The scene edited to a level, in a temporary file (for the loaders whose cost estimate reads the knob
// from the scene, not from an option); removed when it goes out of scope.
struct EditedScene {
  fs::path file;
  EditedScene(const fs::path& scene, const std::function<std::string(toml::table&, const Level&)>& edit, const Level& l) {
    toml::table t;
    try {
      t = toml::parse_file(scene.string());
    } catch (const toml::parse_error& e) {
      throw PlanError(scene.string() + ": " + std::string(e.description()));
    }
    edit(t, l);
    static int serial = 0;
    file = fs::temp_directory_path() /
           ("polymech_plan_" + std::to_string(::getpid()) + "_" + std::to_string(serial++) + "_" + scene.filename().string());
    std::ofstream(file) << t << "\n";
  }
  ~EditedScene() {
    std::error_code ec;
    fs::remove(file, ec);
  }
};

toml::table& section(toml::table& t, const char* name) {
  if (!t[name].is_table()) t.insert_or_assign(name, toml::table{});
  return *t[name].as_table();
}

// The EFG static crack (tools/plot_efg_accuracy_cost.py): h_min and h_max scaled together, Gauss points per cell.
std::string edit_efg(toml::table& t, const Level& l) {
  auto& d = section(t, "discretization");
  const double h_min = d["h_min"].value<double>().value_or(l.resolution);
  const double h_max = d["h_max"].value<double>().value_or(4 * l.resolution);
  d.insert_or_assign("h_min", l.resolution);
  d.insert_or_assign("h_max", l.resolution * h_max / h_min);
  d.insert_or_assign("gauss", static_cast<int64_t>(l.order));
  return "";  // the scene's default preset, as the sweep ran it
}

// The DEM impacts (bench/sweep_dem_impacts.py): steps per Hertz contact time.
std::string edit_dem(toml::table& t, const Level& l) {
  section(t, "time").insert_or_assign("steps_per_contact", l.resolution);
  return "";  // dem_benchmark has no presets
}

// MPS (point source, crack harmonics): the coarsening as the draft preset's factor; the sweep's steps where it
// sets them (0: the scene's, or the crop's until the burst has passed the probe).
double estimate_mps(const fs::path& f, const Level& l) {
  MpsSceneOptions o;
  o.coarsening = l.resolution;
  o.precision = precision(l.single);
  o.steps = l.steps;
  return one_thread(load_mps_elastic_scene(f, o).cost);
}
std::string edit_draft(toml::table& t, const Level& l) {
  set_accuracy(t, "draft", l.resolution);
  return "draft";
}

// The ISPH floating cylinder (bench/sweep_isph_float.py): spacing = D / across, dt = 0.1 s/m x spacing, no
// snapshots, at the scene's paper preset.
std::string edit_isph(toml::table& t, const Level& l) {
  const double d = section(t, "body")["diameter"].value<double>().value_or(0.1);
  const double spacing = d / l.resolution;
  section(t, "fluid").insert_or_assign("spacing", spacing);
  auto& time = section(t, "time");
  time.insert_or_assign("dt", 0.1 * spacing);
  time.insert_or_assign("snapshot_every", 0.0);
  set_accuracy(t, "paper", 1.0);
  return "paper";
}

// The PD penetration sweep (bench/sweep_pd_penetration --cv 0.3): coarsening, horizon ratio, c_v = 0.3.
std::string edit_pd_penetration(toml::table& t, const Level& l) {
  section(t, "discretization").insert_or_assign("horizon_ratio", l.order);
  section(t, "stabilization").insert_or_assign("c_v", 0.3);
  set_accuracy(t, "draft", l.resolution);
  return "draft";
}

const std::vector<Case>& cases() {
  static const std::vector<Case> c = {
      {"MPS point source",
       "mps_elastic",
       "mps_point_source",
       {"point_source"},
       "docs/figures/mps/mps_point_source.csv",
       "build/release/bench/sweep_mps_point_source --out docs/figures/mps",
       "coarsening",
       "spacing",
       "",
       "is_float",
       "cpu_seconds",
       "steps",
       "coarsening",
       "",
       {{"cp", "cp_rel_error", "cp_relative_error", "P-wave speed (relative error)"},
        {"cs", "cs_rel_error", "cs_relative_error", "S-wave speed (relative error)"}},
       estimate_mps,
       edit_draft,
       "mps",
       {},
       false,
       ""},
      {"Helmholtz FEM",
       "helmholtz",
       "helmholtz",
       {"cube", "duct", "duct_2khz"},
       "docs/figures/helmholtz/helmholtz_{stem}.csv",
       "build/release/bench/sweep_helmholtz --cases {stem} --out docs/figures/helmholtz",
       "elements_x",
       "h",
       "order",
       "is_float",
       "cpu_seconds",
       "",
       "elements along x",
       "order",
       {{"l2", "l2_error", "l2_error", "L2 error of the pressure (eq. (28), relative)"}},
       [](const fs::path& f, const Level& l) {
         const auto base = load_helmholtz_scene(f, {"paper", "", 0, 1.0});
         HelmholtzSceneOptions o;
         o.accuracy = "paper";
         o.precision = precision(l.single);
         o.order = static_cast<int>(l.order);
         const double n = l.resolution;
         for (int d = 0; d < 3; ++d)
           o.elements[d] = std::max(1, static_cast<int>(std::lround(n * base.box_elements[d] / base.box_elements[0])));
         return one_thread(load_helmholtz_scene(f, o).cost);
       },
       [](toml::table& t, const Level& l) {
         t["discretization"].as_table()->insert_or_assign("order", static_cast<int64_t>(l.order));
         auto* mesh = t["mesh"].as_table();
         auto* e = (*mesh)["elements"].as_array();
         std::vector<double> base;
         for (auto& v : *e) base.push_back(v.value<double>().value_or(1.0));
         toml::array ne;
         for (double b : base) ne.push_back(static_cast<int64_t>(std::max(1L, std::lround(l.resolution * b / base[0]))));
         mesh->insert_or_assign("elements", ne);
         // the sweep's float runs stop at 1e-6 (float cannot reach the paper's 1e-10; sweep_helmholtz)
         if (l.single) t["solver"].as_table()->insert_or_assign("tolerance", 1e-6);
         set_accuracy(t, "paper", 1.0);
         return std::string("paper");
       },
       "helmholtz",
       {},
       false,
       ""},
      {"PD tension",
       "nosb_pd",
       "pd_tension",
       {"tension_lattice", "tension_conforming", "tension_jittered", "tension_jittered_hourglass"},
       "docs/figures/pd/{stem}.csv",
       "build/release/bench/sweep_pd_tension --threads 1 --scene scenes/pd/{stem}.toml --name {stem} --coarsening 4,2 "
       "--horizon-ratio 2,3,4 --precision double,float --out docs/figures/pd (--coarsening 4,2,1 for tension_jittered_hourglass)",
       "coarsening",
       "spacing",
       "horizon_ratio",
       "is_float",
       "cpu_seconds|wall_seconds",
       "",
       "coarsening",
       "horizon ratio",
       {{"modulus", "modulus_relative_error", "relative_error", "Young's modulus (relative error)"}},
       [](const fs::path& f, const Level& l) {
         NosbPdSceneOptions o;
         o.coarsening = l.resolution;
         o.precision = precision(l.single);
         o.horizon_ratio = l.order;
         return one_thread(load_nosb_pd_scene(f, o).cost);
       },
       [](toml::table& t, const Level& l) {
         t["discretization"].as_table()->insert_or_assign("horizon_ratio", l.order);
         set_accuracy(t, "draft", l.resolution);
         return std::string("draft");
       },
       "pd",
       {},
       false,
       ""},
      {"EFG static crack",
       "efg",
       "efg",
       {"edge_crack_static"},
       "docs/figures/efg/accuracy_cost.csv",
       "/usr/bin/python3 tools/plot_efg_accuracy_cost.py --app build/release/bin/efg --out docs/figures/efg",
       "h_min_m",
       "h_min_m",
       "gauss",
       "is_float",
       "wall_seconds",
       "",
       "h_min [m]",
       "Gauss points per cell side",
       {{"kI", "sif_error", "sif_error", "K_I, mean of the J paths (relative error against the handbook)"}},
       [](const fs::path& f, const Level& l) {
         const EditedScene e(f, edit_efg, l);
         return one_thread(load_efg_scene(e.file, {"", precision(l.single)}).cost);
       },
       edit_efg,
       "efg",
       {{"support_factor", 1.5}},
       false,
       ""},
      {"DEM impact",
       "dem",
       "dem_benchmark",
       {"chung_ooi_test1"},
       "docs/figures/dem/impacts_accuracy_cost.csv",
       "/usr/bin/python3 bench/sweep_dem_impacts.py --app build/release/bin/dem_benchmark --out docs/figures/dem",
       "steps_per_contact",
       "",  // h = 1 / steps per contact (the time step over the contact time)
       "",
       "precision_bits",
       "test1_cpu_seconds",
       "",
       "steps per contact",
       "",
       {{"force", "test1_max_force_error", "test1_max_force_error",
         "largest contact force, two spheres head on (relative error against Hertz)"}},
       [](const fs::path& f, const Level& l) {
         const EditedScene e(f, edit_dem, l);
         return one_thread(load_dem_scene(e.file, {"", precision(l.single)}).cost);
       },
       edit_dem,
       "dem",
       {},
       true,
       ""},
      {"MPS crack harmonics",
       "mps_elastic",
       "mps_harmonics",
       {"crack_p_wave_cropped"},
       "docs/figures/mps/{stem}.csv",
       "build/release/bench/sweep_mps_harmonics --scene scenes/mps/{stem}.toml --coarsening 4,2,1 --precision double,float "
       "--threads 1 --out docs/figures/mps",
       "coarsening",
       "spacing",
       "",
       "is_float",
       "cpu_seconds",
       "",
       "coarsening",
       "",
       {{"r3", "crack_r3", "ratios_crack/2",
         "third-harmonic ratio A3/A1 at probe A behind the crack (relative error against the Richardson limit)", true},
        {"r2", "crack_r2", "ratios_crack/1",
         "second-harmonic ratio A2/A1 at probe A behind the crack (relative error against the Richardson limit)", true},
        {"r4", "crack_r4", "ratios_crack/3",
         "fourth-harmonic ratio A4/A1 at probe A behind the crack (relative error against the Richardson limit)", true},
        {"r5", "crack_r5", "ratios_crack/4",
         "fifth-harmonic ratio A5/A1 at probe A behind the crack (relative error against the Richardson limit)", true}},
       estimate_mps,
       edit_draft,
       "mps",
       {},
       false,
       ""},
      {"ISPH floating cylinder",
       "isph",
       "isph",
       {"floating_cylinder_small_divergence"},
       "docs/figures/isph/float_accuracy_cost_precision.csv",
       "/usr/bin/python3 bench/sweep_isph_float.py --app build/release/bin/isph --scene "
       "scenes/isph/floating_cylinder_small_divergence.toml --precision double|float (the two sweep.csv concatenated)",
       "across",
       "spacing",
       "",
       "precision_bits",
       "cpu_seconds",
       "",
       "particles across the cylinder",
       "",
       {{"draft", "error_volume", "draft_relative_error",
         "equilibrium draft of a cylinder of density ratio 0.8 (relative error against Archimedes)"}},
       [](const fs::path& f, const Level& l) {
         const EditedScene e(f, edit_isph, l);
         return one_thread(load_isph_scene(e.file, {"paper", precision(l.single)}).cost);
       },
       edit_isph,
       "isph",
       {},
       true,  // the sweep timed whole processes
       ""},
      {"PD penetration",
       "nosb_pd",
       "pd_penetration",
       {"penetration_303"},
       "docs/figures/pd/accuracy_cost_penetration.csv",
       "build/release/bench/sweep_pd_penetration --threads 1 --coarsening 4,2,1 --precision double,float "
       "--horizon-ratio 2,3,4 --cv 0.3 --name accuracy_cost_penetration (docs/VALIDATION.md, PD accuracy against cost)",
       "coarsening",
       "spacing",
       "horizon_ratio",
       "is_float",
       "wall_seconds",
       "",
       "coarsening",
       "horizon ratio",
       {{"residual_velocity", "residual_velocity", "residual_velocity",
         "residual velocity of the projectile at 303.5 m/s, c_v = 0.3 (relative error against the Richardson limit)", true}},
       [](const fs::path& f, const Level& l) {
         const EditedScene e(f, edit_pd_penetration, l);
         NosbPdSceneOptions o;
         o.coarsening = l.resolution;
         o.precision = precision(l.single);
         o.horizon_ratio = l.order;
         return one_thread(load_nosb_pd_scene(e.file, o).cost);
       },
       edit_pd_penetration,
       "pd",
       {{"c_v", 0.3}},
       false,
       ""},
  };
  return c;
}

std::string scene_dir(const Case& cs) {
  return !cs.dir.empty() ? cs.dir : cs.kind == "nosb_pd" ? "pd" : cs.kind == "mps_elastic" ? "mps" : cs.kind;
}

std::string expand(std::string s, const std::string& stem) {
  for (auto p = s.find("{stem}"); p != std::string::npos; p = s.find("{stem}")) s.replace(p, 6, stem);
  return s;
}

std::string scene_kind(const fs::path& scene) {
  const Scene s = Scene::load(scene);
  return s.root().table("model").string("kind");
}

const Case* find_case(const std::string& kind, const std::string& stem) {
  for (const auto& c : cases())
    if (c.kind == kind && std::find(c.scenes.begin(), c.scenes.end(), stem) != c.scenes.end()) return &c;
  return nullptr;
}

// A CSV of text cells (the overhead table names apps and scenes).
struct TextTable {
  std::vector<std::vector<std::string>> rows;
};
TextTable read_csv_text(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw PlanError(file.string() + ": cannot read");
  TextTable t;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    t.rows.push_back(cells);
  }
  return t;
}

Model model_of(const Case& cs, const fs::path& scene, const std::string& stem, const fs::path& root, const std::string& quantity,
               bool with_overhead = true) {
  Model m;
  m.method = cs.name;
  m.app = cs.app;
  const QuantitySpec* q = nullptr;
  std::string keys;
  for (const auto& qs : cs.quantities) {
    keys += (keys.empty() ? "" : ", ") + qs.key;
    if (qs.key == quantity || (quantity.empty() && !q)) q = &qs;
  }
  if (!q) throw PlanError("--quantity " + quantity + ": not a quantity of " + cs.name + "; allowed: " + keys);
  m.quantity = q->key;
  m.quantity_text = q->text;
  m.summary_key = q->summary_key;
  m.resolution_name = cs.resolution_name;
  m.order_name = cs.order_name;
  m.csv = expand(cs.csv, stem);
  m.sweep_command = expand(cs.sweep_command, stem);
  const Table t = read_csv(root / m.csv);
  auto col = [&](const std::string& name) {
    if (name.empty()) return -1;
    const int k = t.column(name);
    if (k < 0) throw PlanError((root / m.csv).string() + ": no column '" + name + "'");
    return k;
  };
  // "a|b": the first of the columns the CSV has (CPU seconds where the sweep records them, else wall seconds)
  auto first_col = [&](const std::string& names) {
    std::stringstream ss(names);
    std::string name;
    while (std::getline(ss, name, '|'))
      if (t.column(name) >= 0) return t.column(name);
    return col(names);
  };
  const int res = col(cs.resolution_column), h = col(cs.h_column), ord = col(cs.order_column),
            prec = col(cs.precision_column), tm = first_col(cs.time_column), st = col(cs.steps_column), err = col(q->column);
  const int status = t.column("status");  // Helmholtz: 0 = converged
  std::vector<std::pair<int, double>> where;
  for (const auto& [name, value] : cs.where) where.emplace_back(col(name), value);
  const bool bits = cs.precision_column == "precision_bits";  // 32 / 64 (else a 0/1 is_float)
  std::vector<SweepPoint> pts;
  for (const auto& r : t.rows) {
    if (status >= 0 && r[status] != 0) continue;
    bool keep = true;
    for (const auto& [k, v] : where) keep = keep && r[k] == v;
    if (!keep) continue;
    SweepPoint p;
    p.resolution = r[res];
    p.h = h >= 0 ? r[h] : 1.0 / r[res];
    p.order = ord >= 0 ? r[ord] : 0.0;
    p.single = prec >= 0 && (bits ? r[prec] == 32 : r[prec] != 0);
    p.error = q->richardson ? r[err] : std::abs(r[err]);  // Richardson: the value, made an error below
    p.seconds = r[tm];
    p.steps = st >= 0 ? static_cast<std::int64_t>(r[st]) : 0;
    if (!std::isfinite(p.error)) continue;
    p.estimate = cs.estimate(scene, {p.resolution, p.order, p.single, p.steps});
    pts.push_back(p);
  }
  if (pts.empty()) throw PlanError((root / m.csv).string() + ": no sweep point with a finite " + q->column);
  m.reference_note = cs.reference_note;
  std::vector<std::pair<std::pair<double, bool>, Richardson>> limits;  // (order, single) -> its extrapolation
  if (q->richardson) {
    // no analytic reference: each (order, precision) group's errors against its own Richardson limit;
    // groups where Richardson is not usable are left out, with the reason
    m.richardson = true;
    std::vector<SweepPoint> kept;
    std::string notes;
    for (const auto& p : pts) {
      bool seen = false;
      for (const auto& l : limits) seen = seen || (l.first.first == p.order && l.first.second == p.single);
      if (seen) continue;
      std::vector<double> hs, qs;
      for (const auto& o : pts)
        if (o.order == p.order && o.single == p.single) hs.push_back(o.h), qs.push_back(o.error);
      limits.push_back({{p.order, p.single}, richardson(hs, qs)});
    }
    // a float group is measured against the double group's limit of the same order where that is usable (its
    // own limit would hide what float's rounding adds to the discretisation error)
    for (auto& [key, r] : limits)
      if (key.second && r.ok)
        for (const auto& [dkey, d] : limits)
          if (!dkey.second && dkey.first == key.first && d.ok) r.limit = d.limit, r.reason = "the double limit";
    for (const auto& [key, r] : limits) {
      std::string name = key.second ? "float" : "double";
      if (!cs.order_name.empty()) name = cs.order_name + " " + num3(key.first) + " " + name;
      if (r.ok) {
        notes += (notes.empty() ? "" : "; ") + name + ": observed order " + num3(r.order) +
                 (r.reason.empty() ? ", limit " : ", errors against the double limit ") + num3(r.limit);
        for (auto p : pts)
          if (p.order == key.first && p.single == key.second) {
            p.error = std::abs(p.error - r.limit) / std::abs(r.limit);
            kept.push_back(p);
          }
      } else {
        m.unusable += (m.unusable.empty() ? "" : "; ") + name + ": " + r.reason;
      }
    }
    m.reference_note = "no analytic reference; errors against the Richardson limit of each group's three finest runs (" +
                       (notes.empty() ? std::string("none usable") : notes) +
                       "); the finest run's error is an estimate, not a measurement";
    pts = kept;
    if (!pts.empty() && !m.unusable.empty()) {  // the plan chooses among the usable groups; the others are named
      m.reference_note += "; left out: " + m.unusable;
      m.unusable.clear();
    }
  }
  m.groups = fit_groups(pts, cs.affine_time);
  for (auto& g : m.groups)
    for (const auto& [key, r] : limits)
      if (r.ok && key.first == g.order && key.second == g.single) g.reference = r.limit, g.reference_order = r.order;
  m.candidates = predict(pts, m.groups);
  if (with_overhead) {
    // the app's fixed cost, measured against this model by `polymech plan --measure-overhead`
    const fs::path oh = root / overhead_csv();
    if (fs::exists(oh)) {
      // per app (start-up and output are the app's): the row whose cheapest run the model times least,
      // so the sweep's own timing noise (wall times on a shared machine) disturbs it least
      const TextTable o = read_csv_text(oh);
      double least = INFINITY;
      for (const auto& r : o.rows)
        if (r.size() >= 7 && r[0] == cs.app) {
          const double model_seconds = std::strtod(r[4].c_str(), nullptr);
          if (model_seconds < least) {
            least = model_seconds;
            m.overhead_seconds = std::max(0.0, std::strtod(r[6].c_str(), nullptr));
            m.overhead_source = overhead_csv() + std::string(", ") + r[1];
          }
        }
    }
    for (auto& c : m.candidates) c.predicted_seconds += m.overhead_seconds;
  }
  return m;
}

std::string number(double x) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

}  // namespace

fs::path source_dir(const fs::path& scene) {
  if (const char* s = std::getenv("POLYMECH_SOURCE_DIR"); s && *s && fs::exists(fs::path(s) / "docs" / "figures")) return s;
  for (fs::path base : {fs::absolute(scene).parent_path(), fs::current_path()})
    for (fs::path p = base; !p.empty(); p = p.parent_path()) {
      if (fs::exists(p / "docs" / "figures")) return p;
      if (p == p.parent_path()) break;
    }
  throw PlanError("cannot find the sweep data (docs/figures) above " + scene.string() +
                  " or the working folder; set POLYMECH_SOURCE_DIR to the source folder");
}

std::vector<std::string> planned_cases() {
  std::vector<std::string> out;
  for (const auto& c : cases()) {
    std::string s = c.name + " (kind " + c.kind + ", app " + c.app + "; scenes:";
    for (const auto& n : c.scenes) s += " " + n;
    out.push_back(s + ")");
  }
  return out;
}

Model build_model(const fs::path& scene, const std::string& quantity, bool with_overhead) {
  const std::string kind = scene_kind(scene);
  const std::string stem = scene.stem().string();
  const Case* cs = find_case(kind, stem);
  if (!cs) {
    std::string known;
    for (const auto& c : planned_cases()) known += "\n  " + c;
    throw PlanError(scene.string() + ": no accuracy-cost sweep data for this scene (kind '" + kind +
                    "'), so no error model to plan from; scenes with sweep data:" + known);
  }
  return model_of(*cs, scene, stem, source_dir(scene), quantity, with_overhead);
}

std::vector<fs::path> overhead_scenes(const fs::path& root) {
  std::vector<fs::path> out;
  for (const auto& cs : cases())
    for (const auto& stem : cs.scenes) {
      const fs::path scene = root / "scenes" / scene_dir(cs) / (stem + ".toml");
      if (fs::exists(root / expand(cs.csv, stem)) && fs::exists(scene)) out.push_back(scene);
    }
  return out;
}

std::string fit_report(const fs::path& root) {
  std::ostringstream s;
  s << "| case | quantity | " << "order | precision | points | rate | constant | log rms | bound | floor | time factor | "
       "time exponent | time log rms | time offset | reference |\n";
  s << "| --- | --- | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- |\n";
  for (const auto& cs : cases())
    for (const auto& stem : cs.scenes) {
      const fs::path scene = root / "scenes" / scene_dir(cs) / (stem + ".toml");
      if (!fs::exists(root / expand(cs.csv, stem)) || !fs::exists(scene)) continue;
      for (const auto& q : cs.quantities) {
        const Model m = model_of(cs, scene, stem, root, q.key);
        if (m.groups.empty() && !m.unusable.empty())
          s << "| " << cs.name << " `" << stem << "` | " << q.key << " | - | - | - | Richardson not usable: " << m.unusable
            << " | | | | | | | | | Richardson |\n";
        for (const auto& g : m.groups)
          s << "| " << cs.name << " `" << stem << "` | " << q.key << " | " << (m.order_name.empty() ? "-" : number(g.order))
            << " | " << (g.single ? "float" : "double") << " | " << g.points << " | "
            << (g.converges ? number(g.fit.rate) : "no convergence") << " | " << number(g.fit.constant) << " | "
            << number(g.fit.log_rms) << " | " << (g.converges ? number(g.bound) : "envelope") << " | "
            << (g.floor > 0 ? number(g.floor) : "-") << " | " << number(g.time_factor) << " | " << number(g.time_exponent) << " | " << number(g.time_log_rms)
            << " | " << (g.time_offset > 0 ? number(g.time_offset) : "-") << " | "
            << (std::isfinite(g.reference) ? "Richardson " + number(g.reference) + " (p " + number(g.reference_order) + ")"
                                           : std::string("analytic"))
            << " |\n";
      }
    }
  return s.str();
}

std::vector<std::string> run_arguments(const Model& model, const fs::path& scene, const Candidate& c, const fs::path& out,
                                       int threads) {
  const Case* cs = nullptr;
  for (const auto& k : cases())
    if (k.name == model.method) cs = &k;
  if (!cs) throw PlanError("no case " + model.method);
  toml::table t;
  try {
    t = toml::parse_file(scene.string());
  } catch (const toml::parse_error& e) {
    throw PlanError(scene.string() + ": " + std::string(e.description()));
  }
  const Level l{c.point.resolution, c.point.order, c.point.single, c.point.steps};
  const std::string preset = cs->edit(t, l);
  fs::create_directories(out);
  const fs::path planned = out / "plan_scene.toml";
  {
    std::ofstream f(planned);
    f << "# " << scene.string() << " as planned by `polymech plan` (" << describe_candidate(model, c) << ")\n" << t << "\n";
    if (!f) throw PlanError(planned.string() + ": cannot write");
  }
  std::vector<std::string> a = {"--scene", planned.string(), "--out", out.string(), "--precision", precision(c.point.single),
                                "--threads", std::to_string(threads), "--quiet"};
  if (!preset.empty()) a.insert(a.begin() + 4, {"--accuracy", preset});
  if (c.point.steps > 0) a.insert(a.end(), {"--steps", std::to_string(c.point.steps)});
  return a;
}

std::string describe_candidate(const Model& model, const Candidate& c) {
  std::ostringstream s;
  s << model.resolution_name << " " << number(c.point.resolution);
  if (!model.order_name.empty()) s << ", " << model.order_name << " " << number(c.point.order);
  s << ", " << precision(c.point.single);
  if (c.point.steps > 0) s << ", " << c.point.steps << " steps";
  return s.str();
}

std::string describe_plan(const Model& model, const Plan& plan, double target) {
  std::ostringstream s;
  s << "[plan] " << model.method << ": " << model.quantity_text << ", target " << number(target) << "\n";
  s << "  error model: fitted to " << model.csv.string() << " (" << model.sweep_command << ")\n";
  s << "  time model: a * (the scene loader's cost estimate)^b fitted to the sweep's measured times, one thread";
  if (model.overhead_seconds > 0)
    s << ", plus the app's fixed cost " << number(model.overhead_seconds) << " s (" << model.overhead_source
      << ", polymech plan --measure-overhead)";
  s << "\n";
  if (!model.reference_note.empty()) s << "  reference: " << model.reference_note << "\n";
  if (!plan.refused) {
    s << "  choice: " << describe_candidate(model, plan.choice) << "\n";
    s << "  predicted error " << number(plan.choice.predicted_error) << " (measured in the sweep "
      << number(plan.choice.point.error) << "), predicted time " << number(plan.choice.predicted_seconds)
      << " s (measured in the sweep " << number(plan.choice.point.seconds) << " s)\n";
  } else {
    s << "  refused: " << plan.reason << "\n";
  }
  if (plan.pareto.empty()) return s.str();
  s << "  Pareto front (" << plan.pareto.size()
    << " points; predicted error against predicted time; * chosen, x misses the target; nearest 9 shown):\n";
  s << "    " << (model.order_name.empty() ? "" : model.order_name + " / ") << "precision / " << model.resolution_name
    << " : predicted error, predicted s\n";
  // at most four points on either side of the choice (or of the best reachable error when refused)
  std::size_t centre = plan.pareto.empty() ? 0 : plan.pareto.size() - 1;
  for (std::size_t k = 0; k < plan.pareto.size(); ++k) {
    const auto& c = plan.pareto[k];
    if (!plan.refused && c.point.resolution == plan.choice.point.resolution && c.point.order == plan.choice.point.order &&
        c.point.single == plan.choice.point.single)
      centre = k;
  }
  for (std::size_t k = 0; k < plan.pareto.size(); ++k) {
    if (k + 4 < centre || k > centre + 4) continue;
    const auto& c = plan.pareto[k];
    const bool chosen = !plan.refused && c.point.resolution == plan.choice.point.resolution &&
                        c.point.order == plan.choice.point.order && c.point.single == plan.choice.point.single;
    s << "    " << (chosen ? "* " : c.predicted_error > target ? "x " : "  ") << describe_candidate(model, c) << " : "
      << number(c.predicted_error) << ", " << number(c.predicted_seconds) << "\n";
  }
  return s.str();
}

}  // namespace polymech::io::plan
