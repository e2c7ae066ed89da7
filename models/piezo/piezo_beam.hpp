// The finite-element piezoelectric beam (issue 35; seed 002 paper 1 eqs. (4)-(10)): a layered cantilever or
// free plate of piezoceramic and elastic layers, in 2D (plane stress or plane strain, the (length, thickness)
// plane) or 3D, with displacement and electric potential at the nodes (Lagrange order 1..4), electrodes as
// equipotential surfaces with one unknown each, a conducting grounded host (eq. (7)) and an external circuit.
// The matrices are assembled once (models/piezo/assembly.hpp) and the solvers (static, harmonic, natural
// frequencies here; time domain in models/piezo/transient.hpp) factorise them with the host sparse LU, which is
// the fast choice at these sizes (issue 34 measured the direct solve against CG on the same solid elements).
//
// This file holds the class: its accessors, the static, harmonic and natural-frequency solves, the scaling of
// the coupled matrix and the assembly of the matrices; the spec is models/piezo/beam_spec.hpp, the mesh and the
// numbering of the unknowns (the members check_spec .. number_unknowns) models/piezo/beam_mesh.hpp. Include
// models/piezo/beam_model.hpp, which holds all three.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#include "piezo/assembly.hpp"
#include "piezo/beam_spec.hpp"
#include "piezo/bordered_solver.hpp"
#include "piezo/circuit.hpp"
#include "solid/discretization.hpp"
#include "solvers/host_sparse_lu.hpp"

namespace polymech::piezo {

class PiezoBeam {
 public:
  explicit PiezoBeam(const BeamSpec& spec) : spec_(spec) {
    check_spec();
    build_mesh();
    number_unknowns();
    assemble();
  }

  const BeamSpec& spec() const { return spec_; }
  int dim() const { return spec_.dim; }
  std::int64_t unknowns() const { return n_; }
  std::int64_t displacement_unknowns() const { return nu_; }
  std::int64_t nodes() const { return disc_.nodes; }
  int electrodes() const { return static_cast<int>(electrode_dof_.size()); }
  int electrode(const std::string& name) const {
    for (std::size_t k = 0; k < electrode_names_.size(); ++k)
      if (electrode_names_[k] == name) return static_cast<int>(k);
    throw std::invalid_argument("piezo beam: no floating or prescribed electrode named '" + name + "'");
  }
  std::int64_t electrode_unknown(int k) const { return electrode_dof_[static_cast<std::size_t>(k)]; }
  const HostCsr& K() const { return K_; }
  const HostCsr& M() const { return M_; }
  const HostCsr& Kuu() const { return Kuu_; }
  const SparseTriplets& K_triplets() const { return Kt_; }
  const SparseTriplets& M_triplets() const { return Mt_; }
  const SparseTriplets& Kuu_triplets() const { return Kuut_; }
  // The unit base translation along the thickness on the displacement unknowns (zero elsewhere).
  const std::vector<double>& base_direction() const { return r_; }
  // Unknown of component c at node v, or -1.
  std::int64_t dof_u(std::int64_t v, int c) const { return dof_u_[static_cast<std::size_t>(dim() * v + c)]; }
  std::int64_t dof_phi(std::int64_t v) const { return dof_phi_[static_cast<std::size_t>(v)]; }
  const std::vector<double>& coordinates() const { return disc_.coordinates; }

  // The tip deflection: the mean thickness-direction displacement over the nodes at x = L.
  template <class S>
  S tip(const std::vector<S>& x) const {
    S s{};
    for (const auto d : tip_dofs_) s += x[static_cast<std::size_t>(d)];
    return s / static_cast<double>(tip_dofs_.size());
  }
  // The electrode charges of a state: Q_k = -(K x)_k on the electrode rows (assembly.hpp), mechanical load free.
  std::vector<double> charges(const std::vector<double>& x) const {
    std::vector<double> y;
    K_.apply(x, y);
    std::vector<double> Q(electrode_dof_.size());
    for (std::size_t k = 0; k < Q.size(); ++k) Q[k] = -y[static_cast<std::size_t>(electrode_dof_[k])];
    return Q;
  }
  std::vector<double> electrode_potentials(const std::vector<double>& x) const {
    std::vector<double> V(electrode_dof_.size());
    for (std::size_t k = 0; k < V.size(); ++k) V[k] = x[static_cast<std::size_t>(electrode_dof_[k])];
    return V;
  }
  bool prescribed(int k) const { return electrode_kind_[static_cast<std::size_t>(k)] == ElectrodeKind::prescribed; }

