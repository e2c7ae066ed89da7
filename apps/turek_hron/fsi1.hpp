// The Turek-Hron FSI1 case of apps/turek_hron (issue 36): the steady elastic flag, run from its scene.
#pragma once

#include "apps/common/app.hpp"
#include "io/flow_scene.hpp"

namespace polymech::apps {

// Builds fsi::TurekHronFsi at the scene's level, solves the coupled steady state and writes summary.json
// (ux_A, uy_A, drag, lift against Turek & Hron 2006's Table 12, the coupling's evaluations and history, the CPU
// split). Returns 0, or 1 when the coupling (or a fluid or solid solve inside it) stopped without converging;
// summary.json then says why (`reason`).
int run_turek_hron_fsi1(const io::FlowScene& scene, const CommonOptions& opt);

}  // namespace polymech::apps
