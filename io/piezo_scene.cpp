#include "io/piezo_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include "io/ranges.hpp"

namespace polymech::io {

namespace {

const std::vector<std::string> kMaterials = {"pzt5a", "pvdf", "brass"};
const std::vector<std::string> kElectrodeKinds = {"floating", "grounded", "prescribed"};

Range metres(const char* what) { return Range{1e-7, 1e2, false, false, std::string("m (") + what + ")"}; }
Range volts() { return Range{-1e6, 1e6, false, false, "V"}; }
Range ohms() { return Range{1e-6, 1e15, false, false, "ohm"}; }

int coarsened(std::int64_t n, double f, int floor) {
  return std::max(floor, static_cast<int>(std::ceil(static_cast<double>(n) / f - 1e-9)));
}

// The thickness plane index (0 = bottom, layers = top) of a surface name, or -1.
int surface_index(const std::string& s, int layers) {
  if (s == "bottom") return 0;
  if (s == "top") return layers;
  if (s.rfind("interface ", 0) == 0) {
    const std::string k = s.substr(10);
    if (k.empty() || k.size() > 4 || k.find_first_not_of("0123456789") != std::string::npos) return -1;
    const int i = std::stoi(k);
    return i >= 1 && i < layers ? i : -1;
  }
  return -1;
}

void read_beam(const SceneTable& t, piezo::HarvesterSetup& c, double f) {
  c.length = t.real("length", metres("the cantilever's length"));
  c.width = t.real("width", metres("the beam's width"));
  c.dim = static_cast<int>(t.integer("dim", 2, 2, 3));
  if (c.dim == 2) {
    c.plane = t.choice("plane", {"stress", "strain"}, "stress");
  } else if (t.has("plane")) {
    t.fail("plane", "applies to 2D beams only (dim = 2); a 3D beam has no plane assumption");
  }
  c.conducting_host = t.boolean("conducting_host", true);
  c.support = t.choice("support", {"clamped", "free"}, "clamped");
  const auto layers = t.tables("layers");
  if (layers.empty()) t.fail("layers", "is missing; give the layers bottom to top as [[beam.layers]] tables");
  if (layers.size() > 16) t.fail("layers", "has " + std::to_string(layers.size()) + " layers; allowed: at most 16");
  std::string piezo, piezo_layer;
  std::set<std::string> names;
  for (const auto& l : layers) {
    piezo::HarvesterLayer h;
    h.name = l.string("name");
    if (!names.insert(h.name).second) l.fail("name", "= \"" + h.name + "\" names two layers; each layer needs its own name");
    h.thickness = l.real("thickness", metres("the layer's thickness"));
    h.material = l.choice("material", kMaterials);
    if (h.piezoelectric()) {
      const auto p = l.integer("poling", 1, -1, 1);
      if (p == 0) l.fail("poling", "= 0 is not allowed; allowed: +1 (poled along +thickness) or -1");
      h.poling = static_cast<int>(p);
      if (piezo.empty()) {
        piezo = h.material;
        piezo_layer = h.name;
      } else if (h.material != piezo) {
        l.fail("material", "= \"" + h.material + "\": the beam has one piezoelectric law and layer '" + piezo_layer +
                               "' is \"" + piezo + "\"; allowed: \"" + piezo + "\" or \"brass\"");
      }
    } else if (l.has("poling")) {
      l.fail("poling", "applies to piezoelectric layers (\"pzt5a\", \"pvdf\"); a \"brass\" layer is elastic");
    }
    h.cells = coarsened(l.integer("cells", 1, 1, 1000), f, 1);
    l.finish();
    c.layers.push_back(h);
  }
  if (piezo.empty()) t.fail("layers", "has no piezoelectric layer; allowed materials of one: \"pzt5a\", \"pvdf\"");
  double total = 0.0;
  for (const auto& l : c.layers) total += l.thickness;
  if (!(total < c.length))
    t.fail("length", "= " + format_number(c.length) + " m is not longer than the layers' " + format_number(total) +
                         " m together; allowed: length > the beam's thickness");
  t.finish();
}

void read_electrodes(const SceneTable& root, piezo::HarvesterSetup& c, const std::string& analysis) {
  const int nl = static_cast<int>(c.layers.size());
  std::vector<std::string> surfaces = {"bottom", "top"};
  for (int k = 1; k < nl; ++k) surfaces.push_back("interface " + std::to_string(k));
  std::set<std::string> names;
  std::vector<int> used(static_cast<std::size_t>(nl) + 1, 0);
  for (const auto& e : root.tables("electrodes")) {
    piezo::HarvesterElectrode h;
    h.name = e.string("name");
    if (!names.insert(h.name).second) e.fail("name", "= \"" + h.name + "\" names two electrodes; each needs its own name");
    const std::string s = e.string("surface");
    const int k = surface_index(s, nl);
    if (k < 0) {
      std::string list;
      for (const auto& x : surfaces) list += (list.empty() ? "\"" : ", \"") + x + "\"";
      e.fail("surface", "= \"" + s + "\" is not a surface of this " + std::to_string(nl) + "-layer beam; allowed: " + list);
    }
    if (used[static_cast<std::size_t>(k)]) e.fail("surface", "= \"" + s + "\" already carries an electrode; one per surface");
    used[static_cast<std::size_t>(k)] = 1;
    h.surface = s;
    h.kind = e.choice("kind", kElectrodeKinds, "floating");
    if (h.name == "ground" && h.kind != "grounded")
      e.fail("name", "= \"ground\" is the circuit's ground: allowed for a kind = \"grounded\" electrode only; choose another name");
    if (h.kind == "prescribed") {
      if (analysis != "static")
        e.fail("kind", "= \"prescribed\" applies to analysis.kind = \"static\"; a " + analysis +
                           " run has a circuit: allowed \"floating\" or \"grounded\"");
      h.potential = e.real("potential", volts());
    } else if (e.has("potential")) {
      e.fail("potential", "applies to kind = \"prescribed\" electrodes; a " + h.kind + " electrode's potential is " +
                              (h.kind == "grounded" ? "0 V" : "solved for"));
    }
    // an electrode on a face of a conducting (grounded) layer can only be grounded (eq. (7))
    const bool below_host = k > 0 && !c.layers[static_cast<std::size_t>(k - 1)].piezoelectric();
    const bool above_host = k < nl && !c.layers[static_cast<std::size_t>(k)].piezoelectric();
    if (c.conducting_host && h.kind != "grounded" && (below_host || above_host))
      e.fail("kind", "= \"" + h.kind + "\": surface \"" + s +
                         "\" touches the grounded conducting host (beam.conducting_host, eq. (7)); allowed: \"grounded\", "
                         "or beam.conducting_host = false");
    e.finish();
    c.electrodes.push_back(h);
  }
}

void read_circuit(const SceneTable& root, piezo::HarvesterSetup& c, const std::string& analysis) {
  const auto t = root.optional_table("circuit");
  if (!t) return;
  if (analysis == "static")
    t->fail_table("means nothing to analysis.kind = \"static\" (the floating electrodes are charge-free); remove it or "
                  "run a harmonic or transient analysis");
  std::vector<std::string> allowed = {"ground"};
  std::vector<std::string> grounded;
  for (const auto& e : c.electrodes) (e.kind == "floating" ? allowed : grounded).push_back(e.name);
  for (const auto& r : t->tables("resistors")) {
    piezo::HarvesterResistor h;
    for (const char* key : {"from", "to"}) {
      const std::string v = r.string(key);
      if (v != "ground" && std::find(grounded.begin(), grounded.end(), v) != grounded.end())
        r.fail(key, "= \"" + v + "\" is a grounded electrode; write \"ground\"");
      if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        std::string list;
        for (const auto& x : allowed) list += (list.empty() ? "\"" : ", \"") + x + "\"";
        r.fail(key, "= \"" + v + "\" is not a floating electrode; allowed: " + list);
      }
      (std::string(key) == "from" ? h.from : h.to) = v;
    }
    if (h.from == h.to) r.fail("to", "= \"" + h.to + "\" is the resistor's other end too; a resistor joins two terminals");
    h.ohm = r.real("ohm", ohms());
    r.finish();
    c.resistors.push_back(h);
  }
  t->finish();
}

void read_damping(const SceneTable& root, piezo::HarvesterSetup& c) {
  const auto t = root.optional_table("damping");
  if (!t) return;
  if (t->has("zeta")) {
    c.zeta = t->real("zeta", Range{0.0, 1.0, true, true, "(the damping ratio at the short-circuit frequency)"});
    for (const char* k : {"alpha", "beta"})
      if (t->has(k)) t->fail(k, "and damping.zeta exclude each other: give zeta, or alpha and beta");
  } else {
    c.alpha = t->real("alpha", 0.0, Range{0.0, 1e9, false, false, "1/s (mass-proportional Rayleigh damping)"});
    c.beta = t->real("beta", 0.0, Range{0.0, 1.0, false, false, "s (stiffness-proportional Rayleigh damping)"});
  }
  t->finish();
}

// analysis.frequency: "resonance" or a number of Hz.
double read_frequency(const SceneTable& t) {
  const Range hz{1e-3, 1e9, false, false, "Hz"};
  if (!t.has("frequency")) return 0.0;
  try {
    return t.real("frequency", hz);
  } catch (const SceneError& e) {
    if (std::string(e.what()).find("must be a number, got") == std::string::npos) throw;
  }
  try {
    t.choice("frequency", {"resonance"});
  } catch (const SceneError&) {
    t.fail("frequency", "must be \"resonance\" (the FE short-circuit frequency) or a number " + hz.text());
  }
  return 0.0;
}

void read_analysis(const SceneTable& t, piezo::HarvesterSetup& c, const std::string& kind, double f) {
  piezo::HarvesterAnalysis& a = c.analysis;
  a.kind = kind;
  auto refuse = [&](std::initializer_list<const char*> keys, const char* belongs) {
    for (const char* k : keys)
      if (t.has(k)) t.fail(k, std::string("applies to analysis.kind = \"") + belongs + "\", not \"" + kind + "\"");
  };
  if (kind == "static") {
    refuse({"loads", "load_range", "load_points", "points", "fmin", "fmax"}, "harmonic");
    refuse({"frequency", "periods", "steps_per_period", "scheme", "average_periods", "sample_every", "base_acceleration"},
           "transient");
    return;
  }
  a.base_acceleration = t.real("base_acceleration", 9.81, Range{1e-9, 1e6, false, false, "m/s^2 (the amplitude of a_b)"});
  if (kind == "harmonic") {
    refuse({"frequency", "periods", "steps_per_period", "scheme", "average_periods", "sample_every"}, "transient");
    if (t.has("loads") && t.has("load_range")) t.fail("load_range", "and analysis.loads exclude each other: give one");
    if (t.has("loads")) {
      a.loads = t.reals("loads", ohms());
      if (a.loads.empty()) t.fail("loads", "is empty; give at least one load (ohm)");
      if (a.loads.size() > 10000) t.fail("loads", "has more than 10 000 loads");
    } else if (t.has("load_range")) {
      const auto r = t.reals("load_range", ohms());
      if (r.size() != 2 || !(r[1] > r[0])) t.fail("load_range", "must be [lo, hi] with lo < hi (ohm)");
      const int n = static_cast<int>(t.integer("load_points", 2, 10000));
      for (int i = 0; i < n; ++i) a.loads.push_back(r[0] * std::pow(r[1] / r[0], static_cast<double>(i) / (n - 1)));
    } else if (t.has("load_points")) {
      t.fail("load_points", "needs analysis.load_range = [lo, hi]");
    }
    if (a.loads.empty() && c.resistors.empty())
      t.fail_table("a harmonic sweep needs a load: analysis.loads, analysis.load_range or [circuit] resistors");
    const auto points = t.integer("points", 200, 1, 100000);
    a.points = std::max(coarsened(points, f, 1), std::min<int>(11, static_cast<int>(points)));
    a.fmin = t.real("fmin", 0.0, Range{0.0, 1e9, false, false, "Hz (0: 0.9 f_sc of the FE model)"});
    a.fmax = t.real("fmax", 0.0, Range{0.0, 1e9, false, false, "Hz (0: 1.1 f_oc of the FE model)"});
    if (a.fmin > 0 && a.fmax > 0 && !(a.fmax > a.fmin))
      t.fail("fmax", "= " + format_number(a.fmax) + " is out of range: must be > analysis.fmin = " + format_number(a.fmin) + " Hz");
    if (!a.loads.empty() && c.resistors.empty())
      t.fail("loads", "needs a load resistor to vary: add [circuit] resistors = [{ from, to, ohm }] (the first is the load)");
    return;
  }
  refuse({"loads", "load_range", "load_points", "points", "fmin", "fmax"}, "harmonic");
  a.frequency = read_frequency(t);
  a.periods = t.real("periods", Range{0.0, 1e6, true, false, "(periods of the excitation)"});
  // not coarsened by the preset: at resonance Newmark's period error (w dt)^2 / 12 detunes the drive by that
  // fraction, which must stay well below zeta (20 steps per period: -22 % of the steady amplitude at zeta 0.01)
  a.steps_per_period = static_cast<int>(t.integer("steps_per_period", 80, 4, 100000));
  a.scheme = t.choice("scheme", {"monolithic", "partitioned"}, "monolithic");
  a.average_periods = static_cast<int>(t.integer("average_periods", 2, 1, 1000000));
  if (!(a.average_periods <= a.periods))
    t.fail("average_periods", "= " + std::to_string(a.average_periods) + " is out of range: must be <= analysis.periods = " +
                                  format_number(a.periods));
  a.sample_every = static_cast<int>(t.integer("sample_every", 1, 1, 1000000));
  if (a.steps() < 1) t.fail("periods", "= " + format_number(a.periods) + " gives no step at " + std::to_string(a.steps_per_period) + " steps per period");
  if (a.steps() > 1000000000LL) t.fail("periods", "= " + format_number(a.periods) + " gives more than 1e9 steps");
}

}  // namespace

