// The cases of apps/turek_hron (issue 36), each run from its scene (io/flow_scene.hpp) into summary.json:
// the steady CFD1 and CFD2 and the periodic CFD3 on the fixed mesh (apps/turek_hron/cfd.cpp), the steady FSI1
// with the elastic flag (apps/turek_hron/fsi1.cpp), the periodic FSI2 and FSI3 (apps/turek_hron/fsi_transient.cpp);
// and the summary keys they share.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/app.hpp"
#include "apps/common/restart.hpp"
#include "flow/navier_stokes.hpp"
#include "io/flow_scene.hpp"

namespace polymech::apps {

// A steady case's force in the keys: NAME, NAME_mean (= the value), NAME_amplitude (0) and NAME_error
// (relative to the reference); the CFD and FSI1 summaries share them.
inline void put_steady_force(nlohmann::json& j, const std::string& name, double value, double reference) {
  j[name] = value;
  j[name + "_mean"] = value;
  j[name + "_amplitude"] = 0.0;
  j[name + "_error"] = value / reference - 1.0;
}

// An FSI case's sizes: the mesh level, fluid cells and unknowns, the mesh motion's and the solid's unknowns,
// the wet interface nodes (FSI1 and FSI2/FSI3 summaries; Model: fsi::TurekHronFsi or its transient form).
template <class Model>
void put_fsi_sizes(nlohmann::json& j, const Model& model, int level) {
  j["level"] = level;
  j["cells"] = model.fluid().mesh().element_count();
  j["unknowns"] = model.fluid_unknowns();
  j["mesh_unknowns"] = model.mesh_unknowns();
  j["solid_unknowns"] = model.solid_unknowns();
  j["interface_nodes"] = model.interface_nodes();
}

// The flow solve's CPU split (process seconds per part, the assembly and factorisation counts).
inline nlohmann::json flow_cpu_split(const flow::FlowTimings& t) {
  return {{"element_kernel", t.element_kernel}, {"scatter", t.scatter}, {"lu_factor", t.factor},
          {"lu_solve", t.solve}, {"assemblies", t.assemblies}, {"factorizations", t.factorizations}};
}

// CFD1 and CFD2: the steady Newton solve (Oseen steps first); summary.json with drag and lift against Turek &
// Hron 2006's Table 12, the Newton iterations, the CPU split. Returns 1 when Newton did not converge.
int run_turek_hron_steady(const io::FlowScene& scene, const CommonOptions& opt);

// CFD3: BDF2 from rest with the ramped inflow; forces.csv as the run goes, summary.json with the means,
// amplitudes and frequency over the last lift period (and the period before it). Returns 1 when a step's
// Newton iteration did not converge. Checkpoints and --restart as every time-stepping app (restart.hpp).
int run_turek_hron_transient(const io::FlowScene& scene, const CommonOptions& opt, const RestartOptions& restart);

// Builds fsi::TurekHronFsi at the scene's level, solves the coupled steady state and writes summary.json
// (ux_A, uy_A, drag, lift against Turek & Hron 2006's Table 12, the coupling's evaluations and history, the CPU
// split). Returns 0, or 1 when the coupling (or a fluid or solid solve inside it) stopped without converging;
// summary.json then says why (`reason`).
int run_turek_hron_fsi1(const io::FlowScene& scene, const CommonOptions& opt);

// FSI2 and FSI3: fsi::TurekHronFsiTransient at the scene's level and dt from rest with the ramped inflow; series.csv
// as the run goes, summary.json with ux, uy (point A), drag and lift's mean and amplitude over the last period of
// uy(A) and its frequency against Table 13, the coupling evaluations per step, the CPU split. Returns 1 when the
// coupling (or a fluid or solid solve inside it) stopped; summary.json then says why (`reason`). Checkpoints and
// --restart as every time-stepping app (restart.hpp).
int run_turek_hron_fsi_transient(const io::FlowScene& scene, const CommonOptions& opt, const RestartOptions& restart);

// The flow-driven piezoelectric harvester (seed 002 paper 1 case 2; [case] benchmark = "harvester"):
// fsi::FlowHarvester from rest with the ramped inflow (apps/turek_hron/harvester.cpp); series.csv as the run goes,
// summary.json with the tip, lift, drag, voltage and power statistics over the last `window` seconds against the
// plate's first frequency, the coupling evaluations and circuit solves per step, the CPU split. Returns 1 when the
// coupling or the fluid's Newton iteration stopped; summary.json then says why (`reason`). Checkpoints and
// --restart as every time-stepping app (restart.hpp).
int run_flow_harvester(const io::FlowScene& scene, const CommonOptions& opt, const RestartOptions& restart);

}  // namespace polymech::apps
