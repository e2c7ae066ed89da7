// Validated description of a Helmholtz run (seed 002 paper 3): mesh, order, acoustics, boundary
// conditions, analytic reference and solver settings. Filled by io/helmholtz_scene.cpp from a scene
// (or directly by tests and benchmarks); the model never sees text.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "effects.hpp"
#include "helmholtz/mesh.hpp"
#include "helmholtz/partition.hpp"
#include "solvers/options.hpp"

namespace polymech::helmholtz {

class Communicator;  // helmholtz/parallel.hpp

enum class BoundaryKind {
  rigid,      // dPhi/dn = 0: natural, nothing to integrate (paper §3(3): "rigid elsewhere")
  dirichlet,  // Phi = the analytic field (eq. (27)) or a constant, strongly imposed (effect `dirichlet`)
  impedance,  // dPhi/dn = -j omega rho Phi / Zn, eq. (7) -> C of eq. (19) (effect `impedance`)
  vibrating,  // normal velocity v, eq. (8) -> q of eq. (20) (effect `vibrating`)
};

inline const char* to_string(BoundaryKind k) {
  switch (k) {
    case BoundaryKind::rigid: return "rigid";
    case BoundaryKind::dirichlet: return "dirichlet";
    case BoundaryKind::impedance: return "impedance";
    case BoundaryKind::vibrating: return "vibrating";
  }
  return "?";
}

struct BoundaryCondition {
  std::string name;  // a boundary of the mesh (box: xmin ... zmax; Gmsh: a physical surface name)
  BoundaryKind kind = BoundaryKind::rigid;
  double impedance = 0.0;  // Zn [kg/(m^2 s)] (impedance)
  double velocity = 0.0;   // v [m/s] (vibrating)
  double value = 0.0;      // dirichlet: constant value of Phi when the case has no analytic field
};

enum class AnalyticKind {
  none,
  plane_cosines,  // Phi = cos kx + cos ky + cos kz, eq. (27)
  duct,           // p(x) of eq. (29), Phi = p / (j omega rho)
};

struct AnalyticSpec {
  AnalyticKind kind = AnalyticKind::none;
  // duct (eq. (29)): vibrating end at x = x0 with velocity v0, impedance Zn at x = x0 + length
  double x0 = 0.0, length = 1.0, velocity = 0.014, impedance = 445.9;
};

// Preconditioner of COCG (models/helmholtz/preconditioners.hpp).
enum class Preconditioner {
  none,
  jacobi,     // inverse diagonal of K
  chebyshev,  // Chebyshev polynomial in D^-1 S, S = A + s k^2 M (shifted Laplacian)
  pmg,        // p-multigrid V-cycle on S with Chebyshev smoothing
};

inline const char* to_string(Preconditioner p) {
  switch (p) {
    case Preconditioner::none: return "none";
    case Preconditioner::jacobi: return "jacobi";
    case Preconditioner::chebyshev: return "chebyshev";
    case Preconditioner::pmg: return "pmg";
  }
  return "?";
}

// Settings of the shifted-Laplacian preconditioners (chebyshev, pmg).
struct ShiftedOptions {
  double shift = 1.0;             // s of S = A + s k^2 M
  int smoothing_degree = 3;       // pmg: Chebyshev degree of the pre- and post-smoothing
  double smoothing_range = 15.0;  // pmg: smoothing interval [hi / range, hi] of D^-1 S
  int polynomial_degree = 0;      // chebyshev / pmg coarse level: 0 = from the spectrum (bound 0.1)
  int lanczos_steps = 40;         // CG steps of the spectrum estimate on the order-1 (or only) level
};

struct Config {
  int order = 1;  // p = 1..4
  HexMesh mesh;
  double node_perturbation = 0.0;  // curved elements: interior DoF nodes moved by up to this x h / p
  double sound_speed = 343.0;      // c [m/s]
  double frequency = 500.0;        // f [Hz]
  double density = 1.3;            // rho [kg/m^3]
  std::vector<BoundaryCondition> boundaries;  // boundaries not listed are rigid
  AnalyticSpec analytic;
  Preconditioner preconditioner = Preconditioner::jacobi;
  ShiftedOptions shifted;  // chebyshev, pmg
  int chunk_elements = 0;  // elements per chunk of the scatter colouring; 0: automatic (host ~8000 nodes, device 1)
  int batch_elements = 0;  // elements per batch of the volume kernels (SIMD lanes); 0: one SIMD register (fem::volume_batch)
  bool affine_geometry = true;  // affine batches keep one Jacobian per element (false: factors at every point)
  solvers::SolverOptions solver;
  EffectSet effects;
  // Domain decomposition: one part per rank of `communicator` (null: one part, no messages).
  std::shared_ptr<const Communicator> communicator;
  PartitionMethod partition = PartitionMethod::automatic;

  double omega() const { return 2.0 * 3.14159265358979323846 * frequency; }
  double wavenumber() const { return omega() / sound_speed; }
};

}  // namespace polymech::helmholtz
