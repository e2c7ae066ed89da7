// The section of the tyre 37x12.5R16.5 (seed 002 paper 2 §4; issue 37): its dimensions, wall gauges, laws' constants
// and belt options (TyreSpec), and the inner contour's three arcs per half (TyreSection, tyre_section). Free of
// Kokkos, so scene readers can check a section before a model is built; the lattice, the laws per cell and the
// plate are in solid/tyre.hpp (whose header describes the section's geometry).
#pragma once

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace polymech::solid {

struct TyreSpec {
  double outer_radius = 0.445;   // paper 2 §4
  double width = 0.310;          // paper 2 §4 (section width)
  double rim_radius = 0.2096;    // 16.5 in / 2
  double rim_width = 0.2096;     // 8.25 in: the 16.5x8.25 rim of this size (bead heels at +-rim_width / 2)
  double tread_gauge = 0.020;    // h_t: carcass + belts + smooth tread over the crown (assumed, light-truck tyres)
  double wall_gauge = 0.012;     // h_w: sidewall (assumed, light-truck tyres 10-15 mm)
  double crown_radius = 0.35;    // R_t: the tread arc of the inner contour (assumed)
  double tread_half_width = 0.100;  // inner tread arc's half width (assumed: ~ 2/3 of the section)
  // Rubber (Mooney-Rivlin), the carcass plies, the composite's density and compressibility.
  double C10 = 0.8e6, C01 = 0.2e6;     // Pa: tyre rubber (Pa); E_rubber = 6 (C10 + C01)
  double cord_modulus = 4.0e9;          // Pa: polyester cord (carcass)
  double cord_fraction = 0.3;           // V_f in a ply
  double ply_thickness = 1.0e-3;        // m
  int plies = 2;                        // radial carcass plies
  double kappa_ratio = 10.0;            // kappa / mu_eq (nu = 0.45)
  double mass = 37.6;                   // kg: the tyre's mass; the density follows from the volume
  // The wall's law: false, the one smeared law (tyre_equivalent_law) in every element; true, layers through the
  // wall (tyre_layers: rubber, the cord layer in the middle cell, rubber; needs an odd n_wall >= 3).
  bool layered = false;
  // The steel belt over the crown (issue 37; paper 2 §4 names "belt reinforcements"): with belted (needs layered),
  // the cell layer just outside the cord layer (k = n_wall / 2 + 1, toward the tread) becomes the belt layer in the
  // crown cells, E = E_rubber + f E_belt t_belt / h_c (tyre_layers). Values assumed (light-truck / off-road radial
  // tyres; no data sheet of this tyre): two steel-cord plies at +-20 deg to the circumference, steel cord E 200 GPa,
  // cord volume fraction 0.25 in a ply, 1.2 mm per ply, the belt 0.18 m wide along the contour (the inner tread arc
  // is 0.203 m: a belt a little narrower than the tread).
  bool belted = false;
  double belt_modulus = 200.0e9;      // Pa: steel cord
  double belt_fraction = 0.25;        // V_f in a belt ply
  double belt_ply_thickness = 1.2e-3; // m
  int belt_plies = 2;                 // crossed plies, +-belt_angle
  double belt_angle_deg = 20.0;       // cord angle to the circumferential direction
  double belt_half_width = 0.090;     // m, along the contour from the crown's centre line
  // The reading of the +-20 deg plies as one isotropic modulus (the Mooney-Rivlin law is isotropic): false (the
  // default), the laminate's circumferential membrane modulus with the lateral strain held (A11 / t: the belt
  // stretched round the wheel between the tread and the inflated carcass; 39 GPa), which makes the layer as stiff
  // across the crown as round it (a real +-20 deg belt is ~ 56 x softer across, A22 / t = 0.69 GPa); true, the
  // free laminate's E_x = (A11 - A12^2 / A22) / t (lateral stress zero: the plies scissor; 0.42 GPa).
  bool belt_laterally_free = false;
  // The third reading (issue 37; seed 002 paper 2 §4, the belt reinforcements): rebar. With belt_rebar the belt
  // layer's cells keep the rubber's law (the layered wall's scale) and carry two steel-cord families at
  // +-belt_angle_deg to the circumferential direction in the cell's tangent plane (Hyperelastic::set_fibres: each a
  // fibre stress along its cord, S_f = k E_a a (x) a), so the layer is stiff round the wheel (2 k cos^4 beta), soft
  // across (2 k sin^4 beta, 57 x less at 20 deg) and scissors as crossed plies do (held by the rubber and the
  // carcass layer below). belt_laterally_free is ignored. belt_tension_only: cords carry no compression.
  bool belt_rebar = false;
  bool belt_tension_only = false;
};

// The inner contour's half (the y > 0 side) from the centre line: three arcs (radius, turning angle).
struct TyreSection {
  double r_top = 0.0;                       // inner crown radius
  std::array<double, 3> radius{}, angle{};  // tread, shoulder, sidewall arcs
  double half_length = 0.0;
  double widest_r = 0.0, widest_a = 0.0;    // the inner contour's widest point
  double tread_gauge = 0.0, wall_gauge = 0.0;

  // Inner point (a, r), the unit outward normal (n_a, n_r) and the gauge at arc length sigma >= 0 from the crown.
  void at(double sigma, double* p, double* n, double& h) const {
    double a = 0.0, r = r_top, phi = 0.0, left = sigma;
    for (int k = 0; k < 3; ++k) {
      const double len = radius[k] * angle[k];
      const double d = k == 2 ? left : std::fmin(left, len);
      const double dphi = d / radius[k];
      a += radius[k] * (std::sin(phi + dphi) - std::sin(phi));
      r += radius[k] * (std::cos(phi + dphi) - std::cos(phi));
      if (k == 1) {  // the gauge blends over the shoulder arc
        const double f = 0.5 * (1.0 - std::cos(3.14159265358979323846 * std::fmin(1.0, d / len)));
        h = tread_gauge + (wall_gauge - tread_gauge) * f;
      } else if (k == 0) {
        h = tread_gauge;
      }
      phi += dphi;
      left -= d;
      if (left <= 0.0) break;
    }
    if (sigma > radius[0] * angle[0] + radius[1] * angle[1]) h = wall_gauge;
    p[0] = a;
    p[1] = r;
    n[0] = std::sin(phi);  // heading (cos phi, -sin phi) in (a, r), turned outward
    n[1] = std::cos(phi);
  }
};

inline TyreSection tyre_section(const TyreSpec& s) {
  TyreSection c;
  c.tread_gauge = s.tread_gauge;
  c.wall_gauge = s.wall_gauge;
  c.r_top = s.outer_radius - s.tread_gauge;
  const double Wi = 0.5 * s.width - s.wall_gauge;  // inner half width at the widest point
  if (!(s.crown_radius > s.tread_half_width))
    throw std::invalid_argument("solid::tyre_section: the crown radius R_t = " + std::to_string(s.crown_radius) +
                                " m must exceed the tread's half width " + std::to_string(s.tread_half_width) + " m");
  const double Rt = s.crown_radius, at = std::asin(s.tread_half_width / Rt);
  const double Rs = (Wi - Rt * std::sin(at)) / (1.0 - std::sin(at));
  if (!(Rs > s.tread_gauge) || !(Wi > 0.5 * s.rim_width))
    throw std::invalid_argument("solid::tyre_section: the tread, the width and the gauges leave no shoulder arc (R_s = " +
                                std::to_string(Rs) + " m)");
  const double r2 = c.r_top - Rt * (1.0 - std::cos(at)) - Rs * std::cos(at);
  const double da = Wi - 0.5 * s.rim_width, dr = r2 - s.rim_radius;
  if (!(dr > 0.0)) throw std::invalid_argument("solid::tyre_section: the widest point lies below the rim");
  const double aw = 2.0 * std::atan(da / dr), Rw = dr / std::sin(aw);
  c.radius = {Rt, Rs, Rw};
  c.angle = {at, 0.5 * 3.14159265358979323846 - at, aw};
  c.half_length = Rt * at + Rs * c.angle[1] + Rw * aw;
  c.widest_r = r2;
  c.widest_a = Wi;
  return c;
}

}  // namespace polymech::solid
