// Preconditioners of COCG for the Helmholtz system K = A - k^2 M + j rho omega C (seed 002 paper 3
// eq. (16)) beyond Jacobi, all linear and complex symmetric (so COCG stays valid), all matrix-free:
//
//  - shifted Laplacian: each approximates S^-1 with the positive shifted operator S = A + s k^2 M
//    (s = shift, default 1; the impedance term dropped), which is real symmetric positive definite. K
//    and S share the 1 / h^2 conditioning of A, which is what Jacobi leaves to COCG (its iterations
//    grow with the DoFs per direction); S^-1 K has eigenvalues (l - k^2) / (l + s k^2) in (-1, 1] for the
//    generalized eigenvalues l of (A, M): the few below k^2 (the indefinite part) stay for COCG.
//  - chebyshev: a Chebyshev polynomial in D^-1 S of fixed degree (kernels/solvers/chebyshev.hpp) on
//    the whole spectrum of D^-1 S, which Lanczos estimates;
//  - pmg: a p-multigrid V-cycle on S: Chebyshev smoothing on orders p, p / 2, ... (the upper part of
//    the spectrum of each order), transfers by the order-q interpolant at the finer GLL nodes, and on
//    order 1 the Chebyshev polynomial on the whole spectrum.
#pragma once

#include <memory>
#include <vector>

#include "fem/transfer.hpp"
#include "helmholtz/analytic.hpp"
#include "helmholtz/config.hpp"
#include "helmholtz/discretization.hpp"
#include "helmholtz/dofs.hpp"
#include "helmholtz/operator.hpp"
#include "solvers/chebyshev.hpp"

namespace polymech::helmholtz {

// One order of the hierarchy: S on that order's DoFs (from that order's discretization of the same Config)
// and its Jacobi inverse.
template <class T>
struct ShiftedLevel {
  using C = Kokkos::complex<T>;
  HelmholtzOperator<T> S;
  View1<C> inv_diag;
  solvers::Spectrum spectrum;
  int order = 1;
};

template <class T>
ShiftedLevel<T> shifted_level(const HelmholtzOperator<T>& op, const Config& c, double shift, int lanczos_steps) {
  using C = Kokkos::complex<T>;
  ShiftedLevel<T> l;
  const double k = c.wavenumber();
  l.order = c.order;
  l.S = op.shifted(static_cast<T>(shift * k * k));
  const Index n = l.S.local_size();
  View1<C> d("polymech::helmholtz::shifted_diagonal", n);
  l.S.diagonal(d);
  l.inv_diag = View1<C>("polymech::helmholtz::shifted_inverse_diagonal", n);
  solvers::jacobi_inverse(l.S.owned_size(), n, d, l.inv_diag);
  l.spectrum = solvers::estimate_spectrum(l.S, l.inv_diag, lanczos_steps);
  return l;
}

// Prolongation from the order-q discretization `coarse` to `fine` (same mesh, same element order):
// the coarse interpolant at every fine GLL node. Constrained (Dirichlet) fine rows and coarse columns
// are left out: corrections vanish there.
template <class T>
fem::Transfer<T> prolongation(const HexDofs& fine, const std::vector<char>& fine_constrained, const HexDofs& coarse,
                              const std::vector<char>& coarse_constrained, bool transpose) {
  const int Nf = fine.n1d, Nc = coarse.n1d, Nf3 = fine.nodes_per_element(), Nc3 = coarse.nodes_per_element();
  const std::vector<double> xf = fem::gauss_lobatto_nodes(Nf), xc = fem::gauss_lobatto_nodes(Nc);
  std::vector<double> l(static_cast<std::size_t>(Nf * Nc));  // l[i Nc + a] = coarse l_a at fine node i
  for (int i = 0; i < Nf; ++i)
    for (int a = 0; a < Nc; ++a) {
      double v = fem::lagrange(xc, a, xf[i]);
      if (std::abs(v) < 1e-14) v = 0.0;
      if (std::abs(v - 1.0) < 1e-14) v = 1.0;
      l[static_cast<std::size_t>(i * Nc + a)] = v;
    }
  const std::int64_t ne = static_cast<std::int64_t>(fine.element_dofs.size()) / Nf3;
  std::vector<std::vector<std::pair<Index, double>>> rows(static_cast<std::size_t>(transpose ? coarse.count : fine.count));
  std::vector<char> done(static_cast<std::size_t>(fine.count), 0);
  for (std::int64_t e = 0; e < ne; ++e)
    for (int k = 0; k < Nf; ++k)
      for (int j = 0; j < Nf; ++j)
        for (int i = 0; i < Nf; ++i) {
          const std::int32_t f = fine.element_dofs[static_cast<std::size_t>(e * Nf3 + i + Nf * (j + Nf * k))];
          if (done[f] || fine_constrained[f]) continue;
          done[f] = 1;
          for (int c = 0; c < Nc; ++c)
            for (int b = 0; b < Nc; ++b)
              for (int a = 0; a < Nc; ++a) {
                const double w = l[static_cast<std::size_t>(i * Nc + a)] * l[static_cast<std::size_t>(j * Nc + b)] *
                                 l[static_cast<std::size_t>(k * Nc + c)];
                const std::int32_t g = coarse.element_dofs[static_cast<std::size_t>(e * Nc3 + a + Nc * (b + Nc * c))];
                if (w == 0.0 || coarse_constrained[g]) continue;
                if (transpose)
                  rows[g].push_back({f, w});
                else
                  rows[f].push_back({g, w});
              }
        }
  return fem::make_transfer<T>(rows);
}

// A Chebyshev polynomial in D^-1 S on the whole estimated spectrum, as a preconditioner.
template <class T>
class ChebyshevPreconditioner {
 public:
  using C = Kokkos::complex<T>;
  // d: the discretization of Config c (at c.order); the options are c.shifted.
  ChebyshevPreconditioner(const Discretization<T>& d, const Config& c)
      : level_(std::make_unique<ShiftedLevel<T>>(shifted_level(d.op, c, c.shifted.shift, c.shifted.lanczos_steps))) {
    const ShiftedOptions& o = c.shifted;
    const double lo = level_->spectrum.lo, hi = 1.1 * level_->spectrum.hi;
    const int degree = o.polynomial_degree > 0 ? o.polynomial_degree : solvers::chebyshev_degree(lo, hi, 0.1, 400);
    cheb_ = solvers::Chebyshev<HelmholtzOperator<T>, C>(&level_->S, level_->inv_diag, lo, hi, degree);
  }
  void apply(const View1<C>& r, const View1<C>& z) const { cheb_.apply(r, z); }
  int degree() const { return cheb_.degree(); }
  std::string describe() const {
    return "Chebyshev degree " + std::to_string(cheb_.degree()) + " on D^-1 S, spectrum [" +
           std::to_string(cheb_.lo()) + ", " + std::to_string(cheb_.hi()) + "]";
  }

