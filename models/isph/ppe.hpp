// The pressure Poisson equation of the ISPH model (seed 002 paper 4, eqs. (10), (20) with the Neumann wall
// pressure (25)-(26)): the operator y = D^-1 A x over the step's three neighbour lists, its pair
// coefficients stored once per step (`ppe_operator = "stored"`) or computed in every apply (matrix-free),
// and its solve by BiCGSTAB, Jacobi-scaled or with the two-level preconditioner (ppe_two_level.hpp),
// warm-started from the last pressure; with the solver's record (the last solve, the counts).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "isph/config.hpp"
#include "isph/ppe_two_level.hpp"
#include "neighbors/neighbor_list.hpp"
#include "solvers/krylov.hpp"
#include "sph/bicgstab.hpp"
#include "sph/ghosts.hpp"
#include "sph/laplacian.hpp"

namespace polymech::isph {

// The PPE operator y = D^-1 A x as a Krylov operator (kernels/sph/bicgstab.hpp concept).
template <class T, int D>
struct PressureOperator {
  sph::Fluid<T, D> f;
  sph::WallPoints<T, D> wp;
  sph::Params<T, D> c;
  const neighbors::NeighborList* ff = nullptr;
  const neighbors::NeighborList* fw = nullptr;
  const neighbors::NeighborList* gf = nullptr;
  Index local_size() const { return f.size(); }
  Index owned_size() const { return f.size(); }
  // the pair coefficients of the three passes (empty: matrix-free, computed in every apply)
  View1<T> ghost_coef, fluid_coef, wall_coef;
  void apply(const View1<T>& x, const View1<T>& y) const {
    neighbors::for_each_row("polymech::sph::ghost_pressure", *gf, sph::GhostPressure<T, D>{f, wp, c, x, false, ghost_coef});
    neighbors::for_each_row("polymech::sph::laplacian_fluid", *ff, sph::FluidLaplacian<T, D>{f, c, x, fluid_coef});
    neighbors::for_each_row("polymech::sph::laplacian_wall", *fw, sph::WallLaplacian<T, D>{f, wp, c, x, y, wall_coef});
  }
  // Store the coefficients for the lists as they are now (once per step, before the solve), reusing
  // `ghost_coef`, ... when they are large enough.
  void store_coefficients() {
    store(*gf, sph::GhostPressure<T, D>{f, wp, c, f.pressure, false}, ghost_coef, "polymech::isph::ppe_ghost_coef");
    store(*ff, sph::FluidLaplacian<T, D>{f, c, f.pressure}, fluid_coef, "polymech::isph::ppe_fluid_coef");
    store(*fw, sph::WallLaplacian<T, D>{f, wp, c, f.pressure, f.scratch}, wall_coef, "polymech::isph::ppe_wall_coef");
  }
  template <class Pass>
  static void store(const neighbors::NeighborList& list, const Pass& pass, View1<T>& coef, const char* label) {
    const auto pairs = static_cast<std::size_t>(list.num_pairs);
    if (coef.extent(0) < pairs) coef = View1<T>(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), pairs + pairs / 4);
    neighbors::for_each_row(label, list, sph::StorePairCoefficients<T, Pass>{pass, coef});
  }
};

struct PpeRecord {
  int iterations = 0;
  double residual = 0.0;
  std::vector<double> history;  // of the last solve
};

// The PPE's solver with what it keeps from step to step: the stored coefficients' Views (grown when the
// lists grow), the two-level preconditioner (ppe_preconditioner two_level only; empty otherwise) and the
// record of the solves.
template <class T, int D>
class PpeSolver {
 public:
  void configure(const Config& c) {
    stored_ = c.ppe_stored;
    two_level_enabled_ = c.ppe_preconditioner == Config::Preconditioner::two_level;
    coarse_cell_ = c.ppe_coarse_cell * c.spacing;
    opts_.tolerance = c.tolerance;
    opts_.max_iterations = c.max_iterations;
  }

