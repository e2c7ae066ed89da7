// The rigid ties of solid::HyperelasticExplicit (issue 34: "nodes tied to a rigid body"; issue 37: the tyre's
// rim): the members that set up the bodies, place the tied nodes from a body's pose, gather the structure's
// force and moment on a body and report the drivers' forces. The tie and its state: models/solid/rigid_tie.hpp;
// the model: models/solid/hyperelastic_explicit.hpp (include models/solid/finite_strain_explicit.hpp).
//
// Rigid tie (RigidTie): the nodes of a named side follow a rigid body whose degrees of freedom are the D
// translations of its reference point c (the tied nodes' centre of mass c_0 at the start) and one rotation theta
// about a fixed axis n through it (2D: z; 3D: given):
//   x_i = c + R_n(theta) (X_i - c_0),  v_i = V + omega n x (x_i - c).
// Each body DoF is either prescribed (a velocity function of time: the tyre's speed and slip) or free (driven by
// an applied force or torque function: the tyre's vertical load). The tied nodes' lumped masses join the body
// (M_b = m_own + sum m_i, I_b = I_own + sum m_i |n x (X_i - c_0)|^2, constant under the rotation), and the
// structure's force on the body is the sum of -r over the tied DoFs (with its moment about c): so the momentum
// exchanged between the solid and the body is exact, and the body is kicked and drifted with the same Verlet
// halves (with c at the tied nodes' centre of mass, translation and rotation do not couple through the mass).
// What the driver of a prescribed DoF must apply is reported
// (drive_force: M_b A - F along it), as the tyre's tractive force and torque are.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "solid/explicit_dynamics.hpp"
#include "solid/hyperelastic_explicit.hpp"
#include "solid/rigid_tie.hpp"

