// What a run will cost, estimated by the scene loaders before anything is allocated at full size:
// particles or DoFs, pairs, steps or solver iterations, memory and a predicted wall time from the rates
// measured in docs/PERFORMANCE.md. Apps print it before every run (`--dry-run` prints it and stops), and
// a loader refuses a run whose memory estimate exceeds the memory this machine has available, naming
// the keys that set the run's size. Host-only, free of Kokkos.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "io/scene.hpp"

namespace polymech::io {

struct CostEstimate {
  std::string method;        // "MPS elastic", ...
  std::string item_name;     // "particles" or "DoFs"
  double items = 0.0;        // particles or DoFs
  double max_items = 0.0;    // the most the model can index (0: no limit)
  double pairs = 0.0;        // bonds of the particle methods (0: none)
  double steps = 0.0;        // time steps over all runs, or solver iterations
  std::string step_name;     // "steps" or "COCG iterations (estimate)"
  double bytes = 0.0;        // memory while running
  double seconds = 0.0;      // predicted wall time
  std::string rate;          // the measured rate the prediction uses, and where it is documented
  int rate_threads = 1;      // the threads the rate was measured with (apps scale `seconds` to theirs)
  std::vector<std::string> size_keys;  // "domain.width = 0.05 m", ...: what sets the size
};

// Several lines, "  particles 125 000, bonds ...": what apps print.
std::string describe(const CostEstimate& c);

// Bytes this run may use: $POLYMECH_MEMORY_LIMIT (bytes, or with a suffix K, M, G, T: "512M") if set,
// else MemAvailable of /proc/meminfo; infinity where neither can be read. memory_source() says which.
double available_memory();
std::string memory_source();

// Refuses a run too large for the machine (memory) or for the model's indices (max_items), as a
// SceneError located at the table `at` that lists the size keys and the estimate.
void check_size(const CostEstimate& c, const SceneTable& at);

// Lattice neighbours within `ratio` spacings on a square (dim 2) or cubic (dim 3) lattice: the bonds
// per interior particle of a reference family.
double lattice_neighbours(int dim, double ratio);

// MPS elastic waves (2D): `runs` runs of `steps` steps each (mps_harmonics runs twice).
CostEstimate mps_cost(double particles, double influence_radius, bool rotation, bool single, double steps, int runs);
// NOSB peridynamics: particles, bonds per particle, steps.
// elastic_only: no damage, contact, velocity viscosity or short-range force (the bond pass alone is twice as fast)
CostEstimate pd_cost(double particles, double bonds_per_particle, bool single, double steps, bool elastic_only);
// Matrix-free Helmholtz: DoFs, elements, order, and the solver's iteration limit.
CostEstimate helmholtz_cost(double dofs, double elements, int order, bool single, int max_iterations);
// DEM spheres: spheres and steps (over all runs of a scene).
CostEstimate dem_cost(double spheres, double steps);

}  // namespace polymech::io
