// Partitioned coupling of two solvers through an interface (issue 36: "Dirichlet-Neumann with Aitken relaxation
// and a quasi-Newton method (IQN-ILS); added-mass hard cases must converge or stop with a reason"). Host code:
// the interface vectors are small (the nodes of a wet surface), the solvers behind the map are the models'.
//
// Within a time step the coupled state is the fixed point x = G(x) of the interface map G (Dirichlet-Neumann:
// the fluid takes the interface displacement x, returns its traction, the structure takes the traction and
// returns the new displacement G(x)); r(x) = G(x) - x. Methods (CouplingMethod):
//   relaxation  x_{k+1} = x_k + omega r_k (omega = 1: the plain Gauss-Seidel iteration);
//   aitken      omega_k = -omega_{k-1} r_{k-1} . (r_k - r_{k-1}) / |r_k - r_{k-1}|^2 (Irons & Tuck 1969;
//               Kuettler & Wall 2008, eq. (44)), the first omega_0 capped to omega_max;
//   iqn_ils     the interface quasi-Newton method with the inverse Jacobian from a least-squares model (Degroote,
//               Bathe & Vierendeels 2009): V = [r_k - r_i], W = [x~_k - x~_i] over the previous iterates i
//               (x~ = G(x)), c = argmin |V c + r_k| by a QR of V with the columns that are (nearly) dependent
//               filtered out (|R_jj| < eps |R_00|), x_{k+1} = x~_k + W c. The columns of the last `reuse` time
//               steps are kept, so a step starts with the previous steps' Jacobian model.
// The plain iteration converges only while the spectral radius of G' is below 1: for an incompressible fluid on
// a light structure it is the ratio of the added mass to the structure's mass (Causin, Gerbeau & Nobile 2005),
// so it diverges at a ratio above 1 whatever the time step; a stopped iteration reports why (non-finite, growing,
// or the iteration limit with the last residual), and never returns an unconverged state as converged.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "common/archive.hpp"

namespace polymech::fsi {

enum class CouplingMethod { relaxation, aitken, iqn_ils };

inline CouplingMethod coupling_method(const std::string& s) {
  if (s == "relaxation") return CouplingMethod::relaxation;
  if (s == "aitken") return CouplingMethod::aitken;
  if (s == "iqn_ils" || s == "iqn-ils") return CouplingMethod::iqn_ils;
  throw std::invalid_argument("coupling method '" + s + "' (allowed: relaxation, aitken, iqn_ils)");
}

struct CouplingOptions {
  CouplingMethod method = CouplingMethod::iqn_ils;
  double omega = 0.5;          // relaxation: the factor; aitken / iqn_ils: the first step's factor
  double omega_max = 1.0;      // aitken: |omega| is capped here
  double tolerance = 1e-8;     // |r| <= tolerance max(|x~|, scale)
  double scale = 0.0;          // a floor of the norm the tolerance is relative to (0: |x~| alone)
  int max_iterations = 100;
  int reuse = 8;               // iqn_ils: time steps whose columns are kept
  double filter = 1e-10;       // iqn_ils: QR filter
  double divergence = 1e6;     // stop when |r_k| > divergence |r_0|
};

struct CouplingResult {
  bool converged = false;
  int iterations = 0;             // evaluations of G
  double residual = 0.0;          // the last |r|
  std::string reason;             // why it stopped, when not converged
  std::vector<double> history;    // |r_k|
};

// The coupling iteration of one time step after another (state: Aitken's last omega, IQN-ILS's columns).
class InterfaceCoupling {
 public:
  using Map = std::function<std::vector<double>(const std::vector<double>& x)>;

  explicit InterfaceCoupling(const CouplingOptions& o = {}) : o_(o) {
    if (!(o.omega > 0.0) || !(o.omega_max > 0.0)) throw std::invalid_argument("fsi coupling: omega and omega_max must be > 0");
    if (!(o.tolerance > 0.0) || o.max_iterations < 1) throw std::invalid_argument("fsi coupling: tolerance > 0 and max_iterations >= 1 needed");
    if (o.reuse < 0) throw std::invalid_argument("fsi coupling: reuse must be >= 0");
  }

  const CouplingOptions& options() const { return o_; }

