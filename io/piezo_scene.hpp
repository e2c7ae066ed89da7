// Scene files of the piezoelectric harvester (issue 35; seed 002 paper 1): scenes/piezo/*.toml -> a validated
// piezo::HarvesterSetup (models/piezo/harvester_setup.hpp) that apps/piezo_harvester runs. SI units.
//
//   [model]      kind = "piezo", effects = [] (the model has none), precision = "double" (the sparse direct
//                solves are double; "float" is refused)
//   [beam]       length, width (m; in 2D the width multiplies every integral), dim = 2 | 3, plane = "stress" |
//                "strain" (2D), conducting_host (an elastic layer is a grounded conductor, paper 1 eq. (7);
//                default true), support = "clamped" | "free"
//   [[beam.layers]]  bottom to top: name, thickness (m), material = "pzt5a" | "pvdf" | "brass", poling = +1 | -1
//                (piezoelectric layers), cells (through the thickness, default 1)
//   [[electrodes]]   name, surface = "bottom" | "top" | "interface K", kind = "floating" | "grounded" |
//                "prescribed", potential (V, prescribed only)
//   [mesh]       order 1..4, cells_length, cells_width (3D)
//   [circuit]    resistors = [{ from, to, ohm }, ...] (electrode names or "ground"; the first is the load)
//   [damping]    zeta (stiffness-proportional Rayleigh at the FE short-circuit frequency) or alpha, beta
//   [analysis]   kind = "static" | "harmonic" | "transient";
//                harmonic: loads (ohm, a list) or load_range = [lo, hi] + load_points (log-spaced), points,
//                  fmin, fmax (Hz; default 0.9 f_sc .. 1.1 f_oc of the FE model), base_acceleration
//                transient: frequency ("resonance" = the FE short-circuit frequency, or Hz), base_acceleration
//                  (m/s^2, default 9.81: a_b = A sin(w t)), periods, steps_per_period, scheme = "monolithic" |
//                  "partitioned", average_periods (default 2), sample_every (steps between series rows)
//   [accuracy]   the presets (default "paper"): draft x4, standard x2, paper x1 divide the cell counts of [mesh]
//                and [[beam.layers]] (at least 1) and analysis.points (at least 11); not steps_per_period (at
//                resonance the time step's period error detunes the drive: it must stay well below zeta)
//
// Every problem is a SceneError naming the file, line, key and what is allowed; what the finite-element beam
// would refuse (an electrode on the grounded host, two electrodes on one surface, a surface that does not
// exist) is refused here, at its key. Host-only and free of Kokkos.
#pragma once

#include <filesystem>

#include "io/cost.hpp"
#include "io/scene.hpp"
#include "piezo/harvester_setup.hpp"

namespace polymech::io {

struct PiezoScene {
  SceneHeader header;
  piezo::HarvesterSetup config;
  double unknowns = 0.0;  // of the FE beam, closed form (harvester_unknowns)
  CostEstimate cost;
};

// What a run of `s` costs: the factorisations and solves of its analysis on a beam of `unknowns` unknowns.
CostEstimate piezo_cost(const piezo::HarvesterSetup& s, double unknowns);

PiezoScene load_piezo_scene(const std::filesystem::path& file, const SceneOptions& options = {});

}  // namespace polymech::io
