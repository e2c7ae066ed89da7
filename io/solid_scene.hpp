// Scene files of the finite-element solid model (issue 34; seed 002 paper 5): scenes/solid/*.toml -> a
// validated micro-cantilever case: the crystal (cubic elastic constants and, with the effect "plasticity",
// Hill plasticity with power-law hardening, eqs. (1)-(4)), the beam and its support block, the mesh, the
// load-unload path, the Newton options and, optionally, the synthetic inverse study of the paper's section 5.
// Units: um, GPa, mN (1 mN / um^2 = 1 GPa).
//
//   [model]   kind = "solid", effects = ["plasticity"] (or [] for a linear elastic beam), precision
//   [crystal] C11, C12, C44 (GPa; default 8YSZ 401 / 96 / 56); with plasticity: yield_stress (GPa),
//             hardening_exponent n in [0, 1), R12 > 0, hill_form = "yield_stress_ratio" | "as_printed"
//   [beam]    length, width, height, wall, support_length (0: the root clamped), support_width, support_depth,
//             angles (deg from [001] in the (110) plane, default the paper's six), peak_force (mN)
//   [mesh]    order 1..4, h_root (um, at the paper's accuracy), growth, h_beam_max, support_growth, h_support_max
//   [load]    load_increments, unload_increments
//   [newton]  tolerance, max_iterations, line_search, max_cuts, solver = "elastic_pcg" | "direct"
//   [inverse] start = { C11, C12, C44, yield_stress, hardening_exponent, R12 } (the estimator's first guess; the
//             hidden truth is [crystal]), noise (um), seed, experiment_h_root (um, <= mesh.h_root), max_iterations,
//             model_accuracy
//   [accuracy] the presets: draft x4, standard x2, paper x1 times every cell size of [mesh] and experiment_h_root
//
// Every problem is a SceneError naming the file, line, key and what is allowed. The loader counts the mesh's
// cells and DoFs in closed form (the lattice of models/solid/micro_cantilever.hpp) for the cost estimate, so
// nothing is allocated. Host-only and free of Kokkos, like the rest of io/: the app turns these plain values
// into solid::CurveSpec and materials::CubicHillParameters.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "io/cost.hpp"
#include "io/scene.hpp"

namespace polymech::io {

struct SolidCrystal {
  double C11 = 401.0, C12 = 96.0, C44 = 56.0;  // GPa
  double yield_stress = 0.0;                   // GPa (plasticity only)
  double hardening_exponent = 0.0;
  double R12 = 1.0;
  std::string hill_form = "yield_stress_ratio";  // or "as_printed"
};

struct SolidBeam {
  double length = 12.0, width = 2.5, height = 1.5, wall = 0.75;  // um
  double support_length = 6.0, support_width = 20.0, support_depth = 12.0;
  std::vector<double> angles;  // deg
  double peak_force = 0.25;    // mN
};

struct SolidMesh {
  int order = 2;
  double h_root = 0.2, growth = 1.2, h_beam_max = 1.0, support_growth = 1.5, h_support_max = 3.0;  // um, after the preset
};

struct SolidNewton {
  double tolerance = 1e-8;
  int max_iterations = 25;
  bool line_search = true;
  int max_cuts = 10;
  std::string solver = "two_level_pcg";  // or "elastic_pcg", "direct" (models/solid/elastoplastic.hpp)
  double forcing = 0.1;                  // inexact Newton (0: every CG to 1e-10)
};

// The mesh's size in closed form.
struct SolidMeshSize {
  double cells = 0.0, nodes = 0.0, dofs = 0.0;
  double points = 0.0;  // quadrature points ((order + 1)^3 per cell)
};

struct SolidInverse {
  SolidCrystal start;            // the estimator's first guess (hill_form: the crystal's)
  double noise = 0.005;          // um, standard deviation of the measured deflections
  std::uint32_t seed = 1;
  double experiment_h_root = 0;  // um, after the preset (the experiment's mesh: [mesh] with this h_root)
  int max_iterations = 30;       // Levenberg-Marquardt iterations
  double model_accuracy = 0;     // relative accuracy of a forward run (default: newton.tolerance)
  SolidMeshSize experiment_size;
};

struct SolidScene {
  SceneHeader header;
  bool plasticity = false;  // model.effects has "plasticity"
  SolidCrystal crystal;     // with an [inverse] table: the hidden truth of the synthetic experiment
  SolidBeam beam;
  SolidMesh mesh;
  int load_increments = 8, unload_increments = 4;
  SolidNewton newton;
  std::optional<SolidInverse> inverse;
  SolidMeshSize size;
  CostEstimate cost;          // the load-unload curves at every angle
  CostEstimate inverse_cost;  // the inverse study (when [inverse] is given)
};

// Cells, nodes and DoFs of the micro-cantilever lattice (beam + support block) for `mesh` (its h_root
// replaced by h_root when > 0).
SolidMeshSize solid_mesh_size(const SolidBeam& beam, const SolidMesh& mesh, double h_root = 0.0);

// Predicted time and memory of `curves` load-unload curves of (load + unload) increments on a mesh of `size`.
CostEstimate solid_cost(const SolidMeshSize& size, int order, bool plasticity, bool single, double curves, int increments,
                        const std::string& solver = "two_level_pcg");

// The cost of running scene `s` at `angles` angles: its load-unload curves, or (inverse) its inverse study.
CostEstimate solid_scene_cost(const SolidScene& s, std::size_t angles, bool inverse);

SolidScene load_solid_scene(const std::filesystem::path& file, const SceneOptions& options = {});

// Cook's membrane (issue 34's verification case; models/solid/cases.hpp): a solid scene with
//   [case]     test = "cook_membrane"
//   [material] youngs_modulus, poisson_ratio (< 0.5), plane = "stress" | "strain"
//   [load]     shear_traction (on the edge x = 48)
//   [mesh]     order 1..4, cells (per side at accuracy "paper"; standard / 2, draft / 4, at least 1)
//   [solver]   kind = "direct" (host sparse LU) | "cg" (matrix-free Jacobi CG), tolerance (cg)
// run by apps/cook_membrane. Linear elastic only: model.effects must be empty.
struct CookScene {
  SceneHeader header;
  int order = 2, cells = 16;
  double young = 70.0, poisson = 1.0 / 3.0, traction = 6250.0;
  std::string plane = "stress";
  std::string solver = "direct";
  double tolerance = 1e-10;
  CostEstimate cost;
};

CookScene load_cook_scene(const std::filesystem::path& file, const SceneOptions& options = {});

// The app of a solid scene, read off its text: "cook_membrane" when [case] test = "cook_membrane", else
// "micro_cantilever".
std::string solid_app(const std::filesystem::path& file);

}  // namespace polymech::io
