// The crack of an MpsElastic model (seed 000 §4): the bonds the crack cuts (mps_elastic/crack_bonds.hpp,
// found once from the lattice), the crack-face contact pairs and their state, and the intact-body
// monitor of the force through the crack line.
//
// Set-up runs once on the host. Per step, MpsElastic calls add_contact_forces() after the elastic
// accelerations (effects crack_contact.open_close and/or crack_contact.slip) or monitor()
// (CrackMode::monitor). Views of effects that are off stay empty.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/host_copy.hpp"
#include "common/state.hpp"
#include "contact/crack_faces.hpp"
#include "mps/interface_force.hpp"
#include "mps_elastic/config.hpp"
#include "mps_elastic/crack_bonds.hpp"
#include "neighbors/filter.hpp"

namespace polymech::mps_elastic {

namespace detail {

// Bond index of (from -> to) in the family for every crossing, both directions (-1: not a bond of the
// family, e.g. a lattice bond the family's radius test left out by round-off).
inline void find_crossing_bonds(const neighbors::BondFamily& family, const View1<Index>& from, const View1<Index>& to,
                                const View1<Offset>& forward, const View1<Offset>& backward) {
  Kokkos::parallel_for(
      "polymech::mps_elastic::crack_bond_index", range(static_cast<std::int64_t>(from.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t q) {
        auto find = [&](Index i, Index j) {
          for (Offset k = family.begin(i); k < family.end(i); ++k)
            if (family.neighbor(k) == j) return k;
          return Offset(-1);
        };
        forward(q) = find(from(q), to(q));
        backward(q) = find(to(q), from(q));
      });
}

// keep(i, j, k) for neighbors::filter_bonds: the bond survives unless it is marked as cut.
struct UnmarkedBond {
  Kokkos::View<std::uint8_t*, MemSpace> cut;
  KOKKOS_INLINE_FUNCTION bool operator()(Index, Index, Offset k) const { return cut(k) == 0; }
};

inline void mark_bonds(const Kokkos::View<std::uint8_t*, MemSpace>& mask, const View1<Offset>& bonds) {
  Kokkos::parallel_for(
      "polymech::mps_elastic::crack_mark_bonds", range(static_cast<std::int64_t>(bonds.extent(0))),
      KOKKOS_LAMBDA(const std::int64_t q) { mask(bonds(q)) = 1; });
}

}  // namespace detail

template <class T>
class CrackFaces {
 public:
  CrackFaces() = default;

  // c: the model's configuration (its crack, effects, lattice); x0 / family: the reference positions and
  // the uncut family; mass: particle mass. Throws std::invalid_argument for a crack that cuts nothing
  // or contact effects that cannot work (slip without any normal force).
  CrackFaces(const Config& config, const neighbors::BondFamily& family, double mass, double dt)
      : cfg_(config.crack),
        open_close_(config.effects.has("crack_contact.open_close")),
        slip_(config.effects.has("crack_contact.slip")) {
    const CrackConfig& c = cfg_;
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
    segment_ = crack_segment(c);
    params_.kn = static_cast<T>(c.k_prime * mass / (dt * dt));  // eq. (19)
    params_.ks = params_.kn;                                      // seed 000 §4.2.2: ks = kn
    params_.mu_s = static_cast<T>(c.mu_s);
    params_.mu_d = static_cast<T>(c.mu_d);
    params_.s = Vec2<T>{{static_cast<T>(segment_.t1), static_cast<T>(segment_.t3)}};
    mass_ = static_cast<T>(mass);
    build(config, family);
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

  // The reference family without the bonds the crack cuts (CrackMode::cut), both directions of each.
  neighbors::BondFamily cut(const neighbors::BondFamily& family) const {
    Kokkos::View<std::uint8_t*, MemSpace> mask("polymech::mps_elastic::crack_cut_mask",
                                               static_cast<std::size_t>(family.num_pairs));
    detail::mark_bonds(mask, forward_);
    detail::mark_bonds(mask, backward_);
    return neighbors::filter_bonds(family, detail::UnmarkedBond{mask});
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

  // The contact state a step reads (pair states and forces, slip anchors and signs) and the monitor.
  void register_state(models::StateRegistry& r) const {
    r.add("crack_state", state_.state);
    r.add("crack_force", state_.force);
    r.add("crack_slip_normal_force", state_.normal_force);
    r.add("crack_slip_anchor", state_.du_anchor);
    r.add("crack_slip_sign", state_.slip_sign);
    r.add("crack_line_shear_max", shear_max_);
  }

 private:
  void build(const Config& config, const neighbors::BondFamily& family) {
    // the crossings, with their bond indices in the family, ordered as the family orders them
    std::vector<CrackCrossing> found = crack_crossings<T>(config);
    std::vector<Offset> kf(found.size()), kb(found.size());
    {
      std::vector<Index> from(found.size()), to(found.size());
      for (std::size_t q = 0; q < found.size(); ++q) from[q] = found[q].upper, to[q] = found[q].lower;
      const View1<Offset> fw("polymech::mps_elastic::crack_forward_bonds", found.size());
      const View1<Offset> bw("polymech::mps_elastic::crack_backward_bonds", found.size());
      detail::find_crossing_bonds(family, models::to_device("polymech::mps_elastic::crack_from", from),
                                  models::to_device("polymech::mps_elastic::crack_to", to), fw, bw);
      auto hf = Kokkos::create_mirror_view_and_copy(HostSpace(), fw);
      auto hb = Kokkos::create_mirror_view_and_copy(HostSpace(), bw);
      for (std::size_t q = 0; q < found.size(); ++q) kf[q] = hf(q), kb[q] = hb(q);
    }
    std::vector<std::size_t> order;
    for (std::size_t q = 0; q < found.size(); ++q)
      if (kf[q] >= 0 && kb[q] >= 0) order.push_back(q);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return found[a].upper != found[b].upper ? found[a].upper < found[b].upper : kf[a] < kf[b];
    });
    cut_bonds_ = 2 * static_cast<std::int64_t>(order.size());
    if (cut_bonds_ == 0)
      throw std::invalid_argument("mps_elastic: the crack cuts no bond (it lies outside the body or is shorter than "
                                  "the gap between particle rows it would have to cross)");
    std::vector<Offset> forward, backward;
    for (std::size_t q : order) forward.push_back(kf[q]), backward.push_back(kb[q]);
    forward_ = models::to_device("polymech::mps_elastic::crack_cut_forward", forward);
    backward_ = models::to_device("polymech::mps_elastic::crack_cut_backward", backward);
    if (cfg_.mode == CrackMode::monitor) {
      build_monitor(found, order, kf);
      return;
    }
    if (!contact()) return;  // a free (traction-free) crack: nothing to allocate
    std::vector<Index> plus, minus;
    std::vector<T> d0;
    std::vector<double> r0x, r0y;
    for (std::size_t q : order) {
      if (!is_contact_pair(found[q], config)) continue;
      plus.push_back(found[q].upper);
      minus.push_back(found[q].lower);
      r0x.push_back(found[q].dx);
      r0y.push_back(found[q].dy);
      d0.push_back(static_cast<T>(std::sqrt(found[q].dx * found[q].dx + found[q].dy * found[q].dy)));
    }
    if (plus.empty())
      throw std::invalid_argument("mps_elastic: the crack has no contact pair (no cut bond within the contact radius)");
    build_pairs(plus, minus, d0, r0x, r0y);
  }

