// A small-strain elasto-plastic law with stored history for the solid element kernel (issue 34): Hill (1948)
// plasticity with cubic symmetry and power-law hardening (kernels/materials/hill_plasticity.hpp, seed 002
// paper 5 eqs. (1)-(4); J2 its isotropic case) evaluated at every quadrature point of the matrix-free
// operator (solid/elastic_operator.hpp), so the internal force of the weak form
//   f_int(u)_a,c = int dN_a/dx_j sigma_cj(eps(u), history) dOmega
// is the same sum-factorized kernel as the linear operator, with this law as its template parameter.
//
// Storage per quadrature point (element e, point q = i + Q (j + Q k), the kernel's order):
//   history(e, q, 0..6)  the CONVERGED state of the last accepted load step: plastic strain (Voigt, engineering
//                        shear) and eps_bar;
//   trial(e, q, 0..6)    the state the last residual evaluation produced (committed by copying it onto
//                        history once the global Newton iteration has converged);
//   tangent(e, q, 36)    the consistent tangent d sigma / d eps of the last evaluation, in the layout of
//                        PointStiffness (solid/laws.hpp), so Newton's tangent apply is add_internal_force
//                        with PointStiffness{tangent};
//   status(e, q)         the local return mapping's outcome: 0 elastic, > 0 plastic (its local residual
//                        evaluations), -1 failure (then the stress is NaN and the global step is cut).
// A residual evaluation hands every point a COPY of its converged history (never the trial one), so the
// evaluations of one Newton iteration, and of a line search, do not depend on each other's order: the
// return mapping is path-independent within a step (backward Euler from the last converged state).
//
// The law's stress() is const and works on lanes (fem::Lanes, E elements per batch): per lane it extracts the
// strain, calls update() and writes the stress lane, the tangent, the trial history and the status to the
// Views (a View is writable through a const copy). Lanes past `count` (a partial batch) get zero stress and
// write nothing. Each batch is one thread of fem::parallel_for_batches, so no two threads write one point.
//
// Dimensions: 3D, and 2D plane strain (the kernel's (11, 22, 12) strain is embedded with eps_33 = gamma_23 =
// gamma_13 = 0; the 3D law runs unchanged and its full tangent is stored, of which PointStiffness reads the
// (11, 22, 12) block). Plane stress would need a local iteration on sigma_33 = 0 and is refused by the model.
//
// Elastic laws (ElementStiffness, has_history absent or false) allocate nothing of this: the model builds a
// PlasticLaw only when the configuration carries a plastic law.
#pragma once

#include <string>

#include "materials/hill_plasticity.hpp"
#include "solid/laws.hpp"

namespace polymech::solid {

inline constexpr int plastic_history_size = 7;  // plastic strain (6), eps_bar

template <class T>
using PointArray = Kokkos::View<T***, Kokkos::LayoutRight, MemSpace>;

// The law of a batch of elements e0 .. e0 + count - 1 (lanes of P).
template <int D, class T, class P>
struct PlasticLawBatch {
  materials::HillPlasticity<T> law;
  PointArray<T> history, trial, tangent;
  Kokkos::View<int**, Kokkos::LayoutRight, MemSpace> status;
  Index e0;
  int count;

  KOKKOS_FORCEINLINE_FUNCTION void stress(int q, const P (&eps)[strain_components<D>],
                                          P (&sig)[strain_components<D>]) const {
    constexpr int E = P::size, S = strain_components<D>;
    for (int i = 0; i < S; ++i) sig[i] = P::broadcast(T(0));
    for (int l = 0; l < E && l < count; ++l) {
      const Index e = e0 + l;
      materials::Voigt6<T> strain, s;
      for (int i = 0; i < S; ++i) strain[voigt_component<D>(i)] = eps[i].get(l);
      materials::PlasticState<T> h;  // a copy of the converged state
      for (int i = 0; i < 6; ++i) h.plastic_strain[i] = history(e, q, i);
      h.equivalent_plastic_strain = history(e, q, 6);
      materials::Stiffness6<T> C;
      const int it = law.update(strain, h, s, C);
      for (int i = 0; i < S; ++i) sig[i].set(l, s[voigt_component<D>(i)]);
      for (int i = 0; i < 6; ++i) trial(e, q, i) = h.plastic_strain[i];
      trial(e, q, 6) = h.equivalent_plastic_strain;
      for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j) tangent(e, q, 6 * i + j) = C.c[i][j];
      status(e, q) = it;
    }
  }
};

