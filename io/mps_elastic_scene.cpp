#include "io/mps_elastic_scene.hpp"

#include "io/ranges.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace polymech::io {

namespace me = polymech::mps_elastic;
namespace pl = polymech::io::plausible;

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

MpsElasticScene load_mps_elastic_scene(const std::filesystem::path& file, const MpsSceneOptions& options) {
  MpsElasticScene out;
  const OpenScene s = open_scene(file, "mps_elastic", me::effect_table(), options.precision, out);
  const SceneTable& root = s.root;
  const SceneTable& model = s.model;
  me::Config& c = out.config;
  model.finish();

  // [accuracy]: preset name -> spacing factor
  out.header.set_accuracy(read_accuracy(root, options.accuracy, options.coarsening));
  const double f = out.header.coarsening;
  const std::string& accuracy = out.header.accuracy;

  // [domain]
  const SceneTable domain = root.table("domain");
  c.width = domain.real("width", pl::length());
  c.height = domain.real("height", pl::length());
  const double spacing = domain.real("spacing", pl::spacing());
  c.influence_radius = domain.real("influence_radius", 2.1, Range{1.0, 5.0, true, false, "spacings"});
  const std::string nd = domain.choice("number_density", {"mean", "interior"}, "mean");
  c.number_density = nd == "mean" ? me::NumberDensityReference::mean : me::NumberDensityReference::interior;
  c.spacing = spacing * f;
  if (c.spacing > c.width || c.spacing > c.height)
    domain.fail("spacing", "= " + format_number(spacing) + " m (x " + format_number(f) + " at accuracy '" + accuracy +
                               "') is larger than the domain (" + format_number(c.width) + " x " +
                               format_number(c.height) + " m); allowed: 0 < spacing <= min(width, height) / " +
                               format_number(f));
  domain.finish();

  // The size of the run, refused before anything is computed over the lattice if it cannot fit.
  me::Lattice lattice = me::make_lattice(c);  // again after a [crop]
  const auto size_keys = [&] {
    return std::vector<std::string>{"domain.width = " + format_number(c.width) + " m",
                                    "domain.height = " + format_number(c.height) + " m",
                                    "domain.spacing = " + format_number(spacing) + " m (x " + format_number(f) +
                                        " at accuracy '" + accuracy + "')",
                                    "domain.influence_radius = " + format_number(c.influence_radius)};
  };
  const auto cost = [&](double steps, int runs) {
    CostEstimate e = mps_cost(static_cast<double>(lattice.nx) * static_cast<double>(lattice.ny), c.influence_radius,
                              c.effects.has("rotation"), out.header.precision == "float", steps, runs);
    e.size_keys = size_keys();
    return e;
  };
  check_size(cost(0.0, 1), domain);

  // [material]
  const SceneTable material = root.table("material");
  c.density = material.real("density", pl::density());
  c.c55 = material.real("c55", pl::modulus());
  // lambda > -mu: positive-definite plane-strain stiffness
  c.c13 = material.real("c13", Range{-c.c55, pl::modulus().hi, true, false, "Pa (> -c55: a positive-definite stiffness)"});
  c.inertia_factor = material.real("inertia_factor", 1.0 / 6.0, pl::factor(1e-6, 10.0));
  material.finish();
  {
    const double cp = std::sqrt((c.c13 + 2.0 * c.c55) / c.density);
    if (!pl::wave_speed().contains(cp))
      material.fail("density", "= " + format_number(c.density) + " kg/m^3 with c13 = " + format_number(c.c13) +
                                   " Pa and c55 = " + format_number(c.c55) + " Pa gives the P-wave speed sqrt((c13 + 2 c55) / density) = " +
                                   format_number(cp) + " m/s; allowed: a wave speed " + pl::wave_speed().text());
  }

  // [time]
  const SceneTable time = root.table("time");
  const double dt = time.real("dt", pl::time_step());
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
    c.excitation.amplitude = ex->real("amplitude", 10.0e-9, pl::amplitude());
    c.excitation.period = ex->real("period", 5.0e-7, pl::duration());
    c.excitation.cycles = ex->real("cycles", kind == "point" ? 1.0 : 5.0, between(0.25, 1000.0));
    c.excitation.position = ex->real("position", 0.5 * c.width, between(0.0, c.width));
    c.excitation.width = ex->real("width", 0.0, between(0.0, c.width));
    if (c.excitation.period < 4.0 * c.dt)
      ex->fail("period", "= " + format_number(c.excitation.period) + " s is shorter than 4 time steps (dt = " +
                             format_number(c.dt) + " s at accuracy '" + accuracy + "'); the pulse would not be resolved");
    ex->finish();
  } else {
    c.excitation.kind = me::ExcitationKind::none;
  }

  // [crack]: a straight crack whose bonds are cut (seed 000 §4); contact by the crack_contact effects
  const auto cr = root.optional_table("crack");
  if (cr) {
    auto& k = c.crack;
    k.mode = me::CrackMode::cut;
    k.x1 = cr->real("x1", between(0.0, c.width));
    k.x3 = cr->real("x3", between(0.0, c.height));
    k.length = cr->real("length", pl::length());
    k.angle = cr->real("angle", 0.0, between(-180.0, 180.0));
    k.k_prime = cr->real("k_prime", 0.1, Range{1e-6, 2.0, false, true});
    k.mu_s = cr->real("mu_s", 0.74, pl::factor(0.0, 10.0));
    k.mu_d = cr->real("mu_d", 0.57, between(0.0, k.mu_s));
    k.normal_reaction = cr->real("normal_reaction", 0.0, Range{0.0, 1e12, false, false, "N/m"});
    out.normal_reaction_ratio = cr->real("normal_reaction_ratio", 0.0, pl::factor(0.0, 1e3));
    k.contact_radius = cr->real("contact_radius", 1.0001, between(1.0, 3.0));
    if (k.length < c.spacing)
      cr->fail("length", "= " + format_number(k.length) + " m is shorter than the spacing " + format_number(c.spacing) +
                             " m at accuracy '" + accuracy + "': the crack would cut no bond; allowed: length >= spacing");
    if (c.effects.has("crack_contact.slip") && !c.effects.has("crack_contact.open_close") &&
        !(k.normal_reaction > 0) && !(out.normal_reaction_ratio > 0))
      cr->fail("normal_reaction", "is needed by effect crack_contact.slip without crack_contact.open_close (nothing "
                                  "else presses the faces together); give normal_reaction > 0 [N/m per pair] or "
                                  "normal_reaction_ratio > 0");
    cr->finish();
  } else if (c.effects.has("crack_contact.open_close") || c.effects.has("crack_contact.slip")) {
    model.fail("effects", "lists a crack_contact effect, but the scene has no [crack] table");
  }

  // [[probes]]
  std::vector<SceneTable> probe_tables = root.tables("probes");
  for (const auto& p : probe_tables) {
    me::Probe probe;
    probe.name = p.string("name");
    probe.x1 = p.real("x1", pl::coordinate());
    probe.x3 = p.real("x3", pl::coordinate());
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
  const auto an = root.optional_table("analysis");
  if (an) {
    out.p_wave_probes = probe_pair(*an, "p_wave_probes", c.probes);
    out.s_wave_probes = probe_pair(*an, "s_wave_probes", c.probes);
    out.harmonics_probe = an->string("harmonics_probe", "");
    out.harmonics_component = an->choice("harmonics_component", {"u1", "u3"}, "u3");
    if (!out.harmonics_probe.empty() &&
        std::none_of(c.probes.begin(), c.probes.end(), [&](const me::Probe& p) { return p.name == out.harmonics_probe; }))
      an->fail("harmonics_probe", "names probe '" + out.harmonics_probe + "', which is not in [[probes]]; probes: " +
                                      names_of(c.probes));
    an->finish();
  }
  // a crack scene runs in mps_harmonics, which analyses one probe's spectrum
  if (cr && out.harmonics_probe.empty()) {
    const std::string what = "a scene with a [crack] runs in mps_harmonics, which needs analysis.harmonics_probe (one of: " +
                             names_of(c.probes) + ")";
    if (an) an->fail("harmonics_probe", "is missing or empty; " + what);
    cr->fail_table("needs [analysis] harmonics_probe: " + what);
  }

  // [crop]: the reduced-size crack case of the accuracy-cost sweep (bench/sweep_mps_harmonics, `polymech plan`):
  // the plate cut down around the crack (mps_elastic::crop_around_crack: the crack centred across `width`,
  // `depth` of plate above it, `below` under it; probes keep their offsets, those outside are dropped) and
  // the run ended when the burst has passed the harmonics probe (the [time] steps are then not used)
  if (auto cp = root.optional_table("crop")) {
    if (!cr) cp->fail_table("needs a [crack] to crop around");
    const double width = cp->real("width", pl::length());
    const double depth = cp->real("depth", pl::length());
    const double below = cp->real("below", pl::length());
    cp->finish();
    if (width < c.crack.length + 4 * c.spacing)
      cp->fail("width", "= " + format_number(width) + " m leaves no plate beside the crack (length " +
                            format_number(c.crack.length) + " m); allowed: width >= crack length + 4 spacings");
    me::crop_around_crack(c, width, depth, below);
    if (std::none_of(c.probes.begin(), c.probes.end(), [&](const me::Probe& p) { return p.name == out.harmonics_probe; }))
      cp->fail_table("drops the harmonics probe '" + out.harmonics_probe + "' (outside the cropped plate); allowed: a crop "
                     "that keeps it (depth and below around the crack)");
    lattice = me::make_lattice(c);
    check_size(cost(0.0, 1), *cp);  // a crop larger than the plate is refused like a plate too large
    if (options.steps <= 0) c.steps = me::steps_until_burst_passes(c, out.harmonics_probe);
  }

  // [output]
  if (auto o = root.optional_table("output")) {
    const std::int64_t every = o->integer("snapshot_every", 0, 0, std::int64_t(1) << 40);
    out.snapshot_every = every > 0 ? std::max<std::int64_t>(1, std::llround(static_cast<double>(every) / f)) : 0;
    c.probe_every = o->integer("probe_every", 1, 1, 1 << 20);
    o->finish();
  }
  root.finish();

  // The crack must cut bonds, and with contact effects it must have contact pairs.
  if (c.crack.mode != me::CrackMode::none) {
    const auto cut = out.header.precision == "float" ? me::crack_crossings<float>(c) : me::crack_crossings<double>(c);
    const auto pairs = std::count_if(cut.begin(), cut.end(), [&](const me::CrackCrossing& x) { return me::is_contact_pair(x, c); });
    if (cut.empty())
      cr->fail_table("cuts no bond at spacing " + format_number(c.spacing) +
                     " m (is it outside the plate, or shorter than the gap between particle rows?); allowed: a crack "
                     "across at least one bond (crack.x1, crack.x3, crack.length, crack.angle)");
    if (pairs == 0 && (c.effects.has("crack_contact.open_close") || c.effects.has("crack_contact.slip")))
      cr->fail("contact_radius", "= " + format_number(c.crack.contact_radius) +
                                     " spacings gives no contact pair (no cut bond is that short); allowed: a radius "
                                     "that reaches the shortest cut bond");
  }

  // The stability limit of this resolution (seed 000 eqs. (13)-(16) are explicit): refused before
  // anything is allocated at full size.
  out.stable_dt = me::stable_time_step(c);
  if (!(out.stable_dt > 0) || !std::isfinite(out.stable_dt))
    material.fail_table("gives no finite stable time step (" + format_number(out.stable_dt) +
                        " s) at spacing " + format_number(c.spacing) + " m; allowed: material constants in the plausible ranges "
                        "whose combination is a stable solid");
  if (c.dt > out.stable_dt)
    time.fail("dt", "= " + format_number(dt) + " s (x " + format_number(f) + " = " + format_number(c.dt) +
                        " s at accuracy '" + accuracy + "') is above the stability limit " + format_number(out.stable_dt) +
                        " s of spacing " + format_number(c.spacing) + " m; allowed: 0 < dt <= " +
                        format_number(out.stable_dt / f) + " s");
  out.cost = cost(static_cast<double>(c.steps), c.crack.mode == me::CrackMode::none ? 1 : 2);
  return out;
}

}  // namespace polymech::io
