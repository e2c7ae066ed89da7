// Efg<T>, part: crack growth at a prescribed speed (seed 004 §3.3): the tips moved each step, the crack
// segments, shape functions, K and M rebuilt and K_eff refactorised; the path nodes the tip passes
// split in two (the paper's Model 4) and, optionally, tied while the tip runs on (Config::
// path_release_gradual, the finite-element node-release remedy, not in the paper). Included by
// efg/efg.hpp.
#pragma once

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "efg/efg.hpp"

namespace polymech::efg {

// The prescribed growth of seed 004 §3.3 (config growth_start, growth_speed, final_crack_length): from
// growth_start both tips run at growth_speed up to final_crack_length. grow_crack() moves them to where
// they are at the END of the coming step, t_n + dt (nothing before growth_start or once there): the
// implicit step solves the balance at t_n + dt, so the solution at time t has the crack a(t) (moving
// it to a(t_n) instead lags the crack by one step: the first step after growth_start then still has
// the stationary crack). With set_prescribed_growth(true) every step() does it first (models::run).
template <class T>
inline void Efg<T>::grow_crack() {
  const auto& c = config_;
  const double t = time_ + dt_;
  if (!(c.growth_speed > 0) || t <= c.growth_start + 1e-3 * dt_) return;
  const double a = std::min(c.final_crack_length, initial_a_ + c.growth_speed * (t - c.growth_start));
  if (a > c.crack_length) set_crack_length(a, a < c.final_crack_length ? c.growth_speed : 0.0);
}

// Moves the tip(s) to half-length (or length) a running at `speed`: the crack segment, the shape
// functions, K and M are rebuilt (the nodal coefficients stay), K_eff refactorised, the J' paths and the
// opening probe follow the tip. The residual r of the next step carries the released forces.
template <class T>
inline void Efg<T>::set_crack_length(double a, double speed) {
  config_.crack_length = a;
  speed_ = speed;
  if (config_.crack == CrackKind::edge) {
    layout_.crack[2] = a;
  } else if (config_.crack == CrackKind::centre) {
    layout_.crack[0] = -a;
    layout_.crack[2] = a;
  }
  layout_.tip_x = a;
  split_passed_nodes();
  upload_crack();
  contours_.clear();
  cod_ready_ = false;
  assemble();
  factor_effective_stiffness();
}

// The layout's crack segments to the device (crack_ sized by the constructor).
template <class T>
inline void Efg<T>::upload_crack() {
  auto hc = Kokkos::create_mirror_view(crack_);
  for (std::size_t s = 0; s < layout_.crack.size() / 4; ++s)
    for (int k = 0; k < 4; ++k) hc(s, k) = static_cast<T>(layout_.crack[4 * s + static_cast<std::size_t>(k)]);
  Kokkos::deep_copy(crack_, hc);
}

// A node on the crack line (y = 0 exactly: a path node of Config::path_nodes) that the crack now
// covers would be seen from both faces and tie them together: it becomes two, the node itself moved
// onto the upper face and a twin on the lower one (y = +- Layout::face_offset, as the layout puts
// crack-face nodes), same support radius, the twin appended with a copy of the node's u, v, a
// coefficients (the field is continuous there until the faces separate). A node at the tip (within
// 1e-9 h_min) stays whole: the visibility criterion lets a segment through the tip see it.
template <class T>
inline void Efg<T>::split_passed_nodes() {
  const double a = config_.crack_length, tol = 1e-9 * config_.h_min, eps = layout_.face_offset;
  if (config_.crack == CrackKind::none) return;
  std::vector<std::size_t> passed;
  for (std::size_t i = 0; i < layout_.node_count(); ++i) {
    const double x = layout_.nodes[2 * i], y = layout_.nodes[2 * i + 1];
    const double ax = config_.crack == CrackKind::centre ? std::abs(x) : x;
    if (y == 0.0 && ax < a - tol) passed.push_back(i);
  }
  if (passed.empty()) return;
  // twins appended in the order the tips pass them (|x|, then x), so a restart that splits all the
  // passed nodes at once numbers them as the run that split them step by step did
  std::sort(passed.begin(), passed.end(), [&](std::size_t i, std::size_t j) {
    const double xi = layout_.nodes[2 * i], xj = layout_.nodes[2 * j];
    const double ai = config_.crack == CrackKind::centre ? std::abs(xi) : xi, aj = config_.crack == CrackKind::centre ? std::abs(xj) : xj;
    return ai < aj || (ai == aj && xi < xj);
  });
  const Eigen::Index n0 = static_cast<Eigen::Index>(2 * layout_.node_count());
  for (const std::size_t i : passed) {
    layout_.nodes[2 * i + 1] = eps;
    layout_.nodes.insert(layout_.nodes.end(), {layout_.nodes[2 * i], -eps});
    layout_.dm.push_back(layout_.dm[i]);
    if (config_.path_release_gradual) {
      const double ax = config_.crack == CrackKind::centre ? std::abs(layout_.nodes[2 * i]) : layout_.nodes[2 * i];
      const auto next = std::upper_bound(layout_.xs.begin(), layout_.xs.end(), ax + tol);
      const double length = next != layout_.xs.end() ? *next - ax : config_.h_min;
      ties_.push_back({static_cast<Index>(i), static_cast<Index>(layout_.dm.size() - 1), ax, length, Tie::fresh, {0.0, 0.0}});
    }
  }
  const auto grow = [&](Eigen::VectorXd& x) {
    if (x.size() != n0) return;  // not started: start_dynamic sizes it
    x.conservativeResize(n0 + static_cast<Eigen::Index>(2 * passed.size()));
    for (std::size_t k = 0; k < passed.size(); ++k)
      for (int c = 0; c < 2; ++c)
        x(n0 + static_cast<Eigen::Index>(2 * k) + c) = x(static_cast<Eigen::Index>(2 * passed[k]) + c);
  };
  grow(ud_);
  grow(vd_);
  grow(ad_);
  split_nodes_ += static_cast<Index>(passed.size());
  upload_nodes();
  if (ud_.size() == static_cast<Eigen::Index>(2 * layout_.node_count())) sync_dynamic();
}

// Config::path_release_gradual (the finite-element node-release remedy, not in the paper): a split
// pair stays tied (a penalty spring k (u+ - u-)^2 / 2 per component, k = tie_stiffness()) for the step
// that splits it; from the next growth step on the spring is replaced by the force it carried then,
// F0 = k (u+ - u-), applied to the twins and falling linearly to 0 while the tip runs the next node
// spacing past the node: F = F0 (1 - s), s = (a - x_node) / spacing. Called by assemble().
template <class T>
inline void Efg<T>::add_ties(Triplets& trip, Eigen::VectorXd& f) {
  const Index n = nodes();
  for (auto& t : ties_) {
    if (t.state == Tie::tied && !restore_ties_ && ud_.size() == static_cast<Eigen::Index>(2 * n)) {
      for (int c = 0; c < 2; ++c) t.f0[c] = tie_stiffness() * (ud_(2 * t.upper + c) - ud_(2 * t.lower + c));
      t.state = Tie::released;
    }
    if (t.state == Tie::fresh || t.state == Tie::tied) {  // (tied: only when a checkpoint is restored)
      for (int c = 0; c < 2; ++c) {
        const int a = static_cast<int>(2 * t.upper + c), b = static_cast<int>(2 * t.lower + c);
        trip.emplace_back(a, a, tie_stiffness());
        trip.emplace_back(b, b, tie_stiffness());
        trip.emplace_back(a, b, -tie_stiffness());
        trip.emplace_back(b, a, -tie_stiffness());
      }
      t.state = Tie::tied;
    } else if (t.state == Tie::released) {
      const double left = std::max(0.0, 1.0 - (config_.crack_length - t.x) / t.length);
      for (int c = 0; c < 2; ++c) {
        f(2 * t.upper + c) -= left * t.f0[c];
        f(2 * t.lower + c) += left * t.f0[c];
      }
    }
  }
}

}  // namespace polymech::efg
