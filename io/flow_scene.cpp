#include "io/flow_scene.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace polymech::io {

double flow_channel_cells(int level) { return 260.0 * std::pow(4.0, level); }

double flow_harvester_cells(int level) {
  // counted (apps/turek_hron's summary: 278, 1 100, 4 376, 17 456 cells at levels 0-3): 272 f^2 + 6 f, f = 2^level
  // (the plate's row stays one cell thick)
  const double f = std::ldexp(1.0, level);
  return 272.0 * f * f + 6.0 * f;
}

double flow_harvester_unknowns(int level) {
  // counted by models/flow (NavierStokes2D::unknowns, apps/turek_hron's summary) on levels 0-3
  static const double counted[4] = {2393.0, 9683.0, 38951.0, 156239.0};
  if (level <= 3) return counted[level < 0 ? 0 : level];
  return counted[3] * std::pow(4.0, level - 3);
}

double flow_channel_unknowns(int level) {
  // counted by models/flow (NavierStokes2D::unknowns) on levels 0-3 (notes h-ns-docs)
  static const double counted[4] = {2212.0, 9106.0, 36934.0, 148750.0};
  if (level <= 3) return counted[level < 0 ? 0 : level];
  return counted[3] * std::pow(4.0, level - 3);
}

// Rates measured with bench/sweep_turek_hron_cfd and apps/turek_hron on one thread of the Intel Xeon of
// docs/PERFORMANCE.md: a Newton iteration (the element kernel, the scatter, Eigen's SparseLU and its solves)
// ~0.15 s at 9 106 unknowns, growing like N^1.6 (the factorisation: 91 %); a chord time step (one
// factorisation, ~3 residual passes and solves) ~1.2 such iterations.
// Coupling evaluations until |G(x) - x| <= tol |G(x)| on FSI1, from the measured histories (notes h-fsi1, the
// same at every level): the first residual ~2 |G(x)| (the flag at rest), then IQN-ILS gains ~1.5 decades per
// evaluation (superlinear: 6 at 1e-8), Aitken ~0.8 (11 at 1e-8), constant relaxation the decades of
// max(|1 - omega|, 0.1) per evaluation (the contraction of G itself is far below 1: omega 0.5 halves |r|, 24
// evaluations at 1e-8 measured, 28 predicted). At most max_iterations.
double flow_fsi_evaluations(const FlowSetup& s) {
  const double decades = std::log10(2.0 / s.coupling_tolerance);
  double per = 1.5;
  if (s.coupling_method == "aitken") per = 0.8;
  if (s.coupling_method == "relaxation") per = -std::log10(std::max(std::fabs(1.0 - s.coupling_omega), 0.1));
  return std::min(static_cast<double>(s.coupling_max_iterations), std::max(1.0, std::ceil(decades / per)));
}

