// The bordered direct solver of the piezoelectric harvester (issue 35; models/piezo/beam_model.hpp): a sparse
// LU of the interior unknowns and the dense Schur complement of a few border unknowns (the electrodes), for real
// and complex matrices, with a symmetric scaling of the unknowns; also the partitioned use (the border given,
// its residual returned) that paper 1's loop needs.
#pragma once

#include <algorithm>
#include <complex>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "solvers/host_sparse_lu.hpp"

namespace polymech::piezo {

// A sparse matrix whose last `border` unknowns (the electrodes) have dense rows and columns (an electrode
// couples to every node of its surface). Eigen's supernodal LU factorises such a matrix 5x slower than the
// same matrix without them (measured: 0.17 s against 0.034 s at 2248 unknowns), so the border is eliminated:
//   A = [A_ss A_se; A_es A_ee],  Z = A_ss^-1 A_se,  S = A_ee - A_es Z  (border x border, dense),
//   x_e = S^-1 (b_e - A_es A_ss^-1 b_s),  x_s = A_ss^-1 b_s - Z x_e:
// one sparse factorisation of A_ss, `border` solves to form Z, then one sparse solve per right-hand side.
// Every unknown i is scaled by scale[i] (S A S, PiezoBeam::unknown_scale) before the factorisation.
template <class Scalar>
class BorderedSolver {
  using Sparse = std::conditional_t<std::is_same_v<Scalar, double>, solvers::HostSparseLU, solvers::HostSparseLUComplex>;

 public:
  void factor(std::int64_t n, std::int64_t border, const std::vector<std::int64_t>& rows,
              const std::vector<std::int64_t>& cols, const std::vector<Scalar>& values, const std::vector<double>& scale) {
    n_ = n;
    ne_ = border;
    ns_ = n - border;
    scale_ = scale;
    std::vector<std::int64_t> rs, cs;
    std::vector<Scalar> vs;
    rs.reserve(values.size());
    cs.reserve(values.size());
    vs.reserve(values.size());
    std::vector<Scalar> Ase(static_cast<std::size_t>(ns_ * ne_), Scalar(0.0));
    Aes_.assign(static_cast<std::size_t>(ne_ * ns_), Scalar(0.0));
    std::vector<Scalar> Aee(static_cast<std::size_t>(ne_ * ne_), Scalar(0.0));
    for (std::size_t k = 0; k < values.size(); ++k) {
      const std::int64_t r = rows[k], c = cols[k];
      const Scalar v = values[k] * scale_[static_cast<std::size_t>(r)] * scale_[static_cast<std::size_t>(c)];
      if (r < ns_ && c < ns_) {
        rs.push_back(r);
        cs.push_back(c);
        vs.push_back(v);
      } else if (r < ns_) {
        Ase[static_cast<std::size_t>((c - ns_) * ns_ + r)] += v;
      } else if (c < ns_) {
        Aes_[static_cast<std::size_t>((r - ns_) * ns_ + c)] += v;
      } else {
        Aee[static_cast<std::size_t>((r - ns_) * ne_ + (c - ns_))] += v;
      }
    }
    lu_.factor(ns_, rs, cs, vs);
    Ase_ = Ase;
    Aee_ = Aee;
    Z_ = Ase;
    for (std::int64_t j = 0; j < ne_; ++j) lu_.solve(&Z_[static_cast<std::size_t>(j * ns_)]);
    S_ = Aee;
    for (std::int64_t a = 0; a < ne_; ++a)
      for (std::int64_t b = 0; b < ne_; ++b) {
        Scalar t(0.0);
        for (std::int64_t i = 0; i < ns_; ++i)
          t += Aes_[static_cast<std::size_t>(a * ns_ + i)] * Z_[static_cast<std::size_t>(b * ns_ + i)];
        S_[static_cast<std::size_t>(a * ne_ + b)] -= t;
      }
  }

  // b <- A^-1 b
  void solve(std::vector<Scalar>& b) const { solve(b, {}); }

  // b <- (A + E)^-1 b where E adds border_add (border x border, row-major, unscaled; empty: nothing) to the
  // border block: a change of the electrode rows only (another load of the circuit) reuses the factorisation.
  void solve(std::vector<Scalar>& b, const std::vector<Scalar>& border_add) const {
    std::vector<Scalar> S = S_;
    if (!border_add.empty())
      for (std::int64_t a = 0; a < ne_; ++a)
        for (std::int64_t c = 0; c < ne_; ++c)
          S[static_cast<std::size_t>(a * ne_ + c)] += border_add[static_cast<std::size_t>(a * ne_ + c)] *
                                                     scale_[static_cast<std::size_t>(ns_ + a)] *
                                                     scale_[static_cast<std::size_t>(ns_ + c)];
    for (std::size_t i = 0; i < b.size(); ++i) b[i] *= scale_[i];
    lu_.solve(b.data());
    std::vector<Scalar> xe(static_cast<std::size_t>(ne_));
    for (std::int64_t a = 0; a < ne_; ++a) {
      Scalar t = b[static_cast<std::size_t>(ns_ + a)];
      for (std::int64_t i = 0; i < ns_; ++i) t -= Aes_[static_cast<std::size_t>(a * ns_ + i)] * b[static_cast<std::size_t>(i)];
      xe[static_cast<std::size_t>(a)] = t;
    }
    dense_solve(S, xe);
    for (std::int64_t a = 0; a < ne_; ++a) {
      for (std::int64_t i = 0; i < ns_; ++i)
        b[static_cast<std::size_t>(i)] -= Z_[static_cast<std::size_t>(a * ns_ + i)] * xe[static_cast<std::size_t>(a)];
      b[static_cast<std::size_t>(ns_ + a)] = xe[static_cast<std::size_t>(a)];
    }
    for (std::size_t i = 0; i < b.size(); ++i) b[i] *= scale_[i];
  }

