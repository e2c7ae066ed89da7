// Structural dynamics of the solid layer (issue 34; models/solid/dynamics.hpp, kernels/solid/mass.hpp) against
// analytic answers. Every number an assertion rests on is printed; measured values in the comments (double,
// x86-64 AVX2 build).
//  - mass: the row-sum lumped mass is positive and sums to rho x volume (orders 1..4, 2D and 3D, distorted
//    cells); the matrix-free consistent mass equals the assembled one;
//  - a fixed-free bar (2D plane stress, nu = 0: one-dimensional axial motion) in its fundamental mode: period
//    4 L / c, c = sqrt(E / rho), from the zero crossings of the tip displacement of Newmark and central-difference
//    histories, converging with the mesh;
//  - Newmark's average acceleration conserves the energy of an undamped free vibration to round-off; central
//    differences keep it bounded; Newmark is second order in dt;
//  - central differences at 1.05 x the power-iteration dt_crit blow up, at 0.9 x they stay bounded, and a dt
//    above dt_crit is refused unless forced;
//  - Rayleigh damping: the logarithmic decrement of the fundamental mode gives zeta = alpha / (2 omega) + beta_K
//    omega / 2; the energy balance holds with the dissipation;
//  - base excitation: a prescribed root motion of a rigidly moving bar is carried without strain;
//  - a slender cantilever's first bending frequency against Euler-Bernoulli.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "solid/dynamics.hpp"

namespace pm = polymech;
namespace so = polymech::solid;

namespace {

// A unit 2D block of nx x ny order-2 cells, E = 1, nu = 0.3, clamped on xmin.
so::Config<2> clamped_block(int nx, int ny) {
  so::BoxSpec b;
  b.cells = {nx, ny, 1};
  so::Config<2> c;
  c.mesh = so::make_box<2>(b);
  c.order = 2;
  c.stiffness = pm::materials::isotropic_stiffness(1.0, 0.3);
  c.dirichlet.push_back({"xmin", 3u, {}});
  return c;
}

constexpr double pi = 3.14159265358979323846;

// A fixed-free bar [0, L] x [0, h], plane stress, nu = 0, clamped at x = 0 (c = sqrt(E / rho) = 1, L = 1).
so::Config<2> bar(int order, int n, double L = 1.0, double h = 0.1) {
  so::BoxSpec b;
  b.lengths = {L, h, 1.0};
  b.cells = {n, 1, 1};
  so::Config<2> c;
  c.mesh = so::make_box<2>(b);
  c.order = order;
  c.plane = so::Plane::stress;
  c.stiffness = pm::materials::isotropic_stiffness(1.0, 0.0);
  c.dirichlet.push_back({"xmin", 3u, {}});
  return c;
}

// The bar's fundamental mode u_x = sin(pi x / (2 L)) as an initial displacement.
so::PointFunction first_mode(double L = 1.0) {
  return [L](const double* x, double* u) {
    u[0] = std::sin(pi * x[0] / (2.0 * L));
    u[1] = 0.0;
    u[2] = 0.0;
  };
}

// The DoF of component c at the node nearest x.
template <int D>
pm::Index dof_near(const so::SolidProblem<double, D>& m, const std::array<double, D>& x, int c) {
  const auto& co = m.discretization().coordinates;
  double best = 1e300;
  pm::Index k = 0;
  for (std::int64_t v = 0; v < m.discretization().nodes; ++v) {
    double d2 = 0.0;
    for (int d = 0; d < D; ++d) d2 += (co[static_cast<std::size_t>(D * v + d)] - x[d]) * (co[static_cast<std::size_t>(D * v + d)] - x[d]);
    if (d2 < best) {
      best = d2;
      k = static_cast<pm::Index>(D * v + c);
    }
  }
  return k;
}

double value_at(const pm::View1<double>& v, pm::Index i) {
  double h = 0.0;
  Kokkos::deep_copy(h, Kokkos::subview(v, i));
  return h;
}

// Zero crossings (linear interpolation) of a history; the period is twice their mean spacing.
double period_from_crossings(const std::vector<double>& t, const std::vector<double>& y) {
  std::vector<double> z;
  for (std::size_t k = 1; k < y.size(); ++k)
    if ((y[k - 1] > 0.0) != (y[k] > 0.0)) z.push_back(t[k - 1] + (t[k] - t[k - 1]) * y[k - 1] / (y[k - 1] - y[k]));
  if (z.size() < 2) return 0.0;
  return 2.0 * (z.back() - z.front()) / static_cast<double>(z.size() - 1);
}

template <class Integrator>
double tip_period(Integrator& m, double t_end) {
  const pm::Index tip = dof_near<2>(m, {1.0, 0.0}, 0);
  std::vector<double> t{m.time()}, y{value_at(m.displacement(), tip)};
  while (m.time() < t_end) {
    m.step();
    t.push_back(m.time());
    y.push_back(value_at(m.displacement(), tip));
  }
  return period_from_crossings(t, y);
}

// Random displacement on the free DoFs (rich in every mode).
std::vector<double> rough(pm::Index n, double amplitude) {
  std::vector<double> u(static_cast<std::size_t>(n));
  std::uint32_t s = 12345u;
  for (auto& v : u) {
    s = s * 1664525u + 1013904223u;
    v = amplitude * (static_cast<double>(s >> 8) / 16777216.0 - 0.5);
  }
  return u;
}

}  // namespace