 private:
  std::unique_ptr<ShiftedLevel<T>> level_;
  solvers::Chebyshev<HelmholtzOperator<T>, C> cheb_;
};

// The p-multigrid V-cycle on S (orders p, p / 2, ..., 1): each coarser order is the discretization of the
// same Config at that order (discretization.hpp); no model is built for it.
template <class T>
class PMultigrid {
 public:
  using C = Kokkos::complex<T>;
  using Smoother = solvers::Chebyshev<HelmholtzOperator<T>, C>;

  // fine: the discretization of Config c (at c.order); the options are c.shifted.
  PMultigrid(const Discretization<T>& fine, const Config& c) {
    const ShiftedOptions& o = c.shifted;
    const Discretization<T>* finer = &fine;
    Config level = c;
    for (int q = c.order;;) {
      level.order = q;
      auto l = std::make_unique<ShiftedLevel<T>>(shifted_level(finer->op, level, o.shift, q == 1 ? o.lanczos_steps : 20));
      levels_.push_back(std::move(l));
      if (q == 1) break;
      const int next = q / 2;
      level.order = next;
      auto coarse = std::make_unique<Discretization<T>>(level, AnalyticField::from(level));
      const auto fine_mask = finer->constrained_mask(), coarse_mask = coarse->constrained_mask();
      prolong_.push_back(prolongation<T>(finer->dofs, fine_mask, coarse->dofs, coarse_mask, false));
      restrict_.push_back(prolongation<T>(finer->dofs, fine_mask, coarse->dofs, coarse_mask, true));
      owned_.push_back(std::move(coarse));
      finer = owned_.back().get();
      q = next;
    }
    for (std::size_t i = 0; i < levels_.size(); ++i) {
      auto& l = *levels_[i];
      const double hi = 1.1 * l.spectrum.hi;
      const bool coarsest = i + 1 == levels_.size();
      const double lo = coarsest ? l.spectrum.lo : hi / o.smoothing_range;
      const int degree = coarsest ? (o.polynomial_degree > 0 ? o.polynomial_degree : solvers::chebyshev_degree(lo, hi, 0.1, 400))
                                  : o.smoothing_degree;
      smoothers_.push_back(Smoother(&l.S, l.inv_diag, lo, hi, degree));
      const Index n = l.S.local_size();
      r_.push_back(View1<C>("polymech::helmholtz::mg_r", n));
      z_.push_back(View1<C>("polymech::helmholtz::mg_z", n));
      t_.push_back(View1<C>("polymech::helmholtz::mg_t", n));
    }
  }

  void apply(const View1<C>& r, const View1<C>& z) const { cycle(0, r, z); }

  std::string describe() const {
    std::string s = "p-multigrid on orders";
    for (const auto& l : levels_) s += " " + std::to_string(l->order);
    s += ", Chebyshev smoothing degree " + std::to_string(smoothers_.front().degree()) + ", coarse degree " +
         std::to_string(smoothers_.back().degree());
    return s;
  }

 private:
  void cycle(std::size_t l, const View1<C>& r, const View1<C>& z) const {
    const Smoother& s = smoothers_[l];
    if (l + 1 == levels_.size()) {
      s.apply(r, z);
      return;
    }
    const auto& S = levels_[l]->S;
    s.apply(r, z);                                       // pre-smoothing from zero
    S.apply(z, t_[l]);                                   // residual t = r - S z
    solvers::detail::subtract_from(S.local_size(), r, t_[l], t_[l]);
    restrict_[l].template apply<false>(t_[l], r_[l + 1]);
    cycle(l + 1, r_[l + 1], z_[l + 1]);
    prolong_[l].template apply<true>(z_[l + 1], z);     // z += P z_c
    s.smooth(r, z);                                      // post-smoothing
  }

  std::vector<std::unique_ptr<ShiftedLevel<T>>> levels_;
  std::vector<std::unique_ptr<Discretization<T>>> owned_;  // the coarser orders
  std::vector<fem::Transfer<T>> prolong_, restrict_;
  std::vector<Smoother> smoothers_;
  std::vector<View1<C>> r_, z_, t_;
};

}  // namespace polymech::helmholtz
