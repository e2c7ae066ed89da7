// Incident waves of seed 000 as prescribed displacements of source particles.
//  - point source, eq. (22): u3 = -u0/2 (1 - cos 2 pi alpha), alpha = n dt / T in [0, 1];
//  - plane P wave, eq. (23): u3 = -u0 sin 2 pi alpha on the whole top row, alpha in [0, 5];
//  - plane S wave, eq. (24): u1 = -u0 sin 2 pi alpha on the whole top row, alpha in [0, 5].
// While the pulse lasts the prescribed component of every source particle is set after each step;
// afterwards the particles move freely (the top surface becomes a free surface again).
#pragma once

#include <cmath>

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::mps {

enum class PulseShape {
  hann,  // eq. (22): -u0/2 (1 - cos 2 pi alpha), one cycle
  sine,  // eqs. (23)-(24): -u0 sin 2 pi alpha, `cycles` cycles
};

struct Pulse {
  PulseShape shape = PulseShape::hann;
  double amplitude = 0.0;  // u0
  double period = 0.0;     // T
  double cycles = 1.0;     // alpha runs over [0, cycles]
  int component = 1;       // 0: x1 (horizontal), 1: x3 (vertical)

  double duration() const { return cycles * period; }
  bool active(double t) const { return t >= 0.0 && t <= duration() * (1.0 + 1e-12); }
  // Prescribed displacement at time t (zero outside the pulse).
  double displacement(double t) const {
    if (!active(t)) return 0.0;
    const double alpha = t / period;
    constexpr double two_pi = 6.283185307179586476925286766559;
    return shape == PulseShape::hann ? -0.5 * amplitude * (1.0 - std::cos(two_pi * alpha))
                                     : -amplitude * std::sin(two_pi * alpha);
  }
};

// Set component c of u and v of the source particles to the prescribed motion between t and t + dt.
template <class T>
void prescribe_displacement(const View1<Index>& sources, const VecView<T, 2>& u, const VecView<T, 2>& v,
                            int component, double u_new, double u_old, double dt) {
  const T un = static_cast<T>(u_new);
  const T vn = static_cast<T>((u_new - u_old) / dt);
  Kokkos::parallel_for(
      "polymech::mps::prescribed_displacement", range(static_cast<std::int64_t>(sources.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t k) {
        const Index i = sources(k);
        u(i, component) = un;
        v(i, component) = vn;
      });
}

}  // namespace polymech::mps
