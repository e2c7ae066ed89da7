// The tyre 37x12.5R16.5 of seed 002 paper 2 (issue 37; models/solid/tyre.hpp) on a coarse mesh (seconds):
//  - the section's arcs meet the bead and the widest point given, the lattice is valid (det J > 0 everywhere);
//  - inflation to 0.35 MPa (follower pressure on the inner surface ramped by the load factor, mass-proportional
//    damping to settle), both beads tied to one rim (two bodies held still): the net rim force is zero to
//    round-off against the bead forces, the two beads pull equally, the shape stays axisymmetric and symmetric,
//    the tyre grows, and the bead's axial force is the membrane closed form p pi (r_m^2 - r_b^2) (r_m the widest
//    point of the inflated inner surface) within the wall's bending share;
//  - pressed on the rigid plate, the plate's force is the rim's reaction once settled;
//  - a step above the critical one is refused;
//  - per-cell stiffness scales (the layered wall): scales of 1 are the one law, a two-region block in series and
//    in parallel gives the rules by hand, the layered tyre carries less load on the plate than the smeared one at
//    the same deflection and its critical step is shorter (measured 8 x 6 cells: 0.79 of the load, 0.24 of dt).
//  - the steel belt (TyreSpec::belted): the belt layer's scales in the crown cells of the layer outside the cord
//    layer only (the laminate's moduli by hand), the other scales the layered wall's bitwise; the belted crown
//    hardly grows on inflation where the layered one does, and its critical step is shorter.
//  - the rebar belt (TyreSpec::belt_rebar, two cord families in the rubber; Hyperelastic::set_fibres): the fibre
//    law on a block in homogeneous stretch (the nodal forces and energy against S_f = k E_a a (x) a by hand, no force
//    across the cords, tension-only cords, the +-20 deg pair's cos^4 / sin^4 stiffness ratio, the tangent against
//    differences of the residual); the belt's cells and cord stiffness by hand; the rebar crown hardly grows on
//    inflation, stable at the power iteration's step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "solid/tyre.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

constexpr double kP = 0.35e6;

so::Config<3> tyre_config(const so::TyreSpec& spec) {
  so::Config<3> c;
  c.mesh = so::make_tyre(spec, 12, 6, 1);
  c.order = 2;
  return c;
}

std::vector<so::RigidTie<3>> rim() {
  std::vector<so::RigidTie<3>> beads(2);
  for (int k = 0; k < 2; ++k) {
    beads[k].boundary = k == 0 ? "ymin" : "ymax";
    beads[k].axis = {0.0, 1.0, 0.0};
    for (int q = 0; q < 4; ++q) beads[k].velocity[q] = [](double) { return 0.0; };
  }
  return beads;
}

}  // namespace

TEST(Tyre, SectionMeetsTheBeadAndTheWidestPoint) {
  const so::TyreSpec spec{};
  const so::TyreSection c = so::tyre_section(spec);
  double p[2], n[2], h = 0.0;
  c.at(c.half_length, p, n, h);
  EXPECT_NEAR(p[0], 0.5 * spec.rim_width, 1e-12);
  EXPECT_NEAR(p[1], spec.rim_radius, 1e-12);
  EXPECT_NEAR(h, spec.wall_gauge, 1e-15);
  c.at(0.0, p, n, h);
  EXPECT_NEAR(p[1] + h * n[1], spec.outer_radius, 1e-12);
  c.at(c.radius[0] * c.angle[0] + c.radius[1] * c.angle[1], p, n, h);  // the widest point: normal axial
  EXPECT_NEAR(p[0] + h * n[0], 0.5 * spec.width, 1e-12);
  EXPECT_NEAR(n[1], 0.0, 1e-12);
  // the volume: a revolved section ~ contour length x gauge x 2 pi r
  const double v = so::tyre_volume(spec);
  EXPECT_GT(v, 0.015);
  EXPECT_LT(v, 0.035);
}

