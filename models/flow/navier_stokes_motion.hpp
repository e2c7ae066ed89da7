// What a driver changes between the solves of flow::NavierStokes2D (models/flow/navier_stokes.hpp): the
// Dirichlet values (the boundary velocity, per-node overrides), the mesh (ALE coordinates and mesh velocity),
// and the time-stepping state a partitioned FSI step restores to take a step again.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/navier_stokes_model.hpp"

namespace polymech::flow {

inline void NavierStokes2D::apply_dirichlet(double t) {
  for (std::int64_t n = 0; n < nn_; ++n) {
    const unsigned tags = mesh_.tags[static_cast<std::size_t>(n)];
    if (!(tags & cfg_.dirichlet_tags)) continue;
    Vec2 v{0.0, 0.0};
    if (cfg_.boundary_velocity) v = cfg_.boundary_velocity(tags, mesh_.x[2 * n], mesh_.x[2 * n + 1], t);
    u_host_[2 * static_cast<std::size_t>(n)] = v[0];
    u_host_[2 * static_cast<std::size_t>(n) + 1] = v[1];
  }
  for (std::size_t k = 0; k < node_velocity_nodes_.size(); ++k) {
    u_host_[2 * static_cast<std::size_t>(node_velocity_nodes_[k])] = node_velocity_values_[2 * k];
    u_host_[2 * static_cast<std::size_t>(node_velocity_nodes_[k]) + 1] = node_velocity_values_[2 * k + 1];
  }
  if (pinned_ >= 0) u_host_[static_cast<std::size_t>(pinned_)] = cfg_.pin_value;
}

// A moving mesh (ALE; models/fsi/mesh_motion.hpp): new node coordinates (node_count x 2, the same topology),
// then the geometry is recomputed (throws for an inverted element). The state is kept as the next start.
inline void NavierStokes2D::set_coordinates(const std::vector<double>& x) {
  if (x.size() != mesh_.x.size())
    throw std::invalid_argument("flow: set_coordinates got " + std::to_string(x.size()) + " values for " +
                                std::to_string(mesh_.x.size()));
  mesh_.x = x;
  update_geometry();
}

// The mesh velocity w per node (node_count x 2, indexed like the state's velocity part) for the ALE convective
// velocity u - w; an empty vector: a mesh at rest.
inline void NavierStokes2D::set_mesh_velocity(const std::vector<double>& w) {
  if (w.empty()) {
    W_ = View1<double>();
    return;
  }
  if (w.size() != static_cast<std::size_t>(2 * nn_))
    throw std::invalid_argument("flow: set_mesh_velocity got " + std::to_string(w.size()) + " values for " +
                                std::to_string(2 * nn_));
  if (W_.extent(0) != w.size()) W_ = View1<double>("polymech::flow::W", w.size());
  copy_to(W_, w);
}

// Per-node prescribed velocities (a moving wall whose velocity is known node by node, e.g. the wet nodes of an
// elastic body in a partitioned FSI step, models/fsi/turek_hron_fsi_transient.hpp): nodes[k] gets (values[2k],
// values[2k + 1]) instead of boundary_velocity, from the next solve or step on. Each node must be a Dirichlet
// node (a tag in dirichlet_tags); empty vectors remove the override.
inline void NavierStokes2D::set_node_velocity(const std::vector<std::int64_t>& nodes, const std::vector<double>& values) {
  if (values.size() != 2 * nodes.size())
    throw std::invalid_argument("flow: set_node_velocity got " + std::to_string(values.size()) + " values for " +
                                std::to_string(nodes.size()) + " nodes (2 per node)");
  for (const std::int64_t n : nodes)
    if (n < 0 || n >= nn_ || !(mesh_.tags[static_cast<std::size_t>(n)] & cfg_.dirichlet_tags))
      throw std::invalid_argument("flow: set_node_velocity: node " + std::to_string(n) + " is not a Dirichlet velocity node");
  node_velocity_nodes_ = nodes;
  node_velocity_values_ = values;
}

inline void NavierStokes2D::set_time_state(const TimeState& s) {
  if (s.u.size() != u_host_.size() || s.u_prev.size() != u_host_.size() || s.u_prev2.size() != u_host_.size())
    throw std::invalid_argument("flow: set_time_state got a state of another size");
  u_host_ = s.u;
  u_prev_ = s.u_prev;
  u_prev2_ = s.u_prev2;
  time_ = s.time;
  last_dt_ = s.last_dt;
  steps_ = s.steps;
}

}  // namespace polymech::flow
