// The particle set every particle method shares (MPS, peridynamics, SPH, DEM, EFG nodes): reference
// positions, displacement, velocity, acceleration, volume, and velocity constraints. A method keeps
// its own state beside it (pd::Fields and mps::ElasticFields derive from it), so the integrators, the
// reductions, the watchdog and the contact kernels work on any method's particles.
//
// State is the displacement u from the reference positions x0, not the position: with nanometre waves
// in a 0.1 m plate (seed 000), positions in float would lose the signal, while u keeps full relative
// precision in either type. The current position is x0 + u.
//
// Optional parts stay empty Views (extent 0) when a method does not need them: `volume` (methods
// whose particles all have the same volume keep that constant themselves) and the constraints.
#pragma once

#include <cstdint>
#include <string>

#include "core/small_math.hpp"
#include "core/types.hpp"

namespace polymech::particles {

// Constraint bits (ParticleSet::constraint): bit k set = velocity component k is prescribed.
inline constexpr std::uint8_t constrain_all = 7;

template <class T, int D>
struct ParticleSet {
  using value_type = T;
  static constexpr int dim = D;

  VecView<T, D> x0;  // reference positions
  VecView<T, D> u;   // displacement
  VecView<T, D> v;   // velocity
  VecView<T, D> a;   // acceleration
  View1<T> volume;   // per particle; empty when the method's particles share one volume
  Kokkos::View<std::uint8_t*, MemSpace> constraint;  // bits: prescribed velocity components (empty: none)
  VecView<T, D> prescribed_v;                         // the prescribed velocity where constrained

  KOKKOS_INLINE_FUNCTION Index size() const { return static_cast<Index>(x0.extent(0)); }
  KOKKOS_INLINE_FUNCTION Vec<T, D> reference(Index i) const { return load<D>(x0, i); }
  KOKKOS_INLINE_FUNCTION Vec<T, D> displacement(Index i) const { return load<D>(u, i); }
  KOKKOS_INLINE_FUNCTION Vec<T, D> velocity(Index i) const { return load<D>(v, i); }
  KOKKOS_INLINE_FUNCTION Vec<T, D> position(Index i) const { return load<D>(x0, i) + load<D>(u, i); }
  bool constrained() const { return constraint.extent(0) > 0; }
};

// What allocate() creates besides x0, u, v, a.
struct ParticleLayout {
  bool volume = false;       // a per-particle volume
  bool constraints = false;  // constraint bits and prescribed velocities (zero: nothing constrained)
};

// Allocates n particles (zero-initialised), labelled "<prefix>x0", "<prefix>u", ... so that kernel
// censuses and profiles name the owning model.
template <class T, int D>
void allocate(ParticleSet<T, D>& p, Index n, const std::string& prefix, ParticleLayout layout = {}) {
  const auto size = static_cast<std::size_t>(n);
  p.x0 = VecView<T, D>(prefix + "x0", size);
  p.u = VecView<T, D>(prefix + "u", size);
  p.v = VecView<T, D>(prefix + "v", size);
  p.a = VecView<T, D>(prefix + "a", size);
  if (layout.volume) p.volume = View1<T>(prefix + "volume", size);
  if (layout.constraints) {
    p.constraint = Kokkos::View<std::uint8_t*, MemSpace>(prefix + "constraint", size);
    p.prescribed_v = VecView<T, D>(prefix + "prescribed_v", size);
  }
}

// Copies host reference positions (n x D, row-major) into x0, rounded to T.
template <class T, int D, class HostCoordinates>
void set_reference_positions(const ParticleSet<T, D>& p, const HostCoordinates& coord) {
  auto h = Kokkos::create_mirror_view(p.x0);
  for (Index i = 0; i < p.size(); ++i)
    for (int k = 0; k < D; ++k) h(i, k) = static_cast<T>(coord(i, k));
  Kokkos::deep_copy(p.x0, h);
}

}  // namespace polymech::particles
