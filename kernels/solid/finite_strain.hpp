// Total-Lagrangian finite-strain element kernels of the solid (issue 34: the tyre and the FSI benchmarks):
// the internal force, the strain energy and the consistent tangent of a hyperelastic law, and the follower
// pressure with its load stiffness.
//
// Kinematics (reference configuration X, displacement u): F = I + Grad u, Grad u = sum_a u_a (x) Grad N_a,
// Grad N_a = J^-T grad_ref N_a from the element geometry of solid/elements.hpp (J^-1 and w det J per point,
// the reference configuration's, computed once). 2D is plane strain: F embedded in 3x3 with F_33 = 1.
//
// Internal force and tangent in the first-Piola form (equivalent to int B_NL^T S dV0 and K_mat + K_geo:
// P = F S, and A = dP/dF = d_ik S_JL + F_iM C_MJNL F_kN carries both the material part (C) and the geometric
// part (S) in one tensor):
//   f_int(a, i) = sum_q w_q det J  P_iJ(F_q) Grad N_a,J,
//   K[(a, i), (b, k)] = sum_q w_q det J  Grad N_a,J A_iJkL(F_q) Grad N_b,L,
//   Pi_int = sum_q w_q det J W(F_q).
// The laws (materials/hyperelastic.hpp, materials/elastic.hpp) give W, P and A in closed form; the kernel
// refuses F with J = det F <= 0 (or any non-finite value) before calling the law: the element's status is
// then 1, its force and energy zero, and the model treats the evaluation as failed (cuts the step), so a
// NaN never reaches the Newton iteration.
//
// Element loop: full tensor-product basis gradients at the Q^D = N^D Gauss points (direct evaluation, as
// solid/assembly.hpp, not sum factorization: the per-point law dominates and the tangent is dense anyway),
// one thread per batch of fem::parallel_for_batches (the colours scatter the force without atomics, so the
// sum does not depend on the thread count). The element matrices are written to a View [elements][(D N^D)^2]
// in double and assembled on the host (assemble_element_matrices) for the sparse LU.
//
// Follower pressure p on a side (the current normal, Nanson's n da = J F^-T N dA, written on the face as
// n da = x_,s x x_,t ds dt in 3D and (x_,s)^perp ds in 2D with x = X + u):
//   f_p(a) = -p int N_a n da,   K_p[(a, i), (b, k)] = -d f_p(a, i) / d u_(b, k) = p int N_a dn_i/du_(b, k),
// dn/du_(b, k) = N_b,s e_k x x_,t + x_,s x N_b,t e_k (3D), and (N_b,s e_k)^perp (2D). K_p is not symmetric
// in general (its skew part integrates to boundary terms that vanish on a closed surface or one whose edge
// is fixed); the model assembles the full K_p (exact Newton) and the LU handles the non-symmetry. The
// outward sign of a structured side: with a positively oriented lattice (the geometry check refuses the
// other), x_,s x x_,t (s, t the side's lattice directions in increasing order) points to +dir on the sides
// of directions 0 and 2 and to -dir on those of direction 1; the side's sign makes it outward.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "materials/hyperelastic.hpp"
#include "solid/assembly.hpp"
#include "solid/elements.hpp"

namespace polymech::solid {

// --- the laws as the kernel sees them: W(F), P(F), A(F) ------------------------------------------------

template <class T>
KOKKOS_INLINE_FUNCTION materials::PiolaTangent<T> piola_tangent(const materials::StVenantKirchhoff<T>& l,
                                                                const Mat3<T>& F) {
  return materials::svk_tangent(F, l.elastic);
}
template <class T>
KOKKOS_INLINE_FUNCTION materials::PiolaTangent<T> piola_tangent(const materials::NeoHookean<T>& l, const Mat3<T>& F) {
  return l.tangent(F);
}
template <class T>
KOKKOS_INLINE_FUNCTION materials::PiolaTangent<T> piola_tangent(const materials::MooneyRivlin<T>& l, const Mat3<T>& F) {
  return l.tangent(F);
}

// S = F^-1 P, the second Piola-Kirchhoff stress.
template <class T>
KOKKOS_INLINE_FUNCTION Mat3<T> second_piola(const Mat3<T>& F, const Mat3<T>& P) {
  return inverse(F) * P;
}

// The material tangent C = dS/dE (Voigt 6x6, order 11 22 33 23 13 12, E with engineering shears, so
// dS_voigt = C dE_voigt) from P and A: A_iJkL = d_ik S_JL + F_iM C_MJNL F_kN gives
// C_MJNL = Fi_Mi (A_iJkL - d_ik S_JL) Fi_Nk.
template <class T>
KOKKOS_INLINE_FUNCTION materials::Stiffness6<T> material_tangent_voigt(const Mat3<T>& F, const Mat3<T>& P,
                                                                       const materials::PiolaTangent<T>& A) {
  const Mat3<T> Fi = inverse(F), S = Fi * P;
  constexpr int pi[6] = {0, 1, 2, 1, 0, 0}, pj[6] = {0, 1, 2, 2, 2, 1};
  materials::Stiffness6<T> C;
  for (int I = 0; I < 6; ++I)
    for (int K = 0; K < 6; ++K) {
      const int M = pi[I], J = pj[I], N = pi[K], L = pj[K];
      T s = T(0);
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) s += Fi.a[M][i] * (A(i, J, k, L) - (i == k ? S.a[J][L] : T(0))) * Fi.a[N][k];
      C.c[I][K] = s;
    }
  return C;
}