  // Static solve: the prescribed electrodes at their potentials, the floating ones charge-free (open), no
  // mechanical load. Returns the full unknown vector.
  std::vector<double> solve_static() const {
    SparseTriplets A = with_prescribed_rows(Kt_);
    std::vector<double> b(static_cast<std::size_t>(n_), 0.0);
    for (std::size_t k = 0; k < electrode_dof_.size(); ++k)
      if (electrode_kind_[k] == ElectrodeKind::prescribed) b[static_cast<std::size_t>(electrode_dof_[k])] = electrode_value_[k];
    BorderedSolver<double> lu;
    factor(A, lu);
    lu.solve(b);
    return b;
  }

  // The natural angular frequencies of the lowest mode, short circuit (every electrode grounded) or open
  // circuit (every electrode floating, no circuit), by inverse iteration on the coupled matrix (its solve is
  // (Kuu + Kuphi Kpp^-1 Kuphi^T)^-1, the condensed stiffness, which is positive definite) [rad/s].
  double natural_frequency(bool short_circuit, int iterations = 30) const {
    const SparseTriplets A = short_circuit ? with_grounded_electrodes(Kt_) : Kt_;
    BorderedSolver<double> lu;
    factor(A, lu);
    std::vector<double> x(r_), y, Mx;
    double lambda = 0.0;
    for (int it = 0; it < iterations; ++it) {
      M().apply(x, Mx);
      y = Mx;
      lu.solve(y);
      for (std::size_t i = static_cast<std::size_t>(nu_); i < y.size(); ++i) Mx[i] = 0.0;
      double xMx = 0.0, xMy = 0.0;
      for (std::int64_t i = 0; i < nu_; ++i) {
        xMx += x[static_cast<std::size_t>(i)] * Mx[static_cast<std::size_t>(i)];
        xMy += y[static_cast<std::size_t>(i)] * Mx[static_cast<std::size_t>(i)];
      }
      const double next = xMx / xMy;
      double norm = 0.0;
      for (const double v : y) norm = std::max(norm, std::fabs(v));
      for (std::size_t i = 0; i < y.size(); ++i) x[i] = y[i] / norm;
      if (it > 2 && std::fabs(next - lambda) <= 1e-14 * next) {
        lambda = next;
        break;
      }
      lambda = next;
    }
    return std::sqrt(lambda);
  }

  // The steady response at w [rad/s] to a unit base acceleration with the circuit (floating electrodes
  // without a branch are open) and Rayleigh damping: one complex factorisation and solve,
  //   [Kuu - w^2 M + i w C, Kuphi; Kuphi^T, -Kpp + (i / w) G] x = [-M r; 0]
  // (the electrode rows: i w Q = -G V and -Q = Kuphi^T u - Kpp phi, assembly.hpp and circuit.hpp).
  HarmonicResponse harmonic(double omega, const Circuit& circuit, const Rayleigh& damping) const {
    return harmonic(omega, std::vector<Circuit>{circuit}, damping).front();
  }

