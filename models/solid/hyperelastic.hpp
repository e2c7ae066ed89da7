// The quasi-static finite-strain (total-Lagrangian) hyperelastic solid (issue 34: "St. Venant-Kirchhoff,
// neo-Hookean and Mooney-Rivlin for finite strain", "surface tractions (also follower pressure)").
//
// Laws (HyperelasticLaw): materials::StVenantKirchhoff (S = lambda tr(E) I + 2 mu E), materials::NeoHookean
// (W = mu/2 (I1 - 3 - 2 ln J) + lambda/2 (ln J)^2), materials::MooneyRivlin (decoupled:
// W = C10 (I1b - 3) + C01 (I2b - 3) + kappa/2 (J - 1)^2); kernels/materials/hyperelastic.hpp. 3D, and 2D plane
// strain (F_33 = 1); plane stress is refused (it would need the out-of-plane stretch as a local unknown).
//
// Loads, scaled by the load factor lambda: the dead loads of the Config (tractions per reference area and body
// forces per reference volume: the SolidProblem's f_ext), the Dirichlet values (u_c = lambda g) and follower
// pressures on named sides (FollowerPressure; kernels/solid/finite_strain.hpp: p times the current normal
// area). Residual r(u) = f_int(u) - lambda (f_ext + f_p(u)) on the free DoFs, zero on the constrained rows.
//
// Newton: solid::NewtonSolid (models/solid/newton.hpp: load paths with step cutting, the line search on the
// potential, the force test, reactions, monitor) with the hooks of this model: evaluate() is the residual
// above with the tangent, solve_tangent() assembles the exact tangent K = dr/du = K_int(u) (material +
// geometric, from A = dP/dF) + lambda K_p(u) (the follower load stiffness, not symmetric) on the host from the
// element and face matrices the Kokkos kernels compute, and factorizes it with the host sparse LU every iteration
// (TangentSolver::direct, the only solver here; finite_strain_newton_options()). The line search's slope
// du . r(u + alpha du) is the potential's (Pi = sum W - lambda f_ext . u - lambda p V) for dead loads and for
// pressure on a closed or edge-fixed surface; otherwise the same test on the Galerkin projection of r. A failed
// evaluation (J <= 0 or a non-finite W or P at any point: kernels/solid/finite_strain.hpp) halves alpha in the
// line search and fails the step (which is cut) when it occurs at the step's start: never a NaN iterate.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "materials/hyperelastic.hpp"
#include "solid/mass.hpp"
#include "solid/newton.hpp"
#include "solid/finite_strain.hpp"
#include "solid/problem.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::solid {

using HyperelasticLaw =
    std::variant<materials::StVenantKirchhoff<double>, materials::NeoHookean<double>, materials::MooneyRivlin<double>>;

// A follower pressure p (force per current area; positive pushes against the surface) on a side, times the
// load factor.
struct FollowerPressure {
  std::string boundary;
  double p = 0.0;
};

namespace detail {
template <class T>
materials::StVenantKirchhoff<T> cast_hyperelastic(const materials::StVenantKirchhoff<double>& l) {
  materials::StVenantKirchhoff<T> r;
  r.elastic.lambda = static_cast<T>(l.elastic.lambda);
  r.elastic.mu = static_cast<T>(l.elastic.mu);
  return r;
}
template <class T>
materials::NeoHookean<T> cast_hyperelastic(const materials::NeoHookean<double>& l) {
  materials::NeoHookean<T> r;
  r.elastic.lambda = static_cast<T>(l.elastic.lambda);
  r.elastic.mu = static_cast<T>(l.elastic.mu);
  return r;
}
template <class T>
materials::MooneyRivlin<T> cast_hyperelastic(const materials::MooneyRivlin<double>& l) {
  materials::MooneyRivlin<T> r;
  r.C10 = static_cast<T>(l.C10);
  r.C01 = static_cast<T>(l.C01);
  r.kappa = static_cast<T>(l.kappa);
  return r;
}
}  // namespace detail

