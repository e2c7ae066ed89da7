// Kernel results with 1 and with 2 OpenMP threads agree within round-off. ctest runs this binary
// twice (OMP_NUM_THREADS=1, then 2): each run computes the same results (a neighbour list of a random
// cloud, 200 MPS steps of a plate with a clapping and slipping crack, energies), the first writes them
// to a file, the second reads that file and compares. Neighbour lists must be identical (fixed order
// within rows); the MPS fields are per-particle gathers, but n0 (a mean, eq. (2)) is a parallel
// reduction, so fields and energies agree to round-off. DEM spheres (sphere-sphere and sphere-facet
// contact with friction, 300 steps) have no reduction but the exact max of the Verlet-skin check: their
// state must be bitwise the same. The finite-element solid (issue 34): its internal force is scattered by
// coloured chunks (no atomics, one order of the sums per DoF), so one residual evaluation is bitwise the
// same; an elasto-plastic load path (J2, Newton with line search, sparse LU) goes through reductions (norms,
// the line search's slopes), so its displacements agree to round-off.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <vector>

#include "dem/benchmark.hpp"
#include "mps_elastic/mps_elastic.hpp"
#include "neighbors/neighbor_search.hpp"
#include "solid/cases.hpp"
#include "solid/elastoplastic.hpp"

namespace pm = polymech;
namespace me = polymech::mps_elastic;

namespace {

struct Results {
  std::vector<double> neighbors;  // the CSR list of a random cloud, as numbers
  std::vector<double> fields;     // u, v, theta after the steps
  std::vector<double> reductions; // energies, contact counts
  std::vector<double> dem;        // DEM spheres: x, v, omega after the steps
  std::vector<double> solid_force;  // a residual of the elasto-plastic cantilever at a fixed displacement
  std::vector<double> solid_u;      // its displacement after a plastic load path
};

// 27 spheres with random velocities onto a meshed wall (friction, damping, fe_surfaces).
std::vector<double> dem_spheres() {
  namespace dm = polymech::dem;
  auto c = dm::sphere_on_wall(dm::chung_ooi_alumina(), 50, 0.0, true);
  const double r = 0.0025;
  std::mt19937 g(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  c.spheres.clear();
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) {
        dm::SphereInit s;
        s.radius = r * (1 + 0.1 * u(g));
        s.position = {(i - 1) * 2.1 * r, (j - 1) * 2.1 * r, 1.1 * r + k * 2.1 * r};
        s.velocity = {u(g), u(g), u(g) - 1.0};
        c.spheres.push_back(s);
      }
  c.friction = 0.3;
  c.restitution = 0.7;
  c.dt = 0;
  c.effects = pm::EffectSet::resolve({"friction", "damping", "fe_surfaces"}, dm::effect_table());
  dm::Dem<double> m(c);
  for (int s = 0; s < 300; ++s) m.step();
  std::vector<double> out;
  for (pm::Index i = 0; i < 27; ++i) {
    const auto st = m.sphere(i);
    out.insert(out.end(), st.x, st.x + 3);
    out.insert(out.end(), st.v, st.v + 3);
    out.insert(out.end(), st.omega, st.omega + 3);
  }
  return out;
}

// A J2 cantilever (order 2, 8 x 2 x 2) loaded into the plastic range in 4 steps, then the residual at a fixed
// smooth displacement field.
void solid_cantilever(Results& r) {
  namespace so = polymech::solid;
  so::CantileverSpec s;
  s.cells = {8, 2, 2};
  s.length = 6.0;
  s.young = 200.0;
  s.poisson = 0.3;
  s.force = 0.1;  // clamp bending stress 6 P L / (b h^2) = 3.6 = 1.8 x the yield stress
  so::Config<3> c = so::cantilever(s);
  const auto law = polymech::materials::make_j2(200.0, 0.3, 2.0, 0.1);
  c.stiffness = law.C;
  c.plasticity = law;
  so::NewtonOptions o;
  o.solver = so::TangentSolver::direct;
  so::ElastoPlastic<double, 3> m(c, o);
  so::LoadPath path;
  path.points = {0.0, 1.0};
  path.increments = {4};
  m.run(path);
  EXPECT_GT(m.law().counts().plastic, 0) << "the cantilever must be loaded into the plastic range";
  r.solid_u = m.displacement_host();
  pm::View1<double> u("u", m.dof_count()), res("r", m.dof_count());
  auto h = Kokkos::create_mirror_view(u);
  for (pm::Index i = 0; i < m.dof_count(); ++i) h(i) = 1e-3 * std::sin(0.37 * static_cast<double>(i));
  Kokkos::deep_copy(u, h);
  m.residual(u, 0.5, res);
  r.solid_force = pm::models::to_host(res);
}

Results compute() {
  Results r;
  {
    const std::int64_t n = 4000;
    pm::VecView<double, 3> x("x", n);
    auto h = Kokkos::create_mirror_view(x);
    std::mt19937 g(11);
    std::uniform_real_distribution<double> u(0.0, 16.0);
    for (std::int64_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) h(i, k) = u(g);
    Kokkos::deep_copy(x, h);
    pm::neighbors::NeighborSearch<double, 3> search;
    pm::neighbors::NeighborList list;
    search.build(x, 1.5, pm::neighbors::ListKind::full, list);
    auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
    auto nb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbors);
    for (std::int64_t i = 0; i <= n; ++i) r.neighbors.push_back(static_cast<double>(off(i)));
    for (pm::Offset k = 0; k < list.num_pairs; ++k) r.neighbors.push_back(nb(k));
  }
  me::Config c;
  c.width = 40e-4;
  c.height = 50e-4;
  c.spacing = 1e-4;
  c.dt = 4e-9;
  c.excitation.kind = me::ExcitationKind::plane_p;
  c.excitation.cycles = 5;
  c.crack.mode = me::CrackMode::cut;
  c.crack.x1 = 20e-4;
  c.crack.x3 = 25e-4;
  c.crack.length = 10e-4;
  c.crack.angle = 30.0;
  c.probes.push_back({"A", 20e-4, 20e-4});
  c.effects = pm::EffectSet::resolve({"rotation", "crack_contact.open_close", "crack_contact.slip"},
                                     me::MpsElastic<double>::effects());
  me::MpsElastic<double> m(c);
  for (int s = 0; s < 200; ++s) m.step();
  const auto h = m.host_fields();
  r.fields = h.u;
  r.fields.insert(r.fields.end(), h.v.begin(), h.v.end());
  r.fields.insert(r.fields.end(), h.theta.begin(), h.theta.end());
  const auto e = m.energy();
  const auto n = m.crack().counts();
  r.reductions = {e.kinetic, e.strain, double(n.separation), double(n.stick), double(n.slip)};
  r.dem = dem_spheres();
  solid_cantilever(r);
  return r;
}

