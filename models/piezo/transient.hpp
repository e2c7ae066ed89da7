// The time-domain harvester (issue 35; seed 002 paper 1 eqs. (4)-(10)): the piezoelectric beam of
// models/piezo/beam_model.hpp under a prescribed base acceleration a_b(t) along the thickness, with Rayleigh
// damping and the circuit, integrated by Newmark (average acceleration by default) for the displacements and
// the trapezoidal rule for the electrodes' charge balance. In the frame of the base (relative displacements u,
// the root clamped) the base motion is the load F(t) = -M r a_b(t), r the unit translation (exact: K r = 0).
//
// Step n -> n+1, unknowns x = (u, phi, V) at n+1:
//   [Kuu + c0 M + c1 C,  Kuphi                ] x = [F_{n+1} + M (c0 u_n + c2 v_n + c3 a_n) + C (c1 u_n + c4 v_n + c5 a_n)]
//   [Kuphi^T,           -Kpp - (dt/2) G_border]     [-Q_n + (dt/2) G V_n   on the electrode rows, 0 elsewhere           ]
// (c0 = 1/(beta dt^2), c1 = gamma/(beta dt), c2 = 1/(beta dt), c3 = 1/(2 beta) - 1, c4 = gamma/beta - 1,
// c5 = dt (gamma/(2 beta) - 1)): the mechanical rows are Newmark's, the electrical rows Gauss's law (eq. (5)),
// and an electrode row is eq. (10) integrated by the trapezoidal rule, Q_{n+1} = Q_n - (dt/2) G (V_n + V_{n+1}),
// with Q = -(Kuphi^T u - Kpp phi) on its rows (assembly.hpp) and G the circuit's conductance (eq. (9)).
//
// Two schemes give the same x:
//   monolithic:  the whole matrix, factorised once (constant dt) with the electrodes as the border
//                (BorderedSolver): one sparse solve per step.
//   partitioned: paper 1's loop (its Fig. 2): the electrode potentials V are the unknowns of a nonlinear solver;
//                for given V the piezo-structure problem (u, phi) is solved with V as Dirichlet data, the charges
//                follow, and the charge residual r^Q(V) of eq. (10) is driven to zero by quasi-Newton (Broyden)
//                updates. Its Jacobian starts from finite differences at the first step (one extra solve per
//                electrode: the linear problem makes it exact) or, as an option, from the capacitance alone.
//
// Energy (exact for average acceleration with this trapezoidal charge balance; tested):
//   E = 1/2 v^T M v + 1/2 u^T Kuu u + 1/2 phi^T Kpp phi (strain and field energy),
//   E_{n+1} - E_n + dt v_avg^T C v_avg + dt V_avg^T G V_avg = (u_{n+1} - u_n)^T F_avg,
// so the base's work equals the energy dissipated in the resistor and the damping plus the stored energy.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "piezo/beam_model.hpp"

