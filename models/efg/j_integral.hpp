// Efg<T>, part: the J-integral of seed 004 eq. (13) around the (right) crack tip: the static J on a
// circle (contour part), the dynamic J' (contour with the kinetic energy plus the inertia integral over
// the disc), their mean over a radial band (Config::j_band), and the velocity factor of a running crack
// that turns J' into K. Included by efg/efg.hpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "efg/efg.hpp"
#include "fem/gauss_legendre.hpp"

namespace polymech::efg {

// seed 004 eq. (13) on the path of `radius`: dynamic_j_at(radius) (the paper's single circle) when
// Config::j_band is 0, else the mean of dynamic_j_at over the band of radii [r - d/2, r + d/2],
// d = j_band_width(r), at 4 radial Gauss points. The mean over r of eq. (13) equals the equivalent
// domain integral with q(r) falling linearly across the band; it cancels the error of the MLS
// stresses that oscillates with r at the period of the node lines (docs/METHODS.md, 'J-integral band').
template <class T>
inline JResult Efg<T>::dynamic_j(double radius, int cells) {
  return banded(radius, [&](double r) { return dynamic_j_at(r, cells); }, effective_modulus(config_) / velocity_factor(speed_), initial_a_);
}

// seed 004 eq. (13): J' = int_Gamma [(W + K) n_1 - t_i u_i,1] dS + int_V [rho a_i u_i,1 - rho v_i v_i,1] dV
// on the circle of `radius` around the tip and the disc inside it (radial x angular cells of `cells`
// each, 4 x 4 Gauss points: the paper's 20 x 20).
template <class T>
inline JResult Efg<T>::dynamic_j_at(double radius, int cells) {
  auto& c = contour_cache(radius, cells);
  double j = 0.0;
  const auto u = probe(c.contour, u_), v = probe(c.contour, v_);
  for (std::size_t p = 0; p < c.w.size(); ++p) {
    const double* g = &u[6 * p];
    const double* h = &v[6 * p];
    const double exx = g[2], eyy = g[5], gxy = g[3] + g[4];
    const double sxx = (lam_ + 2 * mu_) * exx + lam_ * eyy, syy = lam_ * exx + (lam_ + 2 * mu_) * eyy, sxy = mu_ * gxy;
    const double W = 0.5 * (sxx * exx + syy * eyy + sxy * gxy);
    const double Kd = 0.5 * config_.density * (h[0] * h[0] + h[1] * h[1]);
    const double n1 = std::cos(c.th[p]), n2 = std::sin(c.th[p]);
    const double t1 = sxx * n1 + sxy * n2, t2 = sxy * n1 + syy * n2;
    j += c.w[p] * ((W + Kd) * n1 - (t1 * g[2] + t2 * g[4]));
  }
  const auto du = probe(c.domain, u_), dv = probe(c.domain, v_), da = probe(c.domain, a_);
  for (std::size_t p = 0; p < c.dw.size(); ++p) {
    const double* g = &du[6 * p];
    const double* h = &dv[6 * p];
    const double* q = &da[6 * p];
    j += c.dw[p] * config_.density * (q[0] * g[2] + q[1] * g[4] - (h[0] * h[2] + h[1] * h[4]));
  }
  constexpr double pi = 3.14159265358979323846;
  JResult r;
  r.radius = radius;
  r.j = j;
  r.k = std::sqrt(std::max(0.0, j) * effective_modulus(config_) / velocity_factor(speed_));
  r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * initial_a_)) : 0.0;
  return r;
}

// J' = A_I(v) K_I^2 / E' for a crack running at v (Freund; Nishioka & Atluri): A_I = v^2 alpha_d /
// ((1 - nu) c_s^2 D), D = 4 alpha_d alpha_s - (1 + alpha_s^2)^2, alpha = sqrt(1 - v^2 / c^2); with the
// plane-stress nu' = nu / (1 + nu) in plane stress. 1 at v = 0.
template <class T>
inline double Efg<T>::velocity_factor(double v) const {
  if (!(v > 0)) return 1.0;
  const double nu = config_.plane_strain ? config_.poisson : config_.poisson / (1 + config_.poisson);
  const double cs2 = mu_ / config_.density, cd2 = (lam_ + 2 * mu_) / config_.density;
  const double ad = std::sqrt(std::max(0.0, 1 - v * v / cd2)), as = std::sqrt(std::max(0.0, 1 - v * v / cs2));
  const double D = 4 * ad * as - (1 + as * as) * (1 + as * as);
  return v * v * ad / ((1 - nu) * cs2 * D);
}

// The static J on the path of `radius`: j_integral_at(radius) when Config::j_band is 0, else its mean
// over the band of radii as in dynamic_j.
template <class T>
inline JResult Efg<T>::j_integral(double radius) const {
  return banded(radius, [&](double r) { return j_integral_at(r); }, effective_modulus(config_), config_.crack_length);
}

