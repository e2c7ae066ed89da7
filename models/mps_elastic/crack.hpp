// The crack of an MpsElastic model (seed 000 §4): which bonds the crack cuts, the crack-face contact
// pairs and their state, and the intact-body monitor of the force through the crack line.
//
// Set-up runs once on the host from the uncut reference family. Per step, MpsElastic calls
// add_contact_forces() after the elastic accelerations (effects crack_contact.open_close and/or
// crack_contact.slip) or monitor() (CrackMode::monitor). Views of effects that are off stay empty.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/crack_faces.hpp"
#include "contact/crack_geometry.hpp"
#include "effects.hpp"
#include "mps/interface_force.hpp"
#include "mps_elastic/config.hpp"
#include "neighbors/filter.hpp"

namespace polymech::mps_elastic {

// keep(i, j) for neighbors::filter_bonds: the bond survives unless the crack cuts it.
template <class T>
struct UncutBond {
  VecView<T, 2> x0;
  contact::CrackSegment crack;
  KOKKOS_INLINE_FUNCTION bool operator()(Index i, Index j) const {
    return !crack.cuts(static_cast<double>(x0(i, 0)), static_cast<double>(x0(i, 1)), static_cast<double>(x0(j, 0)),
                       static_cast<double>(x0(j, 1)));
  }
};

template <class T>
class CrackFaces {
 public:
  CrackFaces() = default;

  // family: the uncut reference family; x0: reference positions. Throws std::invalid_argument for a
  // crack that cuts nothing or contact effects that cannot work (slip without any normal force).
  CrackFaces(const CrackConfig& c, const EffectSet& effects, const VecView<T, 2>& x0,
             const neighbors::BondFamily& family, double spacing, double mass, double dt)
      : cfg_(c), open_close_(effects.has("crack_contact.open_close")), slip_(effects.has("crack_contact.slip")) {
    if (c.mode == CrackMode::none) {
      if (open_close_ || slip_) throw std::invalid_argument("mps_elastic: the crack_contact effects need a crack");
      return;
    }
    if (c.mode == CrackMode::monitor && (open_close_ || slip_))
      throw std::invalid_argument("mps_elastic: crack contact effects need a cut crack (mode cut), not a monitored line");
    if (!(c.length > 0)) throw std::invalid_argument("mps_elastic: crack length must be > 0");
    if (!(c.k_prime > 0 && c.k_prime < 2))
      throw std::invalid_argument("mps_elastic: crack k' must be in (0, 2): the penalty spring alone is unstable for "
                                  "k' >= 2 (omega dt = sqrt(2 k'))");
    if (!(c.mu_s >= 0) || !(c.mu_d >= 0) || c.mu_d > c.mu_s)
      throw std::invalid_argument("mps_elastic: friction coefficients must satisfy 0 <= mu_d <= mu_s");
    if (slip_ && !open_close_ && !(c.normal_reaction > 0))
      throw std::invalid_argument("mps_elastic: crack_contact.slip without crack_contact.open_close needs a normal "
                                  "reaction > 0 (nothing else presses the faces together)");
    segment_ = contact::CrackSegment::make(c.x1, c.x3, c.length, c.angle);
    params_.kn = static_cast<T>(c.k_prime * mass / (dt * dt));  // eq. (19)
    params_.ks = params_.kn;                                      // seed 000 §4.2.2: ks = kn
    params_.mu_s = static_cast<T>(c.mu_s);
    params_.mu_d = static_cast<T>(c.mu_d);
    params_.s = Vec2<T>{{static_cast<T>(segment_.t1), static_cast<T>(segment_.t3)}};
    mass_ = static_cast<T>(mass);
    build(x0, family, spacing);
  }

  CrackMode mode() const { return cfg_.mode; }
  bool contact() const { return open_close_ || slip_; }
  const contact::CrackSegment& segment() const { return segment_; }
  Index pair_count() const { return pairs_.count(); }
  Index crossing_particles() const { return static_cast<Index>(crossings_.particles.extent(0)); }
  std::int64_t cut_bonds() const { return cut_bonds_; }  // directed bonds removed (each pair twice)
  const contact::CrackPairs<T>& pairs() const { return pairs_; }
  const contact::CrackContactState<T>& state() const { return state_; }
  const contact::CrackContactParams<T>& params() const { return params_; }

  // The reference family without the bonds the crack cuts (CrackMode::cut).
  neighbors::BondFamily cut(const neighbors::BondFamily& family, const VecView<T, 2>& x0) const {
    return neighbors::filter_bonds(family, UncutBond<T>{x0, segment_});
  }

