// The boundaries of the Helmholtz model (seed 002 paper 3), on one part of the domain decomposition:
//   dirichlet  strong values on the DoFs of the boundary's faces: the analytic field of eq. (27), or a
//              constant; those rows of eq. (16) become identity rows (kernels/fem/dirichlet.hpp)
//   impedance  the face term j rho omega / Z_n of eqs. (7), (19), in the operator
//   vibrating  the face load of eqs. (8), (20): the normal velocity, on the right-hand side
// Rigid boundaries (dPhi/dn = 0) are natural and cost nothing. Host set-up; one kernel (dirichlet_data).
#pragma once

#include <complex>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "fem/boundary_faces.hpp"
#include "fem/dirichlet.hpp"
#include "helmholtz/analytic.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/distribute.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/element_data.hpp"

namespace polymech::helmholtz {

namespace detail {

// Kernels of the model, as free functions (CUDA: no extended lambdas in constructors or private members).

inline void dirichlet_data(const View1<Index>& constrained, const CoordinateView& x, const AnalyticField& field,
                           double constant, bool analytic, const View1<Kokkos::complex<double>>& g) {
  Kokkos::parallel_for(
      "polymech::helmholtz::dirichlet_data", range(static_cast<Index>(constrained.extent(0))),
      KOKKOS_LAMBDA(const Index k) {
        const Index d = constrained(k);
        g(k) = analytic ? field(x(d, 0), x(d, 1), x(d, 2)) : Kokkos::complex<double>(constant, 0.0);
      });
}

template <class T>
void to_precision(const View1<Kokkos::complex<double>>& from, const View1<Kokkos::complex<T>>& to) {
  Kokkos::parallel_for(
      "polymech::helmholtz::to_precision", range(static_cast<Index>(from.extent(0))),
      KOKKOS_LAMBDA(const Index i) { to(i) = Kokkos::complex<T>(static_cast<T>(from(i).real()), static_cast<T>(from(i).imag())); });
}

}  // namespace detail

// Faces of one boundary kind, as the model sets them up (host description, also used by the assembled
// reference): the boundary faces and one coefficient per face.
struct FaceTerm {
  std::vector<BoundaryFace> faces;
  std::vector<std::complex<double>> coefficient;
};

// The coefficient of a face of mesh boundary `boundary` if that is of `kind`: j rho omega / Z_n
// (impedance, eq. (19)), the normal velocity (vibrating, eq. (20)); 0 otherwise.
inline std::complex<double> face_coefficient(const Config& c, BoundaryKind kind, int boundary) {
  for (const auto& b : c.boundaries)
    if (b.kind == kind && c.mesh.boundary_index(b.name) == boundary) {
      if (kind == BoundaryKind::impedance) return {0.0, c.density * c.omega() / b.impedance};  // j rho omega / Zn
      if (kind == BoundaryKind::vibrating) return {b.velocity, 0.0};                           // eq. (20)
    }
  return {0.0, 0.0};
}

// The mesh's boundary faces of the boundaries of `kind`, boundary after boundary.
inline std::vector<BoundaryFace> faces_of(const Config& c, BoundaryKind kind) {
  std::vector<BoundaryFace> out;
  for (const auto& b : c.boundaries) {
    if (b.kind != kind) continue;
    const int id = c.mesh.boundary_index(b.name);
    for (const auto& f : c.mesh.boundary_faces)
      if (f.boundary == id) out.push_back(f);
  }
  return out;
}

inline FaceTerm face_term(const Config& c, BoundaryKind kind) {
  FaceTerm t;
  for (const auto& f : faces_of(c, kind)) {
    t.faces.push_back(f);
    t.coefficient.push_back(face_coefficient(c, kind, f.boundary));
  }
  return t;
}

// The Dirichlet mask of the part's local DoFs (all zero without the effect `dirichlet`).
inline std::vector<char> constrained_mask_of_part(const Config& c, const HexDofs& dofs, const PartLayout& layout) {
  std::vector<char> global(static_cast<std::size_t>(dofs.count), 0);
  if (c.effects.has("dirichlet")) global = dofs_on_faces(dofs, faces_of(c, BoundaryKind::dirichlet));
  const Index n = static_cast<Index>(layout.global_of_local.size());
  std::vector<char> local(static_cast<std::size_t>(n), 0);
  for (Index i = 0; i < n; ++i) local[i] = global[layout.global_of_local[i]];
  return local;
}

// The part's faces of `kind` (those of its elements), coloured by shared vertices, with their local DoFs
// (constrained ones encoded), coefficients and weights (kernels/fem/boundary_faces.hpp). Throws
// std::invalid_argument for a degenerate face.
template <class T>
fem::HexFaces<T, Kokkos::complex<T>> boundary_faces(const Config& c, const HexDofs& dofs, const PartLayout& layout,
                                                    const CoordinateView& x, BoundaryKind kind,
                                                    const std::vector<char>& constrained, const std::string& name) {
  using C = Kokkos::complex<T>;
  FaceTerm term;  // this part's faces: those of its elements
  {
    const FaceTerm all = face_term(c, kind);
    std::vector<char> here(static_cast<std::size_t>(c.mesh.element_count()), 0);
    for (const auto e : layout.elements) here[e] = 1;
    for (std::size_t i = 0; i < all.faces.size(); ++i)
      if (here[all.faces[i].element]) {
        term.faces.push_back(all.faces[i]);
        term.coefficient.push_back(all.coefficient[i]);
      }
  }
  const int N = dofs.n1d, N3 = dofs.nodes_per_element();
  std::vector<std::int64_t> verts;
  for (const auto& f : term.faces)
    for (int v : hex_face_vertices(f.face)) verts.push_back(c.mesh.hexes[8 * f.element + v]);
  std::vector<std::int64_t> order;
  std::vector<std::int32_t> offsets;
  sort_by_color(color_by_shared_vertices(verts, 4, c.mesh.vertex_count()), order, offsets);
  fem::HexFaces<T, C> f;
  f.order = c.order;
  f.color_offsets.assign(offsets.begin(), offsets.end());
  const std::string prefix = "polymech::helmholtz::" + name;
  f.dofs = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>(prefix + "_face_dofs", order.size(), N * N);
  f.coefficient = View1<C>(prefix + "_face_coefficients", order.size());
  auto hd = Kokkos::create_mirror_view(f.dofs);
  auto hc = Kokkos::create_mirror_view(f.coefficient);
  for (std::size_t s = 0; s < order.size(); ++s) {
    const BoundaryFace& bf = term.faces[order[s]];
    const auto nodes = face_local_nodes(N, bf.face);
    for (int a = 0; a < N * N; ++a) {
      const std::int32_t d = layout.local_of_global[dofs.element_dofs[bf.element * N3 + nodes[a]]];
      hd(s, a) = constrained[d] ? fem::constrained_dof(d) : d;
    }
    const auto cf = term.coefficient[order[s]];
    hc(s) = C(static_cast<T>(cf.real()), static_cast<T>(cf.imag()));
  }
  Kokkos::deep_copy(f.dofs, hd);
  Kokkos::deep_copy(f.coefficient, hc);
  const double ratio = fem::compute_face_weights(f, x, prefix + "_face_weights");
  if (!(ratio > 0.0))
    throw std::invalid_argument("helmholtz: a " + name + " boundary face is degenerate (zero area at a point)");
  return f;
}

// The Dirichlet DoFs of the part (local indices) and their values g in precision T: the analytic field
// of eq. (27) where the case has one, else the constant of the (last) Dirichlet boundary.
template <class T>
struct DirichletValues {
  View1<Index> dofs;
  View1<Kokkos::complex<T>> values;
};
template <class T>
DirichletValues<T> dirichlet_values(const Config& c, const AnalyticField& field, const CoordinateView& x,
                                    const std::vector<char>& constrained) {
  DirichletValues<T> d;
  std::vector<Index> list;
  for (Index i = 0; i < static_cast<Index>(constrained.size()); ++i)
    if (constrained[i]) list.push_back(i);
  d.dofs = models::to_device<Index>("polymech::helmholtz::dirichlet_dofs", list);
  double value = 0.0;
  for (const auto& b : c.boundaries)
    if (b.kind == BoundaryKind::dirichlet) value = b.value;
  View1<Kokkos::complex<double>> g("polymech::helmholtz::dirichlet_values_double", list.size());
  detail::dirichlet_data(d.dofs, x, field, value, field.kind != AnalyticKind::none, g);
  d.values = View1<Kokkos::complex<T>>("polymech::helmholtz::dirichlet_values", list.size());
  detail::to_precision(g, d.values);
  return d;
}

}  // namespace polymech::helmholtz
