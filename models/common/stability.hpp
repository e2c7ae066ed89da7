// One stability estimate for any explicit model: the largest eigenvalue lambda of M^-1 K of its
// linearised operator, by power iteration (kernels/particles/power_iteration.hpp), and the stable step
// of symplectic Euler and velocity Verlet, dt <= 2 / sqrt(lambda) (both are the same leapfrog for a
// linear system). Models run it on a small patch of their own discretisation (the fastest modes are
// local), so a scene's time step is checked before anything of full size is allocated.
#pragma once

#include <cmath>

#include "particles/power_iteration.hpp"

namespace polymech::models {

// apply(): the model's accelerations at the current state (dofs.response), after any state-derived
// refresh the model needs (e.g. the rotation's trigonometry). Leaves the DoFs at the last iterate:
// the caller resets its state.
template <class T, class Dofs, class Apply>
double largest_eigenvalue(const Dofs& dofs, Index n, Apply&& apply, T eps, int iterations,
                          particles::StartVector start) {
  particles::power_iteration_start(dofs, n, eps, start);
  double lambda = 0.0;
  for (int it = 0; it < iterations; ++it) {
    apply();
    lambda = particles::power_iteration_rayleigh_quotient(dofs, n);
    particles::power_iteration_step(dofs, n, eps);
  }
  return lambda;
}

// The stable step of the explicit leapfrog for a largest eigenvalue lambda of M^-1 K.
inline double leapfrog_stable_step(double lambda) { return lambda > 0.0 ? 2.0 / std::sqrt(lambda) : 0.0; }

}  // namespace polymech::models