  // Contact forces of the enabled effects, added to the accelerations (seed 000 eqs. (17)-(21)).
  void add_contact_forces(const mps::ElasticFields<T>& f) const {
    if (!contact()) return;
    if (open_close_) {
      if (slip_)
        contact::crack_open_close<T, true>(pairs_, state_, f.u, params_);
      else
        contact::crack_open_close<T, false>(pairs_, state_, f.u, params_);
    }
    if (slip_) {
      if (open_close_)
        contact::crack_slip<T, true>(pairs_, state_, f.u, f.v, params_);
      else
        contact::crack_slip<T, false>(pairs_, state_, f.u, f.v, params_);
    }
    contact::crack_apply_forces(pairs_, state_, f.a, mass_);
  }

  // CrackMode::monitor: running maximum of the shear force through the crack line per particle.
  template <bool Rotation>
  void monitor(const mps::ElasticFields<T>& f, const mps::ElasticParams<T>& p) const {
    if (cfg_.mode != CrackMode::monitor) return;
    mps::interface_shear_force_max<T, Rotation>(crossings_, f, p, params_.s[0], params_.s[1], shear_max_);
  }
  // Largest shear force through the crack line so far (monitor), over the particles along the crack.
  double max_shear_force() const {
    if (shear_max_.extent(0) == 0) return 0.0;
    T m = T(0);
    const auto v = shear_max_;
    Kokkos::parallel_reduce(
        "polymech::mps_elastic::crack_shear_max", range(static_cast<std::int64_t>(v.extent(0))),
        KOKKOS_LAMBDA(const std::int64_t q, T& x) { x = v(q) > x ? v(q) : x; }, Kokkos::Max<T>(m));
    return static_cast<double>(m);
  }

  contact::CrackStateCounts counts() const {
    return contact() ? contact::crack_state_counts(pairs_, state_) : contact::CrackStateCounts{};
  }

  // Reset the contact state to the initial one (closed crack: pairs in stick, anchors at rest).
  void reset() const {
    if (!contact()) return;
    Kokkos::deep_copy(state_.state, int(open_close_ ? contact::pair_separation : contact::pair_stick));
    Kokkos::deep_copy(state_.force, T(0));
    if (slip_) {
      Kokkos::deep_copy(state_.du_anchor, T(0));
      Kokkos::deep_copy(state_.slip_sign, 1);
    }
  }