void write(const std::string& path, const Results& r) {
  std::ofstream o(path, std::ios::binary);
  for (const auto* v : {&r.neighbors, &r.fields, &r.reductions, &r.dem, &r.solid_force, &r.solid_u}) {
    const std::uint64_t n = v->size();
    o.write(reinterpret_cast<const char*>(&n), sizeof n);
    o.write(reinterpret_cast<const char*>(v->data()), static_cast<std::streamsize>(n * sizeof(double)));
  }
}

bool read(const std::string& path, Results& r) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  for (auto* v : {&r.neighbors, &r.fields, &r.reductions, &r.dem, &r.solid_force, &r.solid_u}) {
    std::uint64_t n = 0;
    in.read(reinterpret_cast<char*>(&n), sizeof n);
    v->resize(n);
    in.read(reinterpret_cast<char*>(v->data()), static_cast<std::streamsize>(n * sizeof(double)));
  }
  return static_cast<bool>(in);
}

}  // namespace

TEST(ThreadAgreement, OneAndTwoThreadsGiveTheSameResults) {
  const char* file = std::getenv("POLYMECH_AGREEMENT_FILE");
  ASSERT_NE(file, nullptr) << "run through ctest (sets POLYMECH_AGREEMENT_FILE)";
  const int threads = pm::kx::concurrency<pm::ExecSpace>();
  const Results now = compute();
  if (threads == 1) {
    write(file, now);
    return;
  }
  Results ref;
  ASSERT_TRUE(read(file, ref)) << "no 1-thread results in " << file;
  ASSERT_EQ(now.neighbors, ref.neighbors);  // identical lists, whatever the thread count
  ASSERT_EQ(now.fields.size(), ref.fields.size());
  double scale = 0;
  for (double v : ref.fields) scale = std::max(scale, std::abs(v));
  ASSERT_GT(scale, 0.0);
  for (std::size_t k = 0; k < now.fields.size(); ++k)
    ASSERT_NEAR(now.fields[k], ref.fields[k], 1e-12 * scale) << "field value " << k;
  for (std::size_t k = 0; k < now.reductions.size(); ++k)
    EXPECT_NEAR(now.reductions[k], ref.reductions[k], 1e-10 * std::abs(ref.reductions[k])) << "reduction " << k;
  EXPECT_EQ(now.dem, ref.dem);  // DEM: bitwise
  EXPECT_EQ(now.solid_force, ref.solid_force);  // the solid's coloured scatter: bitwise
  ASSERT_EQ(now.solid_u.size(), ref.solid_u.size());
  double us = 0;
  for (double v : ref.solid_u) us = std::max(us, std::abs(v));
  ASSERT_GT(us, 0.0);
  for (std::size_t k = 0; k < now.solid_u.size(); ++k)
    ASSERT_NEAR(now.solid_u[k], ref.solid_u[k], 1e-10 * us) << "solid displacement " << k;
}
