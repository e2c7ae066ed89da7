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
// The class and its constructor, in named steps, are here; the parts: element_data.hpp (chunks, colours,
// element DoFs, geometry), boundary.hpp (Dirichlet, impedance and vibrating faces), operator.hpp (the
// matrix-free operator of eq. (16)), solve.hpp (right-hand side, COCG, results), preconditioners.hpp.
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
#include "helmholtz/boundary.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/distribute.hpp"
#include "helmholtz/effect_table.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/element_data.hpp"
#include "helmholtz/operator.hpp"
#include "helmholtz/parallel.hpp"
#include "solvers/krylov.hpp"

namespace polymech::helmholtz {
template <class T>
class Helmholtz;
}
#include "helmholtz/preconditioners.hpp"

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
    std::vector<std::complex<double>> out(static_cast<std::size_t>(dofs_.count));
    for (std::size_t i = 0; i < out.size(); ++i) {
      const auto v = field_(dofs_.coordinates[3 * i], dofs_.coordinates[3 * i + 1], dofs_.coordinates[3 * i + 2]);
      out[i] = {v.real(), v.imag()};
    }
    return out;
  }

  // Description of the discrete problem for the assembled reference (assembled.hpp).
  FaceTerm face_term(BoundaryKind kind) const { return helmholtz::face_term(cfg_, kind); }
  std::vector<char> constrained_mask() const;

  const Config& config() const { return cfg_; }
  const HexDofs& dofs() const { return dofs_; }
  const HelmholtzOperator<T>& op() const { return op_; }
  const View1<C>& solution() const { return solution_; }
  const solvers::SolveResult& result() const { return result_; }
  const AnalyticField& analytic() const { return field_; }
  Index dof_count() const { return static_cast<Index>(dofs_.count); }  // global
  Index element_count() const { return static_cast<Index>(cfg_.mesh.element_count()); }  // global
  // Domain decomposition: this rank's part.
  int rank() const { return comm_->rank(); }
  int ranks() const { return comm_->size(); }
  const PartLayout& part() const { return layout_; }
  const Communicator& communicator() const { return *comm_; }
  Index local_element_count() const { return el_.elements(); }
  int colors() const { return el_.colors(); }
  Index constrained_count() const { return static_cast<Index>(constrained_.extent(0)); }
  Index impedance_face_count() const { return op_.impedance_faces().faces(); }
  Index vibrating_face_count() const { return vibrating_.faces(); }
  double min_jacobian_ratio() const { return jacobian_.min_ratio; }
  double setup_seconds() const { return setup_seconds_; }
  double solve_seconds() const { return solve_seconds_; }
  // Set-up of the last solve's preconditioner (chebyshev, pmg; included in solve_seconds) and what it was.
  double preconditioner_seconds() const { return preconditioner_seconds_; }
  const std::string& preconditioner_description() const { return preconditioner_; }
  const View1<Index>& constrained_dofs() const { return constrained_; }
  // DoFs per second of the operator, from `applies` timed applications (wall time) after one warm-up.
  double apply_rate(int applies) const;
  // Typical element size h = (bounding-box volume / elements)^(1/3) (the perturbation scale).
  double mean_element_size() const {
    double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
    for (std::int64_t v = 0; v < cfg_.mesh.vertex_count(); ++v)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], cfg_.mesh.vertices[3 * v + k]);
        hi[k] = std::max(hi[k], cfg_.mesh.vertices[3 * v + k]);
      }
    const double vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    return std::cbrt(vol / static_cast<double>(cfg_.mesh.element_count()));
  }
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

  // The steps of the constructor.
  void number_global_dofs(const std::vector<std::int64_t>& traversal);
  void set_up_elements(const std::vector<char>& constrained);
  fem::HexFaces<T, C> set_up_boundaries(const std::vector<char>& constrained);
  void set_up_operator(const fem::HexFaces<T, C>& impedance);

  View1<C> jacobi_inverse_diagonal() const;  // solve.hpp

  std::string where(Index local_dof) const {  // coordinates of a local DoF
    if (local_dof < 0 || local_dof >= static_cast<Index>(layout_.global_of_local.size())) return "";
    const auto* p = &dofs_.coordinates[3 * static_cast<std::size_t>(layout_.global_of_local[local_dof])];
    return "at (" + models::format_g(p[0]) + ", " + models::format_g(p[1]) + ", " + models::format_g(p[2]) + ")";
  }

  Config cfg_;
  AnalyticField field_;
  HexDofs dofs_;  // global numbering (every rank)
  std::shared_ptr<const Communicator> comm_;
  PartLayout layout_;  // this rank's elements and local DoFs
  Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace> error_dofs_;  // elements counted in eq. (28), local DoFs
  std::vector<std::int64_t> element_order_;  // storage index -> mesh element
  fem::HexElements<T> el_;
  CoordinateView x_;
  fem::JacobianCheck jacobian_;
  fem::HexFaces<T, C> vibrating_;
  View1<Index> constrained_;
  View1<C> dirichlet_values_;
  HelmholtzOperator<T> op_;
  View1<C> solution_;
  solvers::SolveResult result_;
  double setup_seconds_ = 0.0, solve_seconds_ = 0.0, preconditioner_seconds_ = 0.0;
  std::string preconditioner_;
};

