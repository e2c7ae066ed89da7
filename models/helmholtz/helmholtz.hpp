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
#include "helmholtz/distribute.hpp"
#include "helmholtz/effect_table.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/operator.hpp"
#include "helmholtz/parallel.hpp"
#include "solvers/krylov.hpp"

namespace polymech::helmholtz {
template <class T>
class Helmholtz;
}
#include "helmholtz/preconditioners.hpp"

namespace polymech::helmholtz {

using CoordinateView = Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace>;

namespace detail {

// Kernels of the model, as free functions (CUDA: no extended lambdas in constructors or private members).

inline void dirichlet_data(const View1<Index>& constrained, const CoordinateView& x, const AnalyticField& field,
                           double constant, bool analytic, const View1<Kokkos::complex<double>>& g) {
  Kokkos::parallel_for(
      "polymech::helmholtz::dirichlet_data", range(static_cast<Index>(constrained.extent(0))),
      KOKKOS_LAMBDA(const Index k) {
        const Index d = constrained(k);
        g(k) = analytic ? field(x(d, 0), x(d, 1), x(d, 2)) : Kokkos::complex<double>(constant, 0.0);
      });
}

template <class T>
void to_precision(const View1<Kokkos::complex<double>>& from, const View1<Kokkos::complex<T>>& to) {
  Kokkos::parallel_for(
      "polymech::helmholtz::to_precision", range(static_cast<Index>(from.extent(0))),
      KOKKOS_LAMBDA(const Index i) { to(i) = Kokkos::complex<T>(static_cast<T>(from(i).real()), static_cast<T>(from(i).imag())); });
}

template <class T>
void to_double(const View1<Kokkos::complex<T>>& from, const View1<Kokkos::complex<double>>& to) {
  Kokkos::parallel_for(
      "polymech::helmholtz::to_double", range(static_cast<Index>(from.extent(0))), KOKKOS_LAMBDA(const Index i) {
        to(i) = Kokkos::complex<double>(static_cast<double>(from(i).real()), static_cast<double>(from(i).imag()));
      });
}

template <class V>
void subtract(const View1<V>& a, const View1<V>& b) {  // a -= b
  Kokkos::parallel_for(
      "polymech::helmholtz::lift_rhs", range(static_cast<Index>(a.extent(0))), KOKKOS_LAMBDA(const Index i) { a(i) -= b(i); });
}

}  // namespace detail

// Faces of one boundary kind, as the model sets them up (host description, also used by the assembled
// reference): the boundary faces and one coefficient per face.
struct FaceTerm {
  std::vector<BoundaryFace> faces;
  std::vector<std::complex<double>> coefficient;
};

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
  FaceTerm face_term(BoundaryKind kind) const {
    FaceTerm t;
    for (const auto& f : faces_of(kind)) {
      t.faces.push_back(f);
      t.coefficient.push_back(face_coefficient(kind, f.boundary));
    }
    return t;
  }
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

  std::complex<double> face_coefficient(BoundaryKind kind, int boundary) const {
    for (const auto& b : cfg_.boundaries)
      if (b.kind == kind && cfg_.mesh.boundary_index(b.name) == boundary) {
        if (kind == BoundaryKind::impedance) return {0.0, cfg_.density * cfg_.omega() / b.impedance};  // j rho omega / Zn
        if (kind == BoundaryKind::vibrating) return {b.velocity, 0.0};                                // eq. (20)
      }
    return {0.0, 0.0};
  }

  std::vector<BoundaryFace> faces_of(BoundaryKind kind) const {
    std::vector<BoundaryFace> out;
    for (const auto& b : cfg_.boundaries) {
      if (b.kind != kind) continue;
      const int id = cfg_.mesh.boundary_index(b.name);
      for (const auto& f : cfg_.mesh.boundary_faces)
        if (f.boundary == id) out.push_back(f);
    }
    return out;
  }

  fem::HexFaces<T, C> build_faces(BoundaryKind kind, const std::vector<char>& constrained, const std::string& name);