namespace polymech::piezo {

enum class Scheme { monolithic, partitioned };
inline const char* to_string(Scheme s) { return s == Scheme::monolithic ? "monolithic" : "partitioned"; }

struct TransientOptions {
  double dt = 0.0;
  Rayleigh damping{};
  Scheme scheme = Scheme::monolithic;
  double beta = 0.25, gamma = 0.5;  // Newmark (average acceleration)
  // partitioned: stop when every |r^Q_k| <= tolerance * (the charge scale Cp |V| + |Q|) or below 1e-30 C
  double tolerance = 1e-9;
  int max_iterations = 50;
  bool finite_difference_jacobian = true;  // false: start Broyden from the capacitance block alone
};

// Everything a restart needs.
struct TransientState {
  std::int64_t step = 0;
  double time = 0.0, base_acceleration = 0.0;
  std::vector<double> x, v, a, Q;  // unknowns, their rates (displacements only), electrode charges
  std::vector<double> jacobian;     // the partitioned loop's Broyden Jacobian (empty before its first step)
  std::vector<double> f_ext;        // the external nodal load of the last step (empty: none so far; fsi/flow_harvester.hpp)
  double work_in = 0.0, work_damping = 0.0, work_circuit = 0.0, energy0 = 0.0;
};

class PiezoTransient {
 public:
  PiezoTransient(const PiezoBeam& beam, const Circuit& circuit, const TransientOptions& o)
      : beam_(beam), circuit_(circuit), o_(o), G_(circuit.conductance()) {
    if (!(o.dt > 0.0) || !std::isfinite(o.dt)) throw std::invalid_argument("piezo transient: dt must be positive");
    if (!(o.beta > 0.0) || !(o.gamma >= 0.5))
      throw std::invalid_argument("piezo transient: Newmark needs beta > 0 and gamma >= 1/2");
    if (circuit.electrodes() != beam.electrodes())
      throw std::invalid_argument("piezo transient: the circuit has " + std::to_string(circuit.electrodes()) +
                                  " electrodes, the beam " + std::to_string(beam.electrodes()));
    for (int k = 0; k < beam.electrodes(); ++k)
      if (beam.prescribed(k)) throw std::invalid_argument("piezo transient: a prescribed electrode in a circuit run");
    const double dt = o.dt, b = o.beta, g = o.gamma;
    c_ = {1.0 / (b * dt * dt), g / (b * dt), 1.0 / (b * dt), 1.0 / (2.0 * b) - 1.0, g / b - 1.0, dt * (g / (2.0 * b) - 1.0)};
    const SparseTriplets& K = beam.K_triplets();
    const SparseTriplets& M = beam.M_triplets();
    const SparseTriplets& Kuu = beam.Kuu_triplets();
    SparseTriplets A = K;
    const double cm = c_[0] + c_[1] * o.damping.alpha, ck = c_[1] * o.damping.beta;
    for (std::size_t k = 0; k < M.values.size(); ++k) add_entry(A, M.rows[k], M.cols[k], cm * M.values[k]);
    if (ck != 0.0)
      for (std::size_t k = 0; k < Kuu.values.size(); ++k) add_entry(A, Kuu.rows[k], Kuu.cols[k], ck * Kuu.values[k]);
    const int ne = beam.electrodes();
    for (int i = 0; i < ne; ++i)
      for (int j = 0; j < ne; ++j) {
        const double gij = G_[static_cast<std::size_t>(i) * ne + j];
        if (gij != 0.0) add_entry(A, beam.electrode_unknown(i), beam.electrode_unknown(j), -0.5 * dt * gij);
      }
    beam.factor(A, solver_);
    // the capacitance block (for the partitioned scheme's optional start): the electrode rows of A
    cap_.assign(static_cast<std::size_t>(ne) * ne, 0.0);
    for (std::size_t k = 0; k < A.values.size(); ++k)
      for (int i = 0; i < ne; ++i)
        for (int j = 0; j < ne; ++j)
          if (A.rows[k] == beam.electrode_unknown(i) && A.cols[k] == beam.electrode_unknown(j))
            cap_[static_cast<std::size_t>(i) * ne + j] += A.values[k];
    const auto n = static_cast<std::size_t>(beam.unknowns());
    s_.x.assign(n, 0.0);
    s_.v.assign(n, 0.0);
    s_.a.assign(n, 0.0);
    s_.Q.assign(static_cast<std::size_t>(ne), 0.0);
  }

  // Start at rest (u = v = 0, no charge) with the base acceleration a_b(0): a_0 = -r a_b(0).
  void start(double ab0) {
    std::fill(s_.x.begin(), s_.x.end(), 0.0);
    std::fill(s_.v.begin(), s_.v.end(), 0.0);
    const auto& r = beam_.base_direction();
    for (std::size_t i = 0; i < s_.a.size(); ++i) s_.a[i] = -r[i] * ab0;
    std::fill(s_.Q.begin(), s_.Q.end(), 0.0);
    s_.step = 0;
    s_.time = 0.0;
    s_.base_acceleration = ab0;
    s_.work_in = s_.work_damping = s_.work_circuit = 0.0;
    s_.energy0 = energy();
  }