 private:
  void build(const VecView<T, 2>& x0, const neighbors::BondFamily& family, double spacing) {
    auto hx = Kokkos::create_mirror_view_and_copy(HostSpace(), x0);
    auto hoff = Kokkos::create_mirror_view_and_copy(HostSpace(), family.offsets);
    auto hnb = Kokkos::create_mirror_view_and_copy(HostSpace(), family.neighbors);
    const double contact_r2 = cfg_.contact_radius * spacing * cfg_.contact_radius * spacing;
    std::vector<Index> plus, minus, cross_particles, cross_nb;
    std::vector<Offset> cross_off(1, 0), cross_bond;
    std::vector<double> r0x, r0y, d0;
    for (Index i = 0; i < family.num_particles; ++i) {
      const double xi = static_cast<double>(hx(i, 0)), yi = static_cast<double>(hx(i, 1));
      const bool upper = segment_.upper(xi, yi);
      const std::size_t before = cross_nb.size();
      for (Offset k = hoff(i); k < hoff(i + 1); ++k) {
        const Index j = hnb(k);
        const double xj = static_cast<double>(hx(j, 0)), yj = static_cast<double>(hx(j, 1));
        if (!segment_.cuts(xi, yi, xj, yj)) continue;
        ++cut_bonds_;
        if (!upper) continue;  // each crossing once, from its S+ end
        cross_nb.push_back(j);
        cross_bond.push_back(k);
        const double dx = xj - xi, dy = yj - yi;
        if (dx * dx + dy * dy <= contact_r2) {
          plus.push_back(i);
          minus.push_back(j);
          r0x.push_back(dx);
          r0y.push_back(dy);
          d0.push_back(std::sqrt(dx * dx + dy * dy));
        }
      }
      if (cross_nb.size() > before) {
        cross_particles.push_back(i);
        cross_off.push_back(static_cast<Offset>(cross_nb.size()));
      }
    }
    if (cut_bonds_ == 0)
      throw std::invalid_argument("mps_elastic: the crack cuts no bond (it lies outside the body or is shorter than "
                                  "the gap between particle rows it would have to cross)");
    if (cfg_.mode == CrackMode::monitor) {
      crossings_.particles = upload<Index>("polymech::mps_elastic::crack_line_particles", cross_particles);
      crossings_.offsets = upload<Offset>("polymech::mps_elastic::crack_line_offsets", cross_off);
      crossings_.neighbors = upload<Index>("polymech::mps_elastic::crack_line_neighbors", cross_nb);
      crossings_.bonds = upload<Offset>("polymech::mps_elastic::crack_line_bonds", cross_bond);
      shear_max_ = View1<T>("polymech::mps_elastic::crack_line_shear_max", cross_particles.size());
      return;
    }
    if (!contact()) return;  // a free (traction-free) crack: nothing to allocate
    if (plus.empty())
      throw std::invalid_argument("mps_elastic: the crack has no contact pair (no cut bond within the contact radius)");
    const std::size_t np = plus.size();
    pairs_.plus = upload<Index>("polymech::contact::crack_pair_plus", plus);
    pairs_.minus = upload<Index>("polymech::contact::crack_pair_minus", minus);
    pairs_.d0 = upload<T>("polymech::contact::crack_pair_d0", std::vector<T>(d0.begin(), d0.end()));
    pairs_.r0 = VecView<T, 2>("polymech::contact::crack_pair_r0", np);
    {
      auto h = Kokkos::create_mirror_view(pairs_.r0);
      for (std::size_t k = 0; k < np; ++k) {
        h(k, 0) = static_cast<T>(r0x[k]);
        h(k, 1) = static_cast<T>(r0y[k]);
      }
      Kokkos::deep_copy(pairs_.r0, h);
    }
    // particle -> pairs, for the deterministic gather of the pair forces
    std::vector<std::vector<Index>> by_particle_pairs;
    std::vector<Index> faces;
    {
      std::vector<std::pair<Index, Index>> entries;  // (particle, pair)
      for (std::size_t k = 0; k < np; ++k) {
        entries.emplace_back(plus[k], static_cast<Index>(k));
        entries.emplace_back(minus[k], static_cast<Index>(k));
      }
      std::sort(entries.begin(), entries.end());
      std::vector<Offset> off(1, 0);
      std::vector<Index> ids;
      for (std::size_t e = 0; e < entries.size(); ++e) {
        if (e == 0 || entries[e].first != entries[e - 1].first) {
          if (e > 0) off.push_back(static_cast<Offset>(ids.size()));
          faces.push_back(entries[e].first);
        }
        ids.push_back(entries[e].second);
      }
      off.push_back(static_cast<Offset>(ids.size()));
      pairs_.face_particles = upload<Index>("polymech::contact::crack_face_particles", faces);
      pairs_.face_offsets = upload<Offset>("polymech::contact::crack_face_offsets", off);
      pairs_.face_pairs = upload<Index>("polymech::contact::crack_face_pairs", ids);
    }
    state_.state = Kokkos::View<int*, MemSpace>("polymech::contact::crack_state", np);
    state_.force = VecView<T, 2>("polymech::contact::crack_force", np);
    if (open_close_ && slip_) state_.normal_force = View1<T>("polymech::contact::crack_slip_normal_force", np);
    if (slip_) {
      state_.du_anchor = VecView<T, 2>("polymech::contact::crack_slip_anchor", np);
      state_.slip_sign = Kokkos::View<int*, MemSpace>("polymech::contact::crack_slip_sign", np);
      state_.preload = View1<T>("polymech::contact::crack_slip_preload", np);
      Kokkos::deep_copy(state_.preload, static_cast<T>(cfg_.normal_reaction));
    }
    reset();
  }

  template <class V>
  static Kokkos::View<V*, MemSpace> upload(const std::string& label, const std::vector<V>& host) {
    Kokkos::View<V*, MemSpace> d(label, host.size());
    auto h = Kokkos::create_mirror_view(d);
    for (std::size_t k = 0; k < host.size(); ++k) h(k) = host[k];
    Kokkos::deep_copy(d, h);
    return d;
  }

  CrackConfig cfg_;
  bool open_close_ = false, slip_ = false;
  contact::CrackSegment segment_;
  contact::CrackContactParams<T> params_;
  T mass_ = T(1);
  std::int64_t cut_bonds_ = 0;
  contact::CrackPairs<T> pairs_;
  contact::CrackContactState<T> state_;
  mps::LineCrossings crossings_;
  View1<T> shear_max_;
};

}  // namespace polymech::mps_elastic