namespace polymech::solid {

template <class T, int D>
inline double HyperelasticExplicit<T, D>::acceleration(std::size_t k, int q) const {
  const double m = q < D ? body_[k].mass : body_[k].inertia;
  return m > 0.0 ? state_[k].force[static_cast<std::size_t>(q)] / m : 0.0;
}

// The driver's force on each prescribed DoF: M_b A - F with A the prescribed acceleration (differenced).
template <class T, int D>
inline void HyperelasticExplicit<T, D>::drive_forces(std::size_t k, double t) {
  TieState<D>& s = state_[k];
  for (int q = 0; q <= D; ++q) {
    const auto& pv = ties_[k].velocity[static_cast<std::size_t>(q)];
    if (!pv) {
      s.drive_force[static_cast<std::size_t>(q)] = 0.0;
      continue;
    }
    const double e = 1e-3 * dt_ > 0.0 ? 1e-3 * dt_ : 1e-9;
    const double A = (pv(t + e) - pv(t - e)) / (2.0 * e);
    const double m = q < D ? body_[k].mass : body_[k].inertia;
    s.drive_force[static_cast<std::size_t>(q)] = m * A - s.force[static_cast<std::size_t>(q)];
  }
}

// Rotation of a body-fixed offset by theta about the axis (Rodrigues; 2D: about z).
template <class T, int D>
inline void HyperelasticExplicit<T, D>::rotate(const std::array<double, 3>& n, double theta, const double* x, double* y) {
  const double c = std::cos(theta), s = std::sin(theta);
  if (D == 2) {
    y[0] = c * x[0] - s * x[1];
    y[1] = s * x[0] + c * x[1];
    return;
  }
  const double nx = n[0] * x[0] + n[1] * x[1] + n[2] * x[2];
  const double cr[3] = {n[1] * x[2] - n[2] * x[1], n[2] * x[0] - n[0] * x[2], n[0] * x[1] - n[1] * x[0]};
  for (int d = 0; d < 3; ++d) y[d] = c * x[d] + s * cr[d] + (1.0 - c) * nx * n[static_cast<std::size_t>(d)];
}

// The tied nodes' displacement (and with velocities, velocity) from the body's pose.
template <class T, int D>
inline void HyperelasticExplicit<T, D>::place_tied(std::size_t k, bool velocities) {
  const Body& b = body_[k];
  const TieState<D>& s = state_[k];
  TiedPose pose;
  pose.ct = std::cos(s.angle);
  pose.st = std::sin(s.angle);
  pose.n0 = b.axis[0];
  pose.n1 = b.axis[1];
  pose.n2 = b.axis[2];
  for (int d = 0; d < D; ++d) {
    pose.c[d] = s.position[static_cast<std::size_t>(d)];
    pose.c0[d] = b.centre[static_cast<std::size_t>(d)];
    pose.V[d] = s.velocity[static_cast<std::size_t>(d)];
  }
  pose.w = s.omega;
  explicit_place_tied<T, D>(b.node_view, b.offsets, pose, velocities, u_, v_);
}

// The structure's force on body k: sum of -r over the tied DoFs, and its moment about c; plus the applied loads.
template <class T, int D>
inline void HyperelasticExplicit<T, D>::body_force(std::size_t k, double t) {
  Body& b = body_[k];
  explicit_gather_tied<T, D>(b.node_view, r_, b.gathered);
  const auto gh = Kokkos::create_mirror_view_and_copy(HostSpace(), b.gathered);
  const auto oh = Kokkos::create_mirror_view_and_copy(HostSpace(), b.offsets);
  TieState<D>& s = state_[k];
  std::array<double, D + 1> F{};
  for (std::size_t j = 0; j < b.nodes.size(); ++j) {
    double x[3] = {0, 0, 0}, y[3] = {0, 0, 0}, f[3] = {0, 0, 0};
    for (int d = 0; d < D; ++d) {
      x[d] = oh(j, d);
      f[d] = gh(j, d);
      F[static_cast<std::size_t>(d)] += f[d];
    }
    rotate(b.axis, s.angle, x, y);  // x_i - c
    if (D == 2)
      F[D] += y[0] * f[1] - y[1] * f[0];
    else
      F[D] += b.axis[0] * (y[1] * f[2] - y[2] * f[1]) + b.axis[1] * (y[2] * f[0] - y[0] * f[2]) +
              b.axis[2] * (y[0] * f[1] - y[1] * f[0]);
  }
  for (int q = 0; q <= D; ++q) {
    const auto& l = ties_[k].load[static_cast<std::size_t>(q)];
    if (ties_[k].velocity[static_cast<std::size_t>(q)]) continue;  // prescribed
    if (l) F[static_cast<std::size_t>(q)] += l(t);
    const double c = ties_[k].damping[static_cast<std::size_t>(q)];
    if (c > 0.0) F[static_cast<std::size_t>(q)] -= c * (q < D ? s.velocity[static_cast<std::size_t>(q)] : s.omega);
  }
  if (static_cast<int>(k) == o_.damping_frame && o_.damping > 0.0)  // the dashpots' reaction (frame_damping)
    for (int q = 0; q <= D; ++q) F[static_cast<std::size_t>(q)] += frame_force_[q];
  s.force = F;
}

// The damping relative to the frame body's rigid motion: its velocity (the half-step one of a free DoF, the
// prescribed one otherwise) and angular velocity omega n at its current pose (3D).
template <class T, int D>
inline void HyperelasticExplicit<T, D>::frame_damping() {
  const std::size_t k = static_cast<std::size_t>(o_.damping_frame);
  const TieState<D>& s = state_[k];
  DampingFrame f;
  for (int d = 0; d < D; ++d) {
    f.c[d] = s.position[static_cast<std::size_t>(d)];
    f.V[d] = s.velocity[static_cast<std::size_t>(d)];
    f.n[d] = body_[k].axis[static_cast<std::size_t>(d)];
    f.w[d] = s.omega * body_[k].axis[static_cast<std::size_t>(d)];
  }
  frame_force_ = explicit_frame_damping<T>(solid_.discretization().nodes, kind_, coordinates_, u_, v_, mass_, o_.damping, f, r_, frame_partials_);
}

// The bodies of the ties: their nodes, mass, centre of mass, inertia about the axis and the tied offsets.
template <class T, int D>
inline void HyperelasticExplicit<T, D>::set_up_ties() {
  const auto& X = solid_.discretization().coordinates;
  for (std::size_t k = 0; k < ties_.size(); ++k) {
    const RigidTie<D>& tie = ties_[k];
    Body b;
    if (!(tie.mass >= 0.0) || !(tie.inertia >= 0.0))
      throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "': mass and inertia must be >= 0");
    // the nodes of one side, or of several joined by '+' (the tyre's rim: "ymin+ymax", both beads on one body)
    for (std::size_t from = 0; from <= tie.boundary.size();) {
      const std::size_t to = std::min(tie.boundary.find('+', from), tie.boundary.size());
      for (const std::int64_t v : side_nodes(solid_.discretization(), tie.boundary.substr(from, to - from)))
        if (std::find(b.nodes.begin(), b.nodes.end(), v) == b.nodes.end()) b.nodes.push_back(v);
      from = to + 1;
    }
    if (b.nodes.empty()) throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "' has no nodes");
    if (D == 3) {
      const double nn = std::sqrt(tie.axis[0] * tie.axis[0] + tie.axis[1] * tie.axis[1] + tie.axis[2] * tie.axis[2]);
      if (!(nn > 0.0)) throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary + "': the axis is zero");
      for (int d = 0; d < 3; ++d) b.axis[static_cast<std::size_t>(d)] = tie.axis[static_cast<std::size_t>(d)] / nn;
    }
    // mass, centre of mass of the tied nodes
    double m = 0.0, cm[3] = {0, 0, 0};
    for (const std::int64_t v : b.nodes)
      for (int d = 0; d < D; ++d) {
        const std::size_t i = static_cast<std::size_t>(D * v + d);
        if (kind_host_[i] != 0)
          throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary +
                                      "': a tied node is also constrained (a Dirichlet condition or another tie)");
        kind_host_[i] = 2;
        if (d == 0) m += mass_host_[i];
        cm[d] += mass_host_[i] * X[i];
      }
    for (int d = 0; d < D; ++d) b.centre[static_cast<std::size_t>(d)] = cm[d] / m;
    b.mass = tie.mass + m;
    const std::size_t nt = b.nodes.size();
    std::vector<double> off(nt * D);
    double I = tie.inertia;
    for (std::size_t j = 0; j < nt; ++j) {
      double y[3] = {0, 0, 0};
      for (int d = 0; d < D; ++d) y[d] = X[static_cast<std::size_t>(D * b.nodes[j] + d)] - b.centre[static_cast<std::size_t>(d)];
      for (int d = 0; d < D; ++d) off[j * D + static_cast<std::size_t>(d)] = y[d];
      double r2;
      if (D == 2) {
        r2 = y[0] * y[0] + y[1] * y[1];
      } else {
        const double ny = b.axis[0] * y[0] + b.axis[1] * y[1] + b.axis[2] * y[2];
        r2 = y[0] * y[0] + y[1] * y[1] + y[2] * y[2] - ny * ny;
      }
      I += mass_host_[static_cast<std::size_t>(D * b.nodes[j])] * r2;
    }
    b.inertia = I;
    for (int q = 0; q <= D; ++q) {
      const bool free = !tie.velocity[static_cast<std::size_t>(q)];
      if (free && !((q < D ? b.mass : b.inertia) > 0.0))
        throw std::invalid_argument("solid::HyperelasticExplicit: rigid tie '" + tie.boundary +
                                    "': a free degree of freedom without mass or inertia");
    }
    b.node_view = Kokkos::View<Index*, MemSpace>("polymech::solid::fse_tied_nodes", nt);
    b.offsets = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::fse_tied_offsets", nt, D);
    b.gathered = Kokkos::View<T**, Kokkos::LayoutRight, MemSpace>("polymech::solid::fse_tied_forces", nt, D);
    auto nh = Kokkos::create_mirror_view(b.node_view);
    auto oh = Kokkos::create_mirror_view(b.offsets);
    for (std::size_t j = 0; j < nt; ++j) {
      nh(j) = static_cast<Index>(b.nodes[j]);
      for (int d = 0; d < D; ++d) oh(j, d) = off[j * D + static_cast<std::size_t>(d)];
    }
    Kokkos::deep_copy(b.node_view, nh);
    Kokkos::deep_copy(b.offsets, oh);
    body_.push_back(b);
  }
  state_.assign(ties_.size(), TieState<D>{});
}

}  // namespace polymech::solid
