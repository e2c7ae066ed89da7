// Plate perforation by a rigid projectile (seed 003 §3(3)-§4, Figs. 3-7): when the run may stop,
// and what the plate looks like afterwards.
//
//  - perforated: the nose is more than one horizon below the plate's bottom face and the contact
//    force has vanished (the projectile flies free); the residual velocity is then its speed;
//  - shear plugging vs collapse (Figs. 4-5): mean damage of the plate material under the centre of
//    the projectile (r < R_p / 2, "core") against the material at its rim (|r - R_p| < spacing,
//    "rim"); a plug keeps its core and fails at the rim, a collapsed impact zone is damaged through;
//  - plug mass: particles inside r < 1.5 R_p moving with the projectile (faster than half its speed).
#pragma once

#include <cmath>
#include <vector>

#include "nosb_pd/run.hpp"

namespace polymech::nosb_pd {

struct ImpactState {
  bool perforated = false;          // through and free (no contact force left)
  bool through = false;             // nose more than a horizon below the bottom face, still moving down
                                    // (the plug may ride on the nose: in contact, yet through the plate)
  double residual_velocity = 0.0;  // projectile speed along the impact direction [m/s]
  double core_damage = 0.0, rim_damage = 0.0;
  double plug_mass = 0.0, plug_mass_nominal = 0.0;  // [kg]; nominal: rho pi R_p^2 H (3D)
  double max_damage = 0.0;
};

// Projectile through the plate and free: nose below the bottom face by a horizon, no contact force.
template <class T, int D>
bool projectile_free(const NosbPd<T, D>& m) {
  const Config& c = m.config();
  const auto& p = m.projectile();
  const double nose = p.position[D - 1] - (c.projectile.shape == ProjectileShape::sphere ? c.projectile.radius : 0.0);
  double f = 0;
  for (int k = 0; k < D; ++k) f += p.reaction[k] * p.reaction[k];
  return nose < -c.geometry.thickness - c.horizon() && std::sqrt(f) == 0.0;
}

template <class T, int D>
ImpactState analyse_impact(const NosbPd<T, D>& m) {
  const Config& c = m.config();
  ImpactState s;
  const auto& p = m.projectile();
  s.residual_velocity = -p.velocity[D - 1];
  s.perforated = projectile_free(m);
  const double nose = p.position[D - 1] - (c.projectile.shape == ProjectileShape::sphere ? c.projectile.radius : 0.0);
  s.through = nose < -c.geometry.thickness - c.horizon() && s.residual_velocity > 0;
  const HostFields h = m.host_fields();
  const double Rp = c.projectile.radius, rho = c.material.density;
  double core = 0, rim = 0;
  int ncore = 0, nrim = 0;
  for (std::size_t i = 0; i < h.volume.size(); ++i) {
    double r2 = 0;
    for (int k = 0; k < D - 1; ++k) r2 += h.x0[D * i + k] * h.x0[D * i + k];
    const double r = std::sqrt(r2), d = h.damage.empty() ? 0.0 : h.damage[i];
    s.max_damage = std::max(s.max_damage, d);
    if (r < 0.5 * Rp) core += d, ++ncore;
    if (std::abs(r - Rp) < c.spacing) rim += d, ++nrim;
    if (r < 1.5 * Rp && -h.v[D * i + D - 1] > 0.5 * std::abs(s.residual_velocity) && s.residual_velocity > 0)
      s.plug_mass += rho * h.volume[i];
  }
  s.core_damage = ncore ? core / ncore : 0.0;
  s.rim_damage = nrim ? rim / nrim : 0.0;
  s.plug_mass_nominal = D == 3 ? rho * 3.14159265358979323846 * Rp * Rp * c.geometry.thickness : rho * 2 * Rp * c.geometry.thickness;
  return s;
}

// Runs an impact up to `steps` steps; with stop_after_perforation, ends once the projectile has been
// through and free for five samples in a row (the residual velocity no longer changes). A run whose
// accounted energy triples has diverged (the uncontrolled zero-energy modes) and is ended there.
template <class T, int D>
RunStats run_impact(NosbPd<T, D>& m, std::int64_t steps, RunHooks hooks, bool stop_after_perforation = true) {
  if (hooks.energy_limit <= 0) hooks.energy_limit = 3.0;
  int free_samples = 0;
  if (stop_after_perforation)
    hooks.stop = [&] {
      free_samples = projectile_free(m) ? free_samples + 1 : 0;
      return free_samples >= 5;
    };
  return run(m, steps, hooks);
}

}  // namespace polymech::nosb_pd
