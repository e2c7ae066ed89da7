// Material data of the piezoelectric harvester (issue 35; seed 002 paper 1, the duToit & Wardle 2007
// cantilever): PZT-5A and PZT-5H (poled along x3, transversely isotropic, class 6mm), the brass host, and the
// PVDF of the Hwang & Park (1993) static bimorph. Plain C++17, no Kokkos: the analytic side that the
// finite-element results are verified against, and the source of the constants the FE model uses.
//
// Storage. A piezoceramic is stored by its strain-charge data as the manufacturers and the tables give them:
// the compliance at constant field s^E, the charge constants d and the permittivity at constant stress eps^T.
// Everything the stress-charge law of paper 1 eq. (6) needs is DERIVED from them, so the set is consistent
// by construction (the published c^E and e tables are rounded and disagree with the inverted s^E by up to 1 %):
//   C^E   = (s^E)^-1                     (6x6, Voigt order 11,22,33,23,13,12, engineering shear strains)
//   e     = d C^E                        (3x6, C/m^2)
//   eps^S = eps^T - d C^E d^T            (3x3, F/m)
// The plane-stress reduced constants of a thin layer in a beam (sigma_2 = sigma_3 = 0; Erturk & Inman 2009,
// Smart Mater. Struct. 18 025009, section 2 and Table 1; Erturk & Inman 2011, "Piezoelectric Energy
// Harvesting", Wiley, appendix A):
//   c11_bar = 1 / s11^E,   e31_bar = d31 / s11^E,   eps33_bar = eps33^T - d31^2 / s11^E.
//
// PZT-5A: the Berlincourt (Vernitron / Morgan Electro Ceramics) table, the values of the IEEE-standard-style
// tables reproduced by Erturk & Inman 2011 (appendix E) and used in Erturk & Inman 2009 for their PZT-5A
// bimorph (c11_bar 61 GPa, e31_bar -10.4 C/m^2, eps33_bar 13.3 nF/m, rho 7750 kg/m^3):
//   s^E [1e-12 m^2/N]: s11 16.4, s12 -5.74, s13 -7.22, s33 18.8, s44 = s55 47.5, s66 = 2 (s11 - s12) 44.3
//   d [1e-12 C/N]: d31 -171, d33 374, d15 584;  eps^T / eps0: eps11 1730, eps33 1700;  rho 7750 kg/m^3.
// The published stiffness-form values (checked against the derived ones in tests/piezo): c11 12.1, c12 7.54,
// c13 7.52, c33 11.1, c44 2.11, c66 2.26 [1e10 Pa]; e31 -5.4, e33 15.8, e15 12.3 C/m^2; eps^S/eps0 916, 830.
// PZT-5H (the Erturk & Inman 2009 bimorph without tip mass): s11^E 16.5e-12, d31 -274e-12, eps33^T 3400
// eps0, the reduced constants c11_bar 60.6 GPa, e31_bar -16.6 C/m^2, eps33_bar 25.55 nF/m as in their Table 1;
// the other 5H entries are not needed by the beam model and are not stored.
#pragma once

#include <array>
#include <cmath>
#include <utility>

