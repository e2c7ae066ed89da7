// The solid models on unstructured hexahedral meshes read from Gmsh MSH 4.1 files (issue 34): the order-p
// nodes numbered by the shared hexahedral machinery (models/common/hex_dofs.hpp), the named physical surface
// groups as the boundaries of Dirichlet conditions and tractions.
//  - patch test: a 2 x 2 x 2 box whose node tags are shuffled, whose hexahedra list their vertices in rotated
//    orders and whose interior and face-centre vertices are moved (tests/io/data/solid_box_2x2x2.msh, written
//    by write_box_msh below); a linear field prescribed on three sides and its tractions on the other three is
//    reproduced to round-off at orders 1..3;
//  - the slender cantilever of test_solid_verification as the lattice and as a Gmsh file of the same cells (node
//    tags shuffled, elements rotated): the same tip deflection to round-off, elastic and elasto-plastic;
//  - a boundary named in the configuration that the mesh does not have: an error naming it, the file and the
//    groups there are.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/hex_mesh.hpp"
#include "core/hash.hpp"
#include "io/gmsh_msh.hpp"
#include "solid/analysis.hpp"
#include "solid/cases.hpp"
#include "solid/elastoplastic.hpp"
#include "support/error_messages.hpp"

namespace pm = polymech;
namespace so = polymech::solid;
namespace fs = std::filesystem;

