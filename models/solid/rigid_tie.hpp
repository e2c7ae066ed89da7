// Nodes tied to a rigid body (issue 34: "nodes tied to a rigid body"; issue 37: the tyre's rim is a rigid body
// carrying the load, the speed and the slip): the tie's description (RigidTie) and the body's state (TieState)
// of solid::HyperelasticExplicit (models/solid/finite_strain_explicit.hpp).
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

#include <array>
#include <functional>
#include <string>

namespace polymech::solid {

// Nodes of a named side tied to a rigid body (see the header).
template <int D>
struct RigidTie {
  static constexpr int dofs = D + 1;  // D translations and the rotation about `axis`
  std::string boundary;
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // 3D: the rotation axis (normalised here); 2D: z
  double mass = 0.0;     // the body's own mass (the tied nodes' lumped mass is added)
  double inertia = 0.0;  // its own moment of inertia about the axis through the reference point
  // Per body DoF (x, y, (z), rotation): a prescribed velocity of time, or empty (free).
  std::array<std::function<double(double)>, D + 1> velocity;
  // Per free body DoF: the applied force (torque) as a function of time; empty: none.
  std::array<std::function<double(double)>, D + 1> load;
  // Per free body DoF: a dashpot to the ground, -damping x the DoF's half-step velocity (N s/m; N m s about the
  // axis); 0: none (the tyre's rim: the carriage's vertical damper, dem::WheelSpec::damping).
  std::array<double, D + 1> damping{};
};

// The body's state (host): the reference point, the rotation, their rates, the forces of the last evaluation.
template <int D>
struct TieState {
  std::array<double, D> position{}, velocity{};
  double angle = 0.0, omega = 0.0;
  std::array<double, D + 1> force{};        // the structure's force (torque) on the body, plus the applied loads
  std::array<double, D + 1> drive_force{};  // what the driver of each prescribed DoF applies (0 on free DoFs)
};

}  // namespace polymech::solid
