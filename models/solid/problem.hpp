// The set-up a static solid model shares (issue 34): from a Config, the discretization of the structured mesh or of
// the unstructured hexahedral one (elements, chunks and colours), the node coordinates and geometry, the Dirichlet
// constraints (the mask per node, the encoded element table, the list of constrained DoFs and their values g), the
// uniform elastic stiffness per element, the external force f_ext (tractions and body forces) and the linear lifting
// rhs = f_ext - K g off the constrained rows, g on them. solid::LinearElastic (linear_elastic.hpp) and
// solid::ElastoPlastic (elastoplastic.hpp) both derive from it.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "solid/assembly.hpp"
#include "solid/config.hpp"
#include "solid/discretization.hpp"
#include "solid/elastic_operator.hpp"
#include "solid/loads.hpp"

namespace polymech::solid {

template <class T, int D>
class SolidProblem {
 public:
  explicit SolidProblem(const Config<D>& c) : config_(c) {
    set_up_elements();
    set_up_constraints();
    set_up_load();
  }

  const Config<D>& config() const { return config_; }
  const Discretization<D>& discretization() const { return disc_; }
  const ElasticOperator<T, D>& op() const { return op_; }
  const SolidElements<T, D>& elements() const { return op_.el; }
  const NodeCoordinates<D>& coordinates() const { return x_; }
  Index dof_count() const { return op_.el.dof_count(); }
  Index element_count() const { return op_.el.elements(); }
  const fem::JacobianCheck& jacobian() const { return jacobian_; }
  const View1<T>& rhs() const { return rhs_; }                 // f - K g, g on the constrained rows
  const View1<T>& external_force() const { return f_ext_; }   // f_ext, every DoF
  const View1<T>& dirichlet_values() const { return g_; }     // g, one per constrained DoF (op().constrained)
  const std::vector<char>& constrained_mask() const { return constrained_; }  // per DoF