  // Iterate x <- x_{k+1} from the predictor x until |G(x) - x| is small; x holds the converged interface state
  // (the last G(x) on success; the last iterate when it stopped).
  CouplingResult solve(std::vector<double>& x, const Map& G) {
    CouplingResult res;
    const std::size_t n = x.size();
    std::vector<double> xt, r, r_prev, xt_prev;
    std::vector<Eigen::VectorXd> V, W;  // this step's columns (differences to the latest iterate)
    double r0 = 0.0;
    for (int k = 0; k < o_.max_iterations; ++k) {
      xt = G(x);
      if (xt.size() != n) throw std::invalid_argument("fsi coupling: the interface map changed the vector's size");
      ++res.iterations;
      r.assign(n, 0.0);
      double rn = 0.0, xn = 0.0;
      for (std::size_t i = 0; i < n; ++i) {
        r[i] = xt[i] - x[i];
        rn += r[i] * r[i];
        xn += xt[i] * xt[i];
      }
      rn = std::sqrt(rn);
      xn = std::sqrt(xn);
      res.residual = rn;
      res.history.push_back(rn);
      if (!std::isfinite(rn)) {
        res.reason = "the interface residual is not finite after " + std::to_string(k + 1) + " evaluations";
        return res;
      }
      if (k == 0) r0 = std::max(rn, std::numeric_limits<double>::min());
      if (rn <= o_.tolerance * std::max(xn, o_.scale)) {
        x = xt;
        res.converged = true;
        if (o_.method == CouplingMethod::iqn_ils) keep_columns(V, W);
        return res;
      }
      if (rn > o_.divergence * r0) {
        res.reason = "the coupling iteration diverges: |r| grew from " + format(r0) + " to " + format(rn) + " in " +
                     std::to_string(k + 1) + " evaluations (for an incompressible fluid on a light structure the plain "
                     "iteration diverges when the added mass exceeds the structure's mass; use aitken or iqn_ils)";
        return res;
      }
      switch (o_.method) {
        case CouplingMethod::relaxation:
          for (std::size_t i = 0; i < n; ++i) x[i] += o_.omega * r[i];
          break;
        case CouplingMethod::aitken: {
          if (k == 0) {
            omega_ = std::min(o_.omega, o_.omega_max);
          } else {
            double num = 0.0, den = 0.0;
            for (std::size_t i = 0; i < n; ++i) {
              const double d = r[i] - r_prev[i];
              num += r_prev[i] * d;
              den += d * d;
            }
            if (den > 0.0) omega_ = -omega_ * num / den;
            omega_ = std::max(-o_.omega_max, std::min(o_.omega_max, omega_));
          }
          for (std::size_t i = 0; i < n; ++i) x[i] += omega_ * r[i];
          break;
        }
        case CouplingMethod::iqn_ils: {
          if (k > 0) {
            Eigen::VectorXd dv(n), dw(n);
            for (std::size_t i = 0; i < n; ++i) {
              dv(static_cast<Eigen::Index>(i)) = r[i] - r_prev[i];
              dw(static_cast<Eigen::Index>(i)) = xt[i] - xt_prev[i];
            }
            V.insert(V.begin(), dv);  // newest first
            W.insert(W.begin(), dw);
          }
          if (!quasi_newton(V, W, r, xt, x)) {
            for (std::size_t i = 0; i < n; ++i) x[i] += o_.omega * r[i];  // no columns yet: relax
          }
          break;
        }
      }
      r_prev = r;
      xt_prev = xt;
    }
    res.reason = "no convergence in " + std::to_string(o_.max_iterations) + " evaluations (|r| = " + format(res.residual) +
                 ", the tolerance " + format(o_.tolerance) + " relative)";
    return res;
  }

  // The state carried from one time step to the next (Aitken's last omega, IQN-ILS's kept columns, newest step
  // first) into a checkpoint and back: a run resumed from it iterates exactly as one never interrupted.
  void save(models::Archive& a, const std::string& prefix) const {
    a.put(prefix + "omega", omega_);
    a.put(prefix + "steps", static_cast<std::uint64_t>(old_V_.size()));
    for (std::size_t s = 0; s < old_V_.size(); ++s) {
      std::vector<double> v, w;
      for (std::size_t j = 0; j < old_V_[s].size(); ++j) {
        v.insert(v.end(), old_V_[s][j].data(), old_V_[s][j].data() + old_V_[s][j].size());
        w.insert(w.end(), old_W_[s][j].data(), old_W_[s][j].data() + old_W_[s][j].size());
      }
      a.put(prefix + std::to_string(s) + "/columns", static_cast<std::uint64_t>(old_V_[s].size()));
      a.put_vector(prefix + std::to_string(s) + "/V", v);
      a.put_vector(prefix + std::to_string(s) + "/W", w);
    }
  }
  void load(const models::Archive& a, const std::string& prefix) {
    omega_ = a.get<double>(prefix + "omega");
    old_V_.clear();
    old_W_.clear();
    const auto steps = a.get<std::uint64_t>(prefix + "steps");
    for (std::uint64_t s = 0; s < steps; ++s) {
      const auto m = a.get<std::uint64_t>(prefix + std::to_string(s) + "/columns");
      const auto v = a.get_vector<double>(prefix + std::to_string(s) + "/V");
      const auto w = a.get_vector<double>(prefix + std::to_string(s) + "/W");
      if (v.size() != w.size() || (m == 0 ? !v.empty() : v.size() % m != 0))
        throw std::runtime_error("checkpoint: " + prefix + std::to_string(s) + ": the coupling's columns do not fit");
      const std::size_t n = m == 0 ? 0 : v.size() / m;
      std::vector<Eigen::VectorXd> V, W;
      for (std::size_t j = 0; j < m; ++j) {
        V.push_back(Eigen::Map<const Eigen::VectorXd>(v.data() + j * n, static_cast<Eigen::Index>(n)));
        W.push_back(Eigen::Map<const Eigen::VectorXd>(w.data() + j * n, static_cast<Eigen::Index>(n)));
      }
      old_V_.push_back(std::move(V));
      old_W_.push_back(std::move(W));
    }
  }