// NewtonOptions with the direct solver (the one this model has).
inline NewtonOptions finite_strain_newton_options() {
  NewtonOptions o;
  o.solver = TangentSolver::direct;
  o.secant_predictor = true;  // measured: the elastica 113 -> 57 Newton iterations, Turek-Hron CSM1 40 -> 22
  return o;
}

template <class T, int D = 3>
class Hyperelastic : public NewtonSolid<T, D, Hyperelastic<T, D>> {
  using Base = NewtonSolid<T, D, Hyperelastic<T, D>>;

 public:
  Hyperelastic(const Config<D>& c, const HyperelasticLaw& law, const std::vector<FollowerPressure>& pressures = {},
               const NewtonOptions& o = finite_strain_newton_options())
      : Base(c, o, "solid::Hyperelastic"), law_(law) {
    if (c.plasticity) throw std::invalid_argument("solid::Hyperelastic: the configuration carries a plastic law");
    if (D == 2 && c.plane == Plane::stress)
      throw std::invalid_argument("solid::Hyperelastic: plane stress is not supported at finite strain (plane strain and 3D are)");
    if (o.solver != TangentSolver::direct)
      throw std::invalid_argument("solid::Hyperelastic: only TangentSolver::direct (the assembled tangent and the host "
                                  "sparse LU) is implemented");
    f_load_ = View1<T>("polymech::solid::fs_load", this->dof_count());
    set_up_pressure(pressures);
  }

  // Per-cell stiffness scales (issue 37: layered walls): cell c's law is the model's law with its moduli times
  // s[c] (kernels/solid/finite_strain.hpp, FiniteStrainElementData::scale), c the mesh's cell id (lattice order
  // i0 + c0 (i1 + c1 i2) on a lattice, the element on an unstructured mesh). Every s[c] must be finite and > 0.
  // An empty vector returns to the one law (nothing stored, the kernel's one-law path).
  void set_cell_scale(const std::vector<double>& s) {
    if (s.empty()) {
      elements_.scale = View1<T>();
      scale_max_ = 1.0;
      return;
    }
    const auto& cells = this->discretization().element_cells;
    std::vector<T> per_element(cells.size());
    scale_max_ = 0.0;
    for (std::size_t e = 0; e < cells.size(); ++e) {
      const std::int64_t c = cells[e];
      if (c < 0 || static_cast<std::size_t>(c) >= s.size())
        throw std::invalid_argument("solid::Hyperelastic::set_cell_scale: " + std::to_string(s.size()) + " scales for a mesh with cell " +
                                    std::to_string(c));
      const double v = s[static_cast<std::size_t>(c)];
      if (!(v > 0.0) || !std::isfinite(v))
        throw std::invalid_argument("solid::Hyperelastic::set_cell_scale: cell " + std::to_string(c) + " has scale " +
                                    std::to_string(v) + " (must be finite and > 0)");
      per_element[e] = static_cast<T>(v);
      scale_max_ = std::fmax(scale_max_, v);
    }
    elements_.scale = models::to_device<T>("polymech::solid::fs_element_scale", per_element);
  }
  // The largest per-cell scale (1 with one law).
  double cell_scale_max() const { return scale_max_; }