  // The same for several circuits at one frequency: the circuit enters the electrode block only, so one
  // factorisation serves them all (the bordered solve's Schur complement gains (i/w) G per circuit).
  std::vector<HarmonicResponse> harmonic(double omega, const std::vector<Circuit>& circuits, const Rayleigh& damping) const {
    using C = std::complex<double>;
    if (!(omega > 0.0)) throw std::invalid_argument("piezo beam: harmonic solve needs w > 0");
    for (const auto& c : circuits) check_circuit(c);
    const C iw(0.0, omega);
    std::vector<std::int64_t> rows, cols;
    std::vector<C> vals;
    rows.reserve(Kt_.values.size() + Kuut_.values.size() + Mt_.values.size());
    cols.reserve(rows.capacity());
    vals.reserve(rows.capacity());
    for (std::size_t k = 0; k < Kt_.values.size(); ++k) {
      rows.push_back(Kt_.rows[k]);
      cols.push_back(Kt_.cols[k]);
      vals.push_back(Kt_.values[k]);
    }
    for (std::size_t k = 0; k < Kuut_.values.size(); ++k) {
      rows.push_back(Kuut_.rows[k]);
      cols.push_back(Kuut_.cols[k]);
      vals.push_back(iw * damping.beta * Kuut_.values[k]);
    }
    for (std::size_t k = 0; k < Mt_.values.size(); ++k) {
      rows.push_back(Mt_.rows[k]);
      cols.push_back(Mt_.cols[k]);
      vals.push_back((-omega * omega + iw * damping.alpha) * Mt_.values[k]);
    }
    BorderedSolver<C> lu;
    lu.factor(n_, electrodes(), rows, cols, vals, scales());
    std::vector<double> Mr;
    M().apply(r_, Mr);
    const int ne = electrodes();
    std::vector<HarmonicResponse> out;
    out.reserve(circuits.size());
    for (const auto& circuit : circuits) {
      const std::vector<double> G = circuit.conductance();
      std::vector<C> add(G.size());
      for (std::size_t k = 0; k < G.size(); ++k) add[k] = C(0.0, G[k] / omega);
      std::vector<C> x(static_cast<std::size_t>(n_));
      for (std::size_t i = 0; i < x.size(); ++i) x[i] = -Mr[i];
      lu.solve(x, add);
      HarmonicResponse h;
      h.omega = omega;
      h.tip = tip(x);
      h.V.resize(static_cast<std::size_t>(ne));
      for (int k = 0; k < ne; ++k) h.V[static_cast<std::size_t>(k)] = x[static_cast<std::size_t>(electrode_dof_[static_cast<std::size_t>(k)])];
      for (const auto& rs : circuit.resistors()) {
        const C va = rs.a == Circuit::ground ? C(0.0) : h.V[static_cast<std::size_t>(rs.a)];
        const C vb = rs.b == Circuit::ground ? C(0.0) : h.V[static_cast<std::size_t>(rs.b)];
        h.power += 0.5 * std::norm(va - vb) / rs.R;
      }
      // mean input power 1/2 Re(F^H v) with F = -M r, v = i w u; damping 1/2 w^2 u^H C u
      std::vector<double> ur(static_cast<std::size_t>(n_), 0.0), ui(ur.size());
      for (std::int64_t i = 0; i < nu_; ++i) {
        ur[static_cast<std::size_t>(i)] = x[static_cast<std::size_t>(i)].real();
        ui[static_cast<std::size_t>(i)] = x[static_cast<std::size_t>(i)].imag();
      }
      C Fv(0.0);
      for (std::int64_t i = 0; i < nu_; ++i) Fv += -Mr[static_cast<std::size_t>(i)] * iw * x[static_cast<std::size_t>(i)];
      h.power_in = 0.5 * Fv.real();
      const double uCu =
          damping.alpha * (M().dot(ur, ur) + M().dot(ui, ui)) + damping.beta * (Kuu().dot(ur, ur) + Kuu().dot(ui, ui));
      h.power_damping = 0.5 * omega * omega * uCu;
      out.push_back(std::move(h));
    }
    return out;
  }

  // Symmetric scaling of the coupled matrix. Its blocks differ by ~19 orders of magnitude (stiffness ~1e9 Pa m,
  // permittivity ~1e-10 F/m), and an LU of the raw matrix loses digits in the electrical block (a free layer's
  // capacitance came out 2e-6 off). The potentials are scaled by s = sqrt(max diag Kuu / max diag Kpp): the
  // solvers factorise S A S (S = diag(1, s)), solve for y = S^-1 x with the right-hand side S b.
  double potential_scale() const { return phi_scale_; }
  double unknown_scale(std::int64_t i) const { return i < nu_ ? 1.0 : phi_scale_; }
  std::vector<double> scales() const {
    std::vector<double> s(static_cast<std::size_t>(n_));
    for (std::int64_t i = 0; i < n_; ++i) s[static_cast<std::size_t>(i)] = unknown_scale(i);
    return s;
  }
  // A coupled matrix factorised with the electrodes as the border (BorderedSolver).
  void factor(const SparseTriplets& A, BorderedSolver<double>& lu) const {
    lu.factor(A.n, electrodes(), A.rows, A.cols, A.values, scales());
  }

  // The coupled matrix with every electrode grounded (its rows and columns replaced by the identity).
  SparseTriplets with_grounded_electrodes(const SparseTriplets& A) const {
    return with_identity_rows(A, [&](std::int64_t r) { return is_electrode_[static_cast<std::size_t>(r)] != 0; }, true);
  }
  // The coupled matrix with the prescribed electrodes' rows replaced by the identity (their columns kept:
  // the potential enters the other rows).
  SparseTriplets with_prescribed_rows(const SparseTriplets& A) const {
    return with_identity_rows(A, [&](std::int64_t r) { return is_prescribed_[static_cast<std::size_t>(r)] != 0; }, false);
  }