  // One step to t + dt with the base acceleration a_b(t + dt) and, optionally, external nodal loads F_ext(t + dt)
  // on the unknowns (the fluid's forces on the wet nodes, models/fsi/flow_harvester.hpp: entries on displacement
  // unknowns only; their work enters the energy balance with the trapezoidal average of the step's two loads).
  // Returns the partitioned scheme's iterations (1 for the monolithic one). Throws if the partitioned loop does
  // not converge.
  int step(double ab_next, const std::vector<double>* f_ext = nullptr) {
    const std::size_t n = s_.x.size();
    const double dt = o_.dt;
    const int ne = beam_.electrodes();
    // right-hand side
    std::vector<double> w(n), Mw, Kw, b(n, 0.0);
    const auto& r = beam_.base_direction();
    for (std::size_t i = 0; i < n; ++i) w[i] = c_[0] * s_.x[i] + c_[2] * s_.v[i] + c_[3] * s_.a[i] - r[i] * ab_next;
    for (std::size_t i = static_cast<std::size_t>(beam_.displacement_unknowns()); i < n; ++i) w[i] = 0.0;
    beam_.M().apply(w, Mw);
    std::vector<double> d(n, 0.0);  // the damping's history vector c1 u + c4 v + c5 a
    for (std::size_t i = 0; i < static_cast<std::size_t>(beam_.displacement_unknowns()); ++i)
      d[i] = c_[1] * s_.x[i] + c_[4] * s_.v[i] + c_[5] * s_.a[i];
    std::vector<double> Md, Kd;
    if (o_.damping.alpha != 0.0) beam_.M().apply(d, Md);
    if (o_.damping.beta != 0.0) beam_.Kuu().apply(d, Kd);
    if (f_ext && f_ext->size() != n)
      throw std::invalid_argument("piezo transient: the external load has " + std::to_string(f_ext->size()) + " entries, the beam " +
                                  std::to_string(n) + " unknowns");
    for (std::size_t i = 0; i < static_cast<std::size_t>(beam_.displacement_unknowns()); ++i) {
      b[i] = Mw[i];
      if (o_.damping.alpha != 0.0) b[i] += o_.damping.alpha * Md[i];
      if (o_.damping.beta != 0.0) b[i] += o_.damping.beta * Kd[i];
      if (f_ext) b[i] += (*f_ext)[i];
    }
    const std::vector<double> Vn = beam_.electrode_potentials(s_.x);
    for (int k = 0; k < ne; ++k) {
      double gv = 0.0;
      for (int j = 0; j < ne; ++j) gv += G_[static_cast<std::size_t>(k) * ne + j] * Vn[static_cast<std::size_t>(j)];
      b[static_cast<std::size_t>(beam_.electrode_unknown(k))] = -s_.Q[static_cast<std::size_t>(k)] + 0.5 * dt * gv;
    }
    int iterations = 1;
    std::vector<double> x;
    if (o_.scheme == Scheme::monolithic) {
      x = b;
      solver_.solve(x);
    } else {
      iterations = partitioned_solve(b, Vn, x);
    }
    // Newmark update, charge balance, energy
    std::vector<double> a_new(n, 0.0), v_new(n, 0.0);
    for (std::size_t i = 0; i < static_cast<std::size_t>(beam_.displacement_unknowns()); ++i) {
      a_new[i] = c_[0] * (x[i] - s_.x[i]) - c_[2] * s_.v[i] - c_[3] * s_.a[i];
      v_new[i] = s_.v[i] + dt * ((1.0 - o_.gamma) * s_.a[i] + o_.gamma * a_new[i]);
    }
    const std::vector<double> Vnew = beam_.electrode_potentials(x);
    std::vector<double> Vavg(static_cast<std::size_t>(ne));
    for (int k = 0; k < ne; ++k) Vavg[static_cast<std::size_t>(k)] = 0.5 * (Vn[static_cast<std::size_t>(k)] + Vnew[static_cast<std::size_t>(k)]);
    for (int k = 0; k < ne; ++k) {
      double gv = 0.0;
      for (int j = 0; j < ne; ++j) gv += G_[static_cast<std::size_t>(k) * ne + j] * Vavg[static_cast<std::size_t>(j)];
      s_.Q[static_cast<std::size_t>(k)] -= dt * gv;
    }
    // work of the base load F = -M r a_b over the step, the damping and the circuit (module comment)
    std::vector<double> du(n, 0.0), vavg(n, 0.0), rm(n, 0.0), Mr;
    for (std::size_t i = 0; i < static_cast<std::size_t>(beam_.displacement_unknowns()); ++i) {
      du[i] = x[i] - s_.x[i];
      vavg[i] = 0.5 * (s_.v[i] + v_new[i]);
      rm[i] = r[i];
    }
    beam_.M().apply(rm, Mr);
    const double Favg = -0.5 * (s_.base_acceleration + ab_next);
    s_.work_in += Favg * std::inner_product(du.begin(), du.end(), Mr.begin(), 0.0);
    if (f_ext || !s_.f_ext.empty()) {  // the external loads' work, du . (F_n + F_n+1) / 2
      double w_ext = 0.0;
      for (std::size_t i = 0; i < static_cast<std::size_t>(beam_.displacement_unknowns()); ++i)
        w_ext += du[i] * 0.5 * ((s_.f_ext.empty() ? 0.0 : s_.f_ext[i]) + (f_ext ? (*f_ext)[i] : 0.0));
      s_.work_in += w_ext;
      if (f_ext) s_.f_ext = *f_ext;
      else s_.f_ext.clear();
    }
    double vCv = 0.0;
    if (o_.damping.alpha != 0.0) vCv += o_.damping.alpha * beam_.M().dot(vavg, vavg);
    if (o_.damping.beta != 0.0) vCv += o_.damping.beta * beam_.Kuu().dot(vavg, vavg);
    s_.work_damping += dt * vCv;
    s_.work_circuit += dt * circuit_.power(Vavg);
    s_.x = std::move(x);
    s_.v = std::move(v_new);
    s_.a = std::move(a_new);
    s_.base_acceleration = ab_next;
    s_.time += dt;
    ++s_.step;
    last_iterations_ = iterations;
    total_solves_ += o_.scheme == Scheme::monolithic ? 1 : iterations;
    return iterations;
  }