TEST(Tyre, InflationReactionsShapeAndPlate) {
  const so::TyreSpec spec{};
  const so::TyreLaw law = so::tyre_equivalent_law(spec);
  so::ExplicitFiniteStrainOptions eo;
  eo.density = law.density;
  eo.damping = 1000.0;
  const double t_ramp = 0.005;
  eo.load_factor = [t_ramp](double t) { return std::fmin(t / t_ramp, 1.0); };
  so::HyperelasticExplicit<double, 3> m(tyre_config(spec), so::HyperelasticLaw(law.law), eo, {{"zmin", kP}}, rim());
  const auto& d = m.solid().discretization();
  m.advance(static_cast<std::int64_t>(std::ceil(0.012 / m.time_step())));
  const std::vector<double> u = pm::models::to_host(m.displacement());
  const auto& A = m.ties()[0];
  const auto& B = m.ties()[1];
  double net = 0.0;
  for (int q = 0; q < 3; ++q) net = std::fmax(net, std::fabs(A.force[q] + B.force[q]));
  const auto w = so::widest_inner_point(d, u);
  const double rb = spec.rim_radius, closed = kP * 3.14159265358979 * (w[1] * w[1] - rb * rb);
  // shape: the outer crown radius round the wheel, the width either side
  double rmin = 1e300, rmax = 0.0, ylo = 0.0, yhi = 0.0;
  for (const auto n : so::side_nodes(d, "zmax")) {
    const std::size_t i = static_cast<std::size_t>(3 * n);
    const double x = d.coordinates[i] + u[i], y = d.coordinates[i + 1] + u[i + 1], z = d.coordinates[i + 2] + u[i + 2];
    ylo = std::fmin(ylo, y);
    yhi = std::fmax(yhi, y);
    if (d.lattice_index(n)[1] != d.lattice[1] / 2) continue;
    rmin = std::fmin(rmin, std::sqrt(x * x + z * z));
    rmax = std::fmax(rmax, std::sqrt(x * x + z * z));
  }
  std::printf("tyre inflated (12 x 6 x 1 cells, order 2, %lld DoFs, dt %.3g s): bead axial forces %.6g / %.6g N, net rim force "
              "%.3g N; p pi (r_m^2 - r_b^2) = %.6g N (r_m %.4f; ratio %.4f); crown radius %.5f..%.5f (+%.3f %%), width %.5f "
              "(%.6f / %.6f); kinetic %.3g J\n",
              static_cast<long long>(m.solid().dof_count()), m.time_step(), A.force[1], B.force[1], net, closed, w[1],
              B.force[1] / closed, rmin, rmax, 100.0 * (rmax / spec.outer_radius - 1.0), yhi - ylo, ylo, yhi, m.kinetic_energy());
  // measured (Xeon, 1 thread): net 1.4e-9 N against 5.8e4 N; bead force / closed form 0.79
  EXPECT_LT(net, 1e-8 * B.force[1]);
  EXPECT_GT(B.force[1], 0.0);  // the tyre pulls the beads apart (outward, against the rim's flanges)
  EXPECT_NEAR(A.force[1] / B.force[1], -1.0, 1e-9);
  EXPECT_NEAR(yhi / ylo, -1.0, 1e-9);
  EXPECT_LT(rmax - rmin, 2e-3 * (rmax - spec.outer_radius));  // measured 2.6e-4: corner and mid-side nodes (order 2)
  EXPECT_GT(rmax, spec.outer_radius * 1.005);  // the tyre grows on inflation
  EXPECT_LT(rmax, spec.outer_radius * 1.05);
  EXPECT_GT(B.force[1] / closed, 0.75);  // the membrane closed form, within the wall's bending share
  EXPECT_LT(B.force[1] / closed, 1.10);
  EXPECT_LT(m.kinetic_energy(), 0.05);  // settled (measured 0.014 J; 1 J during the ramp)
  // the plate: raised 15 mm against the tyre over 10 ms, held 10 ms; then its force is the rim's reaction
  const double t1 = m.time(), z0 = -rmax;
  so::PlateContact<double> plate(
      d, m.lumped_mass(), m.omega_max(), 0.1, 0.3, [t1, z0](double t) { return z0 + 1.5 * std::fmin(0.01, std::fmax(0.0, t - t1)); },
      [t1](double t) { return t - t1 < 0.01 ? 1.5 : 0.0; });
  m.set_external_force([&plate](double t, const pm::View1<double>& uu, const pm::View1<double>& vv, const pm::View1<double>& rr) {
    plate.apply(t, uu, vv, rr);
  });
  m.set_damping(400.0);
  m.advance(static_cast<std::int64_t>(std::ceil(0.02 / m.time_step())));
  const double rim_z = m.ties()[0].force[2] + m.ties()[1].force[2];
  std::printf("tyre on the plate, 15 mm: plate force %.6g N, the structure's force on the rim %.6g N, %d nodes in contact\n",
              plate.force(), rim_z, plate.nodes_in_contact());
  EXPECT_GT(plate.force(), 1000.0);
  EXPECT_NEAR(rim_z / plate.force(), 1.0, 0.05);  // the plate pushes the tyre up, the tyre the rim
  EXPECT_GT(plate.nodes_in_contact(), 0);
}

TEST(Tyre, AStepAboveTheCriticalOneIsRefused) {
  const so::TyreSpec spec{};
  const so::TyreLaw law = so::tyre_equivalent_law(spec);
  so::ExplicitFiniteStrainOptions eo;
  eo.density = law.density;
  so::HyperelasticExplicit<double, 3> ok(tyre_config(spec), so::HyperelasticLaw(law.law), eo, {{"zmin", kP}}, rim());
  eo.dt = 1.2 * ok.critical_time_step();
  EXPECT_THROW((so::HyperelasticExplicit<double, 3>(tyre_config(spec), so::HyperelasticLaw(law.law), eo, {{"zmin", kP}}, rim())),
               std::invalid_argument);
}

// --- per-cell stiffness scales (the layered wall, issue 37) ---------------------------------------------------

