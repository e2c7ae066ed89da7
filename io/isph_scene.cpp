#include "io/isph_scene.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include "io/ranges.hpp"

namespace polymech::io {

namespace pl = polymech::io::plausible;

// Rates: bench/bench_isph.cpp, BM_IsphStep (docs/PERFORMANCE.md, "ISPH: the stored PPE operator"), 1 thread:
// a step costs about one particle-PPE-iteration per particle and BiCGSTAB iteration, 8e6 /s with the
// stored operator (7.3e6 at 1e3 particles, 1.07e7 at 1e4) and 2.5e6 /s matrix-free (2.2e6 - 2.6e6);
// iterations ~ 1.75 sqrt(N) in 2D and ~ 1.4 N^(1/3) in 3D (measured at 200 to 1e4 particles). Memory:
// ~40 reals per particle and wall point plus the three neighbour lists (~35 pairs per particle in 2D,
// ~150 in 3D, one int each) and, stored, one real per pair of each list (with a quarter's headroom).
// With the two-level preconditioner (models/isph/ppe_two_level.hpp) the iterations no longer grow with N
// (7-8 per step, warm-started): 2.2e5 particle-steps/s at 1e3 to 1e6 particles in 2D (BM_IsphStep mode 2),
// scaled by the pair count in 3D.
CostEstimate isph_cost(double particles, double wall_points, int dim, double steps, bool stored, bool two_level) {
  CostEstimate c;
  c.method = "stabilized ISPH (IGCB walls)";
  c.item_name = "particles";
  c.items = particles;
  c.max_items = static_cast<double>(std::numeric_limits<std::int32_t>::max());
  const double pairs_per = dim == 2 ? 35.0 : 150.0;
  c.pairs = particles * pairs_per;
  c.steps = steps;
  c.step_name = "steps";
  const double list_pairs = 3.0 * (particles + wall_points) * pairs_per;
  c.bytes = 64e6 + (particles + wall_points) * 40.0 * 8.0 + list_pairs * 4.0 + (stored ? list_pairs * 1.25 * 8.0 : 0.0);
  const double iterations = dim == 2 ? 1.75 * std::sqrt(particles) : 1.4 * std::cbrt(particles);
  // Refreshed from the draft runs of every shipped 2D scene (2026-11-27, one thread; docs/PERFORMANCE.md "Cost
  // estimate against measured time"): a step costs 0.64 ms whatever its size (neighbour lists of particles and
  // wall points, the IGCB ghost cells, the host's checks: 100-particle tanks spend half their time there) plus the
  // PPE at 4.8e6 particle-iterations/s with the stored operator (bench_isph's 7.3e6 is the solve alone); the
  // matrix-free operator at the same ratio to it as in bench_isph (2.5 / 8).
  const double per_step = 6.4e-4;
  const double rate2 = stored ? 4.8e6 : 4.8e6 * 2.5 / 8.0;
  const double rate = dim == 2 ? rate2 : rate2 * 35.0 / 150.0;  // particle-iterations/s
  c.seconds = steps * (per_step + particles * std::max(iterations, 5.0) / rate);
  c.rate = std::string(stored ? "4.8e6" : "1.5e6") + " particle-PPE-iterations/s in 2D (" +
           (stored ? "stored" : "matrix-free") +
           " operator; scaled by the pair count in 3D), about 1.75 sqrt(N) BiCGSTAB iterations per step, + 0.64 ms "
           "per step; docs/PERFORMANCE.md 'Cost estimate against measured time', 1 thread";
  if (two_level) {
    // the draft floating cylinder (1 000 particles): 1.5e5 particle-steps/s beside the step's 0.64 ms; bench_isph
    // BM_IsphStep mode 2 gives 2.2e5 at 1e4-1e6 particles: 1.6e5 taken
    c.seconds = steps * (per_step + particles / (dim == 2 ? 1.6e5 : 1.6e5 * 35.0 / 150.0));
    c.bytes += particles * 0.5 * 8.0 * 40.0;  // the coarse LU (1/16 of the unknowns, its fill-in) and vectors
    c.rate = "1.6e5 particle-steps/s in 2D with the two-level PPE preconditioner (scaled by the pair count in 3D), "
             "+ 0.64 ms per step; docs/PERFORMANCE.md 'Cost estimate against measured time', 1 thread";
  }
  return c;
}

IsphScene load_isph_scene(const std::filesystem::path& file, const SceneOptions& options) {
  const std::string& accuracy = options.accuracy;
  const std::string& precision = options.precision;
  IsphScene out;
  const OpenScene s = open_scene(file, "isph", isph::effect_table(), precision, out);
  const SceneTable& root = s.root;
  auto& c = out.config;
  c.dim = static_cast<int>(s.model.integer("dimension", 2, 2, 3));
  c.wall = s.model.choice("wall", {"no_slip", "slip"}, "no_slip") == "slip" ? isph::WallCondition::slip
                                                                            : isph::WallCondition::no_slip;
  // defaults: the paper's forms (as isph::Config's); the others are options (docs/VALIDATION.md, stage 4)
  c.ghost_interpolation = s.model.choice("ghost_interpolation", {"shepard", "linear"}, "shepard") == "linear"
                              ? isph::GhostInterpolation::linear
                              : isph::GhostInterpolation::shepard;
  c.pressure_gradient = s.model.choice("pressure_gradient", {"symmetric", "difference"}, "symmetric") == "difference"
                            ? isph::PressureGradient::difference
                            : isph::PressureGradient::symmetric;
  if (c.effects.has("rigid_body") && c.dim != 2) s.model.fail("effects", "lists \"rigid_body\": the body is 2D only");
  s.model.finish();
  out.header.set_accuracy(read_accuracy(root, accuracy, 0.0, "paper"));
  const double f = out.header.coarsening;

  const SceneTable fluid = root.table("fluid");
  c.density = fluid.real("density", pl::density());
  c.viscosity = fluid.real("viscosity", 1e-6, Range{1e-9, 10.0, false, false, "m^2/s (kinematic viscosity)"});
  c.gravity = fluid.real("gravity", 9.8, Range{0.0, 1e3, false, false, "m/s^2 (along -y)"});
  c.spacing = f * fluid.real("spacing", pl::spacing());
  c.radius_factor = fluid.real("radius_factor", 3.3, Range{2.0, 5.0, false, false, "re / l0"});
  c.alpha = fluid.real("alpha", 5e-3, Range{0.0, 1.0, false, false, "density relaxation of eq. (4)"});
  c.surface_threshold =
      fluid.real("surface_threshold", 0.95, Range{0.5, 0.999, false, false, "free surface where rho < this x rho0"});
  c.surface_correction = fluid.boolean("surface_correction", true);
  // free-surface particles: by the density (surface_threshold), by the divergence of position, or by either
  {
    const std::string surface =
        fluid.choice("surface_detection", {"density", "divergence", "divergence_or_density"}, "density");
    c.surface_detection = surface == "divergence"              ? isph::SurfaceDetection::divergence
                          : surface == "divergence_or_density" ? isph::SurfaceDetection::divergence_or_density
                                                               : isph::SurfaceDetection::density;
  }
  c.surface_divergence = fluid.real("surface_divergence", 0.0,
                                    Range{0.0, 3.0, false, false, "free surface where div r < this (0: 1.5 in 2D, 2.4 in 3D)"});
  c.tolerance = fluid.real("ppe_tolerance", 1e-8, Range{1e-14, 1e-2, false, false, "relative residual"});
  c.max_iterations = static_cast<int>(fluid.integer("ppe_max_iterations", 2000, 1, 1000000));
  c.ppe_stored = fluid.choice("ppe_operator", {"stored", "matrix_free"}, "stored") == "stored";
  c.ppe_preconditioner = fluid.choice("ppe_preconditioner", {"jacobi", "two_level"}, "jacobi") == "two_level"
                             ? isph::Config::Preconditioner::two_level
                             : isph::Config::Preconditioner::jacobi;
  c.ppe_coarse_cell = fluid.real("ppe_coarse_cell", 4.0, Range{1.0, 64.0, false, false, "particle spacings (side of an aggregate)"});
  if (c.ppe_preconditioner == isph::Config::Preconditioner::two_level && !c.ppe_stored)
    fluid.fail("ppe_preconditioner", "\"two_level\" needs fluid.ppe_operator = \"stored\" (its coarse matrix is built "
                                     "from the stored coefficients); allowed with \"matrix_free\": \"jacobi\"");
  fluid.finish();

  const SceneTable tank = root.table("tank");
  out.case_name = tank.choice("case", {"hydrostatic", "dam_break"});
  c.tank[0] = tank.real("width", pl::length());
  c.tank[1] = tank.real("height", pl::length());
  c.fluid[0] = tank.real("water_width", pl::length());
  c.fluid[1] = tank.real("water_height", pl::length());
  if (c.dim == 3) {
    c.tank[2] = tank.real("depth", pl::length());
    c.fluid[2] = tank.real("water_depth", pl::length());
  }
  for (int k = 0; k < c.dim; ++k) {
    const char* key = k == 0 ? "water_width" : k == 1 ? "water_height" : "water_depth";
    if (c.fluid[k] > c.tank[k]) tank.fail(key, "is larger than the tank (" + format_number(c.tank[k]) + " m)");
    if (c.fluid[k] < 2 * c.spacing)
      tank.fail(key, "= " + format_number(c.fluid[k]) + " m holds fewer than 2 particles at the spacing " +
                         format_number(c.spacing) + " m");
  }
  if (out.case_name == "dam_break" && c.fluid[0] >= c.tank[0])
    tank.fail("water_width", "fills the tank: a dam break needs room for the surge");
  tank.finish();

  if (const auto body = root.optional_table("body")) {
    if (!c.effects.has("rigid_body")) body->fail_table("needs the effect \"rigid_body\" in model.effects");
    c.body.diameter = body->real("diameter", pl::length());
    c.body.centre[0] = body->real("x", pl::coordinate());
    c.body.centre[1] = body->real("y", pl::coordinate());
    c.body.density_ratio = body->real("density_ratio", Range{0.05, 20.0, false, false, "rho_body / rho_water"});
    const double R = 0.5 * c.body.diameter;
    if (c.body.diameter <= 2 * c.spacing) body->fail("diameter", "must be more than 2 particle spacings");
    if (c.body.centre[0] - R < 0 || c.body.centre[0] + R > c.tank[0]) body->fail("x", "puts the body outside the tank");
    if (c.body.centre[1] - R < 0 || c.body.centre[1] + R > c.tank[1]) body->fail("y", "puts the body outside the tank");
    c.body.added_mass = body->real("added_mass", 1.0, Range{0.0, 10.0, false, false, "C_a (0: plain CSS as the paper)"});
    c.body.release_time = body->real("release_time", 0.0, Range{0.0, 1e6, false, false, "s (held fixed until then)"});
    c.body.fluid_rings = static_cast<int>(body->integer("fluid_rings", 0, 0, 20));
    c.body.fluid_clearance =
        body->real("fluid_clearance", 0.0, Range{0.0, 2.0, false, false, "l0 (the lattice starts at R + (fluid_rings + this) l0)"});
    out.draft_average_last = body->real("draft_average_last", 0.0, Range{0.0, 1e6, false, false, "s"});
    c.body.contact_modulus =
        body->real("contact_modulus", 0.0, Range{0.0, 1e13, false, false, "Pa, E* of the body-tank contact (0: automatic)"});
    c.body.restitution = body->real("restitution", 0.5, Range{0.01, 1.0, true, false, "of the body-tank contact"});
    c.body.friction = body->real("friction", 0.3, Range{0.0, 10.0, false, false, "Coulomb, body against the tank"});
    body->finish();
  } else if (c.effects.has("rigid_body")) {
    s.model.fail("effects", "lists \"rigid_body\" but the scene has no [body] table");
  }

  const SceneTable time = root.table("time");
  c.dt = f * time.real("dt", pl::time_step());
  out.end_time = time.real("end_time", pl::duration());
  out.snapshot_every = time.real("snapshot_every", 0.0, Range{0.0, 1e6, false, false, "s (0: no snapshots)"});
  out.sample_every = time.real("sample_every", 0.0, Range{0.0, 1e6, false, false, "s (0: every step)"});
  out.average_last = time.real("average_last", 0.0, Range{0.0, 1e6, false, false, "s"});
  time.finish();
  root.finish();

  out.limit = isph::time_step_limit(c);
  if (c.dt > out.limit.limit)
    time.fail("dt", "gives dt = " + format_number(c.dt) + " s, above the limit " + out.limit.describe());
  const double steps = std::ceil(out.end_time / c.dt - 1e-9);
  if (!(steps <= 1e12)) time.fail("end_time", "needs more than 1e12 steps");
  out.steps = static_cast<std::int64_t>(steps);
  if (out.average_last > out.end_time) time.fail("average_last", "is longer than end_time");

  if (c.effects.has("rigid_body")) {
    const isph::BodyContact bc = isph::body_contact(c);
    if (bc.contact_time < 10.0 * c.dt)
      time.fail("dt", "= " + format_number(c.dt) + " s is too long for the body's contact with the tank: an impact at " +
                          format_number(bc.reference_speed) + " m/s lasts " + format_number(bc.contact_time) +
                          " s with body.contact_modulus = " + format_number(bc.e_star) +
                          " Pa; at least 10 steps are needed (lower the modulus or dt)");
  }
  const auto n = isph::count(c);
  out.cost = isph_cost(double(n.fluid), double(n.wall_points), c.dim, steps, c.ppe_stored,
                       c.ppe_preconditioner == isph::Config::Preconditioner::two_level);
  out.cost.size_keys = {"fluid.spacing = " + format_number(c.spacing) + " m (after the accuracy preset)",
                        "tank.water_width, water_height = " + format_number(c.fluid[0]) + ", " +
                            format_number(c.fluid[1]) + " m",
                        "time.end_time / time.dt = " + format_number(steps) + " steps"};
  check_size(out.cost, s.model);
  const std::string why = isph::check(c);
  if (!why.empty()) s.model.fail("kind", why);
  return out;
}

nlohmann::json isph_choices(const isph::Config& c) {
  using isph::GhostInterpolation, isph::PressureGradient, isph::SurfaceDetection;
  nlohmann::json j;
  j["dimension"] = c.dim;
  j["spacing"] = c.spacing;
  j["dt"] = c.dt;
  j["alpha"] = c.alpha;
  j["ppe_operator"] = c.ppe_stored ? "stored" : "matrix_free";
  j["ppe_preconditioner"] = c.ppe_preconditioner == isph::Config::Preconditioner::two_level ? "two_level" : "jacobi";
  j["surface_detection"] = c.surface_detection == SurfaceDetection::divergence              ? "divergence"
                           : c.surface_detection == SurfaceDetection::divergence_or_density ? "divergence_or_density"
                                                                                             : "density";
  j["pressure_gradient"] = c.pressure_gradient == PressureGradient::difference ? "difference" : "symmetric";
  j["ghost_interpolation"] = c.ghost_interpolation == GhostInterpolation::linear ? "linear" : "shepard";
  return j;
}

}  // namespace polymech::io
