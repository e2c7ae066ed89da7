// The linear piezoelectric law of the finite-element harvester in the model's axes (issue 35; seed 002 paper 1
// eq. (6), stress-charge form):
//   T = C^E S - e^T E,   D = e S + eps^S E,   E = -grad phi,
// with the 3D data derived from the strain-charge tables (models/piezo/materials.hpp) and reduced here to what
// an element of dimension D reads.
//
// Axes. The beam's length is model x. In 3D the model axes are the material axes (x = 1 length, y = 2 width,
// z = 3 thickness and poling). In 2D the model plane is (length, thickness): model x = material 1, model y =
// material 3; the width (material 2) is out of plane.
//   plane stress (a narrow beam, T2 = 0): the width strain S2 is condensed out of the generalized 9 x 9 law
//     [T; D] = H [S; E] (H = [[C, -e^T], [e, eps]]) by T2 = 0, i.e. H' = H - H(:,2) H(2,:) / H(2,2);
//   plane strain (a wide plate, S2 = 0, E2 = 0): the rows and columns of the plane are taken as they are.
// The out-of-plane shears (S4 = 2 S23, S6 = 2 S12) and E2 decouple from the plane in class 6mm and in the
// isotropic host, so nothing else is condensed.
// Poling. A layer poled along -3 has e -> -e (the axis reversed: e is odd in the poling direction, C and eps
// even); any other orientation is not offered (the harvester's layers are poled through their thickness).
// Voigt order of the element (kernels/solid/elements.hpp): 3D (11, 22, 33, 23, 13, 12), 2D (11, 22, 12) of the
// model axes, engineering shears.
#pragma once

#include <array>
#include <stdexcept>
#include <string>

#include "piezo/materials.hpp"

namespace polymech::piezo {

enum class Plane { stress, strain };
inline const char* to_string(Plane p) { return p == Plane::stress ? "stress" : "strain"; }

// The law as the element reads it: S = 3 (2D) or 6 (3D) strain components, D field components.
struct FeLaw {
  int dim = 3;
  double C[6][6] = {};    // [S][S] stiffness at constant field [Pa]
  double e[3][6] = {};    // [D][S] stress coefficients [C/m^2]
  double eps[3][3] = {};  // [D][D] clamped permittivity [F/m]
  double rho = 0.0;       // [kg/m^3]
  bool piezoelectric = false;  // false: an elastic, conducting layer (e and eps not read)
};

// The generalized 9 x 9 matrix [[C, -e^T], [e, eps^S]] of a poled ceramic (poling sign +-1).
inline std::array<std::array<double, 9>, 9> generalized_law(const PiezoCeramic& m, int poling) {
  const Matrix6 C = m.stiffness_E();
  const Matrix36 e = m.e_matrix();
  const Matrix3 eps = m.eps_S();
  const double s = poling < 0 ? -1.0 : 1.0;
  std::array<std::array<double, 9>, 9> H{};
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) H[i][j] = C[i][j];
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 6; ++j) {
      H[j][6 + k] = -s * e[k][j];
      H[6 + k][j] = s * e[k][j];
    }
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) H[6 + k][6 + l] = eps[k][l];
  return H;
}

// The element law of a piezoceramic layer: dim 3, or dim 2 with the plane reading.
inline FeLaw piezo_law(const PiezoCeramic& m, int dim, Plane plane, int poling) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("piezo law: dimension " + std::to_string(dim));
  if (poling != 1 && poling != -1) throw std::invalid_argument("piezo law: poling must be +1 or -1");
  auto H = generalized_law(m, poling);
  FeLaw L;
  L.dim = dim;
  L.rho = m.rho;
  L.piezoelectric = true;
  // model strain slot -> material Voigt slot; model field component -> material field component
  int strain[6], field[3];
  if (dim == 3) {
    for (int i = 0; i < 6; ++i) strain[i] = i;
    for (int k = 0; k < 3; ++k) field[k] = k;
  } else {
    strain[0] = 0;  // S11
    strain[1] = 2;  // S33 (model yy: the thickness)
    strain[2] = 4;  // 2 S13 (model xy)
    field[0] = 0;   // E1
    field[1] = 2;   // E3
    if (plane == Plane::stress) {  // T2 = 0: condense S2 (generalized index 1)
      const double h = H[1][1];
      auto Hc = H;
      for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) Hc[i][j] = H[i][j] - H[i][1] * H[1][j] / h;
      H = Hc;
    }
  }
  const int S = dim == 3 ? 6 : 3;
  for (int i = 0; i < S; ++i)
    for (int j = 0; j < S; ++j) L.C[i][j] = H[strain[i]][strain[j]];
  for (int k = 0; k < dim; ++k)
    for (int j = 0; j < S; ++j) L.e[k][j] = H[6 + field[k]][strain[j]];
  for (int k = 0; k < dim; ++k)
    for (int l = 0; l < dim; ++l) L.eps[k][l] = H[6 + field[k]][6 + field[l]];
  return L;
}

// An isotropic elastic layer (the host): plane stress uses E / (1 - nu^2) etc., plane strain the 3D values.
inline FeLaw elastic_law(const IsotropicElastic& m, int dim, Plane plane) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("elastic law: dimension " + std::to_string(dim));
  FeLaw L;
  L.dim = dim;
  L.rho = m.rho;
  const double E = m.E, nu = m.nu, G = E / (2.0 * (1.0 + nu));
  if (dim == 3) {
    const double lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) L.C[i][j] = lam + (i == j ? 2.0 * G : 0.0);
    for (int i = 3; i < 6; ++i) L.C[i][i] = G;
  } else if (plane == Plane::stress) {
    const double c = E / (1.0 - nu * nu);
    L.C[0][0] = L.C[1][1] = c;
    L.C[0][1] = L.C[1][0] = c * nu;
    L.C[2][2] = G;
  } else {
    const double lam = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    L.C[0][0] = L.C[1][1] = lam + 2.0 * G;
    L.C[0][1] = L.C[1][0] = lam;
    L.C[2][2] = G;
  }
  return L;
}

// An isotropic piezoelectric polymer by its engineering data (the PVDF of Hwang & Park: E, nu, d31 = d32,
// no d33 or d15 given, so 0; eps_r read as the free permittivity in every direction).
inline PiezoCeramic isotropic_piezo(double E, double nu, double d31, double eps_r, double rho) {
  PiezoCeramic m{};
  m.s11E = m.s33E = 1.0 / E;
  m.s12E = m.s13E = -nu / E;
  m.s44E = 2.0 * (1.0 + nu) / E;
  m.d31 = d31;
  m.d33 = 0.0;
  m.d15 = 0.0;
  m.eps11T = m.eps33T = eps_r * kEps0;
  m.rho = rho;
  return m;
}

}  // namespace polymech::piezo