namespace {

// Block [0, 2] x [0, 1] x [0, 1], `cells` cells, rollers on the min sides, u_x = 2 (stretch - 1) on xmax.
so::Config<3> scaled_block(std::array<int, 3> cells, double stretch) {
  so::BoxSpec b;
  b.lengths = {2.0, 1.0, 1.0};
  b.cells = cells;
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = 2;
  c.dirichlet.push_back({"xmin", 1u, {}});
  c.dirichlet.push_back({"ymin", 2u, {}});
  c.dirichlet.push_back({"zmin", 4u, {}});
  c.dirichlet.push_back({"xmax", 1u, [stretch](const double*, double* u) { u[0] = 2.0 * (stretch - 1.0); }});
  return c;
}

pm::materials::MooneyRivlin<double> block_law() {
  pm::materials::MooneyRivlin<double> l;
  l.C10 = 0.8e6;
  l.C01 = 0.2e6;
  l.kappa = 4.0e6 / 3.0;  // = 2/3 mu (mu = 2 (C10 + C01)): Poisson's ratio 0, so the two regions in series
                          // stretch without lateral strain and the series rule is exact to the finite strain
  return l;
}

// The xmax reaction of the block stretched by 0.1 % (quasi-static Newton), the cells scaled by `scale`.
double block_reaction(std::array<int, 3> cells, const std::vector<double>& scale) {
  so::Hyperelastic<double, 3> m(scaled_block(cells, 1.001), so::HyperelasticLaw(block_law()));
  m.set_cell_scale(scale);
  so::Monitor mon;
  mon.reaction_boundary = "xmax";
  so::LoadPath path;
  path.increments = {1};
  return m.run(path, mon).back().reaction[0];
}

}  // namespace

TEST(TyreLayers, UnitScalesAreTheOneLaw) {
  // the residual at a displacement field of 1e-3 shears and stretches, with and without scales of 1
  so::Hyperelastic<double, 3> a(scaled_block({2, 2, 3}, 1.0), so::HyperelasticLaw(block_law()));
  so::Hyperelastic<double, 3> b(scaled_block({2, 2, 3}, 1.0), so::HyperelasticLaw(block_law()));
  b.set_cell_scale(std::vector<double>(12, 1.0));
  const auto& X = a.discretization().coordinates;
  std::vector<double> u(X.size());
  for (std::size_t i = 0; i < u.size(); ++i) u[i] = 1e-3 * (X[(i + 1) % X.size()] + 0.5 * X[i] * X[i]);
  pm::View1<double> uv = pm::models::to_device<double>("test::u", u), ra("test::ra", u.size()), rb("test::rb", u.size());
  const double na = a.residual(uv, 1.0, ra), nb = b.residual(uv, 1.0, rb);
  const std::vector<double> ha = pm::models::to_host(ra), hb = pm::models::to_host(rb);
  double diff = 0.0;
  for (std::size_t i = 0; i < ha.size(); ++i) diff = std::fmax(diff, std::fabs(ha[i] - hb[i]));
  std::printf("unit cell scales: |r| %.10g vs %.10g, max difference %.3g; energy %.10g vs %.10g\n", na, nb, diff, a.strain_energy(),
              b.strain_energy());
  EXPECT_GT(na, 0.0);
  EXPECT_LE(diff, 1e-14 * na);
  EXPECT_NEAR(a.strain_energy(), b.strain_energy(), 1e-14 * a.strain_energy());
  EXPECT_DOUBLE_EQ(b.cell_scale_max(), 1.0);
  EXPECT_THROW(b.set_cell_scale(std::vector<double>(11, 1.0)), std::invalid_argument);  // too few
  EXPECT_THROW(b.set_cell_scale(std::vector<double>(12, 0.0)), std::invalid_argument);   // not > 0
}

TEST(TyreLayers, TwoRegionBlockInSeriesAndInParallel) {
  const double s = 8.0;
  const double one = block_reaction({2, 2, 1}, {});
  // in series: the stiff half along the stretch (cells i0 = 1): compliance L/2 / E + L/2 / (s E)
  const double series = block_reaction({2, 2, 1}, {1.0, s, 1.0, s});
  // in parallel: the stiff half across (cells i1 = 1): stiffness (E + s E) / 2
  const double parallel = block_reaction({2, 2, 1}, {1.0, 1.0, s, s});
  const double series_hand = 2.0 / (1.0 + 1.0 / s), parallel_hand = 0.5 * (1.0 + s);
  std::printf("two-region block (s = %g): series %.6f (by hand %.6f), parallel %.6f (by hand %.6f) x the one law\n", s,
              series / one, series_hand, parallel / one, parallel_hand);
  // Poisson's ratio 0: no lateral strain, both rules exact but for the 0.1 % finite strain
  EXPECT_NEAR(parallel / one, parallel_hand, 2e-3 * parallel_hand);
  EXPECT_NEAR(series / one, series_hand, 2e-3 * series_hand);
}