namespace {

std::uint32_t mix(std::uint32_t x) { return polymech::mix32(x); }

// The 24 proper rotations of the reference cube as signed axis permutations: new axis k is old axis perm[k]
// times sign[k] (det +1, so a rotated hexahedron keeps det J > 0).
struct Rotation {
  std::array<int, 3> perm, sign;
};
std::vector<Rotation> cube_rotations() {
  std::vector<Rotation> out;
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
  for (int p = 0; p < 6; ++p)
    for (int s = 0; s < 8; ++s) {
      const std::array<int, 3> sign{s & 1 ? -1 : 1, s & 2 ? -1 : 1, s & 4 ? -1 : 1};
      const int parity = p < 3 ? 1 : -1;
      if (parity * sign[0] * sign[1] * sign[2] == 1) out.push_back({{perms[p][0], perms[p][1], perms[p][2]}, sign});
    }
  return out;
}

struct BoxMsh {
  std::array<int, 3> cells{2, 2, 2};
  std::array<double, 3> lengths{1.0, 1.0, 1.0};
  bool shuffle = true;   // node tags a permutation of the lattice order (with gaps), element tags reversed
  bool rotate = true;    // each hexahedron's vertex list in one of the 24 rotated orders
  bool distort = false;  // interior vertices moved in 3D, face-interior ones within their face
  std::string volume = "solid";
};

// A box of hexahedra as Gmsh writes it (MSH 4.1 ASCII): surface groups xmin .. zmax, one volume group.
std::string write_box_msh(const BoxMsh& b) {
  const int nx = b.cells[0], ny = b.cells[1], nz = b.cells[2];
  const int vx = nx + 1, vy = ny + 1, vz = nz + 1, nv = vx * vy * vz;
  auto vid = [&](int i, int j, int k) { return i + vx * (j + vy * k); };
  // node tags: a pseudo-random permutation of the lattice order, spread with gaps
  std::vector<std::pair<std::uint32_t, int>> keys;
  for (int v = 0; v < nv; ++v)
    keys.push_back({b.shuffle ? mix(static_cast<std::uint32_t>(v) + 17u) : static_cast<std::uint32_t>(v), v});
  std::sort(keys.begin(), keys.end());
  std::vector<long long> tag(static_cast<std::size_t>(nv));
  for (int r = 0; r < nv; ++r)
    tag[static_cast<std::size_t>(keys[static_cast<std::size_t>(r)].second)] = b.shuffle ? 3 + 2 * r : 1 + r;
  std::vector<std::array<double, 3>> x(static_cast<std::size_t>(nv));
  for (int k = 0; k < vz; ++k)
    for (int j = 0; j < vy; ++j)
      for (int i = 0; i < vx; ++i) {
        const int idx[3] = {i, j, k}, n[3] = {nx, ny, nz};
        auto& p = x[static_cast<std::size_t>(vid(i, j, k))];
        for (int d = 0; d < 3; ++d) {
          const double h = b.lengths[d] / n[d];
          p[d] = h * idx[d];
          const bool inside = idx[d] > 0 && idx[d] < n[d];
          int boundary_dirs = 0;
          for (int e = 0; e < 3; ++e) boundary_dirs += idx[e] == 0 || idx[e] == n[e];
          // move along d if d is not a direction the vertex is on the boundary of, and the vertex is inside
          // the box or inside a face (not on an edge)
          if (b.distort && inside && boundary_dirs <= 1)
            p[d] += 0.22 * h *
                    (static_cast<double>(mix(static_cast<std::uint32_t>(3 * vid(i, j, k) + d)) % 2001) / 1000.0 - 1.0);
        }
      }
  // hexahedra: Gmsh corner offsets, rotated
  static const int off[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const auto rots = cube_rotations();
  std::vector<std::array<int, 8>> hexes;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const int e = static_cast<int>(hexes.size());
        const Rotation& R = rots[b.rotate ? static_cast<std::size_t>((7 * e + 5) % 24) : 0];
        std::array<int, 8> h;
        for (int c = 0; c < 8; ++c) {
          int s[3];  // the new local corner c in {-1, 1}^3, then the old corner it sits at
          for (int d = 0; d < 3; ++d) s[d] = 2 * off[c][d] - 1;
          int o[3];
          for (int d = 0; d < 3; ++d) o[R.perm[d]] = R.sign[d] * s[d];
          h[static_cast<std::size_t>(c)] = vid(i + (o[0] + 1) / 2, j + (o[1] + 1) / 2, k + (o[2] + 1) / 2);
        }
        hexes.push_back(h);
      }
  // boundary quadrangles per side, written from a rotated start, every other one reversed
  std::array<std::vector<std::array<int, 4>>, 6> quads;
  for (int side = 0; side < 6; ++side) {
    const int dir = side / 2, t0 = dir == 0 ? 1 : 0, t1 = dir == 2 ? 1 : 2;
    const int n[3] = {nx, ny, nz};
    for (int b1 = 0; b1 < n[t1]; ++b1)
      for (int a0 = 0; a0 < n[t0]; ++a0) {
        std::array<int, 4> q;
        const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int c = 0; c < 4; ++c) {
          int idx[3];
          idx[dir] = side % 2 ? n[dir] : 0;
          idx[t0] = a0 + corner[c][0];
          idx[t1] = b1 + corner[c][1];
          q[static_cast<std::size_t>(c)] = vid(idx[0], idx[1], idx[2]);
        }
        const int r = static_cast<int>(quads[side].size());
        std::rotate(q.begin(), q.begin() + r % 4, q.end());
        if (r % 2) std::reverse(q.begin(), q.end());
        quads[side].push_back(q);
      }
  }
  static const char* names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  std::ostringstream o;
  o.precision(17);
  o << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n7\n";
  for (int s = 0; s < 6; ++s) o << "2 " << s + 1 << " \"" << names[s] << "\"\n";
  o << "3 7 \"" << b.volume << "\"\n$EndPhysicalNames\n$Entities\n0 0 6 1\n";
  for (int s = 0; s < 6; ++s)
    o << s + 1 << " 0 0 0 " << b.lengths[0] << " " << b.lengths[1] << " " << b.lengths[2] << " 1 " << s + 1 << " 0\n";
  o << "1 0 0 0 " << b.lengths[0] << " " << b.lengths[1] << " " << b.lengths[2] << " 1 7 0\n$EndEntities\n";
  long long lo = tag[0], hi = tag[0];
  for (auto t : tag) lo = std::min(lo, t), hi = std::max(hi, t);
  o << "$Nodes\n1 " << nv << " " << lo << " " << hi << "\n3 1 0 " << nv << "\n";
  std::vector<int> by_tag(static_cast<std::size_t>(nv));  // nodes listed in tag order
  for (int r = 0; r < nv; ++r) by_tag[static_cast<std::size_t>(r)] = keys[static_cast<std::size_t>(r)].second;
  if (!b.shuffle)
    for (int v = 0; v < nv; ++v) by_tag[static_cast<std::size_t>(v)] = v;
  for (int v : by_tag) o << tag[static_cast<std::size_t>(v)] << "\n";
  for (int v : by_tag)
    o << x[static_cast<std::size_t>(v)][0] << " " << x[static_cast<std::size_t>(v)][1] << " "
      << x[static_cast<std::size_t>(v)][2] << "\n";
  o << "$EndNodes\n$Elements\n";
  std::size_t nquads = 0;
  for (const auto& q : quads) nquads += q.size();
  const std::size_t total = nquads + hexes.size();
  o << "7 " << total << " 1 " << total << "\n";
  long long next = 1;
  for (int s = 0; s < 6; ++s) {
    o << "2 " << s + 1 << " 3 " << quads[static_cast<std::size_t>(s)].size() << "\n";
    for (const auto& q : quads[static_cast<std::size_t>(s)]) {
      o << next++;
      for (int v : q) o << " " << tag[static_cast<std::size_t>(v)];
      o << "\n";
    }
  }
  o << "3 1 5 " << hexes.size() << "\n";
  for (std::size_t e = 0; e < hexes.size(); ++e) {
    o << (b.shuffle ? static_cast<long long>(total - e) : next + static_cast<long long>(e));
    for (int v : hexes[e]) o << " " << tag[static_cast<std::size_t>(v)];
    o << "\n";
  }
  o << "$EndElements\n";
  return o.str();
}

