#include "io/dem_scene.hpp"

#include <cmath>

#include "io/ranges.hpp"

namespace polymech::io {

namespace pl = polymech::io::plausible;

dem::Config dem_impact_config(const DemScene& s, double angle_deg, double restitution) {
  dem::Config c = s.target == "sphere" ? dem::two_spheres(s.impact, s.steps_per_contact)
                                       : dem::sphere_on_wall(s.impact, s.steps_per_contact, angle_deg, s.target == "mesh");
  c.restitution = restitution;
  c.friction = s.config.friction;
  c.effects = s.config.effects;
  if (s.dt > 0) c.dt = s.dt;
  return c;
}

namespace {

dem::Material read_material(const SceneTable& t, bool wall) {
  dem::Material m;
  if (wall && t.boolean("rigid", false)) return m;  // young = 0: rigid
  m.young = t.real("youngs_modulus", pl::modulus());
  m.poisson = t.real("poisson_ratio", Range{-1.0, 0.5, true, true});
  if (!wall) m.density = t.real("density", pl::density());
  return m;
}

}  // namespace

DemScene load_dem_scene(const std::filesystem::path& file, const SceneOptions& options) {
  const std::string& precision = options.precision;
  DemScene out;
  const OpenScene s = open_scene(file, "dem", dem::effect_table(), precision, out);
  const SceneTable& root = s.root;
  s.model.finish();
  out.header.set_accuracy(read_accuracy(root, "", 0.0, "paper"));
  const auto& fx = out.config.effects;
  if (fx.has("clumps")) s.model.fail("effects", "lists \"clumps\", but an impact scene has spheres only (no clumps)");
  if (fx.has("rigid_wheel"))  // the wheel drives over a bed: dem_pour scenes (issue 33 item 11)
    s.model.fail("effects", "lists \"rigid_wheel\", but an impact scene has no wheel (a [wheel] table belongs to a bed scene "
                            "run by dem_pour)");

  const SceneTable particle = root.table("particle");
  out.impact.particle = read_material(particle, false);
  out.impact.radius = particle.real("radius", Range{1e-6, 10.0, false, false, "m (a sphere radius: 1 um to 10 m)"});
  particle.finish();
  if (const auto wall = root.optional_table("wall")) {
    out.impact.wall = read_material(*wall, true);
    wall->finish();
  }

  const SceneTable contact = root.table("contact");
  const double e = contact.real("restitution", 1.0, Range{1e-3, 1.0, false, false, "(1: elastic)"});
  out.config.friction = contact.real("friction", 0.0, pl::factor(0.0, 10.0));
  if (e < 1.0 && !fx.has("damping")) contact.fail("restitution", "< 1 needs the effect \"damping\" in model.effects");
  if (out.config.friction > 0 && !fx.has("friction")) contact.fail("friction", "> 0 needs the effect \"friction\" in model.effects");
  contact.finish();

  const SceneTable impact = root.table("impact");
  out.target = impact.choice("target", {"sphere", "plane", "mesh"});
  if (out.target == "mesh" && !fx.has("fe_surfaces")) impact.fail("target", "= \"mesh\" needs the effect \"fe_surfaces\"");
  if (out.target != "mesh" && fx.has("fe_surfaces")) impact.fail("target", "is not \"mesh\", but model.effects lists \"fe_surfaces\"");
  out.impact.speed = impact.real("speed", Range{1e-3, 1e3, false, false, "m/s (an impact speed)"});
  out.angles = impact.has("angles") ? impact.reals("angles", Range{0.0, 89.0, false, false, "degrees from the normal"})
                                    : std::vector<double>{0.0};
  if (out.angles.empty()) impact.fail("angles", "is empty; give at least one incidence angle");
  if (out.target == "sphere" && (out.angles.size() != 1 || out.angles[0] != 0.0))
    impact.fail("angles", "must be [0] for target = \"sphere\" (head-on)");
  out.restitutions = impact.has("restitutions")
                         ? impact.reals("restitutions", Range{1e-3, 1.0, false, false, "coefficients of restitution"})
                         : std::vector<double>{e};
  if (out.restitutions.empty()) impact.fail("restitutions", "is empty");
  if (impact.has("restitutions") && !fx.has("damping"))
    impact.fail("restitutions", "needs the effect \"damping\" in model.effects");
  impact.finish();

  if (const auto bench = root.optional_table("benchmark")) {
    out.test = static_cast<int>(bench->integer("test", 1, 4));
    bench->finish();
  }

  const SceneTable time = root.table("time");
  out.steps_per_contact = time.real("steps_per_contact", 400.0, Range{20.0, 1e5, false, false, "steps per Hertz contact time"});
  const double dt = out.dt = time.real("dt", 0.0, Range{0.0, pl::time_step().hi, false, false, "s (0: from steps_per_contact)"});
  time.finish();
  root.finish();

  // the configuration of the first run, its limit, and the refusal of a step above it
  out.config.dt = 0.0;
  for (double angle : out.angles)
    for (double r : out.restitutions) {
      dem::Config c = dem_impact_config(out, angle, r);
      const auto limit = dem::time_step_limit(c);
      if (!(limit.limit > 0) || !std::isfinite(limit.limit))
        time.fail("steps_per_contact", "gives no finite time-step limit for these materials");
      if (c.dt > limit.limit)
        time.fail(dt > 0 ? "dt" : "steps_per_contact",
                  "gives dt = " + format_number(c.dt) + " s, above the limit " + limit.describe());
      if (out.config.dt == 0.0) {
        out.limit = limit;
        const double friction = out.config.friction;
        const auto effects = out.config.effects;
        out.config = c;
        out.config.friction = friction;
        out.config.effects = effects;
      }
    }

  // cost: a contact of steps_per_contact steps (and the approach), per run
  const double runs = static_cast<double>(out.angles.size() * out.restitutions.size());
  out.cost = dem_cost(double(out.config.spheres.size()), 1.2 * out.steps_per_contact * runs);
  check_size(out.cost, s.model);
  return out;
}

}  // namespace polymech::io