namespace {

struct Pressed {
  double force = 0.0, length = 0.0, width = 0.0, dt_crit = 0.0;
  int nodes = 0;
};

// The coarse tyre (8 x 6 x n_wall cells, order 2) inflated (ramp 4 ms, settled to 8 ms), then the plate raised
// `deflection` against it over 5 ms and held 5 ms (the rim held): the plate's force and the contact patch.
Pressed press_on_plate(const so::TyreSpec& spec, int n_wall, double deflection) {
  const so::TyreLaw law = so::tyre_equivalent_law(spec);
  so::ExplicitFiniteStrainOptions eo;
  eo.density = law.density;
  eo.damping = 1000.0;
  eo.load_factor = [](double t) { return std::fmin(t / 0.004, 1.0); };
  eo.cell_scale = so::tyre_cell_scale(spec, 8, 6, n_wall);
  so::Config<3> c;
  c.mesh = so::make_tyre(spec, 8, 6, n_wall);
  c.order = 2;
  so::HyperelasticExplicit<double, 3> m(c, so::HyperelasticLaw(law.law), eo, {{"zmin", kP}}, rim());
  const auto& d = m.solid().discretization();
  m.advance(static_cast<std::int64_t>(std::ceil(0.008 / m.time_step())));
  const std::vector<double> u = pm::models::to_host(m.displacement());
  double zlow = 0.0;
  for (const auto n : so::side_nodes(d, "zmax")) zlow = std::fmin(zlow, d.coordinates[static_cast<std::size_t>(3 * n + 2)] + u[static_cast<std::size_t>(3 * n + 2)]);
  const double t1 = m.time(), speed = deflection / 0.005;
  so::PlateContact<double> plate(
      d, m.lumped_mass(), m.omega_max(), 0.1, 0.3,
      [t1, zlow, speed](double t) { return zlow + speed * std::fmin(0.005, std::fmax(0.0, t - t1)); },
      [t1, speed](double t) { return t - t1 < 0.005 ? speed : 0.0; });
  m.set_external_force([&plate](double t, const pm::View1<double>& uu, const pm::View1<double>& vv, const pm::View1<double>& rr) {
    plate.apply(t, uu, vv, rr);
  });
  m.set_damping(400.0);
  m.advance(static_cast<std::int64_t>(std::ceil(0.010 / m.time_step())));
  Pressed o;
  o.force = plate.force();
  o.nodes = plate.nodes_in_contact();
  const auto patch = plate.patch(d, m.displacement(), m.time());
  o.length = patch[0];
  o.width = patch[1];
  o.dt_crit = m.critical_time_step();
  return o;
}

}  // namespace

TEST(TyreLayers, TheLayeredWallIsSofterOnThePlate) {
  so::TyreSpec smeared{}, layered{};
  layered.layered = true;
  EXPECT_THROW(so::tyre_layers(layered, 12, 6, 2), std::invalid_argument);  // an odd n_wall >= 3
  const so::TyreLayers lay = so::tyre_layers(layered, 12, 6, 3);
  // the membrane stiffness is the smeared law's on the sidewall: (2 E_r + E_cord) h / 3 = E_eq h
  const so::TyreLaw eq = so::tyre_equivalent_law(smeared);
  EXPECT_NEAR((2.0 * lay.E_rubber + lay.E_cord_max) / 3.0, eq.E_equivalent, 1e-9 * eq.E_equivalent);
  // pressed 15 mm: the smeared wall (one cell through, the default) against the layered one (three cells). The
  // patch itself needs the bench's finer mesh (docs/VALIDATION.md, the tyre alone): here 8 x 6 cells resolve
  // only the load, which drops with the plies' bending share.
  const double deflection = 0.015;
  const Pressed s = press_on_plate(smeared, 1, deflection), l = press_on_plate(layered, 3, deflection);
  std::printf("tyre 8 x 6 on the plate, %.0f mm: smeared (1 cell through) %.5g N, patch %.4f x %.4f m (%d nodes), dt_crit %.4g s; "
              "layered (3 cells) %.5g N, patch %.4f x %.4f m (%d nodes), dt_crit %.4g s\n",
              1e3 * deflection, s.force, s.length, s.width, s.nodes, s.dt_crit, l.force, l.length, l.width, l.nodes, l.dt_crit);
  EXPECT_GT(l.force, 0.3 * s.force);
  EXPECT_LT(l.force, 0.9 * s.force);
  // the thin stiff cord layer shortens the critical step: 3 cells through (x 1/3) and the layer's modulus
  EXPECT_LT(l.dt_crit, 0.35 * s.dt_crit);
  EXPECT_GT(l.dt_crit, 0.15 * s.dt_crit);
}