  // The stored energy 1/2 v^T M v + 1/2 u^T Kuu u + 1/2 phi^T Kpp phi [J].
  double energy() const {
    const std::size_t nu = static_cast<std::size_t>(beam_.displacement_unknowns());
    std::vector<double> u(s_.x.size(), 0.0), phi(s_.x.size(), 0.0);
    for (std::size_t i = 0; i < s_.x.size(); ++i) (i < nu ? u : phi)[i] = s_.x[i];
    return 0.5 * beam_.M().dot(s_.v, s_.v) + 0.5 * beam_.Kuu().dot(u, u) - 0.5 * beam_.K().dot(phi, phi);
  }
  // (E - E_0 + W_damping + W_circuit) / W_in - 1: the relative energy balance error.
  double energy_balance_error() const {
    const double lhs = energy() - s_.energy0 + s_.work_damping + s_.work_circuit;
    return s_.work_in != 0.0 ? lhs / s_.work_in - 1.0 : lhs;
  }

  const TransientState& state() const { return s_; }
  void restore(const TransientState& s) {
    const std::size_t m = s_.Q.size();
    if (s.x.size() != s_.x.size() || s.v.size() != s_.v.size() || s.a.size() != s_.a.size() || s.Q.size() != m ||
        (!s.jacobian.empty() && s.jacobian.size() != m * m) || (!s.f_ext.empty() && s.f_ext.size() != s_.x.size()))
      throw std::invalid_argument("piezo transient: the restart state does not fit this model");
    s_ = s;
  }
  double time() const { return s_.time; }
  std::vector<double> electrode_potentials() const { return beam_.electrode_potentials(s_.x); }
  double tip() const { return beam_.tip(s_.x); }
  // V_a - V_b between electrodes a and b (Circuit::ground for 0 V).
  double voltage(int a, int b) const {
    const double va = a == Circuit::ground ? 0.0 : s_.x[static_cast<std::size_t>(beam_.electrode_unknown(a))];
    const double vb = b == Circuit::ground ? 0.0 : s_.x[static_cast<std::size_t>(beam_.electrode_unknown(b))];
    return va - vb;
  }
  double power() const { return circuit_.power(electrode_potentials()); }
  int last_iterations() const { return last_iterations_; }
  std::int64_t total_solves() const { return total_solves_; }
  const TransientOptions& options() const { return o_; }