// --- element kernel -------------------------------------------------------------------------------------

// Per element: strain energy and status (0 fine, 1 J <= 0 or non-finite at a point).
template <class T>
struct FiniteStrainElementData {
  View1<double> energy;                                           // [elements]
  View1<int> status;                                              // [elements]
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> matrices;  // [elements][(D N^D)^2] when tangent
  // Per-element stiffness scale s_e (storage order; empty: one law, s_e = 1): element e's law is the given one
  // times s_e. For a law whose W is linear in its moduli at fixed F (Mooney-Rivlin in C10, C01, kappa; neo-Hookean
  // and St. Venant-Kirchhoff in lambda, mu), s_e W, s_e P and s_e A are the same law with its moduli times s_e:
  // a layered body (the tyre's cord layer, issue 37) with one law evaluation per point. Applied to the
  // quadrature weight (w_q det J -> s_e w_q det J), so s_e = 1 gives the one-law result bitwise.
  View1<T> scale;
  // Rebar: two cord families per element (seed 002 paper 2 §4, the belt reinforcements; issue 37: the tyre's steel
  // belt; empty: none, nothing stored or evaluated). Per element (storage order) {k, cos beta, sin beta}: the unit
  // reference directions a_+- = cos beta t_0 +- sin beta t_1 in the element's local tangent plane at each point (t_0
  // the unit reference tangent along the element's direction 0, t_1 that along direction 1 made orthogonal to t_0:
  // on a mapped lattice the lattice's tangents, the tyre's circumferential and lateral directions), each family a
  // fibre with S_f = k E_a a (x) a, E_a = a.E.a = (a.C.a - 1) / 2 (1D Hooke in the Green strain along the cord,
  // W_f = k E_a^2 / 2; k the smeared modulus of the family's cords per element volume: the small-strain stiffness
  // along the cord). Added to the law's P and A (P_f = F S_f, A_f = d_ik S_f,JL + k (F a)_i a_J (F a)_k a_L) with
  // the unscaled weight w_q det J (the per-element scale is the matrix law's). fibre_tension_only: S_f = 0 where
  // E_a < 0 (cords do not carry compression). An element with k = 0 is skipped.
  Kokkos::View<T* [3], Kokkos::LayoutRight, MemSpace> fibre;
  bool fibre_tension_only = false;
};

struct FiniteStrainEvaluation {
  double energy = 0.0;
  Index failed_elements = 0;
};