namespace {

// The mean outer radius of the crown line (the outer-surface nodes on the section's centre line) after `t_end` of
// the inflation ramped over 4 ms (damping 1000 1/s), and the critical step at the reference state.
std::array<double, 2> crown_growth(const so::TyreSpec& spec, int n_wall, double t_end) {
  const so::TyreLaw law = so::tyre_equivalent_law(spec);
  so::ExplicitFiniteStrainOptions eo;
  eo.density = law.density;
  eo.damping = 1000.0;
  eo.load_factor = [](double t) { return std::fmin(t / 0.004, 1.0); };
  eo.cell_scale = so::tyre_cell_scale(spec, 8, 6, n_wall);
  eo.fibre_stiffness = so::tyre_fibre_stiffness(spec, 8, 6, n_wall);  // empty but with the rebar belt
  eo.fibre_angle_deg = spec.belt_angle_deg;
  so::Config<3> c;
  c.mesh = so::make_tyre(spec, 8, 6, n_wall);
  c.order = 2;
  so::HyperelasticExplicit<double, 3> m(c, so::HyperelasticLaw(law.law), eo, {{"zmin", kP}}, rim());
  const auto& d = m.solid().discretization();
  m.advance(static_cast<std::int64_t>(std::ceil(t_end / m.time_step())));
  const std::vector<double> u = pm::models::to_host(m.displacement());
  double r0 = 0.0, r1 = 0.0, count = 0.0;
  for (const auto n : so::side_nodes(d, "zmax")) {
    if (d.lattice_index(n)[1] != d.lattice[1] / 2) continue;
    const std::size_t i = static_cast<std::size_t>(3 * n);
    const double x = d.coordinates[i], z = d.coordinates[i + 2];
    r0 += std::sqrt(x * x + z * z);
    r1 += std::sqrt((x + u[i]) * (x + u[i]) + (z + u[i + 2]) * (z + u[i + 2]));
    count += 1.0;
  }
  return {r1 / r0 - 1.0, m.critical_time_step()};
}

}  // namespace

TEST(TyreBelt, TheBeltLayerSitsOverTheCrownOnly) {
  so::TyreSpec layered{}, belted{};
  layered.layered = belted.layered = belted.belted = true;
  layered.belted = false;
  const int nt = 4, ns = 12, nw = 3;
  const so::TyreLayers a = so::tyre_layers(layered, nt, ns, nw), b = so::tyre_layers(belted, nt, ns, nw);
  // the laminate by hand (python, classical lamination theory, +-20 deg, E_1 = 50.0045 GPa, E_2 = 8 MPa,
  // G_12 = 2.667 MPa, nu_12 = 0.45): A11 / t = 3.89931e10, A22 / t = 6.9236e8, free E_x = 4.18674e8 Pa
  EXPECT_NEAR(b.E_belt_held, 3.89931e10, 1e-5 * 3.89931e10);
  EXPECT_NEAR(b.E_belt_across, 6.9236e8, 1e-4 * 6.9236e8);
  EXPECT_NEAR(b.E_belt_free, 4.18674e8, 1e-5 * 4.18674e8);
  EXPECT_EQ(b.E_belt, b.E_belt_held);
  EXPECT_EQ(b.belt_layer, 2);  // outside the cord layer (k = 1), toward the tread
  // 12 cells along the 2 x 0.3284 m contour (54.7 mm each): the belt's +-90 mm covers the two crown cells and
  // 0.645 of the next on each side
  EXPECT_EQ(b.belt_cells, 4);
  const so::TyreLaw eq = so::tyre_equivalent_law(layered);
  const double half = so::tyre_section(layered).half_length, ds = 2.0 * half / ns, t_belt = 2 * 1.2e-3, hc = 0.020 / 3.0;
  int changed = 0;
  for (int k = 0; k < nw; ++k)
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nt; ++i) {
        const std::size_t id = static_cast<std::size_t>(i + nt * (j + ns * k));
        if (a.cell_scale[id] == b.cell_scale[id]) continue;  // the unbelted scales, bitwise
        ++changed;
        EXPECT_EQ(k, 2);
        EXPECT_TRUE(j >= 4 && j <= 7) << "contour cell " << j;
        const double f = (j == 5 || j == 6) ? 1.0 : (0.090 - ds) / ds;  // the crown's tread gauge: 20 mm
        EXPECT_NEAR(b.cell_scale[id], (6.0e6 + f * b.E_belt * t_belt / hc) / eq.E_equivalent, 1e-9 * b.cell_scale[id]);
      }
  EXPECT_EQ(changed, 4 * nt);
  EXPECT_NEAR(b.E_belt_layer_max, 6.0e6 + 3.89931e10 * t_belt / hc, 1e-5 * b.E_belt_layer_max);  // 14.04 GPa
  // the other reading of the plies (the laminate free to contract across)
  so::TyreSpec free_belt = belted;
  free_belt.belt_laterally_free = true;
  EXPECT_EQ(so::tyre_layers(free_belt, nt, ns, nw).E_belt, b.E_belt_free);
  // the belt needs the layered wall; bad belt values are refused
  so::TyreSpec bad = belted;
  bad.layered = false;
  EXPECT_THROW(so::tyre_cell_scale(bad, nt, ns, nw), std::invalid_argument);
  bad = belted;
  bad.belt_fraction = 1.0;
  EXPECT_THROW(so::tyre_layers(bad, nt, ns, nw), std::invalid_argument);
}