  // Columns kept from earlier time steps (iqn_ils).
  std::size_t stored_columns() const {
    std::size_t c = 0;
    for (const auto& s : old_V_) c += s.size();
    return c;
  }

 private:
  static std::string format(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.3g", v);
    return b;
  }

  // x = x~ + W c, c = argmin |V c + r| over this step's and the kept steps' columns (filtered QR); false when
  // there is no column.
  bool quasi_newton(const std::vector<Eigen::VectorXd>& V, const std::vector<Eigen::VectorXd>& W, const std::vector<double>& r,
                    const std::vector<double>& xt, std::vector<double>& x) {
    std::vector<const Eigen::VectorXd*> cv, cw;
    for (std::size_t j = 0; j < V.size(); ++j) {
      cv.push_back(&V[j]);
      cw.push_back(&W[j]);
    }
    for (std::size_t s = 0; s < old_V_.size(); ++s)
      for (std::size_t j = 0; j < old_V_[s].size(); ++j) {
        cv.push_back(&old_V_[s][j]);
        cw.push_back(&old_W_[s][j]);
      }
    const Eigen::Index n = static_cast<Eigen::Index>(r.size());
    if (cv.empty()) return false;
    // filtered modified Gram-Schmidt QR (QR1 filter: drop a column whose R_jj falls below filter |R_00|)
    std::vector<Eigen::VectorXd> Q;
    std::vector<std::size_t> kept;
    double r00 = 0.0;
    for (std::size_t j = 0; j < cv.size() && static_cast<Eigen::Index>(Q.size()) < n; ++j) {
      Eigen::VectorXd q = *cv[j];
      for (const auto& qi : Q) q -= qi.dot(q) * qi;
      const double rjj = q.norm();
      if (Q.empty()) r00 = rjj;
      if (!(rjj > o_.filter * r00) || rjj == 0.0) continue;
      Q.push_back(q / rjj);
      kept.push_back(j);
    }
    if (kept.empty()) return false;
    const Eigen::Index m = static_cast<Eigen::Index>(kept.size());
    Eigen::MatrixXd A(n, m), B(n, m);
    for (Eigen::Index j = 0; j < m; ++j) {
      A.col(j) = *cv[kept[static_cast<std::size_t>(j)]];
      B.col(j) = *cw[kept[static_cast<std::size_t>(j)]];
    }
    Eigen::VectorXd rv(n);
    for (Eigen::Index i = 0; i < n; ++i) rv(i) = r[static_cast<std::size_t>(i)];
    const Eigen::VectorXd c = A.colPivHouseholderQr().solve(-rv);
    const Eigen::VectorXd dx = B * c;
    for (Eigen::Index i = 0; i < n; ++i) x[static_cast<std::size_t>(i)] = xt[static_cast<std::size_t>(i)] + dx(i);
    return true;
  }

  void keep_columns(const std::vector<Eigen::VectorXd>& V, const std::vector<Eigen::VectorXd>& W) {
    if (o_.reuse == 0) return;
    old_V_.push_front(V);
    old_W_.push_front(W);
    while (static_cast<int>(old_V_.size()) > o_.reuse) {
      old_V_.pop_back();
      old_W_.pop_back();
    }
  }

  CouplingOptions o_;
  double omega_ = 0.0;
  std::deque<std::vector<Eigen::VectorXd>> old_V_, old_W_;
};

}  // namespace polymech::fsi