// (a) Lumped mass: positive, total rho x volume; consistent mass matrix-free = assembled.
template <int D>
void lumped_mass_checks(int order) {
  so::BoxSpec b;
  b.cells = {3, 2, 2};
  b.distortion = so::Distortion::smooth;
  b.amplitude = 0.15;
  so::Config<D> c;
  c.mesh = so::make_box<D>(b);
  c.order = order;
  so::DynamicsOptions o;
  o.density = 2.5;
  so::NewmarkOptions no;
  no.solver = so::NewmarkSolver::cg;  // no factorization needed here
  so::Newmark<double, D> m(c, o, 0.1, no);
  const std::vector<double> mh = pm::models::to_host(m.lumped_mass());
  double total = 0.0, smallest = 1e300;
  for (std::size_t i = 0; i < mh.size(); i += D) {
    total += mh[i];
    smallest = std::fmin(smallest, mh[i]);
  }
  // the consistent mass applied to a random vector against the assembled triplets
  const auto x = rough(m.dof_count(), 1.0);
  pm::View1<double> xv("x", m.dof_count()), yv("y", m.dof_count());
  {
    auto h = Kokkos::create_mirror_view(xv);
    for (std::size_t i = 0; i < x.size(); ++i) h(i) = x[i];
    Kokkos::deep_copy(xv, h);
  }
  m.mass_apply(xv, yv);
  const std::vector<double> y = pm::models::to_host(yv);
  const so::Triplets t = so::assemble_mass(m.assembly_input(), o.density);
  std::vector<double> ya(x.size(), 0.0);
  double entries = 0.0;
  for (std::size_t k = 0; k < t.values.size(); ++k) {
    ya[static_cast<std::size_t>(t.rows[k])] += t.values[k] * x[static_cast<std::size_t>(t.cols[k])];
    entries += t.values[k];
  }
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    diff = std::fmax(diff, std::fabs(y[i] - ya[i]));
    norm = std::fmax(norm, std::fabs(ya[i]));
  }
  std::printf("mass D=%d p=%d: lumped total %.15f (rho V = %.15f), min entry %.3e, sum of M %.15f, |M x - M_asm x| / |M x| "
              "%.1e\n",
              D, order, total, o.density, smallest, entries / D, diff / norm);
  EXPECT_NEAR(total, o.density, 1e-12 * o.density);
  EXPECT_NEAR(entries / D, o.density, 1e-12 * o.density);
  EXPECT_GT(smallest, 0.0);
  EXPECT_LT(diff / norm, 1e-12);
}

TEST(SolidMass, LumpedPositiveAndTotal) {
  for (int p = 1; p <= 4; ++p) {
    lumped_mass_checks<2>(p);
    lumped_mass_checks<3>(p);
  }
}