namespace detail {

// The two cord families of FiniteStrainElementData::fibre at one point (3D): w0 = w_q det J; adds to the energy,
// the element force and, with Tangent, the element matrix (seed 002 paper 2 §4, the belt reinforcements).
template <class T, int D, int ND, bool Tangent, class Km_t>
KOKKOS_INLINE_FUNCTION void add_fibres(const Mat3<T>& F, const T (&Ji)[D][D], const T (&G)[ND][D], const T k, const T cb,
                                       const T sb, const bool tension_only, const T w0, double& we, T (&fe)[ND][D], const Km_t& Km,
                                       const Index e) {
  if constexpr (D == 3) {
    // the reference tangents t_0, t_1: columns 0 and 1 of J = (J^-1)^-1
    Mat3<T> Jinv;
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < 3; ++j) Jinv.a[r][j] = Ji[r][j];
    const Mat3<T> Jr = inverse(Jinv);  // Jr.a[c][d] = dX_c / dxi_d
    T t0[3], t1[3];
    T n0 = T(0);
    for (int c = 0; c < 3; ++c) n0 += Jr.a[c][0] * Jr.a[c][0];
    n0 = T(1) / kx::sqrt(n0);
    for (int c = 0; c < 3; ++c) t0[c] = Jr.a[c][0] * n0;
    T p = T(0);
    for (int c = 0; c < 3; ++c) p += Jr.a[c][1] * t0[c];
    T n1 = T(0);
    for (int c = 0; c < 3; ++c) {
      t1[c] = Jr.a[c][1] - p * t0[c];
      n1 += t1[c] * t1[c];
    }
    n1 = T(1) / kx::sqrt(n1);
    for (int c = 0; c < 3; ++c) t1[c] *= n1;
    constexpr int M = D * ND;
    for (int fam = 0; fam < 2; ++fam) {
      const T sg = fam == 0 ? T(1) : T(-1);
      T a[3], Fa[3];
      for (int c = 0; c < 3; ++c) a[c] = cb * t0[c] + sg * sb * t1[c];
      T I4 = T(0);
      for (int c = 0; c < 3; ++c) {
        Fa[c] = F.a[c][0] * a[0] + F.a[c][1] * a[1] + F.a[c][2] * a[2];
        I4 += Fa[c] * Fa[c];
      }
      const T Ea = T(0.5) * (I4 - T(1));
      if (tension_only && !(Ea > T(0))) continue;
      const T sf = k * Ea;  // S_f = sf a (x) a
      we += static_cast<double>(w0 * T(0.5) * k * Ea * Ea);
      T Ga[ND];  // Grad N_a . a
      for (int aa = 0; aa < ND; ++aa) Ga[aa] = G[aa][0] * a[0] + G[aa][1] * a[1] + G[aa][2] * a[2];
      // P_f G_a = sf (F a) (a . G_a)
      for (int aa = 0; aa < ND; ++aa)
        for (int c = 0; c < 3; ++c) fe[aa][c] += w0 * sf * Fa[c] * Ga[aa];
      if constexpr (Tangent) {
        // K[(a, c), (b, d)] += w0 (d_cd sf Ga_a Ga_b + k Fa_c Ga_a Fa_d Ga_b)
        for (int aa = 0; aa < ND; ++aa)
          for (int c = 0; c < 3; ++c)
            for (int bb = 0; bb < ND; ++bb)
              for (int d = 0; d < 3; ++d) {
                const T v = (c == d ? sf : T(0)) * Ga[aa] * Ga[bb] + k * Fa[c] * Ga[aa] * Fa[d] * Ga[bb];
                Km(e, (aa * 3 + c) * M + bb * 3 + d) += static_cast<double>(w0 * v);
              }
      }
    }
  }
}