pm::mesh::HexMesh read_hex(const fs::path& file) { return pm::mesh::hex_mesh_from(pm::io::read_gmsh_mesh(file)); }

fs::path source_dir() {
  const char* d = std::getenv("POLYMECH_SOURCE_DIR");
  return d ? fs::path(d) : fs::path(".");
}

// u = A x + b, |A| ~ 1e-3 (the field of test_solid_operator's patch test)
void linear_field(const double* x, double* u) {
  static const double A[3][3] = {{1.0e-3, 2.0e-4, -3.0e-4}, {-5.0e-4, 0.7e-3, 4.0e-4}, {2.5e-4, -1.5e-4, -0.6e-3}};
  static const double b[3] = {1e-4, -2e-4, 3e-4};
  for (int i = 0; i < 3; ++i) u[i] = b[i] + A[i][0] * x[0] + A[i][1] * x[1] + A[i][2] * x[2];
}

// The linear field on xmin, ymin, zmin (every component) and its constant traction sigma n on xmax, ymax,
// zmax: the exact solution is the linear field. Returns the worst nodal error relative to |A| (LU, then CG).
std::array<double, 2> gmsh_patch(const pm::mesh::HexMesh& mesh, int order) {
  so::Config<3> c;
  c.hex_mesh = mesh;
  c.order = order;
  c.stiffness = pm::materials::isotropic_stiffness(210e3, 0.3);
  for (const char* s : {"xmin", "ymin", "zmin"}) c.dirichlet.push_back({s, 7u, linear_field});
  double g[3][3], u0[3];
  const double o0[3] = {0, 0, 0};
  linear_field(o0, u0);
  for (int j = 0; j < 3; ++j) {
    double p[3] = {0, 0, 0}, uj[3];
    p[j] = 1.0;
    linear_field(p, uj);
    for (int i = 0; i < 3; ++i) g[i][j] = uj[i] - u0[i];
  }
  const double eps[6] = {g[0][0], g[1][1], g[2][2], g[1][2] + g[2][1], g[0][2] + g[2][0], g[0][1] + g[1][0]};
  double sv[6] = {};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) sv[i] += c.stiffness.c[i][j] * eps[j];
  const double sigma[3][3] = {{sv[0], sv[5], sv[4]}, {sv[5], sv[1], sv[3]}, {sv[4], sv[3], sv[2]}};
  const char* high[3] = {"xmax", "ymax", "zmax"};
  for (int d = 0; d < 3; ++d) c.tractions.push_back({high[d], {sigma[0][d], sigma[1][d], sigma[2][d]}});
  so::LinearElastic<double, 3> m(c);
  auto nodal_error = [&] {
    const auto u = m.displacement_host();
    const auto& x = m.discretization().coordinates;
    double e = 0.0;
    for (std::int64_t v = 0; v < m.discretization().nodes; ++v) {
      double ex[3];
      linear_field(&x[static_cast<std::size_t>(3 * v)], ex);
      for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(u[static_cast<std::size_t>(3 * v + k)] - ex[k]));
    }
    return e / 1e-3;
  };
  m.solve_direct();
  const double lu = nodal_error();
  pm::solvers::SolverOptions o;
  o.tolerance = 1e-13;
  const auto r = m.solve_cg(o);
  EXPECT_TRUE(r.converged()) << r.reason;
  return {lu, nodal_error()};
}

}  // namespace

