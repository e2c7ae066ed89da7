#include "io/efg_scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "io/ranges.hpp"

namespace polymech::io {

namespace pl = polymech::io::plausible;

namespace {

// Memory and time of a static EFG run from its counts (rates: docs/PERFORMANCE.md, section EFG).
CostEstimate efg_cost(double nodes, double gauss_points, double support_factor) {
  CostEstimate c;
  c.method = "EFG (MLS, static)";
  c.item_name = "nodes";
  c.items = nodes;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max()) / 2;
  // nodes per Gauss point: the supports (radius factor x spacing) of a square grid cover ~pi f^2 + 4
  const double per_point = 3.14159 * support_factor * support_factor + 4.0;
  c.pairs = gauss_points * per_point;
  c.steps = 1.0;
  c.step_name = "static solve";
  // candidates + rows + phi, dphi per pair; stiffness pattern ~ 4 pi f^2 blocks of 4 reals per node
  c.bytes = 20e6 + gauss_points * (40.0 + per_point * 3.0 * (4.0 + 8.0 + 16.0)) +
            nodes * 4.0 * 3.14159 * support_factor * support_factor * 4.0 * (8.0 + 16.0 + 40.0);
  // 3.6e5: the draft static scenes on 2026-11-27 (1 thread, docs/PERFORMANCE.md "Cost estimate against measured
  // time"; 1.3e5 of section "EFG (static)" was measured before the assembly's and the solve's speed-ups)
  c.seconds = gauss_points / 3.6e5;
  c.rate = "3.6e5 background Gauss points/s (shape functions, assembly, solve, J; 1 thread), docs/PERFORMANCE.md 'Cost estimate against measured time'";
  return c;
}

}  // namespace