CostEstimate flow_cost(const FlowSetup& s, double unknowns) {
  CostEstimate c;
  c.method = "Taylor-Hood Q2/Q1 Navier-Stokes, Turek-Hron CFD" + std::to_string(s.test) + ", level " + std::to_string(s.level) +
             (s.transient ? ", BDF2" : ", steady Newton");
  c.item_name = "unknowns";
  c.items = unknowns;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  const double iteration = 0.15 * std::pow(unknowns / 9106.0, 1.6);
  if (s.transient) {
    c.steps = static_cast<double>(s.steps());
    c.step_name = "time steps";
    c.seconds = c.steps * 1.2 * iteration;
  } else {
    c.steps = s.picard_steps + 6.0;
    c.step_name = "Oseen and Newton iterations (estimate)";
    c.seconds = c.steps * iteration;
  }
  // the LU's fill, ~ N log2 N: resident 67 MB at 9 106 and 400 MB at 36 934 unknowns (CFD3 runs, one thread)
  c.bytes = 30e6 + unknowns * (2e3 + 600.0 * std::log2(std::max(2.0, unknowns)));
  c.rate = "a Newton iteration ~ 0.15 s x (unknowns / 9106)^1.6, a time step ~1.2 of them (1 thread, docs/PERFORMANCE.md)";
  c.rate_threads = 1;
  c.size_keys = {"mesh.level = " + std::to_string(s.scene_level)};
  if (s.transient) {
    c.size_keys.push_back("time.dt = " + format_number(s.dt));
    c.size_keys.push_back("time.end_time = " + format_number(s.end_time));
  }
  if (s.harvester) {
    // The flow-driven harvester (models/fsi/flow_harvester.hpp): per time step ~2 coupling evaluations (IQN-ILS:
    // 1 to 3 measured), each the mesh motion, one chord fluid step and the piezo step. Fitted on the model's runs on
    // one thread of the Intel Xeon of docs/PERFORMANCE.md (bench/sweep_flow_harvester, 2026-11-27): ~0.04 CPU s per
    // step at level 0 (278 cells) and ~0.30 s at level 1 (1 100 cells), 1.0 to 3 evaluations per step: an
    // evaluation ~0.02 s x (cells / 278)^1.47, two per step. Levels above 1 are extrapolated (the LU's growth is
    // steeper there: expect more).
    const double e = 2.0, evaluation = 0.02 * std::pow(flow_harvester_cells(s.level) / 278.0, 1.47);
    c.method = "Taylor-Hood Q2/Q1 ALE Navier-Stokes (BDF2, Smagorinsky " + format_number(s.smagorinsky) +
               ") + PZT-5A/brass bimorph and resistor (Newmark, " + s.scheme + "), the flow-driven harvester, level " +
               std::to_string(s.level) + ", dt " + format_number(s.dt) + ", " + s.coupling_method + " coupling per step";
    c.steps = static_cast<double>(s.steps());
    c.step_name = "time steps (~2 coupling evaluations each)";
    c.seconds = c.steps * e * evaluation;
    c.bytes = 30e6 + 1.45 * unknowns * (2e3 + 600.0 * std::log2(std::max(2.0, unknowns)));
    c.rate = "a time step ~ 2 coupling evaluations x 0.02 s x (cells / 278)^1.47 (1 thread; measured 0.04 s at level 0, 0.30 s at level 1)";
  } else if (s.fsi && s.transient) {
    // FSI2 / FSI3 (models/fsi/turek_hron_fsi_transient.hpp): per time step ~3 coupling evaluations (IQN-ILS
    // reusing 8 steps: 2.7-3.1 on average, docs/VALIDATION.md), each one chord fluid step (one factorisation and
    // its solves, ~1 Newton iteration's cost), and the incremental mesh motion's factorisation (as FSI1's set-up).
    // Measured at level 0 (bench/sweep_turek_hron_fsi, one thread, Intel Xeon): 0.057 s per FSI2 step (3000
    // steps, 170 s), 0.059 s per FSI3 step (5000, 297 s); this gives 0.057 s at level 0 and 0.53 s at level 1
    // (apps/turek_hron, notes h-fsi23: 0.060 s per step for FSI2 at level 0, dt 0.008; 0.48-0.52 s for FSI3 at level 1).
    const double per_step = 3.0 * iteration + 0.08 * std::pow(unknowns / 9106.0, 1.4);
    c.method = "Taylor-Hood Q2/Q1 ALE Navier-Stokes (BDF2) + SVK flag (Newmark), " +
               (s.flap ? std::string("the weakly coupled flap (CSM3's flag in the fluid at rest)") : "Turek-Hron FSI" + std::to_string(s.test)) +
               ", level " + std::to_string(s.level) + ", dt " + format_number(s.dt) + ", " + s.coupling_method + " coupling per step";
    c.steps = static_cast<double>(s.steps());
    c.step_name = "time steps (~3 coupling evaluations each)";
    c.seconds = c.steps * per_step;
    c.bytes = 30e6 + 1.45 * unknowns * (2e3 + 600.0 * std::log2(std::max(2.0, unknowns)));
    c.rate = "a time step ~ 3 x 0.15 s x (unknowns / 9106)^1.6 + the mesh motion's factorisation (1 thread, level 0 measured)";
  } else if (s.fsi) {
    // FSI1 (models/fsi/turek_hron_fsi.hpp): every coupling evaluation solves the fluid from the last state. Measured
    // (notes h-fsi1, levels 0-3): the first solve 3 Oseen + ~5 Newton iterations, ~2 per later evaluation and ~2
    // for the final solve on the converged mesh: 8 + 2 E iterations (IQN-ILS, E = 6: 20 vs 21 counted; Aitken,
    // E = 11: 30 vs 29-30). The set-up adds the mesh motion's factorisation (~0.9 N unknowns): 0.08 s at 9 106
    // unknowns, ~N^1.4 (0.57 s at level 2, 3.7 s at level 3); the solid (<= 4 352 DoFs) is ~0.1 %.
    const double e = flow_fsi_evaluations(s);
    c.method = "Taylor-Hood Q2/Q1 Navier-Stokes on a pseudo-elastically moved mesh + SVK flag, Turek-Hron FSI1, level " +
               std::to_string(s.level) + ", " + s.coupling_method + " coupling";
    c.steps = 8.0 + 2.0 * e;
    c.step_name = "fluid Newton iterations over ~" + format_number(e) + " coupling evaluations (estimate)";
    c.seconds = c.steps * iteration + 0.08 * std::pow(unknowns / 9106.0, 1.4);
    // the fluid's LU (as above) and the mesh motion's (~0.9 N unknowns, two fields of Q2 nodes: sparser): resident
    // 102 MB, 539 MB, 2.62 GB at levels 1-3 measured (apps/turek_hron, one thread) against 160, 625 MB, 2.68 GB here
    c.bytes = 30e6 + 1.45 * unknowns * (2e3 + 600.0 * std::log2(std::max(2.0, unknowns)));
    c.rate = "a fluid Newton iteration ~ 0.15 s x (unknowns / 9106)^1.6, 8 + 2 per coupling evaluation (1 thread, notes h-fsi1)";
  }
  return c;
}