// The committed example mesh is what write_box_msh writes (so the file and the generator stay one thing;
// POLYMECH_WRITE_MESH=<path> writes the generated text there).
TEST(SolidGmsh, ExampleMeshIsTheGenerated) {
  BoxMsh b;
  b.distort = true;
  if (const char* out = std::getenv("POLYMECH_WRITE_MESH")) std::ofstream(out) << write_box_msh(b);
  std::ifstream f(source_dir() / "tests/io/data/solid_box_2x2x2.msh");
  ASSERT_TRUE(f.good()) << "tests/io/data/solid_box_2x2x2.msh";
  std::stringstream s;
  s << f.rdbuf();
  EXPECT_EQ(s.str(), write_box_msh(b));
}

TEST(SolidGmsh, PatchTestOnShuffledRotatedDistortedBox) {
  const auto mesh = read_hex(source_dir() / "tests/io/data/solid_box_2x2x2.msh");
  ASSERT_EQ(mesh.element_count(), 8);
  for (int p = 1; p <= 3; ++p) {
    const auto e = gmsh_patch(mesh, p);
    std::printf("gmsh patch order=%d: max nodal error / |A| LU %.2e, CG %.2e\n", p, e[0], e[1]);
    EXPECT_LT(e[0], 1e-11) << "LU, order " << p;
    EXPECT_LT(e[1], 1e-10) << "CG, order " << p;
  }
}

// The cantilever of cases.hpp as the lattice and as a Gmsh file of the same cells: the same discrete space,
// the same tip deflection up to the round-off of the direct solves. The nodes are numbered in another order, so
// the sparse LU pivots differently: measured relative differences 1.2e-11, 6.3e-11, 6.5e-10 at p = 1, 2, 3
// (a slender beam, L / h = 20: the condition number grows like (L / h)^2 p^4); other cells would differ by the
// discretization error (p = 3 against p = 2: 7e-4).
TEST(SolidGmsh, CantileverLatticeEqualsGmsh) {
  pm::testing::TempDir dir;
  so::CantileverSpec s;
  s.cells = {10, 2, 2};
  BoxMsh b;
  b.cells = s.cells;
  b.lengths = {s.length, s.height, s.width};
  const auto mesh = read_hex(dir.write("cantilever.msh", write_box_msh(b)));
  const std::array<double, 3> tip{s.length, 0.5 * s.height, 0.5 * s.width};
  for (int p = 1; p <= 3; ++p) {
    s.order = p;
    so::Config<3> lattice = so::cantilever(s), gmsh = lattice;
    gmsh.hex_mesh = mesh;
    so::LinearElastic<double, 3> a(lattice), g(gmsh);
    a.solve_direct();
    g.solve_direct();
    const double wa = so::displacement_at<double, 3>(a, tip)[1], wg = so::displacement_at<double, 3>(g, tip)[1];
    std::printf("cantilever order=%d: tip lattice %.15e, gmsh %.15e, relative difference %.2e (Timoshenko %.6e)\n", p,
                wa, wg, std::abs(wg - wa) / std::abs(wa), so::timoshenko_tip_deflection(s));
    EXPECT_EQ(a.dof_count(), g.dof_count());
    EXPECT_LT(std::abs(wg - wa), 1e-8 * std::abs(wa)) << "order " << p;
  }
}

// The elasto-plastic model shares the set-up (SolidProblem): a J2 cantilever loaded past first yield, as the
// lattice and as the Gmsh file, the same tip deflection and plastic points.
TEST(SolidGmsh, ElastoPlasticCantileverLatticeEqualsGmsh) {
  pm::testing::TempDir dir;
  const auto law = pm::materials::make_j2(200.0, 0.3, 0.2, 0.2);
  so::BoxSpec box;
  box.lengths = {6.0, 1.0, 1.0};
  box.cells = {6, 1, 1};
  so::Config<3> lattice;
  lattice.mesh = so::make_box<3>(box);
  lattice.order = 2;
  lattice.stiffness = law.C;
  lattice.plasticity = law;
  lattice.dirichlet.push_back({"xmin", 7u, {}});
  lattice.tractions.push_back({"xmax", {0.0, 1.45 * law.hardening.sigma0 / 36.0, 0.0}});  // clamp stress 1.45 sigma0
  BoxMsh b;
  b.cells = box.cells;
  b.lengths = box.lengths;
  so::Config<3> gmsh = lattice;
  gmsh.hex_mesh = read_hex(dir.write("cantilever.msh", write_box_msh(b)));
  so::NewtonOptions o;
  o.solver = so::TangentSolver::direct;
  o.tolerance = 1e-11;
  so::Monitor tip;
  tip.reaction_boundary = "xmin";
  tip.displacement = [](const std::vector<double>& u) {
    double mx = 0.0;
    for (std::size_t i = 1; i < u.size(); i += 3) mx = std::max(mx, u[i]);
    return mx;
  };
  so::LoadPath path;
  path.points = {0.0, 1.0};
  path.increments = {3};
  so::ElastoPlastic<double, 3> a(lattice, o), g(gmsh, o);
  const auto sa = a.run(path, tip).back(), sg = g.run(path, tip).back();
  std::printf("elasto-plastic cantilever: tip lattice %.15e (%ld plastic points), gmsh %.15e (%ld), relative %.2e\n",
              sa.displacement, static_cast<long>(sa.plastic_points), sg.displacement,
              static_cast<long>(sg.plastic_points), std::abs(sg.displacement - sa.displacement) / sa.displacement);
  ASSERT_GT(sa.plastic_points, 0);
  EXPECT_EQ(sa.plastic_points, sg.plastic_points);
  EXPECT_LT(std::abs(sg.displacement - sa.displacement), 1e-8 * sa.displacement);
  EXPECT_NEAR(sa.reaction[1], sg.reaction[1], 1e-9 * std::abs(sa.reaction[1]));
}

