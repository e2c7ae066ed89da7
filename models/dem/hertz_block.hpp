// A rigid sphere pressed into an elastic FE block through the DEM-to-FE coupling, against Hertz (issue 37's
// verification item "a deformable elastic sphere on a rigid plane against Hertz (the coupling's forces and the FE
// contact together)"). Hertz's F = 4/3 E* sqrt(R) d^(3/2), a = sqrt(R d) (Johnson 1985, 4.2) holds the same for an
// elastic sphere on a rigid plane and a rigid sphere on an elastic half-space (E* = E / (1 - nu^2) of the elastic
// body); this case takes the second reading because it exercises the coupling of the FE tyre
// (dem/tyre_drive.hpp, dem/tyre_surface.hpp) end to end:
//
//   - the block: a quarter of [-W, W]^2 x [-H, 0] (x >= 0, y >= 0; symmetry planes xmin: u_x = 0, ymin: u_y = 0;
//     bottom zmin fixed), graded lattice planes (solid::graded_planes) with cells_per_contact cells across the
//     largest contact radius a_max = sqrt(R d_max) under the sphere; the explicit finite-strain solid
//     (solid::HyperelasticExplicit, neo-Hookean, lumped mass, mass-proportional damping);
//   - its top face a contact::SurfaceMesh whose nodes are the FE nodes X + u after every first half-step (and
//     whose node velocities are the FE ones), quadrilaterals between neighbouring lattice points;
//   - the sphere (radius R, kinematic: moved straight down at a constant speed) against the facets by the
//     inside-outside algorithm and Hertz-Mindlin (seed 002 paper 2 eqs. (1)-(17); kernel
//     "polymech::dem::sphere_deforming_facet", frictionless, damped) with a stiff law (contact_stiffness x the
//     block's E*) so that its own overlap is small against the indentation;
//   - the contacts' forces to the facets' nodes with the contact point's weights (contact/facet_weights.hpp,
//     dem::surface_node_loads) and into the FE residual as external forces (dem::subtract_surface_loads), as the
//     tyre does.
//
// The listed facets: those within R (1 + 1e-9) + 1e-3 h_0 of the sphere's centre (kernel
// "polymech::dem::hertz_block_candidates", every step; at most dem::max_facets_per_sphere, else
// std::runtime_error: the quarter keeps the contact's facet count within it).
//
// Measured per row: the FE indentation d = -u_z of the surface node under the sphere (the block's corner node on
// the axis), the sphere's travel (its overlap with that node is travel - d), the sphere's force (x 4: the whole
// contact), the contact radius (the largest distance from the axis of a contact point, sum w_a x_a of a contact
// with a force), the sum of the node loads (x 4; minus the sphere's force to round-off), the kinetic energy.
// Known departures from Hertz (docs/VALIDATION.md): the block's finite size (its fixed bottom at depth H removes the
// half-space's settlement below H, Boussinesq's F (1 + nu)(3 - 2 nu) / (2 pi E H), about 0.7 a / H of d: HertzRow::
// hertz_far puts it back), the mesh's resolution of a, the DEM's own overlap (not in d: d is the node's), the
// press's residual kinetic energy.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dem/contact_forces.hpp"
#include "dem/surface_loads.hpp"
#include "dem/tyre_drive.hpp"
#include "neighbors/transpose.hpp"
#include "solid/finite_strain_explicit.hpp"
#include "solid/tyre.hpp"