  // Rebar (issue 37: the tyre's steel belt; seed 002 paper 2 §4, the belt reinforcements): two cord families per
  // cell at +-beta (beta_deg) to the element's direction 0 in its (0, 1) tangent plane, each with the fibre law of
  // kernels/solid/finite_strain.hpp (S_f = k E_a a (x) a), k = k[c] the family's smeared modulus in cell c (0: no
  // cords there), added to the matrix law (its cell scale applies to the matrix only). 3D only. An empty vector
  // removes them (nothing stored, the kernel's path without fibres).
  void set_fibres(const std::vector<double>& k, double beta_deg, bool tension_only = false) {
    if (k.empty()) {
      elements_.fibre = decltype(elements_.fibre)();
      return;
    }
    if (D != 3) throw std::invalid_argument("solid::Hyperelastic::set_fibres: cord families are for 3D solids");
    if (!(beta_deg >= 0.0 && beta_deg <= 90.0)) throw std::invalid_argument("solid::Hyperelastic::set_fibres: beta must be in [0, 90] deg");
    const auto& cells = this->discretization().element_cells;
    const double b = beta_deg * 3.14159265358979323846 / 180.0;
    decltype(elements_.fibre) dev("polymech::solid::fs_fibre", cells.size());
    auto h = Kokkos::create_mirror_view(dev);
    for (std::size_t e = 0; e < cells.size(); ++e) {
      const std::int64_t c = cells[e];
      if (c < 0 || static_cast<std::size_t>(c) >= k.size())
        throw std::invalid_argument("solid::Hyperelastic::set_fibres: " + std::to_string(k.size()) + " stiffnesses for a mesh with cell " +
                                    std::to_string(c));
      const double v = k[static_cast<std::size_t>(c)];
      if (!(v >= 0.0) || !std::isfinite(v))
        throw std::invalid_argument("solid::Hyperelastic::set_fibres: cell " + std::to_string(c) + " has cord stiffness " +
                                    std::to_string(v) + " (must be finite and >= 0)");
      h(e, 0) = static_cast<T>(v);
      h(e, 1) = static_cast<T>(std::cos(b));
      h(e, 2) = static_cast<T>(std::sin(b));
    }
    Kokkos::deep_copy(dev, h);
    elements_.fibre = dev;
    elements_.fibre_tension_only = tension_only;
  }
  bool has_fibres() const { return elements_.fibre.extent(0) > 0; }

  const PressureFaces<D>& pressure_faces() const { return pressure_; }
  // Strain energy of the last evaluation.
  double strain_energy() const { return energy_; }

  // r = f_int(u) - lambda (f_ext + f_p(u)) off the constrained rows (zero on them); returns |r|, or NaN when
  // the evaluation failed (J <= 0 or a non-finite value at a point). With tangent, also the element and face
  // matrices for assemble_tangent(). u must carry its Dirichlet values.
  double residual(const View1<T>& u, double lambda, const View1<T>& r, bool tangent = false) {
    Kokkos::deep_copy(this->f_int_, T(0));
    FiniteStrainEvaluation ev;
    std::visit(
        [&](const auto& l) {
          const auto lt = detail::cast_hyperelastic<T>(l);
          ev = tangent ? finite_strain_internal_force<true>(this->op_.el, lt, u, this->f_int_, elements_)
                       : finite_strain_internal_force<false>(this->op_.el, lt, u, this->f_int_, elements_);
        },
        law_);
    energy_ = ev.energy;
    if (c0_ > 0.0) add_inertia(u, this->f_int_);
    Kokkos::deep_copy(f_load_, this->f_ext_);
    if (nodal_load_.extent(0) > 0) {  // a consistent nodal force vector (set_nodal_load), a dead load like f_ext
      const auto fl = f_load_, fn = nodal_load_;
      Kokkos::parallel_for(
          "polymech::solid::fs_nodal_load", Kokkos::RangePolicy<ExecSpace>(0, this->dof_count()),
          KOKKOS_LAMBDA(const Index i) { fl(i) += fn(i); });
    }
    solvers::scale(this->dof_count(), static_cast<T>(lambda), f_load_, f_load_);
    if (pressure_.faces() > 0) {
      if (tangent)
        follower_pressure<true>(pressure_, this->x_, u, lambda, face_force_, face_stiffness_);
      else
        follower_pressure<false>(pressure_, this->x_, u, lambda, face_force_, face_stiffness_);
      scatter_pressure(pressure_, face_force_, f_load_);
    }
    const auto fi = this->f_int_, fl = f_load_;
    Kokkos::parallel_for(
        "polymech::solid::fs_residual", Kokkos::RangePolicy<ExecSpace>(0, this->dof_count()),
        KOKKOS_LAMBDA(const Index i) { r(i) = fi(i) - fl(i); });
    fem::fill_constrained(this->op_.constrained, T(0), r);
    if (ev.failed_elements > 0) return std::numeric_limits<double>::quiet_NaN();
    return std::sqrt(solvers::norm2("polymech::solid::fs_residual_norm", this->dof_count(), r));
  }

