// Scene files of the incompressible flow solver (issue 36; seed 002 paper 1 eqs. (1)-(3) on a fixed mesh):
// scenes/flow/*.toml -> a validated FlowScene that apps/turek_hron runs. SI units.
//
//   [model]     kind = "flow", effects = [] (the model has none), precision = "double" (the sparse direct
//               solves are double; "float" is refused)
//   [case]      benchmark = "turek_hron" (the channel with the cylinder and the rigid flag, Turek & Hron 2006),
//               test = "cfd1" | "cfd2" | "cfd3" | "fsi1" | "fsi2" | "fsi3" (the inflow's mean velocity 0.2, 1, 2,
//               0.2, 1, 2 m/s; cfd1, cfd2 and fsi1 are solved steady, cfd3, fsi2 and fsi3 in time; the fsi tests
//               with the elastic SVK flag of models/fsi/turek_hron_fsi.hpp, its solid parameters the benchmark's:
//               models/fsi/turek_hron_fsi_transient.hpp for fsi2 and fsi3), density (default 1000 kg/m^3),
//               viscosity (kinematic, default 1e-3 m^2/s): the benchmark's values unless changed;
//               test = "flap": the weakly coupled check (issue 36; fsi::flap_case): CSM3's flag (rho_s 1000,
//               mu_s 0.5e6, g = 2) released from rest into the fluid at rest (mean_velocity default 0), density
//               default 1 kg/m^3; run in time like fsi2 ([time], [coupling] as theirs), its period against the
//               same flag's in vacuo
//   [mesh]      level 0..6 at accuracy "paper" (260 x 4^level Q2/Q1 cells); the presets "standard" and "draft"
//               take log2 of their factor (1 and 2 by default) levels off, down to level 0
//   [coupling]  fsi tests only, optional: method = "iqn-ils" (default) | "aitken" | "relaxation", tolerance
//               (|G(x) - x| relative to |G(x)|, default 1e-8 for fsi1; fsi2 and fsi3: relative to
//               max(|G(x)|, 1 mm), default 1e-6 per time step), max_iterations (evaluations of G, default 50;
//               per time step in fsi2 and fsi3), omega (the first step's relaxation factor, the constant one for
//               "relaxation", default 0.5), reuse (iqn-ils only, default 8: time steps whose columns are kept;
//               a steady solve has one)
//   [solver]    cfd tests only (the fsi tests' fluid solves use the coupled model's: Newton to 1e-10, the
//               chord iteration in time):
//               picard_steps (Oseen steps from rest before Newton; default 3 for a steady test, 0 in time),
//               max_iterations (Newton, per solve or step, default 25), tolerance (on the update relative to
//               max |u|, default 1e-10), chord (time steps: keep a step's first factorisation, default true)
//   [time]      cfd3, fsi2 and fsi3: dt (s), end_time (s), ramp_time (s, the inflow's cosine ramp, default 2),
//               sample_every (steps between rows of forces.csv / series.csv, default 1). fsi2 and fsi3: dt is
//               the step at accuracy "paper"; a preset that takes levels off the mesh doubles dt per level
//               (the mesh and the step refined together: draft = level 0 at 4 dt when the scene's level is 2)
//   [kick]      cfd3 only, optional: omega (rad/s, the peak angular velocity of a rigid rotation of the cylinder
//               and flag that breaks the symmetry so shedding starts sooner), start (s, default the ramp's
//               end), duration (s, default 0.25); models/flow/turek_hron.hpp
//   [accuracy]  default = "paper" unless set; the presets' factors as every scene
//
// The flow-driven piezoelectric harvester (seed 002 paper 1 case 2, models/fsi/flow_harvester.hpp; run by
// apps/turek_hron/harvester.cpp): [case] benchmark = "harvester" (no `test` key) with inflow (m/s, default 0.85),
// density (1.204 kg/m^3), viscosity (1.516e-5 m^2/s), side (the square cylinder's D in m; default 0: the lock-in
// side St U / f_1, fsi::lock_in_side), plate_length (0.27 m), piezo_thickness (0.2e-3 m, each PZT-5A layer),
// host_thickness (0.2e-3 m, brass), resistance (ohm per metre of span; default 0: 1 / (omega_1 C_p)), zeta (the
// damping ratio at omega_1, 0.01), smagorinsky (C_s of the eddy viscosity, 0.1; 0: none), scheme = "monolithic"
// (default: piezo-structure and circuit together in each FSI iterate) | "partitioned" (paper 1's Fig. 3: the
// piezo-circuit loop nested in the FSI loop); [mesh] level 0..4 (the harvester channel, 272 x 4^level + 6 x
// 2^level cells) with fsi2's preset rule; [time] dt (at accuracy "paper", doubled per level off), end_time,
// ramp_time (default 1 s), gust (the transverse gust over the ramp, of U; default 0.02), window (s, the summary's
// statistics over the last `window` seconds; default end_time / 3), sample_every; [coupling] as fsi2's
// (tolerance 1e-6 per step relative to max(|G(x)|, 1 mm)). No [solver], [kick].
//
// Every problem is a SceneError naming the file, line, key and what is allowed. Host-only and free of Kokkos.
#pragma once