// (b) Fixed-free bar: period 4 L / c from the time histories, converging with the mesh (order 1: error ~ h^2).
TEST(SolidDynamicsBar, PeriodNewmarkAndCentralDifferences) {
  const double T = 4.0;  // 4 L / c
  std::vector<double> err_nm, err_cd;
  for (int n : {8, 16}) {
    so::DynamicsOptions o;
    o.track_energy = false;  // fewer kernels per step (the ctest budget)
    so::Newmark<double, 2> nm(bar(1, n), o, T / 400.0);
    nm.set_initial(first_mode());
    const double Pn = tip_period(nm, 2.1 * T);
    so::CentralDifference<double, 2> cd(bar(1, n), o);
    cd.set_initial(first_mode());
    const double Pc = tip_period(cd, 2.1 * T);
    std::printf("bar p=1 n=%2d: Newmark period %.6f (%+.2e), central differences period %.6f (%+.2e, dt %.4f = 0.9 dt_crit, "
                "omega_max %.3f in %d power iterations)\n",
                n, Pn, Pn / T - 1.0, Pc, Pc / T - 1.0, cd.time_step(), cd.omega_max(), cd.power_iterations_used());
    err_nm.push_back(std::fabs(Pn / T - 1.0));
    err_cd.push_back(std::fabs(Pc / T - 1.0));
  }
  // measured: Newmark -1.58e-3, -3.81e-4 (the consistent mass stiffens: period short by about (k h)^2 / 24);
  // central differences +7.7e-4, +7.6e-5 (the lumped mass softens, the central-difference step shortens the period:
  // the two partly cancel)
  EXPECT_LT(err_nm[0], 3e-3);
  EXPECT_LT(err_cd[0], 3e-3);
  EXPECT_LT(err_nm[1], 8e-4);
  EXPECT_LT(err_cd[1], 8e-4);
  EXPECT_GT(err_nm[0] / err_nm[1], 3.0);
  EXPECT_GT(err_cd[0] / err_cd[1], 3.0);
  // order 2: much closer on a coarse mesh
  so::DynamicsOptions quiet;
  quiet.track_energy = false;
  so::Newmark<double, 2> nm2(bar(2, 4), quiet, T / 200.0);
  nm2.set_initial(first_mode());
  const double P2 = tip_period(nm2, 2.1 * T);
  std::printf("bar p=2 n=4: Newmark period %.6f (%+.2e)\n", P2, P2 / T - 1.0);
  EXPECT_NEAR(P2 / T, 1.0, 2e-4);
}

// (c) Energy: Newmark (average acceleration) conserves it to round-off; central differences keep it bounded.
TEST(SolidDynamicsEnergy, NewmarkConservesCentralDifferencesBounded) {
  const so::Config<2> c = clamped_block(4, 3);
  so::DynamicsOptions o;
  so::Newmark<double, 2> nm(c, o, 0.05);
  nm.set_state(rough(nm.dof_count(), 1e-2), {});
  nm.step();
  const double E0 = nm.energies().initial;
  double worst = 0.0;
  for (int k = 0; k < 500; ++k) {
    nm.step();
    if (k % 50 == 49) worst = std::fmax(worst, std::fabs(nm.energies().total() / E0 - 1.0));
  }
  const so::Energies e = nm.energies();
  std::printf("Newmark energy over 500 steps (rough start): E0 %.6e, worst |E / E0 - 1| %.1e, balance %.1e\n", E0, worst,
              e.balance_error());
  EXPECT_LT(worst, 1e-10);  // measured 1.1e-13
  EXPECT_LT(std::fabs(e.balance_error()), 1e-10);

  so::CentralDifference<double, 2> cd(c, o);
  cd.set_initial(first_mode());
  cd.step();
  const double C0 = cd.energies().initial;
  double cworst = 0.0;
  for (int k = 0; k < 1000; ++k) {
    cd.step();
    if (k % 10 == 9) cworst = std::fmax(cworst, std::fabs(cd.energies().total() / C0 - 1.0));
  }
  std::printf("central differences energy over 1000 steps (dt %.4f): worst |E / E0 - 1| %.2e\n", cd.time_step(), cworst);
  EXPECT_LT(cworst, 2e-2);  // measured 1.33e-2 (the energy of central differences oscillates at O((omega dt)^2))
}

