// The Turek-Hron FSI1 case of apps/turek_hron (issue 36): the steady elastic flag, run from its scene.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "apps/common/app.hpp"
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

// Builds fsi::TurekHronFsi at the scene's level, solves the coupled steady state and writes summary.json
// (ux_A, uy_A, drag, lift against Turek & Hron 2006's Table 12, the coupling's evaluations and history, the CPU
// split). Returns 0, or 1 when the coupling (or a fluid or solid solve inside it) stopped without converging;
// summary.json then says why (`reason`).
int run_turek_hron_fsi1(const io::FlowScene& scene, const CommonOptions& opt);

}  // namespace polymech::apps