// Rates measured with apps/piezo_harvester on one core (notes h-pzapp-docs): the sparse LU of the bordered
// coupled matrix and one solve per step or frequency.
CostEstimate piezo_cost(const piezo::HarvesterSetup& s, double unknowns) {
  CostEstimate c;
  c.method = "FE piezoelectric beam, " + std::to_string(s.dim) + "D, order " + std::to_string(s.order) + ", " + s.analysis.kind;
  c.item_name = "unknowns";
  c.items = unknowns;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  // One LU [s] and one solve of the factorised matrix with a Newmark update [s]: 34 ms and 0.8 ms at 2 248 unknowns
  // (notes h-pzapp-docs); the draft scenes at 324 unknowns (2026-11-27, docs/PERFORMANCE.md "Cost estimate against
  // measured time") ran 1.8 x faster per unknown in the solve and about 2 x in the factorisation, so both grow
  // faster than linearly in 2D too: exponents 0.3 (solve) and 0.6 (LU, as in 3D) on the size.
  const double factor = 1.5e-5 * unknowns * std::pow(unknowns / 2000.0, 0.6);
  const double solve = 3.6e-7 * unknowns * std::pow(unknowns / 2248.0, 0.3);
  const double eigen = 2.0 * (factor + 30.0 * solve);  // f_sc and f_oc by inverse iteration
  if (s.analysis.kind == "static") {
    c.steps = 1;
    c.step_name = "solve";
    c.seconds = factor + solve;
  } else if (s.analysis.kind == "harmonic") {
    const double loads = std::max<double>(1.0, static_cast<double>(s.analysis.loads.size()));
    // one complex factorisation per frequency serves every load (PiezoBeam::harmonic over circuits): 34 ms at
    // 2 248 unknowns, then a solve and the powers per load (measured: the 25 x 200 sweep in 8.2 s CPU, 172 s
    // when every (R, f) was factorised)
    c.steps = s.analysis.points;
    c.step_name = "complex factorisations (frequencies; every load reuses one)";
    c.seconds = eigen + c.steps * factor + loads * s.analysis.points * solve;
  } else {
    c.steps = static_cast<double>(s.analysis.steps());
    c.step_name = "time steps";
    const double per_step = (s.analysis.scheme == "partitioned" ? 2.0 : 1.0) * solve;  // 0.8 ms at 2 248 unknowns
    c.seconds = eigen + 2.0 * factor + c.steps * per_step;
  }
  c.bytes = 30e6 + unknowns * (s.dim == 3 ? 8e3 : 2e3);
  c.rate = "an LU ~ 1.5e-5 s x unknowns x (unknowns / 2000)^0.6, a time step ~ 3.6e-7 s x unknowns x (unknowns / "
           "2248)^0.3 (apps/piezo_harvester, 1 thread, docs/PERFORMANCE.md 'Cost estimate against measured time')";
  c.rate_threads = 1;
  c.size_keys = {"mesh.cells_length = " + std::to_string(s.cells_length), "mesh.order = " + std::to_string(s.order),
                 "beam.layers[].cells"};
  if (s.dim == 3) c.size_keys.push_back("mesh.cells_width = " + std::to_string(s.cells_width));
  return c;
}