  // Nodal forces added to the dead loads f_ext (scaled by the load factor like them): D values per node, every
  // DoF (those on constrained rows go to the reactions). For loads that arrive as consistent nodal forces, such
  // as a fluid's reaction forces at the wet nodes of a partitioned coupling (models/fsi/turek_hron_fsi.hpp): the
  // force is passed as it is, so the momentum it carries is transferred exactly. An empty vector removes it.
  void set_nodal_load(const std::vector<double>& f) {
    if (f.empty()) {
      nodal_load_ = View1<T>();
      return;
    }
    if (f.size() != static_cast<std::size_t>(this->dof_count()))
      throw std::invalid_argument("solid::Hyperelastic: a nodal load needs " + std::to_string(this->dof_count()) +
                                  " values (D per node), got " + std::to_string(f.size()));
    std::vector<T> ft(f.begin(), f.end());
    nodal_load_ = models::to_device<T>("polymech::solid::nodal_load", ft);
  }

  // The tangent dr/du of the last residual(..., tangent = true) evaluation, assembled (identity on the
  // constrained rows and columns).
  Triplets assemble_tangent() const {
    Triplets t;
    t.n = this->dof_count();
    const int ND = this->disc_.nodes_per_element();
    const auto& en = this->disc_.element_nodes;
    append_matrices<D>(elements_.matrices, ND,
                       [&](std::size_t e, int a) { return en[e * static_cast<std::size_t>(ND) + static_cast<std::size_t>(a)]; },
                       this->constrained_, t);
    if (pressure_.faces() > 0) {
      const auto nh = Kokkos::create_mirror_view_and_copy(HostSpace(), pressure_.nodes);
      append_matrices<D>(face_stiffness_, static_cast<int>(nh.extent(1)),
                         [&](std::size_t f, int a) { return static_cast<std::int64_t>(nh(f, a)); }, this->constrained_, t);
    }
    if (c0_ > 0.0) {  // the inertia's c0 rho M (free-free block)
      if (mass_.n == 0) mass_ = assemble_mass(this->assembly_input(), 1.0);
      const double f = c0_ * rho_;
      for (std::size_t k = 0; k < mass_.values.size(); ++k) {
        t.rows.push_back(mass_.rows[k]);
        t.cols.push_back(mass_.cols[k]);
        t.values.push_back(f * mass_.values[k]);
      }
    }
    for (std::int64_t i = 0; i < t.n; ++i)
      if (this->constrained_[static_cast<std::size_t>(i)]) {
        t.rows.push_back(i);
        t.cols.push_back(i);
        t.values.push_back(1.0);
      }
    return t;
  }

  // The inertia of a Newmark step (models/solid/finite_strain_dynamics.hpp): with c0 > 0 the residual gains
  // c0 rho M (u - u_pred) (M the consistent mass of unit density, free-free block) and the tangent c0 rho M, so a
  // Newton solve finds u_{n+1} with M a_{n+1} + f_int(u_{n+1}) = f_ext, a_{n+1} = c0 (u_{n+1} - u_pred). It is
  // also the gradient of 1/2 c0 rho (u - u_pred)^T M (u - u_pred) + W(u) - f.u, so the line search keeps its
  // potential. c0 = 0: quasi-static again.
  void set_inertia(double c0, double rho, const View1<T>& u_pred) {
    if (!(c0 >= 0.0) || !(rho > 0.0)) throw std::invalid_argument("solid::Hyperelastic: inertia needs c0 >= 0, rho > 0");
    c0_ = c0;
    rho_ = rho;
    u_pred_ = u_pred;
    if (inertia_work_.extent(0) != u_pred.extent(0)) inertia_work_ = View1<T>("polymech::solid::fs_inertia", u_pred.extent(0));
  }
  // f += c0 rho M (u - u_pred) (public only for nvcc's extended lambda)
  void add_inertia(const View1<T>& u, const View1<T>& f) {
    const auto w = inertia_work_, a = u, b = u_pred_;
    Kokkos::parallel_for(
        "polymech::solid::fs_inertia_difference", Kokkos::RangePolicy<ExecSpace>(0, this->dof_count()),
        KOKKOS_LAMBDA(const Index i) { w(i) = a(i) - b(i); });
    add_mass_apply<true>(this->op_.el, static_cast<T>(c0_ * rho_), inertia_work_, f);
  }
  // y += rho M x on the free DoFs (the consistent mass, matrix-free).
  void add_mass(double rho, const View1<T>& x, const View1<T>& y) const {
    add_mass_apply<true>(this->op_.el, static_cast<T>(rho), x, y);
  }