  // Elements per chunk. On a device, one (every element its own thread). On the host about 8000 element
  // nodes, so that a thread reuses the DoFs its chunk's elements share while they are in cache (1M DoFs,
  // one thread: p = 2 1.5x, p = 3 1.4x, p = 4 1.4x faster than one element per chunk; p = 1 the same;
  // docs/PERFORMANCE.md), but at least 64 chunks per thread so that the colours still balance.
  // A multiple of the batch size, so that only the last batch of a chunk can be partial.
  static std::int64_t chunk_size(const Config& c, int batch) {
    if (c.chunk_elements > 0) return c.chunk_elements;
    if (!Kokkos::SpaceAccessibility<HostSpace, MemSpace>::accessible) return batch;
    const std::int64_t n = c.order + 1;
    const std::int64_t balance = c.mesh.element_count() / (64 * std::max(1, kx::concurrency<ExecSpace>()));
    const std::int64_t size = std::max<std::int64_t>(1, std::min<std::int64_t>(8000 / (n * n * n), balance));
    return (size + batch - 1) / batch * batch;
  }

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

template <class T>
Helmholtz<T>::Helmholtz(const Config& c) : cfg_(c) {
  const auto t0 = std::chrono::steady_clock::now();
  validate(c);
  field_ = AnalyticField::from(c);
  const std::vector<std::int64_t> traversal = locality_order(c.mesh);
  dofs_ = number_dofs(c.mesh, c.order, traversal);
  if (c.node_perturbation > 0) {
    const auto ext = exterior_faces(c.mesh);
    perturb_nodes(dofs_, dofs_on_faces(dofs_, ext), c.node_perturbation, mean_element_size() / c.order);
  }
  const int N3 = dofs_.nodes_per_element();

  // this rank's part: its elements, local DoFs (owned, then ghosts) and halo (distribute.hpp)
  comm_ = c.communicator ? c.communicator : std::make_shared<SerialCommunicator>();
  layout_ = make_part_layout(c.mesh, dofs_, traversal, comm_->rank(), comm_->size(), c.partition);
  const Index n = static_cast<Index>(layout_.global_of_local.size());
  const auto& local = layout_.local_of_global;

  // Dirichlet DoFs (global mask, then local)
  std::vector<char> constrained_global(static_cast<std::size_t>(dofs_.count), 0);
  if (c.effects.has("dirichlet")) constrained_global = dofs_on_faces(dofs_, faces_of(BoundaryKind::dirichlet));
  std::vector<char> constrained(static_cast<std::size_t>(n), 0);
  for (Index i = 0; i < n; ++i) constrained[i] = constrained_global[layout_.global_of_local[i]];
  auto encode = [&](std::int32_t global) {
    const std::int32_t d = local[global];
    return constrained[d] ? fem::constrained_dof(d) : d;
  };

  // elements in chunks of neighbours (the locality order), the chunks grouped by colour
  const std::vector<std::int64_t>& elements = layout_.elements;
  const std::int64_t ne = static_cast<std::int64_t>(elements.size());
  const int batch = c.batch_elements > 0 ? c.batch_elements : fem::volume_batch<T>();
  const std::int64_t per_chunk = chunk_size(c, batch);
  const std::int64_t nchunks = (ne + per_chunk - 1) / per_chunk;
  std::vector<std::int64_t> chunk_vertex_offsets(1, 0), chunk_vertices;
  for (std::int64_t k = 0; k < nchunks; ++k) {
    const std::size_t first = chunk_vertices.size();
    for (std::int64_t t = k * per_chunk; t < std::min(ne, (k + 1) * per_chunk); ++t)
      for (int v = 0; v < 8; ++v) chunk_vertices.push_back(c.mesh.hexes[8 * elements[t] + v]);
    std::sort(chunk_vertices.begin() + static_cast<std::ptrdiff_t>(first), chunk_vertices.end());
    chunk_vertices.erase(std::unique(chunk_vertices.begin() + static_cast<std::ptrdiff_t>(first), chunk_vertices.end()),
                         chunk_vertices.end());
    chunk_vertex_offsets.push_back(static_cast<std::int64_t>(chunk_vertices.size()));
  }
  std::vector<std::int64_t> chunk_order;
  std::vector<std::int32_t> offsets;
  sort_by_color(color_by_shared_vertices(chunk_vertex_offsets, chunk_vertices, c.mesh.vertex_count()), chunk_order,
                offsets);
  std::vector<Index> chunk_start(1, 0);
  for (const std::int64_t k : chunk_order) {
    for (std::int64_t t = k * per_chunk; t < std::min(ne, (k + 1) * per_chunk); ++t)
      element_order_.push_back(elements[t]);
    chunk_start.push_back(static_cast<Index>(element_order_.size()));
  }
  el_.order = c.order;
  el_.batch = batch;
  el_.owned = layout_.owned;
  el_.ghost = n - layout_.owned;
  el_.color_offsets.assign(offsets.begin(), offsets.end());
  el_.chunk_offsets = models::to_device<Index>("polymech::helmholtz::chunk_offsets", chunk_start);
  el_.dofs = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::helmholtz::element_dofs",
                                                                   element_order_.size(), N3);
  {
    auto h = Kokkos::create_mirror_view(el_.dofs);
    for (std::size_t s = 0; s < element_order_.size(); ++s)
      for (int a = 0; a < N3; ++a) h(s, a) = encode(dofs_.element_dofs[element_order_[s] * N3 + a]);
    Kokkos::deep_copy(el_.dofs, h);
  }
  x_ = CoordinateView("polymech::helmholtz::coordinates", n);
  {
    auto h = Kokkos::create_mirror_view(x_);
    for (Index i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) h(i, k) = dofs_.coordinates[3 * static_cast<std::size_t>(layout_.global_of_local[i]) + k];
    Kokkos::deep_copy(x_, h);
  }
  jacobian_ = fem::compute_geometry(el_, x_, c.affine_geometry);
  {  // the worst element over all parts (a part without the worst reports +1e300)
    double w[2] = {-jacobian_.min_ratio, static_cast<double>(comm_->rank())};
    comm_->max(w, 1);
    if (-w[0] < jacobian_.min_ratio) jacobian_.element = -1;  // another part holds it
    jacobian_.min_ratio = -w[0];
  }
  // the elements each part counts in integrals (eq. (28)): its own, not the overlap
  {
    std::vector<std::int64_t> counted;
    for (const auto e : element_order_)
      if (layout_.counts(e)) counted.push_back(e);
    error_dofs_ = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::helmholtz::error_dofs", counted.size(), N3);
    auto h = Kokkos::create_mirror_view(error_dofs_);
    for (std::size_t s = 0; s < counted.size(); ++s)
      for (int a = 0; a < N3; ++a) h(s, a) = local[dofs_.element_dofs[counted[s] * N3 + a]];
    Kokkos::deep_copy(error_dofs_, h);
  }
  if (!(jacobian_.min_ratio > 0.0))
    throw std::invalid_argument(
        "helmholtz: " +
        (jacobian_.element >= 0 ? c.mesh.describe_element(element_order_[jacobian_.element]) : std::string("an element")) +
        " is inverted or too distorted: det J / (volume / 8) = " + models::format_g(jacobian_.min_ratio) +
        " at a node or quadrature point of the order-" + std::to_string(c.order) +
        " map (allowed: > 0 everywhere); check the vertex order (Gmsh hexahedron numbering) and the distortion");

