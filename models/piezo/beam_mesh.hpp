// The mesh of the finite-element piezoelectric beam and the numbering of its unknowns (issue 35; seed 002 paper 1
// eqs. (7), (8)): the spec's checks, the layered tensor-product mesh through the thickness, the electrode
// surfaces, the supports, and the members of models/piezo/piezo_beam.hpp that build them (check_spec,
// surface_plane, build_mesh, copy_disc, lattice_index, layer_of_cell, number_unknowns).
//
// Unknowns, in this order: the free displacement components (D per node, the clamped ones removed), the free
// potentials of the piezoelectric layers' interior nodes, then one potential per floating or prescribed
// electrode. A node gets no potential unknown when it touches no piezoelectric element, lies in or on the
// conducting host (grounded, eq. (7)), or lies on a grounded electrode.
#pragma once

#include <cstdint>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "piezo/piezo_beam.hpp"
#include "solid/discretization.hpp"

namespace polymech::piezo {

inline void PiezoBeam::check_spec() const {
  const auto& s = spec_;
  auto bad = [](const std::string& m) { throw std::invalid_argument("piezo beam: " + m); };
  if (s.dim != 2 && s.dim != 3) bad("dimension " + std::to_string(s.dim) + " (allowed: 2, 3)");
  if (!(s.length > 0.0) || !(s.width > 0.0) || !std::isfinite(s.length) || !std::isfinite(s.width))
    bad("length and width must be positive and finite");
  if (s.cells_length < 1 || (s.dim == 3 && s.cells_width < 1)) bad("cells per direction must be >= 1");
  if (s.layers.empty()) bad("at least one layer");
  bool any_piezo = false;
  for (const auto& l : s.layers) {
    if (!(l.thickness > 0.0) || !std::isfinite(l.thickness)) bad("layer '" + l.name + "': thickness must be positive");
    if (l.cells < 1) bad("layer '" + l.name + "': cells must be >= 1");
    if (l.poling != 1 && l.poling != -1) bad("layer '" + l.name + "': poling must be +1 or -1");
    any_piezo = any_piezo || l.piezoelectric;
  }
  if (!any_piezo) bad("no piezoelectric layer");
}

// The lattice index through the thickness of an electrode surface.
inline int PiezoBeam::surface_plane(const std::string& surface) const {
  const int nl = static_cast<int>(spec_.layers.size());
  int k = -1;
  if (surface == "bottom") k = 0;
  else if (surface == "top") k = nl;
  else if (surface.rfind("interface ", 0) == 0) {
    try {
      k = std::stoi(surface.substr(10));
    } catch (const std::exception&) {
      k = -1;
    }
    if (k < 1 || k >= nl) k = -1;
  }
  if (k < 0)
    throw std::invalid_argument("piezo beam: electrode surface '" + surface +
                                "' (allowed: bottom, top, interface K with K = 1.." + std::to_string(nl - 1) + ")");
  return spec_.order * layer_start_[static_cast<std::size_t>(k)];
}

inline void PiezoBeam::build_mesh() {
  const int D = spec_.dim;
  std::vector<double> thick{0.0};
  layer_start_.assign(1, 0);
  for (const auto& l : spec_.layers) {
    const double z0 = thick.back();
    for (int c = 1; c <= l.cells; ++c) thick.push_back(c == l.cells ? z0 + l.thickness : z0 + l.thickness * c / l.cells);
    layer_start_.push_back(layer_start_.back() + l.cells);
  }
  std::vector<double> xs(static_cast<std::size_t>(spec_.cells_length) + 1);
  for (int i = 0; i <= spec_.cells_length; ++i) xs[static_cast<std::size_t>(i)] = spec_.length * i / spec_.cells_length;
  if (D == 2) {
    copy_disc(solid::discretize(solid::make_tensor_box<2>({xs, thick}), spec_.order, 1 << 20));
  } else {
    std::vector<double> ys(static_cast<std::size_t>(spec_.cells_width) + 1);
    for (int i = 0; i <= spec_.cells_width; ++i) ys[static_cast<std::size_t>(i)] = spec_.width * i / spec_.cells_width;
    copy_disc(solid::discretize(solid::make_tensor_box<3>({xs, ys, thick}), spec_.order, 1 << 20));
  }
}

template <int D>
inline void PiezoBeam::copy_disc(const solid::Discretization<D>& d) {
  disc_.nodes = d.nodes;
  disc_.coordinates = d.coordinates;
  disc_.element_nodes = d.element_nodes;
  disc_.element_cells = d.element_cells;
  disc_.lattice.assign(d.lattice.begin(), d.lattice.end());
  disc_.cells.assign(d.cells.begin(), d.cells.end());
}

// lattice index of node v along direction d
inline int PiezoBeam::lattice_index(std::int64_t v, int d) const {
  for (int k = 0; k < d; ++k) v /= disc_.lattice[static_cast<std::size_t>(k)];
  return static_cast<int>(v % disc_.lattice[static_cast<std::size_t>(d)]);
}

inline int PiezoBeam::layer_of_cell(std::int64_t cell) const {
  const int D = spec_.dim;
  std::int64_t r = cell;
  for (int d = 0; d < D - 1; ++d) r /= disc_.cells[static_cast<std::size_t>(d)];
  const int ct = static_cast<int>(r);
  for (std::size_t k = 0; k + 1 < layer_start_.size(); ++k)
    if (ct < layer_start_[k + 1]) return static_cast<int>(k);
  return static_cast<int>(spec_.layers.size()) - 1;
}

inline void PiezoBeam::number_unknowns() {
  const int D = spec_.dim, T = D - 1;  // T: the thickness direction
  const std::int64_t nn = disc_.nodes;
  const int ND = static_cast<int>(disc_.element_nodes.size() / disc_.element_cells.size());
  // which nodes touch a piezoelectric element, which a conducting one
  std::vector<char> in_piezo(static_cast<std::size_t>(nn), 0), in_host(static_cast<std::size_t>(nn), 0);
  element_layer_.resize(disc_.element_cells.size());
  for (std::size_t e = 0; e < disc_.element_cells.size(); ++e) {
    const int l = layer_of_cell(disc_.element_cells[e]);
    element_layer_[e] = l;
    const bool pz = spec_.layers[static_cast<std::size_t>(l)].piezoelectric;
    for (int a = 0; a < ND; ++a) {
      const auto v = static_cast<std::size_t>(disc_.element_nodes[e * static_cast<std::size_t>(ND) + a]);
      (pz ? in_piezo : in_host)[v] = 1;
    }
  }
  // electrodes: -2 grounded, k >= 0 the k-th unknown electrode, -1 none
  std::vector<int> on_electrode(static_cast<std::size_t>(nn), -1);
  for (const auto& es : spec_.electrodes) {
    const int plane = surface_plane(es.surface);
    int id = -2;
    if (es.kind != ElectrodeKind::grounded) {
      id = static_cast<int>(electrode_names_.size());
      for (const auto& n : electrode_names_)
        if (n == es.name) throw std::invalid_argument("piezo beam: two electrodes named '" + es.name + "'");
      electrode_names_.push_back(es.name);
      electrode_kind_.push_back(es.kind);
      electrode_value_.push_back(es.potential);
    }
    for (std::int64_t v = 0; v < nn; ++v) {
      if (lattice_index(v, T) != plane) continue;
      if (id >= 0 && spec_.conducting_host && in_host[static_cast<std::size_t>(v)])
        throw std::invalid_argument("piezo beam: electrode '" + es.name + "' on '" + es.surface +
                                    "' touches the grounded conducting host (eq. (7)); make it grounded or the host "
                                    "non-conducting");
      if (on_electrode[static_cast<std::size_t>(v)] != -1 && on_electrode[static_cast<std::size_t>(v)] != id)
        throw std::invalid_argument("piezo beam: electrode '" + es.name + "' overlaps another electrode");
      on_electrode[static_cast<std::size_t>(v)] = id;
    }
  }
  // displacement unknowns
  std::vector<char> fixed(static_cast<std::size_t>(nn) * D, 0);
  if (spec_.support == Support::clamped_root) {
    for (std::int64_t v = 0; v < nn; ++v)
      if (lattice_index(v, 0) == 0)
        for (int c = 0; c < D; ++c) fixed[static_cast<std::size_t>(D * v + c)] = 1;
  } else {  // 3-2-1: (0,0[,0]) all; (L,0[,0]) all but x; 3D: (0,W,0) the thickness component
    auto node_at = [&](int i0, int i1) {
      for (std::int64_t v = 0; v < nn; ++v) {
        bool ok = lattice_index(v, 0) == i0 && lattice_index(v, T) == 0;
        if (D == 3) ok = ok && lattice_index(v, 1) == i1;
        if (ok) return v;
      }
      return std::int64_t{-1};
    };
    const int last0 = disc_.lattice[0] - 1;
    const std::int64_t a = node_at(0, 0), b = node_at(last0, 0);
    for (int c = 0; c < D; ++c) fixed[static_cast<std::size_t>(D * a + c)] = 1;
    for (int c = 1; c < D; ++c) fixed[static_cast<std::size_t>(D * b + c)] = 1;
    if (D == 3) fixed[static_cast<std::size_t>(D * node_at(0, disc_.lattice[1] - 1) + T)] = 1;
  }
  dof_u_.assign(static_cast<std::size_t>(nn) * D, -1);
  std::int64_t next = 0;
  for (std::int64_t i = 0; i < nn * D; ++i)
    if (!fixed[static_cast<std::size_t>(i)]) dof_u_[static_cast<std::size_t>(i)] = next++;
  nu_ = next;
  // potentials: interior free nodes, then the electrodes
  dof_phi_.assign(static_cast<std::size_t>(nn), -1);
  for (std::int64_t v = 0; v < nn; ++v) {
    const auto s = static_cast<std::size_t>(v);
    if (!in_piezo[s] || (spec_.conducting_host && in_host[s]) || on_electrode[s] != -1) continue;
    dof_phi_[s] = next++;
  }
  for (std::size_t k = 0; k < electrode_names_.size(); ++k) electrode_dof_.push_back(next++);
  for (std::int64_t v = 0; v < nn; ++v) {
    const int k = on_electrode[static_cast<std::size_t>(v)];
    if (k >= 0) dof_phi_[static_cast<std::size_t>(v)] = electrode_dof_[static_cast<std::size_t>(k)];
  }
  n_ = next;
  for (std::size_t k = 0; k < electrode_names_.size(); ++k) {
    bool used = false;
    for (std::int64_t v = 0; v < nn && !used; ++v) used = on_electrode[static_cast<std::size_t>(v)] == static_cast<int>(k);
    if (!used) throw std::invalid_argument("piezo beam: electrode '" + electrode_names_[k] + "' has no node");
  }
  is_electrode_.assign(static_cast<std::size_t>(n_), 0);
  is_prescribed_.assign(static_cast<std::size_t>(n_), 0);
  for (std::size_t k = 0; k < electrode_dof_.size(); ++k) {
    is_electrode_[static_cast<std::size_t>(electrode_dof_[k])] = 1;
    if (electrode_kind_[k] == ElectrodeKind::prescribed) is_prescribed_[static_cast<std::size_t>(electrode_dof_[k])] = 1;
  }
  // base direction and tip
  r_.assign(static_cast<std::size_t>(n_), 0.0);
  for (std::int64_t v = 0; v < nn; ++v) {
    const std::int64_t d = dof_u(v, T);
    if (d >= 0) r_[static_cast<std::size_t>(d)] = 1.0;
    if (lattice_index(v, 0) == disc_.lattice[0] - 1 && d >= 0) tip_dofs_.push_back(d);
  }
}

}  // namespace polymech::piezo