template <class T, int D, int N, bool Tangent, class Law>
void finite_strain_elements(const SolidElements<T, D>& el, const Law& law, const View1<T>& u, const View1<T>& f,
                            const FiniteStrainElementData<T>& out) {
  constexpr int Q = N, QD = power<D>(Q), ND = power<D>(N), M = D * ND;
  const fem::HexBasis<T, N, Q> b = fem::make_hex_basis<T, N, Q>();
  const auto dofs = el.cells.dofs;
  const GeometryViews<T, D> geo(el);
  const auto energy = out.energy;
  const auto status = out.status;
  const auto Km = out.matrices;
  const auto scale = out.scale;
  const bool scaled = scale.extent(0) > 0;
  const auto fibre = out.fibre;
  const bool fibred = D == 3 && fibre.extent(0) > 0;
  const bool tension_only = out.fibre_tension_only;
  fem::parallel_for_batches(
      "polymech::solid::finite_strain_elements", el.cells, KOKKOS_LAMBDA(const Index e0, const int count, int) {
        const Index row = geo.slot(e0);
        for (int l = 0; l < count; ++l) {
          const Index e = e0 + l;
          const T se = scaled ? scale(e) : T(1);
          const T kf = fibred ? fibre(e, 0) : T(0);
          T ue[ND][D], fe[ND][D], G[ND][D];
          for (int a = 0; a < ND; ++a)
            for (int c = 0; c < D; ++c) {
              ue[a][c] = u(D * fem::decode_dof(dofs(e, a)) + c);
              fe[a][c] = T(0);
            }
          if (Tangent)
            for (int k = 0; k < M * M; ++k) Km(e, k) = 0.0;
          double we = 0.0;
          int bad = 0;
          for (int q = 0; q < QD && !bad; ++q) {
            T Ji[D][D];
            const T w0 = geo.template at<Q>(row, e0, l, q, b.w, Ji);  // w_q det J
            const T wd = se * w0;                                      // s_e w_q det J
            const int qi[3] = {q % Q, (q / Q) % Q, q / (Q * Q)};
            for (int a = 0; a < ND; ++a) {
              const int ai[3] = {a % N, (a / N) % N, a / (N * N)};
              T gr[D];
              for (int r = 0; r < D; ++r) {
                T g = T(1);
                for (int d = 0; d < D; ++d) g *= (d == r ? b.D[qi[d]][ai[d]] : b.B[qi[d]][ai[d]]);
                gr[r] = g;
              }
              for (int j = 0; j < D; ++j) {
                T s = T(0);
                for (int r = 0; r < D; ++r) s += gr[r] * Ji[r][j];
                G[a][j] = s;
              }
            }
            Mat3<T> F = Mat3<T>::identity();
            for (int a = 0; a < ND; ++a)
              for (int c = 0; c < D; ++c)
                for (int j = 0; j < D; ++j) F.a[c][j] += ue[a][c] * G[a][j];
            const T J = det(F);
            if (!(J > T(0)) || !(J - J == T(0))) {  // J <= 0, NaN or inf
              bad = 1;
              break;
            }
            const T W = law.energy_density(F);
            const Mat3<T> P = law.first_piola_kirchhoff(F);
            T check = W;
            for (int i = 0; i < 3; ++i)
              for (int j = 0; j < 3; ++j) check += P.a[i][j];
            if (!(check - check == T(0))) {  // a non-finite energy or stress
              bad = 1;
              break;
            }
            we += static_cast<double>(wd * W);
            for (int a = 0; a < ND; ++a)
              for (int c = 0; c < D; ++c) {
                T s = T(0);
                for (int j = 0; j < D; ++j) s += P.a[c][j] * G[a][j];
                fe[a][c] += wd * s;
              }
            if (kf != T(0)) detail::add_fibres<T, D, ND, Tangent>(F, Ji, G, kf, fibre(e, 1), fibre(e, 2), tension_only, w0, we, fe, Km, e);
            if (Tangent) {
              const materials::PiolaTangent<T> A = piola_tangent(law, F);
              for (int a = 0; a < ND; ++a)
                for (int c = 0; c < D; ++c) {
                  T AG[D][D];  // AG[d][L] = sum_J G_a,J A_cJdL
                  for (int d = 0; d < D; ++d)
                    for (int L = 0; L < D; ++L) {
                      T s = T(0);
                      for (int j = 0; j < D; ++j) s += G[a][j] * A(c, j, d, L);
                      AG[d][L] = s;
                    }
                  const int r = a * D + c;
                  for (int bb = 0; bb < ND; ++bb)
                    for (int d = 0; d < D; ++d) {
                      T s = T(0);
                      for (int L = 0; L < D; ++L) s += AG[d][L] * G[bb][L];
                      Km(e, r * M + bb * D + d) += static_cast<double>(wd * s);
                    }
                }
            }
          }
          status(e) = bad;
          energy(e) = bad ? 0.0 : we;
          if (!bad)
            for (int a = 0; a < ND; ++a)
              for (int c = 0; c < D; ++c) f(D * fem::decode_dof(dofs(e, a)) + c) += fe[a][c];
        }
      });
}

}  // namespace detail

// f += f_int(u) (every DoF; u carries the Dirichlet values), the energy and status per element and, with
// Tangent, the element matrices (out.matrices sized [elements][(D N^D)^2] by the caller, or by this
// function when its extent does not fit). Returns the total energy and the failed elements.
template <bool Tangent, class T, int D, class Law>
FiniteStrainEvaluation finite_strain_internal_force(const SolidElements<T, D>& el, const Law& law, const View1<T>& u,
                                                    const View1<T>& f, FiniteStrainElementData<T>& out) {
  const Index ne = el.elements();
  if (static_cast<Index>(out.energy.extent(0)) != ne) {
    out.energy = View1<double>("polymech::solid::finite_strain_energy", ne);
    out.status = View1<int>("polymech::solid::finite_strain_status", ne);
  }
  fem::with_nodes(el.order(), [&](auto n) {
    constexpr int N = decltype(n)::value, M = D * power<D>(N);
    if (Tangent && (static_cast<Index>(out.matrices.extent(0)) != ne || out.matrices.extent(1) != std::size_t(M * M)))
      out.matrices = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::finite_strain_matrices",
                                                                           ne, M * M);
    detail::finite_strain_elements<T, D, N, Tangent>(el, law, u, f, out);
  });
  FiniteStrainEvaluation r;
  const auto en = out.energy;
  const auto st = out.status;
  Kokkos::parallel_reduce(
      "polymech::solid::finite_strain_sum", range(ne),
      KOKKOS_LAMBDA(const Index e, double& s, Index& bad) {
        s += en(e);
        bad += st(e) != 0 ? 1 : 0;
      },
      r.energy, r.failed_elements);
  return r;
}