  // What the host assembly reads, without the material (the caller adds `material` or `point_material`).
  AssemblyInput assembly_input() const {
    AssemblyInput in;
    in.dim = D;
    in.order = config_.order;
    in.element_nodes = disc_.element_nodes;
    in.coordinates = disc_.coordinates;
    in.constrained = constrained_;
    return in;
  }
  // The assembled constrained elastic stiffness (one C per element), in double on the host.
  Triplets assemble_elastic() const {
    AssemblyInput in = assembly_input();
    const auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), op_.el.material);
    in.material.resize(m.extent(0) * 36);
    for (std::size_t e = 0; e < m.extent(0); ++e)
      for (int k = 0; k < 36; ++k) in.material[e * 36 + k] = static_cast<double>(m(e, k));
    return assemble_stiffness(in);
  }

 protected:
  void set_up_elements() {
    const bool device = !Kokkos::SpaceAccessibility<HostSpace, MemSpace>::accessible;
    const int threads = kx::concurrency<ExecSpace>();
    if (config_.hex_mesh.element_count() > 0) {
      if constexpr (D == 3) {
        const std::int64_t e = config_.chunk_edge;
        const std::int64_t per_chunk =
            e > 0 ? e * e * e
                  : default_chunk_elements(config_.hex_mesh.element_count(), config_.order, threads, device);
        disc_ = discretize(config_.hex_mesh, config_.order, per_chunk);
      } else {
        throw std::invalid_argument("solid: an unstructured hexahedral mesh needs the 3D model (Config<3>)");
      }
    } else {
      const int edge = config_.chunk_edge > 0 ? config_.chunk_edge
                                              : default_chunk_edge(config_.mesh, config_.order, threads, device);
      disc_ = discretize(config_.mesh, config_.order, edge);
    }
    auto& el = op_.el;
    el.cells.order = config_.order;
    el.cells.batch = solid_batch<T>();
    el.nodes = static_cast<Index>(disc_.nodes);
    el.cells.owned = D * el.nodes;
    el.cells.color_offsets.assign(disc_.color_offsets.begin(), disc_.color_offsets.end());
    std::vector<Index> chunks(disc_.chunk_start.begin(), disc_.chunk_start.end());
    el.cells.chunk_offsets = models::to_device<Index>("polymech::solid::chunk_offsets", chunks);
    // node coordinates
    x_ = NodeCoordinates<D>("polymech::solid::coordinates", disc_.nodes);
    auto xh = Kokkos::create_mirror_view(x_);
    for (std::int64_t v = 0; v < disc_.nodes; ++v)
      for (int d = 0; d < D; ++d) xh(v, d) = disc_.coordinates[static_cast<std::size_t>(D * v + d)];
    Kokkos::deep_copy(x_, xh);
  }

  // Dirichlet data: the mask of constrained components per node, the node table with those nodes encoded,
  // the list of constrained DoFs and their values g.
  void set_up_constraints() {
    auto& el = op_.el;
    std::vector<unsigned char> mask(static_cast<std::size_t>(disc_.nodes), 0);
    std::vector<double> value(static_cast<std::size_t>(disc_.nodes) * D, 0.0);
    for (const auto& dc : config_.dirichlet)
      for (const std::int64_t v : side_nodes(disc_, dc.boundary)) {
        double u[3] = {0.0, 0.0, 0.0}, p[3] = {0.0, 0.0, 0.0};
        for (int d = 0; d < D; ++d) p[d] = disc_.coordinates[static_cast<std::size_t>(D * v + d)];
        if (dc.value) dc.value(p, u);
        for (int c = 0; c < D; ++c)
          if ((dc.components >> c) & 1u) {
            mask[v] |= static_cast<unsigned char>(1u << c);
            value[static_cast<std::size_t>(D * v + c)] = u[c];
          }
      }
    constrained_.assign(static_cast<std::size_t>(D) * disc_.nodes, 0);
    std::vector<Index> list;
    std::vector<T> g;
    for (std::int64_t v = 0; v < disc_.nodes; ++v)
      for (int c = 0; c < D; ++c)
        if ((mask[v] >> c) & 1u) {
          constrained_[static_cast<std::size_t>(D * v + c)] = 1;
          list.push_back(static_cast<Index>(D * v + c));
          g.push_back(static_cast<T>(value[static_cast<std::size_t>(D * v + c)]));
        }
    op_.constrained = models::to_device<Index>("polymech::solid::constrained", list);
    g_ = models::to_device<T>("polymech::solid::dirichlet_values", g);
    el.fixed_mask = models::to_device<unsigned char>("polymech::solid::fixed_mask", mask);
    const int ND = disc_.nodes_per_element();
    el.cells.dofs = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::solid::element_nodes",
                                                                         disc_.element_cells.size(), ND);
    auto dh = Kokkos::create_mirror_view(el.cells.dofs);
    for (std::size_t e = 0; e < disc_.element_cells.size(); ++e)
      for (int a = 0; a < ND; ++a) {
        const Index v = static_cast<Index>(disc_.element_nodes[e * ND + a]);
        dh(e, a) = mask[v] ? fem::constrained_dof(v) : v;
      }
    Kokkos::deep_copy(el.cells.dofs, dh);
    jacobian_ = compute_geometry(el, x_, config_.affine_geometry);
    if (!(jacobian_.min_ratio > 0.0)) {
      const std::int64_t e = jacobian_.element;  // storage index; an unstructured mesh names the file's element
      const bool named = disc_.unstructured && e >= 0 && e < static_cast<std::int64_t>(disc_.element_cells.size());
      const std::string which =
          named ? config_.hex_mesh.describe_element(disc_.element_cells[static_cast<std::size_t>(e)])
                : "element " + std::to_string(e);
      throw std::invalid_argument("solid: " + which +
                                  " is inverted or too distorted: det J / (volume / 2^D) = " +
                                  models::format_g(jacobian_.min_ratio) + " (allowed: > 0); reduce the distortion");
    }
    materials::Stiffness6<double> C = config_.stiffness;
    if (D == 2 && config_.plane == Plane::stress) C = materials::plane_stress_condensed(C);
    set_uniform_material(el, C);
  }

  // rhs = f_ext - K g off the constrained rows, g on them.
  void set_up_load() {
    const Index n = dof_count();
    f_ext_ = View1<T>("polymech::solid::external_force", n);
    rhs_ = View1<T>("polymech::solid::rhs", n);
    if (!config_.tractions.empty()) {
      const int NF = D == 3 ? disc_.n1d * disc_.n1d : disc_.n1d;
      std::vector<std::int64_t> nodes;
      std::vector<double> t;
      for (const auto& tr : config_.tractions) {
        const auto f = side_faces(disc_, tr.boundary);
        nodes.insert(nodes.end(), f.begin(), f.end());
        for (std::size_t k = 0; k < f.size() / NF; ++k) t.insert(t.end(), tr.t.begin(), tr.t.begin() + D);
      }
      TractionFaces<T, D> faces;
      faces.order = config_.order;
      const std::size_t nf = nodes.size() / NF;
      faces.nodes = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::solid::traction_nodes", nf, NF);
      faces.traction = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::tractions", nf, D);
      auto nh = Kokkos::create_mirror_view(faces.nodes);
      auto th = Kokkos::create_mirror_view(faces.traction);
      for (std::size_t f = 0; f < nf; ++f) {
        for (int a = 0; a < NF; ++a) nh(f, a) = static_cast<Index>(nodes[f * NF + a]);
        for (int d = 0; d < D; ++d) th(f, d) = t[f * D + d];
      }
      Kokkos::deep_copy(faces.nodes, nh);
      Kokkos::deep_copy(faces.traction, th);
      compute_face_weights(faces, x_);
      add_face_tractions(faces, f_ext_);
    }
    if (!config_.body_forces.empty()) {
      const auto xq = quadrature_points(op_.el, x_);
      Kokkos::View<double***, Kokkos::LayoutRight, MemSpace> body("polymech::solid::body_force", xq.extent(0),
                                                                  xq.extent(1), D);
      auto bh = Kokkos::create_mirror_view(body);
      const auto xh = Kokkos::create_mirror_view_and_copy(HostSpace(), xq);
      for (std::size_t e = 0; e < xh.extent(0); ++e)
        for (std::size_t q = 0; q < xh.extent(1); ++q) {
          const double p[3] = {xh(e, q, 0), xh(e, q, 1), D == 3 ? xh(e, q, D - 1) : 0.0};
          for (const auto& bf : config_.body_forces) {
            double b[3] = {0.0, 0.0, 0.0};
            bf.b(p, b);
            for (int d = 0; d < D; ++d) bh(e, q, d) += b[d];
          }
        }
      Kokkos::deep_copy(body, bh);
      add_body_force(op_.el, body, f_ext_);
    }
    // lifting: rhs = f - K g (K over every DoF applied to -g, which is zero off the constrained DoFs)
    View1<T> minus_g("polymech::solid::dirichlet_field", n);
    fem::set_constrained_values(op_.constrained, g_, minus_g);
    solvers::scale(n, T(-1), minus_g, minus_g);
    Kokkos::deep_copy(rhs_, f_ext_);
    add_elastic_apply<false>(op_.el, minus_g, rhs_);
    fem::set_constrained_values(op_.constrained, g_, rhs_);
  }

  Config<D> config_;
  Discretization<D> disc_;
  ElasticOperator<T, D> op_;
  NodeCoordinates<D> x_;
  fem::JacobianCheck jacobian_;
  std::vector<char> constrained_;
  View1<T> g_, f_ext_, rhs_;
};

}  // namespace polymech::solid
