// Loading of a NosbPd plate or bar by its particles' velocity constraints (the projectile of an impact
// is a rigid body, models/nosb_pd/impact.hpp):
//  - tension (seed 003 §4(1)): grips of one horizon at x = 0 (held in x) and x = length (pulled in x),
//    free lateral contraction; the measurements of the test (grip force, gauge strain);
//  - impact: the plate's particles farther than clamp_radius from the axis are held fixed.
#pragma once

#include <cstdint>
#include <string>

#include "nosb_pd/config.hpp"
#include "particles/reductions.hpp"
#include "pd/fields.hpp"

namespace polymech::nosb_pd {

// Tension test: internal force on the pulled grip (group 2) along x, and the least-squares slope of
// u_x over x for the particles with x0 in [x_lo, x_hi] (the strain of the gauge section).
struct TensionMeasure {
  double grip_force = 0.0;
  double gauge_strain = 0.0;
};

namespace detail {

template <class T, int D>
TensionMeasure tension_measure(const pd::Fields<T, D>& f, const Kokkos::View<std::uint8_t*, MemSpace>& group, T density,
                               T x_lo, T x_hi) {
  const auto s = particles::ordered_sum<6>(
      "polymech::nosb_pd::tension_measure", static_cast<std::int64_t>(f.u.extent(0)),
      KOKKOS_LAMBDA(const std::int64_t i, double* acc) {
        if (group(i) == 2) acc[0] -= double(density * f.volume(i) * f.a(i, 0));
        const T x = f.x0(i, 0);
        if (x >= x_lo && x <= x_hi) {
          const double xd = double(x), ud = double(f.u(i, 0));
          acc[1] += 1.0;
          acc[2] += xd;
          acc[3] += ud;
          acc[4] += xd * xd;
          acc[5] += xd * ud;
        }
      });
  TensionMeasure m;
  m.grip_force = s[0];
  const double n = s[1], sxx = s[4] - s[2] * s[2] / n, sxu = s[5] - s[2] * s[3] / n;
  m.gauge_strain = n > 1 && sxx > 0 ? sxu / sxx : 0.0;
  return m;
}

}  // namespace detail

template <class T, int D>
class Constraints {
 public:
  Constraints() = default;

  // Allocates the constraint Views of `f` (only when the loading constrains anything) and sets them.
  Constraints(const Config& c, pd::Fields<T, D>& f) : cfg_(c) {
    if (c.loading == Loading::none) return;
    if (c.loading == Loading::impact && !(c.clamp_radius > 0)) return;
    const std::string pre = "polymech::nosb_pd::";
    const auto n = static_cast<std::size_t>(f.size());
    f.constraint = Kokkos::View<std::uint8_t*, MemSpace>(pre + "constraint", n);
    f.prescribed_v = VecView<T, D>(pre + "prescribed_v", n);
    auto hc = Kokkos::create_mirror_view(f.constraint);
    auto hx = Kokkos::create_mirror_view_and_copy(HostSpace(), f.x0);
    Kokkos::deep_copy(hc, std::uint8_t(0));
    if (c.loading == Loading::tension) {
      group_ = Kokkos::View<std::uint8_t*, MemSpace>(pre + "tension_group", n);
      auto hg = Kokkos::create_mirror_view(group_);
      const double delta = c.horizon(), L = c.geometry.length;
      for (std::size_t i = 0; i < n; ++i) {
        const double x = static_cast<double>(hx(i, 0));
        hg(i) = x < delta ? 1 : (x > L - delta ? 2 : 0);
        hc(i) = hg(i) ? 1 : 0;  // the grips hold / pull x only: free lateral contraction
      }
      Kokkos::deep_copy(group_, hg);
      cross_section_ = c.geometry.shape == Shape::round_bar ? bar_cross_section(f)
                                                           : (D == 3 ? c.geometry.width * c.geometry.height : c.geometry.height);
    } else {
      for (std::size_t i = 0; i < n; ++i) {
        double r2 = 0;
        for (int k = 0; k < D - 1; ++k) r2 += static_cast<double>(hx(i, k)) * static_cast<double>(hx(i, k));
        if (r2 > c.clamp_radius * c.clamp_radius) hc(i) = pd::constrain_all;
      }
    }
    Kokkos::deep_copy(f.constraint, hc);
  }

  // Tension: pull the x = length grip at `velocity` (0: hold).
  void set_grip_velocity(const pd::Fields<T, D>& f, double velocity) const {
    auto pv = Kokkos::create_mirror_view_and_copy(HostSpace(), f.prescribed_v);
    auto g = Kokkos::create_mirror_view_and_copy(HostSpace(), group_);
    for (std::size_t i = 0; i < g.extent(0); ++i)
      if (g(i) == 2) pv(i, 0) = static_cast<T>(velocity);
    Kokkos::deep_copy(f.prescribed_v, pv);
  }
  TensionMeasure tension_measure(const pd::Fields<T, D>& f) const {
    const double L = cfg_.geometry.length;
    return detail::tension_measure(f, group_, static_cast<T>(cfg_.material.density), static_cast<T>(L / 3),
                                   static_cast<T>(2 * L / 3));
  }
  double cross_section() const { return cross_section_; }

 private:
  // Volume of the round bar / its length: the particles' cross-section.
  double bar_cross_section(const pd::Fields<T, D>& f) const {
    auto hv = Kokkos::create_mirror_view_and_copy(HostSpace(), f.volume);
    double vol = 0;
    for (std::size_t i = 0; i < hv.extent(0); ++i) vol += static_cast<double>(hv(i));
    return vol / cfg_.geometry.length;
  }

  Config cfg_;
  Kokkos::View<std::uint8_t*, MemSpace> group_;
  double cross_section_ = 0.0;
};

}  // namespace polymech::nosb_pd