  // boundary faces of the enabled effects
  fem::HexFaces<T, C> impedance;
  if (c.effects.has("impedance")) impedance = build_faces(BoundaryKind::impedance, constrained, "impedance");
  if (c.effects.has("vibrating")) vibrating_ = build_faces(BoundaryKind::vibrating, constrained, "vibrating");

  // constrained DoFs and their values
  if (c.effects.has("dirichlet")) {
    std::vector<Index> list;
    for (Index i = 0; i < n; ++i)
      if (constrained[i]) list.push_back(i);
    constrained_ = models::to_device<Index>("polymech::helmholtz::dirichlet_dofs", list);
    double value = 0.0;
    for (const auto& b : c.boundaries)
      if (b.kind == BoundaryKind::dirichlet) value = b.value;
    View1<Kokkos::complex<double>> g("polymech::helmholtz::dirichlet_values_double", list.size());
    detail::dirichlet_data(constrained_, x_, field_, value, field_.kind != AnalyticKind::none, g);
    dirichlet_values_ = View1<C>("polymech::helmholtz::dirichlet_values", list.size());
    detail::to_precision(g, dirichlet_values_);
  }
  const double k = c.wavenumber();
  op_ = HelmholtzOperator<T>(el_, impedance, constrained_, static_cast<T>(-k * k));
  if (comm_->size() > 1)
    op_.distribute(std::make_shared<Halo<C>>(comm_, layout_.neighbours, layout_.send, layout_.recv), comm_);
  solution_ = View1<C>("polymech::helmholtz::solution", n);
  Kokkos::fence();
  setup_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

template <class T>
void Helmholtz<T>::right_hand_side(const View1<C>& rhs, const View1<C>& x0) const {
  Kokkos::deep_copy(rhs, C(0));
  Kokkos::deep_copy(x0, C(0));
  if (vibrating_.faces() > 0) fem::add_face_load(vibrating_, rhs);
  if (constrained_.extent(0) > 0) {
    fem::set_constrained_values(constrained_, dirichlet_values_, x0);
    View1<C> lift("polymech::helmholtz::dirichlet_lift", rhs.extent(0));
    op_.apply_unconstrained(x0, lift);
    detail::subtract(rhs, lift);
    fem::set_constrained_values(constrained_, dirichlet_values_, rhs);
  }
}

template <class T>
solvers::SolveResult Helmholtz<T>::solve(const solvers::SolverOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  const Index n = op_.local_size();
  View1<C> rhs("polymech::helmholtz::rhs", n);
  right_hand_side(rhs, solution_);
  View1<C> inv;
  if (cfg_.preconditioner == Preconditioner::chebyshev || cfg_.preconditioner == Preconditioner::pmg) {
    const auto tp = std::chrono::steady_clock::now();
    if (cfg_.preconditioner == Preconditioner::chebyshev) {
      const ChebyshevPreconditioner<T> P(*this, cfg_.shifted);
      preconditioner_ = P.describe();
      preconditioner_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
      result_ = solvers::cocg_preconditioned(op_, P, rhs, solution_, options);
    } else {
      if (comm_->size() > 1)
        throw std::invalid_argument("helmholtz: preconditioner 'pmg' runs on one part only (its transfers have no halo "
                                    "exchange); allowed with " + std::to_string(comm_->size()) + " ranks: jacobi, "
                                    "chebyshev, none");
      const PMultigrid<T> P(*this, cfg_.shifted);
      preconditioner_ = P.describe();
      preconditioner_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - tp).count();
      result_ = solvers::cocg_preconditioned(op_, P, rhs, solution_, options);
    }
    Kokkos::fence();
    solve_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result_;
  }
  if (cfg_.preconditioner == Preconditioner::jacobi) {
    View1<C> diag("polymech::helmholtz::diagonal", n);
    op_.diagonal(diag);
    inv = View1<C>("polymech::helmholtz::inverse_diagonal", n);
    auto s = solvers::jacobi_inverse(op_.owned_size(), n, diag, inv);
    {  // over all parts
      double v[3] = {-s.min_abs, s.max_abs, static_cast<double>(s.non_finite)};
      comm_->max(v, 2);
      comm_->sum(v + 2, 1);
      if (-v[0] < s.min_abs) s.argmin = -1;
      s.min_abs = -v[0];
      s.max_abs = v[1];
      s.non_finite = static_cast<Index>(v[2]);
    }
    if (s.non_finite > 0 || !(s.min_abs > 1e-12 * s.max_abs))
      throw std::runtime_error("helmholtz: the operator diagonal " +
                               (s.non_finite > 0 ? std::string("is not finite")
                                                 : "vanishes (|d| = " + models::format_g(s.min_abs) + " vs max " +
                                                       models::format_g(s.max_abs) + ") at DoF " +
                                                       std::to_string(s.argmin) + " " + where(s.argmin)) +
                               ": Jacobi preconditioning is impossible at this k h; refine the mesh or set "
                               "solver.preconditioner = \"none\"");
  }
  result_ = solvers::cocg(op_, inv, rhs, solution_, options);
  Kokkos::fence();
  solve_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result_;
}

