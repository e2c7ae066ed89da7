// Validated description of a NOSB peridynamics run (seed 003). Filled by io/ from a scene file or
// directly by tests and benchmarks; the model never sees text. SI units throughout.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>

#include "effects.hpp"

namespace polymech::nosb_pd {

enum class Law {
  elastic,       // St. Venant-Kirchhoff
  johnson_cook,  // J2 with Johnson-Cook hardening, rate and thermal softening
};

enum class Shape {
  box,        // [0, length] x [0, height] (2D) or [0, length] x [0, width] x [0, height] (3D)
  disc,       // plate: 3D disc of radius `radius` in x-y, z in [-thickness, 0]; 2D strip |x| <= radius, y in [-thickness, 0]
  round_bar,  // 3D bar along x, circular cross-section of radius `radius` in y-z, x in [0, length]
};

enum class Layout {
  lattice,      // cubic (square) lattice at cell centres
  jittered,     // lattice points moved by up to jitter * spacing per component (irregular)
  cylindrical,  // rings conforming to the curved surface (disc: around z; round bar: around x), irregular
};

enum class Loading {
  none,
  tension,  // grips of one horizon at x = 0 (held in x) and x = length (pulled in x)
  impact,   // rigid projectile (contact effect), plate clamped beyond clamp_radius
};

enum class DamageCriterion { critical_stretch, energy_release_rate };

struct Geometry {
  Shape shape = Shape::box;
  double length = 0.0, width = 0.0, height = 0.0;  // box / round bar
  double radius = 0.0, thickness = 0.0;            // disc (radius includes the clamped ring) / round bar
  Layout layout = Layout::lattice;
  double jitter = 0.25;     // jittered: amplitude in units of the spacing
  std::uint64_t seed = 1;   // jittered: pseudo-random sequence
};

struct Material {
  Law law = Law::elastic;
  double density = 7850.0;
  double youngs_modulus = 200e9;
  double poisson_ratio = 0.33;
  // Johnson-Cook (law = johnson_cook)
  double jc_a = 0.0, jc_b = 0.0, jc_n = 1.0, jc_c = 0.0, jc_reference_rate = 1.0, jc_m = 1.0;
  double room_temperature = 293.0, melting_temperature = 0.0;  // melting <= room: no thermal softening
  double specific_heat = 452.0, taylor_quinney = 0.9;

  double lambda() const { return youngs_modulus * poisson_ratio / ((1 + poisson_ratio) * (1 - 2 * poisson_ratio)); }
  double mu() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }
  double bulk() const { return youngs_modulus / (3 * (1 - 2 * poisson_ratio)); }
  double p_wave_speed() const { return std::sqrt((lambda() + 2 * mu()) / density); }
};

struct Damage {
  DamageCriterion criterion = DamageCriterion::critical_stretch;
  double critical_stretch = 0.0;       // s_c
  double energy_release_rate = 0.0;    // G_c [J/m^2] -> s_c (Silling & Askari 2005; see critical_stretch())
  // A particle whose intact bonds leave an ill-conditioned shape tensor, det K / (tr K / D)^D below
  // this (1 for a full or half-space family, 0 when the bonds lie in a plane), carries no stress:
  // F would be undetermined along the missing directions.
  double min_shape_quality = 0.2;
  // J2 law with damage: a particle whose J = det F leaves [crush_volume_ratio, 1 / crush_volume_ratio]
  // fails for good (pd::CrushLimits; plastic flow keeps the volume, such a J is a torn family).
  double crush_volume_ratio = 0.5;
};

struct Stabilization {
  double c_v = 6.0;          // velocity viscosity coefficient, eq. (3)
  double omega_v = 0.0;      // [rad/s], eq. (3): identified from the uncontrolled tension test
  double hourglass = 0.1;    // G_s of the hourglass force state (Silling 2017)
};

struct Contact {
  double penalty = 1.0;             // projectile penalty k = penalty * E * spacing [N/m]
  double contact_radius = 0.5;      // particle contact radius / spacing
  double short_range_distance = 0.9;  // d_s / spacing
  double short_range_factor = 15.0;   // c_s = factor * c (bond-based micromodulus), Silling & Askari 2005
  double skin = 0.5;                  // Verlet skin / spacing
};

enum class ProjectileShape { blunt_cylinder, sphere };

struct Projectile {
  ProjectileShape shape = ProjectileShape::blunt_cylinder;
  double radius = 0.01, length = 0.08, mass = 0.197;
  double velocity = 303.5;   // initial speed towards -z (3D) / -y (2D) [m/s]
  double standoff = 0.0;     // gap between nose and plate top at t = 0 [m]
};

struct Tension {
  double strain = 1e-3;       // nominal end strain
  double ramp_time = 0.0;     // time to reach it (then held)
};

struct Config {
  int dimension = 3;
  double spacing = 1e-3;
  double horizon_ratio = 3.0;  // m = delta / spacing
  Geometry geometry;
  Material material;
  Damage damage;
  Stabilization stabilization;
  Contact contact;
  Loading loading = Loading::none;
  Tension tension;
  Projectile projectile;
  double clamp_radius = 0.0;   // impact: particles farther than this from the axis are held fixed
  double dt = 0.0;             // 0: dt_safety x the stable step
  double dt_safety = 0.7;
  std::int64_t steps = 1000;
  double mass_damping = 0.0;   // [1/s], quasi-static relaxation only
  EffectSet effects;

  double horizon() const { return horizon_ratio * spacing; }
};

// Critical stretch of the damage criterion: given directly, or from the critical energy release rate
// by the bond-energy argument of Silling & Askari (2005): s_c = sqrt(5 G_c / (9 K delta)) in 3D and,
// in 2D (Ha & Bobaru 2010, plane), s_c = sqrt(4 pi G_c / (9 E delta)).
inline double critical_stretch(const Config& c) {
  if (c.damage.criterion == DamageCriterion::critical_stretch) return c.damage.critical_stretch;
  const double g = c.damage.energy_release_rate, delta = c.horizon();
  if (c.dimension == 3) return std::sqrt(5.0 * g / (9.0 * c.material.bulk() * delta));
  return std::sqrt(4.0 * 3.14159265358979323846 * g / (9.0 * c.material.youngs_modulus * delta));
}

// Time of the ramp and of the relaxation, in units of the bar's transit time L / c_bar.
struct TensionSchedule {
  double ramp = 4.0, hold = 10.0;
};

inline double bar_wave_speed(const Config& c) { return std::sqrt(c.material.youngs_modulus / c.material.density); }

// The damping that relaxes a bar's fundamental mode fastest (critical damping of omega_1 = pi c / 2L).
inline double relaxation_damping(const Config& c) { return 3.14159265358979323846 * bar_wave_speed(c) / c.geometry.length; }

}  // namespace polymech::nosb_pd