// What a residual evaluation found: plastic points (status > 0) and failed return mappings (status < 0).
struct PlasticCounts {
  Index plastic = 0, failed = 0;
};

template <class T>
struct PlasticLaw {
  static constexpr bool has_history = true;
  materials::HillPlasticity<T> law;
  PointArray<T> history;   // [elements][Q^D][7] converged
  PointArray<T> trial;     // [elements][Q^D][7] of the last evaluation
  PointArray<T> tangent;   // [elements][Q^D][36] of the last evaluation
  Kokkos::View<int**, Kokkos::LayoutRight, MemSpace> status;  // [elements][Q^D]

  PlasticLaw() = default;
  // Zero history (the virgin material), the elastic stiffness as the tangent.
  PlasticLaw(const materials::HillPlasticity<T>& l, Index elements, int points_per_element) : law(l) {
    const std::size_t ne = static_cast<std::size_t>(elements), nq = static_cast<std::size_t>(points_per_element);
    history = PointArray<T>("polymech::solid::plastic_history", ne, nq, plastic_history_size);
    trial = PointArray<T>("polymech::solid::plastic_trial", ne, nq, plastic_history_size);
    tangent = PointArray<T>("polymech::solid::plastic_tangent", ne, nq, 36);
    status = Kokkos::View<int**, Kokkos::LayoutRight, MemSpace>("polymech::solid::plastic_status", ne, nq);
    set_elastic_tangent();
  }

  // Every point's tangent = the elastic stiffness (a member function, not the constructor: nvcc's extended
  // lambdas may not live in constructors).
  void set_elastic_tangent() const {
    const auto tg = tangent;
    const materials::Stiffness6<T> C = law.C;
    const Index ne = static_cast<Index>(tg.extent(0)), nq = static_cast<Index>(tg.extent(1));
    Kokkos::parallel_for(
        "polymech::solid::plastic_tangent_init", Kokkos::MDRangePolicy<ExecSpace, Kokkos::Rank<2>>({0, 0}, {ne, nq}),
        KOKKOS_LAMBDA(const Index e, const Index q) {
          for (int k = 0; k < 36; ++k) tg(e, q, k) = C.c[k / 6][k % 6];
        });
  }

  bool allocated() const { return history.extent(0) > 0; }

  template <int D, int E, class P>
  KOKKOS_FORCEINLINE_FUNCTION PlasticLawBatch<D, T, P> batch(Index e0, int count) const {
    return {law, history, trial, tangent, status, e0, count};
  }

  // The tangent of the last evaluation as the kernel's tangent law (Newton's matrix-free tangent apply).
  PointStiffness<T> point_stiffness() const { return {tangent}; }

  // Accept the last evaluation: its trial history becomes the converged one.
  void commit() const { Kokkos::deep_copy(history, trial); }

  PlasticCounts counts() const {
    const auto st = status;
    const Index ne = static_cast<Index>(st.extent(0)), nq = static_cast<Index>(st.extent(1));
    Index plastic = 0, failed = 0;
    Kokkos::parallel_reduce(
        "polymech::solid::plastic_counts", Kokkos::RangePolicy<ExecSpace>(0, ne * nq),
        KOKKOS_LAMBDA(const Index k, Index& p, Index& f) {
          const int s = st(k / nq, k % nq);
          if (s > 0) ++p;
          if (s < 0) ++f;
        },
        plastic, failed);
    return {plastic, failed};
  }
};

// The law in precision T from its double form (the model's configuration is in double).
template <class T>
materials::HillPlasticity<T> cast_law(const materials::HillPlasticity<double>& d) {
  materials::HillPlasticity<T> l;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      l.C.c[i][j] = static_cast<T>(d.C.c[i][j]);
      l.S.c[i][j] = static_cast<T>(d.S.c[i][j]);
      l.P.c[i][j] = static_cast<T>(d.P.c[i][j]);
    }
  l.hardening.sigma0 = static_cast<T>(d.hardening.sigma0);
  l.hardening.exponent = static_cast<T>(d.hardening.exponent);
  l.hardening.shear_modulus = static_cast<T>(d.hardening.shear_modulus);
  return l;
}

}  // namespace polymech::solid
