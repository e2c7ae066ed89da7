// The reduced-size crack case and the timing of the plane burst (seed 000 section 5.2), free of Kokkos so
// that the scene loader (io/mps_elastic_scene.cpp, [crop]) can use them: a probe by name, the plate cropped
// around the crack, the burst's arrival at a probe and the steps a run or a harmonic window needs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "mps_elastic/config.hpp"

namespace polymech::mps_elastic {

inline const Probe& probe_named(const Config& c, const std::string& name) {
  for (const auto& p : c.probes)
    if (p.name == name) return p;
  throw std::invalid_argument("no probe named '" + name + "'");
}

// Reduced-size versions of a crack scene (tests, sweeps): the plate cut down around the crack, which
// is centred with `depth` of plate above it (to the driven top row) and `below` under it; probes keep
// their offsets from the crack (those that fall outside are dropped).
inline void crop_around_crack(Config& c, double width, double depth, double below) {
  const double dx = 0.5 * width - c.crack.x1, dz = below - c.crack.x3;
  c.width = width;
  c.height = depth + below;
  c.crack.x1 += dx;
  c.crack.x3 += dz;
  c.excitation.position += dx;
  for (auto& p : c.probes) {
    p.x1 += dx;
    p.x3 += dz;
  }
  c.probes.erase(std::remove_if(c.probes.begin(), c.probes.end(),
                                [&](const Probe& p) { return p.x1 < 0 || p.x1 > width || p.x3 < 0 || p.x3 > c.height; }),
                 c.probes.end());
}

// The time the plane burst from the top row needs to reach `probe` (P or S wave speed).
inline double burst_arrival(const Config& c, const Probe& a) {
  const double speed = c.excitation.kind == ExcitationKind::plane_s ? std::sqrt(c.c55 / c.density)
                                                                     : std::sqrt((c.c13 + 2 * c.c55) / c.density);
  return (c.height - a.x3) / speed;
}

// Steps until the plane burst (P or S) from the top row has passed `probe`, with one period to spare.
inline std::int64_t steps_until_burst_passes(const Config& c, const std::string& probe) {
  const double arrival = burst_arrival(c, probe_named(c, probe));
  return std::llround((arrival + (c.excitation.cycles + 1.0) * c.excitation.period) / c.dt);
}

// Steps the record needs for the harmonic ratios at `probe`: the burst's steady window starts one period
// after it arrives (less a quarter, plus the sine's rise to half its peak, T/12) and lasts three periods
// (analysis::burst_steady_start, burst_harmonic_amplitudes); a quarter period to spare for dispersion.
inline std::int64_t steps_for_harmonic_window(const Config& c, const std::string& probe) {
  const double end = burst_arrival(c, probe_named(c, probe)) + 4.0 * c.excitation.period;
  return static_cast<std::int64_t>(std::ceil(end / c.dt));
}

}  // namespace polymech::mps_elastic