template <class T>
double Helmholtz<T>::apply_rate(int applies) const {
  const Index n = op_.local_size();
  View1<C> x("polymech::helmholtz::rate_x", n), y("polymech::helmholtz::rate_y", n);
  Kokkos::deep_copy(x, C(1));
  op_.apply(x, y);
  Kokkos::fence();
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < applies; ++k) op_.apply(x, y);
  Kokkos::fence();
  double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  comm_->max(&s, 1);  // the slowest part
  return s > 0 ? static_cast<double>(dofs_.count) * applies / s : 0.0;
}

template <class T>
fem::ErrorIntegrals Helmholtz<T>::l2_error() const {
  if (field_.kind == AnalyticKind::none) throw std::invalid_argument("helmholtz: this case has no analytic field");
  if (op_.halo()) op_.halo()->update(solution_);  // the ghosts of the elements this part integrates
  View1<Kokkos::complex<double>> u("polymech::helmholtz::solution_double", solution_.extent(0));
  detail::to_double(solution_, u);
  fem::ErrorIntegrals e = fem::l2_error(cfg_.order, error_dofs_, x_, u, field_);
  double v[3] = {e.error2, e.reference2, e.volume};
  comm_->sum(v, 3);
  return {v[0], v[1], v[2]};
}

template <class T>
std::vector<std::complex<double>> Helmholtz<T>::host_solution() const {
  auto m = Kokkos::create_mirror_view_and_copy(HostSpace(), solution_);
  if (comm_->size() == 1) {
    std::vector<std::complex<double>> out(m.extent(0));
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = {static_cast<double>(m(i).real()), static_cast<double>(m(i).imag())};
    return out;
  }
  // owned values with their global indices, gathered on rank 0
  std::vector<double> mine;
  mine.reserve(3 * static_cast<std::size_t>(layout_.owned));
  for (Index i = 0; i < layout_.owned; ++i)
    mine.insert(mine.end(), {static_cast<double>(layout_.global_of_local[i]), static_cast<double>(m(i).real()),
                             static_cast<double>(m(i).imag())});
  const std::vector<double> all = comm_->gather(mine);
  std::vector<std::complex<double>> out(comm_->rank() == 0 ? static_cast<std::size_t>(dofs_.count) : 0);
  for (std::size_t k = 0; k + 2 < all.size(); k += 3) out[static_cast<std::size_t>(all[k])] = {all[k + 1], all[k + 2]};
  return out;
}

