// Plate perforation by a rigid projectile (seed 003 §3(3)-§4, Figs. 3-7): the plate (NosbPd) and the
// projectile (a rigid body, models/common/rigid_bodies.hpp) advanced together by the coupled model of
// models/common/coupled.hpp, with penalty contact between them (the `contact` effect); when the run
// may stop; and what the plate looks like afterwards.
//
//  - perforated: the nose is more than one horizon below the plate's bottom face and the contact
//    force has vanished (the projectile flies free); the residual velocity is then its speed;
//  - shear plugging vs collapse (Figs. 4-5): mean damage of the plate material under the centre of
//    the projectile (r < R_p / 2, "core") against the material at its rim (|r - R_p| < spacing,
//    "rim"); a plug keeps its core and fails at the rim, a collapsed impact zone is damaged through;
//  - plug mass: particles inside r < 1.5 R_p moving with the projectile (faster than half its speed).
//
// The projectile is rigid and moves along its axis (its rotation is locked: frictionless contact on
// a blunt or spherical nose, as the report models it); the contact force on each particle and its
// reaction on the projectile are computed once, so the momentum exchanged is exact.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "common/coupled.hpp"
#include "common/rigid_bodies.hpp"
#include "contact/projectile_penalty.hpp"
#include "nosb_pd/run.hpp"

namespace polymech::nosb_pd {

// The rigid projectile of an impact scene: mass, inertia (a solid cylinder or sphere), its nose (or
// lowest point) `standoff` above the plate top (z = 0 / y = 0), moving towards -z (-y in 2D).
template <int D>
rigid::RigidBody<D> projectile_body(const Projectile& p) {
  rigid::RigidBody<D> b;
  b.mass = p.mass;
  const double r2 = p.radius * p.radius;
  if (p.shape == ProjectileShape::sphere) {
    for (double& i : b.inertia) i = 0.4 * p.mass * r2;
  } else {
    for (double& i : b.inertia) i = p.mass * (3.0 * r2 + p.length * p.length) / 12.0;
    b.inertia[b.rotational - 1] = 0.5 * p.mass * r2;  // about the axis (3D: z; 2D: the one moment)
  }
  b.position[D - 1] = p.standoff + (p.shape == ProjectileShape::sphere ? p.radius : 0.0);
  b.velocity[D - 1] = -p.velocity;
  b.rotation_locked = true;
  return b;
}

// The interaction: penalty contact between the plate's particles and the projectile (seed 003 §3(3)).
template <class T, int D>
class ProjectileContact {
 public:
  ProjectileContact(const Config& c, Index particles)
      : penalty_(static_cast<T>(c.contact.penalty * c.material.youngs_modulus * c.spacing)),
        contact_radius_(static_cast<T>(c.contact.contact_radius * c.spacing)),
        density_(static_cast<T>(c.material.density)),
        force_("polymech::nosb_pd::contact_force", static_cast<std::size_t>(particles)) {
    shape_.shape = c.projectile.shape == ProjectileShape::sphere ? contact::ProjectileShape::sphere
                                                                 : contact::ProjectileShape::blunt_cylinder;
    shape_.radius = static_cast<T>(c.projectile.radius);
    shape_.length = static_cast<T>(c.projectile.length);
  }

  // Forces on the plate's particles (a += f / m) and their sum, reversed, on the projectile.
  void add_forces(NosbPd<T, D>& plate, models::RigidBodies<D>& projectile) {
    rigid::RigidBody<D>& body = projectile.body(0);
    contact::RigidProjectile<T, D> q = shape_;
    for (int k = 0; k < D; ++k) q.position[k] = static_cast<T>(body.position[k]);
    const auto& f = plate.fields();
    contact::projectile_penalty(q, penalty_, contact_radius_, f.x0, f.u, f.volume, density_, force_, f.a);
    const auto s = particles::vector_sum("polymech::nosb_pd::projectile_reaction", force_);
    for (int k = 0; k < D; ++k) body.force[k] += -s[k];
  }
  // Energy stored in the penalty springs.
  double energy() const { return contact::penalty_energy(force_, static_cast<double>(penalty_)); }
  const VecView<T, D>& forces() const { return force_; }