TEST(TyreBelt, TheBeltHoldsTheCrownOnInflation) {
  // 8 x 6 x 3 cells, 2.5 ms of the inflation ramped over 4 ms (the pressure at 0.22 MPa): the layered crown grows
  // freely, the belted one is held by the belt's hoop stiffness (~ 90 x the layered crown's membrane stiffness);
  // the belt layer's modulus shortens the critical step
  so::TyreSpec layered{}, belted{};
  layered.layered = belted.layered = belted.belted = true;
  const auto l = crown_growth(layered, 3, 0.0025), b = crown_growth(belted, 3, 0.0025);
  std::printf("tyre 8 x 6 x 3, 2.5 ms of inflation: crown growth layered %+.4f %%, belted %+.4f %%; dt_crit %.4g / %.4g s (ratio %.3f)\n",
              100.0 * l[0], 100.0 * b[0], l[1], b[1], b[1] / l[1]);
  EXPECT_GT(l[0], 0.0);
  EXPECT_LT(b[0], 0.2 * l[0]);
  EXPECT_LT(b[1], 0.35 * l[1]);
  EXPECT_GT(b[1], 0.08 * l[1]);
}

// --- the rebar belt (TyreSpec::belt_rebar; seed 002 paper 2 §4, the belt reinforcements) ----------------------

namespace {

// A free block [0, 2] x [0, 1] x [0, 1] (2 x 1 x 1 cells, order 2, no constraints), rubber-like matrix.
so::Hyperelastic<double, 3> fibre_block() {
  so::BoxSpec b;
  b.lengths = {2.0, 1.0, 1.0};
  b.cells = {2, 1, 1};
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = 2;
  return so::Hyperelastic<double, 3>(c, so::HyperelasticLaw(block_law()));
}

struct FibreResponse {
  double energy = 0.0, force_x = 0.0, force_y = 0.0;  // the cords' energy, their force on the xmax and ymax nodes
};

// The cords' share at the homogeneous deformation F = diag(lx, ly, 1): (with fibres) - (without), residual at
// load factor 0 (r = f_int).
FibreResponse fibre_response(double k, double beta_deg, bool tension_only, double lx, double ly) {
  so::Hyperelastic<double, 3> a = fibre_block(), b = fibre_block();
  b.set_fibres(std::vector<double>(2, k), beta_deg, tension_only);
  const auto& X = a.discretization().coordinates;
  std::vector<double> u(X.size(), 0.0);
  for (std::size_t n = 0; 3 * n < X.size(); ++n) {
    u[3 * n] = (lx - 1.0) * X[3 * n];
    u[3 * n + 1] = (ly - 1.0) * X[3 * n + 1];
  }
  pm::View1<double> uv = pm::models::to_device<double>("test::u", u), ra("test::ra", u.size()), rb("test::rb", u.size());
  a.residual(uv, 0.0, ra);
  b.residual(uv, 0.0, rb);
  const std::vector<double> ha = pm::models::to_host(ra), hb = pm::models::to_host(rb);
  FibreResponse o;
  o.energy = b.strain_energy() - a.strain_energy();
  for (std::size_t n = 0; 3 * n < X.size(); ++n) {
    if (X[3 * n] > 2.0 - 1e-12) o.force_x += hb[3 * n] - ha[3 * n];
    if (X[3 * n + 1] > 1.0 - 1e-12) o.force_y += hb[3 * n + 1] - ha[3 * n + 1];
  }
  return o;
}

}  // namespace

