// Validated description of an MPS elastic-wave run (seed 000 §5). Filled by io/ from a scene file
// (or directly by tests and benchmarks); the model never sees text.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "effects.hpp"

namespace polymech::mps_elastic {

enum class NumberDensityReference {
  mean,      // mean initial number density over all particles, as seed 000 §2.1 defines n0
  interior,  // value of a particle with a full neighbourhood (6.54 for re = 2.1 l0; Table 1: 6.53)
};

enum class ExcitationKind {
  none,
  point,    // eq. (22): one-cycle Hann pulse in u3 at a point of the top surface
  plane_p,  // eq. (23): u3 = -u0 sin 2 pi alpha on the whole top row
  plane_s,  // eq. (24): u1 = -u0 sin 2 pi alpha on the whole top row
};

struct Excitation {
  ExcitationKind kind = ExcitationKind::point;
  double amplitude = 10.0e-9;  // u0 [m]
  double period = 5.0e-7;      // T [s] (2 MHz)
  double cycles = 1.0;         // eq. (22): 1; eqs. (23)-(24): 5
  double position = -1.0;      // point source: x1 of the source on the top surface; < 0: centre
  double width = 0.0;          // point source: driven width of the top row (cells inside it); 0: nearest particle(s)
};

// A straight crack (seed 000 §4, Fig. 1, Fig. 6) and its contact parameters (eqs. (17)-(21), Table 2).
enum class CrackMode {
  none,     // no crack
  cut,      // bonds crossing the crack are removed; the faces interact only through the contact effects
  monitor,  // intact body: the force transmitted through the crack line is recorded (no bond removed),
            // for the S-wave case's normal reaction (seed 000 §5.2.2)
};

struct CrackConfig {
  CrackMode mode = CrackMode::none;
  double x1 = 0.0, x3 = 0.0;  // centre [m]
  double length = 0.0;        // [m]
  double angle = 0.0;         // degrees from the x1 axis (counter-clockwise); 0: horizontal, S+ above
  double k_prime = 0.1;       // eq. (19): kn = k' m / dt^2 (Table 1)
  double mu_s = 0.74;         // static friction coefficient (Table 2)
  double mu_d = 0.57;         // kinetic friction coefficient (Table 2)
  double normal_reaction = 0.0;  // fixed |f'_n| per contact pair [N/m] (eq. (20); the slip model's preload)
  double contact_radius = 1.0001;  // cut bonds up to this length (in spacings) become contact pairs
};

struct Probe {
  std::string name;
  double x1 = 0.0, x3 = 0.0;
};

struct Config {
  // domain: a width x height rectangle [0, width] x [0, height], particles on a square lattice at
  // ((i + 1/2) l0, (j + 1/2) l0)
  double width = 0.05;
  double height = 0.1;
  double spacing = 5.0e-5;           // l0
  double influence_radius = 2.1;     // r_e in units of l0
  NumberDensityReference number_density = NumberDensityReference::mean;
  double n0_override = 0.0;  // > 0: use this n0 instead (stability patches of a larger domain)
  // material: isotropic steel, Table 2
  double density = 7850.0;
  double c13 = 121.1e9;
  double c55 = 80.8e9;
  double inertia_factor = 1.0 / 6.0;  // particle moment of inertia I = factor * m * l0^2 (a square)
  // time
  double dt = 2.0e-9;
  std::int64_t steps = 10000;
  bool allow_unstable_dt = false;  // only for tests that show the instability above the limit
  Excitation excitation;
  std::vector<Probe> probes;
  std::int64_t probe_every = 1;
  EffectSet effects;
  CrackConfig crack;

  double re() const { return influence_radius * spacing; }
};

}  // namespace polymech::mps_elastic