 private:
  template <class Pred>
  static SparseTriplets with_identity_rows(const SparseTriplets& A, Pred pred, bool columns_too) {
    SparseTriplets B;
    B.n = A.n;
    B.rows.reserve(A.values.size());
    B.cols.reserve(A.values.size());
    B.values.reserve(A.values.size());
    for (std::size_t k = 0; k < A.values.size(); ++k) {
      if (pred(A.rows[k]) || (columns_too && pred(A.cols[k]))) continue;
      add_entry(B, A.rows[k], A.cols[k], A.values[k]);
    }
    for (std::int64_t r = 0; r < A.n; ++r)
      if (pred(r)) add_entry(B, r, r, 1.0);
    return B;
  }

  // The spec's checks, the mesh and the numbering of the unknowns (beam_mesh.hpp).
  void check_spec() const;
  // The lattice index through the thickness of an electrode surface.
  int surface_plane(const std::string& surface) const;
  void build_mesh();
  template <int D>
  void copy_disc(const solid::Discretization<D>& d);
  // lattice index of node v along direction d
  int lattice_index(std::int64_t v, int d) const;
  int layer_of_cell(std::int64_t cell) const;
  void number_unknowns();

  void assemble() {
    PiezoAssemblyInput in;
    in.dim = spec_.dim;
    in.order = spec_.order;
    in.width = spec_.width;
    in.element_nodes = disc_.element_nodes;
    in.coordinates = disc_.coordinates;
    in.laws.push_back(elastic_law(spec_.host, spec_.dim, spec_.plane));
    in.laws.push_back(piezo_law(spec_.piezo, spec_.dim, spec_.plane, 1));
    in.laws.push_back(piezo_law(spec_.piezo, spec_.dim, spec_.plane, -1));
    in.element_law.resize(element_layer_.size());
    for (std::size_t e = 0; e < element_layer_.size(); ++e) {
      const auto& l = spec_.layers[static_cast<std::size_t>(element_layer_[e])];
      in.element_law[e] = !l.piezoelectric ? 0 : (l.poling > 0 ? 1 : 2);
    }
    in.dof_u = dof_u_;
    in.dof_phi = dof_phi_;
    in.unknowns = n_;
    PiezoMatrices m = assemble_piezo(in);
    // merged (one entry per row and column): the CSR of each, and its triplets for the factorisations
    K_ = HostCsr(m.K);
    M_ = HostCsr(m.M);
    Kuu_ = HostCsr(m.Kuu);
    Kt_ = K_.triplets();
    Mt_ = M_.triplets();
    Kuut_ = Kuu_.triplets();
    double du = 0.0, dp = 0.0;
    for (std::size_t k = 0; k < Kt_.values.size(); ++k) {
      if (Kt_.rows[k] != Kt_.cols[k]) continue;
      double& d = Kt_.rows[k] < nu_ ? du : dp;
      d = std::max(d, std::fabs(Kt_.values[k]));
    }
    phi_scale_ = dp > 0.0 ? std::sqrt(du / dp) : 1.0;
  }

  void check_circuit(const Circuit& c) const {
    if (c.electrodes() != electrodes())
      throw std::invalid_argument("piezo beam: the circuit has " + std::to_string(c.electrodes()) +
                                  " electrodes, the beam " + std::to_string(electrodes()));
    for (int k = 0; k < electrodes(); ++k)
      if (prescribed(k))
        throw std::invalid_argument("piezo beam: electrode '" + electrode_names_[static_cast<std::size_t>(k)] +
                                    "' is prescribed; a circuit solve needs floating electrodes");
  }

  struct Mesh {
    std::int64_t nodes = 0;
    std::vector<double> coordinates;
    std::vector<std::int64_t> element_nodes, element_cells;
    std::vector<int> lattice, cells;
  };

  BeamSpec spec_;
  Mesh disc_;
  std::vector<int> layer_start_;  // first thickness cell of each layer, and the end
  std::vector<int> element_layer_;
  std::vector<std::int64_t> dof_u_, dof_phi_, electrode_dof_, tip_dofs_;
  std::vector<std::string> electrode_names_;
  std::vector<ElectrodeKind> electrode_kind_;
  std::vector<double> electrode_value_;
  std::vector<char> is_electrode_, is_prescribed_;
  std::vector<double> r_;
  std::int64_t n_ = 0, nu_ = 0;
  double phi_scale_ = 1.0;
  SparseTriplets Kt_, Mt_, Kuut_;
  HostCsr K_, M_, Kuu_;
};

}  // namespace polymech::piezo
