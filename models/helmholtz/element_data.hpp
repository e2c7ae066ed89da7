// The element data of one part of the Helmholtz model (seed 002 paper 3): its elements in chunks of
// neighbours grouped by colour (so that one colour's chunks scatter without conflicts), each element's
// local DoFs (constrained ones encoded, kernels/fem/dirichlet.hpp), the DoF coordinates, the geometric
// factors of the order-p map with their Jacobian check, and the DoFs of the elements this part counts
// in the L2 error of eq. (28). Built once by the model's constructor (helmholtz.hpp), on the host, then
// copied to the device; launches no kernel of its own but fem::compute_geometry.
#pragma once

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "fem/helmholtz_operator.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/distribute.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/parallel.hpp"

namespace polymech::helmholtz {

using CoordinateView = Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>;

template <class T>
struct ElementData {
  std::vector<std::int64_t> order;  // storage index -> mesh element (chunk after chunk, colour after colour)
  fem::HexElements<T> el;
  CoordinateView x;                 // per local DoF
  fem::JacobianCheck jacobian;      // the worst element over all parts
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> error_dofs;  // elements counted in eq. (28), local DoFs
};

// Elements per chunk. On a device, one (every element its own thread). On the host about 8000 element
// nodes, so that a thread reuses the DoFs its chunk's elements share while they are in cache (1M DoFs,
// one thread: p = 2 1.5x, p = 3 1.4x, p = 4 1.4x faster than one element per chunk; p = 1 the same;
// docs/PERFORMANCE.md), but at least 64 chunks per thread so that the colours still balance.
// A multiple of the batch size, so that only the last batch of a chunk can be partial.
inline std::int64_t chunk_size(const Config& c, int batch) {
  if (c.chunk_elements > 0) return c.chunk_elements;
  if (!Kokkos::SpaceAccessibility<HostSpace, MemSpace>::accessible) return batch;
  const std::int64_t n = c.order + 1;
  const std::int64_t balance = c.mesh.element_count() / (64 * std::max(1, kx::concurrency<ExecSpace>()));
  const std::int64_t size = std::max<std::int64_t>(1, std::min<std::int64_t>(8000 / (n * n * n), balance));
  return (size + batch - 1) / batch * batch;
}

// The part's elements in chunks of neighbours, coloured: mesh::chunk_order (models/common/hex_dofs.hpp).
using mesh::chunk_order;
using mesh::ChunkOrder;

// The DoFs of the elements listed in `elements` (storage order), as local DoFs; `encode` maps a global
// DoF to the stored index (a constrained one encoded, or not).
template <class Encode>
Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> element_dof_table(const std::string& label, const HexDofs& dofs,
                                                                       const std::vector<std::int64_t>& elements,
                                                                       const Encode& encode) {
  const int N3 = dofs.nodes_per_element();
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> table(label, elements.size(), N3);
  auto h = Kokkos::create_mirror_view(table);
  for (std::size_t s = 0; s < elements.size(); ++s)
    for (int a = 0; a < N3; ++a) h(s, a) = encode(dofs.element_dofs[elements[s] * N3 + a]);
  Kokkos::deep_copy(table, h);
  return table;
}

// The coordinates of the part's local DoFs.
inline CoordinateView local_coordinates(const HexDofs& dofs, const PartLayout& layout) {
  const Index n = static_cast<Index>(layout.global_of_local.size());
  CoordinateView x("polymech::helmholtz::coordinates", n);
  auto h = Kokkos::create_mirror_view(x);
  for (Index i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) h(i, k) = dofs.coordinates[3 * static_cast<std::size_t>(layout.global_of_local[i]) + k];
  Kokkos::deep_copy(x, h);
  return x;
}

// The element data of this rank's part (constrained: the local Dirichlet mask). Throws
// std::invalid_argument naming the element where the map is inverted or too distorted (det J <= 0).
template <class T>
ElementData<T> element_data(const Config& c, const HexDofs& dofs, const PartLayout& layout,
                            const std::vector<char>& constrained, const Communicator& comm) {
  ElementData<T> d;
  const Index n = static_cast<Index>(layout.global_of_local.size());
  const auto& local = layout.local_of_global;
  const int batch = c.batch_elements > 0 ? c.batch_elements : fem::volume_batch<T>();
  ChunkOrder chunks = chunk_order(c.mesh, layout.elements, chunk_size(c, batch));
  d.order = std::move(chunks.elements);
  d.el.order = c.order;
  d.el.batch = batch;
  d.el.owned = layout.owned;
  d.el.ghost = n - layout.owned;
  d.el.color_offsets.assign(chunks.color_offsets.begin(), chunks.color_offsets.end());
  d.el.chunk_offsets = models::to_device<Index>(
      "polymech::helmholtz::chunk_offsets", std::vector<Index>(chunks.chunk_start.begin(), chunks.chunk_start.end()));
  d.el.dofs = element_dof_table("polymech::helmholtz::element_dofs", dofs, d.order, [&](std::int32_t global) {
    const std::int32_t l = local[global];
    return constrained[l] ? fem::constrained_dof(l) : l;
  });
  d.x = local_coordinates(dofs, layout);
  d.jacobian = fem::compute_geometry(d.el, d.x, c.affine_geometry);
  {  // the worst element over all parts (a part without the worst reports +1e300)
    double w[2] = {-d.jacobian.min_ratio, static_cast<double>(comm.rank())};
    comm.max(w, 1);
    if (-w[0] < d.jacobian.min_ratio) d.jacobian.element = -1;  // another part holds it
    d.jacobian.min_ratio = -w[0];
  }
  // the elements each part counts in integrals (eq. (28)): its own, not the overlap
  std::vector<std::int64_t> counted;
  for (const auto e : d.order)
    if (layout.counts(e)) counted.push_back(e);
  d.error_dofs = element_dof_table("polymech::helmholtz::error_dofs", dofs, counted,
                                   [&](std::int32_t global) { return local[global]; });
  if (!(d.jacobian.min_ratio > 0.0))
    throw std::invalid_argument(
        "helmholtz: " +
        (d.jacobian.element >= 0 ? c.mesh.describe_element(d.order[d.jacobian.element]) : std::string("an element")) +
        " is inverted or too distorted: det J / (volume / 8) = " + models::format_g(d.jacobian.min_ratio) +
        " at a node or quadrature point of the order-" + std::to_string(c.order) +
        " map (allowed: > 0 everywhere); check the vertex order (Gmsh hexahedron numbering) and the distortion");
  return d;
}

}  // namespace polymech::helmholtz
