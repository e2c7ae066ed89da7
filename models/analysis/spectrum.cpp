#include "analysis/spectrum.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace polymech::analysis {

namespace {
// "1.25e-05" style, short enough for a message (std::to_string gives 0.000004 for 4.2e-6)
std::string format_seconds(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", t);
  return b;
}
}  // namespace

Spectrum amplitude_spectrum(const std::vector<double>& samples, double dt, int pad) {
  const std::size_t n = samples.size();
  if (n < 2 || !(dt > 0)) throw std::invalid_argument("amplitude_spectrum: need >= 2 samples and dt > 0");
  std::size_t nfft = 1;
  while (nfft < n) nfft <<= 1;
  nfft *= static_cast<std::size_t>(std::max(1, pad));
  std::vector<double> in(nfft, 0.0);
  std::copy(samples.begin(), samples.end(), in.begin());
  std::vector<std::complex<double>> out(nfft / 2 + 1);
  fftw_plan plan = fftw_plan_dft_r2c_1d(static_cast<int>(nfft), in.data(), reinterpret_cast<fftw_complex*>(out.data()),
                                        FFTW_ESTIMATE);
  if (!plan) throw std::runtime_error("amplitude_spectrum: FFTW could not make a plan");
  fftw_execute(plan);
  fftw_destroy_plan(plan);
  Spectrum s;
  s.frequency.resize(out.size());
  s.amplitude.resize(out.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    s.frequency[k] = static_cast<double>(k) / (static_cast<double>(nfft) * dt);
    s.amplitude[k] = 2.0 * std::abs(out[k]) / static_cast<double>(n);
  }
  return s;
}

std::vector<double> harmonic_amplitudes(const Spectrum& s, double f0, int count, double half_width) {
  std::vector<double> a(static_cast<std::size_t>(count), 0.0);
  for (int h = 1; h <= count; ++h) {
    const double lo = (h - half_width) * f0, hi = (h + half_width) * f0;
    for (std::size_t k = 0; k < s.frequency.size(); ++k)
      if (s.frequency[k] >= lo && s.frequency[k] <= hi) a[h - 1] = std::max(a[h - 1], s.amplitude[k]);
  }
  return a;
}

std::vector<double> harmonic_ratios(const Spectrum& s, double f0, int count, double half_width) {
  auto a = harmonic_amplitudes(s, f0, count, half_width);
  const double a1 = a.empty() ? 0.0 : a[0];
  for (auto& x : a) x = a1 > 0 ? x / a1 : 0.0;
  return a;
}

std::vector<double> burst_harmonic_amplitudes(const std::vector<double>& t, const std::vector<double>& x,
                                              double t_start, double f0, double periods, int count) {
  if (t.size() != x.size()) throw std::invalid_argument("burst_harmonic_amplitudes: t and x differ in length");
  const double t_end = t_start + periods / f0;
  // a window that runs past the record would mix the burst with silence: its ratios mean nothing (issue 33)
  const double sample = t.size() > 1 ? t[1] - t[0] : 0.0;
  if (t.empty() || t_end > t.back() + 0.5 * sample)
    throw std::invalid_argument("the window [" + format_seconds(t_start) + ", " + format_seconds(t_end) +
                                "] s runs past the end of the record (" + format_seconds(t.empty() ? 0.0 : t.back()) +
                                " s): record more steps");
  std::vector<std::size_t> idx;
  double mean = 0.0;
  for (std::size_t k = 0; k < t.size(); ++k)
    if (t[k] >= t_start && t[k] < t_end) {
      idx.push_back(k);
      mean += x[k];
    }
  if (idx.size() < 8)
    throw std::invalid_argument("the window [" + format_seconds(t_start) + ", " + format_seconds(t_end) +
                                "] s holds fewer than 8 samples: record more often (probe_every)");
  mean /= static_cast<double>(idx.size());
  constexpr double two_pi = 6.283185307179586476925286766559;
  std::vector<double> a(static_cast<std::size_t>(count));
  for (int n = 1; n <= count; ++n) {
    double c = 0.0, s = 0.0;
    for (std::size_t k : idx) {
      const double phase = two_pi * n * f0 * t[k];
      c += (x[k] - mean) * std::cos(phase);
      s += (x[k] - mean) * std::sin(phase);
    }
    a[static_cast<std::size_t>(n - 1)] = 2.0 * std::hypot(c, s) / static_cast<double>(idx.size());
  }
  return a;
}

double burst_steady_start(const std::vector<double>& t, const std::vector<double>& x, double f0) {
  double peak = 0.0;
  for (double v : x) peak = std::max(peak, std::abs(v));
  if (!(peak > 0.0)) throw std::invalid_argument("burst_steady_start: the signal is zero");
  for (std::size_t k = 0; k < x.size(); ++k)
    if (std::abs(x[k]) >= 0.5 * peak) return t[k] - 0.25 / f0 + 1.0 / f0;
  return t.back();
}

}  // namespace polymech::analysis