// The unstructured discretization's tables: (p n + 1)^3 nodes on an n^3 box, every element in one chunk, the
// chunks of one colour sharing no node (so the scatter needs no atomics), the side faces of the box's groups.
TEST(SolidGmsh, UnstructuredTablesAreConsistent) {
  pm::mesh::BoxSpec b;
  b.elements = {4, 3, 2};
  b.perturbation = 0.2;
  const auto mesh = pm::mesh::make_box_mesh(b);
  for (int p = 1; p <= 4; ++p) {
    const auto d = so::discretize(mesh, p, 3);
    EXPECT_EQ(d.nodes, static_cast<std::int64_t>(4 * p + 1) * (3 * p + 1) * (2 * p + 1)) << "order " << p;
    std::vector<std::int64_t> seen(d.element_cells.begin(), d.element_cells.end());
    std::sort(seen.begin(), seen.end());
    for (std::size_t e = 0; e < seen.size(); ++e) EXPECT_EQ(seen[e], static_cast<std::int64_t>(e));
    const int ND = d.nodes_per_element();
    std::vector<std::int64_t> owner(static_cast<std::size_t>(d.nodes), -1);
    int conflicts = 0;
    for (std::size_t c = 0; c + 1 < d.color_offsets.size(); ++c) {
      std::fill(owner.begin(), owner.end(), -1);
      for (std::int64_t k = d.color_offsets[c]; k < d.color_offsets[c + 1]; ++k)
        for (std::int64_t e = d.chunk_start[static_cast<std::size_t>(k)];
             e < d.chunk_start[static_cast<std::size_t>(k + 1)]; ++e)
          for (int a = 0; a < ND; ++a) {
            auto& o = owner[static_cast<std::size_t>(d.element_nodes[static_cast<std::size_t>(e * ND + a)])];
            conflicts += o >= 0 && o != k;
            o = k;
          }
    }
    EXPECT_EQ(conflicts, 0) << "order " << p;
    EXPECT_EQ(so::side_faces(d, "xmax").size(), static_cast<std::size_t>(3 * 2 * (p + 1) * (p + 1)));
    EXPECT_EQ(so::side_nodes(d, "zmin").size(), static_cast<std::size_t>((4 * p + 1) * (3 * p + 1)));
    std::printf("unstructured order=%d: %ld nodes, %zu chunks in %zu colours\n", p, static_cast<long>(d.nodes),
                d.chunk_start.size() - 1, d.color_offsets.size() - 1);
  }
}

// A boundary the configuration names but the mesh does not have: the message names it, the file and the
// groups the file has.
TEST(SolidGmsh, MissingGroupNamed) {
  pm::testing::TempDir dir;
  const auto file = dir.write("box.msh", write_box_msh(BoxMsh{}));
  so::Config<3> c;
  c.hex_mesh = read_hex(file);
  c.order = 1;
  c.dirichlet.push_back({"xmin", 7u, {}});
  c.tractions.push_back({"tip", {0.0, 1.0, 0.0}});
  std::string msg;
  try {
    so::LinearElastic<double, 3> m(c);
  } catch (const std::invalid_argument& e) {
    msg = e.what();
  }
  std::printf("%s\n", msg.c_str());
  pm::testing::expect_message(msg, "box.msh", 0, {"'tip'", "box.msh", "'xmin'", "'zmax'"});
}