// Member functions that launch kernels are defined out of the class (not inline), so the explicit
// instantiation declarations below keep every other translation unit from instantiating them.

// The model of one rank's part, eq. (16) ready to solve: the global DoF numbering, the part, its
// Dirichlet mask, elements and geometry, boundary faces and the operator.
template <class T>
Helmholtz<T>::Helmholtz(const Config& c) : cfg_(c) {
  const auto t0 = std::chrono::steady_clock::now();
  validate(c);
  field_ = AnalyticField::from(c);
  const std::vector<std::int64_t> traversal = locality_order(c.mesh);
  number_global_dofs(traversal);
  // this rank's part: its elements, local DoFs (owned, then ghosts) and halo (distribute.hpp)
  comm_ = c.communicator ? c.communicator : std::make_shared<SerialCommunicator>();
  layout_ = make_part_layout(c.mesh, dofs_, traversal, comm_->rank(), comm_->size(), c.partition);
  const std::vector<char> constrained = constrained_mask_of_part(c, dofs_, layout_);  // Dirichlet DoFs, local
  set_up_elements(constrained);
  const fem::HexFaces<T, C> impedance = set_up_boundaries(constrained);
  set_up_operator(impedance);
  Kokkos::fence();
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Every DoF of the mesh (every rank numbers them all), in the locality order; with
// Config::node_perturbation, the interior nodes moved at random (a fraction of h / p).
template <class T>
void Helmholtz<T>::number_global_dofs(const std::vector<std::int64_t>& traversal) {
  dofs_ = number_dofs(cfg_.mesh, cfg_.order, traversal);
  if (cfg_.node_perturbation > 0) {
    const auto ext = exterior_faces(cfg_.mesh);
    perturb_nodes(dofs_, dofs_on_faces(dofs_, ext), cfg_.node_perturbation, mean_element_size() / cfg_.order);
  }
}

// The part's elements in coloured chunks, their DoFs, the DoF coordinates and the geometry (element_data.hpp).
template <class T>
void Helmholtz<T>::set_up_elements(const std::vector<char>& constrained) {
  ElementData<T> d = element_data<T>(cfg_, dofs_, layout_, constrained, *comm_);
  element_order_ = std::move(d.order);
  el_ = d.el;
  x_ = d.x;
  jacobian_ = d.jacobian;
  error_dofs_ = d.error_dofs;
}

// The boundary faces of the enabled effects and the Dirichlet values (boundary.hpp); returns the
// impedance faces, which the operator keeps.
template <class T>
auto Helmholtz<T>::set_up_boundaries(const std::vector<char>& constrained) -> fem::HexFaces<T, C> {
  fem::HexFaces<T, C> impedance;
  if (cfg_.effects.has("impedance"))
    impedance = boundary_faces<T>(cfg_, dofs_, layout_, x_, BoundaryKind::impedance, constrained, "impedance");
  if (cfg_.effects.has("vibrating"))
    vibrating_ = boundary_faces<T>(cfg_, dofs_, layout_, x_, BoundaryKind::vibrating, constrained, "vibrating");
  if (cfg_.effects.has("dirichlet")) {
    const DirichletValues<T> d = dirichlet_values<T>(cfg_, field_, x_, constrained);
    constrained_ = d.dofs;
    dirichlet_values_ = d.values;
  }
  return impedance;
}

// The operator K = A - k^2 M + j rho omega C of eq. (16) (operator.hpp), its halo on several ranks.
template <class T>
void Helmholtz<T>::set_up_operator(const fem::HexFaces<T, C>& impedance) {
  const double k = cfg_.wavenumber();
  op_ = HelmholtzOperator<T>(el_, impedance, constrained_, static_cast<T>(-k * k));
  if (comm_->size() > 1)
    op_.distribute(std::make_shared<Halo<C>>(comm_, layout_.neighbours, layout_.send, layout_.recv), comm_);
  solution_ = View1<C>("polymech::helmholtz::solution", static_cast<Index>(layout_.global_of_local.size()));
}

// Solving and the results: solve.hpp.
}  // namespace polymech::helmholtz

#include "helmholtz/solve.hpp"

namespace polymech::helmholtz {

// Compiled once, in models/helmholtz/helmholtz.cpp (library polymech_helmholtz): the kernels of four
// orders in two precisions are instantiated there and not in every file that uses the model.
extern template class Helmholtz<double>;
extern template class Helmholtz<float>;

}  // namespace polymech::helmholtz