namespace polymech::dem {

struct HertzBlockSpec {
  double radius = 1.0;             // R of the rigid sphere
  double young = 1.0, poisson = 0.3, density = 1.0;  // the block (neo-Hookean)
  double depth_max = 0.02;         // the largest indentation / R (small strain: a / R = sqrt(d / R))
  double cells_per_contact = 4.0;  // cells across a_max = sqrt(R d_max) under the sphere (the first cell a_max / this)
  double ratio = 1.3;              // growth of the graded cells away from the sphere
  double largest = 2.0;            // the largest cell, in a_max
  double extent = 8.0;             // the quarter block's width W and depth H, in a_max
  double contact_stiffness = 30.0; // the DEM law's E* / the block's E*
  double press_time = 40.0;        // time of the press to d_max, in H / c_s (c_s the shear wave speed)
  double damping = 1.0;            // mass-proportional damping alpha, in c_s / H
  double step_fraction = 0.5;      // dt = this x the smaller of the solid's own step (0.9 x its critical step) and
                                   // the contact's estimate (HertzBlockResult::contact_step)
  int order = 1;
  int rows = 8;
  double plate_penalty = 2.0;      // hertz_plate_press: PlateContact's beta (k = beta m omega_max^2; stable with
                                   // step_fraction 0.5: dt omega_max = 0.9 < 2 / sqrt(1 + beta))
  double restitution = 0.3;        // the DEM contact's (its damping against a node's chatter; 1: undamped)
  bool return_loads = true;        // false: the node loads are not given to the FE block (a check must then fail)
};

struct HertzRow {
  double time = 0, travel = 0, depth = 0;  // the sphere's travel from first touch; d = -u_z of the node under it
  double overlap = 0, approach = 0;        // the largest DEM overlap of its contacts; travel - overlap
  double force = 0, hertz = 0;             // the sphere's force (whole contact) and Hertz's at d
  double depth_far = 0, hertz_far = 0;     // d + the half-space's settlement below H under the force; Hertz's there
  double contact_radius = 0, hertz_radius = 0;  // the largest contact point's radius; sqrt(R d)
  double node_sum = 0;                     // the node loads' z sum (whole contact): -force to round-off
  double kinetic = 0;                      // the block's kinetic energy (whole block: x 4)
  int contacts = 0;                        // contacts with a force (the quarter)
};

struct HertzBlockResult {
  std::vector<HertzRow> rows;
  double e_star = 0, a_max = 0, first_cell = 0, dt = 0, contact_step = 0, cpu_seconds = 0;
  std::int64_t steps = 0, dofs = 0;
  std::array<int, 3> cells{};
  int most_facets = 0;  // the most facets listed for the sphere in a step
};

// Kernel "polymech::dem::hertz_block_candidates": flag(f) = 1 when facet f is within r of p.
template <class T>
void hertz_block_candidates(const contact::SurfaceMesh<T>& mesh, const Vec3<T>& p, T r, const View1<int>& flag) {
  Kokkos::parallel_for(
      "polymech::dem::hertz_block_candidates", range(mesh.facet_count()), KOKKOS_LAMBDA(const Index f) {
        flag(f) = contact::sphere_facet_contact(mesh, f, p, r).region != contact::FacetRegion::none ? 1 : 0;
      });
}

// Kernel "polymech::dem::place_hertz_surface": surface node s at X + u of its FE node, its velocity v.
template <class T>
void place_hertz_surface(const Kokkos::View<Index*, MemSpace>& node, const View1<double>& X, const View1<double>& u,
                         const View1<double>& v, const contact::SurfaceMesh<T>& mesh, const VecView<T, 3>& vel) {
  const auto nodes = mesh.nodes;
  Kokkos::parallel_for(
      "polymech::dem::place_hertz_surface", range(static_cast<Index>(node.extent(0))), KOKKOS_LAMBDA(const Index s) {
        const Index i = node(s);
        for (int k = 0; k < 3; ++k) {
          nodes(s, k) = T(X(3 * i + k) + u(3 * i + k));
          vel(s, k) = T(v(3 * i + k));
        }
      });
  contact::update_geometry(mesh);
}

// Kernel "polymech::dem::hertz_block_sphere": the kinematic sphere's centre and velocity.
template <class T>
void place_hertz_sphere(const SphereSet<T>& s, double z, double vz) {
  const auto x = s.x, v = s.v;
  Kokkos::parallel_for(
      "polymech::dem::hertz_block_sphere", range(1), KOKKOS_LAMBDA(const Index) {
        x(0, 0) = T(0);
        x(0, 1) = T(0);
        x(0, 2) = T(z);
        v(0, 0) = T(0);
        v(0, 1) = T(0);
        v(0, 2) = T(vz);
      });
}

// The spec checked (std::invalid_argument naming `who` and what is allowed; the DEM contact's stiffness only with
// `contact`) and the block's sizes: E* = E / (1 - nu^2), a_max = sqrt(R d_max), the block's width and depth W =
// extent a_max, the first cell h0 = a_max / cells_per_contact.
struct HertzGeometry {
  double R = 0, E = 0, nu = 0, e_star = 0, a_max = 0, W = 0, h0 = 0;
};

inline HertzGeometry hertz_geometry(const HertzBlockSpec& spec, const std::string& who, bool contact) {
  if (!(spec.radius > 0) || !(spec.young > 0) || !(spec.poisson > -1 && spec.poisson < 0.5) || !(spec.density > 0) ||
      !(spec.depth_max > 0 && spec.depth_max < 0.2) || !(spec.cells_per_contact >= 1) || !(spec.ratio >= 1) ||
      !(spec.extent >= 2) || (contact && !(spec.contact_stiffness > 0)) || !(spec.press_time > 0) || !(spec.damping >= 0) ||
      !(spec.step_fraction > 0 && spec.step_fraction <= 1) || spec.rows < 1 || spec.order < 1 || spec.order > 4)
    throw std::invalid_argument(who + ": need R, E, density > 0, nu in (-1, 0.5), depth_max in (0, 0.2), cells_per_contact >= 1, "
                                "ratio >= 1, extent >= 2, " + (contact ? "contact_stiffness > 0, " : "") +
                                "press_time > 0, damping >= 0, step_fraction in (0, 1], rows >= 1, order 1-4");
  HertzGeometry g;
  g.R = spec.radius;
  g.E = spec.young;
  g.nu = spec.poisson;
  g.e_star = g.E / (1.0 - g.nu * g.nu);
  g.a_max = std::sqrt(g.R * spec.depth_max * g.R);
  g.W = spec.extent * g.a_max;
  g.h0 = g.a_max / spec.cells_per_contact;
  return g;
}

// The elastic body of both presses: neo-Hookean with E, nu (Lame's mu, lambda), its shear wave speed, and the explicit
// options (density, mass-proportional damping spec.damping x c_s / W).
struct HertzBody {
  materials::NeoHookean<double> law;
  solid::ExplicitFiniteStrainOptions options;
  double wave_speed = 0.0;
};

inline HertzBody hertz_body(const HertzBlockSpec& spec, const HertzGeometry& g) {
  HertzBody b;
  b.law.elastic.mu = g.E / (2.0 * (1.0 + g.nu));
  b.law.elastic.lambda = g.E * g.nu / ((1.0 + g.nu) * (1.0 - 2.0 * g.nu));
  b.wave_speed = std::sqrt(b.law.elastic.mu / spec.density);
  b.options.density = spec.density;
  b.options.damping = spec.damping * b.wave_speed / g.W;
  return b;
}

// The quasi-static press: spec.rows rows at equal times up to the travel d_max (1 + 1 / contact_stiffness).
// Throws std::invalid_argument for a bad spec, std::runtime_error when the contact lists more facets than a row holds.
inline HertzBlockResult hertz_block_press(const HertzBlockSpec& spec) {
  using T = double;
  const HertzGeometry g = hertz_geometry(spec, "dem::hertz_block_press", true);
  const auto cpu0 = std::clock();
  HertzBlockResult out;
  const double R = g.R, E = g.E, nu = g.nu, e_star = g.e_star, a_max = g.a_max, W = g.W, h0 = g.h0;
  out.e_star = e_star;
  out.a_max = a_max;
  out.first_cell = h0;
  const std::vector<double> px = solid::graded_planes(0.0, W, h0, spec.ratio, std::max(h0, spec.largest * a_max));
  std::vector<double> pz = solid::graded_planes(0.0, -W, h0, spec.ratio, std::max(h0, spec.largest * a_max));
  std::reverse(pz.begin(), pz.end());
  solid::Config<3> c;
  c.mesh = solid::make_tensor_box<3>({px, px, pz});
  c.order = spec.order;
  c.dirichlet = {{"xmin", 1u, {}}, {"ymin", 2u, {}}, {"zmin", 7u, {}}};
  for (int k = 0; k < 3; ++k) out.cells[static_cast<std::size_t>(k)] = c.mesh.cells[static_cast<std::size_t>(k)];
  const HertzBody body = hertz_body(spec, g);
  const double cs = body.wave_speed;
  using Solid = solid::HyperelasticExplicit<double, 3>;
  Solid fe(c, solid::HyperelasticLaw(body.law), body.options);
  out.dofs = fe.dof_count();

  // the top face: one surface node per lattice point of zmax, quadrilaterals counter-clockwise seen from +z
  const auto& d = fe.solid().discretization();
  const int n0 = d.lattice[0], n1 = d.lattice[1], top = d.lattice[2] - 1;
  std::vector<Index> fe_node;
  std::vector<double> xyz;
  for (int j = 0; j < n1; ++j)
    for (int i = 0; i < n0; ++i) {
      const std::int64_t v = d.node({i, j, top});
      fe_node.push_back(static_cast<Index>(v));
      for (int k = 0; k < 3; ++k) xyz.push_back(d.coordinates[static_cast<std::size_t>(3 * v + k)]);
    }
  std::vector<int> sizes;
  std::vector<Index> fn;
  for (int j = 0; j + 1 < n1; ++j)
    for (int i = 0; i + 1 < n0; ++i) {
      const Index q = static_cast<Index>(j) * n0 + i;
      sizes.push_back(4);
      for (const Index a : {q, q + 1, q + n0 + 1, q + n0}) fn.push_back(a);
    }
  // the step: the solid's, and the contact's on the lightest surface node (a node under the sphere carries about
  // the Hertz pressure p_0 = 2 E* a / (pi R) on a quarter cell face h_0^2 / 4 as one facet contact of the DEM law:
  // overlap delta_c = (3 F_c / (4 E_dem sqrt(R)))^(2/3), stiffness k_c = 2 E_dem sqrt(R delta_c)), 2 sqrt(m / k_c)
  const std::vector<double> lumped = models::to_host(fe.lumped_mass());
  double m_min = std::numeric_limits<double>::max();
  for (const Index i : fe_node) m_min = std::min(m_min, lumped[static_cast<std::size_t>(3 * i)]);
  const double e_dem = spec.contact_stiffness * e_star, p0 = 2.0 * e_star * a_max / (3.14159265358979323846 * R);
  const double delta_c = std::pow(3.0 * p0 * h0 * h0 / 4.0 / (4.0 * e_dem * std::sqrt(R)), 2.0 / 3.0);
  const double k_c = 2.0 * e_dem * std::sqrt(R * delta_c);
  out.contact_step = 2.0 * std::sqrt(m_min / k_c);
  const double dt = spec.step_fraction * std::min(fe.time_step(), out.contact_step);
  fe.set_time_step(dt);
  out.dt = dt;
  const auto mesh = contact::make_surface_mesh<T>(xyz, sizes, fn, "polymech::dem::hertz_block_surface");
  const Index ns = mesh.node_count(), nf = mesh.facet_count();
  const auto adjacency = surface_adjacency(ns, sizes, fn);
  const auto node_view = models::to_device<Index>("polymech::dem::hertz_block_nodes", fe_node);
  const auto X = models::to_device<double>("polymech::dem::hertz_block_reference", d.coordinates);
  VecView<T, 3> node_velocity("polymech::dem::hertz_block_node_velocity", static_cast<std::size_t>(ns));
  VecView<T, 3> node_force("polymech::dem::hertz_block_node_force", static_cast<std::size_t>(ns));
  if (spec.return_loads)
    fe.set_external_force([node_view, node_force](double, const View1<double>&, const View1<double>&, const View1<double>& r) {
      subtract_surface_loads(node_view, node_force, 1.0, r);
    });

  // the sphere, the law, the list and its transpose. The sphere's mass (kinematic: it only scales the contact's
  // damping, eq. (12)'s gamma_n ~ sqrt(m* k_n)) is the lightest surface node's, so that the contact damps a node's
  // chatter as a new node comes into contact; its force is mass x acceleration
  SphereSet<T> s;
  allocate(s, 1, "polymech::dem::hertz_block_");
  Kokkos::deep_copy(s.radius, T(R));
  Kokkos::deep_copy(s.mass, T(m_min));
  const HertzMindlin<T> dem_law{e_dem, e_dem / 2.5, T(spec.restitution < 1.0 ? contact::damping_ratio(spec.restitution) : 0.0), T(0)};
  SpringView<T> hist("polymech::dem::hertz_block_springs", static_cast<std::size_t>(nf));
  EntryLoadView<T> entry("polymech::dem::hertz_block_entry_load", static_cast<std::size_t>(nf));
  View1<int> flag("polymech::dem::hertz_block_flag", static_cast<std::size_t>(nf));
  auto flag_host = Kokkos::create_mirror_view(flag);
  neighbors::NeighborList list;
  list.offsets = Kokkos::View<Offset*, MemSpace>("polymech::dem::hertz_block_list_offsets", 2);
  list.neighbors = Kokkos::View<Index*, MemSpace>("polymech::dem::hertz_block_list", static_cast<std::size_t>(nf));
  list.num_particles = 1;
  auto off_host = Kokkos::create_mirror_view(list.offsets);
  auto nbr_host = Kokkos::create_mirror_view(list.neighbors);
  neighbors::ListTranspose by_facet;

  const double travel_max = spec.depth_max * R * (1.0 + 1.0 / spec.contact_stiffness);
  const double t_end = spec.press_time * W / cs, speed = travel_max / t_end;
  const auto total = static_cast<std::int64_t>(std::ceil(t_end / dt));
  const std::int64_t every = std::max<std::int64_t>(1, total / spec.rows);
  const double r_list = R * (1.0 + 1e-9) + 1e-3 * h0;
  // the half-space's settlement below depth H under the force F on its axis (Boussinesq; Johnson 1985, 3.2):
  // F (1 + nu) (3 - 2 nu) / (2 pi E H), which the fixed bottom removes from d
  const double far_field = (1.0 + nu) * (3.0 - 2.0 * nu) / (2.0 * 3.14159265358979323846 * E * W);
  for (std::int64_t n = 1; n <= total; ++n) {
    fe.first_half();
    place_hertz_surface(node_view, X, fe.displacement(), fe.velocity(), mesh, node_velocity);
    const double t = fe.time() + dt, travel = speed * t, zc = R - travel;
    place_hertz_sphere(s, zc, -speed);
    hertz_block_candidates(mesh, Vec3<T>{{0.0, 0.0, zc}}, r_list, flag);
    Kokkos::deep_copy(flag_host, flag);
    Offset listed = 0;
    for (Index f = 0; f < nf; ++f)
      if (flag_host(f)) nbr_host(listed++) = f;
    if (listed > max_facets_per_sphere)
      throw std::runtime_error("dem::hertz_block_press: the sphere touches " + std::to_string(listed) + " facets at travel " +
                               std::to_string(travel) + "; a row holds " + std::to_string(max_facets_per_sphere) +
                               ": fewer cells_per_contact or a smaller depth_max");
    out.most_facets = std::max(out.most_facets, static_cast<int>(listed));
    off_host(0) = 0;
    off_host(1) = listed;
    Kokkos::deep_copy(list.offsets, off_host);
    Kokkos::deep_copy(list.neighbors, nbr_host);
    list.num_pairs = listed;
    neighbors::transpose(list, by_facet, nf);
    body_forces(s, Vec3<T>::zero());
    sphere_deforming_facet_forces(s, mesh, list, hist, dem_law, false, T(dt), node_velocity, entry);
    surface_node_loads(adjacency, by_facet, entry, node_force);
    fe.second_half();
    if (n % every != 0 && n != total) continue;
    // a row: the node under the sphere, the sphere's force, the contact points, the node loads' sum
    HertzRow row;
    row.time = fe.time();
    row.travel = speed * fe.time();
    const std::vector<double> u = models::to_host(fe.displacement());
    row.depth = -u[static_cast<std::size_t>(3 * fe_node[0] + 2)];
    auto a = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), s.a);
    row.force = 4.0 * m_min * a(0, 2);  // up on the sphere; the node loads' sum is down
    row.hertz = row.depth > 0 ? 4.0 / 3.0 * e_star * std::sqrt(R) * std::pow(row.depth, 1.5) : 0.0;
    row.hertz_radius = row.depth > 0 ? std::sqrt(R * row.depth) : 0.0;
    row.depth_far = row.depth + far_field * row.force;
    row.hertz_far = row.depth_far > 0 ? 4.0 / 3.0 * e_star * std::sqrt(R) * std::pow(row.depth_far, 1.5) : 0.0;
    auto nf_host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), node_force);
    for (Index k = 0; k < ns; ++k) row.node_sum += 4.0 * nf_host(k, 2);
    auto e = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), entry);
    auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.nodes);
    auto fac = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.facets);
    for (Offset k = 0; k < listed; ++k) {
      if (e(k, 0) == 0 && e(k, 1) == 0 && e(k, 2) == 0) continue;
      ++row.contacts;
      // the contact's own overlap from its force (frictionless, its damping small at the press's slow rate:
      // F = 4/3 E_dem sqrt(R) delta^1.5)
      const double fk = std::sqrt(e(k, 0) * e(k, 0) + e(k, 1) * e(k, 1) + e(k, 2) * e(k, 2));
      row.overlap = std::max(row.overlap, std::pow(3.0 * fk / (4.0 * e_dem * std::sqrt(R)), 2.0 / 3.0));
      const Index f = nbr_host(k);
      double q[2] = {0, 0};
      for (int c4 = 0; c4 < 4; ++c4)
        for (int m = 0; m < 2; ++m) q[m] += e(k, 3 + c4) * x(fac(f, c4), m);
      row.contact_radius = std::max(row.contact_radius, std::hypot(q[0], q[1]));
    }
    row.approach = row.travel - row.overlap;
    row.kinetic = 4.0 * fe.kinetic_energy();
    out.rows.push_back(row);
  }
  out.steps = total;
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