TEST(TyreBelt, RebarFibreLawByHand) {
  const double k = 1.0e9, lam = 1.01, Ea = 0.5 * (lam * lam - 1.0), V = 2.0;
  // beta = 0: both families along x (the element's direction 0). Stretched along x: P_xx = 2 k E_a lam on the
  // xmax face (area 1), energy 2 x k E_a^2 / 2 x V
  FibreResponse r = fibre_response(k, 0.0, false, lam, 1.0);
  std::printf("fibre law: along the cords force %.10g N (by hand %.10g), energy %.10g J (%.10g)\n", r.force_x, 2.0 * k * Ea * lam,
              r.energy, k * Ea * Ea * V);
  EXPECT_NEAR(r.force_x, 2.0 * k * Ea * lam, 1e-9 * k * Ea);
  EXPECT_NEAR(r.energy, k * Ea * Ea * V, 1e-9 * k * Ea * Ea * V);
  EXPECT_NEAR(r.force_y, 0.0, 1e-9 * k * Ea);
  // stretched across the cords (along y): no force, no energy
  r = fibre_response(k, 0.0, false, 1.0, lam);
  EXPECT_NEAR(r.force_x, 0.0, 1e-9 * k * Ea);
  EXPECT_NEAR(r.force_y, 0.0, 1e-9 * k * Ea);
  EXPECT_NEAR(r.energy, 0.0, 1e-9 * k * Ea * Ea * V);
  // beta = 90 deg: both families along y (direction 1): the y stretch is carried (ymax face area 2)
  r = fibre_response(k, 90.0, false, 1.0, lam);
  EXPECT_NEAR(r.force_y, 2.0 * 2.0 * k * Ea * lam, 1e-9 * k * Ea);
  EXPECT_NEAR(r.force_x, 0.0, 1e-9 * k * Ea);
  // compressed along the cords: compression carried, or not (tension-only)
  const double lc = 0.99, Ec = 0.5 * (lc * lc - 1.0);
  EXPECT_NEAR(fibre_response(k, 0.0, false, lc, 1.0).force_x, 2.0 * k * Ec * lc, 1e-9 * k * std::fabs(Ec));
  r = fibre_response(k, 0.0, true, lc, 1.0);
  EXPECT_EQ(r.force_x, 0.0);
  EXPECT_EQ(r.energy, 0.0);
  // the +-20 deg pair: E_a = cos^2 E_xx along x, sin^2 E_yy across: energies (k E_a^2 V per pair) in the ratio
  // cos^4 / sin^4 = 57.0 at any stretch (the laminate's circumferential vs lateral cord stiffness, 2 k cos^4 vs
  // 2 k sin^4)
  const double b = 20.0 * 3.14159265358979323846 / 180.0, c2 = std::cos(b) * std::cos(b), s2 = std::sin(b) * std::sin(b);
  const FibreResponse rx = fibre_response(k, 20.0, false, lam, 1.0), ry = fibre_response(k, 20.0, false, 1.0, lam);
  std::printf("+-20 deg pair: energy along %.10g, across %.10g J, ratio %.6f (cos^4 / sin^4 = %.6f)\n", rx.energy, ry.energy,
              rx.energy / ry.energy, c2 * c2 / (s2 * s2));
  EXPECT_NEAR(rx.energy, k * c2 * c2 * Ea * Ea * V, 1e-9 * rx.energy);
  EXPECT_NEAR(rx.energy / ry.energy, c2 * c2 / (s2 * s2), 1e-8 * c2 * c2 / (s2 * s2));
  EXPECT_NEAR(rx.force_x, 2.0 * k * c2 * c2 * Ea * lam, 1e-9 * k * Ea);
  // the tangent (with the cords, 20 deg) against central differences of the residual at a general state
  so::Hyperelastic<double, 3> m = fibre_block();
  m.set_fibres(std::vector<double>(2, k), 20.0);
  const auto& X = m.discretization().coordinates;
  std::vector<double> u(X.size()), v(X.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    u[i] = 0.02 * X[(i + 1) % X.size()] + 0.01 * X[i] * X[i];
    v[i] = std::sin(1.0 + 3.0 * static_cast<double>(i));
  }
  pm::View1<double> uv = pm::models::to_device<double>("test::u", u), r0("test::r0", u.size());
  m.residual(uv, 0.0, r0, true);
  const so::Triplets K = m.assemble_tangent();
  std::vector<double> Kv(u.size(), 0.0);
  for (std::size_t t = 0; t < K.values.size(); ++t)
    Kv[static_cast<std::size_t>(K.rows[t])] += K.values[t] * v[static_cast<std::size_t>(K.cols[t])];
  const double h = 1e-7;
  std::vector<double> up(u), um(u);
  for (std::size_t i = 0; i < u.size(); ++i) {
    up[i] += h * v[i];
    um[i] -= h * v[i];
  }
  pm::View1<double> upv = pm::models::to_device<double>("test::up", up), umv = pm::models::to_device<double>("test::um", um),
                    rp("test::rp", u.size()), rm("test::rm", u.size());
  m.residual(upv, 0.0, rp);
  m.residual(umv, 0.0, rm);
  const std::vector<double> hp = pm::models::to_host(rp), hm = pm::models::to_host(rm);
  double err = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < u.size(); ++i) {
    const double fd = (hp[i] - hm[i]) / (2.0 * h);
    err = std::fmax(err, std::fabs(fd - Kv[i]));
    norm = std::fmax(norm, std::fabs(Kv[i]));
  }
  std::printf("rebar tangent: max |K v - difference| %.3g of max |K v| %.4g\n", err, norm);
  EXPECT_LT(err, 1e-6 * norm);
  // bad values are refused
  EXPECT_THROW(m.set_fibres(std::vector<double>(1, k), 20.0), std::invalid_argument);  // too few cells
  EXPECT_THROW(m.set_fibres(std::vector<double>(2, -1.0), 20.0), std::invalid_argument);
}