// --- follower pressure ----------------------------------------------------------------------------------

// Faces of the sides carrying a follower pressure: nodes (face-lexicographic, plain node ids), the outward
// sign of x_,s x x_,t (see the header) and the pressure per face (scaled by the load factor by the caller).
template <int D>
struct PressureFaces {
  int order = 1;
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> nodes;  // [faces][N^(D-1)]
  View1<double> sign, pressure;                               // [faces]
  Index faces() const { return static_cast<Index>(nodes.extent(0)); }
};

// The outward sign of a structured side (direction dir, max side or not).
inline double outward_sign(int dir, bool max_side) { return (dir == 1 ? -1.0 : 1.0) * (max_side ? 1.0 : -1.0); }

namespace detail {

// Nodal forces of every face [faces][D N^(D-1)] (scale * f_p) and, with Tangent, the face load stiffness
// scale * K_p [faces][(D N^(D-1))^2].
template <class T, int D, int N, bool Tangent>
void pressure_faces(const PressureFaces<D>& pf, const NodeCoordinates<D>& x, const View1<T>& u, double scale,
                    const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& force,
                    const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& stiff) {
  constexpr int NF = D == 3 ? N * N : N, M = D * NF, Q = N;
  const fem::HexBasis<double, N, Q> b = fem::make_hex_basis<double, N, Q>();
  const auto nodes = pf.nodes;
  const auto sign = pf.sign;
  const auto pres = pf.pressure;
  Kokkos::parallel_for(
      "polymech::solid::follower_pressure", range(pf.faces()), KOKKOS_LAMBDA(const Index face) {
        double xc[NF][D];
        for (int a = 0; a < NF; ++a) {
          const Index v = nodes(face, a);
          for (int c = 0; c < D; ++c) xc[a][c] = x(v, c) + static_cast<double>(u(D * v + c));
        }
        const double p = scale * pres(face), sg = sign(face);
        for (int k = 0; k < M; ++k) force(face, k) = 0.0;
        if (Tangent)
          for (int k = 0; k < M * M; ++k) stiff(face, k) = 0.0;
        for (int q = 0; q < NF; ++q) {
          const int qs = q % Q, qt = q / Q;
          double Nv[NF], Ns[NF], Nt[NF], w;
          for (int a = 0; a < NF; ++a) {
            const int as = a % N, at = a / N;
            if (D == 3) {
              Nv[a] = b.B[qs][as] * b.B[qt][at];
              Ns[a] = b.D[qs][as] * b.B[qt][at];
              Nt[a] = b.B[qs][as] * b.D[qt][at];
            } else {
              Nv[a] = b.B[qs][a];
              Ns[a] = b.D[qs][a];
              Nt[a] = 0.0;
            }
          }
          w = D == 3 ? b.w[qs] * b.w[qt] : b.w[qs];
          double xs[3] = {0, 0, 0}, xt[3] = {0, 0, 0};
          for (int a = 0; a < NF; ++a)
            for (int c = 0; c < D; ++c) {
              xs[c] += Ns[a] * xc[a][c];
              xt[c] += Nt[a] * xc[a][c];
            }
          double n[3];
          if (D == 3) {
            n[0] = xs[1] * xt[2] - xs[2] * xt[1];
            n[1] = xs[2] * xt[0] - xs[0] * xt[2];
            n[2] = xs[0] * xt[1] - xs[1] * xt[0];
          } else {
            n[0] = xs[1];
            n[1] = -xs[0];
            n[2] = 0.0;
          }
          for (int a = 0; a < NF; ++a)
            for (int c = 0; c < D; ++c) force(face, a * D + c) += -p * sg * w * Nv[a] * n[c];
          if (Tangent) {
            for (int a = 0; a < NF; ++a)
              for (int bb = 0; bb < NF; ++bb)
                for (int c = 0; c < D; ++c)
                  for (int k = 0; k < D; ++k) {
                    double dn;  // d n_c / d u_(bb, k)
                    if (D == 3) {
                      // (Ns_b e_k x xt)_c + (xs x Nt_b e_k)_c; (e_k x v)_c = eps_ckj v_j
                      const int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
                      const double ekxt = k == c1 ? xt[c2] : (k == c2 ? -xt[c1] : 0.0);
                      const double xsxek = k == c2 ? xs[c1] : (k == c1 ? -xs[c2] : 0.0);
                      dn = Ns[bb] * ekxt + Nt[bb] * xsxek;
                    } else {
                      dn = (c == 0 && k == 1) ? Ns[bb] : ((c == 1 && k == 0) ? -Ns[bb] : 0.0);
                    }
                    stiff(face, (a * D + c) * M + bb * D + k) += p * sg * w * Nv[a] * dn;
                  }
          }
        }
      });
}

}  // namespace detail