// (d) Newmark is second order in dt: the error at t = 1 against a fine-dt reference falls by ~4 per halving.
TEST(SolidDynamicsNewmark, SecondOrderInTime) {
  const double t_end = 1.5;
  so::DynamicsOptions quiet;
  quiet.track_energy = false;
  auto run = [&](double dt) {
    so::Newmark<double, 2> m(bar(2, 4), quiet, dt);
    m.set_initial(first_mode());
    const long steps = std::lround(t_end / dt);
    m.advance(steps);
    return pm::models::to_host(m.displacement());
  };
  const std::vector<double> ref = run(t_end / 800.0);
  std::vector<double> err;
  for (int n : {25, 50, 100}) {
    const auto u = run(t_end / n);
    double e = 0.0, r = 0.0;
    for (std::size_t i = 0; i < u.size(); ++i) {
      e += (u[i] - ref[i]) * (u[i] - ref[i]);
      r += ref[i] * ref[i];
    }
    err.push_back(std::sqrt(e / r));
    std::printf("Newmark dt = %.4f: relative error %.3e\n", t_end / n, err.back());
  }
  const double r1 = err[0] / err[1], r2 = err[1] / err[2];
  std::printf("Newmark error ratios per halving: %.3f, %.3f (expected 4)\n", r1, r2);
  EXPECT_NEAR(r1, 4.0, 0.4);
  EXPECT_NEAR(r2, 4.0, 0.4);
}

// (e) Central differences above / below the critical step from power iteration.
TEST(SolidDynamicsCentralDifference, StabilityLimit) {
  const so::Config<2> c = clamped_block(4, 4);
  so::DynamicsOptions o;
  so::CentralDifference<double, 2> probe(c, o);
  const double dtc = probe.critical_time_step();
  std::printf("central differences: omega_max %.6f (%d power iterations), dt_crit %.6f\n", probe.omega_max(),
              probe.power_iterations_used(), dtc);
  EXPECT_THROW((so::CentralDifference<double, 2>(c, o, 1.05 * dtc)), std::invalid_argument);
  auto growth = [&](double factor) {
    so::ExplicitOptions e;
    e.allow_unstable = true;
    so::DynamicsOptions quiet;
    quiet.track_energy = false;
    so::CentralDifference<double, 2> m(c, quiet, factor * dtc, e);
    m.set_state(rough(m.dof_count(), 1e-3), {});
    const double E0 = m.energies().total();
    double worst = 0.0;
    for (int k = 0; k < 400; ++k) {
      m.step();
      worst = std::fmax(worst, m.energies().total() / E0);
      if (!(worst < 1e30)) break;
    }
    return worst;
  };
  const double unstable = growth(1.05), stable = growth(0.9);
  std::printf("central differences, 400 steps from a rough start: max E / E0 = %.3e at 1.05 dt_crit, %.3f at 0.9 dt_crit\n",
              unstable, stable);
  EXPECT_GT(unstable, 1e6);  // measured 2.7e30
  EXPECT_LT(stable, 10.0);    // measured 0.88
}

