// One order of the Helmholtz problem's discretization on this rank's part (seed 002 paper 3): the global
// DoF numbering of the order-p hexahedral Lagrange space, the part's elements and local DoFs, its Dirichlet
// DoFs and values, boundary faces, and the matrix-free operator K = A - k^2 M + j rho omega C of eq. (16).
// The model (helmholtz.hpp) holds one at the scene's order; the p-multigrid preconditioner
// (preconditioners.hpp) builds one per coarser order from the same Config, with no model around it.
//
// The steps, each in its own file: the numbering (models/common/hex_dofs.hpp), the part
// (distribute.hpp), the elements and geometry (element_data.hpp), the faces and the Dirichlet values
// (boundary.hpp), the operator (operator.hpp) and its halo (parallel.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "helmholtz/analytic.hpp"
#include "helmholtz/boundary.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/distribute.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/element_data.hpp"
#include "helmholtz/operator.hpp"
#include "helmholtz/parallel.hpp"

namespace polymech::helmholtz {

// Typical element size h = (bounding-box volume / elements)^(1/3) (the node perturbation's scale).
inline double mean_element_size(const HexMesh& mesh) {
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::int64_t v = 0; v < mesh.vertex_count(); ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], mesh.vertices[3 * v + k]);
      hi[k] = std::max(hi[k], mesh.vertices[3 * v + k]);
    }
  const double vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  return std::cbrt(vol / static_cast<double>(mesh.element_count()));
}

template <class T>
struct Discretization {
  using C = Kokkos::complex<T>;

  HexDofs dofs;  // global numbering (every rank)
  std::shared_ptr<const Communicator> comm;
  PartLayout layout;  // this rank's elements and local DoFs (owned, then ghosts)
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> error_dofs;  // elements counted in eq. (28), local DoFs
  std::vector<std::int64_t> element_order;  // storage index -> mesh element
  fem::HexElements<T> el;
  CoordinateView x;  // per local DoF
  fem::JacobianCheck jacobian;
  fem::HexFaces<T, C> vibrating;
  View1<Index> constrained;
  View1<C> dirichlet_values;
  HelmholtzOperator<T> op;

  Discretization() = default;
  // Config c at its order (c.order); `field` gives the Dirichlet values where the case has an analytic field.
  Discretization(const Config& c, const AnalyticField& field);

  // The Dirichlet mask of every DoF of the mesh (1 = constrained).
  std::vector<char> constrained_mask() const {
    std::vector<char> mask(static_cast<std::size_t>(dofs.count), 0);
    auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), constrained);
    for (std::size_t k = 0; k < h.extent(0); ++k) mask[layout.global_of_local[h(k)]] = 1;
    return mask;
  }
};

// The steps: every DoF of the mesh numbered (every rank numbers them all) in the locality order, with
// Config::node_perturbation the interior nodes moved at random (a fraction of h / p); this rank's part;
// its Dirichlet mask; the elements in coloured chunks with their geometry; the faces of the enabled
// effects and the Dirichlet values; the operator, with its halo on several ranks.
template <class T>
Discretization<T>::Discretization(const Config& c, const AnalyticField& field) {
  const std::vector<std::int64_t> traversal = locality_order(c.mesh);
  dofs = number_dofs(c.mesh, c.order, traversal);
  if (c.node_perturbation > 0) {
    const auto ext = exterior_faces(c.mesh);
    perturb_nodes(dofs, dofs_on_faces(dofs, ext), c.node_perturbation, mean_element_size(c.mesh) / c.order);
  }
  comm = c.communicator ? c.communicator : std::make_shared<SerialCommunicator>();
  layout = make_part_layout(c.mesh, dofs, traversal, comm->rank(), comm->size(), c.partition);
  const std::vector<char> mask = constrained_mask_of_part(c, dofs, layout);  // Dirichlet DoFs, local
  {
    ElementData<T> d = element_data<T>(c, dofs, layout, mask, *comm);
    element_order = std::move(d.order);
    el = d.el;
    x = d.x;
    jacobian = d.jacobian;
    error_dofs = d.error_dofs;
  }
  fem::HexFaces<T, C> impedance;
  if (c.effects.has("impedance"))
    impedance = boundary_faces<T>(c, dofs, layout, x, BoundaryKind::impedance, mask, "impedance");
  if (c.effects.has("vibrating"))
    vibrating = boundary_faces<T>(c, dofs, layout, x, BoundaryKind::vibrating, mask, "vibrating");
  if (c.effects.has("dirichlet")) {
    const DirichletValues<T> dv = helmholtz::dirichlet_values<T>(c, field, x, mask);
    constrained = dv.dofs;
    dirichlet_values = dv.values;
  }
  const double k = c.wavenumber();
  op = HelmholtzOperator<T>(el, impedance, constrained, static_cast<T>(-k * k));
  if (comm->size() > 1)
    op.distribute(std::make_shared<Halo<C>>(comm, layout.neighbours, layout.send, layout.recv), comm);
}

}  // namespace polymech::helmholtz