template <class T>
std::vector<char> Helmholtz<T>::constrained_mask() const {
  std::vector<char> mask(static_cast<std::size_t>(dofs_.count), 0);
  auto h = Kokkos::create_mirror_view_and_copy(HostSpace(), constrained_);
  for (std::size_t k = 0; k < h.extent(0); ++k) mask[layout_.global_of_local[h(k)]] = 1;
  return mask;
}

template <class T>
auto Helmholtz<T>::build_faces(BoundaryKind kind, const std::vector<char>& constrained, const std::string& name)
    -> fem::HexFaces<T, C> {
  FaceTerm term;  // this part's faces: those of its elements
  {
    const FaceTerm all = face_term(kind);
    std::vector<char> here(static_cast<std::size_t>(cfg_.mesh.element_count()), 0);
    for (const auto e : layout_.elements) here[e] = 1;
    for (std::size_t i = 0; i < all.faces.size(); ++i)
      if (here[all.faces[i].element]) {
        term.faces.push_back(all.faces[i]);
        term.coefficient.push_back(all.coefficient[i]);
      }
  }
  const int N = dofs_.n1d, N3 = dofs_.nodes_per_element();
  std::vector<std::int64_t> verts;
  for (const auto& f : term.faces)
    for (int v : hex_face_vertices(f.face)) verts.push_back(cfg_.mesh.hexes[8 * f.element + v]);
  std::vector<std::int64_t> order;
  std::vector<std::int32_t> offsets;
  sort_by_color(color_by_shared_vertices(verts, 4, cfg_.mesh.vertex_count()), order, offsets);
  fem::HexFaces<T, C> f;
  f.order = cfg_.order;
  f.color_offsets.assign(offsets.begin(), offsets.end());
  const std::string prefix = "polymech::helmholtz::" + name;
  f.dofs = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>(prefix + "_face_dofs", order.size(), N * N);
  f.coefficient = View1<C>(prefix + "_face_coefficients", order.size());
  auto hd = Kokkos::create_mirror_view(f.dofs);
  auto hc = Kokkos::create_mirror_view(f.coefficient);
  for (std::size_t s = 0; s < order.size(); ++s) {
    const BoundaryFace& bf = term.faces[order[s]];
    const auto nodes = face_local_nodes(N, bf.face);
    for (int a = 0; a < N * N; ++a) {
      const std::int32_t d = layout_.local_of_global[dofs_.element_dofs[bf.element * N3 + nodes[a]]];
      hd(s, a) = constrained[d] ? fem::constrained_dof(d) : d;
    }
    const auto cf = term.coefficient[order[s]];
    hc(s) = C(static_cast<T>(cf.real()), static_cast<T>(cf.imag()));
  }
  Kokkos::deep_copy(f.dofs, hd);
  Kokkos::deep_copy(f.coefficient, hc);
  const double ratio = fem::compute_face_weights(f, x_, prefix + "_face_weights");
  if (!(ratio > 0.0))
    throw std::invalid_argument("helmholtz: a " + name + " boundary face is degenerate (zero area at a point)");
  return f;
}

// Compiled once, in models/helmholtz/helmholtz.cpp (library polymech_helmholtz): the kernels of four
// orders in two precisions are instantiated there and not in every file that uses the model.
extern template class Helmholtz<double>;
extern template class Helmholtz<float>;

}  // namespace polymech::helmholtz