// Follower-pressure nodal forces (scale * f_p) and, with Tangent, face stiffnesses (scale * K_p), per face;
// the caller scatters them (scatter_pressure, assemble_element_matrices).
template <bool Tangent, class T, int D>
void follower_pressure(const PressureFaces<D>& pf, const NodeCoordinates<D>& x, const View1<T>& u, double scale,
                       Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& force,
                       Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& stiff) {
  if (pf.faces() == 0) return;
  fem::with_nodes(pf.order, [&](auto n) {
    constexpr int N = decltype(n)::value, M = D * (D == 3 ? N * N : N);
    if (force.extent(0) != std::size_t(pf.faces()) || force.extent(1) != std::size_t(M))
      force = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::pressure_force", pf.faces(), M);
    if (Tangent && (stiff.extent(0) != std::size_t(pf.faces()) || stiff.extent(1) != std::size_t(M * M)))
      stiff = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>("polymech::solid::pressure_stiffness", pf.faces(),
                                                                    M * M);
    detail::pressure_faces<T, D, N, Tangent>(pf, x, u, scale, force, stiff);
  });
}

// v += the per-face nodal forces, summed on the host in face order (independent of the thread count).
template <class T, int D>
void scatter_pressure(const PressureFaces<D>& pf, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& force,
                      const View1<T>& v) {
  if (pf.faces() == 0) return;
  const auto fh = Kokkos::create_mirror_view_and_copy(HostSpace(), force);
  const auto nh = Kokkos::create_mirror_view_and_copy(HostSpace(), pf.nodes);
  Kokkos::View<T*, HostSpace> vh("polymech::solid::pressure_scatter", v.extent(0));
  Kokkos::deep_copy(vh, v);
  const int NF = static_cast<int>(nh.extent(1));
  for (std::size_t face = 0; face < fh.extent(0); ++face)
    for (int a = 0; a < NF; ++a)
      for (int c = 0; c < D; ++c) vh(D * nh(face, a) + c) += static_cast<T>(fh(face, a * D + c));
  Kokkos::deep_copy(v, vh);
}

// Triplets of element (or face) matrices [items][M^2] whose rows and columns are the D components of the
// node lists node_of(item, a); rows and columns of constrained DoFs are skipped (the caller adds the identity).
template <int D, class NodeOf>
void append_matrices(const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& m, int nodes_per_item,
                     const NodeOf& node_of, const std::vector<char>& constrained, Triplets& t) {
  const auto mh = Kokkos::create_mirror_view_and_copy(HostSpace(), m);
  const int M = D * nodes_per_item;
  for (std::size_t e = 0; e < mh.extent(0); ++e)
    for (int a = 0; a < nodes_per_item; ++a)
      for (int c = 0; c < D; ++c) {
        const std::int64_t r = D * node_of(e, a) + c;
        if (constrained[static_cast<std::size_t>(r)]) continue;
        for (int bb = 0; bb < nodes_per_item; ++bb)
          for (int d = 0; d < D; ++d) {
            const std::int64_t col = D * node_of(e, bb) + d;
            if (constrained[static_cast<std::size_t>(col)]) continue;
            t.rows.push_back(r);
            t.cols.push_back(col);
            t.values.push_back(mh(e, (a * D + c) * M + bb * D + d));
          }
      }
}

}  // namespace polymech::solid
