// Probes of the 2D MPS models: each probe is a small weighted set of particles (Shepard interpolation
// with the MPS weight, eq. (1), over the particles within r_e of the probe point), sampled by a kernel
// into the shared probe buffer (models/common/probes.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/probes.hpp"
#include "mps/probes.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/lattice.hpp"

namespace polymech::mps_elastic {

// values[p][f][s] for probe p, field f (mps::ProbeField), sample s.
using models::ProbeHistory;

template <class T>
class ProbeRecorder {
 public:
  ProbeRecorder() = default;

  // Throws std::invalid_argument for a probe with no particle within r_e.
  ProbeRecorder(const Config& c, const Lattice& lat) {
    if (c.probes.empty()) return;
    std::vector<Offset> off(1, 0);
    std::vector<Index> ids;
    std::vector<double> wts;
    std::vector<std::string> names;
    const double re = c.re();
    for (const auto& p : c.probes) {
      std::vector<std::pair<Index, double>> near;  // particle, weight
      const auto i0 = static_cast<std::int64_t>(std::floor(p.x1 / c.spacing)) - 3;
      const auto j0 = static_cast<std::int64_t>(std::floor(p.x3 / c.spacing)) - 3;
      for (std::int64_t j = std::max<std::int64_t>(0, j0); j < std::min(lat.ny, j0 + 7); ++j)
        for (std::int64_t i = std::max<std::int64_t>(0, i0); i < std::min(lat.nx, i0 + 7); ++i) {
          const Index id = lat.index(i, j);
          const double r = std::hypot(lat.x1(id) - p.x1, lat.x3(id) - p.x3);
          if (r < 1e-9 * c.spacing)
            near.push_back({id, -1.0});  // the probe sits on this particle: it alone is the probe
          else if (r <= re)
            near.push_back({id, re / r - 1.0});  // eq. (1)
        }
      const auto on = std::find_if(near.begin(), near.end(), [](const auto& q) { return q.second < 0; });
      if (on != near.end()) near = {{on->first, 1.0}};
      if (near.empty())
        throw std::invalid_argument("mps_elastic: probe '" + p.name + "' has no particle within r_e (outside the domain?)");
      double sum = 0.0;
      for (auto& q : near) sum += q.second;
      for (auto& q : near) {
        ids.push_back(q.first);
        wts.push_back(q.second / sum);
      }
      off.push_back(static_cast<Offset>(ids.size()));
      names.push_back(p.name);
    }
    stencil_.offsets = Kokkos::View<Offset*, MemSpace>("polymech::mps_elastic::probe_offsets", off.size());
    stencil_.particles = Kokkos::View<Index*, MemSpace>("polymech::mps_elastic::probe_particles", ids.size());
    stencil_.weights = Kokkos::View<T*, MemSpace>("polymech::mps_elastic::probe_weights", wts.size());
    auto ho = Kokkos::create_mirror_view(stencil_.offsets);
    auto hi = Kokkos::create_mirror_view(stencil_.particles);
    auto hw = Kokkos::create_mirror_view(stencil_.weights);
    for (std::size_t k = 0; k < off.size(); ++k) ho(k) = off[k];
    for (std::size_t k = 0; k < ids.size(); ++k) {
      hi(k) = ids[k];
      hw(k) = static_cast<T>(wts[k]);
    }
    Kokkos::deep_copy(stencil_.offsets, ho);
    Kokkos::deep_copy(stencil_.particles, hi);
    Kokkos::deep_copy(stencil_.weights, hw);
    std::vector<std::string> fields;
    for (int f = 0; f < mps::probe_field_count; ++f) fields.push_back(mps::probe_field_name(f));
    buffer_ = models::ProbeBuffer<T>("polymech::mps_elastic::probe_record", names, fields);
  }

  int count() const { return stencil_.count(); }

  // Record the probe fields now (seed 000: displacement, divergence, rotation, theta) at time t.
  template <bool Rotation>
  void sample(const neighbors::BondFamily& family, const mps::ElasticFields<T>& f, const mps::ElasticParams<T>& p,
              double t) {
    const std::int64_t slot = buffer_.next_slot();
    mps::sample_probes<T, Rotation>(stencil_, family, f, p, buffer_.record(), slot);
    buffer_.commit(t);
  }

  // Everything recorded so far (copies pending samples from the device first).
  const ProbeHistory& history() { return buffer_.history(); }
  void save(models::Archive& a, const std::string& prefix) { buffer_.save(a, prefix); }
  void load(const models::Archive& a, const std::string& prefix) { buffer_.load(a, prefix); }

 private:
  mps::ProbeStencil<T> stencil_;
  models::ProbeBuffer<T> buffer_;
};

}  // namespace polymech::mps_elastic