 private:
  contact::RigidProjectile<T, D> shape_;
  T penalty_, contact_radius_, density_;
  VecView<T, D> force_;
};

namespace detail {
// The parts of an impact, constructed before the coupled model that refers to them.
template <class T, int D>
struct ImpactParts {
  NosbPd<T, D> plate;
  models::RigidBodies<D> bodies;
  ProjectileContact<T, D> contact;
  explicit ImpactParts(const Config& c)
      : plate(c, false), bodies({projectile_body<D>(c.projectile)}, plate.dt()), contact(c, plate.particles()) {}
};
}  // namespace detail

// The plate, the projectile and their contact, advanced as one explicit model.
template <class T, int D>
class Impact : private detail::ImpactParts<T, D>,
               public models::CoupledModel<NosbPd<T, D>, models::RigidBodies<D>, ProjectileContact<T, D>> {
  using Parts = detail::ImpactParts<T, D>;
  using Coupled = models::CoupledModel<NosbPd<T, D>, models::RigidBodies<D>, ProjectileContact<T, D>>;

 public:
  explicit Impact(const Config& c) : Parts(checked(c)), Coupled(Parts::plate, Parts::bodies, Parts::contact) {}

  const NosbPd<T, D>& plate() const { return Parts::plate; }
  NosbPd<T, D>& plate() { return Parts::plate; }
  const rigid::RigidBody<D>& projectile() const { return Parts::bodies.body(0); }
  const ProjectileContact<T, D>& contact() const { return Parts::contact; }
  const Config& config() const { return Parts::plate.config(); }

  // The plate's energies with the contact springs and the projectile's kinetic energy and momentum.
  Energies energy() const {
    Energies e = Parts::plate.energy();
    const auto& p = projectile();
    for (int k = 0; k < D; ++k) e.momentum[k] = e.momentum[k] + p.mass * p.velocity[k];
    e.contact = Parts::contact.energy();
    for (int k = 0; k < D; ++k) e.projectile_kinetic += 0.5 * p.mass * p.velocity[k] * p.velocity[k];
    return e;
  }
  std::int64_t broken_bonds() const { return Parts::plate.broken_bonds(); }

 private:
  static const Config& checked(const Config& c) {
    if (!c.effects.has("contact")) throw std::invalid_argument("nosb_pd: an impact needs the contact effect");
    if (c.loading != Loading::impact) throw std::invalid_argument("nosb_pd: an impact needs loading = impact");
    return c;
  }
};

template <class T, int D>
ProjectileState projectile_state(const Impact<T, D>& m) {
  ProjectileState s;
  const auto& p = m.projectile();
  s.mass = p.mass;
  for (int k = 0; k < D; ++k) {
    s.position[k] = p.position[k];
    s.velocity[k] = p.velocity[k];
    s.reaction[k] = p.force[k];
    s.acceleration[k] = p.force[k] / p.mass;
  }
  return s;
}

struct ImpactState {
  bool perforated = false;          // through and free (no contact force left)
  bool through = false;             // nose more than a horizon below the bottom face, still moving down
                                    // (the plug may ride on the nose: in contact, yet through the plate)
  double residual_velocity = 0.0;  // projectile speed along the impact direction [m/s]
  double core_damage = 0.0, rim_damage = 0.0;
  double plug_mass = 0.0, plug_mass_nominal = 0.0;  // [kg]; nominal: rho pi R_p^2 H (3D)
  double max_damage = 0.0;
};

// Height of the projectile's nose (its lowest point).
template <class T, int D>
double nose_position(const Impact<T, D>& m) {
  const Config& c = m.config();
  return m.projectile().position[D - 1] - (c.projectile.shape == ProjectileShape::sphere ? c.projectile.radius : 0.0);
}

// Projectile through the plate and free: nose below the bottom face by a horizon, no contact force.
template <class T, int D>
bool projectile_free(const Impact<T, D>& m) {
  const Config& c = m.config();
  const auto& p = m.projectile();
  double f = 0;
  for (int k = 0; k < D; ++k) f += p.force[k] * p.force[k];
  return nose_position(m) < -c.geometry.thickness - c.horizon() && std::sqrt(f) == 0.0;
}

template <class T, int D>
ImpactState analyse_impact(const Impact<T, D>& m) {
  const Config& c = m.config();
  ImpactState s;
  s.residual_velocity = -m.projectile().velocity[D - 1];
  s.perforated = projectile_free(m);
  s.through = nose_position(m) < -c.geometry.thickness - c.horizon() && s.residual_velocity > 0;
  const HostFields h = m.plate().host_fields();
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
RunStats run_impact(Impact<T, D>& m, std::int64_t steps, RunHooks hooks, bool stop_after_perforation = true) {
  int free_samples = 0;
  if (hooks.resume) free_samples = hooks.resume->get<int>("impact/free_samples");
  hooks.checkpoint.add.push_back([&free_samples](models::Archive& a) { a.put("impact/free_samples", free_samples); });
  if (stop_after_perforation)
    hooks.stop = [&] {
      free_samples = projectile_free(m) ? free_samples + 1 : 0;
      return free_samples >= 5;
    };
  return run(m, steps, hooks, 3.0);
}

}  // namespace polymech::nosb_pd