EfgScene load_efg_scene(const std::filesystem::path& file, const SceneOptions& options) {
  const std::string& accuracy = options.accuracy;
  const std::string& precision = options.precision;
  EfgScene out;
  const OpenScene s = open_scene(file, "efg", efg::effect_table(), precision, out);
  const SceneTable& root = s.root;
  s.model.finish();
  // float: the MLS shape functions and the stiffness kernel in float, the sparse solve in double (the
  // crack-face nodes' 1e-7 h offsets are y values near 0, which float resolves)
  out.header.set_accuracy(read_accuracy(root, accuracy, 0.0, "paper"));
  auto& c = out.config;

  const SceneTable plate = root.table("plate");
  const std::string crack = plate.choice("crack", {"edge", "centre"});
  c.crack = crack == "edge" ? efg::CrackKind::edge : efg::CrackKind::centre;
  c.loading = efg::Loading::tension;
  c.width = plate.real("width", pl::length());
  c.height = plate.real("height", pl::length());
  c.crack_length = plate.real("crack_length", pl::length());
  if (c.crack == efg::CrackKind::edge && !(c.crack_length < 0.8 * c.width))
    plate.fail("crack_length", "must be below 0.8 x plate.width for an edge crack (the handbook formula holds to a/W = 0.6)");
  if (c.crack == efg::CrackKind::centre && !(c.crack_length < 0.4 * c.width))
    plate.fail("crack_length", "(the half-length a) must be below 0.4 x plate.width for a centre crack");
  if (!(c.height >= 0.5 * c.width)) plate.fail("height", "must be at least plate.width / 2");
  plate.finish();

  const SceneTable mat = root.table("material");
  c.young = mat.real("youngs_modulus", pl::modulus());
  c.poisson = mat.real("poisson_ratio", Range{-0.99, 0.49, false, false, "(a Poisson ratio)"});
  c.density = mat.real("density", pl::density());
  c.plane_strain = mat.choice("state", {"plane_strain", "plane_stress"}, "plane_strain") == "plane_strain";
  mat.finish();

  const SceneTable load = root.table("loading");
  c.stress = load.real("stress", pl::stress());
  load.finish();

  const SceneTable d = root.table("discretization");
  const double coarsening = out.header.coarsening;
  c.h_min = d.real("h_min", pl::spacing()) * coarsening;
  c.h_max = d.real("h_max", pl::spacing()) * coarsening;
  c.growth = d.real("growth", 0.25, pl::factor(0.01, 10.0));
  c.support_factor = d.real("support_factor", 1.5, Range{1.05, 4.0, false, false, "x the local node spacing"});
  c.gauss = static_cast<int>(d.integer("gauss", 10, 1, 12));
  c.jitter = d.real("jitter", 0.0, pl::factor(0.0, 0.4));
  c.tip_offset = d.real("tip_offset", 0.0, pl::factor(0.0, 0.9));
  c.penalty = d.real("penalty", 1e6, Range{1e2, 1e12, false, false, "x the Young modulus"});
  c.min_moment_ratio = d.real("min_moment_ratio", 1e-8, Range{1e-14, 1e-2, false, false, "det(A) / (A00 A11 A22)"});
  if (!(c.h_max >= c.h_min)) d.fail("h_max", "must be at least discretization.h_min");
  if (!(c.h_max <= 0.25 * std::min(c.width, c.height))) d.fail("h_max", "must be at most a quarter of the plate's width and height");
  if (!(c.h_min <= 0.25 * c.crack_length)) d.fail("h_min", "must be at most a quarter of plate.crack_length");
  d.finish();

  // the size, before anything is built
  double nx = 0, ny = 0;
  efg::estimate_lines(c, nx, ny);
  const double nodes = nx * ny + nx;
  const double gauss_points = (nx - 1) * (ny - 1) * c.gauss * c.gauss;
  out.cost = efg_cost(nodes, gauss_points, c.support_factor);
  if (nx < 1e6 && ny < 1e6) {  // the searches' pairs (larger ones are refused by the node count already)
    std::vector<double> xs, ys;
    efg::node_lines(c, xs, ys);
    const efg::SearchSize ss = efg::search_size(c, xs, ys);
    const double pattern_estimated = nodes * 4.0 * 3.14159 * c.support_factor * c.support_factor;
    // candidates: an index each, twice (the search's count and fill passes); pattern: K's 2 x 2 blocks
    out.cost.bytes += ss.candidates * 2.0 * 4.0 + std::max(0.0, ss.pattern - pattern_estimated) * 4.0 * (8.0 + 16.0 + 40.0);
    out.cost.pairs = std::max(out.cost.pairs, ss.candidates);
  }
  out.cost.size_keys = {"plate.width = " + format_number(c.width) + " m", "plate.height = " + format_number(c.height) + " m",
                        "discretization.h_min = " + format_number(c.h_min) + " m",
                        "discretization.h_max = " + format_number(c.h_max) + " m",
                        "discretization.gauss = " + std::to_string(c.gauss)};
  check_size(out.cost, d);

  const SceneTable j = root.table("j_integral");
  c.j_radii = j.reals("radii", pl::length());
  if (c.j_radii.empty()) j.fail("radii", "is empty; give at least one contour radius");
  const double room = std::min({c.crack == efg::CrackKind::edge ? c.crack_length : 2 * c.crack_length,
                                c.crack == efg::CrackKind::edge ? c.width - c.crack_length : 0.5 * c.width - c.crack_length,
                                0.5 * c.height});
  c.j_band = j.real("band", 0.0, Range{0.0, 4.0, false, false, "x the local node spacing (0: the single contour of the paper)"});
  for (double r : c.j_radii) {
    const double half = 0.5 * efg::j_band_width(c, r);
    if (!(r + half < room))
      j.fail("radii", "has " + format_number(r) + " m" + (half > 0 ? " (band to " + format_number(r + half) + " m)" : std::string()) +
                          ": a contour must stay inside the plate and cross only the crack (radius < " + format_number(room) + " m)");
    if (!(r - half > 0))
      j.fail("band", "reaches the tip on the path of radius " + format_number(r) + " m (half-width " + format_number(half) +
                         " m): lower band or raise radii");
  }
  c.j_arcs = static_cast<int>(j.integer("arcs", 20, 4, 400));
  c.j_gauss = static_cast<int>(j.integer("gauss", 4, 1, 4));
  out.domain_cells = static_cast<int>(j.integer("domain_cells", 20, 2, 100));
  j.finish();
  if (const auto dyn = root.optional_table("dynamic")) {
    out.dynamic = true;
    out.dt = dyn->real("dt", pl::time_step());
    out.duration = dyn->real("duration", pl::duration());
    out.output_every = static_cast<int>(dyn->integer("output_every", 1, 1, 1000000));
    const double steps = std::ceil(out.duration / out.dt - 1e-9);
    if (!(steps <= 1e6)) dyn->fail("duration", "gives " + format_number(steps) + " steps of dynamic.dt; at most 1e6");
    out.steps = static_cast<std::int64_t>(steps);
    // the unconditionally stable average-acceleration rule: dt is an accuracy choice; refuse one that
    // does not resolve the dilatational wave crossing one h_max
    const double lam = c.young * c.poisson / ((1 + c.poisson) * (1 - 2 * c.poisson)), mu = c.young / (2 * (1 + c.poisson));
    const double cd = std::sqrt((lam + 2 * mu) / c.density);
    if (!(out.dt <= 10 * c.h_max / cd))
      dyn->fail("dt", "= " + format_number(out.dt) + " s is above 10 h_max / c_d = " + format_number(10 * c.h_max / cd) +
                          " s: the step would not resolve the waves");
    c.newmark_gamma = dyn->real("newmark_gamma", 0.5, Range{0.5, 1.0, false, false, "Newmark's gamma (0.5: the paper's average acceleration)"});
    c.growth_speed = dyn->real("growth_speed", 0.0, Range{0.0, 1e4, false, false, "m/s (0: a stationary crack)"});
    c.growth_start = dyn->real("growth_start", 0.0, Range{0.0, 1e3, false, false, "s"});
    c.final_crack_length = dyn->real("final_crack_length", c.crack_length, pl::length());
    // true: nodes on the crack path, split as the tip passes them (the paper's Model 4); false: none there
    c.path_nodes = dyn->boolean("path_nodes", false);
    c.path_release_gradual = dyn->choice("path_release", {"sudden", "gradual"}, "sudden") == "gradual";
    if (c.growth_speed > 0) {
      const double cs = std::sqrt(mu / c.density);
      if (!(c.growth_speed < 0.9 * cs)) dyn->fail("growth_speed", "must be below 0.9 c_s = " + format_number(0.9 * cs) + " m/s");
      if (!(c.final_crack_length > c.crack_length)) dyn->fail("final_crack_length", "must exceed plate.crack_length for a growing crack");
      const double ahead = c.crack == efg::CrackKind::edge ? c.width - c.final_crack_length : 0.5 * c.width - c.final_crack_length;
      for (double r : c.j_radii)
        if (!(r + 0.5 * efg::j_band_width(c, r) < ahead)) dyn->fail("final_crack_length", "leaves " + format_number(ahead) + " m ahead of the final tip, less than the J-integral radius " + format_number(r) + " m");
    }
    dyn->finish();
    // The dynamic run's time from the rates measured in docs/PERFORMANCE.md, 'EFG dynamics (Newmark,
    // stationary crack)' (chen_centre_crack_dynamic.toml, 120 steps, 1 thread): shape functions + K, M
    // 0.45 s for 36 000 Gauss points, 0.94 s / 80 000, 1.79 s / 218 400 (about 1e5 points/s); the K_eff
    // factorisation 0.019 s at 404 nodes, 0.33 s at 2 292 (about 3e-6 nodes^1.5 s); a step 0.8 ms at 404
    // nodes, 7.9 ms at 2 292 (about 3e-6 s per node); J' 0.47-0.60 s over 61 outputs (about 5 ms per
    // output) on single circles, 1.11-1.38 s with j_integral.band > 0 (4 circles and discs per path: about
    // 20 ms per output). A running crack rebuilds the shape functions, K, M and K_eff at every growth step ('Running
    // crack': 12 growth steps of about 2 s each at 2 272 nodes, 31.6 s in all).
    const double n = static_cast<double>(efg::count_nodes(c));
    // refit on 2026-11-27 to the four draft dynamic scenes (docs/PERFORMANCE.md "Cost estimate against measured
    // time"; two factors on the old terms: the build x 0.92, the per-step and per-output costs x 0.53)
    const double build = gauss_points / 1.1e5 + 3e-6 * std::pow(n, 1.5);
    double growth_steps = 0.0;
    if (c.growth_speed > 0) {
      const double run_time = std::max(0.0, (c.final_crack_length - c.crack_length) / c.growth_speed);
      const double from = std::max(0.0, c.growth_start);
      growth_steps = std::clamp(std::ceil(std::min(run_time, std::max(0.0, out.duration - from)) / out.dt - 1e-9), 0.0, steps);
    }
    const double outputs = std::ceil(steps / out.output_every);
    const double per_output = c.j_band > 0 ? 1.05e-2 : 2.6e-3;
    out.cost.method = c.growth_speed > 0 ? "EFG (MLS, Newmark average acceleration, running crack)"
                                         : "EFG (MLS, Newmark average acceleration)";
    out.cost.steps = steps;
    out.cost.step_name = "Newmark steps";
    out.cost.seconds = build * (1.0 + growth_steps) + steps * n * 1.6e-6 + outputs * per_output;
    out.cost.rate = std::string("1.1e5 Gauss points/s for shape functions + K, M; 3e-6 nodes^1.5 s per K_eff factorisation; 1.6e-6 s per node-step; ") +
                    (c.j_band > 0 ? "10 ms per J' output (band); " : "2.6 ms per J' output; ") + "a rebuild at each of " +
                    format_number(growth_steps) + " growth steps (1 thread), docs/PERFORMANCE.md 'EFG dynamics'";
  }
  out.cost.items = static_cast<double>(efg::count_nodes(c));  // the nodes the layout will place (the size check above used an upper estimate)
  root.finish();
  out.handbook = efg::handbook_factor(c);
  return out;
}

}  // namespace polymech::io