// (f) Rayleigh damping: the decay of the fundamental mode gives zeta = alpha / (2 omega) + beta_K omega / 2.
TEST(SolidDynamicsDamping, RayleighDecay) {
  const so::Config<2> c = bar(2, 8);
  // the axial fundamental frequency pi c / (2 L) (the discrete one of p = 2, n = 8 is within 1e-6 of it; the bar's
  // lowest mode overall is a bending one, so fundamental_frequency() is not the reference here)
  const double omega = pi / 2.0;
  const double zeta = 0.02;
  so::DynamicsOptions o;
  o.rayleigh_mass = zeta * omega;          // alpha / (2 omega) = zeta / 2
  o.rayleigh_stiffness = zeta / omega;     // beta_K omega / 2 = zeta / 2
  const double period = 2.0 * pi / omega;
  // the logarithmic decrement of the tip's positive peaks (refined by a parabola through three samples)
  auto decay = [&](auto& m, long steps) {
    m.set_initial(first_mode());
    const pm::Index tip = dof_near<2>(m, {1.0, 0.0}, 0);
    std::vector<double> y{value_at(m.displacement(), tip)};
    for (long k = 0; k < steps; ++k) {
      m.step();
      y.push_back(value_at(m.displacement(), tip));
    }
    std::vector<double> peaks;
    for (std::size_t k = 1; k + 1 < y.size(); ++k)
      if (y[k] > y[k - 1] && y[k] >= y[k + 1] && y[k] > 0.0) {
        const double a = 0.5 * (y[k - 1] + y[k + 1]) - y[k], bb = 0.5 * (y[k + 1] - y[k - 1]);
        peaks.push_back(y[k] - bb * bb / (4.0 * a));
      }
    EXPECT_GE(peaks.size(), 4u);
    if (peaks.size() < 2) return 0.0;
    const double delta = std::log(peaks.front() / peaks.back()) / static_cast<double>(peaks.size() - 1);
    return delta / std::sqrt(4.0 * pi * pi + delta * delta);
  };
  so::Newmark<double, 2> m(c, o, period / 200.0);
  const double measured = decay(m, 200 * 5);
  so::CentralDifference<double, 2> cd(c, o);
  const double measured_cd = decay(cd, std::lround(5.0 * period / cd.time_step()));
  const so::Energies e = m.energies(), ec = cd.energies();
  std::printf("Rayleigh damping: zeta %.5f (Newmark), %.5f (central differences, dt %.4f), expected %.5f (%+.2e, %+.2e); "
              "Newmark dissipated %.4e of %.4e, balance %.1e; central differences balance %.1e\n",
              measured, measured_cd, cd.time_step(), zeta, measured / zeta - 1.0, measured_cd / zeta - 1.0, e.dissipated,
              e.initial, e.balance_error(), ec.balance_error());
  EXPECT_NEAR(measured / zeta, 1.0, 0.03);  // measured -1.6e-4
  EXPECT_NEAR(measured_cd / zeta, 1.0, 0.03);  // measured +3.4e-4
  EXPECT_LT(std::fabs(ec.balance_error()), 2e-2);  // measured 7.9e-8
  EXPECT_LT(std::fabs(e.balance_error()), 1e-9);   // measured 7.6e-12
}

// Base excitation: the clamped end of the bar moves axially as g s(t), s = sin(w t), from rest: the prescribed
// DoFs follow g s(t) exactly, the bar takes up energy, and the energy balance holds with the support's work
// (to O(dt^2): the prescribed DoFs' increment is not exactly dt (v_n + v_{n+1}) / 2).
TEST(SolidDynamicsBaseMotion, PrescribedRootMotion) {
  so::Config<2> c = bar(2, 8);
  c.dirichlet[0].value = [](const double*, double* u) {
    u[0] = 1e-2;
    u[1] = 0.0;
  };
  const double w = 1.3;
  so::DynamicsOptions o;
  o.base_motion.value = [w](double t) { return std::sin(w * t); };
  o.base_motion.rate = [w](double t) { return w * std::cos(w * t); };
  o.base_motion.acceleration = [w](double t) { return -w * w * std::sin(w * t); };
  so::Newmark<double, 2> m(c, o, 0.01);
  m.set_state(std::vector<double>{}, std::vector<double>{});
  m.advance(400);
  const pm::Index root = dof_near<2>(m, {0.0, 0.0}, 0);
  const double root_u = value_at(m.displacement(), root);
  const so::Energies e = m.energies();
  std::printf("base motion: root u %.9e (expected %.9e), kinetic %.4e strain %.4e work %.4e balance %.1e\n", root_u,
              1e-2 * std::sin(w * m.time()), e.kinetic, e.strain, e.external_work, e.balance_error());
  EXPECT_NEAR(root_u, 1e-2 * std::sin(w * m.time()), 1e-15);
  EXPECT_GT(e.kinetic + e.strain, 0.0);
  // the prescribed DoFs' du is not exactly dt (v_n + v_{n+1}) / 2: the balance holds to O(dt^2)
  EXPECT_LT(std::fabs(e.balance_error()), 1e-3);
  // central differences under the same motion: the root follows exactly, the response agrees with Newmark's
  so::CentralDifference<double, 2> cd(c, o);
  const long steps = std::lround(4.0 / cd.time_step());
  so::Newmark<double, 2> nm(c, o, 4.0 / static_cast<double>(steps));
  cd.advance(steps);
  nm.advance(steps);
  const pm::Index tip = dof_near<2>(m, {1.0, 0.0}, 0);
  const double tip_cd = value_at(cd.displacement(), tip), tip_nm = value_at(nm.displacement(), tip);
  const so::Energies ec = cd.energies();
  std::printf("base motion, t = %.3f: tip u %.6e (central differences, %ld steps) %.6e (Newmark), root %.9e; central "
              "differences balance %.1e\n",
              cd.time(), tip_cd, steps, tip_nm, value_at(cd.displacement(), root), ec.balance_error());
  EXPECT_NEAR(value_at(cd.displacement(), root), 1e-2 * std::sin(w * cd.time()), 1e-15);
  // lumped vs consistent mass, different time errors: measured 0.75 % apart (tip amplitude 3.3e-2)
  EXPECT_NEAR(tip_cd / tip_nm, 1.0, 0.02);
  EXPECT_LT(std::fabs(ec.balance_error()), 2e-2);
}