  // Solves for f.pressure (warm start: p^n in it) over the lists of this step; `box` is the tank as built
  // (the two-level preconditioner's grid). `step` (the step being taken) names a failure.
  //
  // The free-surface particles are the PPE's only Dirichlet rows (p = 0); the walls are Neumann (25)-(26).
  // With none flagged the operator is singular (defined up to a constant, and the source is not compatible
  // with the Neumann data): BiCGSTAB then runs its max_iterations to a residual of 1e12 and a pressure of
  // 1e30, which throws the particles out of the tank. That happens when the top layer of water compacts
  // onto the one below until every top particle's density is back over beta rho0 (the draft
  // hydrostatic tank, 10 x 10 particles, lost its last four surface particles in step 68). Such a solve is
  // not attempted: it is recorded as failed, with the reason.
  //
  // A failure is kept (ok() stays false, the first reason kept) until restore(): the state that follows a
  // failed solve is not valid, and the run's watchdog, which looks every so many steps, must see it even
  // when a later solve converges (the same tank with two threads: the particles thrown out were put back at
  // the safety net's open-top bound, y = 1e30, and fell freely from there; every later solve converged, the
  // check of step 100 found nothing, and the run "completed" with a pressure error of 2e76).
  void solve(const sph::Fluid<T, D>& f, const sph::WallPoints<T, D>& wp, const sph::Params<T, D>& par,
             const neighbors::NeighborList& ff, const neighbors::NeighborList& fw, const neighbors::NeighborList& gf,
             const double (&box)[3], std::int64_t step = 0) {
    if (surface_count(f) == 0) {
      last_.iterations = 0;
      last_.residual = 0.0;
      last_.history.clear();
      fail(step, "no fluid particle passed the free-surface test (the top layer has compacted onto the one "
                 "below): the pressure Poisson equation has no Dirichlet condition p = 0 and is singular");
      ++solves_;
      return;
    }
    PressureOperator<T, D> op{f, wp, par, &ff, &fw, &gf, coef_[0], coef_[1], coef_[2]};
    if (stored_) {
      op.store_coefficients();
      coef_[0] = op.ghost_coef;  // kept for the next step's lists (grown when they grow)
      coef_[1] = op.fluid_coef;
      coef_[2] = op.wall_coef;
    }
    solvers::SolveResult r;
    if (two_level_enabled_) {
      two_level_.setup(op, box, coarse_cell_);
      r = sph::bicgstab(op, f.rhs, f.pressure, opts_, two_level_);
    } else {
      r = sph::bicgstab(op, f.rhs, f.pressure, opts_);  // warm start: p^n in f.pressure
    }
    last_.iterations = r.iterations;
    last_.residual = r.true_relative_residual;
    last_.history = r.history;
    if (!r.converged()) fail(step, r.reason);
    total_ += r.iterations;
    ++solves_;
    seconds_ += r.seconds;
  }

  // y = D^-1 A x over the given lists, with the pair coefficients stored (those of the last solve; computed
  // here when the scene does not store them) or matrix-free.
  void apply(const sph::Fluid<T, D>& f, const sph::WallPoints<T, D>& wp, const sph::Params<T, D>& par,
             const neighbors::NeighborList& ff, const neighbors::NeighborList& fw, const neighbors::NeighborList& gf,
             const View1<T>& x, const View1<T>& y, bool stored) const {
    PressureOperator<T, D> op{f, wp, par, &ff, &fw, &gf, {}, {}, {}};
    if (stored && stored_) {
      op.ghost_coef = coef_[0];
      op.fluid_coef = coef_[1];
      op.wall_coef = coef_[2];
    } else if (stored) {
      op.store_coefficients();
    }
    op.apply(x, y);
  }

  // The number of free-surface (Dirichlet) particles: an integer sum, the same for any thread count.
  static Index surface_count(const sph::Fluid<T, D>& f) {
    const sph::Flags s = f.surface;
    Index n = 0;
    Kokkos::parallel_reduce(
        "polymech::isph::surface_count", Kokkos::RangePolicy<ExecSpace>(0, f.size()),
        KOKKOS_LAMBDA(const Index i, Index& acc) { acc += s(i) ? 1 : 0; }, n);
    return n;
  }

  const PpeRecord& last() const { return last_; }
  // false from the first failed solve on (until restore); reason() says which step and why
  bool ok() const { return ok_; }
  const std::string& reason() const { return reason_; }
  long long iterations_total() const { return total_; }
  long long solves() const { return solves_; }
  double seconds() const { return seconds_; }
  // From a checkpoint: the record as the solves left it.
  void restore(long long total, long long solves, double seconds, PpeRecord last, bool ok, std::string reason) {
    total_ = total;
    solves_ = solves;
    seconds_ = seconds;
    last_ = std::move(last);
    ok_ = ok;
    reason_ = std::move(reason);
  }

 private:
  void fail(std::int64_t step, const std::string& why) {
    if (!ok_) return;  // the first failure is the one to report
    ok_ = false;
    reason_ = "in step " + std::to_string(step + 1) + ": " + why;
  }

  bool stored_ = true, two_level_enabled_ = false;
  double coarse_cell_ = 0.0;
  solvers::SolverOptions opts_;
  TwoLevelPpe<T, D, PressureOperator<T, D>> two_level_;  // ppe_preconditioner two_level only (empty otherwise)
  View1<T> coef_[3];  // the PPE operator's stored pair coefficients (ppe_stored): ghost, fluid, wall lists
  PpeRecord last_;
  bool ok_ = true;
  std::string reason_;
  long long total_ = 0, solves_ = 0;
  double seconds_ = 0.0;
};

}  // namespace polymech::isph
