// Helmholtz model (seed 002 paper 3): order-p hexahedral Lagrange elements on a linear hexahedral mesh,
// the complex symmetric system (A - k^2 M + j rho omega C) Phi = q of eq. (16) applied matrix-free, and
// COCG with Jacobi (or shifted-Laplacian: preconditioners.hpp) preconditioning; one part of an MPI domain
// decomposition when Config::communicator has several ranks (distribute.hpp, parallel.hpp).
//
//   polymech::helmholtz::Config cfg;   // or io::load_helmholtz_scene(...)
//   Helmholtz<double> model(cfg);
//   const auto result = model.solve();
//   const double eps = model.l2_error().relative();   // eq. (28)
//
// Effects (a scene lists those its boundaries need; the others allocate and launch nothing):
//   dirichlet  strong Dirichlet values (the analytic field of eq. (27), or a constant)
//   impedance  impedance boundaries, eqs. (7), (19)
//   vibrating  vibrating boundaries, eqs. (8), (20)
// Rigid boundaries (dPhi/dn = 0) are natural and cost nothing.
//
// The class is here; the parts: discretization.hpp (one order's numbering, part, elements, faces and
// operator, built in named steps from element_data.hpp, boundary.hpp and operator.hpp), solve.hpp
// (right-hand side, COCG, results), preconditioners.hpp (which build coarser orders' discretizations).
#pragma once

#include <algorithm>
#include <chrono>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "fem/l2_error.hpp"
#include "helmholtz/analytic.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/discretization.hpp"
#include "helmholtz/effect_table.hpp"
#include "helmholtz/preconditioners.hpp"
#include "solvers/krylov.hpp"

namespace polymech::helmholtz {

template <class T>
class Helmholtz {
 public:
  using C = Kokkos::complex<T>;

  static const std::vector<EffectSpec>& effects() { return effect_table(); }

  explicit Helmholtz(const Config& c);

  // Right-hand side of eq. (16): q (eq. (20)) minus the Dirichlet lifting, g on constrained rows.
  // x0 receives the initial guess (g on constrained DoFs, 0 elsewhere).
  void right_hand_side(const View1<C>& rhs, const View1<C>& x0) const;

  // Solves eq. (16) with COCG (Jacobi-preconditioned unless the config says otherwise). A diagonal
  // that vanishes or is not finite makes Jacobi impossible: that is a std::runtime_error saying where.
  solvers::SolveResult solve() { return solve(cfg_.solver); }
  solvers::SolveResult solve(const solvers::SolverOptions& options);

  // eq. (28) against the case's analytic field (double precision whatever T is).
  fem::ErrorIntegrals l2_error() const;

  // Host copies for output.
  std::vector<std::complex<double>> host_solution() const;
  std::vector<std::complex<double>> host_analytic() const {
    std::vector<std::complex<double>> out(static_cast<std::size_t>(d_.dofs.count));
    const auto& X = d_.dofs.coordinates;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const auto v = field_(X[3 * i], X[3 * i + 1], X[3 * i + 2]);
      out[i] = {v.real(), v.imag()};
    }
    return out;
  }

  // Description of the discrete problem for the assembled reference (assembled.hpp).
  FaceTerm face_term(BoundaryKind kind) const { return helmholtz::face_term(cfg_, kind); }
  std::vector<char> constrained_mask() const { return d_.constrained_mask(); }

  const Config& config() const { return cfg_; }
  const HexDofs& dofs() const { return d_.dofs; }
  const HelmholtzOperator<T>& op() const { return d_.op; }
  const Discretization<T>& discretization() const { return d_; }
  const View1<C>& solution() const { return solution_; }
  const solvers::SolveResult& result() const { return result_; }
  const AnalyticField& analytic() const { return field_; }
  Index dof_count() const { return static_cast<Index>(d_.dofs.count); }  // global
  Index element_count() const { return static_cast<Index>(cfg_.mesh.element_count()); }  // global
  // Domain decomposition: this rank's part.
  int rank() const { return d_.comm->rank(); }
  int ranks() const { return d_.comm->size(); }
  const PartLayout& part() const { return d_.layout; }
  const Communicator& communicator() const { return *d_.comm; }
  Index local_element_count() const { return d_.el.elements(); }
  int colors() const { return d_.el.colors(); }
  Index constrained_count() const { return static_cast<Index>(d_.constrained.extent(0)); }
  Index impedance_face_count() const { return d_.op.impedance_faces().faces(); }
  Index vibrating_face_count() const { return d_.vibrating.faces(); }
  double min_jacobian_ratio() const { return d_.jacobian.min_ratio; }
  double setup_seconds() const { return setup_seconds_; }
  double solve_seconds() const { return solve_seconds_; }
  // Set-up of the last solve's preconditioner (chebyshev, pmg; included in solve_seconds) and what it was.
  double preconditioner_seconds() const { return preconditioner_seconds_; }
  const std::string& preconditioner_description() const { return preconditioner_; }
  const View1<Index>& constrained_dofs() const { return d_.constrained; }
  // DoFs per second of the operator, from `applies` timed applications (wall time) after one warm-up.
  double apply_rate(int applies) const;
  // Typical element size h = (bounding-box volume / elements)^(1/3) (the perturbation scale).
  double mean_element_size() const { return helmholtz::mean_element_size(cfg_.mesh); }
  // Pressure p = j omega rho Phi (eq. (4)).
  std::complex<double> pressure_factor() const { return {0.0, cfg_.omega() * cfg_.density}; }