// (g) A slender cantilever's first bending frequency against Euler-Bernoulli: omega_1 = 1.8751^2 sqrt(E I / (rho A L^4)).
TEST(SolidDynamicsCantilever, FirstBendingFrequency) {
  so::BoxSpec b;
  const double L = 20.0, h = 1.0, E = 1000.0, rho = 1.0;
  b.lengths = {L, h, h};
  b.cells = {20, 2, 2};
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = 2;
  c.stiffness = pm::materials::isotropic_stiffness(E, 0.0);
  c.dirichlet.push_back({"xmin", 7u, {}});
  so::DynamicsOptions o;
  o.density = rho;
  so::Newmark<double, 3> m(c, o, 1.0);
  const double omega = m.fundamental_frequency();
  const double beta1 = 1.87510407;
  const double eb = beta1 * beta1 * std::sqrt(E * (h * h * h * h / 12.0) / (rho * h * h * L * L * L * L));
  std::printf("cantilever L/h = 20, p = 2: omega_1 %.6f, Euler-Bernoulli %.6f (%+.2e)\n", omega, eb, omega / eb - 1.0);
  EXPECT_NEAR(omega / eb, 1.0, 0.02);  // measured -1.6e-3 (shear and rotary inertia lower it)
}

// The matrix-free CG path of Newmark follows the factorized one (3D, order 2, damped, loaded by a ramped traction).
TEST(SolidDynamicsNewmark, CgMatchesDirect) {
  so::BoxSpec b;
  b.lengths = {4.0, 1.0, 1.0};
  b.cells = {4, 1, 1};
  so::Config<3> c;
  c.mesh = so::make_box<3>(b);
  c.order = 2;
  c.stiffness = pm::materials::isotropic_stiffness(1.0, 0.3);
  c.dirichlet.push_back({"xmin", 7u, {}});
  c.tractions.push_back({"xmax", {0.0, 1e-3, 0.0}});
  so::DynamicsOptions o;
  o.rayleigh_mass = 0.01;
  o.rayleigh_stiffness = 0.01;
  o.load_factor = [](double t) { return std::fmin(t, 1.0); };
  so::NewmarkOptions direct, cg;
  cg.solver = so::NewmarkSolver::cg;
  so::Newmark<double, 3> a(c, o, 0.1, direct), m(c, o, 0.1, cg);
  a.advance(40);
  m.advance(40);
  const auto ua = pm::models::to_host(a.displacement()), um = pm::models::to_host(m.displacement());
  double diff = 0.0, norm = 0.0;
  for (std::size_t i = 0; i < ua.size(); ++i) {
    diff = std::fmax(diff, std::fabs(ua[i] - um[i]));
    norm = std::fmax(norm, std::fabs(ua[i]));
  }
  const so::Energies e = a.energies();
  std::printf("Newmark CG vs LU after 40 steps: max |du| / max |u| %.1e (%d CG iterations in the last step); work %.4e, "
              "balance %.1e\n",
              diff / norm, m.last_iterations(), e.external_work, e.balance_error());
  EXPECT_GT(norm, 0.0);
  EXPECT_LT(diff / norm, 1e-8);
  EXPECT_LT(std::fabs(e.balance_error()), 1e-9);
}
