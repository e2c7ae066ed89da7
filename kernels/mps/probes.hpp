// Probe sampling for the 2D MPS models: a probe is a small weighted set of particles (Shepard
// interpolation with the MPS weight around the probe point), sampled into a device record buffer so
// a run copies probe data to the host in large chunks, not every step.
#pragma once

#include "mps/elastic.hpp"

namespace polymech::mps {

// Fields recorded per probe, in this order.
enum ProbeField : int { probe_u1 = 0, probe_u3, probe_divergence, probe_rotation, probe_theta, probe_field_count };
inline const char* probe_field_name(int f) {
  constexpr const char* names[] = {"u1", "u3", "divergence", "rotation", "theta"};
  return names[f];
}

template <class T>
struct ProbeStencil {
  Kokkos::View<Offset*, MemSpace> offsets;  // probes + 1
  Kokkos::View<Index*, MemSpace> particles;
  Kokkos::View<T*, MemSpace> weights;  // sum to 1 per probe
  int count() const { return offsets.extent(0) > 0 ? static_cast<int>(offsets.extent(0)) - 1 : 0; }
};

// record(slot, probe * probe_field_count + field) = interpolated field at the probe. The
// divergence is the model's volumetric strain e; the rotation is 1/2 curl u from the gradient model
// (seed 000 eq. (3)) on the raw displacement, so it measures the S wave whether or not the
// `rotation` effect is on; theta is the particles' own rotation (0 without the effect).
// sum_j (r_ij x u_ij) w / (|r0_ij| |r_ij|) over the row of i: twice the curl of eq. (3) times n0 / d.
template <class T>
struct CurlSum : ElasticPairSum<T, false, CurlSum<T>> {
  KOKKOS_INLINE_FUNCTION static T term(const ElasticPair<T, false>& q) { return cross(q.r, q.uij) * q.w * q.inv_r0 * q.inv_r; }
};

template <class T, bool Rotation>
void sample_probes(const ProbeStencil<T>& stencil, const neighbors::BondFamily& family, const ElasticFields<T>& f,
                   const ElasticParams<T>& p, const View2<T>& record, std::int64_t slot) {
  const T c = T(2) / p.n0;
  CurlSum<T> curl_sum;
  curl_sum.f = f;
  curl_sum.re = p.re;
  Kokkos::parallel_for(
      "polymech::mps::sample_probes", range(stencil.count()), KOKKOS_LAMBDA(const int probe) {
        T acc[probe_field_count] = {};
        for (Offset s = stencil.offsets(probe); s < stencil.offsets(probe + 1); ++s) {
          const Index i = stencil.particles(s);
          const T wgt = stencil.weights(s);
          auto row = curl_sum.start(i);
          neighbors::gather_row(family, i, curl_sum, row);
          acc[probe_u1] += wgt * f.u(i, 0);
          acc[probe_u3] += wgt * f.u(i, 1);
          acc[probe_divergence] += wgt * f.e(i);
          acc[probe_rotation] += wgt * T(0.5) * c * row.s;
          if constexpr (Rotation) acc[probe_theta] += wgt * f.theta(i);
        }
        for (int k = 0; k < probe_field_count; ++k) record(slot, probe * probe_field_count + k) = acc[k];
      });
}

}  // namespace polymech::mps