// The other reading: the elastic body's tip on a rigid plane, FE contact only (no DEM): a quarter of a block whose
// contact face is Hertz's paraboloid z = rho^2 / (2R) (Hertz's own approximation of a sphere of radius R near its
// contact, Johnson 1985, 4.2; the small-strain limit of an elastic sphere on a rigid plate) out to rho = 2 a_max and
// its tangent cone beyond (which the plate never reaches; the block's corners stay valid), the other side fixed at
// z = H, pressed by solid::PlateContact (node-to-plane penalty, beta = plate_penalty x the stiffest mode's m omega^2, damping
// ratio 0.3; sweep_tyre's beta 0.1 leaves an overlap of about 40 % of d here) rising from z = 0. The lattice's zmax side is the contact face (PlateContact's side): the
// map sends the lattice point (xi, eta, zeta) to (eta, xi, H - zeta + (zeta / H) tip(rho)), rho^2 = xi^2 + eta^2
// (the swap of x and y keeps det J > 0), so the lattice's xmin is y = 0 (u_y = 0), ymin x = 0 (u_x = 0), zmin the
// fixed side. Rows as hertz_block_press: d = u_z of the tip node, the plate's force (x 4), the contact radius the
// largest rho of a node on or behind the plate, node_sum 0 (no DEM), overlap the plate's rise less d.
inline HertzBlockResult hertz_plate_press(const HertzBlockSpec& spec) {
  using T = double;
  const HertzGeometry g = hertz_geometry(spec, "dem::hertz_plate_press", false);
  const auto cpu0 = std::clock();
  HertzBlockResult out;
  const double R = g.R, E = g.E, nu = g.nu, e_star = g.e_star, a_max = g.a_max, W = g.W, h0 = g.h0;
  out.e_star = e_star;
  out.a_max = a_max;
  out.first_cell = h0;
  const std::vector<double> px = solid::graded_planes(0.0, W, h0, spec.ratio, std::max(h0, spec.largest * a_max));
  std::vector<double> pz = solid::graded_planes(W, 0.0, h0, spec.ratio, std::max(h0, spec.largest * a_max));
  std::reverse(pz.begin(), pz.end());
  solid::Config<3> c;
  c.mesh = solid::make_tensor_box<3>({px, px, pz});
  const double rho_p = 2.0 * a_max;  // the paraboloid out to 2 a_max, then its tangent cone (never near the plate)
  c.mesh.map = [W, R, rho_p](const double* xi, double* x) {
    const double rho = std::sqrt(xi[0] * xi[0] + xi[1] * xi[1]);
    const double tip = rho <= rho_p ? rho * rho / (2.0 * R) : rho_p * rho_p / (2.0 * R) + rho_p / R * (rho - rho_p);
    x[0] = xi[1];
    x[1] = xi[0];
    x[2] = W - xi[2] + (xi[2] / W) * tip;
  };
  c.order = spec.order;
  c.affine_geometry = false;
  c.dirichlet = {{"xmin", 2u, {}}, {"ymin", 1u, {}}, {"zmin", 7u, {}}};
  for (int k = 0; k < 3; ++k) out.cells[static_cast<std::size_t>(k)] = c.mesh.cells[static_cast<std::size_t>(k)];
  const HertzBody body = hertz_body(spec, g);
  const double cs = body.wave_speed;
  solid::HyperelasticExplicit<double, 3> fe(c, solid::HyperelasticLaw(body.law), body.options);
  out.dofs = fe.dof_count();
  const auto& d = fe.solid().discretization();
  const double dt = spec.step_fraction * fe.time_step();
  fe.set_time_step(dt);
  out.dt = dt;
  out.contact_step = fe.time_step();
  const double travel_max = spec.depth_max * R * 1.05;
  const double t_end = spec.press_time * W / cs, speed = travel_max / t_end;
  solid::PlateContact<T> plate(
      d, fe.lumped_mass(), fe.omega_max(), spec.plate_penalty, 0.3, [speed](double t) { return speed * t; }, [speed](double) { return speed; });
  fe.set_external_force([&plate](double t, const View1<T>& u, const View1<T>& v, const View1<T>& r) { plate.apply(t, u, v, r); });
  const std::int64_t tip = d.node({0, 0, d.lattice[2] - 1});
  const auto total = static_cast<std::int64_t>(std::ceil(t_end / dt));
  const std::int64_t every = std::max<std::int64_t>(1, total / spec.rows);
  for (std::int64_t n = 1; n <= total; ++n) {
    fe.step();
    if (n % every != 0 && n != total) continue;
    HertzRow row;
    row.time = fe.time();
    row.travel = plate.height(fe.time());
    const std::vector<double> u = models::to_host(fe.displacement());
    row.depth = u[static_cast<std::size_t>(3 * tip + 2)];
    row.overlap = row.travel - row.depth;
    row.approach = row.depth;
    row.force = 4.0 * plate.force();
    row.hertz = row.depth > 0 ? 4.0 / 3.0 * e_star * std::sqrt(R) * std::pow(row.depth, 1.5) : 0.0;
    row.hertz_radius = row.depth > 0 ? std::sqrt(R * row.depth) : 0.0;
    const double far_field = (1.0 + nu) * (3.0 - 2.0 * nu) / (2.0 * 3.14159265358979323846 * E * W);
    row.depth_far = row.depth + far_field * row.force;
    row.hertz_far = row.depth_far > 0 ? 4.0 / 3.0 * e_star * std::sqrt(R) * std::pow(row.depth_far, 1.5) : 0.0;
    for (const std::int64_t v : plate.nodes()) {
      const std::size_t i = static_cast<std::size_t>(3 * v);
      if (d.coordinates[i + 2] + u[i + 2] > row.travel) continue;
      row.contact_radius = std::max(row.contact_radius, std::hypot(d.coordinates[i] + u[i], d.coordinates[i + 1] + u[i + 1]));
    }
    row.contacts = plate.nodes_in_contact();
    row.kinetic = 4.0 * fe.kinetic_energy();
    out.rows.push_back(row);
  }
  out.steps = total;
  out.cpu_seconds = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  return out;
}

}  // namespace polymech::dem