  // The partitioned use (paper 1's loop): with the border unknowns x_e given, b[0:ns) <- x_s = A_ss^-1 (b_s -
  // A_se x_e) and b[ns:) <- x_e; returns the border rows' residual r_e = A_es x_s + A_ee x_e - b_e (one sparse
  // solve; the Schur complement is not used).
  std::vector<Scalar> solve_interior(std::vector<Scalar>& b, const std::vector<Scalar>& xe) const {
    std::vector<Scalar> ye(static_cast<std::size_t>(ne_)), be(static_cast<std::size_t>(ne_));
    for (std::int64_t a = 0; a < ne_; ++a) {
      const double s = scale_[static_cast<std::size_t>(ns_ + a)];
      ye[static_cast<std::size_t>(a)] = xe[static_cast<std::size_t>(a)] / s;
      be[static_cast<std::size_t>(a)] = b[static_cast<std::size_t>(ns_ + a)] * s;
    }
    for (std::int64_t i = 0; i < ns_; ++i) {
      Scalar t = b[static_cast<std::size_t>(i)] * scale_[static_cast<std::size_t>(i)];
      for (std::int64_t a = 0; a < ne_; ++a) t -= Ase_[static_cast<std::size_t>(a * ns_ + i)] * ye[static_cast<std::size_t>(a)];
      b[static_cast<std::size_t>(i)] = t;
    }
    lu_.solve(b.data());
    std::vector<Scalar> r(static_cast<std::size_t>(ne_));
    for (std::int64_t a = 0; a < ne_; ++a) {
      Scalar t = -be[static_cast<std::size_t>(a)];
      for (std::int64_t i = 0; i < ns_; ++i) t += Aes_[static_cast<std::size_t>(a * ns_ + i)] * b[static_cast<std::size_t>(i)];
      for (std::int64_t c = 0; c < ne_; ++c) t += Aee_[static_cast<std::size_t>(a * ne_ + c)] * ye[static_cast<std::size_t>(c)];
      r[static_cast<std::size_t>(a)] = t / scale_[static_cast<std::size_t>(ns_ + a)];
    }
    for (std::int64_t i = 0; i < ns_; ++i) b[static_cast<std::size_t>(i)] *= scale_[static_cast<std::size_t>(i)];
    for (std::int64_t a = 0; a < ne_; ++a) b[static_cast<std::size_t>(ns_ + a)] = xe[static_cast<std::size_t>(a)];
    return r;
  }
  std::int64_t border() const { return ne_; }

  // x <- S^-1 x, S dense m x m (Gaussian elimination with partial pivoting; m is the number of electrodes).
  static void dense_solve(std::vector<Scalar> S, std::vector<Scalar>& x) {  // public: the partitioned loop's update
    const std::size_t m = x.size();
    for (std::size_t c = 0; c < m; ++c) {
      std::size_t p = c;
      for (std::size_t r = c + 1; r < m; ++r)
        if (std::abs(S[r * m + c]) > std::abs(S[p * m + c])) p = r;
      if (std::abs(S[p * m + c]) == 0.0) throw std::runtime_error("piezo: the electrodes' Schur complement is singular");
      if (p != c) {
        for (std::size_t j = 0; j < m; ++j) std::swap(S[c * m + j], S[p * m + j]);
        std::swap(x[c], x[p]);
      }
      for (std::size_t r = c + 1; r < m; ++r) {
        const Scalar f = S[r * m + c] / S[c * m + c];
        for (std::size_t j = c; j < m; ++j) S[r * m + j] -= f * S[c * m + j];
        x[r] -= f * x[c];
      }
    }
    for (std::size_t c = m; c-- > 0;) {
      for (std::size_t j = c + 1; j < m; ++j) x[c] -= S[c * m + j] * x[j];
      x[c] /= S[c * m + c];
    }
  }

 private:
  Sparse lu_;
  std::int64_t n_ = 0, ns_ = 0, ne_ = 0;
  std::vector<double> scale_;
  std::vector<Scalar> Z_, Aes_, Ase_, Aee_, S_;
};

}  // namespace polymech::piezo