PiezoScene load_piezo_scene(const std::filesystem::path& file, const SceneOptions& options) {
  PiezoScene out;
  const OpenScene s = open_scene(file, "piezo", {}, options.precision);
  out.header = s.header;
  if (out.header.precision != "double")
    s.model.fail("precision", "= \"" + out.header.precision + "\"" +
                                  (options.precision.empty() ? std::string() : std::string(" (--precision)")) +
                                  ": the piezoelectric model assembles and factorises in double precision only; "
                                  "allowed: \"double\"");
  s.model.finish();
  const SceneTable& root = s.root;
  out.header.set_accuracy(read_accuracy(root, options.accuracy, 0.0, "paper"));
  const double f = out.header.coarsening;
  piezo::HarvesterSetup& c = out.config;

  const SceneTable analysis = root.table("analysis");
  const std::string kind = analysis.choice("kind", {"static", "harmonic", "transient"});
  read_beam(root.table("beam"), c, f);
  read_electrodes(root, c, kind);
  {
    const SceneTable t = root.table("mesh");
    c.order = static_cast<int>(t.integer("order", 2, 1, 4));
    c.cells_length = coarsened(t.integer("cells_length", 1, 100000), f, 1);
    if (c.dim == 3) {
      c.cells_width = coarsened(t.integer("cells_width", 2, 1, 10000), f, 1);
    } else if (t.has("cells_width")) {
      t.fail("cells_width", "applies to 3D beams (beam.dim = 3); a 2D beam has no cells across its width");
    }
    t.finish();
  }
  read_circuit(root, c, kind);
  read_damping(root, c);
  read_analysis(analysis, c, kind, f);
  analysis.finish();

  // what each analysis needs of the electrodes
  int floating = 0, prescribed = 0;
  for (const auto& e : c.electrodes) {
    floating += e.kind == "floating";
    prescribed += e.kind == "prescribed";
  }
  if (kind == "static" && prescribed == 0)
    root.fail("electrodes", "has no kind = \"prescribed\" electrode: a static solve has no other load (allowed: a "
                            "prescribed electrode with its potential, V)");
  if (kind != "static" && floating == 0)
    root.fail("electrodes", "has no floating electrode: a " + kind + " run harvests through floating electrodes and a circuit");
  if (kind == "transient" && c.resistors.empty())
    root.fail("circuit", std::string(root.has("circuit") ? "has no resistors" : "is missing") +
                             ": a transient run needs resistors = [{ from, to, ohm }] (the first is the load)");
  if (c.support == "free" && kind != "static")
    root.table("beam").fail("support", "= \"free\" applies to static solves; a base-excited harvester is clamped");
  root.finish();

  out.unknowns = piezo::harvester_unknowns(c);
  out.cost = piezo_cost(c, out.unknowns);
  check_size(out.cost, root.table("mesh"));
  return out;
}

}  // namespace polymech::io