namespace {

// [case] of benchmark = "turek_hron": test = cfd1 .. fsi3, flap
void read_turek_hron_case(const SceneTable& t, FlowSetup& c) {
  const std::string test = t.choice("test", {"cfd1", "cfd2", "cfd3", "fsi1", "fsi2", "fsi3", "flap"});
  c.flap = test == "flap";
  c.fsi = c.flap || test.compare(0, 3, "fsi") == 0;
  c.test = c.flap ? 2 : test[3] - '0';  // fsi1, fsi2, fsi3: the inflow of CFD1, CFD2, CFD3; flap: in time as fsi2
  const double ubar[4] = {0.0, 0.2, 1.0, 2.0};
  c.mean_velocity = t.real("mean_velocity", c.flap ? 0.0 : ubar[c.test], Range{0.0, 100.0, true, false, "m/s (the inflow's mean velocity)"});
  c.density = t.real("density", c.flap ? 1.0 : 1000.0, Range{1e-3, 1e5, false, false, "kg/m^3"});
  c.viscosity = t.real("viscosity", 1e-3, Range{1e-8, 1e3, false, false, "m^2/s (kinematic)"});
  t.finish();
}

// [case] of benchmark = "harvester" (models/fsi/flow_harvester.hpp's FlowHarvesterCase; its defaults the model's)
void read_harvester_case(const SceneTable& t, FlowSetup& c) {
  if (t.has("test"))
    t.fail("test", "applies to benchmark = \"turek_hron\" (cfd1 .. fsi3, flap); the harvester is one case: remove it");
  c.harvester = c.fsi = true;
  c.test = 0;
  c.mean_velocity = t.real("inflow", 0.85, Range{0.0, 100.0, true, false, "m/s (the uniform inflow U)"});
  c.density = t.real("density", 1.204, Range{1e-3, 1e5, false, false, "kg/m^3"});
  c.viscosity = t.real("viscosity", 1.516e-5, Range{1e-8, 1e3, false, false, "m^2/s (kinematic)"});
  c.side = t.real("side", 0.0, Range{0.0, 10.0, false, false, "m (the square cylinder's side D; 0: the lock-in side St U / f_1)"});
  c.plate_length = t.real("plate_length", 0.27, Range{1e-3, 10.0, false, false, "m"});
  c.piezo_thickness = t.real("piezo_thickness", 0.2e-3, Range{1e-6, 0.1, false, false, "m (each PZT-5A layer)"});
  c.host_thickness = t.real("host_thickness", 0.2e-3, Range{1e-6, 0.1, false, false, "m (the brass host)"});
  c.resistance = t.real("resistance", 0.0, Range{0.0, 1e15, false, false, "ohm per metre of span (0: the optimum 1 / (omega_1 C_p))"});
  c.zeta = t.real("zeta", 0.01, Range{0.0, 1.0, false, true, "(the damping ratio at omega_1)"});
  c.smagorinsky = t.real("smagorinsky", 0.1, Range{0.0, 1.0, false, true, "(C_s of the eddy viscosity; 0: none)"});
  c.scheme = t.choice("scheme", {"monolithic", "partitioned"}, "monolithic");
  t.finish();
}

}  // namespace