 private:
  static void validate(const Config& c) {
    auto fail = [](const std::string& m) { throw std::invalid_argument("helmholtz: " + m); };
    if (c.order < fem::min_order || c.order > fem::max_order)
      fail("order " + std::to_string(c.order) + " is not supported; allowed: 1..4");
    if (c.mesh.element_count() == 0) fail("the mesh has no elements");
    if (!(c.sound_speed > 0) || !(c.frequency > 0) || !(c.density > 0))
      fail("sound speed, frequency and density must be > 0");
    if (!(c.node_perturbation >= 0)) fail("node perturbation must be >= 0");
    for (const auto& b : c.boundaries) {
      if (c.mesh.boundary_index(b.name) < 0) fail("boundary '" + b.name + "' is not a boundary of the mesh");
      const char* effect = b.kind == BoundaryKind::dirichlet   ? "dirichlet"
                           : b.kind == BoundaryKind::impedance ? "impedance"
                           : b.kind == BoundaryKind::vibrating ? "vibrating"
                                                               : nullptr;
      if (effect && !c.effects.has(effect))
        fail("boundary '" + b.name + "' is of kind " + effect + " but effect '" + effect + "' is not enabled");
      if (b.kind == BoundaryKind::impedance && !(b.impedance > 0))
        fail("boundary '" + b.name + "': impedance must be > 0");
    }
    for (const char* effect : {"dirichlet", "impedance", "vibrating"}) {
      if (!c.effects.has(effect)) continue;
      bool used = false;
      for (const auto& b : c.boundaries) used = used || std::string(to_string(b.kind)) == effect;
      if (!used) fail(std::string("effect '") + effect + "' is enabled but no boundary is of kind " + effect);
    }
  }

  View1<C> jacobi_inverse_diagonal() const;  // solve.hpp

  std::string where(Index local_dof) const {  // coordinates of a local DoF
    if (local_dof < 0 || local_dof >= static_cast<Index>(d_.layout.global_of_local.size())) return "";
    const auto* p = &d_.dofs.coordinates[3 * static_cast<std::size_t>(d_.layout.global_of_local[local_dof])];
    return "at (" + models::format_g(p[0]) + ", " + models::format_g(p[1]) + ", " + models::format_g(p[2]) + ")";
  }

  Config cfg_;
  AnalyticField field_;
  Discretization<T> d_;  // the scene's order on this rank's part
  View1<C> solution_;
  solvers::SolveResult result_;
  double setup_seconds_ = 0.0, solve_seconds_ = 0.0, preconditioner_seconds_ = 0.0;
  std::string preconditioner_;
};

// Member functions that launch kernels are defined out of the class (not inline), so the explicit
// instantiation declarations below keep every other translation unit from instantiating them.

// The model of one rank's part, eq. (16) ready to solve: its discretization (discretization.hpp) and the
// solution vector.
template <class T>
Helmholtz<T>::Helmholtz(const Config& c) : cfg_(c) {
  const auto t0 = std::chrono::steady_clock::now();
  validate(c);
  field_ = AnalyticField::from(c);
  d_ = Discretization<T>(c, field_);
  solution_ = View1<C>("polymech::helmholtz::solution", static_cast<Index>(d_.layout.global_of_local.size()));
  Kokkos::fence();
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Solving and the results: solve.hpp.
}  // namespace polymech::helmholtz

#include "helmholtz/solve.hpp"

namespace polymech::helmholtz {

// Compiled once, in models/helmholtz/helmholtz.cpp (library polymech_helmholtz): the kernels of four
// orders in two precisions are instantiated there and not in every file that uses the model.
extern template struct Discretization<double>;
extern template struct Discretization<float>;
extern template class Helmholtz<double>;
extern template class Helmholtz<float>;

}  // namespace polymech::helmholtz