  // --- the hooks of NewtonSolid (models/solid/newton.hpp) ---
  double evaluate(const View1<T>& u, double lambda, const View1<T>& r) { return residual(u, lambda, r, true); }
  double load_norm(double /*lambda*/) const { return this->free_norm(f_load_); }
  double load_sum(int c, double /*lambda*/) const {
    const std::vector<double> fl = models::to_host(f_load_);
    double s = 0.0;
    for (std::size_t i = static_cast<std::size_t>(c); i < fl.size(); i += D) s += fl[i];
    return s;
  }
  bool solve_tangent(StepResult& res) {
    try {
      const Triplets t = assemble_tangent();
      lu_.factor(t.n, t.rows, t.cols, t.values);
    } catch (const std::runtime_error& e) {
      this->last_failure_ = std::string("the tangent factorization failed: ") + e.what();
      return false;
    }
    detail::HostLUPreconditioner<T>{&lu_}.apply(this->r_, this->du_);
    res.linear_iterations += 1;
    return true;
  }
  void commit(StepResult& /*res*/) {}
  const char* failed_evaluation() const { return "a failed evaluation (J <= 0 or a non-finite stress)"; }

 private:
  void set_up_pressure(const std::vector<FollowerPressure>& pressures) {
    pressure_.order = this->config_.order;
    const int NF = D == 3 ? this->disc_.n1d * this->disc_.n1d : this->disc_.n1d;
    std::vector<std::int64_t> nodes;
    std::vector<double> sign, p;
    for (const auto& fp : pressures) {
      const auto ds = side_of<D>(fp.boundary);
      if (ds[0] < 0) throw std::invalid_argument("solid::Hyperelastic: unknown boundary '" + fp.boundary + "'");
      const auto f = side_faces(this->disc_, fp.boundary);
      nodes.insert(nodes.end(), f.begin(), f.end());
      for (std::size_t k = 0; k < f.size() / static_cast<std::size_t>(NF); ++k) {
        sign.push_back(outward_sign(ds[0], ds[1] != 0));
        p.push_back(fp.p);
      }
    }
    const std::size_t nf = sign.size();
    pressure_.nodes = Kokkos::View<Index**, Kokkos::LayoutRight, MemSpace>("polymech::solid::pressure_nodes", nf, NF);
    auto nh = Kokkos::create_mirror_view(pressure_.nodes);
    for (std::size_t f = 0; f < nf; ++f)
      for (int a = 0; a < NF; ++a) nh(f, a) = static_cast<Index>(nodes[f * NF + a]);
    Kokkos::deep_copy(pressure_.nodes, nh);
    pressure_.sign = models::to_device<double>("polymech::solid::pressure_sign", sign);
    pressure_.pressure = models::to_device<double>("polymech::solid::pressure_values", p);
  }

  HyperelasticLaw law_;
  double c0_ = 0.0, rho_ = 0.0;
  View1<T> u_pred_, inertia_work_;
  mutable Triplets mass_;  // the unit-density consistent mass, assembled on the first tangent with inertia
  PressureFaces<D> pressure_;
  FiniteStrainElementData<T> elements_;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> face_force_, face_stiffness_;
  View1<T> f_load_, nodal_load_;
  double energy_ = 0.0, scale_max_ = 1.0;
  solvers::HostSparseLU lu_;
};

}  // namespace polymech::solid