FlowScene load_flow_scene(const std::filesystem::path& file, const SceneOptions& options) {
  FlowScene out;
  const OpenScene s = open_scene(file, "flow", {}, options.precision);
  out.header = s.header;
  if (out.header.precision != "double")
    s.model.fail("precision", "= \"" + out.header.precision + "\"" +
                                  (options.precision.empty() ? std::string() : std::string(" (--precision)")) +
                                  ": the flow solver assembles and factorises in double precision only; allowed: \"double\"");
  s.model.finish();
  const SceneTable& root = s.root;
  out.header.set_accuracy(read_accuracy(root, options.accuracy, 0.0, "paper"));
  FlowSetup& c = out.config;

  {
    const SceneTable t = root.table("case");
    c.benchmark = t.choice("benchmark", {"turek_hron", "harvester"});
    if (c.benchmark == "harvester") {
      read_harvester_case(t, c);
    } else {
      read_turek_hron_case(t, c);
    }
  }
  c.transient = c.harvester || c.test == 3 || (c.fsi && c.test == 2);  // cfd3, fsi2, fsi3, flap, harvester
  {
    const SceneTable t = root.table("mesh");
    c.scene_level = static_cast<int>(t.integer("level", 0, 6));
    const int coarser = static_cast<int>(std::lround(std::log2(out.header.coarsening)));
    c.level = std::max(0, c.scene_level - coarser);
    if (c.fsi && c.level > 4)
      t.fail("level", "= " + std::to_string(c.scene_level) + (c.level != c.scene_level ? " (level " + std::to_string(c.level) + " at accuracy \"" +
                                                                  out.header.accuracy + "\")" : std::string()) +
                          (c.harvester ? " is out of range: the harvester's channel is built on levels 0..4"
                                       : " is out of range: the fsi tests' flag lattice is built on levels 0..4"));
    // not the benchmark's mesh (its 20 blocks are uniform): the ring's radial planes on the map
    // (exp(a t) - 1) / (exp(a) - 1), a = ring_grading (CFD2 drag -0.29 % at level 1 with a = 1, -2.9 % uniform)
    c.ring_grading = t.real("ring_grading", 0.0, Range{0.0, 6.0, true, true, "(0: uniform; a > 0 grades the ring towards the circle)"});
    if (c.harvester && t.has("ring_grading"))
      t.fail("ring_grading", "applies to the Turek-Hron cfd tests (the ring around the circle); the harvester's channel has its own "
                             "fixed grading: remove it");
    if (c.fsi && c.ring_grading > 0.0)
      t.fail("ring_grading", "applies to cfd1, cfd2 and cfd3; the fsi tests' flag lattice is matched to the uniform mesh: remove it");
    t.finish();
  }
  // fsi2, fsi3: per time step, relative to max(|G(x)|, 1 mm) (bench/sweep_turek_hron_fsi's runs, docs/VALIDATION.md)
  if (c.fsi && c.transient) c.coupling_tolerance = 1e-6;
  if (const auto t = root.optional_table("coupling")) {
    if (!c.fsi)
      t->fail_table("applies to the fsi tests (the elastic flag: test = \"fsi1\", \"fsi2\", \"fsi3\"); cfd1, cfd2 and cfd3 have a rigid "
                    "flag: remove [coupling]");
    c.coupling_method = t->choice("method", {"iqn-ils", "aitken", "relaxation"}, "iqn-ils");
    c.coupling_tolerance = t->real("tolerance", c.coupling_tolerance, Range{1e-14, 1e-2, false, false, "(|G(x) - x| relative to |G(x)|)"});
    c.coupling_max_iterations = static_cast<int>(t->integer("max_iterations", 50, 1, 10000));
    c.coupling_omega = t->real("omega", 0.5, Range{0.0, 2.0, true, true, "(the first step's relaxation factor)"});
    if (c.coupling_method == "iqn-ils") {
      c.coupling_reuse = static_cast<int>(t->integer("reuse", 8, 0, 1000));
    } else if (t->has("reuse")) {
      t->fail("reuse", "applies to method = \"iqn-ils\" (the time steps whose columns the quasi-Newton model keeps)");
    }
    t->finish();
  }
  if (c.harvester) {
    if (const auto t = root.optional_table("solver"))
      t->fail_table("applies to the Turek-Hron cfd tests; the harvester's fluid solves use the coupled model's Newton settings "
                    "(the chord iteration, tolerance 1e-10): remove [solver], set [coupling]");
    c.picard_steps = 0;
  } else if (c.fsi) {
    if (const auto t = root.optional_table("solver"))
      t->fail_table("applies to the cfd tests; the fsi tests' fluid solves use the coupled model's Newton settings (fsi1: 3 "
                    "Oseen steps on the first solve; tolerance 1e-10; fsi2, fsi3: the chord iteration): remove [solver], set [coupling]");
    c.picard_steps = 3;
  } else if (const auto t = root.optional_table("solver")) {
    c.picard_steps = static_cast<int>(t->integer("picard_steps", c.transient ? 0 : 3, 0, 100));
    c.max_iterations = static_cast<int>(t->integer("max_iterations", 25, 1, 1000));
    c.tolerance = t->real("tolerance", 1e-10, Range{1e-15, 1e-2, false, false, "(the Newton update relative to max |u|)"});
    if (c.transient) {
      c.chord = t->boolean("chord", true);
    } else if (t->has("chord")) {
      t->fail("chord", "applies to time steps (test = \"cfd3\"); a steady solve is plain Newton");
    }
    t->finish();
  } else {
    c.picard_steps = c.transient ? 0 : 3;
  }
  const auto time = root.optional_table("time");
  const auto kick = root.optional_table("kick");
  if (!c.transient) {
    if (time) time->fail_table("applies to test = \"cfd3\", \"fsi2\", \"fsi3\" (periodic); cfd1, cfd2 and fsi1 are solved steady: remove [time]");
    if (kick) kick->fail_table("applies to test = \"cfd3\" (periodic); cfd1, cfd2 and fsi1 are solved steady: remove [kick]");
  } else {
    if (!time) root.fail("time", "is missing: " + (c.harvester ? std::string("benchmark = \"harvester\"") : "test = \"" + c.name() + "\"") +
                                      " runs in time and needs [time] dt and end_time (s)");
    if (c.harvester && kick)
      kick->fail_table("applies to test = \"cfd3\" (the rigid flag); the harvester's start has its own transverse gust ([time] gust): remove [kick]");
    if (c.fsi && kick)
      kick->fail_table("applies to test = \"cfd3\" (the rigid flag); in " + c.name() + " the elastic flag's own oscillation breaks the symmetry: remove [kick]");
    c.dt = time->real("dt", Range{1e-6, 1.0, false, false, "s"});
    c.scene_dt = c.dt;
    // fsi2, fsi3: dt at accuracy "paper"; each level the preset takes off the mesh doubles it (scene header)
    if (c.fsi) c.dt = std::ldexp(c.dt, c.scene_level - c.level);
    c.ramp_time = time->real("ramp_time", c.harvester ? 1.0 : 2.0, Range{0.0, 1e4, false, false, "s (0: the full inflow from t = 0)"});
    c.end_time = time->real("end_time", Range{0.0, 1e5, true, false, "s"});
    if (!(c.end_time >= c.dt))
      time->fail("end_time", "= " + format_number(c.end_time) + " is out of range: must be >= time.dt = " + format_number(c.dt) + " s" +
                                 (c.dt != c.scene_dt ? " (" + format_number(c.scene_dt) + " s at accuracy \"paper\", doubled per level off)" : ""));
    if (c.steps() > 100000000LL) time->fail("end_time", "= " + format_number(c.end_time) + " gives more than 1e8 steps of time.dt");
    c.sample_every = static_cast<int>(time->integer("sample_every", 1, 1, 1000000));
    if (c.harvester) {
      // the inflow's transverse gust over the ramp (of U) that breaks the symmetry (models/fsi/flow_harvester.hpp)
      c.gust = time->real("gust", 0.02, Range{0.0, 1.0, true, true, "(of the inflow, over the ramp; 0: none)"});
      c.window = time->real("window", c.end_time / 3.0, Range{0.0, 1e5, false, true, "s (the summary's statistics over the last window)"});
      if (!(c.window <= c.end_time))
        time->fail("window", "= " + format_number(c.window) + " s is out of range: must be in (0, time.end_time = " + format_number(c.end_time) + "] s");
    }
    time->finish();
    if (kick) {
      c.kick_omega = kick->real("omega", Range{-1e3, 1e3, false, false, "rad/s (the peak angular velocity; 0: no kick)"});
      c.kick_start = kick->real("start", std::max(c.ramp_time, 0.0), Range{0.0, 1e5, false, false, "s"});
      c.kick_duration = kick->real("duration", 0.25, Range{0.0, 1e3, true, false, "s"});
      if (!(c.kick_start < c.end_time))
        kick->fail("start", "= " + format_number(c.kick_start) + " s is out of range: must be < time.end_time = " +
                                format_number(c.end_time) + " s");
      kick->finish();
    }
  }
  root.finish();

  if (c.harvester && c.side > 0.0 && !(2.0 * c.piezo_thickness + c.host_thickness < 0.5 * c.side))
    root.table("case").fail("side", "= " + format_number(c.side) + " m is out of range: the plate (2 piezo_thickness + host_thickness = " +
                                        format_number(2.0 * c.piezo_thickness + c.host_thickness) +
                                        " m) must be thinner than half the cylinder's side; allowed: side > " +
                                        format_number(2.0 * (2.0 * c.piezo_thickness + c.host_thickness)) + " m, or 0 (the lock-in side)");
  out.cells = c.harvester ? flow_harvester_cells(c.level) : flow_channel_cells(c.level);
  out.unknowns = c.harvester ? flow_harvester_unknowns(c.level) : flow_channel_unknowns(c.level);
  out.cost = flow_cost(c, out.unknowns);
  check_size(out.cost, root.table("mesh"));
  return out;
}

}  // namespace polymech::io