  // The crack line's crossing bonds per upper particle (CrackMode::monitor), in family order.
  void build_monitor(const std::vector<CrackCrossing>& found, const std::vector<std::size_t>& order,
                     const std::vector<Offset>& kf) {
    std::vector<Index> particles, neighbors;
    std::vector<Offset> offsets(1, 0), bonds;
    for (std::size_t n = 0; n < order.size(); ++n) {
      const CrackCrossing& x = found[order[n]];
      neighbors.push_back(x.lower);
      bonds.push_back(kf[order[n]]);
      if (n + 1 == order.size() || found[order[n + 1]].upper != x.upper) {
        particles.push_back(x.upper);
        offsets.push_back(static_cast<Offset>(neighbors.size()));
      }
    }
    crossings_.particles = models::to_device("polymech::mps_elastic::crack_line_particles", particles);
    crossings_.offsets = models::to_device("polymech::mps_elastic::crack_line_offsets", offsets);
    crossings_.neighbors = models::to_device("polymech::mps_elastic::crack_line_neighbors", neighbors);
    crossings_.bonds = models::to_device("polymech::mps_elastic::crack_line_bonds", bonds);
    shear_max_ = View1<T>("polymech::mps_elastic::crack_line_shear_max", particles.size());
  }

  void build_pairs(const std::vector<Index>& plus, const std::vector<Index>& minus, const std::vector<T>& d0,
                   const std::vector<double>& r0x, const std::vector<double>& r0y) {
    const std::size_t np = plus.size();
    pairs_.plus = models::to_device("polymech::contact::crack_pair_plus", plus);
    pairs_.minus = models::to_device("polymech::contact::crack_pair_minus", minus);
    pairs_.d0 = models::to_device("polymech::contact::crack_pair_d0", d0);
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
    {
      std::vector<std::pair<Index, Index>> entries;  // (particle, pair)
      for (std::size_t k = 0; k < np; ++k) {
        entries.emplace_back(plus[k], static_cast<Index>(k));
        entries.emplace_back(minus[k], static_cast<Index>(k));
      }
      std::sort(entries.begin(), entries.end());
      std::vector<Index> faces, ids;
      std::vector<Offset> off(1, 0);
      for (std::size_t e = 0; e < entries.size(); ++e) {
        if (e == 0 || entries[e].first != entries[e - 1].first) {
          if (e > 0) off.push_back(static_cast<Offset>(ids.size()));
          faces.push_back(entries[e].first);
        }
        ids.push_back(entries[e].second);
      }
      off.push_back(static_cast<Offset>(ids.size()));
      pairs_.face_particles = models::to_device("polymech::contact::crack_face_particles", faces);
      pairs_.face_offsets = models::to_device("polymech::contact::crack_face_offsets", off);
      pairs_.face_pairs = models::to_device("polymech::contact::crack_face_pairs", ids);
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

  CrackConfig cfg_;
  bool open_close_ = false, slip_ = false;
  contact::CrackSegment segment_;
  contact::CrackContactParams<T> params_;
  T mass_ = T(1);
  std::int64_t cut_bonds_ = 0;
  View1<Offset> forward_, backward_;  // bond indices (upper -> lower, lower -> upper) of the cut bonds
  contact::CrackPairs<T> pairs_;
  contact::CrackContactState<T> state_;
  mps::LineCrossings crossings_;
  View1<T> shear_max_;
};

}  // namespace polymech::mps_elastic