namespace polymech::piezo {

inline constexpr double kEps0 = 8.8541878128e-12;  // vacuum permittivity [F/m] (CODATA 2018)

using Matrix6 = std::array<std::array<double, 6>, 6>;
using Matrix36 = std::array<std::array<double, 6>, 3>;
using Matrix3 = std::array<std::array<double, 3>, 3>;

// Inverse of a symmetric positive definite 6x6 matrix (Gauss-Jordan with partial pivoting; set-up only).
inline Matrix6 invert6(Matrix6 a) {
  Matrix6 inv{};
  for (int i = 0; i < 6; ++i) inv[i][i] = 1.0;
  for (int c = 0; c < 6; ++c) {
    int p = c;
    for (int r = c + 1; r < 6; ++r)
      if (std::fabs(a[r][c]) > std::fabs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    std::swap(inv[c], inv[p]);
    const double s = 1.0 / a[c][c];
    for (int j = 0; j < 6; ++j) {
      a[c][j] *= s;
      inv[c][j] *= s;
    }
    for (int r = 0; r < 6; ++r) {
      if (r == c) continue;
      const double f = a[r][c];
      if (f == 0.0) continue;
      for (int j = 0; j < 6; ++j) {
        a[r][j] -= f * a[c][j];
        inv[r][j] -= f * inv[c][j];
      }
    }
  }
  return inv;
}

// A transversely isotropic piezoceramic poled along x3 (crystal class 6mm), by its strain-charge data.
struct PiezoCeramic {
  double s11E, s12E, s13E, s33E, s44E;  // compliance at constant E [m^2/N]; s55 = s44, s66 = 2 (s11 - s12)
  double d31, d33, d15;                 // charge constants [C/N]
  double eps11T, eps33T;                // permittivity at constant stress [F/m]
  double rho;                           // density [kg/m^3]

  Matrix6 compliance_E() const {
    Matrix6 s{};
    s[0][0] = s[1][1] = s11E;
    s[0][1] = s[1][0] = s12E;
    s[0][2] = s[2][0] = s[1][2] = s[2][1] = s13E;
    s[2][2] = s33E;
    s[3][3] = s[4][4] = s44E;
    s[5][5] = 2.0 * (s11E - s12E);
    return s;
  }
  // d as a 3x6 matrix (D_i = d_iJ T_J + eps^T_ik E_k, Voigt J, engineering shear).
  Matrix36 d_matrix() const {
    Matrix36 d{};
    d[2][0] = d[2][1] = d31;
    d[2][2] = d33;
    d[0][4] = d[1][3] = d15;  // d15 couples E1 with the 13 shear (slot 4), d24 = d15 E2 with 23 (slot 3)
    return d;
  }
  Matrix6 stiffness_E() const { return invert6(compliance_E()); }
  // e = d C^E [C/m^2]: the stress-charge law T = C^E S - e^T E, D = e S + eps^S E (paper 1 eq. (6)).
  Matrix36 e_matrix() const {
    const Matrix6 C = stiffness_E();
    const Matrix36 d = d_matrix();
    Matrix36 e{};
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 6; ++J)
        for (int K = 0; K < 6; ++K) e[i][J] += d[i][K] * C[K][J];
    return e;
  }
  // eps^S = eps^T - d C^E d^T [F/m] (clamped permittivity).
  Matrix3 eps_S() const {
    const Matrix6 C = stiffness_E();
    const Matrix36 d = d_matrix();
    Matrix3 eps{};
    eps[0][0] = eps[1][1] = eps11T;
    eps[2][2] = eps33T;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        for (int J = 0; J < 6; ++J)
          for (int K = 0; K < 6; ++K) eps[i][k] -= d[i][J] * C[J][K] * d[k][K];
    return eps;
  }
  // Plane-stress reduced constants of a layer in a beam (Erturk & Inman 2009 section 2).
  double c11_bar() const { return 1.0 / s11E; }
  double e31_bar() const { return d31 / s11E; }
  double eps33_bar() const { return eps33T - d31 * d31 / s11E; }
};

// PZT-5A, Berlincourt table (see the header comment for the source and the published stiffness form).
inline PiezoCeramic pzt5a() {
  PiezoCeramic m{};
  m.s11E = 16.4e-12;
  m.s12E = -5.74e-12;
  m.s13E = -7.22e-12;
  m.s33E = 18.8e-12;
  m.s44E = 47.5e-12;
  m.d31 = -171e-12;
  m.d33 = 374e-12;
  m.d15 = 584e-12;
  m.eps11T = 1730.0 * kEps0;
  m.eps33T = 1700.0 * kEps0;
  m.rho = 7750.0;
  return m;
}

// The published stiffness-form PZT-5A entries (Berlincourt; rounded), only to check the derived ones.
struct PublishedStiffnessForm {
  double c11, c12, c13, c33, c44, c66;  // [Pa]
  double e31, e33, e15;                 // [C/m^2]
  double eps11S, eps33S;                // [F/m]
};
inline PublishedStiffnessForm pzt5a_published_stiffness_form() {
  return {12.1e10, 7.54e10, 7.52e10, 11.1e10, 2.11e10, 2.26e10, -5.4, 15.8, 12.3, 916.0 * kEps0, 830.0 * kEps0};
}

// Plane-stress reduced data of one piezoelectric layer in a beam, and its density.
struct ReducedPiezo {
  double c11;    // c11_bar = 1/s11^E [Pa]
  double e31;    // e31_bar = d31/s11^E [C/m^2]
  double eps33;  // eps33_bar = eps33^T - d31^2/s11^E [F/m]
  double rho;    // [kg/m^3]
};
inline ReducedPiezo reduce(const PiezoCeramic& m) { return {m.c11_bar(), m.e31_bar(), m.eps33_bar(), m.rho}; }

// PZT-5H as in Erturk & Inman 2009 Table 1 (their bimorph without tip mass): c11_bar 60.6 GPa,
// e31_bar -16.6 C/m^2, eps33_bar 25.55 nF/m (= 3400 eps0 - d31^2/s11E with d31 -274 pm/V, s11E 16.5e-12),
// rho 7500 kg/m^3.
inline ReducedPiezo pzt5h_erturk_inman_2009() { return {60.6e9, -16.6, 25.55e-9, 7500.0}; }

// An isotropic elastic layer (the host).
struct IsotropicElastic {
  double E, nu, rho;  // [Pa], [-], [kg/m^3]
};
// Brass of the commercial (Piezo Systems) bimorph shims, as in Erturk & Inman 2009 Table 1: Y = 105 GPa,
// rho = 9000 kg/m^3; nu = 0.34 (handbook value for cartridge brass C26000; the beam model does not use it,
// the 3D FE model does).
inline IsotropicElastic brass() { return {105e9, 0.34, 9000.0}; }

// The PVDF of the static bimorph benchmark (Tzou & Tseng 1990; Hwang & Park 1993, AIAA J. 31(5) 930):
// E = 2 GPa, nu = 0.29, d31 = d32 = 2.2e-11 C/N, relative permittivity 12 (read as eps33^T: the free
// permittivity; the coupling is weak, d31^2 E / eps = 0.9 %, so the clamped/free distinction is below 1 %).
struct Pvdf {
  double E = 2e9, nu = 0.29, d31 = 2.2e-11, eps_r = 12.0;
  double rho = 1780.0;  // [kg/m^3] (a handbook value for PVDF; the static bender does not use it)
  double eps33T() const { return eps_r * kEps0; }
  double eps33_bar() const { return eps33T() - d31 * d31 * E; }
};

}  // namespace polymech::piezo
