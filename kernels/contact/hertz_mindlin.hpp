// Hertz-Mindlin contact with viscous damping and a Coulomb limit (seed 002 paper 2, eqs. (11)-(17)),
// in the form docs/METHODS.md derives (the printed eqs. (15) and (17) are not used as printed):
//
//   E* = 1 / ((1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j)      G* = 1 / ((2 - nu_i)/G_i + (2 - nu_j)/G_j)
//   R* = R_i R_j / (R_i + R_j)    m* = m_i m_j / (m_i + m_j)    (a rigid wall: 1/E_j = 0, m_j = inf, R_j = inf)
//   a  = sqrt(R* delta)           S_n = 2 E* a    S_t = 8 G* a   (Mindlin; eq. (15) prints 16/3 and (1 - nu))
//   F_n = (4/3 E* a) delta  - 2 sqrt(5/6) beta sqrt(S_n m*) v_n        eq. (12): k_n h + gamma_n v_n
//   F_t = -S_t xi           + 2 sqrt(5/6) beta sqrt(S_t m*) v_t        eq. (13): k_t sigma + gamma_t v_t
//   |F_t| <= mu F_n (eq. (14)): on slip F_t is scaled to mu F_n and the spring xi to -F_t / S_t.
//   beta (<= 0) from the restitution e: eq. (17)'s gamma = -zeta m* with zeta = -2 sqrt(5/6) beta sqrt(S / m*);
//   damping_ratio() is the linear spring's ln e / sqrt(ln^2 e + pi^2), the models use the Hertz-calibrated
//   contact::hertz_damping_ratio (kernels/contact/damping.hpp).
// Shared by the DEM (spheres, clumps, FE facets) and the ISPH rigid body against the tank (a disc of unit
// thickness, docs/METHODS.md).
//
// Conventions: n is the unit normal pointing from the partner (sphere j, plane, facet) to sphere i,
// delta > 0 the overlap, v_rel the velocity of i's contact point minus the partner's; v_n = v_rel . n
// (< 0 approaching). The force returned acts on i; the partner gets its negative. F_n is clamped at 0
// (no attraction in the damped recoil). xi is the tangential spring (eq. (13)'s sigma), kept per contact
// in a contact::PairHistory across list rebuilds and rotated into the current tangent plane each step.
#pragma once