// seed 004 eq. (13), static part: J = int_Gamma (W n_1 - t_i u_i,1) dS on the circle of `radius`
// around the tip, counter-clockwise from the lower crack face to the upper one (the crack faces are
// traction-free); `arcs` arcs x `gauss` Gauss points.
template <class T>
inline JResult Efg<T>::j_integral_at(double radius) const {
  const int arcs = config_.j_arcs;
  std::vector<double> gx, gw;
  gauss_rule(config_.j_gauss, gx, gw);
  constexpr double pi = 3.14159265358979323846;
  std::vector<double> xy, w, th;
  const double d = 2 * pi / arcs;
  for (int m = 0; m < arcs; ++m)
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double t = -pi + d * (m + 0.5 * (1 + gx[g]));
      xy.push_back(layout_.tip_x + radius * std::cos(t));
      xy.push_back(layout_.tip_y + radius * std::sin(t));
      w.push_back(0.5 * d * gw[g] * radius);
      th.push_back(t);
    }
  const auto v = fields_at(xy, "J-contour");
  double j = 0.0;
  for (std::size_t p = 0; p < w.size(); ++p) {
    const double* g = &v[6 * p];
    const double exx = g[2], eyy = g[5], gxy = g[3] + g[4];
    const double sxx = (lam_ + 2 * mu_) * exx + lam_ * eyy, syy = lam_ * exx + (lam_ + 2 * mu_) * eyy, sxy = mu_ * gxy;
    const double W = 0.5 * (sxx * exx + syy * eyy + sxy * gxy);
    const double n1 = std::cos(th[p]), n2 = std::sin(th[p]);
    const double t1 = sxx * n1 + sxy * n2, t2 = sxy * n1 + syy * n2;
    j += w[p] * (W * n1 - (t1 * g[2] + t2 * g[4]));
  }
  JResult r;
  r.radius = radius;
  r.j = j;
  r.k = std::sqrt(std::max(0.0, j) * effective_modulus(config_));
  r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * config_.crack_length)) : 0.0;
  return r;
}

// The 1D Gauss-Legendre rule of the J paths and the band, ascending (the one rule of the code base).
template <class T>
inline void Efg<T>::gauss_rule(int n, std::vector<double>& x, std::vector<double>& w) {
  fem::gauss_legendre(n, x, w);
}

// J (and K from it) on the path of `radius`: at_radius(radius) without a band, else the mean of
// at_radius over the 4 radial Gauss points of [radius - d/2, radius + d/2], d = j_band_width(radius).
// `modulus`: K^2 = J x modulus; `a_ref`: the length of K / (stress sqrt(pi a_ref)).
template <class T>
template <class F>
inline JResult Efg<T>::banded(double radius, F&& at_radius, double modulus, double a_ref) const {
  const double d = j_band_width(config_, radius);
  if (!(d > 0)) return at_radius(radius);
  std::vector<double> gx, gw;
  gauss_rule(4, gx, gw);
  double j = 0.0;
  for (std::size_t g = 0; g < gx.size(); ++g) j += 0.5 * gw[g] * at_radius(radius + 0.5 * d * gx[g]).j;
  constexpr double pi = 3.14159265358979323846;
  JResult r;
  r.radius = radius;
  r.j = j;
  r.k = std::sqrt(std::max(0.0, j) * modulus);
  r.factor = config_.stress > 0 ? r.k / (config_.stress * std::sqrt(pi * a_ref)) : 0.0;
  return r;
}

// The points and weights of dynamic_j_at's paths of `radius` (kept while the tip stays): the circle's
// `j_arcs` arcs x `j_gauss` Gauss points and the disc's cells x cells cells of 4 x 4 Gauss points, with
// their MLS shape functions.
template <class T>
inline typename Efg<T>::ContourCache& Efg<T>::contour_cache(double radius, int cells) {
  for (auto& c : contours_)
    if (c.radius == radius && c.cells == cells) return c;
  ContourCache c;
  c.radius = radius;
  c.cells = cells;
  std::vector<double> gx, gw;
  gauss_rule(config_.j_gauss, gx, gw);
  constexpr double pi = 3.14159265358979323846;
  std::vector<double> xy;
  const int arcs = config_.j_arcs;
  const double d = 2 * pi / arcs;
  for (int m = 0; m < arcs; ++m)
    for (std::size_t g = 0; g < gx.size(); ++g) {
      const double t = -pi + d * (m + 0.5 * (1 + gx[g]));
      xy.insert(xy.end(), {layout_.tip_x + radius * std::cos(t), layout_.tip_y + radius * std::sin(t)});
      c.w.push_back(0.5 * d * gw[g] * radius);
      c.th.push_back(t);
    }
  c.contour = shape_functions(xy, 2, "J-contour");
  std::vector<double> g4x, g4w;
  gauss_rule(4, g4x, g4w);
  std::vector<double> dxy;
  const double dr = radius / cells, dt = 2 * pi / cells;
  for (int i = 0; i < cells; ++i)
    for (int k = 0; k < cells; ++k)
      for (std::size_t p = 0; p < 4; ++p)
        for (std::size_t q = 0; q < 4; ++q) {
          const double r = dr * (i + 0.5 * (1 + g4x[p]));
          const double t = -pi + dt * (k + 0.5 * (1 + g4x[q]));
          dxy.insert(dxy.end(), {layout_.tip_x + r * std::cos(t), layout_.tip_y + r * std::sin(t)});
          c.dw.push_back(0.25 * dr * dt * g4w[p] * g4w[q] * r);
        }
  c.domain = shape_functions(dxy, 2, "J-domain");
  contours_.push_back(std::move(c));
  return contours_.back();
}

}  // namespace polymech::efg
