#include "io/mps_elastic_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "mps_elastic/mps_elastic.hpp"

namespace polymech::io {

namespace me = polymech::mps_elastic;

namespace {

std::string names_of(const std::vector<me::Probe>& probes) {
  std::string s;
  for (const auto& p : probes) s += (s.empty() ? "" : ", ") + p.name;
  return s.empty() ? "(none)" : s;
}

// Two probe names that exist in [[probes]].
std::vector<std::string> probe_pair(const SceneTable& t, const std::string& key, const std::vector<me::Probe>& probes) {
  auto names = t.strings(key, {});
  if (names.empty()) return names;
  if (names.size() != 2) t.fail(key, "must name exactly two probes (near, far) on one ray from the source");
  for (const auto& n : names)
    if (std::none_of(probes.begin(), probes.end(), [&](const me::Probe& p) { return p.name == n; }))
      t.fail(key, "names probe '" + n + "', which is not in [[probes]]; probes: " + names_of(probes));
  if (names[0] == names[1]) t.fail(key, "names the same probe twice");
  return names;
}

}  // namespace

Point2 excitation_source_point(const me::Config& c) {
  const me::Lattice lat = me::make_lattice(c);
  Point2 p;
  p.x1 = c.excitation.position < 0 ? 0.5 * c.width : c.excitation.position;
  p.x3 = (static_cast<double>(lat.ny) - 0.5) * c.spacing;  // the top row
  return p;
}

MpsElasticScene load_mps_elastic_scene(const std::filesystem::path& file, const MpsSceneOptions& options) {
  const Scene scene = Scene::load(file);
  const SceneTable root = scene.root();
  MpsElasticScene out;
  out.file = file;
  out.title = root.string("title", file.stem().string());
  me::Config& c = out.config;

  // [model]
  const SceneTable model = root.table("model");
  model.choice("kind", {"mps_elastic"});
  const auto effects = model.strings("effects", {});
  try {
    c.effects = EffectSet::resolve(effects, me::MpsElastic<double>::effects());
  } catch (const EffectError& e) {
    model.fail("effects", std::string("is invalid: ") + e.what());
  }
  out.precision = model.choice("precision", {"double", "float"}, "double");
  model.finish();

  // [accuracy]: preset name -> spacing factor
  std::map<std::string, double> factors = {{"draft", 4.0}, {"standard", 2.0}, {"paper", 1.0}};
  std::string preset = "draft";
  if (auto acc = root.optional_table("accuracy")) {
    preset = acc->choice("default", accuracy_presets(), preset);
    for (auto& [name, f] : factors) f = acc->real(name, f, between(1.0, 64.0));
    acc->finish();
  }
  if (!options.accuracy.empty()) {
    if (!factors.count(options.accuracy)) {
      std::string allowed;
      for (const auto& n : accuracy_presets()) allowed += (allowed.empty() ? "" : ", ") + n;
      throw SceneError(file.string() + ": accuracy '" + options.accuracy + "' is unknown; allowed: " + allowed);
    }
    preset = options.accuracy;
  }
  out.accuracy = preset;
  out.coarsening = options.coarsening > 0 ? options.coarsening : factors.at(preset);
  if (!options.precision.empty()) {
    if (options.precision != "double" && options.precision != "float")
      throw SceneError(file.string() + ": precision '" + options.precision + "' is unknown; allowed: double, float");
    out.precision = options.precision;
  }
  const double f = out.coarsening;

  // [domain]
  const SceneTable domain = root.table("domain");
  c.width = domain.real("width", positive());
  c.height = domain.real("height", positive());
  const double spacing = domain.real("spacing", positive());
  c.influence_radius = domain.real("influence_radius", 2.1, above(1.0));
  const std::string nd = domain.choice("number_density", {"mean", "interior"}, "mean");
  c.number_density = nd == "mean" ? me::NumberDensityReference::mean : me::NumberDensityReference::interior;
  c.spacing = spacing * f;
  if (c.spacing > c.width || c.spacing > c.height)
    domain.fail("spacing", "= " + format_number(spacing) + " m (x " + format_number(f) + " at accuracy '" + preset +
                               "') is larger than the domain (" + format_number(c.width) + " x " +
                               format_number(c.height) + " m); allowed: 0 < spacing <= min(width, height) / " +
                               format_number(f));
  domain.finish();

  // [material]
  const SceneTable material = root.table("material");
  c.density = material.real("density", positive());
  c.c55 = material.real("c55", positive());
  c.c13 = material.real("c13", above(-c.c55));  // lambda > -mu: positive-definite plane-strain stiffness
  c.inertia_factor = material.real("inertia_factor", 1.0 / 6.0, positive());
  material.finish();

  // [time]
  const SceneTable time = root.table("time");
  const double dt = time.real("dt", positive());
  const std::int64_t steps = time.integer("steps", 1, std::int64_t(1) << 40);
  c.dt = dt * f;
  c.steps = options.steps > 0 ? options.steps : std::max<std::int64_t>(1, std::llround(static_cast<double>(steps) / f));
  time.finish();

  // [excitation]
  if (auto ex = root.optional_table("excitation")) {
    const std::string kind = ex->choice("kind", {"none", "point", "plane_p", "plane_s"});
    c.excitation.kind = kind == "none"      ? me::ExcitationKind::none
                        : kind == "point"   ? me::ExcitationKind::point
                        : kind == "plane_p" ? me::ExcitationKind::plane_p
                                            : me::ExcitationKind::plane_s;
    c.excitation.amplitude = ex->real("amplitude", 10.0e-9, positive());
    c.excitation.period = ex->real("period", 5.0e-7, positive());
    c.excitation.cycles = ex->real("cycles", kind == "point" ? 1.0 : 5.0, between(0.25, 1000.0));
    c.excitation.position = ex->real("position", 0.5 * c.width, between(0.0, c.width));
    c.excitation.width = ex->real("width", 0.0, between(0.0, c.width));
    if (c.excitation.period < 4.0 * c.dt)
      ex->fail("period", "= " + format_number(c.excitation.period) + " s is shorter than 4 time steps (dt = " +
                             format_number(c.dt) + " s at accuracy '" + preset + "'); the pulse would not be resolved");
    ex->finish();
  } else {
    c.excitation.kind = me::ExcitationKind::none;
  }

  // [[probes]]
  std::vector<SceneTable> probe_tables = root.tables("probes");
  for (const auto& p : probe_tables) {
    me::Probe probe;
    probe.name = p.string("name");
    probe.x1 = p.real("x1", Range{});
    probe.x3 = p.real("x3", Range{});
    if (!between(0.0, c.width).contains(probe.x1))
      p.fail("x1", "= " + format_number(probe.x1) + " puts probe '" + probe.name +
                       "' outside the domain; allowed: 0 <= x1 <= width = " + format_number(c.width));
    if (!between(0.0, c.height).contains(probe.x3))
      p.fail("x3", "= " + format_number(probe.x3) + " puts probe '" + probe.name +
                       "' outside the domain; allowed: 0 <= x3 <= height = " + format_number(c.height));
    for (const auto& q : c.probes)
      if (q.name == probe.name) p.fail("name", "= \"" + probe.name + "\" is used by two probes; names must be unique");
    p.finish();
    c.probes.push_back(probe);
  }

  // [analysis]
  if (auto an = root.optional_table("analysis")) {
    out.p_wave_probes = probe_pair(*an, "p_wave_probes", c.probes);
    out.s_wave_probes = probe_pair(*an, "s_wave_probes", c.probes);
    an->finish();
  }

  // [output]
  if (auto o = root.optional_table("output")) {
    const std::int64_t every = o->integer("snapshot_every", 0, 0, std::int64_t(1) << 40);
    out.snapshot_every = every > 0 ? std::max<std::int64_t>(1, std::llround(static_cast<double>(every) / f)) : 0;
    c.probe_every = o->integer("probe_every", 1, 1, 1 << 20);
    o->finish();
  }
  root.finish();

  // The stability limit of this resolution (seed 000 eqs. (13)-(16) are explicit): refused before
  // anything is allocated at full size.
  out.stable_dt = me::MpsElastic<double>::stable_time_step(c);
  if (c.dt > out.stable_dt)
    time.fail("dt", "= " + format_number(dt) + " s (x " + format_number(f) + " = " + format_number(c.dt) +
                        " s at accuracy '" + preset + "') is above the stability limit " + format_number(out.stable_dt) +
                        " s of spacing " + format_number(c.spacing) + " m; allowed: 0 < dt <= " +
                        format_number(out.stable_dt / f) + " s");
  return out;
}

}  // namespace polymech::io