 private:
  // Paper 1's loop: V -> (u, phi) with V as Dirichlet data -> the charge residual r(V) (the electrode rows of
  // the step's system, i.e. Q_{n+1}(u, phi) against the circuit's Q_n - dt/2 G (V_n + V)); Broyden on V.
  int partitioned_solve(const std::vector<double>& b, const std::vector<double>& Vn, std::vector<double>& x) {
    const int ne = beam_.electrodes();
    const auto m = static_cast<std::size_t>(ne);
    auto residual = [&](const std::vector<double>& V, std::vector<double>& xs) {
      xs = b;
      std::vector<double> e(m);
      // the border unknowns are the last ne: the electrode unknowns in their order (beam_model.hpp numbering)
      for (std::size_t k = 0; k < m; ++k) e[k] = V[k];
      ++solves_in_step_;
      return solver_.solve_interior(xs, e);
    };
    solves_in_step_ = 0;
    std::vector<double> V = Vn, r = residual(V, x);
    std::vector<double>& J = s_.jacobian;
    if (J.empty()) {  // the first step's Jacobian
      J.assign(m * m, 0.0);
      if (o_.finite_difference_jacobian) {
        double vs = 1.0;
        for (const double v : V) vs = std::max(vs, std::fabs(v));
        std::vector<double> xt;
        for (std::size_t j = 0; j < m; ++j) {
          std::vector<double> Vp = V;
          const double h = 1e-3 * vs;
          Vp[j] += h;
          const std::vector<double> rp = residual(Vp, xt);
          for (std::size_t i = 0; i < m; ++i) J[i * m + j] = (rp[i] - r[i]) / h;
        }
      } else {
        J = cap_;
      }
    }
    double qscale = 1e-30;
    for (std::size_t i = 0; i < m; ++i) {
      double s = std::fabs(b[static_cast<std::size_t>(beam_.electrode_unknown(static_cast<int>(i)))]);
      for (std::size_t j = 0; j < m; ++j) s += std::fabs(cap_[i * m + j] * V[j]);
      qscale = std::max(qscale, s);
    }
    double previous = 0.0;
    for (int it = 0; it < o_.max_iterations; ++it) {
      double rn = 0.0;
      for (const double v : r) rn = std::max(rn, std::fabs(v));
      if (rn <= o_.tolerance * qscale || rn < 1e-30) return solves_in_step_;
      // the round-off floor: the charge rows cancel terms ~ |Kuphi^T u|, so ~1e-9 of the charge scale is the
      // best a residual evaluation can do; a stalled residual below 1e-6 of it has converged
      if (it > 0 && rn > 0.5 * previous && rn <= 1e-6 * qscale) return solves_in_step_;
      previous = rn;
      std::vector<double> dV = r;  // J dV = -r
      BorderedSolver<double>::dense_solve(J, dV);
      for (std::size_t k = 0; k < m; ++k) {
        dV[k] = -dV[k];
        V[k] += dV[k];
        qscale = std::max(qscale, std::fabs(cap_[k * m + k] * V[k]));
      }
      const std::vector<double> rn1 = residual(V, x);
      // Broyden: J += ((dr - J dV) dV^T) / (dV^T dV), only while the residuals are well above their round-off
      // floor (an update from residuals at the floor is noise and spoils J for the following steps)
      double dd = 0.0, r1 = 0.0;
      for (const double v : dV) dd += v * v;
      for (const double v : rn1) r1 = std::max(r1, std::fabs(v));
      if (dd > 0.0 && r1 > 1e-6 * qscale)
        for (std::size_t i = 0; i < m; ++i) {
          double jd = 0.0;
          for (std::size_t j = 0; j < m; ++j) jd += J[i * m + j] * dV[j];
          const double u = (rn1[i] - r[i] - jd) / dd;
          for (std::size_t j = 0; j < m; ++j) J[i * m + j] += u * dV[j];
        }
      r = rn1;
    }
    throw std::runtime_error("piezo transient: the partitioned loop did not converge in " +
                             std::to_string(o_.max_iterations) + " iterations at step " + std::to_string(s_.step + 1));
  }

  const PiezoBeam& beam_;
  Circuit circuit_;
  TransientOptions o_;
  std::vector<double> G_, cap_;
  std::array<double, 6> c_{};
  BorderedSolver<double> solver_;
  TransientState s_;
  int last_iterations_ = 0, solves_in_step_ = 0;
  std::int64_t total_solves_ = 0;
};

}  // namespace polymech::piezo