#include <cmath>

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::contact {

inline constexpr double kPi = 3.14159265358979323846;

// The constants of one kind of contact (sphere-sphere of one material, sphere-wall).
template <class T>
struct HertzMindlin {
  T e_star = T(0);  // effective Young's modulus E*
  T g_star = T(0);  // effective shear modulus G*
  T beta = T(0);    // damping ratio from the restitution coefficient (0: no damping)
  T mu = T(0);      // Coulomb friction coefficient (friction off: tangential force not computed)
};

// E* of two materials; E_j <= 0 stands for a rigid partner (1/E_j = 0).
KOKKOS_INLINE_FUNCTION double effective_modulus(double e_i, double nu_i, double e_j, double nu_j) {
  const double c = (1.0 - nu_i * nu_i) / e_i + (e_j > 0.0 ? (1.0 - nu_j * nu_j) / e_j : 0.0);
  return 1.0 / c;
}
// G* of two materials (Mindlin): 1 / ((2 - nu_i)/G_i + (2 - nu_j)/G_j), G = E / (2 (1 + nu)) (eq. (16)).
KOKKOS_INLINE_FUNCTION double effective_shear_modulus(double e_i, double nu_i, double e_j, double nu_j) {
  const double g_i = e_i / (2.0 * (1.0 + nu_i));
  const double c = (2.0 - nu_i) / g_i + (e_j > 0.0 ? (2.0 - nu_j) / (e_j / (2.0 * (1.0 + nu_j))) : 0.0);
  return 1.0 / c;
}
// beta of a coefficient of restitution e in (0, 1]: ln e / sqrt(ln^2 e + pi^2); 0 for e = 1.
inline double damping_ratio(double restitution) {
  const double l = std::log(restitution);
  return l / std::sqrt(l * l + kPi * kPi);
}

// Closed forms of an undamped, frictionless Hertz impact at approach speed v (Johnson 1985, 11.2):
// the largest overlap, the largest force and the contact time 2.87 (m*^2 / (R* E*^2 v))^(1/5).
inline double hertz_max_overlap(double m_star, double r_star, double e_star, double v) {
  return std::pow(15.0 * m_star * v * v / (16.0 * e_star * std::sqrt(r_star)), 0.4);
}
inline double hertz_max_force(double m_star, double r_star, double e_star, double v) {
  return 4.0 / 3.0 * e_star * std::sqrt(r_star) * std::pow(hertz_max_overlap(m_star, r_star, e_star, v), 1.5);
}
inline double hertz_contact_time(double m_star, double r_star, double e_star, double v) {
  return 2.87 * std::pow(m_star * m_star / (r_star * e_star * e_star * v), 0.2);
}
// The Rayleigh time step of a sphere: pi R sqrt(rho / G) / (0.1631 nu + 0.8766) (the time a Rayleigh
// wave takes across the sphere; DEM codes step at a fraction of it).
inline double rayleigh_time_step(double radius, double density, double e, double nu) {
  const double g = e / (2.0 * (1.0 + nu));
  return kPi * radius * std::sqrt(density / g) / (0.1631 * nu + 0.8766);
}

// What one contact gives: the force on sphere i (normal + tangential) and its normal part.
template <class T>
struct ContactForce {
  Vec3<T> force;
  T normal;  // F_n (>= 0)
};

// sqrt(4 G* / E*) = sqrt(S_t / S_n), a constant of the law (0 for E* = 0): a kernel over many contacts
// takes it once and passes it to the overload below (a division and a square root less per contact).
template <class T>
KOKKOS_INLINE_FUNCTION T shear_root_ratio(const HertzMindlin<T>& p) {
  return p.e_star > T(0) ? kx::sqrt(T(4) * p.g_star / p.e_star) : T(0);
}
template <class T>
KOKKOS_FORCEINLINE_FUNCTION ContactForce<T> hertz_mindlin_force(const HertzMindlin<T>& p, T root_ratio, T r_star, T m_star,
                                                           T delta, const Vec3<T>& n, const Vec3<T>& v_rel, bool friction,
                                                           T dt, Vec3<T>& xi);

// The force on sphere i of one contact (eqs. (11)-(14)); updates the tangential spring xi when
// `friction` (with the step dt). r_star, m_star: of this pair.
// Cost (the DEM step's hottest function, docs/PERFORMANCE.md "DEM: the step against LIGGGHTS"): a
// sticking contact takes three square roots on its chain (a, sqrt(S_n m*), the spring's rescaling):
// sqrt(S_t m*) = sqrt(S_n m*) sqrt(4 G* / E*) (S_t / S_n = 4 G* / E*, a constant of the law), the rotated
// spring is rescaled by sqrt(len0^2 / len1^2), and |F_t| is used only when it slips (|F_t|^2 > (mu F_n)^2).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION ContactForce<T> hertz_mindlin_force(const HertzMindlin<T>& p, T r_star, T m_star, T delta,
                                                           const Vec3<T>& n, const Vec3<T>& v_rel, bool friction,
                                                           T dt, Vec3<T>& xi) {
  return hertz_mindlin_force(p, shear_root_ratio(p), r_star, m_star, delta, n, v_rel, friction, dt, xi);
}
// The same with root_ratio = shear_root_ratio(p) given (the same bits).
template <class T>
KOKKOS_FORCEINLINE_FUNCTION ContactForce<T> hertz_mindlin_force(const HertzMindlin<T>& p, T root_ratio, T r_star, T m_star,
                                                           T delta, const Vec3<T>& n, const Vec3<T>& v_rel, bool friction,
                                                           T dt, Vec3<T>& xi) {
  ContactForce<T> out;
  const T a = kx::sqrt(r_star * delta);
  const T s_n = T(2) * p.e_star * a;
  const T damp = T(-2) * T(0.9128709291752769) * p.beta;  // -2 sqrt(5/6) beta >= 0
  const T v_n = dot(v_rel, n);
  const T root_n = kx::sqrt(s_n * m_star);  // sqrt(S_n m*)
  // eq. (12): k_n h with k_n = 4/3 E* sqrt(R* h), plus the viscous part gamma_n v_n
  T f_n = T(4) / T(3) * p.e_star * a * delta - damp * root_n * v_n;
  f_n = f_n > T(0) ? f_n : T(0);
  out.normal = f_n;
  out.force = f_n * n;
  if (!friction) return out;
  const Vec3<T> v_t = v_rel - v_n * n;
  // Branch-free (selects, no jumps: the host's rows run this over a batch of pairs as one vector loop,
  // kernels/dem/contact_forces.hpp; a GPU's threads do not diverge). Each select picks between values computed
  // as the branches would: the results are the branches'. Denominators that a branch would not reach are 1.
  // The spring of the previous step, rotated into the current tangent plane, its length kept (a zero spring
  // stays zero: its projection is itself).
  const T len0_2 = norm2(xi);
  const Vec3<T> xr = xi - dot(xi, n) * n;
  const T len1_2 = norm2(xr);
  const T keep = len1_2 > T(0) ? kx::sqrt(len0_2 / (len1_2 > T(0) ? len1_2 : T(1))) : T(1);
  xi = keep * xr;
  xi += dt * v_t;
  const T s_t = T(8) * p.g_star * a;
  const T root_t = root_n * root_ratio;  // sqrt(S_t m*)
  Vec3<T> f_t = -s_t * xi - damp * root_t * v_t;  // eq. (13)
  const T ft2 = norm2(f_t), limit = p.mu * f_n;
  // eq. (14): Coulomb slip (|F_t| > mu F_n, so |F_t| > 0): F_t scaled to the limit, the spring keeps what the limit allows
  const bool slip = ft2 > limit * limit;
  const T scale = slip ? limit / kx::sqrt(slip ? ft2 : T(1)) : T(1);
  const T back = s_t > T(0) ? T(-1) / (s_t > T(0) ? s_t : T(1)) : T(0);
  for (int q = 0; q < 3; ++q) {
    f_t[q] = scale * f_t[q];
    xi[q] = slip ? back * f_t[q] : xi[q];
  }
  out.force += f_t;
  return out;
}

}  // namespace polymech::contact
