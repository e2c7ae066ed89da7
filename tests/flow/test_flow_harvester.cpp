// The flow-driven harvester (issue 36; seed 002 paper 1 case 2; models/fsi/flow_harvester.hpp) on its coarsest
// mesh, and the flow's Smagorinsky eddy viscosity (flow::FlowConfig::smagorinsky) against an exact shear flow.
// Measured on an Intel Xeon (lscpu: "Intel(R) Xeon(R) Processor", KVM), one thread.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

#include "flow/harvester_mesh.hpp"
#include "flow/navier_stokes.hpp"
#include "fsi/flow_harvester.hpp"

namespace fs = polymech::fsi;
namespace fl = polymech::flow;

namespace {

// Plane Couette flow u = (g y, 0) in [0, 2] x [0, 1] holds for any constant viscosity, and its |S| = g is uniform,
// so with C_s > 0 the step keeps it and the shear force on the top wall is rho (nu + (C_s Delta)^2 g) g L,
// Delta = sqrt(cell area) / 2 (the Q2 node spacing): the eddy viscosity's value and its use in the residual.
TEST(Smagorinsky, ShearFlowCarriesTheEddyViscosity) {
  const double g = 3.0, nu = 1e-3, rho = 2.0, cs = 0.2, L = 2.0;
  const int nx = 8, ny = 4;
  for (const double c_s : {0.0, cs}) {
    fl::QuadMesh mesh = fl::make_rectangle(0, 0, L, 1.0, nx, ny);
    for (std::int64_t n = 0; n < mesh.node_count(); ++n) {  // every boundary node prescribed; the top wall's force
      auto& t = mesh.tags[static_cast<std::size_t>(n)];
      if (t && mesh.x[2 * n + 1] > 1.0 - 1e-12) t = fl::kObstacle;
      else if (t) t = fl::kWall;
    }
    fl::FlowConfig cfg;
    cfg.rho = rho, cfg.nu = nu, cfg.smagorinsky = c_s;
    cfg.dirichlet_tags = fl::kWall | fl::kObstacle;
    cfg.pin_pressure = true;
    cfg.pin_value = 1.0;  // a pressure scale for Newton's test (the flow's pressure is constant)
    cfg.boundary_velocity = [g](unsigned, double, double y, double) -> fl::Vec2 { return {g * y, 0.0}; };
    fl::NavierStokes2D ns(std::move(mesh), cfg);
    for (std::int64_t n = 0; n < ns.mesh().node_count(); ++n) {
      ns.state()[2 * static_cast<std::size_t>(n)] = g * ns.mesh().x[2 * n + 1];
      ns.state()[2 * static_cast<std::size_t>(n) + 1] = 0.0;
      const std::int64_t p = ns.pressure_dof_of_node(n);
      if (p >= 0) ns.state()[static_cast<std::size_t>(p)] = 1.0;
    }
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(ns.step(0.01).converged);
    const double delta = 0.5 * std::sqrt((L / nx) * (1.0 / ny));
    const double expected = rho * (nu + c_s * c_s * delta * delta * g) * g * L;
    std::printf("C_s %.2f: the top wall's shear force %.12e, expected %.12e\n", c_s, std::fabs(ns.forces().drag), expected);
    EXPECT_NEAR(std::fabs(ns.forces().drag), expected, 1e-8 * expected);
    double err = 0.0;
    for (std::int64_t n = 0; n < ns.mesh().node_count(); ++n)
      err = std::max(err, std::fabs(ns.state()[2 * static_cast<std::size_t>(n)] - g * ns.mesh().x[2 * n + 1]));
    EXPECT_LT(err, 1e-10);
  }
  fl::FlowConfig bad;
  bad.smagorinsky = -0.1;
  EXPECT_THROW(fl::NavierStokes2D(fl::make_rectangle(0, 0, 1, 1, 2, 2), bad), std::invalid_argument);
}

// The plate against beam theory, the mesh around it, the wet nodes.
TEST(FlowHarvester, PlateMeshAndInterfaceMatch) {
  fs::FlowHarvesterCase c;
  const fs::FlowHarvester m(c);
  // the laminate's Euler-Bernoulli first frequency, short circuit (E = 1 / s11^E of PZT-5A, brass 105 GPa)
  const double hp = c.piezo_thickness, hb = c.host_thickness, Ep = 1.0 / 16.4e-12, Eb = 105e9;
  const double EI = Eb * hb * hb * hb / 12 + 2 * Ep * (std::pow(hb / 2 + hp, 3) - std::pow(hb / 2, 3)) / 3;
  const double mass = 9000 * hb + 2 * 7750 * hp, pi = 3.14159265358979323846;
  const double f_beam = 1.875104 * 1.875104 / (2 * pi * c.plate_length * c.plate_length) * std::sqrt(EI / mass);
  const double f1 = m.omega_sc() / (2 * pi);
  std::printf("f_1: FE %.4f Hz, beam theory %.4f Hz (%+.2f %%); open circuit %.4f Hz; D %.4f m; R %.4e ohm m\n", f1, f_beam,
              100 * (f1 / f_beam - 1), m.omega_oc() / (2 * pi), m.geometry().side, m.resistance());
  EXPECT_NEAR(f1 / f_beam, 1.0, 0.02);
  EXPECT_GT(m.omega_oc(), m.omega_sc());
  EXPECT_NEAR(m.geometry().side, c.strouhal * c.inflow / f1, 1e-3 * m.geometry().side);  // lock_in_side on 12 cells
  // 2 x 25 nodes on the faces (the root's corners included) and the tip face's middle node
  EXPECT_EQ(m.interface_nodes(), 51u);
  // the mesh covers the channel less the cylinder and the plate
  const auto& g = m.geometry();
  const double area = g.length() * g.height * g.side - g.side * g.side - g.plate_length * g.plate_thickness;
  const double measured = m.fluid().integrate([](const fl::NavierStokes2D::PointValue&) { return 1.0; }, 3);
  EXPECT_NEAR(measured, area, 1e-10 * area);
  fs::FlowHarvesterCase bad = c;
  bad.dt = -1.0;
  EXPECT_THROW(fs::FlowHarvester{bad}, std::invalid_argument);
  bad = c;
  bad.piezo_thickness = 0.0;
  EXPECT_THROW(fs::FlowHarvester{bad}, std::invalid_argument);
}

// A short coupled start with a strong gust: the nested loop (paper 1's Fig. 3, the piezo-circuit iteration inside
// the FSI iteration) and the single loop give the same history; the fluid mesh follows the plate; the plate's
// energy balance holds with the fluid's work (the loads' trapezoidal work = stored + damping + resistor).
TEST(FlowHarvester, NestedAndSingleLoopAgree) {
  fs::FlowHarvesterCase c;
  c.dt = 0.01;
  c.ramp_time = 0.2;
  c.gust = 0.5;
  c.inflow = 2.0;  // a larger load in a short run
  c.side = 0.03;
  std::vector<double> tip[2], volt[2];
  double mismatch = 0.0, balance[2] = {0, 0};
  long evaluations = 0;
  for (int s = 0; s < 2; ++s) {
    c.scheme = s == 0 ? polymech::piezo::Scheme::monolithic : polymech::piezo::Scheme::partitioned;
    fs::FlowHarvester m(c);
    for (int n = 0; n < 20; ++n) {
      const fs::FlowHarvesterStep r = m.step();
      tip[s].push_back(r.tip);
      volt[s].push_back(r.voltage);
      if (s == 0) evaluations += r.evaluations;
    }
    if (s == 0) mismatch = m.interface_mismatch();
    const auto& st = m.transient().state();  // the balance against the sum of its terms' sizes (W_in changes sign)
    const double stored = m.transient().energy() - st.energy0;
    balance[s] = (stored + st.work_damping + st.work_circuit - st.work_in) /
                 (std::fabs(stored) + st.work_damping + st.work_circuit + std::fabs(st.work_in));
  }
  double tmax = 0.0, vmax = 0.0, dt = 0.0, dv = 0.0;
  for (std::size_t k = 0; k < tip[0].size(); ++k) {
    tmax = std::max(tmax, std::fabs(tip[0][k]));
    vmax = std::max(vmax, std::fabs(volt[0][k]));
    dt = std::max(dt, std::fabs(tip[1][k] - tip[0][k]));
    dv = std::max(dv, std::fabs(volt[1][k] - volt[0][k]));
  }
  std::printf("20 steps: max |tip| %.4e m, |V| %.4e V; nested - single: %.2e m, %.2e V; %.2f evaluations/step; mismatch %.2e m; "
              "energy balance %.2e / %.2e\n",
              tmax, vmax, dt, dv, evaluations / 20.0, mismatch, balance[0], balance[1]);
  EXPECT_GT(tmax, 1e-7);
  EXPECT_GT(vmax, 1e-6);
  EXPECT_LT(dt, 1e-4 * tmax);  // both stop at the coupling's tolerance, 1e-6 of |x| with a 1e-9 m floor
  EXPECT_LT(dv, 1e-4 * vmax);
  EXPECT_LT(mismatch, 1e-8);
  // round-off, not truncation: the plate's solves (thickness modes 1e6 x stiffer than the first) under the rough
  // loads of a coupled start; the same plate under random nodal loads alone balances to 5e-6 .. 1e-4 at dt 1e-2
  // and 1e-8 .. 5e-7 at dt 1e-4 (2.6e-5 and 5.2e-5 here); an O(dt) error in the loads' work would be ~1e-1
  EXPECT_LT(std::fabs(balance[0]), 5e-4);
  EXPECT_LT(std::fabs(balance[1]), 5e-4);
}

}  // namespace