#include <filesystem>
#include <string>

#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct FlowSetup {
  std::string benchmark = "turek_hron";
  int test = 1;                       // 1, 2, 3: CFD1, CFD2, CFD3
  double mean_velocity = 0.2, density = 1000.0, viscosity = 1e-3;
  int level = 0;                      // after the accuracy preset
  int scene_level = 0;                // as written (accuracy "paper")
  double ring_grading = 0.0;          // [mesh] ring_grading: the ring around the circle graded towards it (0: uniform)
  bool transient = false;             // cfd3
  int picard_steps = 3, max_iterations = 25;
  double tolerance = 1e-10;
  bool chord = true;
  double dt = 0.0, end_time = 0.0, ramp_time = 0.0;
  int sample_every = 1;
  double kick_omega = 0.0, kick_start = 2.0, kick_duration = 0.25;
  bool fsi = false;                   // fsi1, fsi2, fsi3 (test 1, 2, 3: the inflow of CFD1, CFD2, CFD3), flap
  bool flap = false;                  // the weakly coupled flap (fsi, test 2: in time; no inflow by default)
  double scene_dt = 0.0;              // [time] dt as written (fsi2, fsi3: at accuracy "paper"; dt after the preset)
  std::string coupling_method = "iqn-ils";
  double coupling_tolerance = 1e-8, coupling_omega = 0.5;
  int coupling_max_iterations = 50, coupling_reuse = 8;
  // benchmark = "harvester" (fsi and transient set too; test 0): models/fsi/flow_harvester.hpp's FlowHarvesterCase
  bool harvester = false;
  double side = 0.0, plate_length = 0.27, piezo_thickness = 0.2e-3, host_thickness = 0.2e-3;
  double resistance = 0.0, zeta = 0.01, smagorinsky = 0.1, gust = 0.02, window = 0.0;
  std::string scheme = "monolithic";
  std::string name() const {
    if (harvester) return "harvester";
    return flap ? std::string("flap") : (fsi ? "fsi" : "cfd") + std::to_string(test);
  }
  std::int64_t steps() const { return transient ? static_cast<std::int64_t>(end_time / dt + 0.5) : 0; }
};

struct FlowScene {
  SceneHeader header;
  FlowSetup config;
  double cells = 0.0, unknowns = 0.0;  // of the Turek-Hron channel at config.level
  CostEstimate cost;
};

// Cells and free unknowns (two velocity components on the free Q2 nodes, the Q1 pressures) of the Turek-Hron
// channel at `level`: counted on levels 0-3 (models/flow/mesh.hpp), x4 per level above.
double flow_channel_cells(int level);
double flow_channel_unknowns(int level);
// The harvester channel's cells at `level` (models/flow/harvester_mesh.hpp; 272 f^2 + 6 f, f = 2^level, counted on
// levels 0-3) and its free unknowns (counted on levels 0-3, x4 per level above).
double flow_harvester_cells(int level);
double flow_harvester_unknowns(int level);

// What a run costs: the Newton iterations (steady) or the time steps (one factorisation each with the chord
// iteration), each dominated by the sparse LU (docs/PERFORMANCE.md, issue 36); for fsi1 the fluid's Newton
// iterations over the expected coupling evaluations (flow_fsi_evaluations) and the mesh motion's factorisation;
// for fsi2 and fsi3 the time steps, each ~3 coupling evaluations of one chord fluid step and a mesh factorisation.
double flow_fsi_evaluations(const FlowSetup& s);
CostEstimate flow_cost(const FlowSetup& s, double unknowns);

FlowScene load_flow_scene(const std::filesystem::path& file, const SceneOptions& options = {});

}  // namespace polymech::io
