#include "io/nosb_pd_scene.hpp"

#include "io/ranges.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "nosb_pd/particles.hpp"

namespace polymech::io {

namespace np = polymech::nosb_pd;
namespace pl = polymech::io::plausible;

namespace {

template <class E>
E pick(const SceneTable& t, const std::string& key, const std::vector<std::pair<std::string, E>>& options,
       const std::string& fallback = "") {
  std::vector<std::string> names;
  for (const auto& o : options) names.push_back(o.first);
  const std::string v = fallback.empty() ? t.choice(key, names) : t.choice(key, names, fallback);
  for (const auto& o : options)
    if (o.first == v) return o.second;
  return options.front().second;
}

void read_geometry(const SceneTable& g, np::Config& c) {
  auto& geo = c.geometry;
  geo.shape = pick<np::Shape>(g, "shape", {{"box", np::Shape::box}, {"disc", np::Shape::disc}, {"round_bar", np::Shape::round_bar}});
  if (geo.shape == np::Shape::box) {
    geo.length = g.real("length", pl::length());
    if (c.dimension == 3) geo.width = g.real("width", pl::length());
    geo.height = g.real("height", pl::length());
  } else if (geo.shape == np::Shape::disc) {
    geo.radius = g.real("radius", pl::length());
    geo.thickness = g.real("thickness", pl::length());
  } else {
    if (c.dimension != 3) g.fail("shape", "= \"round_bar\" needs model.dimension = 3");
    geo.length = g.real("length", pl::length());
    geo.radius = g.real("radius", pl::length());
  }
  g.finish();
}

void read_material(const SceneTable& m, np::Config& c) {
  auto& mat = c.material;
  mat.law = pick<np::Law>(m, "law", {{"elastic", np::Law::elastic}, {"johnson_cook", np::Law::johnson_cook}}, "elastic");
  mat.density = m.real("density", pl::density());
  mat.youngs_modulus = m.real("youngs_modulus", pl::modulus());
  mat.poisson_ratio = m.real("poisson_ratio", Range{-1.0, 0.5, true, true});
  const auto jc = m.optional_table("johnson_cook");
  if (mat.law == np::Law::johnson_cook && !jc) m.fail("law", "= \"johnson_cook\" needs a [material.johnson_cook] table");
  if (mat.law != np::Law::johnson_cook && jc) jc->fail_table("is given, but material.law is not \"johnson_cook\"");
  if (jc) {
    mat.jc_a = jc->real("A", Range{1e3, pl::stress().hi, false, false, pl::stress().note});
    mat.jc_b = jc->real("B", pl::stress());
    mat.jc_n = jc->real("n", pl::factor(1e-6, 10.0));
    mat.jc_c = jc->real("C", 0.0, pl::factor(0.0, 10.0));
    mat.jc_reference_rate = jc->real("reference_strain_rate", 1.0, pl::strain_rate());
    mat.jc_m = jc->real("m", 1.0, pl::factor(1e-6, 10.0));
    mat.room_temperature = jc->real("room_temperature", 293.0, pl::temperature());
    mat.melting_temperature = jc->real("melting_temperature", 0.0, Range{0.0, pl::temperature().hi, false, false, "K (0: no thermal softening)"});
    if (mat.melting_temperature > 0 && mat.melting_temperature <= mat.room_temperature)
      jc->fail("melting_temperature", "= " + format_number(mat.melting_temperature) +
                                          " K is not above room_temperature; allowed: 0 (no thermal softening) or > " +
                                          format_number(mat.room_temperature) + " K");
    mat.specific_heat = jc->real("specific_heat", 452.0, pl::specific_heat());
    mat.taylor_quinney = jc->real("taylor_quinney", 0.9, between(0.0, 1.0));
    jc->finish();
  }
  m.finish();
  const double cp = mat.p_wave_speed();
  if (!pl::wave_speed().contains(cp))
    m.fail("density", "= " + format_number(mat.density) + " kg/m^3 with youngs_modulus = " + format_number(mat.youngs_modulus) +
                          " Pa and poisson_ratio = " + format_number(mat.poisson_ratio) + " gives the P-wave speed " +
                          format_number(cp) + " m/s; allowed: a wave speed " + pl::wave_speed().text());
}

// The keys that set the number of particles (nosb_pd::lattice_size counts them).
std::vector<std::string> size_keys(const np::Config& c, double spacing, const std::string& accuracy) {
  const auto& g = c.geometry;
  std::vector<std::string> keys = {"discretization.spacing = " + format_number(spacing) + " m (x " +
                                       format_number(c.spacing / spacing) + " at accuracy '" + accuracy + "')",
                                   "discretization.horizon_ratio = " + format_number(c.horizon_ratio)};
  auto add = [&](const char* k, double v) { keys.push_back(std::string("geometry.") + k + " = " + format_number(v) + " m"); };
  if (g.shape == np::Shape::box) {
    add("length", g.length);
    if (c.dimension == 3) add("width", g.width);
    add("height", g.height);
  } else if (g.shape == np::Shape::disc) {
    add("radius", g.radius);
    add("thickness", g.thickness);
  } else {
    add("length", g.length);
    add("radius", g.radius);
  }
  return keys;
}

}  // namespace

NosbPdScene load_nosb_pd_scene(const std::filesystem::path& file, const NosbPdSceneOptions& options) {
  NosbPdScene out;
  const OpenScene s = open_scene(file, "nosb_pd", np::effect_table(), options.precision, out);
  const SceneTable& root = s.root;
  const SceneTable& model = s.model;
  np::Config& c = out.config;
  c.dimension = static_cast<int>(model.integer("dimension", 3, 2, 3));
  model.finish();

  // [accuracy]: preset name -> spacing factor
  out.header.set_accuracy(read_accuracy(root, options.accuracy, options.coarsening));
  const double f = out.header.coarsening;
  const std::string& accuracy = out.header.accuracy;

  // [discretization]
  const SceneTable disc = root.table("discretization");
  const double spacing = disc.real("spacing", pl::spacing());
  c.spacing = spacing * f;
  c.horizon_ratio = disc.real("horizon_ratio", 3.0, Range{1.0, 8.0, false, false, "spacings"});
  if (options.horizon_ratio > 0) c.horizon_ratio = options.horizon_ratio;
  c.geometry.layout = pick<np::Layout>(
      disc, "layout", {{"lattice", np::Layout::lattice}, {"jittered", np::Layout::jittered}, {"cylindrical", np::Layout::cylindrical}},
      "lattice");
  c.geometry.jitter = disc.real("jitter", 0.25, Range{0.0, 0.5, false, true});
  c.geometry.seed = static_cast<std::uint64_t>(disc.integer("seed", 1, 0, std::int64_t(1) << 62));
  disc.finish();

  // [geometry]
  read_geometry(root.table("geometry"), c);
  {
    const auto& g = c.geometry;
    const double smallest = g.shape == np::Shape::box ? std::min({g.length, g.height, c.dimension == 3 ? g.width : g.length})
                            : g.shape == np::Shape::disc ? std::min(g.thickness, g.radius)
                                                         : std::min(g.length, g.radius);
    if (c.spacing > smallest)
      disc.fail("spacing", "= " + format_number(spacing) + " m (x " + format_number(f) + " at accuracy '" + accuracy +
                               "') is larger than the body (smallest dimension " + format_number(smallest) +
                               " m); allowed: 0 < spacing <= " + format_number(smallest / f) + " m");
    if (g.layout == np::Layout::cylindrical && (c.dimension != 3 || g.shape == np::Shape::box))
      disc.fail("layout", "= \"cylindrical\" conforms to a circle: it needs a 3D disc or round_bar geometry");
  }
  // The size of the run, refused before anything is built over the body if it cannot fit.
  const np::LatticeSize size = np::lattice_size(c);
  const auto cost = [&](double steps) {
    const bool elastic_only = !c.effects.has("damage") && !c.effects.has("contact") && !c.effects.has("velocity_viscosity") &&
                              !c.effects.has("short_range");
    CostEstimate e = pd_cost(size.particles, size.bonds / std::max(1.0, size.particles), out.header.precision == "float", steps,
                             elastic_only);
    e.size_keys = size_keys(c, spacing, accuracy);
    return e;
  };
  check_size(cost(0.0), disc);

  // [material]
  read_material(root.table("material"), c);

  // [damage]
  const auto dmg = root.optional_table("damage");
  if (c.effects.has("damage") && !dmg) model.fail("effects", "lists \"damage\", which needs a [damage] table");
  if (dmg) {
    const bool sc = dmg->has("critical_stretch"), gc = dmg->has("energy_release_rate");
    if (sc == gc)
      dmg->fail_table("needs exactly one of critical_stretch (a bond stretch) or energy_release_rate (G_c [J/m^2])");
    if (sc) {
      c.damage.criterion = np::DamageCriterion::critical_stretch;
      c.damage.critical_stretch = dmg->real("critical_stretch", pl::factor(1e-6, 10.0));
    } else {
      c.damage.criterion = np::DamageCriterion::energy_release_rate;
      c.damage.energy_release_rate = dmg->real("energy_release_rate", Range{0.0, 1e9, true, false, "J/m^2"});
    }
    // J2 law: particles whose det F leaves [r, 1/r] fail for good; 0 switches it off
    c.damage.crush_volume_ratio = dmg->real("crush_volume_ratio", 0.5, Range{0.0, 1.0, false, true});
    dmg->finish();
  }

  // [stabilization]
  if (auto st = root.optional_table("stabilization")) {
    c.stabilization.c_v = st->real("c_v", 6.0, pl::factor(0.0, 1e3));
    c.stabilization.omega_v = st->real("omega_v", 0.0, pl::rate()) / f;
    c.stabilization.hourglass = st->real("hourglass", 0.02, pl::factor(0.0, 1e3));
    if (options.c_v >= 0) c.stabilization.c_v = options.c_v;
    if (c.effects.has("velocity_viscosity") && !(c.stabilization.omega_v > 0))
      st->fail("omega_v", "is missing or 0; the velocity_viscosity effect needs omega_v > 0 [rad/s] (identify it with "
                          "the uncontrolled tension test: pd_tension --identify-omega-v)");
    st->finish();
  } else if (c.effects.has("velocity_viscosity")) {
    model.fail("effects", "lists \"velocity_viscosity\", which needs [stabilization] omega_v (and c_v)");
  }

  // [contact]
  if (auto ct = root.optional_table("contact")) {
    c.contact.penalty = ct->real("penalty", 1.0, pl::factor(1e-6, 1e6));
    c.contact.contact_radius = ct->real("contact_radius", 0.5, Range{0.0, 2.0, true, false});
    c.contact.short_range_distance = ct->real("short_range_distance", 0.9, Range{0.0, 2.0, true, false});
    c.contact.short_range_factor = ct->real("short_range_factor", 15.0, pl::factor(1e-6, 1e6));
    c.contact.skin = ct->real("skin", 0.5, pl::factor(1e-6, 10.0));
    ct->finish();
  }

  // [loading]
  const SceneTable load = root.table("loading");
  c.loading = pick<np::Loading>(load, "kind", {{"none", np::Loading::none}, {"tension", np::Loading::tension}, {"impact", np::Loading::impact}});
  if (c.loading == np::Loading::tension) {
    if (c.geometry.shape == np::Shape::disc) load.fail("kind", "= \"tension\" needs a box or round_bar geometry");
    c.tension.strain = load.real("strain", 1e-3, pl::factor(1e-9, 0.1));
    out.tension.ramp = load.real("ramp", 4.0, Range{1e-3, 1e4, false, false, "bar transit times"});
    out.tension.hold = load.real("hold", 10.0, Range{0.0, 1e4, false, false, "bar transit times"});
    c.mass_damping = load.real("damping", np::relaxation_damping(c), pl::rate());
  }
  if (c.loading == np::Loading::impact) {
    if (!c.effects.has("contact")) load.fail("kind", "= \"impact\" needs the \"contact\" effect in model.effects");
    if (c.geometry.shape != np::Shape::disc) load.fail("kind", "= \"impact\" needs a disc (plate) geometry");
    c.clamp_radius = load.real("clamp_radius", pl::length());
    if (c.clamp_radius >= c.geometry.radius)
      load.fail("clamp_radius", "= " + format_number(c.clamp_radius) +
                                    " m is not inside the plate; allowed: 0 < clamp_radius < geometry.radius = " +
                                    format_number(c.geometry.radius) + " m");
    out.stop_after_perforation = load.boolean("stop_after_perforation", true);
  }
  load.finish();

  // [projectile]
  double scene_velocity = 0.0;
  const auto pr = root.optional_table("projectile");
  if (c.loading == np::Loading::impact && !pr) load.fail("kind", "= \"impact\" needs a [projectile] table");
  if (pr) {
    auto& p = c.projectile;
    p.shape = pick<np::ProjectileShape>(*pr, "shape", {{"blunt_cylinder", np::ProjectileShape::blunt_cylinder}, {"sphere", np::ProjectileShape::sphere}});
    p.radius = pr->real("radius", pl::length());
    p.length = p.shape == np::ProjectileShape::blunt_cylinder ? pr->real("length", pl::length()) : 0.0;
    p.mass = pr->real("mass", pl::mass());
    scene_velocity = pr->real("velocity", pl::velocity());
    p.velocity = options.velocity > 0 ? options.velocity : scene_velocity;
    p.standoff = pr->real("standoff", 0.25 * c.spacing, pl::gap());
    if (c.loading == np::Loading::impact && p.radius >= c.clamp_radius)
      pr->fail("radius", "= " + format_number(p.radius) + " m is not inside the clamped span; allowed: < loading.clamp_radius = " +
                             format_number(c.clamp_radius) + " m");
    pr->finish();
  }

  if (c.effects.has("contact") && c.loading != np::Loading::impact)
    model.fail("effects", "lists \"contact\", the projectile of an impact, but loading.kind is not \"impact\"");

  // [experiment]: the measured residual velocity at the scene's impact velocity (not at an overridden one)
  if (auto ex = root.optional_table("experiment")) {
    const double v = ex->real("residual_velocity", Range{0.0, pl::velocity().hi, false, false, "m/s"});
    if (c.loading != np::Loading::impact) ex->fail_table("holds an impact's residual velocity, but loading.kind is not \"impact\"");
    if (c.projectile.velocity == scene_velocity) out.experiment_residual_velocity = v;
    ex->finish();
  }

  // [time]
  const SceneTable time = root.table("time");
  const double dt = time.real("dt", 0.0, Range{0.0, pl::time_step().hi, false, false, "s (0: automatic)"}) * f;
  c.dt_safety = time.real("safety", 0.7, Range{0.0, 1.0, true, false});
  if (c.loading == np::Loading::impact) out.end_time = time.real("end_time", pl::duration());
  out.sample_every = time.integer("sample_every", 50, 1, 1 << 30);
  time.finish();

  // [output]
  if (auto o = root.optional_table("output")) {
    out.snapshots = o->integer("snapshots", 0, 0, 10000);
    o->finish();
  }
  root.finish();

  // The stability limit of this resolution: refused before anything is allocated at full size.
  out.stable_dt = np::stable_time_step(c);
  if (!(out.stable_dt > 0) || !std::isfinite(out.stable_dt))
    root.table("material").fail_table("gives no finite stable time step (" + format_number(out.stable_dt) + " s) at spacing " +
                                      format_number(c.spacing) + " m; allowed: material constants in the plausible ranges "
                                      "whose combination is a stable solid");
  if (dt > 0 && dt > out.stable_dt)
    time.fail("dt", "= " + format_number(dt / f) + " s (x " + format_number(f) + " = " + format_number(dt) + " s at accuracy '" +
                        accuracy + "') is above the stability limit " + format_number(out.stable_dt) + " s of spacing " +
                        format_number(c.spacing) + " m; allowed: 0 (automatic) or 0 < dt <= " + format_number(out.stable_dt / f) + " s");
  c.dt = dt > 0 ? dt : c.dt_safety * out.stable_dt;

  // The run's length: the impact's simulated time, or the tension schedule in bar transit times.
  const double run_time = c.loading == np::Loading::impact    ? out.end_time
                          : c.loading == np::Loading::tension ? (out.tension.ramp + out.tension.hold) *
                                                                    c.geometry.length / np::bar_wave_speed(c)
                                                              : 0.0;
  const double steps = std::ceil(run_time / c.dt);
  if (!(steps <= 1e12))
    time.fail_table("the run would take " + format_number(steps) + " steps of dt = " + format_number(c.dt) +
                    " s; allowed: at most 1e12 steps (shorten time.end_time or loading.ramp / loading.hold)");
  out.steps = static_cast<std::int64_t>(steps);
  out.cost = cost(steps);
  return out;
}

}  // namespace polymech::io
