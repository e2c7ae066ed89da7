#include "io/dem_pour_scene.hpp"

#include <algorithm>
#include <cmath>

#include "io/ranges.hpp"
#include "dem/tyre_spec.hpp"

namespace polymech::io {

namespace pl = polymech::io::plausible;

namespace {

// [wheel] (seed 002 paper 2, sec. 4): the tyre's size, the load and speed schedule (times after
// `start`, when the wheel is set on the settled bed), the slip.
void read_wheel(const SceneTable& t, const dem::PourSpec& p, double duration, dem::WheelSpec& w) {
  w.radius = t.real("radius", Range{1e-3, 100.0, false, false, "m"});
  w.width = t.real("width", Range{1e-3, 100.0, false, false, "m"});
  if (w.width >= p.bin[1]) t.fail("width", "= " + format_number(w.width) + " m does not fit the bin's width " + format_number(p.bin[1]) + " m");
  const double facet = t.real("facet_size", p.radius_max, Range{1e-5, 10.0, false, false, "m (the mesh's facets, about; default gravel.radius_max)"});
  const double two_pi = 6.283185307179586;
  w.around = std::max(16, static_cast<int>(std::ceil(two_pi * w.radius / facet)));
  w.across = std::max(1, static_cast<int>(std::ceil(w.width / facet)));
  if (double(w.around) * w.across > 1e7) t.fail("facet_size", "makes more than 1e7 facets; make it larger");
  w.side_depth = t.real("side_depth", 0.25 * w.radius, Range{0.0, 100.0, false, false, "m (the side walls' depth below the tread)"});
  if (w.side_depth >= w.radius) t.fail("side_depth", "must be smaller than radius = " + format_number(w.radius) + " m");
  w.mass = t.real("mass", pl::mass());
  w.damping = t.real("damping", 0.0, Range{0.0, 1e8, false, false, "N s/m (a damper on the rim's vertical velocity, reacted by the carriage; 0: none)"});
  w.load = t.real("load", Range{0.0, 1e9, false, false, "N (the vertical load, downwards)"});
  const auto ramp = [&t](const std::string& key, double& from, double& to) {
    const auto r = t.reals(key, Range{0.0, 1e3, false, false, "s after wheel.start"});
    if (r.size() != 2 || !(r[1] > r[0])) t.fail(key, "must be [from, to] with to > from (s after wheel.start)");
    from = r[0];
    to = r[1];
  };
  ramp("load_ramp", w.load_from, w.load_to);
  w.speed = t.real("speed", Range{0.0, 1e3, false, false, "m/s (forward, +x)"});
  ramp("speed_ramp", w.speed_from, w.speed_to);
  w.slip = t.real("slip", Range{0.0, 1.0, false, true, "(1 - v / (omega R); 0.2: 20 %)"});
  w.start = t.real("start", Range{0.0, 1e3, false, false, "s (when the wheel is set on the bed)"});
  if (w.start >= duration) t.fail("start", "= " + format_number(w.start) + " s is not before time.duration = " + format_number(duration) + " s");
  w.x_start = t.real("x_start", Range{0.0, 1e3, false, false, "m (the axis' position along the bin)"});
  if (w.x_start <= 0 || w.x_start >= p.bin[0]) t.fail("x_start", "must lie inside the bin, (0, " + format_number(p.bin[0]) + ") m");
  w.y_centre = 0.5 * p.bin[1];
  // where the axis ends: the speed ramp's mean speed during it, then the full speed
  const double run = duration - w.start, ramp_time = std::min(run, w.speed_to) - std::min(run, w.speed_from);
  const double travel = w.speed * (0.5 * ramp_time + std::max(0.0, run - w.speed_to));
  if (w.x_start + travel >= p.bin[0])
    t.fail("speed", "carries the axis to x = " + format_number(w.x_start + travel) + " m by time.duration, past the bin's end " +
                        format_number(p.bin[0]) + " m; lower the speed, the duration or x_start");
  t.finish();
}

// [tyre] (the `fe_tyre` effect, seed 002 paper 2 sec. 4; models/dem/tyre_drive.hpp): the FE tyre's lattice,
// inflation, damping and tread rubber (its size is [wheel]'s radius and width), and its wall ("smeared" or
// "layered").
void read_tyre(const SceneTable& t, dem::TyreInit& y) {
  if (t.has("cells")) {
    const auto cells = t.reals("cells", Range{1.0, 1e5, false, false, "cells"});
    if (cells.size() != 3 || cells[0] < 3 || cells[1] < 2 || cells[0] != std::floor(cells[0]) || cells[1] != std::floor(cells[1]) ||
        cells[2] != std::floor(cells[2]))
      t.fail("cells", "must be three integers [around, across, through] with around >= 3 and across >= 2 (cells round the wheel, along "
                      "the section's contour, through the wall)");
    y.around = static_cast<int>(cells[0]);
    y.across = static_cast<int>(cells[1]);
    y.through = static_cast<int>(cells[2]);
  }
  if (double(y.around) * y.across * y.through > 1e6) t.fail("cells", "makes more than 1e6 cells");
  y.order = static_cast<int>(t.integer("order", y.order, 1, 4));
  y.pressure = t.real("pressure", y.pressure, Range{0.0, 1e8, false, false, "Pa (inflation)"});
  y.inflate_to = t.real("inflate_to", y.inflate_to, Range{1e-6, 1e3, false, false, "s after wheel.start (the inflation's ramp 0 -> pressure)"});
  if (t.has("deflate")) {  // [t0, t1] s after the set-down: the pressure let down to zero (a flat tyre)
    const auto d = t.reals("deflate", Range{0.0, 1e3, false, false, "s after wheel.start"});
    if (d.size() != 2 || !(d[0] >= y.inflate_to) || !(d[1] > d[0]))
      t.fail("deflate", "must be [t0, t1] with inflate_to = " + format_number(y.inflate_to) +
                            " s <= t0 < t1 (s after wheel.start: the pressure ramps from full to zero between them)");
    y.deflate = {d[0], d[1]};
  }
  y.damping = t.real("damping", y.damping, Range{0.0, 1e6, false, false, "1/s (mass-proportional, relative to the rim's rigid motion)"});
  y.tread_young = t.real("tread_youngs_modulus", y.tread_young, pl::modulus());
  y.tread_poisson = t.real("tread_poisson_ratio", y.tread_poisson, Range{-1.0, 0.5, true, true});
  y.mass = t.real("mass", y.mass, pl::mass());
  // the wall's law (models/solid/tyre.hpp): the smeared one (default), the layered wall, or the layered wall with
  // the steel belt as rebar cords over the crown (TyreSpec::belt_rebar)
  const std::string wall = t.choice("wall", {"smeared", "layered", "belted_rebar"}, "smeared");
  y.layered = wall != "smeared";
  y.belt_rebar = wall == "belted_rebar";
  // the inner tread arc's transverse radius R_t (0: the section's default, 0.35 m; a flatter crown is larger)
  y.crown_radius = t.real("crown_radius", y.crown_radius, Range{0.0, 1e3, false, false, "m (0: the default 0.35 m)"});
  // the tyre's steps per DEM step (models/dem/tyre_drive.hpp): 1, one common step (the smaller of the two
  // stable ones); 0, as many as the tyre's stable step needs under the spheres' (subcycling); n, exactly n
  y.substeps = static_cast<int>(t.integer("substeps", y.substeps, 0, 1000));
  if (y.layered && (y.through < 3 || y.through % 2 == 0))
    t.fail("wall", "is \"" + wall + "\", which needs an odd number of cells through the wall >= 3 (cells[2] = " + std::to_string(y.through) +
                       "): rubber, the cord layer in the middle, rubber");
  t.finish();
}

}  // namespace

DemPourScene load_dem_pour_scene(const std::filesystem::path& file, const SceneOptions& options) {
  const std::string& accuracy = options.accuracy;
  const std::string& precision = options.precision;
  DemPourScene out;
  const OpenScene s = open_scene(file, "dem_pour", dem::effect_table(), precision, out);
  const SceneTable& root = s.root;
  s.model.finish();
  if (out.header.precision == "float")
    s.model.fail("precision", "= \"float\": a pour runs in double precision (the clumps' poses and loads are double)");
  out.header.set_accuracy(read_accuracy(root, accuracy, 0.0, "paper"));
  const auto& fx = out.config.effects;
  dem::Config& c = out.config;

  const SceneTable particle = root.table("particle");
  c.particle.young = particle.real("youngs_modulus", pl::modulus());
  c.particle.poisson = particle.real("poisson_ratio", Range{-1.0, 0.5, true, true});
  c.particle.density = particle.real("density", pl::density());
  particle.finish();
  const SceneTable wall = root.table("wall");
  c.wall.young = wall.real("youngs_modulus", pl::modulus());
  c.wall.poisson = wall.real("poisson_ratio", Range{-1.0, 0.5, true, true});
  wall.finish();

  const SceneTable contact = root.table("contact");
  c.restitution = contact.real("restitution", 1.0, Range{1e-3, 1.0, false, false, "(1: elastic)"});
  c.friction = contact.real("friction", 0.0, pl::factor(0.0, 10.0));
  if (c.restitution < 1.0 && !fx.has("damping")) contact.fail("restitution", "< 1 needs the effect \"damping\" in model.effects");
  if (c.friction > 0 && !fx.has("friction")) contact.fail("friction", "> 0 needs the effect \"friction\" in model.effects");
  // a denser bed (docs/METHODS.md "A denser bed: the pour's friction"): a lower mu while the gravel falls and settles
  const bool pour_mu = contact.has("pour_friction");
  if (pour_mu) {
    c.pour_friction = contact.real("pour_friction", pl::factor(0.0, 10.0));
    if (!fx.has("friction")) contact.fail("pour_friction", "needs the effect \"friction\" in model.effects");
  }
  if (contact.has("pour_friction_until") && !pour_mu) contact.fail("pour_friction_until", "is given without contact.pour_friction");
  const double pour_until = pour_mu ? contact.real("pour_friction_until", 0.0, Range{0.0, 1e3, false, false, "s (0: wheel.start)"}) : 0.0;
  contact.finish();
  const auto wheel = root.optional_table("wheel");
  if (fx.has("fe_surfaces") && !wheel)
    s.model.fail("effects", "lists \"fe_surfaces\", but the scene has no [wheel] (the bin is planes; the wheel is the FE surface)");
  for (const char* e : {"rigid_wheel", "fe_tyre"})
    if (fx.has(e) && !wheel)
      s.model.fail("effects", std::string("lists \"") + e + "\", but the scene has no [wheel] table (radius, width, mass, slip, ...)");
  if (fx.has("rigid_wheel") && fx.has("fe_tyre"))
    s.model.fail("effects", "lists both \"rigid_wheel\" and \"fe_tyre\"; the wheel is one or the other");
  if (wheel && !fx.has("rigid_wheel") && !fx.has("fe_tyre"))
    wheel->fail_table("needs the effects \"fe_surfaces\" and \"rigid_wheel\" (or \"fe_tyre\") in model.effects");
  const auto tyre = root.optional_table("tyre");
  if (tyre && !fx.has("fe_tyre")) tyre->fail_table("needs the effect \"fe_tyre\" in model.effects");
  if (tyre) read_tyre(*tyre, c.tyre);

  const SceneTable gravel = root.table("gravel");
  auto& p = out.pour;
  const std::int64_t count = gravel.integer("count", 1, 10000000);
  p.shapes = gravel.strings("shapes", {"cylinder", "cone", "cube"});
  if (p.shapes.empty()) gravel.fail("shapes", "is empty; give one or more of \"cylinder\", \"cone\", \"cube\", \"sphere\"");
  bool clumps = false;
  for (const auto& name : p.shapes) {
    if (name != "cylinder" && name != "cone" && name != "cube" && name != "sphere")
      gravel.fail("shapes", "has \"" + name + "\"; allowed: \"cylinder\", \"cone\", \"cube\" (the paper's gravel) or \"sphere\"");
    clumps = clumps || name != "sphere";
  }
  if (clumps && !fx.has("clumps")) gravel.fail("shapes", "names multi-sphere shapes; they need the effect \"clumps\" in model.effects");
  if (!clumps && fx.has("clumps")) s.model.fail("effects", "lists \"clumps\", but gravel.shapes has spheres only");
  p.radius_min = gravel.real("radius_min", Range{1e-6, 10.0, false, false, "m (a particle's bounding radius)"});
  p.radius_max = gravel.real("radius_max", Range{1e-6, 10.0, false, false, "m (a particle's bounding radius)"});
  if (p.radius_max < p.radius_min) gravel.fail("radius_max", "is smaller than radius_min = " + format_number(p.radius_min));
  p.seed = static_cast<std::uint64_t>(gravel.integer("seed", 1, 0, std::int64_t(1) << 62));
  // the accuracy preset divides the count (draft: / 4, standard: / 2; a sweep's factor likewise)
  p.count = static_cast<int>(std::max<std::int64_t>(1, std::llround(double(count) / out.header.coarsening)));
  gravel.finish();

  const SceneTable bin = root.table("bin");
  const auto size = bin.reals("size", pl::length());
  if (size.size() != 3) bin.fail("size", "must be [lx, ly, lz] (3 lengths), got " + std::to_string(size.size()));
  p.bin = {size[0], size[1], size[2]};
  p.release_at = bin.real("release_at", 0.0, Range{0.0, 1e3, false, false, "s (0: the bin stays closed; > 0: its wall x = lx opens then, a heap forms)"});
  if (p.bin[0] < 2.2 * p.radius_max || p.bin[1] < 2.2 * p.radius_max)
    bin.fail("size", "is narrower than one particle (2.2 x gravel.radius_max = " + format_number(2.2 * p.radius_max) + " m)");
  bin.finish();

  const SceneTable time = root.table("time");
  out.duration = time.real("duration", pl::duration());
  if (wheel) read_wheel(*wheel, p, out.duration, c.wheel);
  if (pour_mu) {  // the pour's friction ends by the set-down (the wheel meets the scene's friction) and within the run
    c.pour_friction_until = pour_until > 0 ? pour_until : (wheel ? c.wheel.start : 0.0);
    if (!(c.pour_friction_until > 0))
      contact.fail("pour_friction_until", "is missing: the time (s) until which contact.pour_friction holds (without a wheel there is no default)");
    if (wheel && c.pour_friction_until > c.wheel.start)
      contact.fail("pour_friction_until", "= " + format_number(c.pour_friction_until) + " s is after wheel.start = " + format_number(c.wheel.start) +
                                              " s: the wheel must meet the scene's friction");
    if (c.pour_friction_until >= out.duration)
      contact.fail("pour_friction_until", "= " + format_number(c.pour_friction_until) + " s is not before time.duration = " + format_number(out.duration) + " s");
  }
  if (tyre && wheel) {  // the tyre's section from the wheel's size and the crown radius (solid::tyre_section)
    const solid::TyreSpec ts = dem::tyre_spec(c.wheel, c.tyre);
    try {
      (void)solid::tyre_section(ts);
    } catch (const std::invalid_argument& e) {
      if (tyre->has("crown_radius")) tyre->fail("crown_radius", "= " + format_number(ts.crown_radius) + " m gives no tyre section: " + e.what());
      wheel->fail("radius", "and wheel.width give no tyre section: " + std::string(e.what()));
    }
  }
  if (p.release_at > 0 && p.release_at >= out.duration)
    bin.fail("release_at", "= " + format_number(p.release_at) + " s is not before time.duration = " + format_number(out.duration) + " s");
  const double dt = time.real("dt", 0.0, Range{0.0, pl::time_step().hi, false, false, "s (0: dt_safety x the limit)"});
  c.dt_safety = time.real("dt_safety", 0.5, Range{0.01, 1.0, false, false, "(a fraction of the time-step limit)"});
  time.finish();
  c.gravity = {0, 0, -9.81};
  if (const auto g = root.optional_table("gravity")) {
    const auto v = g->reals("vector", Range{-1e3, 1e3, false, false, "m/s^2"});
    if (v.size() != 3) g->fail("vector", "must be [gx, gy, gz]");
    c.gravity = {v[0], v[1], v[2]};
    g->finish();
  }
  if (const auto o = root.optional_table("output")) {
    out.snapshots = static_cast<int>(o->integer("snapshots", 10, 0, 10000));
    out.sample_every = o->integer("sample_every", 0, 0, std::int64_t(1) << 30);
    o->finish();
  } else {
    out.snapshots = 10;
  }
  root.finish();

  try {
    auto pour = dem::pour_config(c, p);
    if (c.wheel.enabled()) {
      c.wheel.parked = {c.wheel.x_start, c.wheel.y_centre, dem::pour_top(p) + 3 * p.radius_max + 2 * c.wheel.radius};
      pour.wheel = c.wheel;
      if (fx.has("fe_tyre"))
        pour.tyre = c.tyre;  // its surface is the tyre's own (dem::TyreDrive)
      else
        pour.surface = dem::wheel_surface(c.wheel);
    }
    const double top = dem::pour_top(p);
    if (top > 10 * p.bin[2])
      bin.fail("size", "holds " + std::to_string(p.count) + " particles in layers up to z = " + format_number(top) +
                           " m, more than 10 x its height; widen the bin or pour fewer");
    const auto limit = dem::time_step_limit(pour);
    out.limit = limit;
    if (!(limit.limit > 0) || !std::isfinite(limit.limit)) particle.fail("youngs_modulus", "gives no finite time-step limit");
    c = pour;
    c.dt = dt > 0 ? dt : c.dt_safety * limit.limit;
    if (c.dt > limit.limit) time.fail("dt", "= " + format_number(c.dt) + " s is above the limit " + limit.describe());
  } catch (const std::invalid_argument& e) {
    gravel.fail("count", e.what());
  }
  const double spheres_per_particle = p.shapes.size() == 1 && p.shapes[0] == "sphere" ? 1.0 : 5.0;
  out.steps = static_cast<std::int64_t>(std::ceil(out.duration / c.dt));
  out.cost = dem_cost(spheres_per_particle * p.count, double(out.steps));
  if (fx.has("fe_tyre")) {  // the tyre's explicit steps after the set-down: 3.6e6 DoF-steps/s (docs/VALIDATION.md, the tyre alone)
    const auto& y = c.tyre;
    const double dofs = 3.0 * (y.around * y.order) * (y.across * y.order + 1.0) * (y.through * y.order + 1.0);
    // The tyre's stable step is known only once it is built; estimated here from the measured ones (docs/VALIDATION.md,
    // the tyre alone: 0.9 x 1.07e-5 s for one order-2 cell through the smeared wall; it scales with the node spacing
    // through the wall, 1 / (through x order), and the layered walls' cord layer takes 0.72 of it: 2.36e-6 s at 3
    // cells, measured 2.355e-6). substeps 1 (one common step): the smaller step sets the count; 0: as many tyre
    // steps per DEM step as it needs; n: n.
    const double tyre_dt = 0.9 * 1.07e-5 * 2.0 / (y.through * y.order) * (y.layered ? 0.72 : 1.0);
    const double common = std::min(c.dt, tyre_dt);
    const double per_dem = y.substeps == 1 ? 1.0 : y.substeps == 0 ? std::max(1.0, std::ceil(c.dt / tyre_dt)) : double(y.substeps);
    const double dem_dt = y.substeps == 1 ? common : c.dt;
    out.cost.seconds *= c.dt / dem_dt;  // the spheres step at the common step too
    out.cost.seconds += (out.duration - c.wheel.start) / dem_dt * per_dem * dofs / 3.6e6;
    out.cost.bytes += dofs * 60.0 * 8.0;
    out.cost.rate += "; the tyre's " + format_number(dofs) + " DoFs at 3.6e6 DoF-steps/s after the set-down";
    // the rim steps with the tyre (its estimated step; the model checks the exact one)
    if (const auto bad = c.wheel.damping_problem(dem_dt / per_dem); !bad.empty()) wheel->fail("damping", bad);
  } else if (wheel) {
    if (const auto bad = c.wheel.damping_problem(c.dt); !bad.empty()) wheel->fail("damping", bad);
  }
  out.cost.size_keys = {"gravel.count = " + std::to_string(count) + " (" + std::to_string(p.count) + " at accuracy '" +
                            out.header.accuracy + "')",
                        "time.duration = " + format_number(out.duration) + " s", "dt = " + format_number(c.dt) + " s"};
  check_size(out.cost, gravel);
  if (out.sample_every == 0)  // with a wheel: 400 samples of its drive (the histories of Figs. 8-10)
    out.sample_every = std::max<std::int64_t>(
        1, c.wheel.enabled() ? static_cast<std::int64_t>((out.duration - c.wheel.start) / c.dt / 400) : static_cast<std::int64_t>(out.cost.steps / 200));
  // the tyre's stable step may be the smaller one: without time.dt the model takes the smaller of the spheres'
  // (the estimate above) and the tyre's, and the app counts the steps from it
  if (fx.has("fe_tyre") && !(dt > 0)) c.dt = 0.0;
  return out;
}

}  // namespace polymech::io