TEST(TyreBelt, RebarBeltCellsAndCordStiffness) {
  so::TyreSpec layered{}, rebar{};
  layered.layered = rebar.layered = rebar.belted = rebar.belt_rebar = true;
  const int nt = 4, ns = 12, nw = 3;
  const so::TyreLayers a = so::tyre_layers(layered, nt, ns, nw), b = so::tyre_layers(rebar, nt, ns, nw);
  // the matrix is the layered wall's, bitwise: the belt layer keeps the rubber
  ASSERT_EQ(a.cell_scale.size(), b.cell_scale.size());
  for (std::size_t i = 0; i < a.cell_scale.size(); ++i) EXPECT_EQ(a.cell_scale[i], b.cell_scale[i]);
  EXPECT_TRUE(a.fibre_stiffness.empty());
  EXPECT_TRUE(so::tyre_fibre_stiffness(layered, nt, ns, nw).empty());
  ASSERT_EQ(b.fibre_stiffness.size(), b.cell_scale.size());
  EXPECT_EQ(b.belt_cells, 4);
  // k = f E_cord V_f (t_belt / 2) / h_c: 200e9 x 0.25 x 1.2e-3 / (0.020 / 3) = 9.0 GPa in the crown cells
  const double half = so::tyre_section(layered).half_length, ds = 2.0 * half / ns, hc = 0.020 / 3.0;
  int cells = 0;
  for (int k = 0; k < nw; ++k)
    for (int j = 0; j < ns; ++j)
      for (int i = 0; i < nt; ++i) {
        const double kf = b.fibre_stiffness[static_cast<std::size_t>(i + nt * (j + ns * k))];
        if (kf == 0.0) continue;
        ++cells;
        EXPECT_EQ(k, 2);
        EXPECT_TRUE(j >= 4 && j <= 7) << "contour cell " << j;
        const double f = (j == 5 || j == 6) ? 1.0 : (0.090 - ds) / ds;
        EXPECT_NEAR(kf, f * 200.0e9 * 0.25 * 1.2e-3 / hc, 1e-9 * kf);
      }
  EXPECT_EQ(cells, 4 * nt);
  EXPECT_NEAR(b.fibre_k_max, 9.0e9, 1e-9 * 9.0e9);
  so::TyreSpec bad = rebar;
  bad.belted = false;
  EXPECT_THROW(so::tyre_fibre_stiffness(bad, nt, ns, nw), std::invalid_argument);
}

TEST(TyreBelt, TheRebarBeltHoldsTheCrownOnInflation) {
  // 8 x 6 x 3 cells, 2.5 ms of the inflation as TheBeltHoldsTheCrownOnInflation: the cords (9 GPa per family,
  // 2 k cos^4 = 14.0 GPa round the wheel) hold the crown as the isotropic A11 layer does, and the run stays finite
  // (no inverted element) at 0.9 of the power iteration's step. That step is the layered wall's (measured ratio
  // 1.000): the cords stiffen the layer along the 0.35 m cells round the wheel, not through its 6.7 mm thickness
  // (where the isotropic 14 GPa layer sets the highest mode: ratio 0.205), so the cord layer's through-thickness
  // mode stays the highest (RebarStepSeesTheCords: the step does see the cords where they set the highest mode)
  so::TyreSpec layered{}, rebar{};
  layered.layered = rebar.layered = rebar.belted = rebar.belt_rebar = true;
  const auto l = crown_growth(layered, 3, 0.0025), b = crown_growth(rebar, 3, 0.0025);
  std::printf("tyre 8 x 6 x 3, 2.5 ms of inflation: crown growth layered %+.4f %%, rebar belt %+.4f %%; dt_crit %.4g / %.4g s (ratio %.3f)\n",
              100.0 * l[0], 100.0 * b[0], l[1], b[1], b[1] / l[1]);
  EXPECT_GT(l[0], 0.0);
  EXPECT_TRUE(std::isfinite(b[0]));
  EXPECT_LT(std::fabs(b[0]), 0.2 * l[0]);
  EXPECT_NEAR(b[1] / l[1], 1.0, 0.1);
}

TEST(TyreBelt, RebarStepSeesTheCords) {
  // the free block (2 x 1 x 1 cells, order 2, rho 1000) with cords along x 250 and 1000 x stiffer than the matrix's
  // P-wave modulus (4 MPa): the cords set the highest mode, omega ~ sqrt(2 k / rho) / dx, so 4 x k halves dt_crit
  auto dt_crit = [](double k) {
    so::BoxSpec bs;
    bs.lengths = {2.0, 1.0, 1.0};
    bs.cells = {2, 1, 1};
    so::Config<3> c;
    c.mesh = so::make_box<3>(bs);
    c.order = 2;
    so::ExplicitFiniteStrainOptions eo;
    eo.density = 1000.0;
    if (k > 0.0) eo.fibre_stiffness = std::vector<double>(2, k);
    so::HyperelasticExplicit<double, 3> m(c, so::HyperelasticLaw(block_law()), eo);
    return m.critical_time_step();
  };
  const double d0 = dt_crit(0.0), d1 = dt_crit(0.5e9), d4 = dt_crit(2.0e9);
  std::printf("rebar block: dt_crit matrix only %.4g s, k 0.5 GPa %.4g s, k 2 GPa %.4g s (ratio %.4f)\n", d0, d1, d4, d4 / d1);
  EXPECT_LT(d1, 0.1 * d0);
  EXPECT_NEAR(d4 / d1, 0.5, 0.01);
}
