// Host-side analysis of probe time series: arrival times, wave speeds, waveform differences.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace polymech::analysis {

// Arrival time of a pulse: the first time |s| reaches `fraction` of its largest magnitude over the
// record (linear interpolation between samples). With fraction 1/2 this is the half-amplitude
// point of the leading edge: it follows the wave front, does not care which lobe of a dispersed
// pulse ends up largest, and needs no expected speed. Probes must sit where the direct wave is the
// strongest arrival of the record.
inline double arrival_time(const std::vector<double>& t, const std::vector<double>& s, double fraction = 0.5) {
  if (t.size() != s.size() || t.size() < 2) throw std::invalid_argument("arrival_time: need matching series of >= 2 samples");
  double peak = 0.0;
  for (double v : s) peak = std::max(peak, std::abs(v));
  if (!(peak > 0.0) || !std::isfinite(peak)) throw std::invalid_argument("arrival_time: the signal is zero or not finite");
  const double level = fraction * peak;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (std::abs(s[k]) < level) continue;
    if (k == 0) return t[0];
    const double a = std::abs(s[k - 1]), b = std::abs(s[k]);
    return t[k - 1] + (level - a) / (b - a) * (t[k] - t[k - 1]);
  }
  return t.back();
}

struct SpeedMeasurement {
  double speed = 0.0;        // (r_far - r_near) / (t_far - t_near)
  double t_near = 0.0, t_far = 0.0;
  double r_near = 0.0, r_far = 0.0;
};

// Wave speed from the arrival times at two probes on one ray from the source, at distances r_near
// and r_far: differencing cancels the source's own delay and most of the near-field shape change.
inline SpeedMeasurement wave_speed(const std::vector<double>& t, const std::vector<double>& near,
                                   const std::vector<double>& far, double r_near, double r_far) {
  SpeedMeasurement m;
  m.r_near = r_near;
  m.r_far = r_far;
  m.t_near = arrival_time(t, near);
  m.t_far = arrival_time(t, far);
  if (!(m.t_far > m.t_near)) throw std::invalid_argument("wave_speed: the far probe's arrival is not later than the near probe's");
  m.speed = (r_far - r_near) / (m.t_far - m.t_near);
  return m;
}

// Linear interpolation of (t, s) at time x (clamped to the record).
inline double interpolate(const std::vector<double>& t, const std::vector<double>& s, double x) {
  if (x <= t.front()) return s.front();
  if (x >= t.back()) return s.back();
  const auto it = std::upper_bound(t.begin(), t.end(), x);
  const std::size_t k = static_cast<std::size_t>(it - t.begin());
  const double w = (x - t[k - 1]) / (t[k] - t[k - 1]);
  return (1 - w) * s[k - 1] + w * s[k];
}

// ||s - s_ref|| / ||s_ref|| over the reference's time grid, with s interpolated onto it: how far a
// coarse run's probe waveform is from the finest run's.
inline double relative_l2_difference(const std::vector<double>& t, const std::vector<double>& s,
                                     const std::vector<double>& t_ref, const std::vector<double>& s_ref) {
  double num = 0.0, den = 0.0;
  for (std::size_t k = 0; k < t_ref.size(); ++k) {
    if (t_ref[k] > t.back()) break;
    const double d = interpolate(t, s, t_ref[k]) - s_ref[k];
    num += d * d;
    den += s_ref[k] * s_ref[k];
  }
  return den > 0 ? std::sqrt(num / den) : 0.0;
}

}  // namespace polymech::analysis
