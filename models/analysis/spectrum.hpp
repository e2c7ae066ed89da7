// Amplitude spectra of probe signals and the amplitudes at harmonics of a drive frequency (seed 000
// §5.2, Figs. 8 and 10: spectra normalised by the peak at the 2 MHz drive). Host-only, FFTW.
#pragma once

#include <vector>

namespace polymech::analysis {

struct Spectrum {
  std::vector<double> frequency;  // [Hz], 0 .. Nyquist
  std::vector<double> amplitude;  // single-sided amplitude |X(f)| * 2 / n (a sine of amplitude A peaks near A)
};

// Spectrum of samples taken every dt, zero-padded to `pad` times the next power of two of the length
// (interpolates the spectrum so peaks are found between bins; it adds no information).
Spectrum amplitude_spectrum(const std::vector<double>& samples, double dt, int pad = 4);

// Largest amplitude within [k f0 - w, k f0 + w], k = 1..count, with w = half_width * f0.
std::vector<double> harmonic_amplitudes(const Spectrum& s, double f0, int count = 5, double half_width = 0.25);

// harmonic_amplitudes divided by the first one: [A1/A1, A2/A1, ..., A_count/A1].
std::vector<double> harmonic_ratios(const Spectrum& s, double f0, int count = 5, double half_width = 0.25);

// Harmonic content of the steady part of a tone burst (seed 000 §5.2): the Fourier coefficients at
// n f0, n = 1..count, of x over exactly `periods` drive periods starting at t_start (mean removed).
// Over an integer number of periods a steady sinusoid has no leakage into n f0, n >= 2: what is
// found there was generated (crack clapping, friction), not smeared from the burst's abrupt edges.
std::vector<double> burst_harmonic_amplitudes(const std::vector<double>& t, const std::vector<double>& x,
                                              double t_start, double f0, double periods = 3.0, int count = 5);

// The burst's steady window: it starts one period after the arrival (the first time |x| reaches half
// its peak, minus a quarter period). Returns the start time.
double burst_steady_start(const std::vector<double>& t, const std::vector<double>& x, double f0);

}  // namespace polymech::analysis
